//! `motion.svg`: a [`Motion`] written as SVG animated with SMIL (`<animate>`,
//! `<animateTransform>`), looping, no script.

use super::motion::{Motion, TITLE_STRIP};
use super::motion_labels::{Ground, Lines};
use super::motion_timing::{color, fine, num, polyline, Timing};
use super::picture::{Ink, P2};
use super::strokes::in_lane;
use crate::render::escape::html as xml;
use std::fmt::Write;

/// The motion as an SVG document.
pub fn export(motion: &Motion) -> String {
    let p = &motion.projection;
    let [width, height] = motion.size;
    let mut out = String::new();
    let numbers: Vec<String> = p.numbers().iter().map(|x| format!("{x:.9}")).collect();
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" class=\"mbd motion\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" data-projection=\"{}\" data-duration=\"{}\" data-frames=\"{}\" font-family=\"DejaVu Serif, Times New Roman, serif\" font-size=\"13\" text-anchor=\"middle\" stroke-linecap=\"round\" stroke-linejoin=\"round\">",
        numbers.join(" "),
        fine(motion.frames.last().map_or(0.0, |f| f.t)),
        motion.frames.len(),
        w = num(width),
        h = num(height),
    );
    let _ = writeln!(
        out,
        "<title>Motion of {}</title>",
        xml(&super::svg::title_text(&motion.title))
    );
    out.push_str(super::svg::SCRIPT_STYLE);
    out.push('\n');
    let _ = writeln!(
        out,
        "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"#fff\"/>",
        num(width),
        num(height)
    );
    let _ = writeln!(
        out,
        "<text x=\"{}\" y=\"{}\">{}</text>",
        num(width / 2.0),
        num(TITLE_STRIP * 0.7),
        xml(&motion.title)
    );
    let timing = Timing::new(&motion.frames);
    let lines = Lines {
        floors: super::motion_marks::floor_lines(motion),
        ground: ground_lines(motion),
        springs: spring_lines(motion),
        dampers: damper_lines(motion),
        marks: super::motion_marks::marks(motion),
    };
    let labels = super::motion_labels::place(motion, &lines);
    super::motion_marks::floors(&mut out, &lines.floors);
    ground(&mut out, &lines.ground);
    for k in 0..motion.bodies.len() {
        super::motion_bodies::body(&mut out, motion, &timing, k);
    }
    for frames in &lines.springs {
        let shapes: Vec<String> = frames.iter().map(|f| polyline(f, num)).collect();
        animated_path(&mut out, "spring", &shapes, &timing);
    }
    for frames in &lines.dampers {
        let shapes: Vec<String> = frames
            .iter()
            .map(|parts| parts.iter().map(|part| polyline(part, num)).collect())
            .collect();
        animated_path(&mut out, "damper", &shapes, &timing);
    }
    super::motion_marks::gauges(&mut out, motion, &timing, &lines.marks, &labels.gauges);
    points(&mut out, motion, &timing, &labels.captions);
    out.push_str("</svg>\n");
    out
}

/// Supports under the joints on `N`, and the track of each rolling contact.
fn ground_lines(motion: &Motion) -> Ground {
    let p = &motion.projection;
    let mut supports = Vec::new();
    for &(i, toward) in &motion.grounded {
        let Some(first) = motion.frames.first() else {
            break;
        };
        let c = p.point(first.points[i]);
        // A triangle from the pin away from its body, on a hatched ground line.
        let up = super::strokes::p2unit(p.direction(toward)).unwrap_or([0.0, -1.0]);
        let across = [-up[1], up[0]];
        let at = |back: f64, side: f64| {
            [
                c[0] - up[0] * back + across[0] * side,
                c[1] - up[1] * back + across[1] * side,
            ]
        };
        let mut pieces = vec![
            (vec![c, at(14.0, 8.0), at(14.0, -8.0)], true),
            (vec![at(14.0, -12.0), at(14.0, 12.0)], false),
        ];
        for k in 0..5 {
            let side = -12.0 + 6.0 * f64::from(k);
            pieces.push((vec![at(14.0, side), at(19.0, side - 4.0)], false));
        }
        supports.push(pieces);
    }
    // A fixed round track whole, not only the arc its contact runs over.
    for rim in &motion.rims {
        supports.push(vec![(rim.iter().map(|q| p.point(*q)).collect(), true)]);
    }
    let tracks = motion
        .rolling
        .iter()
        .map(|&i| motion.frames.iter().map(|f| p.point(f.points[i])).collect())
        .collect();
    Ground { supports, tracks }
}

