//! `motion.svg`'s bodies: each body's group, and in it each of its sheets drawn once in
//! metres and carried to the picture, frame by frame, by four animated transforms (the
//! orthographic picture of a moving plane is an affine map of it).

use super::motion::{Motion, Part};
use super::motion_timing::{color, fine, num, Timing};
use super::numbers::P3;
use super::picture::{Ink, Projection, P2};
use crate::render::escape::html as xml;
use std::fmt::Write;

/// The SVG matrix `[a, b, c, d, e, f]` (x' = a u + c v + e, y' = b u + d v + f) of a sheet
/// at origin `o` with unit vectors `e1`, `e2`, seen through `p`.
pub(super) fn sheet_matrix(p: &Projection, [o, e1, e2]: &[P3; 3]) -> [f64; 6] {
    let [a, b] = p.direction(*e1);
    let [c, d] = p.direction(*e2);
    let [e, f] = p.point(*o);
    [a, b, c, d, e, f]
}

/// An affine map as translate · rotate · skewX · scale: `[e, f, θ°, φ°, sx, sy]`.
fn decompose([a, b, c, d, e, f]: [f64; 6]) -> [f64; 6] {
    let sx = a.hypot(b);
    let theta = b.atan2(a);
    let (sin, cos) = theta.sin_cos();
    // R(−θ) M is upper triangular: [[sx, m12], [0, m22]] = skewX(φ) · scale(sx, m22).
    let m12 = cos * c + sin * d;
    let mut sy = -sin * c + cos * d;
    // A sheet seen edge on: keep the skew finite (the sheet is a line either way).
    let least = 1e-4 * sx.max(m12.abs());
    if sy.abs() < least {
        sy = if sy < 0.0 { -least } else { least };
    }
    let skew = (m12 / sy).atan();
    [e, f, theta.to_degrees(), skew.to_degrees(), sx, sy]
}

/// The composition of what [`decompose`] gives, for checking it.
#[cfg(test)]
fn compose([e, f, theta, skew, sx, sy]: [f64; 6]) -> [f64; 6] {
    let (sin, cos) = theta.to_radians().sin_cos();
    let k = skew.to_radians().tan();
    // R · K · S with K = [[1, k], [0, 1]], S = diag(sx, sy).
    [
        cos * sx,
        sin * sx,
        (cos * k - sin) * sy,
        (sin * k + cos) * sy,
        e,
        f,
    ]
}

/// A body: its group, and in it each of its sheets with its parts (in metres), moved by
/// four animated transforms; a particle's ball, moved by its centre.
pub(super) fn body(out: &mut String, motion: &Motion, timing: &Timing, k: usize) {
    let body = &motion.bodies[k];
    let p = &motion.projection;
    let _ = writeln!(
        out,
        "<g class=\"body\" id=\"body-{}\" data-shape=\"{}\">",
        xml(&body.name),
        body.kind.name()
    );
    for (s, sheet) in motion.sheets.iter().enumerate() {
        if sheet.body == k && !sheet.parts.is_empty() {
            out.push_str("<g class=\"sheet\">\n");
            sheet_transforms(out, motion, timing, s);
            for part in &sheet.parts {
                self::part(out, part);
            }
            out.push_str("</g>\n");
        }
    }
    if let Some(i) = body.ball {
        let track: Vec<P2> = motion.frames.iter().map(|f| p.point(f.points[i])).collect();
        let rest = format!("r=\"7\" fill=\"{}\"", color(Ink::Black));
        timing.moving_circle(out, &track, "class=\"ball\"", &rest);
    }
    out.push_str("</g>\n");
}

/// The four transforms that carry sheet `s` from its own plane to the picture, per frame.
fn sheet_transforms(out: &mut String, motion: &Motion, timing: &Timing, s: usize) {
    let p = &motion.projection;
    let mut parts: [Vec<String>; 4] = Default::default();
    let (mut last_angle, mut last_turn): (Option<f64>, f64) = (None, 0.0);
    for frame in &motion.frames {
        let [e, f, mut theta, skew, sx, sy] = decompose(sheet_matrix(p, &frame.sheets[s]));
        // The turn goes on continuously: the angle nearest to where the last frame's turn
        // carries it on, so a body that turns more than half a turn between frames (a fast
        // pinion) is not seen to turn back.
        if let Some(last) = last_angle {
            let expected = last + last_turn;
            theta += 360.0 * ((expected - theta) / 360.0).round();
            last_turn = theta - last;
        }
        last_angle = Some(theta);
        parts[0].push(format!("{} {}", num(e), num(f)));
        parts[1].push(num(theta));
        parts[2].push(num(skew));
        parts[3].push(format!("{} {}", fine(sx), fine(sy)));
    }
    for (kind, values) in ["translate", "rotate", "skewX", "scale"].iter().zip(&parts) {
        timing.transform(out, kind, values);
    }
}

