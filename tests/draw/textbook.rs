//! The pictures as a textbook draws them, measured on the laid-out pictures: a rack or cart
//! that slides rests on the hatched ground (no rollers); unit vectors stand above the
//! ground, and two frames' unit vectors with their names stand apart; the top's â_z is not
//! named on its vertical axis line; a free body printed in LaTeX fills the room its page
//! gives it.

use super::drawings;
use crate::support::problem as problem_path;
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::{
    text_size, Drawing, Item, Picture, View, BESIDE_A_TABLE, CONFIGURATION,
};

type P2 = [f64; 2];

fn pictures(name: &str) -> Vec<Drawing> {
    let problem = mbd_tutor::problem::load_file(&problem_path(name)).expect("a bundled problem");
    let (_, pictures, _) = drawings(&problem, Method::MotionLaw, View::Isometric);
    pictures
}

/// Every item of `items`, groups and bodies opened, with the class of the group it is in.
fn flat<'a>(items: &'a [Item], class: &'a str, out: &mut Vec<(&'a str, &'a Item)>) {
    for item in items {
        match item {
            Item::Group { class, items } => flat(items, class, out),
            Item::Body { items, .. } => flat(items, "body", out),
            _ => out.push((class, item)),
        }
    }
}

fn all(picture: &Picture) -> Vec<(&str, &Item)> {
    let mut out = Vec::new();
    flat(&picture.items, "", &mut out);
    out
}

/// The groups of `class`, each as its items.
fn groups<'a>(picture: &'a Picture, class: &str) -> Vec<&'a [Item]> {
    (picture.items.iter())
        .filter_map(|i| match i {
            Item::Group { class: c, items } if *c == class => Some(items.as_slice()),
            _ => None,
        })
        .collect()
}

fn stroke_points(items: &[Item]) -> Vec<P2> {
    (items.iter())
        .flat_map(|i| match i {
            Item::Stroke(s) => s.points.clone(),
            _ => Vec::new(),
        })
        .collect()
}

fn bounds(points: &[P2]) -> (P2, P2) {
    points
        .iter()
        .fold(([f64::MAX; 2], [f64::MIN; 2]), |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        })
}

/// The block of body `name`: its outline's corners.
fn block(picture: &Picture, name: &str) -> Vec<P2> {
    (picture.items.iter())
        .find_map(|i| match i {
            Item::Body { id, items, .. } if *id == format!("body-{name}") => Some(items),
            _ => None,
        })
        .and_then(|items| {
            items.iter().find_map(|i| match i {
                Item::Stroke(s) if s.closed => Some(s.points.clone()),
                _ => None,
            })
        })
        .unwrap_or_else(|| panic!("no block {name}"))
}

/// Each ground line: its ends, and the side of it that is ground (where its hatching goes).
fn grounds(picture: &Picture) -> Vec<(P2, P2, P2)> {
    groups(picture, "ground")
        .into_iter()
        .map(|items| {
            let strokes: Vec<&Vec<P2>> = (items.iter())
                .filter_map(|i| match i {
                    Item::Stroke(s) => Some(&s.points),
                    _ => None,
                })
                .collect();
            let (a, b) = (strokes[0][0], strokes[0][1]);
            let tick = strokes.get(1).expect("hatched");
            let down = [tick[1][0] - tick[0][0], tick[1][1] - tick[0][1]];
            (a, b, down)
        })
        .collect()
}

/// Whether `p` lies on the ground's side of the line `a`–`b`, within its length.
fn in_ground(p: P2, (a, b, down): (P2, P2, P2)) -> bool {
    let t = [b[0] - a[0], b[1] - a[1]];
    let length = t[0].hypot(t[1]);
    let s = ((p[0] - a[0]) * t[0] + (p[1] - a[1]) * t[1]) / length;
    let n = [-t[1] / length, t[0] / length];
    let side = (p[0] - a[0]) * n[0] + (p[1] - a[1]) * n[1];
    let ground_side = down[0] * n[0] + down[1] * n[1];
    (0.0..=length).contains(&s) && side * ground_side > 1.0
}

#[test]
fn a_sliding_rack_or_cart_rests_on_the_ground_without_rollers() {
    for (name, body) in [("rack-and-pinion", "R"), ("disc-on-cart", "C")] {
        let picture = &pictures(name)[0].picture;
        // The one wheel drawn is the rolling body's: no roller under the block.
        let wheels = (all(picture).into_iter())
            .filter(|(_, i)| matches!(i, Item::Circle { radius, .. } if *radius > 6.0))
            .count();
        assert_eq!(wheels, 1, "{name}: wheels drawn");
        let (lo, hi) = bounds(&block(picture, body));
        let under = grounds(picture).into_iter().any(|(a, b, down)| {
            let level = (a[1] - hi[1]).abs() < 0.5 && (b[1] - hi[1]).abs() < 0.5;
            let spans = a[0].min(b[0]) <= lo[0] && a[0].max(b[0]) >= hi[0];
            level && spans && down[1] > 0.0
        });
        assert!(under, "{name}: no ground along the block's bottom {hi:?}");
    }
}

#[test]
fn unit_vectors_stand_above_the_ground() {
    for name in ["bowling-ball", "rack-and-pinion", "disc-on-cart"] {
        for drawing in pictures(name).iter().take(1) {
            for picture in [
                drawing.picture.clone(),
                drawing.laid_out_in(CONFIGURATION).into_owned(),
            ] {
                let lines = grounds(&picture);
                assert!(!lines.is_empty(), "{name}: a ground");
                for triad in groups(&picture, "triad") {
                    for p in stroke_points(triad) {
                        assert!(
                            !lines.iter().any(|l| in_ground(p, *l)),
                            "{name}: a unit vector at {p:?} in the ground {lines:?}"
                        );
                    }
                }
            }
        }
    }
}

