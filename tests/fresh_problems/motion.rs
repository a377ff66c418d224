//! Planar problems in motion: the second derivatives and the reactions of `solve` by every
//! method against closed forms, and the answers of a bar's questions (vectors in a named
//! frame, a steady state and its period, an identity).

use super::{at, close, command, solve_each, triple};

/// The bar: m, L, g, τ, the pin at 0.1 n̂_x. Its centre is at L/2 (−sin θ, cos θ) from the
/// pin and gravity is −g n̂_x, so the weight's moment about the pin is m g L/2 cos θ and
/// (m L²/3) θ̈ = m g L/2 cos θ + τ.
const BAR: (f64, f64, f64, f64) = (1.5, 0.8, 9.81, 2.0);

fn bar_acceleration(theta: f64) -> f64 {
    let (m, l, g, tau) = BAR;
    (m * g * l / 2.0 * theta.cos() + tau) / (m * l * l / 3.0)
}

/// The pin force on the bar in N: m a* − m g, g = −g n̂_x.
fn bar_pin_force(theta: f64, rate: f64, acc: f64) -> [f64; 2] {
    let (m, l, g, _) = BAR;
    let ax = l / 2.0 * (-theta.cos() * acc + theta.sin() * rate * rate);
    let ay = l / 2.0 * (-theta.sin() * acc - theta.cos() * rate * rate);
    [m * ax + m * g, m * ay]
}

#[test]
fn a_bar_under_sideways_gravity_by_every_method() {
    for (theta, rate) in [(0.4, 1.3), (2.5, -0.7), (-1.0, 0.0)] {
        let state = format!("theta={theta},theta'={rate}");
        for s in solve_each("bar-under-sideways-gravity", &["--state", &state]) {
            let what = format!("{} at {state}", s["method"]);
            let acc = bar_acceleration(theta);
            close(at(&s, &["accelerations", "theta"]), acc, &what);
            let f = triple(&s["reactions"]["O"]["force"]);
            let want = bar_pin_force(theta, rate, acc);
            close(f[0], want[0], &format!("{what}: F_x"));
            close(f[1], want[1], &format!("{what}: F_y"));
            close(f[2], 0.0, &format!("{what}: F_z"));
            let moment = triple(&s["reactions"]["O"]["moment"]);
            moment.iter().for_each(|c| close(*c, 0.0, &what));
        }
    }
}

fn component(answer: &serde_json::Value, axis: &str) -> f64 {
    at(answer, &["components", axis])
}

#[test]
fn the_bars_answers_in_its_own_frame_at_its_equilibrium_and_as_an_identity() {
    let (m, l, g, tau) = BAR;
    for method in crate::support::METHODS {
        let a = command("answer", "bar-under-sideways-gravity", method, &[]);
        let list = a["answers"].as_array().expect("answers");
        let (theta, rate) = (0.4, 1.3);
        let acc = bar_acceleration(theta);
        // The tip, L along the bar's ŷ: a = −L θ̈ b̂_x − L θ̇² b̂_y.
        assert_eq!(list[0]["kind"], "value");
        assert_eq!(list[0]["frame"], "bar", "{method}: `in` names the frame");
        close(component(&list[0], "x"), -l * acc, "tip b̂_x");
        close(component(&list[0], "y"), -l * rate * rate, "tip b̂_y");
        // The pin force, rotated into b̂_x = (cos θ, sin θ), b̂_y = (−sin θ, cos θ).
        let f = bar_pin_force(theta, rate, acc);
        let (c, s) = (theta.cos(), theta.sin());
        assert_eq!(list[1]["kind"], "reaction");
        assert_eq!(list[1]["frame"], "bar");
        close(component(&list[1], "x"), f[0] * c + f[1] * s, "pin b̂_x");
        close(component(&list[1], "y"), -f[0] * s + f[1] * c, "pin b̂_y");
        assert_eq!(
            list[2]["frame"], "N",
            "{method}: a reaction without `in` is in the parent's"
        );
        close(component(&list[2], "x"), f[0], "pin n̂_x");
        close(component(&list[2], "y"), f[1], "pin n̂_y");
        close(at(&list[3], &["value"]), acc, "θ̈");
        // Equilibrium: m g L/2 cos θ + τ = 0 on the side where the weight's moment restores.
        let theta_e = (-2.0 * tau / (m * g * l)).acos();
        assert_eq!(list[4]["kind"], "steady");
        close(at(&list[4], &["unknowns", "theta"]), theta_e, "θ at rest");
        // ω² = K/M: K = m g L/2 sin θₑ, M = m L²/3.
        let omega = ((m * g * l / 2.0 * theta_e.sin()) / (m * l * l / 3.0)).sqrt();
        assert_eq!(list[5]["kind"], "period");
        assert_eq!(list[5]["unit"], "s");
        close(
            at(&list[5], &["value"]),
            2.0 * std::f64::consts::PI / omega,
            "period",
        );
        assert_eq!(list[6]["kind"], "show");
        assert_eq!(
            list[6]["holds"], true,
            "{method}: the equation of motion holds"
        );
        close(at(&list[6], &["lhs"]), at(&list[6], &["rhs"]), "lhs = rhs");
        close(at(&list[6], &["lhs"]), m * l * l / 3.0 * acc, "lhs by hand");
    }
}

