//! What `motion.svg` draws besides the bodies: the floors they roll on, and the
//! coordinates' marks (arcs and dimension lines with their labels) moved frame by frame.
//! Every frame's path has the same commands, so that one frame's turns into the next.

use super::motion::{Gauge, Motion};
use super::motion_timing::{coarse, color, polyline, Timing};
use super::numbers::{add, cross, scale};
use super::picture::{Ink, Projection, P2};
use super::strokes::{head, p2add, p2norm, p2scale, p2unit};
use crate::render::escape::html as xml;
use std::fmt::Write;

/// The radius of an angle's arc, as the still picture draws it.
const ARC: f64 = 30.0;
/// The arc's straight pieces: a sixth of a pixel from the true arc at most.
const ARC_STEPS: u32 = 16;
/// How far a dimension line stands off the points it measures, and its extension lines.
const STANDOFF: f64 = 14.0;
const EXTENSION: f64 = 18.0;

/// A floor as drawn: its outline, and the ticks of its two edges lowest on the page.
pub(super) struct Floor {
    pub(super) outline: Vec<P2>,
    pub(super) ticks: Vec<[P2; 2]>,
}

/// The floors in the picture, their two edges lowest on the page hatched outwards.
pub(super) fn floor_lines(motion: &Motion) -> Vec<Floor> {
    let p = &motion.projection;
    let mut floors = Vec::new();
    for corners in &motion.floors {
        let points: Vec<P2> = corners.iter().map(|c| p.point(*c)).collect();
        let middle = p2scale(points.iter().fold([0.0, 0.0], |m, q| p2add(m, *q)), 0.25);
        let mut edges: Vec<(P2, P2)> = (0..4).map(|k| (points[k], points[(k + 1) % 4])).collect();
        edges.sort_by(|a, b| (b.0[1] + b.1[1]).total_cmp(&(a.0[1] + a.1[1])));
        let mut ticks = Vec::new();
        for &(a, b) in &edges[..2] {
            let along = [b[0] - a[0], b[1] - a[1]];
            let (Some(t), length) = (p2unit(along), p2norm(along)) else {
                continue;
            };
            let mid = p2scale(p2add(a, b), 0.5);
            let mut n = [-t[1], t[0]];
            if (mid[0] - middle[0]) * n[0] + (mid[1] - middle[1]) * n[1] < 0.0 {
                n = p2scale(n, -1.0);
            }
            let count = (length / 7.0).floor().max(1.0) as usize;
            for k in 0..=count {
                let s = p2add(a, p2scale(t, k as f64 * length / count as f64));
                ticks.push([s, p2add(s, p2add(p2scale(n, 6.0), p2scale(t, -4.0)))]);
            }
        }
        floors.push(Floor {
            outline: points,
            ticks,
        });
    }
    floors
}

/// The floors, lightly filled, their two edges lowest on the page hatched outwards.
pub(super) fn floors(out: &mut String, floors: &[Floor]) {
    for floor in floors {
        let mut d = polyline(&floor.outline, coarse);
        d.push('Z');
        let ticks: String = floor.ticks.iter().map(|t| polyline(t, coarse)).collect();
        let _ = writeln!(
            out,
            "<g class=\"floor\"><path d=\"{d}\" fill=\"{}\" stroke=\"{}\" stroke-width=\"1\"/><path d=\"{ticks}\" fill=\"none\" stroke=\"{}\" stroke-width=\"0.8\"/></g>",
            color(Ink::Floor),
            color(Ink::Grey),
            color(Ink::Black)
        );
    }
}

/// One mark as drawn at one frame, in the picture: its thin dashed lines, its line or
/// arc, its arrowheads, and where its label would go: beside `anchor`, towards `toward`
/// (radians) if that is free.
pub(super) struct Drawn {
    pub(super) dashed: Vec<Vec<P2>>,
    pub(super) line: Vec<P2>,
    pub(super) heads: Vec<[P2; 3]>,
    pub(super) anchor: P2,
    pub(super) toward: f64,
}

/// The picture's pixels per metre.
fn pixels(p: &Projection) -> f64 {
    p.a[0].iter().map(|x| x * x).sum::<f64>().sqrt().max(1e-12)
}

