//! Statics and the questions of rest on problems the bundled set does not hold, against
//! closed forms: a crate on a rough guide (`slips`), a bar on a rough floor twisted by a
//! couple, which has no equilibrium (`tips` and `slips` as it starts to move), a block
//! pushed level up and down a rough slope (`impending`), a bar held level by a motor
//! (`held`), and a crate pushed so high that its back corner would have to be pulled
//! down (the contact is lost), by every method.

use super::{at, close, command, triple};
use crate::support::METHODS;

const G: f64 = 9.81;

/// At rest the guide's friction holds the push: |F| = P, N = m g, ratio P/(μ m g).
#[test]
fn a_crate_on_a_rough_guide_slips_when_the_push_passes_mu_m_g() {
    let (m, mu) = (12.0, 0.35);
    for p in [30.0, 50.0] {
        let set = format!("P={p}");
        let ratio = p / (mu * m * G);
        for method in METHODS {
            let what = format!("{method}, P = {p}");
            let s = command(
                "statics",
                "crate-pushed-on-rough-slide",
                method,
                &["--set", &set],
            );
            let site = &s["equilibria"][0]["friction"]["guide"];
            close(at(site, &["normal"]).abs(), m * G, &what);
            close(at(site, &["tangential"]).abs(), p, &what);
            close(at(site, &["ratio"]), ratio, &what);
            let a = command(
                "answer",
                "crate-pushed-on-rough-slide",
                method,
                &["--set", &set],
            );
            let answer = &a["answers"][0];
            assert_eq!(answer["kind"], "slips", "{what}: {answer}");
            assert_eq!(answer["value"], ratio > 1.0, "{what}: {answer}");
            close(at(answer, &["ratio"]), ratio, &what);
            // A guide takes either sense: no contact to lose.
            assert!(answer.get("contact_lost").is_none(), "{what}: {answer}");
        }
    }
}

/// The bar (m, L, foot at its origin, θ from the upward vertical) with a couple T greater
/// than m g L/2 has no equilibrium. As it starts, pivoting on its sticking foot:
/// θ̈ = (T + m g (L/2) sin θ)/(m L²/3), and its centre accelerates θ̈ (L/2)(−cos θ, −sin θ),
/// so the floor pushes N = m g − m (L/2) θ̈ sin θ and holds the foot by F = −m (L/2) θ̈ cos θ.
#[test]
fn a_twisted_bar_with_no_equilibrium_is_asked_whether_it_tips_or_slips_as_it_starts() {
    let (m, l, mu, t, th) = (2.0, 1.2, 2.0, 15.0, 0.3f64);
    let alpha = (t + m * G * l / 2.0 * th.sin()) / (m * l * l / 3.0);
    let normal = m * G - m * l / 2.0 * alpha * th.sin();
    let friction = -m * l / 2.0 * alpha * th.cos();
    for method in METHODS {
        let what = format!("{method}: twisted bar");
        let s = command("solve", "rod-twisted-on-rough-floor", method, &[]);
        close(at(&s, &["accelerations", "th"]), alpha, &what);
        close(at(&s, &["accelerations", "x"]), 0.0, &what);
        let f = triple(&s["reactions"]["foot"]["force"]);
        close(f[0], friction, &what);
        close(f[1], normal, &what);
        let a = command("answer", "rod-twisted-on-rough-floor", method, &[]);
        let tips = &a["answers"][0];
        assert_eq!(tips["kind"], "tips", "{what}: {tips}");
        assert_eq!(tips["value"], false, "{what}: {tips}");
        close(at(tips, &["normal"]), normal, &what);
        assert_eq!(tips["unit"], "N", "{what}: {tips}");
        let slips = &a["answers"][1];
        assert_eq!(slips["value"], false, "{what}: {slips}");
        close(at(slips, &["ratio"]), friction.abs() / (mu * normal), &what);
        close(at(slips, &["slip_speed"]), 0.0, &what);
        assert_eq!(slips["contact_lost"], false, "{what}: {slips}");
    }
}