/// m ẍ = −k (x − x₀) − c ẋ − m g sin b + F cos(w t); the guide pushes m g cos b along the
/// normal (−sin b, cos b): the joint's own spring and damper are not counted in it.
#[test]
fn a_block_on_a_tilted_guide_with_spring_damper_and_a_pulse() {
    let (m, g, k, c, x0, b, f, w) = (2.0, 9.81, 50.0, 3.0, 0.2, 0.6f64, 4.0, 3.0);
    for (x, v, t) in [(0.05, -0.4, 0.0f64), (-0.3, 1.2, 0.7)] {
        let state = format!("x={x},x'={v}");
        let time = t.to_string();
        let args = ["--state", state.as_str(), "--time", time.as_str()];
        for s in solve_each("slider-on-tilted-guide", &args) {
            let what = format!("{} at {state}, t = {t}", s["method"]);
            let acc = (-k * (x - x0) - c * v - m * g * b.sin() + f * (w * t).cos()) / m;
            close(at(&s, &["accelerations", "x"]), acc, &what);
            let force = triple(&s["reactions"]["G"]["force"]);
            close(force[0], -m * g * b.cos() * b.sin(), &what);
            close(force[1], m * g * b.cos() * b.cos(), &what);
        }
    }
}

/// y = p x²: ẍ = −2 p x (g + 2 p ẋ²)/(1 + 4 p² x²), ÿ = 2 p (ẋ² + x ẍ).
#[test]
fn a_bead_on_a_parabolic_wire_held_by_a_position_constraint() {
    let (g, p) = (9.81, 1.5);
    for (x, v) in [(0.4, -0.9), (-0.7, 0.3)] {
        let state = format!("x={x},x'={v}");
        for s in solve_each("bead-on-parabola", &["--state", &state]) {
            let what = format!("{} at {state}", s["method"]);
            close(
                at(&s, &["state", "y"]),
                p * x * x,
                &format!("{what}: y assembled"),
            );
            close(
                at(&s, &["state", "y'"]),
                2.0 * p * x * v,
                &format!("{what}: y'"),
            );
            let ax = -2.0 * p * x * (g + 2.0 * p * v * v) / (1.0 + 4.0 * p * p * x * x);
            close(at(&s, &["accelerations", "x"]), ax, &what);
            close(
                at(&s, &["accelerations", "y"]),
                2.0 * p * (v * v + x * ax),
                &what,
            );
        }
    }
}

/// A hoop (I = m r²) at rest on a slope β: rolling needs F = m g sin β / 2 against
/// N = m g cos β, so it rolls (ẍ = g sin β / 2) while tan β ≤ 2μ, else slides with
/// ẍ = g (sin β − μ cos β) and turns at −μ g cos β / r.
#[test]
fn a_hoop_on_a_rough_incline_rolls_or_slides_by_tan_beta_against_two_mu() {
    let (m, r, g, beta) = (2.0, 0.3, 9.81, 0.5f64);
    for mu in [0.4, 0.1] {
        let set = format!("mu={mu}");
        for s in solve_each("hoop-on-rough-incline", &["--set", &set]) {
            let what = format!("{} with μ = {mu}", s["method"]);
            let site = &s["friction"]["slope"];
            let normal = m * g * beta.cos();
            close(at(site, &["normal"]), normal, &what);
            if beta.tan() <= 2.0 * mu {
                assert_eq!(site["mode"], "stick", "{what}");
                close(at(&s, &["accelerations", "x"]), g * beta.sin() / 2.0, &what);
                close(
                    at(&s, &["accelerations", "theta"]),
                    -g * beta.sin() / (2.0 * r),
                    &what,
                );
                close(at(site, &["tangential"]), m * g * beta.sin() / 2.0, &what);
                close(at(site, &["ratio"]), beta.tan() / 2.0, &what);
            } else {
                assert_eq!(site["mode"], "slip", "{what}");
                let ax = g * (beta.sin() - mu * beta.cos());
                close(at(&s, &["accelerations", "x"]), ax, &what);
                close(
                    at(&s, &["accelerations", "theta"]),
                    -mu * g * beta.cos() / r,
                    &what,
                );
                close(at(site, &["tangential"]), mu * normal, &what);
            }
            // The slope's force on the hoop, in N: friction up the slope, the normal push.
            let force = triple(&s["reactions"]["slope"]["force"]);
            close(force[1], normal, &what);
        }
    }
}

