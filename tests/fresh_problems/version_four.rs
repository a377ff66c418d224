//! Version 4's answers on problems the bundled set does not hold, each against a closed
//! form written here: a block held to a sloping line by a `position` constraint and a disc
//! rolling down an incline (Lagrange's multipliers among the four methods), a swinging
//! bar's pin force in two frames (`in`), `show` and `period`, a block on a spring on a
//! slope (`steady` then `period` about it), and a spinning disc dropped on a rough floor.

use super::{at, close, command, solve_each, triple};
use crate::support::METHODS;
use std::f64::consts::PI;

const G: f64 = 9.81;

/// The block on the line y = x tan α, pushed by P along N.x: s̈ = (P cos α − m g sin α)/m
/// along the line, so ẍ = s̈ cos α, ÿ = s̈ sin α, and it does not turn.
#[test]
fn a_block_on_a_line_by_a_position_constraint_by_every_method() {
    let (m, al, p) = (2.5, 0.45f64, 6.0);
    let s = (p * al.cos() - m * G * al.sin()) / m;
    for sol in solve_each("block-on-line-by-constraint", &[]) {
        let what = format!("{}", sol["method"]);
        close(at(&sol, &["state", "y"]), 0.4 * al.tan(), &what);
        close(at(&sol, &["state", "y'"]), 0.5 * al.tan(), &what);
        close(at(&sol, &["accelerations", "x"]), s * al.cos(), &what);
        close(at(&sol, &["accelerations", "y"]), s * al.sin(), &what);
        close(at(&sol, &["accelerations", "th"]), 0.0, &what);
    }
}

/// The disc (I = k m R²) rolls down the slope of angle β: a = g sin β/(1 + k) along
/// t = (cos β, −sin β), θ̈ = −a/R; the ground pushes m g cos β along the normal and holds
/// it back by the friction k m a up the slope.
#[test]
fn a_disc_rolling_down_an_incline_gives_the_ground_force_by_every_method() {
    let (m, r, be, k) = (2.0, 0.3, 0.35f64, 0.5);
    let a = G * be.sin() / (1.0 + k);
    let (normal, friction) = (m * G * be.cos(), k * m * a);
    let force = [
        normal * be.sin() - friction * be.cos(),
        normal * be.cos() + friction * be.sin(),
    ];
    for method in METHODS {
        let sol = command("solve", "disc-rolls-down-incline-planar", method, &[]);
        let what = format!("{method}: disc on the incline");
        close(at(&sol, &["accelerations", "x"]), a * be.cos(), &what);
        close(at(&sol, &["accelerations", "y"]), -a * be.sin(), &what);
        close(at(&sol, &["accelerations", "th"]), -a / r, &what);
        let v = 0.4 / be.cos();
        close(at(&sol, &["state", "th'"]), -v / r, &what);
        close(at(&sol, &["state", "y'"]), -v * be.sin(), &what);
        let f = triple(&sol["reactions"]["slope"]["force"]);
        close(f[0], force[0], &what);
        close(f[1], force[1], &what);
        let ans = command("answer", "disc-rolls-down-incline-planar", method, &[]);
        let first = &ans["answers"][0];
        assert_eq!(first["frame"], "N", "{what}: {first}");
        close(at(first, &["components", "x"]), force[0], &what);
        close(at(first, &["components", "y"]), force[1], &what);
    }
}

