//! Where several loads act at one point, each still reads as itself, as a textbook draws
//! it: a point's name stands at its point and not at the tip of an arrow acting elsewhere
//! (where it would read as that arrow's name), and a weight ends clear of the bodies its
//! mass centre is not in (ending on the cart a disc stands on, it reads as a push on the
//! cart). Every free body of every bundled problem by every method, as drawn and as a page
//! beside its table prints it.

use super::drawings;
use crate::support::all_problems;
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::{text_size, Drawing, Item, Kind, Picture, View, BESIDE_A_TABLE};

type P2 = [f64; 2];

/// Closer than this (px) to an arrow's tip, a point's name reads as the arrow's.
const OFF_A_TIP: f64 = 4.0;

/// A label's box: its centre and half sizes (as `tests/draw/labels.rs` measures it).
#[derive(Clone, Copy, Debug)]
struct Box2 {
    center: P2,
    half: P2,
}

impl Box2 {
    fn distance_to(&self, p: P2) -> f64 {
        let dx = ((p[0] - self.center[0]).abs() - self.half[0]).max(0.0);
        let dy = ((p[1] - self.center[1]).abs() - self.half[1]).max(0.0);
        dx.hypot(dy)
    }
}

/// The labels of a picture (neither its title nor its legend), with their boxes.
fn labels(picture: &Picture) -> Vec<(String, Box2)> {
    let texts = &picture.texts;
    let last = texts.len() - picture.legend.lines;
    (texts[1..last].iter())
        .filter_map(|t| match t {
            Item::Text { at, label, .. } => {
                let size = text_size(&label.plain);
                let g = picture.grow;
                Some((
                    label.plain.clone(),
                    Box2 {
                        center: *at,
                        half: [g * size[0] / 2.0 - 1.0, g * size[1] / 2.0 - 2.0],
                    },
                ))
            }
            _ => None,
        })
        .collect()
}

/// Whether `p` lies inside a body's outline: a closed stroke's polygon or an ellipse.
fn in_body(item: &Item, p: P2) -> bool {
    let Item::Body { items, .. } = item else {
        return false;
    };
    items.iter().any(|part| match part {
        Item::Stroke(s) if s.closed && s.points.len() > 2 => {
            let mut inside = false;
            let mut j = s.points.len() - 1;
            for i in 0..s.points.len() {
                let (a, b) = (s.points[i], s.points[j]);
                if (a[1] > p[1]) != (b[1] > p[1])
                    && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]
                {
                    inside = !inside;
                }
                j = i;
            }
            inside
        }
        Item::Ellipse {
            center,
            rx,
            ry,
            angle,
            ..
        } => {
            let (sin, cos) = angle.to_radians().sin_cos();
            let d = [p[0] - center[0], p[1] - center[1]];
            let (x, y) = (d[0] * cos + d[1] * sin, -d[0] * sin + d[1] * cos);
            (x / rx).powi(2) + (y / ry).powi(2) < 1.0
        }
        Item::Circle { center, radius, .. } => (p[0] - center[0]).hypot(p[1] - center[1]) < *radius,
        _ => false,
    })
}

/// Every free body's picture of every bundled problem by every method, as drawn and as a
/// page beside its table prints it.
fn free_bodies() -> Vec<(String, Picture)> {
    let mut out = Vec::new();
    for path in all_problems() {
        let problem = mbd_tutor::problem::load_file(&path).expect("a bundled problem");
        for method in [
            Method::MotionLaw,
            Method::NewtonEuler,
            Method::Kane,
            Method::Lagrange,
        ] {
            let (_, pictures, _) = drawings(&problem, method, View::Isometric);
            for d in pictures
                .iter()
                .filter(|d: &&Drawing| !d.free_body.is_empty())
            {
                let name = format!("{} {method:?} {}", path.display(), d.name);
                out.push((name.clone(), d.picture.clone()));
                out.push((
                    format!("{name} (beside a table)"),
                    d.laid_out_in(BESIDE_A_TABLE).into_owned(),
                ));
            }
        }
    }
    out
}

/// The faults of one picture, as `name: what`.
fn faults_of(name: &str, picture: &Picture) -> Vec<String> {
    let mut faults = Vec::new();
    let grow = picture.grow;
    let labels = labels(picture);
    let arrow_labels: Vec<&str> = (picture.arrows.iter())
        .map(|a| a.label.plain.as_str())
        .collect();
    // A point's name not at the tip of an arrow that does not end at a marked point.
    let at_a_mark =
        |p: P2| (picture.marks.iter()).any(|m| (m.at[0] - p[0]).hypot(m.at[1] - p[1]) < 3.0);
    let tips: Vec<(&str, P2)> = (picture.arrows.iter())
        .filter(|a| a.arc.is_none())
        .map(|a| (a.label.plain.as_str(), a.head))
        .filter(|(_, t)| !at_a_mark(*t))
        .collect();
    for (plain, b) in labels
        .iter()
        .filter(|(p, _)| !arrow_labels.contains(&p.as_str()))
    {
        let names_a_point = (picture.marks.iter()).any(|m| b.distance_to(m.at) < 30.0 * grow);
        if !names_a_point {
            continue;
        }
        for (arrow, tip) in &tips {
            let off = b.distance_to(*tip);
            if off < OFF_A_TIP {
                faults.push(format!(
                    "{name}: the point's name {plain} at the tip of {arrow} ({off:.1} px)"
                ));
            }
        }
    }
    // A weight ends clear of the bodies its mass centre is not in.
    for w in (picture.arrows.iter()).filter(|a| a.kind == Kind::Gravity && a.arc.is_none()) {
        let from = w.leader.map_or(w.tail, |(point, _)| point);
        let length = (w.head[0] - w.tail[0]).hypot(w.head[1] - w.tail[1]);
        let u = [
            (w.head[0] - w.tail[0]) / length,
            (w.head[1] - w.tail[1]) / length,
        ];
        let beyond = [w.head[0] + 3.0 * u[0], w.head[1] + 3.0 * u[1]];
        for item in picture.items.iter().filter(|i| !in_body(i, from)) {
            if in_body(item, beyond) {
                faults.push(format!(
                    "{name}: the weight {} ends on another body",
                    w.label.plain
                ));
            }
        }
    }
    faults
}

#[test]
fn each_load_at_a_crowded_point_reads_as_itself() {
    let pictures = free_bodies();
    assert!(pictures.len() > 60, "only {} pictures", pictures.len());
    let faults: Vec<String> = (pictures.iter())
        .flat_map(|(name, picture)| faults_of(name, picture))
        .collect();
    assert!(
        faults.is_empty(),
        "{} faults:\n{}",
        faults.len(),
        faults.join("\n")
    );
}