/// Pushed level by P on a slope α, friction μ: slip up impends at
/// P = m g (sin α + μ cos α)/(cos α − μ sin α), slip down at
/// P = m g (sin α − μ cos α)/(cos α + μ sin α); at P = 40 N friction holds
/// |m g sin α − P cos α| of μ (m g cos α + P sin α).
#[test]
fn a_block_pushed_level_on_a_rough_slope_starts_up_and_down_at_the_textbook_pushes() {
    let (m, mu, al, p) = (5.0, 0.3, 0.6f64, 40.0);
    let (s, c) = (al.sin(), al.cos());
    let up = m * G * (s + mu * c) / (c - mu * s);
    let down = m * G * (s - mu * c) / (c + mu * s);
    let normal = m * G * c + p * s;
    let ratio = (m * G * s - p * c).abs() / (mu * normal);
    for method in METHODS {
        let what = format!("{method}: block on the slope");
        let st = command("statics", "block-pushed-up-rough-slope", method, &[]);
        let site = &st["equilibria"][0]["friction"]["slope"];
        close(at(site, &["normal"]).abs(), normal, &what);
        close(at(site, &["ratio"]), ratio, &what);
        let a = command("answer", "block-pushed-up-rough-slope", method, &[]);
        let list = a["answers"].as_array().expect("answers");
        assert_eq!(list[0]["value"], false, "{what}: {a}");
        close(at(&list[0], &["ratio"]), ratio, &what);
        for (i, want) in [(1, up), (2, down)] {
            assert_eq!(list[i]["kind"], "impending", "{what}: {a}");
            assert_eq!(list[i]["impends"], "slip", "{what}: {a}");
            assert_eq!(list[i]["constant"], "P", "{what}: {a}");
            assert_eq!(list[i]["unit"], "N", "{what}: {a}");
            close(at(&list[i], &["value"]), want, &what);
        }
    }
}

/// The bar held at θ by its motor, a weight W at its tip: the motor gives
/// τ = (m g L/2 + W L) cos θ; the pin holds up m g + W, which along the bar's unit vectors
/// is ((m g + W) sin θ, (m g + W) cos θ).
#[test]
fn a_bar_held_by_its_motor_takes_the_textbook_torque() {
    let (m, l, w, th) = (4.0, 1.5, 30.0, 0.25f64);
    let tau = (m * G * l / 2.0 + w * l) * th.cos();
    let up = m * G + w;
    for method in METHODS {
        let what = format!("{method}: held bar");
        let s = command("statics", "bar-held-level-with-load", method, &[]);
        let e = &s["equilibria"][0];
        close(at(e, &["held", "th"]), tau, &what);
        close(at(e, &["state", "th"]), th, &what);
        let f = triple(&e["reactions"]["O"]["force"]);
        close(f[0], 0.0, &what);
        close(f[1], up, &what);
        let a = command("answer", "bar-held-level-with-load", method, &[]);
        let list = a["answers"].as_array().expect("answers");
        assert_eq!(list[0]["kind"], "drive", "{what}: {a}");
        close(at(&list[0], &["value"]), tau, &what);
        assert_eq!(list[1]["frame"], "A", "{what}: {a}");
        close(at(&list[1], &["components", "x"]), up * th.sin(), &what);
        close(at(&list[1], &["components", "y"]), up * th.cos(), &what);
    }
}

/// Pushed at height h by P beyond m g w/(2h), the crate at rest would need its back corner
/// pulled down: moments about the front corner give N = m g/2 − P h/w < 0. The contact is
/// lost, so friction cannot hold it there, whatever |F|/(μ|N|) comes to.
#[test]
fn a_crate_whose_back_corner_would_have_to_be_pulled_loses_the_contact() {
    let (m, w, h, p) = (20.0, 0.6, 0.8, 76.0);
    let normal = m * G / 2.0 - p * h / w;
    assert!(normal < 0.0);
    for method in METHODS {
        let what = format!("{method}: crate pushed high");
        let a = command("answer", "crate-pushed-high", method, &["--set", "P=76"]);
        let list = a["answers"].as_array().expect("answers");
        assert_eq!(list[0]["value"], true, "{what}: tips {}", list[0]);
        close(at(&list[0], &["normal"]), normal, &what);
        let slips = &list[1];
        assert_eq!(slips["kind"], "slips", "{what}: {slips}");
        assert_eq!(slips["contact_lost"], true, "{what}: {slips}");
        assert_eq!(slips["value"], true, "{what}: {slips}");
        close(at(slips, &["normal"]), normal, &what);
    }
}
