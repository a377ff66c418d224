//! `mbd-tutor answer --format json` against closed forms derived by hand here: the heavy
//! top's slow and fast steady precession, a rod's steady angle on a spinning shaft, a rod
//! pendulum's pin reaction and the torque that drives a rod.

use crate::support::{problem, run, run_json};
use serde_json::{json, Value};

/// Writes `problem` to a scratch file named after `name`.
fn scratch(name: &str, problem: &Value) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("mbd-answer-json-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch");
    let path = dir.join(format!("{name}.json"));
    std::fs::write(&path, serde_json::to_string_pretty(problem).expect("json")).expect("write");
    path
}

fn answers(path: &std::path::Path) -> Vec<Value> {
    let out = run_json(&[
        "answer".as_ref(),
        path.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    out["answers"].as_array().expect("answers").clone()
}

fn close(found: f64, expected: f64, tolerance: f64, what: &str) {
    assert!(
        (found - expected).abs() <= tolerance * expected.abs().max(1.0),
        "{what}: {found} against {expected}"
    );
}

#[test]
fn top_precession_rates_are_the_roots_of_the_steady_quadratic() {
    let found = answers(&problem("heavy-symmetric-top"));
    // m g h = Ω (I3 ω3 − I1 Ω cos θ), I1 = It + m h²: I1 cos θ Ω² − I3 ω3 Ω + m g h = 0.
    let (m, h, i3, it, g, theta, spin) = (0.5, 0.04, 4.0e-4, 2.5e-4, 9.81, 0.5f64, 150.0);
    let i1 = it + m * h * h;
    let (a, b, c) = (i1 * theta.cos(), -i3 * spin, m * g * h);
    let root = (b * b - 4.0 * a * c).sqrt();
    let (slow, fast) = ((-b - root) / (2.0 * a), (-b + root) / (2.0 * a));
    for (index, rate) in [(1, slow), (2, fast)] {
        let answer = &found[index];
        assert_eq!(answer["kind"], "steady");
        assert_eq!(answer["units"]["psi'"], "rad/s");
        let psi = answer["unknowns"]["psi'"].as_f64().expect("psi'");
        let phi = answer["unknowns"]["phi'"].as_f64().expect("phi'");
        close(psi, rate, 1e-8, "precession rate");
        // The spin held: φ' + ψ' cos θ = 150, in the state reported too.
        close(phi + psi * theta.cos(), spin, 1e-8, "spin");
        assert_eq!(answer["state"]["psi'"].as_f64(), Some(psi));
        assert_eq!(answer["state"]["theta"].as_f64(), Some(theta));
        assert_eq!(answer["time"].as_f64(), Some(0.0));
    }
    // The statement's "show that", at the slow steady precession found: both sides equal
    // m g h there, and the handout derives it.
    let shown = &found[0];
    assert_eq!(shown["kind"], "show");
    assert_eq!(shown["holds"], true);
    close(
        shown["lhs"].as_f64().expect("lhs"),
        m * g * h,
        1e-12,
        "m g h",
    );
    close(
        shown["rhs"].as_f64().expect("rhs"),
        m * g * h,
        1e-9,
        "right side",
    );
    assert_eq!(shown["state"]["psi'"], found[1]["unknowns"]["psi'"]);
    // The reaction at the tip: the force components only (a spherical joint takes no
    // moment); its vertical component carries the weight, the top not rising.
    let tip = &found[3];
    assert_eq!(tip["kind"], "reaction");
    assert_eq!(tip["unit"], "N");
    assert!(tip["components"].get("moment").is_none(), "{tip}");
    close(
        tip["components"]["z"].as_f64().expect("z"),
        m * g,
        1e-3,
        "weight",
    );
    // The horizontal one turns the mass centre on its circle: m h sin θ ψ'² inward.
    let psi = slow;
    close(
        tip["components"]["y"].as_f64().expect("y").abs(),
        m * h * theta.sin() * psi * psi,
        1e-4,
        "centripetal force",
    );
}

#[test]
fn a_rod_on_a_spinning_shaft_stands_at_cos_theta_3g_over_2l_omega_squared() {
    let (l, w, g) = (0.5f64, 6.0f64, 9.81f64);
    let spinning = json!({
        "title": "Rod hinged to a spinning shaft",
        "dimension": 3,
        "constants": { "m": 0.3, "L": l, "w": w, "g": g },
        "coordinates": {
            "psi": { "motion": "w*t" },
            "theta": { "initial": 0.8 }
        },
        "gravity": "-g*N.z",
        "bodies": {
            "S": { "mass": 1, "inertia": { "xx": 0.01, "yy": 0.01, "zz": 0.01 } },
            "R": { "mass": "m", "center": "-L/2*R.z", "inertia": { "xx": "m*L^2/12", "yy": "m*L^2/12", "zz": 0 } }
        },
        "joints": [
            { "name": "shaft", "type": "revolute", "parent": "N", "child": "S", "axis": "N.z", "coordinates": ["psi"] },
            { "name": "hinge", "type": "revolute", "parent": "S", "child": "R", "axis": "S.x", "coordinates": ["theta"] }
        ],
        "find": { "questions": [
            { "steady": { "unknowns": ["theta"], "zero": ["theta''"] },
              "at": { "state": { "theta": 0.8, "theta'": 0 } } }
        ] }
    });
    let found = answers(&scratch("spinning-rod", &spinning));
    // About the hinge: (m L²/3) ω² sin θ cos θ = m g (L/2) sin θ, so cos θ = 3 g / (2 L ω²).
    let expected = (3.0 * g / (2.0 * l * w * w)).acos();
    let theta = found[0]["unknowns"]["theta"].as_f64().expect("theta");
    close(theta.abs(), expected, 1e-8, "steady angle");
    assert_eq!(found[0]["units"]["theta"], "rad");
}

/// A uniform rod of mass m and length L pinned at O, at angle θ from N.x.
fn rod(questions: Value, motion: Option<&str>) -> Value {
    let mut p = json!({
        "title": "Rod pendulum",
        "dimension": 2,
        "constants": { "m": 1.5, "L": 0.8, "g": 9.81, "th0": 0.4, "w": 2.0, "al": 3.0 },
        "coordinates": { "theta": { "initial": -0.7, "rate": 1.3 } },
        "gravity": "-g*N.y",
        "bodies": { "B": { "mass": "m", "center": "L/2*B.x", "inertia": "m*L^2/12" } },
        "joints": [ { "name": "O", "type": "revolute", "parent": "N", "child": "B",
                      "coordinates": ["theta"] } ],
        "find": { "reactions": ["O"], "questions": questions }
    });
    if let Some(motion) = motion {
        p["coordinates"]["theta"] = json!({ "motion": motion });
    }
    p
}

#[test]
fn a_pendulum_pin_reaction_is_m_a_minus_m_g() {
    let found = answers(&scratch(
        "rod-pendulum",
        &rod(json!([{ "value": "theta''" }, { "reaction": "O" }]), None),
    ));
    let (m, l, g, theta, rate) = (1.5, 0.8, 9.81, -0.7f64, 1.3f64);
    // About O: (m L²/3) θ'' = −m g (L/2) cos θ.
    let acceleration = -3.0 * g / (2.0 * l) * theta.cos();
    close(
        found[0]["value"].as_f64().expect("value"),
        acceleration,
        1e-10,
        "theta''",
    );
    assert_eq!(found[0]["unit"], "rad/s^2");
    // The pin's force on the rod: F + m g = m a_G, a_G = (L/2)(θ'' e_θ − θ'² e_r).
    let (s, c) = theta.sin_cos();
    let ax = l / 2.0 * (-acceleration * s - rate * rate * c);
    let ay = l / 2.0 * (acceleration * c - rate * rate * s);
    let components = &found[1]["components"];
    close(components["x"].as_f64().expect("x"), m * ax, 1e-10, "F_x");
    close(
        components["y"].as_f64().expect("y"),
        m * ay + m * g,
        1e-10,
        "F_y",
    );
    // A pin takes no moment about its axis: none reported, in JSON as in the handout.
    assert!(components.get("moment").is_none(), "{components}");
    assert_eq!(found[1]["state"]["theta'"].as_f64(), Some(rate));
}

#[test]
fn a_drive_is_the_torque_that_keeps_the_prescribed_motion() {
    let found = answers(&scratch(
        "driven-rod",
        &rod(
            json!([{ "drive": "theta" }, { "drive": "theta", "at": { "time": 0.25 } }]),
            Some("th0 + w*t + al*t^2/2"),
        ),
    ));
    let (m, l, g, th0, w, al) = (1.5, 0.8, 9.81, 0.4f64, 2.0, 3.0);
    // (m L²/3) θ'' = Q − m g (L/2) cos θ, with θ'' = al.
    let torque =
        |t: f64| m * l * l / 3.0 * al + m * g * l / 2.0 * (th0 + w * t + al * t * t / 2.0).cos();
    for (index, t) in [(0, 0.0), (1, 0.25)] {
        assert_eq!(found[index]["kind"], "drive");
        assert_eq!(found[index]["unit"], "N m");
        assert_eq!(found[index]["time"].as_f64(), Some(t));
        close(
            found[index]["value"].as_f64().expect("drive"),
            torque(t),
            1e-8,
            "drive",
        );
    }
}

#[test]
fn answer_text_lists_every_value_with_its_unit() {
    let out = run(&["answer".as_ref(), problem("four-bar").as_os_str()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("[0] value at t = 0.0 s"), "{text}");
    assert!(text.contains("O.force.x = "), "{text}");
    assert!(
        text.lines()
            .any(|l| l.trim().starts_with("q1'' = ") && l.ends_with(" rad/s^2")),
        "{text}"
    );
}

#[test]
fn a_problem_without_questions_is_refused_with_its_path() {
    let mut asks_nothing = rod(json!([]), None);
    asks_nothing["find"] = json!({ "reactions": ["O"] });
    let path = scratch("asks-nothing", &asks_nothing);
    let out = run(&["answer".as_ref(), path.as_os_str()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("find.questions"), "{stderr}");
}
