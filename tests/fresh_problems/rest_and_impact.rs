//! Impacts with restitution and friction, statics with friction at impending slip and tip,
//! and a held coordinate, against closed forms, by every method.

use super::{at, close, command, triple};
use crate::support::METHODS;

/// The rod (m, L, I = m L²/12) tilted θ, its lower end r = −L/2 (cos θ, sin θ) from the
/// centre, strikes the smooth floor: P = −(1 + e) v⁻ₙ / (1/m + r_x²/I), v⁻ₙ = ẏ + ω r_x;
/// then ẏ⁺ = ẏ + P/m, ω⁺ = ω + r_x P / I, ẋ unchanged.
#[test]
fn a_tilted_rod_bounces_on_a_smooth_floor_with_restitution() {
    let (m, l, th, x_rate, y_rate, w) = (1.6, 1.0, 0.5f64, 0.3, -2.5, 0.7);
    let i = m * l * l / 12.0;
    for e in [0.6, 0.0, 1.0] {
        let set = format!("e={e}");
        let rx = -l / 2.0 * th.cos();
        let vn = y_rate + w * rx;
        let p = -(1.0 + e) * vn / (1.0 / m + rx * rx / i);
        let (y_after, w_after) = (y_rate + p / m, w + rx * p / i);
        let energy = |y: f64, w: f64| 0.5 * m * (x_rate * x_rate + y * y) + 0.5 * i * w * w;
        for method in METHODS {
            let s = command(
                "impact",
                "tilted-rod-drops-on-floor",
                method,
                &["--set", &set],
            );
            let what = format!("{method}, e = {e}");
            assert_eq!(s["method"], method);
            close(at(&s, &["before", "y'"]), y_rate, &what);
            close(at(&s, &["after", "x'"]), x_rate, &what);
            close(at(&s, &["after", "y'"]), y_after, &what);
            close(at(&s, &["after", "theta'"]), w_after, &what);
            let blow = triple(&s["impulses"]["floor"]);
            close(blow[0], 0.0, &what);
            close(blow[1], p, &what);
            close(at(&s, &["energy", "before"]), energy(y_rate, w), &what);
            close(
                at(&s, &["energy", "after"]),
                energy(y_after, w_after),
                &what,
            );
            // The end leaves the floor at −e times the speed it struck with.
            close(y_after + w_after * rx, -e * vn, &what);
        }
    }
}

/// A ball (u, −v) on a rough floor: P_n = m (1 + e) v; the tangential impulse that stops
/// the slip is m u, allowed while m u ≤ μ P_n, else μ P_n against the slip.
#[test]
fn a_ball_striking_a_rough_floor_sticks_or_slides() {
    let (m, u, v, e) = (0.3, 2.0, 3.0, 0.5);
    for mu in [0.2, 0.9] {
        let set = format!("mu={mu}");
        let normal = m * (1.0 + e) * v;
        let sticks = m * u <= mu * normal;
        let tangential = if sticks { m * u } else { mu * normal };
        for method in METHODS {
            let what = format!("{method}, μ = {mu}");
            let s = command(
                "impact",
                "ball-strikes-rough-floor",
                method,
                &["--set", &set],
            );
            close(at(&s, &["after", "y'"]), e * v, &what);
            close(at(&s, &["after", "x'"]), u - tangential / m, &what);
            let blow = triple(&s["impulses"]["floor"]);
            close(blow[0], -tangential, &what);
            close(blow[1], normal, &what);
            let a = command(
                "answer",
                "ball-strikes-rough-floor",
                method,
                &["--set", &set],
            );
            close(at(&a["answers"][0], &["value"]), u - tangential / m, &what);
        }
    }
}

