//! What a picture claims is what it draws: every angle of a planar configuration is an arc
//! (its sense shown by its head, turning the way the angle counts, a zero angle by the arc
//! of its positive sense, an angle below zero named −q); the legend names Newton's third
//! law exactly where a free body draws a reaction opposite the same unknown on its partner;
//! the kinetic diagram's moment vector does not leave the mass centre beside `m a*`; and the
//! HTML names each free body once, the configuration in a course's words with units.

use super::drawings;
use crate::support::{all_problems, problem as problem_path, run};
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::{
    Drawing, DrawnArrow, Ink, Item, Kind, Shape, View, ABOVE_A_TABLE, BESIDE_A_TABLE,
};
use mbd_tutor::solution::{FREE_BODY_LEGEND, FREE_BODY_LEGEND_THIRD_LAW, SLIDING_FRICTION};

type P2 = [f64; 2];

/// The picture's open grey strokes of one pixel: the angles' arcs.
fn arcs(items: &[Item], out: &mut Vec<Vec<P2>>) {
    for item in items {
        match item {
            Item::Stroke(s) if !s.closed && s.ink == Ink::Grey && s.width == 1.0 => {
                out.push(s.points.clone());
            }
            Item::Body { items, .. } | Item::Group { items, .. } => arcs(items, out),
            _ => {}
        }
    }
}

/// The radius (px) of the smallest wheel (a circle of at least 12 px) drawn about `c`.
fn wheel_about(items: &[Item], c: P2) -> Option<f64> {
    (items.iter())
        .filter_map(|item| match item {
            Item::Body { items, .. } | Item::Group { items, .. } => wheel_about(items, c),
            Item::Circle { center, radius, .. }
                if *radius >= 12.0 && (center[0] - c[0]).hypot(center[1] - c[1]) < 1.0 =>
            {
                Some(*radius)
            }
            _ => None,
        })
        .reduce(f64::min)
}

/// The turn from `a` to `b` about `c` on the page (radians; y down, so a turn
/// counterclockwise in `N` is negative here).
fn turn(c: P2, a: P2, b: P2) -> f64 {
    let (u, v) = ([a[0] - c[0], a[1] - c[1]], [b[0] - c[0], b[1] - c[1]]);
    (u[0] * v[1] - u[1] * v[0]).atan2(u[0] * v[0] + u[1] * v[1])
}

#[test]
fn every_angle_is_an_arc_turning_the_way_it_counts() {
    let mut checked = 0;
    for path in all_problems() {
        let problem = mbd_tutor::problem::load_file(&path).expect("a bundled problem");
        if problem.dimension != mbd_tutor::problem::Dimension::Two {
            continue;
        }
        let (_, pictures, _) = drawings(&problem, Method::MotionLaw, View::Isometric);
        let configuration = &pictures[0];
        let mut drawn = Vec::new();
        arcs(&configuration.picture.items, &mut drawn);
        let p = &configuration.picture.projection;
        for shape in &configuration.scene.shapes {
            let Shape::Angle {
                center,
                axis,
                angle,
                label,
                ..
            } = shape
            else {
                continue;
            };
            let c = p.point(*center);
            // An arc about the angle's centre: 30 px out, further for a short angle (up to
            // 45 px) or round a velocity's arrow (48 px); about a wheel's centre, at 0.7 of
            // the wheel's radius where that is less (inside the wheel).
            let inside = wheel_about(&configuration.picture.items, c).map(|rim| 0.7 * rim);
            let arc = (drawn.iter())
                .find(|a| {
                    let r = (a[0][0] - c[0]).hypot(a[0][1] - c[1]);
                    a.len() > 10
                        && ((29.5..60.5).contains(&r)
                            || inside.is_some_and(|w| (r - w).abs() < 0.5))
                        && a.iter()
                            .all(|q| ((q[0] - c[0]).hypot(q[1] - c[1]) - r).abs() < 0.5)
                })
                .unwrap_or_else(|| panic!("{}: no arc for {}", path.display(), label.plain));
            let sweep: f64 = arc.windows(2).map(|w| turn(c, w[0], w[1])).sum();
            let r = (arc[0][0] - c[0]).hypot(arc[0][1] - c[1]);
            // Counterclockwise about its axis: clockwise on the page for N.z (out of the
            // page); never a dot, and long enough to carry its head (8 px) where its radius
            // allows.
            assert!(
                sweep * axis[2].signum() < -0.14
                    && (r * sweep.abs() >= 27.0
                        || r > 44.5
                        || inside.is_some_and(|w| (r - w).abs() < 0.5)),
                "{}: {} swept {sweep} at {r} px",
                path.display(),
                label.plain
            );
            assert!(*angle >= 0.0 || angle.abs() < 0.15, "{}", path.display());
            checked += 1;
        }
    }
    assert!(checked >= 10, "only {checked} angles");
}

