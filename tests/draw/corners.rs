//! Where a textbook puts what it draws: a rack's and a cart's mass centre halfway down the
//! block and the point it slides on at its underside; a ladder's wall and floor meeting at
//! their corner; every point a picture names defined in the text of step 1.

use super::drawings;
use crate::support::{all_problems, between, explain_file, problem as problem_path};
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::{Drawing, Shape, View};

type P3 = [f64; 3];

fn configuration(name: &str) -> Drawing {
    let problem = mbd_tutor::problem::load_file(&problem_path(name)).expect("a bundled problem");
    let (_, pictures, _) = drawings(&problem, Method::MotionLaw, View::Isometric);
    pictures.into_iter().next().expect("a configuration")
}

fn marker(d: &Drawing, caption: &str) -> P3 {
    (d.scene.markers.iter())
        .find(|m| m.caption.as_ref().is_some_and(|c| c.tex == caption))
        .unwrap_or_else(|| panic!("{caption} is marked"))
        .at
}

/// The top and bottom heights of body `name`'s block, in N.y.
fn block(d: &Drawing, name: &str) -> (f64, f64) {
    let parts = (d.scene.shapes.iter())
        .find_map(|s| match s {
            Shape::Body { name: n, parts, .. } if n == name => Some(parts),
            _ => None,
        })
        .unwrap_or_else(|| panic!("{name} is drawn"));
    let Some(Shape::Polygon(corners)) = parts.first() else {
        panic!("{name} is a block: {parts:?}");
    };
    let ys = corners.iter().map(|c| c[1]);
    (
        ys.clone().fold(f64::MIN, f64::max),
        ys.fold(f64::MAX, f64::min),
    )
}

/// The rack's mass centre is b = 0.02 m below its pitch line and it slides at its
/// underside, 2b down; the cart's is c = 0.06 m below its top, its underside 2c down.
/// Each block is drawn from its face to its underside: the centre halfway, S on the bottom.
#[test]
fn a_carrier_is_as_deep_as_given_its_centre_halfway_and_it_slides_at_its_underside() {
    for (name, body, centre, depth) in [
        ("rack-and-pinion", "R", "R^*", 0.04),
        ("disc-on-cart", "C", "C^*", 0.12),
    ] {
        let d = configuration(name);
        let (top, bottom) = block(&d, body);
        assert!(
            (top - bottom - depth).abs() < 1e-9,
            "{name}: depth {}",
            top - bottom
        );
        let c = marker(&d, centre);
        assert!(
            (c[1] - 0.5 * (top + bottom)).abs() < 1e-9,
            "{name}: {centre} at {c:?}"
        );
        let s = marker(&d, "S");
        assert!(
            (s[1] - bottom).abs() < 1e-9,
            "{name}: S at {s:?}, bottom {bottom}"
        );
    }
}

/// The ladder's wall (x = 0) and floor (y = 0) are drawn to their corner, the origin.
#[test]
fn a_wall_and_a_floor_meet_at_their_corner() {
    let d = configuration("ladder-about-to-slip");
    let ends: Vec<(P3, P3)> = (d.scene.shapes.iter())
        .filter_map(|s| match s {
            Shape::Surface {
                at,
                along,
                fixed: true,
                ..
            } => Some((
                std::array::from_fn(|i| at[i] - along[i]),
                std::array::from_fn(|i| at[i] + along[i]),
            )),
            _ => None,
        })
        .collect();
    assert_eq!(ends.len(), 2, "{ends:?}");
    for (a, b) in ends {
        let at_corner = |p: P3| p[0].abs() < 1e-9 && p[1].abs() < 1e-9;
        assert!(at_corner(a) || at_corner(b), "{a:?} to {b:?}");
    }
}

/// Every point a configuration names by one capital letter (a joint's S, a contact's U)
/// is named in the text of step 1 as well: the coordinates' table or the notes under it.
#[test]
fn every_point_a_picture_names_is_named_in_step_one() {
    let mut faults = Vec::new();
    for path in all_problems() {
        let Ok(problem) = mbd_tutor::problem::load_file(&path) else {
            continue;
        };
        if problem.dimension != mbd_tutor::problem::Dimension::Two {
            continue;
        }
        let (_, pictures, _) = drawings(&problem, Method::MotionLaw, View::Isometric);
        let Some(d) = pictures.first() else { continue };
        let text = explain_file(&path, &["--method", "motion-law", "--format", "markdown"]);
        let step1 = between(&text, "## Step 1", "## Step 2");
        let words: String = step1.lines().filter(|l| !l.starts_with('<')).collect();
        for m in &d.scene.markers {
            let Some(caption) = &m.caption else { continue };
            for name in caption.plain.split(", ") {
                let letter = name.len() == 1 && name.chars().all(|c| c.is_ascii_uppercase());
                let said = [
                    format!("point {name}"),
                    format!("pin {name}"),
                    format!("{name} is"),
                ]
                .iter()
                .any(|w| words.contains(w.as_str()));
                if letter && !said {
                    faults.push(format!("{}: {name}", path.display()));
                }
            }
        }
    }
    assert!(faults.is_empty(), "{faults:#?}");
}
