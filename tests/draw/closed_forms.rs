//! Whole pictures against what is known without the program: the double pendulum's points
//! where the closed form puts them, the isometric and front views' projections, and the
//! same picture every time.

use super::{drawings, read};
use crate::support::problem as problem_path;
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::View;

#[test]
fn the_double_pendulum_is_where_the_closed_form_puts_it() {
    let problem =
        mbd_tutor::problem::load_file(&problem_path("double-pendulum-rods")).expect("bundled");
    let (_, pictures, _) = drawings(&problem, Method::MotionLaw, View::Isometric);
    let r = read("double pendulum", &pictures[0].svg(""));
    let (q1, q2, l1, l2) = (0.7f64, -0.4f64, 0.6, 0.4);
    let p = [l1 * q1.sin(), -l1 * q1.cos(), 0.0];
    let expected = [
        ("joint-O", [0.0, 0.0, 0.0]),
        ("joint-P", p),
        ("cm-A", [p[0] / 2.0, p[1] / 2.0, 0.0]),
        (
            "cm-B",
            [
                p[0] + l2 / 2.0 * (q1 + q2).sin(),
                p[1] - l2 / 2.0 * (q1 + q2).cos(),
                0.0,
            ],
        ),
    ];
    for (id, at) in expected {
        let want = r.project(at);
        let got = r.points[id];
        assert!(
            (want[0] - got[0]).hypot(want[1] - got[1]) < 0.01,
            "{id}: {got:?} vs {want:?}"
        );
    }
}

#[test]
fn spatial_pictures_default_to_the_isometric_view_and_take_another() {
    let problem =
        mbd_tutor::problem::load_file(&problem_path("heavy-symmetric-top")).expect("bundled");
    let (_, pictures, _) = drawings(&problem, Method::MotionLaw, View::Isometric);
    let p = read("top", &pictures[0].svg("")).projection;
    let s = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
    let right = [-1.0 / 2f64.sqrt(), 1.0 / 2f64.sqrt(), 0.0];
    let down = [1.0 / 6f64.sqrt(), 1.0 / 6f64.sqrt(), -2.0 / 6f64.sqrt()];
    for k in 0..3 {
        assert!(
            (p[k] / s - right[k]).abs() < 1e-9 && (p[3 + k] / s - down[k]).abs() < 1e-9,
            "{p:?}"
        );
    }
    let (_, pictures, _) = drawings(
        &problem,
        Method::MotionLaw,
        View::parse("front").expect("a view"),
    );
    let p = read("top", &pictures[0].svg("")).projection;
    assert!(
        p[1] == 0.0 && p[2] == 0.0 && p[3] == 0.0 && p[4] == 0.0 && p[0] > 0.0 && p[5] < 0.0,
        "{p:?}"
    );
}

#[test]
fn pictures_are_the_same_every_time() {
    let problem =
        mbd_tutor::problem::load_file(&problem_path("floating-plate-springs")).expect("bundled");
    let once: Vec<String> = drawings(&problem, Method::MotionLaw, View::Isometric)
        .1
        .iter()
        .map(|d| d.svg("") + &d.tikz())
        .collect();
    let twice: Vec<String> = drawings(&problem, Method::MotionLaw, View::Isometric)
        .1
        .iter()
        .map(|d| d.svg("") + &d.tikz())
        .collect();
    assert_eq!(once, twice);
}