#[test]
fn a_zero_angle_shows_its_positive_sense_and_one_below_zero_is_named_minus() {
    let load = |name: &str| {
        let problem = mbd_tutor::problem::load_file(&problem_path(name)).expect("a problem");
        let (_, pictures, _) = drawings(&problem, Method::MotionLaw, View::Isometric);
        pictures.into_iter().next().expect("a configuration")
    };
    let angles = |d: &Drawing| -> Vec<(String, f64)> {
        (d.scene.shapes.iter())
            .filter_map(|s| match s {
                Shape::Angle { label, angle, .. } => Some((label.plain.clone(), *angle)),
                _ => None,
            })
            .collect()
    };
    // The ball's θ is 0 at release: an arc of 45°, named θ.
    let ball = angles(&load("bowling-ball"));
    assert_eq!(ball, vec![("θ".to_string(), 0.0)]);
    // The double pendulum's q₂ = −0.4: the arc from B back to where it lay, named −q₂ (a minus sign, not a hyphen).
    let pendulum = angles(&load("double-pendulum-rods"));
    assert!(
        pendulum
            .iter()
            .any(|(l, a)| l == "\u{2212}q_2" && (a - 0.4).abs() < 1e-9),
        "{pendulum:?}"
    );
}

#[test]
fn the_legend_names_the_third_law_where_a_reaction_is_drawn_opposite_its_partner() {
    let mut third_law = 0;
    for path in all_problems() {
        let problem = mbd_tutor::problem::load_file(&path).expect("a bundled problem");
        let (_, pictures, _) = drawings(&problem, Method::NewtonEuler, View::Isometric);
        let free_bodies: Vec<&Drawing> = pictures
            .iter()
            .filter(|d| !d.free_body.is_empty())
            .collect();
        let reactions = |d: &Drawing| -> Vec<(String, [f64; 3])> {
            (d.scene.arrows.iter())
                .filter(|a| a.kind == Kind::Reaction)
                .map(|a| (a.label.plain.clone(), a.direction))
                .collect()
        };
        // A free body that draws an unknown opposite the way another free body draws it.
        let opposite = |d: &Drawing| {
            reactions(d).iter().any(|(label, u)| {
                free_bodies.iter().any(|o| {
                    o.name != d.name
                        && reactions(o).iter().any(|(l, v)| {
                            l == label && u[0] * v[0] + u[1] * v[1] + u[2] * v[2] < -0.99
                        })
                })
            })
        };
        for d in &free_bodies {
            // A sliding friction adds its clause; the rest is one of the two legends.
            let legend = d.scene.legend.replace(SLIDING_FRICTION, "");
            let legend = legend.as_str();
            assert!(
                legend == FREE_BODY_LEGEND || legend == FREE_BODY_LEGEND_THIRD_LAW,
                "{legend}"
            );
            if legend == FREE_BODY_LEGEND_THIRD_LAW {
                // Claimed: some unknown of it is its partner's, drawn the other way.
                assert!(opposite(d), "{}: {}", path.display(), d.name);
                third_law += 1;
            }
        }
        // Every pair drawn opposite has the claim on one of its two free bodies.
        for d in free_bodies.iter().filter(|d| opposite(d)) {
            let partners = free_bodies.iter().filter(|o| {
                reactions(o)
                    .iter()
                    .any(|(l, _)| reactions(d).iter().any(|(m, _)| l == m))
            });
            assert!(
                partners
                    .clone()
                    .any(|o| o.scene.legend == FREE_BODY_LEGEND_THIRD_LAW),
                "{}: {} and its partner say only + axes",
                path.display(),
                d.name
            );
        }
    }
    assert!(
        third_law > 5,
        "only {third_law} free bodies name the third law"
    );
}

