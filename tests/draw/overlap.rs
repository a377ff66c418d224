//! No two force arrows of one free body (or of its kinetic diagram) lie on each other: for
//! every free body of every bundled problem, by the Motion Law and by Newton–Euler, no
//! straight arrow read back from the SVG runs along another's line over it, but where two
//! meet at an end (two components at one pin) or stand in a stack of two lengths from one
//! tail, as the legend says.

use super::{drawings, line, read};
use crate::support::all_problems;
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::View;

/// Closer than this (px) to another arrow's line, a point of an arrow lies on it.
const ON: f64 = 1.5;
/// The part of each end of an arrow where it may meet another (px): its head, its tail.
const END: f64 = 8.0;

type Segment = ([f64; 2], [f64; 2]);

/// How far `p` is from the segment `a`–`b`.
pub(super) fn to_segment(p: [f64; 2], (a, b): Segment) -> f64 {
    let d = [b[0] - a[0], b[1] - a[1]];
    let length2 = d[0] * d[0] + d[1] * d[1];
    let t = if length2 > 0.0 {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / length2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - a[0] - t * d[0]).hypot(p[1] - a[1] - t * d[1])
}

/// The unit direction of a segment, tail to head.
fn direction((p, q): Segment) -> Option<[f64; 2]> {
    let length = (q[0] - p[0]).hypot(q[1] - p[1]);
    (length > 0.0).then(|| [(q[0] - p[0]) / length, (q[1] - p[1]) / length])
}

/// Whether `a` lies on `b`: the two run along one line (within 8°) and the middle of `a`
/// (its ends left out) comes within `ON` of `b`'s middle. Two arrows from one tail the same
/// way are a stack, drawn on purpose in two lengths (the legend says so), not an overlap.
fn lies_on(a: Segment, b: Segment) -> bool {
    let (Some(u), Some(v)) = (direction(a), direction(b)) else {
        return false;
    };
    let cos = u[0] * v[0] + u[1] * v[1];
    if cos.abs() < (8.0f64).to_radians().cos() {
        return false;
    }
    let same_tail = (a.0[0] - b.0[0]).hypot(a.0[1] - b.0[1]) < 0.5;
    if same_tail && cos > 0.0 {
        return false;
    }
    let middle = |(p, q): Segment| -> Option<Segment> {
        let length = (q[0] - p[0]).hypot(q[1] - p[1]);
        if length <= 2.0 * END {
            return None;
        }
        let u = [(q[0] - p[0]) / length, (q[1] - p[1]) / length];
        Some((
            [p[0] + END * u[0], p[1] + END * u[1]],
            [q[0] - END * u[0], q[1] - END * u[1]],
        ))
    };
    let (Some(a), Some(b)) = (middle(a), middle(b)) else {
        return false;
    };
    (0..=40).any(|k| {
        let t = f64::from(k) / 40.0;
        let p = [
            a.0[0] + t * (a.1[0] - a.0[0]),
            a.0[1] + t * (a.1[1] - a.0[1]),
        ];
        to_segment(p, b) < ON
    })
}

/// The arrows of each free body that lie on one another, as `problem picture: A on B`.
fn overlaps(method: Method) -> Vec<String> {
    let mut faults = Vec::new();
    for path in all_problems() {
        let problem = mbd_tutor::problem::load_file(&path).expect("a bundled problem");
        let (_, pictures, _) = drawings(&problem, method, View::Isometric);
        for picture in pictures.iter().skip(1) {
            let name = format!("{} {}", path.display(), picture.name);
            let r = read(&name, &picture.svg(""));
            let arrows: Vec<(String, Segment)> = (r.arrows.iter())
                .filter_map(|(g, m)| {
                    let label = g.attr("data-label").unwrap_or("").to_string();
                    line(g, *m).map(|s| (label, s))
                })
                .collect();
            for (i, (a, sa)) in arrows.iter().enumerate() {
                for (b, sb) in &arrows[i + 1..] {
                    if lies_on(*sa, *sb) || lies_on(*sb, *sa) {
                        faults.push(format!("{name}: {a} on {b}"));
                    }
                }
            }
        }
    }
    faults
}

#[test]
fn no_two_arrows_of_a_free_body_lie_on_each_other() {
    for method in [Method::MotionLaw, Method::NewtonEuler] {
        let faults = overlaps(method);
        assert!(
            faults.is_empty(),
            "{method:?}: {} arrows on others:\n{}",
            faults.len(),
            faults.join("\n")
        );
    }
}

#[test]
fn arrows_that_share_a_line_are_found() {
    // The check itself: one arrow along another's line, one that ends where the other
    // starts coming the opposite way over it, one across its middle (crossing, not lying
    // on it), one that meets it at its tail, and a stack of two from one tail.
    let a = ([0.0, 0.0], [44.0, 0.0]);
    assert!(lies_on(a, ([10.0, 0.5], [54.0, 0.5])));
    assert!(lies_on(a, ([44.0, 0.0], [0.0, 0.0])));
    assert!(!lies_on(a, ([22.0, -22.0], [22.0, 22.0])));
    assert!(!lies_on(a, ([0.0, 0.0], [0.0, -44.0])));
    assert!(!lies_on(a, ([0.0, 0.0], [-44.0, 0.0])));
    assert!(!lies_on(a, ([0.0, 0.0], [66.0, 0.0])));
}
