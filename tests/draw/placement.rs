//! Where the configuration puts what a textbook's figure shows: a point of the rack named
//! on the rack's side, not inside the pinion above it; a cart drawn about its mass centre;
//! the forces the problem applies (the pull on the cart);
//! and a weight drawn from its mass centre, short of the contact below it.

use super::drawings;
use crate::support::problem as problem_path;
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::{Drawing, Item, Kind, Picture, View, BESIDE_A_TABLE, CONFIGURATION};

fn pictures(name: &str, method: Method) -> Vec<Drawing> {
    let problem = mbd_tutor::problem::load_file(&problem_path(name)).expect("a bundled problem");
    let (_, pictures, _) = drawings(&problem, method, View::Isometric);
    pictures
}

/// A body's group of items (`body-NAME`) in a picture's first panel.
fn body<'a>(picture: &'a Picture, name: &str) -> &'a [Item] {
    (picture.items.iter())
        .find_map(|item| match item {
            Item::Body { id, items, .. } if *id == format!("body-{name}") => Some(items.as_slice()),
            _ => None,
        })
        .unwrap_or_else(|| panic!("no body {name}"))
}

/// Where a label of plain text `plain` stands (alone, or named with the other points at
/// its dot: `R^*, S`).
fn label_at(picture: &Picture, plain: &str) -> [f64; 2] {
    (picture.texts.iter())
        .find_map(|t| match t {
            Item::Text { at, label, .. } if label.plain.split(", ").any(|n| n == plain) => {
                Some(*at)
            }
            _ => None,
        })
        .unwrap_or_else(|| panic!("no label {plain}"))
}

/// The centre and radius of a wheel's circle.
fn wheel(items: &[Item]) -> ([f64; 2], f64) {
    (items.iter())
        .find_map(|i| match i {
            Item::Circle { center, radius, .. } if *radius > 10.0 => Some((*center, *radius)),
            _ => None,
        })
        .expect("a wheel")
}

/// The corners of a block's outline.
fn block(items: &[Item]) -> Vec<[f64; 2]> {
    (items.iter())
        .find_map(|i| match i {
            Item::Stroke(s) if s.closed => Some(s.points.clone()),
            _ => None,
        })
        .expect("a block")
}

#[test]
fn the_racks_points_are_named_on_the_rack_not_inside_the_pinion() {
    let configuration = &pictures("rack-and-pinion", Method::MotionLaw)[0];
    for picture in [
        configuration.picture.clone(),
        configuration.laid_out_in(CONFIGURATION).into_owned(),
    ] {
        let (center, radius) = wheel(body(&picture, "P"));
        let corners = block(body(&picture, "R"));
        let top = corners.iter().map(|c| c[1]).fold(f64::INFINITY, f64::min);
        for name in ["S", "R^*"] {
            let at = label_at(&picture, name);
            let from_axle = (at[0] - center[0]).hypot(at[1] - center[1]);
            assert!(
                from_axle > radius,
                "{name} at {at:?}, inside the pinion ({center:?}, r = {radius})"
            );
            assert!(at[1] > top, "{name} at {at:?}, above the rack's top {top}");
        }
    }
}

#[test]
fn the_cart_is_drawn_about_its_mass_centre_with_the_pull_on_it() {
    let configuration = &pictures("disc-on-cart", Method::Kane)[0];
    let picture = &configuration.picture;
    let corners = block(body(picture, "C"));
    let (lo, hi) = corners
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
            (lo.min(c[0]), hi.max(c[0]))
        });
    let centre = (picture.marks.iter())
        .find(|m| m.id == "cm-C")
        .expect("the cart's mass centre")
        .at;
    assert!(
        (0.5 * (lo + hi) - centre[0]).abs() < 0.5,
        "C* at {centre:?}, the cart from {lo} to {hi}"
    );
    // P pulls along N.x: to the right on the page (gravity is down, N.x right).
    let pull = (picture.arrows.iter())
        .find(|a| a.kind == Kind::Load && a.label.plain == "P")
        .expect("the pull drawn in the configuration");
    assert!(pull.head[0] - pull.tail[0] > 20.0, "{pull:?}");
    assert!((pull.head[1] - pull.tail[1]).abs() < 1e-6, "{pull:?}");
}

#[test]
fn a_weight_hangs_from_its_mass_centre() {
    // A wheel on a pin at its centre (its vertical reaction drawn up from there), a ball
    // and a disc on their contacts (the normal force arriving at the contact below):
    // the weight is drawn from the mass centre itself, with no leader, and stops short of
    // the contact's point on its line. Each as drawn and as its handout prints it.
    for (name, method, body) in [
        ("gear-pair-torque", Method::MotionLaw, "A"),
        ("rack-and-pinion", Method::MotionLaw, "P"),
        ("bowling-ball", Method::MotionLaw, "B"),
        ("disc-in-cylinder", Method::Lagrange, "D"),
    ] {
        let pictures = pictures(name, method);
        let free_body = (pictures.iter())
            .find(|d| d.free_body == body)
            .unwrap_or_else(|| panic!("{name}: no free body {body}"));
        let printed = free_body.laid_out_in(BESIDE_A_TABLE);
        for picture in [&free_body.picture, printed.as_ref()] {
            let weight = (picture.arrows.iter())
                .find(|a| a.kind == Kind::Gravity)
                .expect("a weight");
            let centre = (picture.marks.iter())
                .find(|m| m.id == format!("cm-{body}"))
                .expect("the mass centre")
                .at;
            assert!(weight.leader.is_none(), "{name}: {weight:?}");
            let at = |p: [f64; 2]| (p[0] - centre[0]).hypot(p[1] - centre[1]) < 1e-6;
            assert!(at(weight.tail) || at(weight.head), "{name}: {weight:?}");
            // Straight down the page.
            assert!((weight.head[0] - weight.tail[0]).abs() < 1e-6, "{name}");
            assert!(weight.head[1] > weight.tail[1], "{name}");
            // Every other force's point straight below the centre lies past the tip.
            for other in picture
                .marks
                .iter()
                .filter(|m| m.id != format!("cm-{body}"))
            {
                let below = other.at[1] - centre[1];
                if (other.at[0] - centre[0]).abs() < 1.0 && below > 1.0 && weight.tail == centre {
                    assert!(
                        weight.head[1] < other.at[1],
                        "{name}: {weight:?} past {}",
                        other.id
                    );
                }
            }
        }
    }
}

#[test]
fn the_tops_picture_shows_the_frame_its_equations_use() {
    let path = problem_path("heavy-symmetric-top");
    let out = crate::support::run(&["explain", &path.to_string_lossy(), "--format", "html"]);
    assert!(out.status.success());
    let html = String::from_utf8_lossy(&out.stdout);
    let start = html.find("<svg").expect("a picture");
    let end = start + html[start..].find("</svg>").expect("its end");
    let configuration = &html[start..end];
    // Resal's frame A (â_x, â_y, â_z), which does not spin, not the top's own.
    assert!(
        configuration.contains("a\u{302}"),
        "no â in the configuration"
    );
    let spinning = ["x\u{302}", "y\u{302}", "z\u{302}"];
    assert!(
        !spinning.iter().any(|s| configuration.contains(s)),
        "the spinning frame's unit vectors drawn"
    );
}