/// A mark at one frame as the still picture draws it.
fn drawn(p: &Projection, gauge: &Gauge) -> Drawn {
    match *gauge {
        Gauge::Angle {
            center,
            from,
            axis,
            angle,
            reference,
        } => {
            // Past a whole turn (a crank that keeps turning) only the last turn is drawn,
            // which ends where the whole angle does.
            let angle = angle % std::f64::consts::TAU;
            let r = ARC / pixels(p);
            let v = cross(axis, from);
            let c = p.point(center);
            let line: Vec<P2> = (0..=ARC_STEPS)
                .map(|k| {
                    let t = angle * f64::from(k) / f64::from(ARC_STEPS);
                    p.point(add(
                        center,
                        scale(add(scale(from, t.cos()), scale(v, t.sin())), r),
                    ))
                })
                .collect();
            let n = line.len();
            let tangent = p2unit([
                line[n - 1][0] - line[n - 2][0],
                line[n - 1][1] - line[n - 2][1],
            ])
            .unwrap_or([1.0, 0.0]);
            // A small angle's head shrinks into its tip rather than jump away.
            let grown = (angle.abs() / 0.15).min(1.0);
            let tip = line[n - 1];
            let heads = vec![head(tip, tangent)
                .map(|q| p2add(tip, p2scale([q[0] - tip[0], q[1] - tip[1]], grown)))];
            let middle = line[n / 2];
            let toward = p2unit([middle[0] - c[0], middle[1] - c[1]]).unwrap_or([1.0, 0.0]);
            Drawn {
                dashed: vec![vec![c, p.point(add(center, scale(from, reference)))]],
                line,
                heads,
                anchor: middle,
                toward: toward[1].atan2(toward[0]),
            }
        }
        Gauge::Distance { from, to, along } => {
            let (a, b) = (p.point(from), p.point(to));
            let u = p2unit(p.direction(along))
                .or_else(|| p2unit([b[0] - a[0], b[1] - a[1]]))
                .unwrap_or([1.0, 0.0]);
            let n = [-u[1], u[0]];
            let (a2, b2) = (
                p2add(a, p2scale(n, STANDOFF)),
                p2add(b, p2scale(n, STANDOFF)),
            );
            let sense = if (b[0] - a[0]) * u[0] + (b[1] - a[1]) * u[1] < 0.0 {
                -1.0
            } else {
                1.0
            };
            let grown = (p2norm([b2[0] - a2[0], b2[1] - a2[1]]) / 18.0).min(1.0);
            let heads = [(b2, p2scale(u, sense)), (a2, p2scale(u, -sense))]
                .map(|(tip, d)| {
                    head(tip, d).map(|q| p2add(tip, p2scale([q[0] - tip[0], q[1] - tip[1]], grown)))
                })
                .to_vec();
            Drawn {
                dashed: vec![
                    vec![a, p2add(a, p2scale(n, EXTENSION))],
                    vec![b, p2add(b, p2scale(n, EXTENSION))],
                ],
                line: vec![a2, b2],
                heads,
                anchor: p2scale(p2add(a2, b2), 0.5),
                toward: n[1].atan2(n[0]),
            }
        }
    }
}

/// Each coordinate's mark as drawn at each frame.
pub(super) fn marks(motion: &Motion) -> Vec<Vec<Drawn>> {
    let p = &motion.projection;
    (0..motion.gauges.len())
        .map(|k| {
            motion
                .frames
                .iter()
                .filter_map(|f| f.gauges.get(k))
                .map(|g| drawn(p, g))
                .collect()
        })
        .collect()
}

