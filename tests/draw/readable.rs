//! Pictures that read as they mean: a weight is not drawn along a bar, where the bar hides
//! it, nor (moved aside) ending at another point or on another force, where it would read
//! as acting there; and in the motion a rack stays under its pinion, in mesh, over the
//! whole run.

use super::drawings;
use crate::support::{all_problems, problem as problem_path};
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::{Drawing, Item, Kind, Part, View, BESIDE_A_TABLE};

type P2 = [f64; 2];

fn to_segment(p: P2, a: P2, b: P2) -> f64 {
    let (v, w) = ([b[0] - a[0], b[1] - a[1]], [p[0] - a[0], p[1] - a[1]]);
    let length = v[0] * v[0] + v[1] * v[1];
    let t = if length > 0.0 {
        ((w[0] * v[0] + w[1] * v[1]) / length).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - a[0] - t * v[0]).hypot(p[1] - a[1] - t * v[1])
}

/// The bars of a picture: the wide open strokes inside the bodies, with their widths.
fn bars(items: &[Item], out: &mut Vec<(Vec<P2>, f64)>) {
    for item in items {
        match item {
            Item::Body { items, .. } => {
                for part in items {
                    if let Item::Stroke(s) = part {
                        if !s.closed && s.width >= 4.0 {
                            out.push((s.points.clone(), s.width));
                        }
                    }
                }
            }
            Item::Group { items, .. } => bars(items, out),
            _ => {}
        }
    }
}

/// Every free body's picture of `name`'s problem by the Motion Law and Newton–Euler, as
/// drawn and as a page beside its table prints it.
fn free_bodies(path: &std::path::Path) -> Vec<(String, mbd_tutor::render::draw::Picture)> {
    let problem = mbd_tutor::problem::load_file(path).expect("a bundled problem");
    let mut out = Vec::new();
    for method in [Method::MotionLaw, Method::NewtonEuler] {
        let (_, pictures, _) = drawings(&problem, method, View::Isometric);
        for d in pictures
            .iter()
            .filter(|d: &&Drawing| !d.free_body.is_empty())
        {
            let name = format!("{} {method:?} {}", path.display(), d.name);
            out.push((name.clone(), d.picture.clone()));
            out.push((name, d.laid_out_in(BESIDE_A_TABLE).into_owned()));
        }
    }
    out
}

#[test]
fn a_weight_is_neither_hidden_by_a_bar_nor_drawn_at_another_point() {
    let mut checked = 0;
    for path in all_problems() {
        for (name, picture) in free_bodies(&path) {
            let mut found = Vec::new();
            bars(&picture.items, &mut found);
            let others: Vec<_> = (picture.arrows.iter())
                .filter(|a| a.kind != Kind::Gravity && a.arc.is_none())
                .collect();
            for weight in picture.arrows.iter().filter(|a| a.kind == Kind::Gravity) {
                checked += 1;
                let at = |t: f64| {
                    let (a, b) = (weight.tail, weight.head);
                    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
                };
                // Along a bar: three of four points of its shaft under the bar's stroke
                // (its half width and 3 px).
                let hidden = [0.2, 0.4, 0.6, 0.8]
                    .iter()
                    .filter(|&&t| {
                        found.iter().any(|(points, width)| {
                            (points.windows(2))
                                .any(|w| to_segment(at(t), w[0], w[1]) < width / 2.0 + 3.0)
                        })
                    })
                    .count();
                assert!(
                    hidden < 3,
                    "{name}: the weight runs along a bar: {weight:?}"
                );
                let Some((point, _)) = weight.leader else {
                    continue;
                };
                // Moved aside: its shaft keeps 10 px off every other marked point, and its
                // head off every other force's arrow.
                for mark in &picture.marks {
                    let d = (mark.at[0] - point[0]).hypot(mark.at[1] - point[1]);
                    if d > 2.0 {
                        let off = to_segment(mark.at, weight.tail, weight.head);
                        assert!(off >= 10.0, "{name}: the weight ends by {}: {off}", mark.id);
                    }
                }
                for other in &others {
                    let off = to_segment(weight.head, other.tail, other.head);
                    assert!(
                        off >= 8.0,
                        "{name}: the weight's head on {:?}",
                        other.label.plain
                    );
                }
            }
        }
    }
    assert!(checked > 40, "only {checked} weights");
}

#[test]
fn the_rack_stays_under_its_pinion_over_the_whole_motion() {
    let problem = mbd_tutor::problem::load_file(&problem_path("rack-and-pinion")).expect("read");
    let (derivation, _, _) = drawings(&problem, Method::MotionLaw, View::Isometric);
    // Over a second the rack runs about 2.5 m: fifty pinion radii.
    let frames = mbd_tutor::pipeline::frames(&problem, &derivation, 1.0, 25.0).expect("frames");
    let motion = mbd_tutor::solution::motion_picture(&derivation, &frames, View::Isometric);
    let rack = (motion.bodies.iter().position(|b| b.name == "R")).expect("the rack");
    let (k, sheet) = (motion.sheets.iter().enumerate())
        .find(|(_, s)| s.body == rack)
        .expect("its sheet");
    let corners = (sheet.parts.iter())
        .find_map(|p| match p {
            Part::Outline(c) => Some(c.clone()),
            _ => None,
        })
        .expect("its block");
    let (lo, hi) = corners.iter().fold((f64::MAX, f64::MIN), |(lo, hi), c| {
        (lo.min(c[0]), hi.max(c[0]))
    });
    let contact = (motion.points.iter())
        .position(|(id, _)| id == "joint-teeth")
        .expect("the contact");
    let last = frames.last().expect("a frame");
    assert!(
        last.q[0] < -1.0 || last.q[0] > 1.0,
        "the rack moves: x = {}",
        last.q[0]
    );
    for frame in &motion.frames {
        // The contact in the rack's sheet: along its x from the sheet's origin.
        let [origin, x, _] = frame.sheets[k];
        let p = frame.points[contact];
        let along = (0..3).map(|i| (p[i] - origin[i]) * x[i]).sum::<f64>();
        assert!(
            lo < along && along < hi,
            "t = {}: the contact at {along} m off the rack [{lo}, {hi}]",
            frame.t
        );
    }
}