/// Supports under the joints on `N`, and the track of each rolling contact as its ground.
fn ground(out: &mut String, ground: &Ground) {
    let grey = color(Ink::Grey);
    let _ = writeln!(
        out,
        "<g class=\"ground\" fill=\"none\" stroke=\"{grey}\" stroke-width=\"1.2\">"
    );
    for pieces in &ground.supports {
        let mut d = String::new();
        for (points, closed) in pieces {
            d.push_str(&polyline(points, num));
            if *closed {
                d.push('Z');
            }
        }
        let _ = writeln!(out, "<path d=\"{d}\"/>");
    }
    for track in &ground.tracks {
        let _ = writeln!(
            out,
            "<path d=\"{}\" stroke-dasharray=\"6 3\"/>",
            polyline(track, num)
        );
    }
    out.push_str("</g>\n");
}

/// The springs as zig-zags that stretch with the motion: per spring, per frame.
fn spring_lines(motion: &Motion) -> Vec<Vec<Vec<P2>>> {
    let p = &motion.projection;
    let count = motion.frames.first().map_or(0, |f| f.springs.len());
    (0..count)
        .map(|s| {
            motion
                .frames
                .iter()
                .map(|f| {
                    let [a, b] = f.springs[s].map(|e| p.point(e));
                    let ([a1, b1], legs) = in_lane(a, b, motion.spring_lanes[s]);
                    let mut points: Vec<P2> =
                        legs.first().map_or(Vec::new(), |leg| leg[..2].to_vec());
                    points.extend(zigzag(a1, b1));
                    points.extend(legs.get(1).map_or(Vec::new(), |leg| vec![leg[1], leg[0]]));
                    points
                })
                .collect()
        })
        .collect()
}

/// A path of class `class` drawn in the known loads' ink, one shape per frame.
fn animated_path(out: &mut String, class: &str, shapes: &[String], timing: &Timing) {
    let _ = writeln!(
        out,
        "<path class=\"{class}\" d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.4\">",
        shapes[0],
        color(Ink::Known)
    );
    timing.animate(out, "d", shapes);
    out.push_str("</path>\n");
}

/// The dampers as dashpots, per damper, per frame: a cylinder fixed to the first end and
/// a piston on a rod from the second, both of fixed length, so that the piston slides in
/// the cylinder as the ends move; the cylinder is made long enough for the piston's whole
/// stroke.
fn damper_lines(motion: &Motion) -> Vec<Vec<Vec<Vec<P2>>>> {
    let p = &motion.projection;
    let count = motion.frames.first().map_or(0, |f| f.dampers.len());
    (0..count)
        .map(|s| {
            // The dashpot's own ends in its lane, and the legs that join them to the points.
            let ends: Vec<([P2; 2], Vec<Vec<P2>>)> = motion
                .frames
                .iter()
                .map(|f| {
                    in_lane(
                        p.point(f.dampers[s][0]),
                        p.point(f.dampers[s][1]),
                        motion.damper_lanes[s],
                    )
                })
                .collect();
            let lengths = ends
                .iter()
                .map(|([a, b], _)| (b[0] - a[0]).hypot(b[1] - a[1]));
            let shortest = lengths.clone().fold(f64::INFINITY, f64::min);
            let longest = lengths.fold(0.0, f64::max);
            let dashpot = Dashpot::for_stroke(shortest, longest);
            ends.into_iter()
                .map(|([a, b], mut legs)| {
                    legs.extend(dashpot.parts(a, b));
                    legs
                })
                .collect()
        })
        .collect()
}

/// A dashpot's fixed lengths on the page: its piston's distance back from the second end,
/// and its cylinder's bottom and open end measured from the first.
struct Dashpot {
    piston_back: f64,
    bottom: f64,
    open: f64,
}

impl Dashpot {
    /// One whose piston stays inside the cylinder while the ends are `shortest` to
    /// `longest` apart.
    fn for_stroke(shortest: f64, longest: f64) -> Dashpot {
        let piston_back = 0.45 * shortest;
        Dashpot {
            piston_back,
            bottom: 0.25 * shortest,
            open: (longest - piston_back + 4.0).max(0.75 * shortest),
        }
    }

    /// The dashpot from `a` to `b`, as path data.
    #[cfg(test)]
    fn path(&self, a: P2, b: P2) -> String {
        self.parts(a, b)
            .iter()
            .map(|part| polyline(part, num))
            .collect()
    }