/// The coordinates' marks (`marks`), each a group `<g class="gauge" data-label="q_1"
/// data-kind="angle">` whose dashed lines, arc or line, heads and label move with the
/// motion; each label's centre per frame in `labels`.
pub(super) fn gauges(
    out: &mut String,
    motion: &Motion,
    timing: &Timing,
    marks: &[Vec<Drawn>],
    labels: &[Vec<P2>],
) {
    let grey = color(Ink::Grey);
    for (k, label) in motion.gauges.iter().enumerate() {
        let (Some(frames), Some(centres), Some(gauge)) =
            (marks.get(k), labels.get(k), motion.frames[0].gauges.get(k))
        else {
            continue;
        };
        if frames.is_empty() || centres.is_empty() {
            continue;
        }
        let kind = match gauge {
            Gauge::Angle { .. } => "angle",
            Gauge::Distance { .. } => "distance",
        };
        let _ = writeln!(
            out,
            "<g class=\"gauge\" data-kind=\"{kind}\" data-label=\"{}\" fill=\"none\" stroke=\"{grey}\">",
            xml(&label.plain)
        );
        let shapes =
            |path: &dyn Fn(&Drawn) -> String| -> Vec<String> { frames.iter().map(path).collect() };
        let dashed = shapes(&|d| d.dashed.iter().map(|l| polyline(l, coarse)).collect());
        let line = shapes(&|d| polyline(&d.line, coarse));
        let heads = shapes(&|d| {
            d.heads
                .iter()
                .map(|h| polyline(h, coarse) + "Z")
                .collect::<String>()
        });
        for (class, values, style) in [
            (
                "reference",
                &dashed,
                "stroke-width=\"0.8\" stroke-dasharray=\"4 3\"",
            ),
            (
                if kind == "angle" { "arc" } else { "dimension" },
                &line,
                "stroke-width=\"1\"",
            ),
            ("heads", &heads, "stroke-width=\"0.8\""),
        ] {
            let fill = if class == "heads" {
                format!(" fill=\"{grey}\"")
            } else {
                String::new()
            };
            let _ = writeln!(
                out,
                "<path class=\"{class}\" d=\"{}\"{fill} {style}>",
                values[0]
            );
            timing.animate(out, "d", values);
            out.push_str("</path>\n");
        }
        let (xs, ys) = label_track(centres);
        let _ = writeln!(
            out,
            "<text class=\"label\" x=\"{}\" y=\"{}\" fill=\"{}\" stroke=\"none\">{}",
            xs[0],
            ys[0],
            color(Ink::Black),
            super::svg::label_spans(label)
        );
        timing.animate(out, "x", &xs);
        timing.animate(out, "y", &ys);
        out.push_str("</text>\n</g>\n");
    }
}

/// A label's `x` and `y` per frame from its centres: the letters' line sits below the
/// middle of the box.
pub(super) fn label_track(centres: &[P2]) -> (Vec<String>, Vec<String>) {
    (
        centres.iter().map(|c| coarse(c[0])).collect(),
        centres.iter().map(|c| coarse(c[1] + 4.5)).collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_arc_ends_where_the_angle_has_turned() {
        // Seen from +N.z with y down: counterclockwise in N is clockwise on the page.
        let p = Projection {
            a: [[100.0, 0.0, 0.0], [0.0, -100.0, 0.0]],
            b: [200.0, 200.0],
        };
        let gauge = |angle: f64| Gauge::Angle {
            center: [0.0; 3],
            from: [1.0, 0.0, 0.0],
            axis: [0.0, 0.0, 1.0],
            angle,
            reference: 0.3,
        };
        let d = drawn(&p, &gauge(0.7));
        let tip = d.line[d.line.len() - 1];
        let turned = (-(tip[1] - 200.0)).atan2(tip[0] - 200.0);
        assert!((turned - 0.7).abs() < 1e-9, "{turned}");
        assert!((p2norm([tip[0] - 200.0, tip[1] - 200.0]) - ARC).abs() < 1e-9);
        assert_eq!(d.line.len(), ARC_STEPS as usize + 1);
        // A crank past a whole turn shows its last turn, ending at the same place.
        let again = drawn(&p, &gauge(0.7 + std::f64::consts::TAU));
        let other = again.line[again.line.len() - 1];
        assert!(p2norm([other[0] - tip[0], other[1] - tip[1]]) < 1e-9);
        let (m, n) = (
            again.line[ARC_STEPS as usize / 2],
            d.line[ARC_STEPS as usize / 2],
        );
        assert!(p2norm([m[0] - n[0], m[1] - n[1]]) < 1e-9, "{m:?} {n:?}");
    }

    #[test]
    fn a_distance_keeps_its_side_through_zero() {
        let p = Projection {
            a: [[100.0, 0.0, 0.0], [0.0, -100.0, 0.0]],
            b: [0.0, 0.0],
        };
        let at = |x: f64| Gauge::Distance {
            from: [0.0; 3],
            to: [x, 0.0, 0.0],
            along: [1.0, 0.0, 0.0],
        };
        let (plus, minus) = (drawn(&p, &at(0.5)), drawn(&p, &at(-0.5)));
        assert_eq!(plus.line[0][1], minus.line[0][1]);
        assert_eq!(plus.anchor[1], minus.anchor[1]);
        assert_eq!(plus.toward, minus.toward);
    }
}
