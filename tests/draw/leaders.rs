//! A weight drawn aside, off a reaction's line, keeps its point shown: a dashed leader
//! from the point it acts at to one of its ends.

use crate::svg_reader::{apply, Element};

/// Whether the arrow `g` (transform `m`) has a leader from `point` to one of its `ends`.
pub(super) fn leads_to(g: &Element, m: [f64; 6], point: [f64; 2], ends: [[f64; 2]; 2]) -> bool {
    let same = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]) < 0.01;
    g.children
        .iter()
        .find(|c| c.name == "line" && c.attr("class") == Some("leader"))
        .is_some_and(|l| {
            let from = apply(m, [l.number("x1"), l.number("y1")]);
            let to = apply(m, [l.number("x2"), l.number("y2")]);
            same(from, point) && ends.iter().any(|e| same(to, *e))
        })
}
