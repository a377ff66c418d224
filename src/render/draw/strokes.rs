//! Small pieces of the layout in picture coordinates: vector arithmetic, arrowheads,
//! springs and dashpots, the ellipse a disc projects to, arrows stacked at one point, and
//! words wrapped into lines.

use super::picture::{DrawnArrow, P2};
use super::place::text_size;

pub fn p2add(a: P2, b: P2) -> P2 {
    [a[0] + b[0], a[1] + b[1]]
}

pub fn p2scale(a: P2, k: f64) -> P2 {
    [a[0] * k, a[1] * k]
}

pub fn p2norm(a: P2) -> f64 {
    a[0].hypot(a[1])
}

pub fn p2unit(a: P2) -> Option<P2> {
    let n = p2norm(a);
    (n > 1e-9).then(|| p2scale(a, 1.0 / n))
}

/// A triangle for an arrowhead at `tip` pointing along unit `u`.
pub fn head(tip: P2, u: P2) -> [P2; 3] {
    let n = [-u[1], u[0]];
    let back = p2add(tip, p2scale(u, -9.0));
    [
        tip,
        p2add(back, p2scale(n, 3.8)),
        p2add(back, p2scale(n, -3.8)),
    ]
}

/// A zig-zag from `a` to `b`.
pub fn zigzag(a: P2, b: P2) -> Vec<P2> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let Some(u) = p2unit(d) else {
        return vec![a, b];
    };
    let n = [-u[1], u[0]];
    let length = p2norm(d);
    let lead = (0.15 * length).min(14.0);
    let coils = 8;
    let mut points = vec![a, p2add(a, p2scale(u, lead))];
    for k in 0..coils {
        let t = lead + (length - 2.0 * lead) * (k as f64 + 0.5) / coils as f64;
        let side = if k % 2 == 0 { 6.0 } else { -6.0 };
        points.push(p2add(p2add(a, p2scale(u, t)), p2scale(n, side)));
    }
    points.push(p2add(a, p2scale(u, length - lead)));
    points.push(b);
    points
}

/// A dashpot from `a` to `b`: rod, cylinder, piston, rod.
pub fn dashpot(a: P2, b: P2) -> Vec<Vec<P2>> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let Some(u) = p2unit(d) else {
        return vec![vec![a, b]];
    };
    let n = [-u[1], u[0]];
    let length = p2norm(d);
    let at = |t: f64, side: f64| p2add(p2add(a, p2scale(u, t * length)), p2scale(n, side));
    vec![
        vec![a, at(0.4, 0.0)],
        vec![at(0.6, 8.0), at(0.4, 8.0), at(0.4, -8.0), at(0.6, -8.0)],
        vec![at(0.52, 6.0), at(0.52, -6.0)],
        vec![at(0.52, 0.0), b],
    ]
}

/// The page distance between two springs or dampers drawn side by side.
pub const LANE_WIDTH: f64 = 18.0;

/// The ends of an element drawn `lane` steps to the side of the line from `a` to `b`, and
/// the two short legs that join it to `a` and `b` (none in lane 0).
pub fn in_lane(a: P2, b: P2, lane: f64) -> ([P2; 2], Vec<Vec<P2>>) {
    let Some(u) = p2unit([b[0] - a[0], b[1] - a[1]]) else {
        return ([a, b], Vec::new());
    };
    if lane == 0.0 {
        return ([a, b], Vec::new());
    }
    let side = p2scale([-u[1], u[0]], lane * LANE_WIDTH);
    let (a2, b2) = (p2add(a, side), p2add(b, side));
    // The legs leave the ends a little way along the line, as a bracket.
    let inset = p2scale(u, 6.0);
    let (a1, b1) = (p2add(a2, inset), p2add(b2, p2scale(inset, -1.0)));
    ([a1, b1], vec![vec![a, a2, a1], vec![b, b2, b1]])
}