/// The box of a triad's arrows and of the names at their tips (the labels nearest them).
fn triad_with_names(picture: &Picture, triad: &[Item], letter: char) -> (P2, P2) {
    let mut points = stroke_points(triad);
    for t in &picture.texts {
        if let Item::Text { at, label, .. } = t {
            let hatted = label.plain.starts_with(&format!("{letter}\u{302}"));
            if hatted {
                let size = text_size(&label.plain);
                points.push([at[0] - size[0] / 2.0, at[1] - size[1] / 2.0]);
                points.push([at[0] + size[0] / 2.0, at[1] + size[1] / 2.0]);
            }
        }
    }
    bounds(&points)
}

#[test]
fn two_frames_unit_vectors_and_their_names_stand_apart() {
    let drawing = &pictures("rack-and-pinion")[0];
    for picture in [
        drawing.picture.clone(),
        drawing.laid_out_in(CONFIGURATION).into_owned(),
    ] {
        let triads = groups(&picture, "triad");
        // n̂ in its corner, then the rack's r̂ and the pinion's p̂.
        let boxes: Vec<(P2, P2)> = ['r', 'p']
            .iter()
            .zip(&triads[1..])
            .map(|(letter, triad)| triad_with_names(&picture, triad, *letter))
            .collect();
        let (a, b) = (boxes[0], boxes[1]);
        let meet = (0..2).all(|k| a.0[k] < b.1[k] && b.0[k] < a.1[k]);
        assert!(!meet, "r̂ {a:?} and p̂ {b:?} overlap");
    }
}

#[test]
fn the_tops_unit_vector_is_not_named_on_its_vertical_axis() {
    let drawing = &pictures("heavy-symmetric-top")[0];
    for picture in [
        drawing.picture.clone(),
        drawing.laid_out_in(CONFIGURATION).into_owned(),
    ] {
        let axis: Vec<Vec<P2>> = (all(&picture).into_iter())
            .filter_map(|(_, i)| match i {
                Item::Stroke(s) if s.dashed => Some(s.points.clone()),
                _ => None,
            })
            .collect();
        assert!(!axis.is_empty(), "the vertical axis is drawn dashed");
        let (at, size) = (picture.texts.iter())
            .find_map(|t| match t {
                Item::Text { at, label, .. } if label.plain == "a\u{302}_z" => {
                    Some((*at, text_size(&label.plain)))
                }
                _ => None,
            })
            .expect("â_z named");
        let half = [size[0] * picture.grow / 2.0, size[1] * picture.grow / 2.0];
        for line in &axis {
            for k in 0..=20 {
                let t = f64::from(k) / 20.0;
                let p = [
                    line[0][0] + t * (line[1][0] - line[0][0]),
                    line[0][1] + t * (line[1][1] - line[0][1]),
                ];
                let inside = (p[0] - at[0]).abs() < half[0] && (p[1] - at[1]).abs() < half[1];
                assert!(!inside, "â_z at {at:?} on the axis line {line:?}");
            }
        }
    }
}

/// The coordinates of every `(x,y)` a `tikzpicture` draws at, and its unit (points per
/// picture unit, as `x={min(UNIT,…)*1pt}` sets it).
fn tikz_ink(tikz: &str) -> (f64, Vec<P2>) {
    let unit: f64 = tikz
        .split("x={min(")
        .nth(1)
        .and_then(|s| s.split(',').next())
        .and_then(|s| s.parse().ok())
        .expect("a unit");
    let mut points = Vec::new();
    for statement in tikz.split(";\n") {
        let mut here = Vec::new();
        for piece in statement.split('(').skip(1) {
            let Some(inner) = piece.split(')').next() else {
                continue;
            };
            let mut xy = inner.split(',').map(|v| v.trim().parse::<f64>());
            if let (Some(Ok(x)), Some(Ok(y)), None) = (xy.next(), xy.next(), xy.next()) {
                here.push([x, y]);
            }
        }
        // A circle reaches its radius round its centre.
        let radius = (statement.split("circle[radius=").nth(1))
            .and_then(|r| r.split(']').next())
            .and_then(|r| r.parse::<f64>().ok());
        if let (Some(r), Some(&[x, y])) = (radius, here.first()) {
            here.extend([[x - r, y - r], [x + r, y + r]]);
        }
        points.extend(here);
    }
    (unit, points)
}

/// The gear pair's free bodies, set beside their tables of forces, print as large as the
/// room allows: their ink (every point drawn, by the TikZ) as high as the room, or as wide,
/// or at the picture's natural size. Scaled by the layout's box with its margin, they
/// printed three quarters of it.
#[test]
fn a_free_body_fills_the_room_its_page_gives_it() {
    let natural = 8.0 / 13.0;
    for drawing in pictures("gear-pair-torque").iter().skip(1) {
        let figure = drawing.figure_beside_a_table();
        let (unit, points) = tikz_ink(figure.picture_latex.as_str());
        let (lo, hi) = bounds(&points);
        let (width, height) = ((hi[0] - lo[0]) * unit, (hi[1] - lo[1]) * unit);
        let room = BESIDE_A_TABLE;
        let fills = height > 0.85 * room.height
            || width > 0.85 * room.width
            || (unit - natural).abs() < 1e-3;
        assert!(
            fills,
            "{}: {width:.0} × {height:.0} pt in {} × {} pt",
            drawing.name, room.width, room.height
        );
    }
}
