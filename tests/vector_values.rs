//! Vector `value` questions: `r(P)`, `v(P)`, `a(B*)`, `w(B)`, `alpha(B)` answered with
//! components along N's unit vectors (or the frame `in` names), the frame beside them in
//! `answer --format json` and in key.csv's columns, every number checked against a hand
//! derivation written here: the double pendulum's points and lower rod, a rolling
//! cylinder's contact point (at rest, its acceleration r θ̇² toward the centre), and a
//! heavy top's angular velocity and acceleration from its Euler angles.

use crate::support::{problem_json, run, run_json, scratch};
use serde_json::{json, Value};
use std::path::Path;

fn answers(path: &Path) -> Vec<Value> {
    let out = run_json(&[
        "answer".as_ref(),
        path.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    out["answers"].as_array().expect("answers").clone()
}

fn close(found: f64, expected: f64, what: &str) {
    assert!(
        (found - expected).abs() <= 1e-6 * expected.abs().max(1.0),
        "{what}: {found} against {expected}"
    );
}

/// The components of a vector answer, checked to be exactly the axes `axes`, in `frame`.
fn components(answer: &Value, frame: &str, axes: &[&str]) -> Vec<f64> {
    assert_eq!(answer["kind"], "value", "{answer}");
    assert_eq!(answer["frame"], frame, "{answer}");
    let found = answer["components"].as_object().expect("components");
    let keys: Vec<&str> = found.keys().map(String::as_str).collect();
    assert_eq!(keys, axes, "{answer}");
    axes.iter()
        .map(|a| found[*a].as_f64().expect("a number"))
        .collect()
}

fn value(answer: &Value) -> f64 {
    answer["value"].as_f64().expect("a scalar value")
}

/// The double pendulum (q₁ = 0.7, q₂ = −0.4, q̇₁ = 1, q̇₂ = −0.5): by hand, the elbow P is
/// at L₁(sin q₁, −cos q₁), moving at L₁ q̇₁ along â_x; B's centre at P + L₂/2 (sin q₁₂,
/// −cos q₁₂), q₁₂ = q₁ + q₂, with velocity and acceleration its derivatives; B turns at
/// q̇₁ + q̇₂ with angular acceleration q̈₁ + q̈₂.
#[test]
fn the_double_pendulums_points_and_lower_rod_by_hand() {
    let mut p = problem_json("double-pendulum-rods");
    p["find"]["questions"] = json!([
        { "value": "q1''" },
        { "value": "q2''" },
        { "value": "r(P)" },
        { "value": "v(P)", "in": "A" },
        { "value": "v(B*)" },
        { "value": "a(B*)" },
        { "value": "w(B)" },
        { "value": "alpha(B)", "unit": "rad/s^2" },
        { "value": "v(N.o)" },
    ]);
    let found = answers(&scratch("vector-values", "double", &p));
    let (l1, l2) = (0.6f64, 0.4f64);
    let (q1, q2, u1, u2) = (0.7f64, -0.4f64, 1.0f64, -0.5f64);
    let (a1, a2) = (value(&found[0]), value(&found[1]));
    let (q12, u12, a12) = (q1 + q2, u1 + u2, a1 + a2);
    let r = components(&found[2], "N", &["x", "y"]);
    close(r[0], l1 * q1.sin(), "r(P)·n̂_x");
    close(r[1], -l1 * q1.cos(), "r(P)·n̂_y");
    let v = components(&found[3], "A", &["x", "y"]);
    close(v[0], l1 * u1, "v(P)·â_x");
    close(v[1], 0.0, "v(P)·â_y");
    let v = components(&found[4], "N", &["x", "y"]);
    close(
        v[0],
        l1 * u1 * q1.cos() + l2 / 2.0 * u12 * q12.cos(),
        "v(B*)·n̂_x",
    );
    close(
        v[1],
        l1 * u1 * q1.sin() + l2 / 2.0 * u12 * q12.sin(),
        "v(B*)·n̂_y",
    );
    assert_eq!(found[4]["unit"], "m/s");
    let a = components(&found[5], "N", &["x", "y"]);
    let ax = l1 * (a1 * q1.cos() - u1 * u1 * q1.sin())
        + l2 / 2.0 * (a12 * q12.cos() - u12 * u12 * q12.sin());
    let ay = l1 * (a1 * q1.sin() + u1 * u1 * q1.cos())
        + l2 / 2.0 * (a12 * q12.sin() + u12 * u12 * q12.cos());
    close(a[0], ax, "a(B*)·n̂_x");
    close(a[1], ay, "a(B*)·n̂_y");
    assert_eq!(found[5]["unit"], "m/s^2");
    close(components(&found[6], "N", &["z"])[0], u12, "ω^B·n̂_z");
    assert_eq!(found[6]["unit"], "rad/s");
    close(components(&found[7], "N", &["z"])[0], a12, "α^B·n̂_z");
    let fixed = components(&found[8], "N", &["x", "y"]);
    assert!(fixed.iter().all(|x| *x == 0.0), "N's origin does not move");
}

/// A cylinder rolling without slipping (radius R = 0.1 m, ẋ = 0.5 m/s, so θ̇ = −ẋ/R = −5
/// rad/s): the point C of the rim touching the plane is at rest, and its acceleration is
/// R θ̇² = 2.5 m/s² toward the centre, along n̂_y. Its centre accelerates down the slope at
/// (2/3) g sin α. In the cylinder's own axes its angular velocity is θ̇ ŵ_z.
#[test]
fn a_rolling_cylinders_contact_point_is_at_rest_and_accelerates_toward_the_centre() {
    let mut p = problem_json("cylinder-on-incline");
    p["points"] = json!({ "C": { "on": "W", "at": "-R*W.y" } });
    p["find"]["questions"] = json!([
        { "value": "v(C)" },
        { "value": "a(C)" },
        { "value": "r(C)" },
        { "value": "w(W)", "in": "W" },
        { "value": "a(W*)" },
    ]);
    let found = answers(&scratch("vector-values", "cylinder", &p));
    let (r, rate) = (0.1, 0.5);
    let spin = -rate / r;
    let v = components(&found[0], "N", &["x", "y"]);
    close(v[0], 0.0, "v(C)·n̂_x");
    close(v[1], 0.0, "v(C)·n̂_y");
    let a = components(&found[1], "N", &["x", "y"]);
    close(a[0], 0.0, "a(C)·n̂_x");
    close(a[1], r * spin * spin, "a(C)·n̂_y");
    let at = components(&found[2], "N", &["x", "y"]);
    close(at[0], 0.0, "r(C)·n̂_x");
    close(at[1], 0.0, "r(C)·n̂_y");
    close(components(&found[3], "W", &["z"])[0], spin, "ω·ŵ_z");
    let centre = components(&found[4], "N", &["x", "y"]);
    close(centre[0], 2.0 / 3.0 * 9.81 * 0.5, "a(W*)·n̂_x");
    close(centre[1], 0.0, "a(W*)·n̂_y");
}

/// The heavy top's zxz Euler angles (ψ, θ, φ): in its own axes ω = (ψ̇ sθ sφ + θ̇ cφ,
/// ψ̇ sθ cφ − θ̇ sφ, ψ̇ cθ + φ̇); in N, ω = ψ̇ n̂_z + θ̇ (cψ, sψ, 0) + φ̇ k, k = (sθ sψ,
/// −sθ cψ, cθ) the symmetry axis, and α its derivative in N.
#[test]
fn the_heavy_tops_angular_velocity_and_acceleration_by_its_euler_angles() {
    let mut p = problem_json("heavy-symmetric-top");
    let at = json!({ "state": { "psi": 0.3, "theta": 0.5, "phi": 0.7,
                               "psi'": 3.0, "theta'": 1.5, "phi'": 20.0 } });
    p["find"]["questions"] = json!([
        { "value": "psi''", "at": at }, { "value": "theta''", "at": at },
        { "value": "phi''", "at": at },
        { "value": "w(top)", "in": "top", "at": at },
        { "value": "w(top)", "at": at },
        { "value": "alpha(top)", "at": at },
    ]);
    let found = answers(&scratch("vector-values", "top", &p));
    let xyz = ["x", "y", "z"];
    let (psi, th, phi) = (0.3f64, 0.5f64, 0.7f64);
    let (dpsi, dth, dphi) = (3.0, 1.5, 20.0);
    let (apsi, ath, aphi) = (value(&found[0]), value(&found[1]), value(&found[2]));
    let own = components(&found[3], "top", &xyz);
    let by_hand = [
        dpsi * th.sin() * phi.sin() + dth * phi.cos(),
        dpsi * th.sin() * phi.cos() - dth * phi.sin(),
        dpsi * th.cos() + dphi,
    ];
    for i in 0..3 {
        close(own[i], by_hand[i], &format!("ω·top_{}", xyz[i]));
    }
    let k = [th.sin() * psi.sin(), -th.sin() * psi.cos(), th.cos()];
    let w = components(&found[4], "N", &xyz);
    let by_hand = [
        dth * psi.cos() + dphi * k[0],
        dth * psi.sin() + dphi * k[1],
        dpsi + dphi * k[2],
    ];
    for i in 0..3 {
        close(w[i], by_hand[i], &format!("ω·n̂_{}", xyz[i]));
    }
    let dk = [
        dth * th.cos() * psi.sin() + dpsi * th.sin() * psi.cos(),
        -dth * th.cos() * psi.cos() + dpsi * th.sin() * psi.sin(),
        -dth * th.sin(),
    ];
    let alpha = components(&found[5], "N", &xyz);
    let by_hand = [
        ath * psi.cos() - dth * dpsi * psi.sin() + aphi * k[0] + dphi * dk[0],
        ath * psi.sin() + dth * dpsi * psi.cos() + aphi * k[1] + dphi * dk[1],
        apsi + aphi * k[2] + dphi * dk[2],
    ];
    for i in 0..3 {
        close(alpha[i], by_hand[i], &format!("α·n̂_{}", xyz[i]));
    }
}

/// key.csv names each component's column with the frame (`aC.y@N`), with the numbers
/// `answer` gives; the handout writes the unit vectors of that frame.
#[test]
fn the_key_and_the_handout_name_the_frame() {
    let mut p = problem_json("cylinder-on-incline");
    p["constants"]["R"]["vary"] = json!([0.08, 0.12]);
    p["constants"]["R"]["step"] = json!(0.01);
    p["points"] = json!({ "C": { "on": "W", "at": "-R*W.y" } });
    p["find"]["questions"] = json!([
        { "value": "a(C)", "symbol": "aC" },
        { "value": "v(W*)", "in": "W" },
    ]);
    let path = scratch("vector-values", "keyed", &p);
    let dir = path.with_extension("variants");
    let _ = std::fs::remove_dir_all(&dir);
    let out = run(&[
        "variants".as_ref(),
        path.as_os_str(),
        "--count".as_ref(),
        "2".as_ref(),
        "--seed".as_ref(),
        "3".as_ref(),
        "-o".as_ref(),
        dir.as_os_str(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let key = std::fs::read_to_string(dir.join("key.csv")).expect("key.csv");
    let header: Vec<&str> = key.lines().next().expect("header").split(',').collect();
    for column in ["aC.x@N", "aC.y@N", "1.x@W", "1.y@W"] {
        assert!(header.contains(&column), "{column} in {header:?}");
    }
    let handout = run(&[
        "explain".as_ref(),
        path.as_os_str(),
        "--format".as_ref(),
        "markdown".as_ref(),
    ]);
    let text = String::from_utf8_lossy(&handout.stdout);
    assert!(
        text.contains("{}^{N}\\mathbf{v}^{W^{*}} \\cdot \\hat{\\mathbf{w}}_{x} = 0.5"),
        "the handout writes the component along ŵ_x"
    );
    assert!(text.contains("{}^{N}\\mathbf{a}^{C} \\cdot \\hat{\\mathbf{n}}_{y} = 2.5"));
}

/// An unknown point, a body where a point is meant, a point where a body is meant and an
/// unknown frame: exit 1, the JSON path, a hint.
#[test]
fn bad_vector_values_name_their_path() {
    for (question, path, words) in [
        (
            json!({ "value": "v(Q)" }),
            "find.questions[0].value",
            "unknown point `Q`",
        ),
        (
            json!({ "value": "v(B)" }),
            "find.questions[0].value",
            "`B` is a body, not a point",
        ),
        (
            json!({ "value": "w(P)" }),
            "find.questions[0].value",
            "not a body",
        ),
        (
            json!({ "value": "a()" }),
            "find.questions[0].value",
            "should name one point",
        ),
        (
            json!({ "value": "v(P)", "in": "C" }),
            "find.questions[0].in",
            "unknown body `C`",
        ),
        (
            json!({ "value": "q1", "in": "A" }),
            "find.questions[0].in",
            "only a vector answer",
        ),
    ] {
        let mut p = problem_json("double-pendulum-rods");
        p["find"]["questions"] = json!([question]);
        let out = run(&[
            "answer".as_ref(),
            scratch("vector-values", "bad", &p).as_os_str(),
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{question}: {err}");
        assert!(
            err.contains(path) && err.contains(words),
            "{question}: {err}"
        );
        assert!(err.contains("hint:"), "{question}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}