/// The ellipse `t -> c + du cos t + dv sin t` as its semi-axes and its turn (degrees,
/// clockwise on the page): the eigen-decomposition of M Mᵀ, M = [du dv].
pub fn ellipse_of(du: P2, dv: P2) -> (f64, f64, f64) {
    let (a, b, d) = (
        du[0] * du[0] + dv[0] * dv[0],
        du[0] * du[1] + dv[0] * dv[1],
        du[1] * du[1] + dv[1] * dv[1],
    );
    let mean = (a + d) / 2.0;
    let spread = (((a - d) / 2.0).powi(2) + b * b).sqrt();
    let (rx, ry) = ((mean + spread).sqrt(), (mean - spread).max(0.0).sqrt());
    let angle = if b.abs() < 1e-12 {
        if a >= d {
            0.0
        } else {
            90.0
        }
    } else {
        b.atan2(mean + spread - d).to_degrees()
    };
    (rx, ry, angle)
}

/// How many arrows were drawn before this one at (or within a head's length of) the same
/// spot of the page along the same line (within 25°, so that two forces that only look
/// collinear in a 3D view, or that would overlap near their tail, are staggered too),
/// whatever points they are named for; 2D couples, arcs (`u` none), count apart. Records
/// this one.
pub fn stack_of(drawn: &mut Vec<(P2, Option<P2>)>, at: P2, u: Option<P2>) -> usize {
    /// Anchors closer than this on the page count as one spot.
    const SAME_SPOT: f64 = 16.0;
    let alike = |v: &Option<P2>| match (v, u) {
        (None, None) => true,
        (Some(a), Some(b)) => a[0] * b[0] + a[1] * b[1] > 25f64.to_radians().cos(),
        _ => false,
    };
    let count = drawn
        .iter()
        .filter(|(p, v)| p2norm([p[0] - at[0], p[1] - at[1]]) < SAME_SPOT && alike(v))
        .count();
    drawn.push((at, u));
    count
}

/// The length of a straight force arrow with `stack` drawn before it along its line at its
/// spot: every arrow has one length, a stacked one a step longer for each.
pub fn arrow_length(stack: usize) -> f64 {
    /// The length of every force arrow.
    const ARROW: f64 = 44.0;
    ARROW + 22.0 * stack as f64
}

/// The points of every straight arrowhead drawn (a moment vector has two), which a new
/// arrow's heads keep clear of.
pub fn tips_of(arrows: &[DrawnArrow]) -> Vec<P2> {
    arrows
        .iter()
        .filter(|a| a.arc.is_none())
        .flat_map(|a| a.heads.iter().map(|h| h[0]))
        .collect()
}

/// `stack` raised, a step at a time, until a straight arrow from `at` along `u`, of length
/// `length(stack)`, has its heads (the tip, and a moment vector's second head `second`
/// back) a head's length from every point of `tips`; an arc (`u` none) keeps `stack`.
pub fn clear_of_tips(
    at: P2,
    u: Option<P2>,
    stack: usize,
    tips: &[P2],
    length: impl Fn(usize) -> f64,
    second: f64,
) -> usize {
    /// The least distance between two arrowheads' points: a head's length and a little.
    const APART: f64 = 12.0;
    let Some(u) = u else { return stack };
    let near = |p: P2| {
        tips.iter()
            .any(|t| p2norm([t[0] - p[0], t[1] - p[1]]) < APART)
    };
    (stack..stack + 6)
        .find(|&k| {
            let tip = p2add(at, p2scale(u, length(k)));
            !near(tip) && !near(p2add(tip, p2scale(u, -second)))
        })
        .unwrap_or(stack)
}

/// Words broken into lines that fit `width`.
pub fn wrap(text: &str, width: f64) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        match lines.last_mut() {
            Some(line) if text_size(&format!("{line} {word}"))[0] <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_element_in_a_lane_is_joined_to_its_ends() {
        let ([a1, b1], legs) = in_lane([0.0, 0.0], [100.0, 0.0], 1.0);
        assert_eq!(a1, [6.0, LANE_WIDTH]);
        assert_eq!(b1, [94.0, LANE_WIDTH]);
        assert_eq!(legs[0].first(), Some(&[0.0, 0.0]));
        assert_eq!(legs[1].first(), Some(&[100.0, 0.0]));
        assert!(in_lane([0.0, 0.0], [100.0, 0.0], 0.0).1.is_empty());
    }
}