    /// The dashpot's pieces from `a` to `b`: always as many points, so that one frame's
    /// path turns into the next.
    fn parts(&self, a: P2, b: P2) -> Vec<Vec<P2>> {
        let d = [b[0] - a[0], b[1] - a[1]];
        let length = d[0].hypot(d[1]).max(1e-9);
        let (u, n) = (
            [d[0] / length, d[1] / length],
            [-d[1] / length, d[0] / length],
        );
        let from = |base: P2, along: f64, side: f64| {
            [
                base[0] + u[0] * along + n[0] * side,
                base[1] + u[1] * along + n[1] * side,
            ]
        };
        let piston = -self.piston_back;
        let parts = [
            vec![a, from(a, self.bottom, 0.0)],
            vec![
                from(a, self.open, 8.0),
                from(a, self.bottom, 8.0),
                from(a, self.bottom, -8.0),
                from(a, self.open, -8.0),
            ],
            vec![from(b, piston, 6.0), from(b, piston, -6.0)],
            vec![from(b, piston, 0.0), b],
        ];
        parts.to_vec()
    }
}

/// A spring from `a` to `b`: straight ends and twelve zig-zags between, always as many
/// points, so that one frame's path turns into the next.
fn zigzag(a: P2, b: P2) -> Vec<P2> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let length = d[0].hypot(d[1]).max(1e-9);
    let across = [-d[1] / length * 6.0, d[0] / length * 6.0];
    let at = |s: f64, side: f64| {
        [
            a[0] + d[0] * s + across[0] * side,
            a[1] + d[1] * s + across[1] * side,
        ]
    };
    let mut out = vec![a, at(0.15, 0.0)];
    for k in 0..12 {
        let s = 0.15 + 0.7 * (f64::from(k) + 0.5) / 12.0;
        out.push(at(s, if k % 2 == 0 { 1.0 } else { -1.0 }));
    }
    out.push(at(0.85, 0.0));
    out.push(b);
    out
}

/// The mass centres and joints: circles outside the bodies, their centres animated, and
/// the words beside them (`captions`: each one's centre per frame).
fn points(out: &mut String, motion: &Motion, timing: &Timing, captions: &[Option<Vec<P2>>]) {
    let p = &motion.projection;
    for (i, (id, center)) in motion.points.iter().enumerate() {
        let track: Vec<P2> = motion.frames.iter().map(|f| p.point(f.points[i])).collect();
        let (r, fill) = if *center {
            ("4", color(Ink::White))
        } else {
            ("3", color(Ink::Black))
        };
        let lead = format!("id=\"{}\"", xml(id));
        let rest = format!(
            "r=\"{r}\" fill=\"{fill}\" stroke=\"{}\" stroke-width=\"1.2\"",
            color(Ink::Black)
        );
        timing.moving_circle(out, &track, &lead, &rest);
        let (Some(name), Some(Some(centres))) = (&motion.captions[i], captions.get(i)) else {
            continue;
        };
        let (xs, ys) = super::motion_marks::label_track(centres);
        let (class, fill) = if *center {
            ("label", String::new())
        } else {
            (
                "label coordinate",
                format!(" fill=\"{}\"", color(Ink::Grey)),
            )
        };
        let _ = writeln!(
            out,
            "<text class=\"{class}\"{fill} x=\"{}\" y=\"{}\">{}",
            xs[0],
            ys[0],
            xml(name)
        );
        timing.animate(out, "x", &xs);
        timing.animate(out, "y", &ys);
        out.push_str("</text>\n");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The numbers of a path's commands, in order.
    fn numbers(path: &str) -> Vec<f64> {
        path.split(['M', 'L', ' '])
            .filter(|s| !s.is_empty())
            .map(|s| s.parse().unwrap())
            .collect()
    }

    #[test]
    fn a_dashpots_piston_slides_inside_its_cylinder() {
        let (shortest, longest) = (60.0, 150.0);
        let dashpot = Dashpot::for_stroke(shortest, longest);
        let commands = |p: &str| p.matches(['M', 'L']).count();
        let first = dashpot.path([0.0, 0.0], [100.0, 0.0]);
        for length in [shortest, 80.0, 100.0, longest] {
            let path = dashpot.path([0.0, 0.0], [length, 0.0]);
            assert_eq!(commands(&path), commands(&first));
            let n = numbers(&path);
            // The parts: rod (2 points), cylinder (4), piston (2), rod (2).
            let (open, bottom, piston) = (n[4], n[6], n[12]);
            assert_eq!((bottom, open), (dashpot.bottom, dashpot.open));
            assert!(
                bottom < piston && piston < open,
                "piston at {piston} out of [{bottom}, {open}]"
            );
            assert!((length - piston - dashpot.piston_back).abs() < 1e-9);
            assert_eq!(n[n.len() - 2], length, "the rod ends at the second end");
        }
    }

    #[test]
    fn a_spring_has_as_many_points_however_long() {
        assert_eq!(
            zigzag([0.0, 0.0], [1.0, 0.0]).len(),
            zigzag([0.0, 0.0], [100.0, 50.0]).len()
        );
    }
}