/// The lines of sheet `s` at `frame` in the picture, each with whether it closes and its
/// width: what labels keep clear of.
pub(super) fn sheet_lines(motion: &Motion, frame: usize, s: usize) -> Vec<(Vec<P2>, bool, f64)> {
    let (Some(sheet), Some(placed)) = (
        motion.sheets.get(s),
        motion.frames.get(frame).and_then(|f| f.sheets.get(s)),
    ) else {
        return Vec::new();
    };
    let [a, b, c, d, e, f] = sheet_matrix(&motion.projection, placed);
    let map = |q: &[f64; 2]| [a * q[0] + c * q[1] + e, b * q[0] + d * q[1] + f];
    let mut lines = Vec::new();
    for part in &sheet.parts {
        match part {
            Part::Wheel {
                center,
                radius,
                mark,
            } => {
                let at = |u: f64, v: f64| {
                    [
                        center[0] + radius * (u * mark[0] - v * mark[1]),
                        center[1] + radius * (u * mark[1] + v * mark[0]),
                    ]
                };
                let rim: Vec<P2> = (0..32)
                    .map(|k| {
                        let t = std::f64::consts::TAU * f64::from(k) / 32.0;
                        map(&at(t.cos(), t.sin()))
                    })
                    .collect();
                lines.push((rim, true, 1.6));
                lines.push((vec![map(&at(-1.0, 0.0)), map(&at(1.0, 0.0))], false, 2.0));
                lines.push((vec![map(&at(0.0, -1.0)), map(&at(0.0, 1.0))], false, 0.8));
            }
            Part::Bar(points) => lines.push((points.iter().map(map).collect(), false, 7.0)),
            Part::Line(p, q) => lines.push((vec![map(p), map(q)], false, 1.1)),
            Part::Outline(points) => lines.push((points.iter().map(map).collect(), true, 1.4)),
        }
    }
    lines
}

/// Path data through sheet points (metres, so finely).
fn sheet_path(points: &[[f64; 2]], closed: bool) -> String {
    let mut d = String::new();
    for (i, q) in points.iter().enumerate() {
        let _ = write!(
            d,
            "{}{} {}",
            if i == 0 { "M" } else { "L" },
            fine(q[0]),
            fine(q[1])
        );
    }
    if closed {
        d.push('Z');
    }
    d
}

/// One part on a sheet; line widths stay in pixels whatever the sheet's scale.
fn part(out: &mut String, part: &Part) {
    let ink = color(Ink::Black);
    let fill = color(Ink::Body);
    const KEEP: &str = "vector-effect=\"non-scaling-stroke\"";
    match part {
        Part::Wheel {
            center,
            radius,
            mark,
        } => {
            let [cx, cy] = *center;
            let _ = writeln!(
                out,
                "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{fill}\" stroke=\"{ink}\" stroke-width=\"1.6\" {KEEP}/>",
                fine(cx),
                fine(cy),
                fine(*radius)
            );
            // A light cross and the dark spoke of the still picture: the wheel is seen to
            // turn.
            let at = |u: f64, v: f64| {
                [
                    cx + radius * (u * mark[0] - v * mark[1]),
                    cy + radius * (u * mark[1] + v * mark[0]),
                ]
            };
            let cross = format!(
                "{}{}",
                sheet_path(&[at(-1.0, 0.0), at(1.0, 0.0)], false),
                sheet_path(&[at(0.0, -1.0), at(0.0, 1.0)], false)
            );
            let _ = writeln!(
                out,
                "<path d=\"{cross}\" stroke=\"{}\" stroke-width=\"0.8\" {KEEP}/>",
                color(Ink::Grey)
            );
            let _ = writeln!(
                out,
                "<path class=\"mark\" d=\"{}\" stroke=\"{ink}\" stroke-width=\"2\" {KEEP}/>",
                sheet_path(&[*center, at(1.0, 0.0)], false)
            );
        }
        Part::Bar(points) => {
            let d = sheet_path(points, false);
            let _ = writeln!(
                out,
                "<path d=\"{d}\" fill=\"none\" stroke=\"{ink}\" stroke-width=\"7\" {KEEP}/>"
            );
            let _ = writeln!(
                out,
                "<path d=\"{d}\" fill=\"none\" stroke=\"{fill}\" stroke-width=\"4.6\" {KEEP}/>"
            );
        }
        Part::Line(a, b) => {
            let _ = writeln!(
                out,
                "<path d=\"{}\" fill=\"none\" stroke=\"{ink}\" stroke-width=\"1.1\" {KEEP}/>",
                sheet_path(&[*a, *b], false)
            );
        }
        Part::Outline(points) => {
            let _ = writeln!(
                out,
                "<path d=\"{}\" fill=\"{fill}\" stroke=\"{ink}\" stroke-width=\"1.4\" {KEEP}/>",
                sheet_path(points, true)
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_affine_map_is_translate_rotate_skew_scale() {
        for m in [
            [2.0, 0.5, -0.3, 1.5, 10.0, 20.0],
            [0.0, 3.0, -3.0, 0.0, 1.0, 2.0],
            [1.0, 0.0, 0.0, -1.0, 0.0, 0.0],
            [-0.7, 0.2, 0.9, 0.4, -5.0, 3.0],
        ] {
            let back = compose(decompose(m));
            for (x, y) in m.iter().zip(back) {
                assert!((x - y).abs() < 1e-9, "{m:?} came back as {back:?}");
            }
        }
    }
}