#[test]
fn the_moment_vector_does_not_lie_beside_m_a() {
    // The arm's end effector: in the isometric view its Ḣ and m a* point nearly one way
    // from a link drawn along them, and every spot tried lies on another arrow. The top as
    // its page prints it (the labels grown): its m a* moved off the rod lands beside Ḣ.
    // Both still to be fixed.
    const KNOWN: [&str; 2] = ["arm-3d-rrp", "heavy-symmetric-top"];
    for path in all_problems() {
        let stem = path.file_stem().unwrap_or_default().to_string_lossy();
        if KNOWN.contains(&stem.as_ref()) {
            continue;
        }
        let problem = mbd_tutor::problem::load_file(&path).expect("a bundled problem");
        let (_, pictures, _) = drawings(&problem, Method::MotionLaw, View::Isometric);
        // As drawn, and as a page prints a free body beside its table or above it.
        let printed: Vec<_> = (pictures.iter().filter(|d| !d.free_body.is_empty()))
            .flat_map(|d| {
                [BESIDE_A_TABLE, ABOVE_A_TABLE].map(|room| d.laid_out_in(room).into_owned())
            })
            .chain(pictures.iter().map(|d| d.picture.clone()))
            .collect();
        for picture in &printed {
            let grow = picture.grow;
            let inertia: Vec<_> = (picture.arrows.iter())
                .filter(|a| a.kind == Kind::Inertia && a.arc.is_none())
                .collect();
            for (i, a) in inertia.iter().enumerate() {
                // One body's moment vector and its own m a*.
                let own = |b: &&&DrawnArrow| a.couple != b.couple && a.at_id == b.at_id;
                for b in inertia[i + 1..].iter().filter(own) {
                    let (u, v) = (
                        [a.head[0] - a.tail[0], a.head[1] - a.tail[1]],
                        [b.head[0] - b.tail[0], b.head[1] - b.tail[1]],
                    );
                    let cos = (u[0] * v[0] + u[1] * v[1]) / (u[0].hypot(u[1]) * v[0].hypot(v[1]));
                    // A point of the first's middle within 10 px of the second.
                    let near = (1..=4).any(|k| {
                        let t = f64::from(k) / 5.0;
                        let p = [a.tail[0] + t * u[0], a.tail[1] + t * u[1]];
                        super::overlap::to_segment(p, (b.tail, b.head)) < 10.0 * grow
                    });
                    assert!(
                        !(near && cos.abs() > 30f64.to_radians().cos()),
                        "{}: {} and {} side by side",
                        path.display(),
                        a.label.plain,
                        b.label.plain
                    );
                }
            }
        }
    }
}

#[test]
fn the_html_names_a_free_body_once_and_the_configuration_with_units() {
    let html = |name: &str, method: &str| {
        let path = problem_path(name);
        let out = run(&[
            "explain",
            &path.to_string_lossy(),
            "--method",
            method,
            "--format",
            "html",
        ]);
        assert!(out.status.success());
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let ball = html("bowling-ball", "motion-law");
    assert!(ball.contains("<h3>Free body"), "no heading");
    assert!(
        !ball.contains(">Free body B</text>"),
        "the title drawn again"
    );
    assert!(
        ball.contains(">The configuration at the start: x = 0 m, y = 0.11 m, θ = 0 rad</text>"),
        "no course caption"
    );
    assert!(!ball.contains("Configuration at"));
    let pendulum = html("double-pendulum-rods", "kane");
    assert!(
        pendulum.contains("q₁ = 0.7 rad, q₂ = \u{2212}0.4 rad"),
        "no minus sign or units"
    );
    // The top's φ as the LaTeX sets \phi.
    let top = html("heavy-symmetric-top", "motion-law");
    let caption = top
        .split("The configuration at the start: ")
        .nth(1)
        .and_then(|s| s.split("</text>").next())
        .expect("the caption");
    assert!(caption.contains('ϕ') && !caption.contains('φ'), "{caption}");
}