/// The cart's speed is held by a velocity constraint, ẍ = 0, so the bob swings as from a
/// fixed pin, θ̈ = −(g/L) sin θ; the pin pulls m (a_bob + g n̂_y), the rail holds the
/// cart's weight and the bob's pull, with no moment about the cart's origin.
#[test]
fn a_pendulum_on_a_cart_kept_at_a_set_speed_by_a_velocity_constraint() {
    let (big_m, m, l, g, v0) = (5.0, 0.7, 0.9, 9.81, 1.5);
    for (theta, rate) in [(0.6f64, -0.5), (-1.2, 2.0)] {
        let state = format!("theta={theta},theta'={rate}");
        for s in solve_each("pendulum-on-cart-at-set-speed", &["--state", &state]) {
            let what = format!("{} at {state}", s["method"]);
            close(
                at(&s, &["state", "x'"]),
                v0,
                &format!("{what}: x' from the constraint"),
            );
            close(at(&s, &["accelerations", "x"]), 0.0, &what);
            let acc = -g / l * theta.sin();
            close(at(&s, &["accelerations", "theta"]), acc, &what);
            let (c, sn) = (theta.cos(), theta.sin());
            let ax = l * (c * acc - sn * rate * rate);
            let ay = l * (sn * acc + c * rate * rate);
            let pin = triple(&s["reactions"]["pin"]["force"]);
            close(pin[0], m * ax, &format!("{what}: pin x"));
            close(pin[1], m * ay + m * g, &format!("{what}: pin y"));
            let rail = triple(&s["reactions"]["rail"]["force"]);
            close(
                rail[1],
                big_m * g + m * ay + m * g,
                &format!("{what}: rail y"),
            );
            close(
                rail[0],
                0.0,
                &format!("{what}: rail x, the guide's free direction"),
            );
            close(triple(&s["reactions"]["rail"]["moment"])[2], 0.0, &what);
        }
    }
}

/// The force that keeps the cart's speed works (its power is the force times v₀), so the
/// total energy is not a constant of the motion: `simulate` must not report a failed
/// energy check for equations that are right.
#[test]
fn the_set_speeds_force_works_and_no_energy_check_fails() {
    let path = super::fixture("pendulum-on-cart-at-set-speed");
    let out = crate::support::run(&[std::ffi::OsStr::new("simulate"), path.as_os_str()]);
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!err.contains("FAIL"), "no check fails:\n{err}");
    assert!(err.contains("agreement between methods"), "{err}");
}

/// "Does the hoop slip when let go?": at rest but in no equilibrium, the question is
/// answered as the motion starts, by the ratio rolling needs, tan β/(2μ).
#[test]
fn whether_the_hoop_slips_when_let_go_is_the_ratio_rolling_needs() {
    let beta = 0.5f64;
    for mu in [0.4, 0.1] {
        let set = format!("mu={mu}");
        for method in crate::support::METHODS {
            let a = command("answer", "hoop-on-rough-incline", method, &["--set", &set]);
            let answer = &a["answers"][0];
            let what = format!("{method}, μ = {mu}");
            assert_eq!(answer["kind"], "slips", "{what}");
            close(at(answer, &["ratio"]), beta.tan() / (2.0 * mu), &what);
            assert_eq!(answer["value"], beta.tan() > 2.0 * mu, "{what}: {answer}");
        }
    }
}

/// A ladder whose top a `position` entry keeps on the wall x = 0 (the foot at L sin θ):
/// its centre moves on a circle of radius L/2, so (m L²/3) θ̈ = m g L/2 sin θ whatever θ̇,
/// and the floor pushes m (g + ÿ*), ÿ* = −L/2 (sin θ θ̈ + cos θ θ̇²).
#[test]
fn a_ladder_on_a_smooth_wall_and_floor_by_a_position_entry() {
    let (m, l, g) = (12.0, 3.0, 9.81);
    for (theta, rate) in [(0.4f64, 0.3), (1.0, -1.5)] {
        let state = format!("theta={theta},theta'={rate}");
        for s in solve_each("ladder-against-smooth-wall", &["--state", &state]) {
            let what = format!("{} at {state}", s["method"]);
            close(at(&s, &["state", "x"]), l * theta.sin(), &what);
            close(at(&s, &["state", "x'"]), l * theta.cos() * rate, &what);
            let acc = 3.0 * g * theta.sin() / (2.0 * l);
            close(at(&s, &["accelerations", "theta"]), acc, &what);
            let x_acc = l * (theta.cos() * acc - theta.sin() * rate * rate);
            close(at(&s, &["accelerations", "x"]), x_acc, &what);
            let y_acc = -l / 2.0 * (theta.sin() * acc + theta.cos() * rate * rate);
            let floor = triple(&s["reactions"]["floor"]["force"]);
            close(
                floor[1],
                m * (g + y_acc),
                &format!("{what}: the floor's push"),
            );
        }
    }
}