/// The crate (m, w × H) pushed by P at height h from its back edge: about the front corner,
/// N_back = (m g w/2 − P h)/w, N_front = m g − N_back; friction carries P, shared at the
/// same ratio P/(μ m g). Tipping impends at P = m g w/(2h), sliding at P = μ m g.
#[test]
fn a_crate_pushed_high_slips_or_tips_at_rest() {
    let (m, g, w, h, mu) = (20.0, 9.81, 0.6, 0.8, 0.4);
    for method in METHODS {
        for p in [40.0, 60.0] {
            let set = format!("P={p}");
            let s = command("statics", "crate-pushed-high", method, &["--set", &set]);
            assert_eq!(s["method"], method);
            let eq = &s["equilibria"][0];
            let what = format!("{method}, P = {p}");
            let back = (m * g * w / 2.0 - p * h) / w;
            let front = m * g - back;
            close(triple(&eq["reactions"]["back"]["force"])[1], back, &what);
            close(triple(&eq["reactions"]["front"]["force"])[1], front, &what);
            close(at(&eq["friction"]["back"], &["normal"]), back, &what);
            close(at(&eq["friction"]["front"], &["normal"]), front, &what);
            let ratio = p / (mu * m * g);
            close(at(&eq["friction"]["back"], &["ratio"]), ratio, &what);
            close(at(&eq["friction"]["front"], &["ratio"]), ratio, &what);
            let total = at(&eq["friction"]["back"], &["tangential"])
                + at(&eq["friction"]["front"], &["tangential"]);
            close(total, p, &what);
            assert!(
                eq["held"].as_object().is_some_and(|o| o.is_empty()),
                "{what}"
            );
        }
        // Pushed low (h = 0.3 m) with 80 N it slides before it tips; high (0.8 m) with
        // 70 N it does neither.
        for (p, h, slides) in [(80.0, 0.3, true), (70.0, 0.8, false)] {
            let set = format!("P={p},h={h}");
            let a = command("answer", "crate-pushed-high", method, &["--set", &set]);
            let list = a["answers"].as_array().expect("answers");
            let what = format!("{method}, {set}");
            let back = (m * g * w / 2.0 - p * h) / w;
            assert_eq!(list[0]["kind"], "tips");
            assert_eq!(
                list[0]["value"], false,
                "{what}: the back corner stays down"
            );
            close(at(&list[0], &["normal"]), back, &what);
            assert_eq!(list[1]["kind"], "slips");
            assert_eq!(list[1]["value"], slides, "{what}");
            close(at(&list[1], &["ratio"]), p / (mu * m * g), &what);
        }
        let a = command("answer", "crate-pushed-high", method, &[]);
        let list = a["answers"].as_array().expect("answers");
        assert_eq!(list[2]["kind"], "impending");
        close(at(&list[2], &["value"]), m * g * w / (2.0 * h), method);
        close(at(&list[3], &["value"]), mu * m * g, method);
    }
}

/// The arm held at θ₀ (joint spring k at O), a collar of mass m₂ on a spring k₂ about s₀
/// along it. At rest s = s₀ − m₂ g sin θ₀ / k₂ and the holding torque is
/// k θ₀ + (m g L/2 + m₂ g s) cos θ₀; the pin carries the whole weight; the collar swings at
/// √(k₂/m₂). In motion from s = 0.5 the same torque holds (θ̇ = 0, no Coriolis term).
#[test]
fn an_arm_held_at_an_angle_with_a_sprung_collar() {
    let (m, l, g, k, th, m2, k2, s0) = (2.0, 1.2, 9.81, 30.0, 0.5f64, 0.8, 60.0, 0.6);
    let hold = |s: f64| k * th + (m * g * l / 2.0 + m2 * g * s) * th.cos();
    for method in METHODS {
        let st = command("statics", "arm-held-with-slider", method, &[]);
        let eq = &st["equilibria"][0];
        let s = s0 - m2 * g * th.sin() / k2;
        close(at(eq, &["state", "s"]), s, method);
        close(at(eq, &["state", "theta"]), th, method);
        close(at(eq, &["held", "theta"]), hold(s), method);
        let pin = triple(&eq["reactions"]["O"]["force"]);
        close(pin[0], 0.0, method);
        close(pin[1], (m + m2) * g, method);
        assert_eq!(eq["stability"], "stable", "{method}");
        let omega = (k2 / m2).sqrt();
        let eig = eq["eigenvalues"].as_array().expect("eigenvalues");
        for pair in eig {
            close(pair[0].as_f64().expect("re"), 0.0, method);
            close(pair[1].as_f64().expect("im").abs(), omega, method);
        }
        let moving = command("solve", "arm-held-with-slider", method, &[]);
        close(at(&moving, &["accelerations", "theta"]), 0.0, method);
        let s_acc = (-k2 * (0.5 - s0) - m2 * g * th.sin()) / m2;
        close(at(&moving, &["accelerations", "s"]), s_acc, method);
        close(at(&moving, &["drives", "theta"]), hold(0.5), method);
        let a = command("answer", "arm-held-with-slider", method, &[]);
        assert_eq!(a["answers"][0]["kind"], "drive");
        close(at(&a["answers"][0], &["value"]), hold(0.5), method);
    }
}