/// The bar (m, L, about its end O, θ from the downward vertical): θ̈ = −3g/(2L) sin θ;
/// a* = (L/2) θ̈ â_x + (L/2) θ̇² â_y, and the pin's force m a* + m g n̂_y is, along the
/// bar's unit vectors, (m g sin θ/4, m (L/2) θ̇² + m g cos θ). Small swings: T = 2π√(2L/3g).
#[test]
fn a_bar_answers_in_its_own_axes_and_the_grounds_and_shows_its_equation() {
    let (m, l, th, w) = (1.2, 0.9, 0.7f64, 1.8);
    let alpha = -3.0 * G / (2.0 * l) * th.sin();
    let in_a = [
        m * l / 2.0 * alpha + m * G * th.sin(),
        m * l / 2.0 * w * w + m * G * th.cos(),
    ];
    // â_x = (cos θ, sin θ), â_y = (−sin θ, cos θ) in N.
    let to_n = |v: [f64; 2]| {
        [
            v[0] * th.cos() - v[1] * th.sin(),
            v[0] * th.sin() + v[1] * th.cos(),
        ]
    };
    let in_n = to_n(in_a);
    let speed = to_n([l / 2.0 * w, 0.0]);
    for method in METHODS {
        let ans = command("answer", "rod-pendulum-in-frames", method, &[]);
        let list = ans["answers"].as_array().expect("answers");
        let what = |i: usize| format!("{method}: answer {i}: {}", list[i]);
        for (i, frame, want) in [(0, "N", in_n), (1, "A", in_a)] {
            assert_eq!(list[i]["kind"], "reaction", "{}", what(i));
            assert_eq!(list[i]["frame"], frame, "{}", what(i));
            close(at(&list[i], &["components", "x"]), want[0], &what(i));
            close(at(&list[i], &["components", "y"]), want[1], &what(i));
            close(at(&list[i], &["components", "z"]), 0.0, &what(i));
        }
        assert_eq!(list[2]["frame"], "A", "{}", what(2));
        close(
            at(&list[2], &["components", "x"]),
            l / 2.0 * alpha,
            &what(2),
        );
        close(
            at(&list[2], &["components", "y"]),
            l / 2.0 * w * w,
            &what(2),
        );
        assert_eq!(list[3]["frame"], "N", "{}", what(3));
        close(at(&list[3], &["components", "x"]), speed[0], &what(3));
        close(at(&list[3], &["components", "y"]), speed[1], &what(3));
        assert_eq!(list[4]["kind"], "show", "{}", what(4));
        assert_eq!(list[4]["holds"], true, "{}", what(4));
        close(at(&list[4], &["lhs"]), alpha, &what(4));
        close(at(&list[4], &["rhs"]), alpha, &what(4));
        assert_eq!(list[5]["holds"], false, "{}", what(5));
        close(at(&list[5], &["rhs"]), -G / l * th.sin(), &what(5));
        let period = 2.0 * PI * (2.0 * l / (3.0 * G)).sqrt();
        close(at(&list[6], &["value"]), period, &what(6));
        assert_eq!(list[6]["unit"], "s", "{}", what(6));
    }
}

/// The block on the spring along the slope rests at s = −m g sin α / k and swings about it
/// with T = 2π √(m/k), whatever the slope.
#[test]
fn a_block_on_a_spring_on_a_slope_rests_and_swings_about_its_rest() {
    let (m, k, al) = (3.0f64, 240.0, 0.5f64);
    let period = 2.0 * PI * (m / k).sqrt();
    for method in METHODS {
        let ans = command("answer", "block-on-spring-on-slope", method, &[]);
        let list = ans["answers"].as_array().expect("answers");
        let what = format!("{method}: {ans}");
        assert_eq!(list[0]["kind"], "steady", "{what}");
        close(
            at(&list[0], &["unknowns", "s"]),
            -m * G * al.sin() / k,
            &what,
        );
        close(at(&list[1], &["value"]), period, &what);
        close(at(&list[2], &["value"]), period, &what);
    }
}

/// The disc (I = m R²/2) strikes the floor with its lowest point at (u + ωR, −v):
/// P_n = m (1 + e) v; the tangential impulse that stops the slip s = u + ωR is
/// s/(1/m + R²/I), allowed up to μ P_n, else μ P_n against the slip; then
/// u⁺ = u − P_t/m and ω⁺ = ω − R P_t/I.
#[test]
fn a_spinning_disc_dropped_on_a_rough_floor_sticks_or_slides() {
    let (m, r, u, v, w, e) = (1.5f64, 0.25, 1.2, 3.0, 6.0, 0.5);
    let i = m * r * r / 2.0;
    for mu in [0.3, 0.1] {
        let set = format!("mu={mu}");
        let normal = m * (1.0 + e) * v;
        let slip = u + w * r;
        let stop = slip / (1.0 / m + r * r / i);
        let tangential = stop.min(mu * normal);
        let (u_after, w_after) = (u - tangential / m, w - r * tangential / i);
        let energy = |u: f64, y: f64, w: f64| 0.5 * m * (u * u + y * y) + 0.5 * i * w * w;
        for method in METHODS {
            let what = format!("{method}, μ = {mu}");
            let s = command(
                "impact",
                "spinning-disc-drops-on-rough-floor",
                method,
                &["--set", &set],
            );
            close(at(&s, &["after", "y'"]), e * v, &what);
            close(at(&s, &["after", "x'"]), u_after, &what);
            close(at(&s, &["after", "th'"]), w_after, &what);
            let blow = triple(&s["impulses"]["floor"]);
            close(blow[0], -tangential, &what);
            close(blow[1], normal, &what);
            close(at(&s, &["energy", "before"]), energy(u, -v, w), &what);
            close(
                at(&s, &["energy", "after"]),
                energy(u_after, e * v, w_after),
                &what,
            );
            let a = command(
                "answer",
                "spinning-disc-drops-on-rough-floor",
                method,
                &["--set", &set],
            );
            close(at(&a["answers"][0], &["value"]), u_after, &what);
            close(at(&a["answers"][1], &["value"]), w_after, &what);
        }
    }
}