/// A hoop that rolls (no slip holds through the impact) struck at its centre by J and
/// twisted by H: m v = J + F, m r² ω = H + r F, v = −r ω, so v = (J − H/r)/(2m) and the
/// ground's tangential impulse is F = −m v − H/r.
#[test]
fn a_rolling_hoop_struck_and_twisted_keeps_rolling() {
    let (m, r, j, h) = (2.0, 0.3, 3.0, 0.5);
    let v = (j - h / r) / (2.0 * m);
    for method in METHODS {
        let s = command("impact", "hoop-struck-on-level-ground", method, &[]);
        close(at(&s, &["after", "x'"]), v, method);
        close(at(&s, &["after", "theta'"]), -v / r, method);
        close(at(&s, &["after", "y'"]), 0.0, method);
        let ground = triple(&s["impulses"]["ground"]["force"]);
        close(ground[0], -m * v - h / r, method);
        close(ground[1], 0.0, method);
        close(
            at(&s, &["energy", "after"]),
            0.5 * m * v * v + 0.5 * m * r * r * (v / r).powi(2),
            method,
        );
    }
}

/// The held arm's collar struck by J n̂_y: the arm stays (its support takes the angular
/// impulse −J s cos θ₀ about O, reported as its drive), the collar takes the part along
/// the arm, ṡ⁺ = J sin θ₀ / m₂, and the pin the rest: m₂ ṡ⁺ â_x − J n̂_y.
#[test]
fn a_held_arms_collar_struck_the_support_takes_the_angular_impulse() {
    let (th, m2, j, s) = (0.5f64, 0.8, 2.0, 0.5);
    let rate = j * th.sin() / m2;
    for method in METHODS {
        let out = command("impact", "arm-held-collar-struck", method, &[]);
        close(at(&out, &["after", "theta'"]), 0.0, method);
        close(at(&out, &["after", "s'"]), rate, method);
        close(at(&out, &["drives", "theta"]), -j * s * th.cos(), method);
        let pin = triple(&out["impulses"]["O"]["force"]);
        close(pin[0], m2 * rate * th.cos(), method);
        close(pin[1], m2 * rate * th.sin() - j, method);
        close(
            at(&out, &["energy", "after"]),
            0.5 * m2 * rate * rate,
            method,
        );
    }
}

/// The bar under sideways gravity and a torque τ rests where m g L/2 cos θ + τ = 0: at
/// θ = ±acos(−2τ/(m g L)), stable where sin θ > 0 (eigenvalues ±iω, ω² = (m g L/2 sin θ)
/// /(m L²/3)), unstable at the other (±ω); the pin holds the weight, m g n̂_x.
#[test]
fn the_bar_rests_at_two_angles_one_stable_one_not() {
    let (m, l, g, tau) = (1.5f64, 0.8, 9.81, 2.0);
    let theta = (-2.0 * tau / (m * g * l)).acos();
    let omega = ((m * g * l / 2.0 * theta.sin()) / (m * l * l / 3.0)).sqrt();
    for method in METHODS {
        let near = ["--near", "theta=2", "--near", "theta=-2"];
        let s = command("statics", "bar-under-sideways-gravity", method, &near);
        let list = s["equilibria"].as_array().expect("equilibria");
        assert_eq!(list.len(), 2, "{method}: one equilibrium per start");
        for (eq, sign, stability) in [(&list[0], 1.0, "stable"), (&list[1], -1.0, "unstable")] {
            let what = format!("{method}, {stability}");
            close(at(eq, &["state", "theta"]), sign * theta, &what);
            assert_eq!(eq["stability"], stability, "{what}");
            let force = triple(&eq["reactions"]["O"]["force"]);
            close(force[0], m * g, &what);
            close(force[1], 0.0, &what);
            for pair in eq["eigenvalues"].as_array().expect("eigenvalues") {
                let (re, im) = (pair[0].as_f64().expect("re"), pair[1].as_f64().expect("im"));
                let (want_re, want_im) = if sign > 0.0 {
                    (0.0, omega)
                } else {
                    (omega, 0.0)
                };
                close(re.abs(), want_re, &what);
                close(im.abs(), want_im, &what);
            }
        }
    }
}
