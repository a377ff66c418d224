//! `describe`: a simulated coordinate's motion, its extremes, mean, amplitude and period,
//! against an independent integration written here: the heavy top's nutation from its
//! one equation in θ, with the spin ω₃ and the vertical momentum L_z conserved,
//!
//!   I₁ θ̈ = I₁ ψ̇² sin θ cos θ − I₃ ω₃ ψ̇ sin θ + m g h sin θ,
//!   ψ̇ = (L_z − I₃ ω₃ cos θ)/(I₁ sin² θ),
//!
//! stepped by classical Runge–Kutta with a step of 10 µs.

use crate::support::{problem, run_json};
use serde_json::Value;

/// The top of problems/heavy-symmetric-top.json.
const M: f64 = 0.5;
const H: f64 = 0.04;
const I3: f64 = 4.0e-4;
const IT: f64 = 2.5e-4;
const G: f64 = 9.81;

/// What the reference integration measures over [0, 2 s].
struct Reference {
    minimum: f64,
    maximum: f64,
    mean: f64,
    period: f64,
    precession: (f64, f64),
}

fn reference() -> Reference {
    let i1 = IT + M * H * H;
    let (theta0, psi_rate0, phi_rate0) = (0.5f64, 3.0, 150.0);
    let spin = phi_rate0 + psi_rate0 * theta0.cos();
    let lz = i1 * psi_rate0 * theta0.sin().powi(2) + I3 * spin * theta0.cos();
    let precession = |th: f64| (lz - I3 * spin * th.cos()) / (i1 * th.sin().powi(2));
    let f = |th: f64, w: f64| {
        let p = precession(th);
        let acc = (i1 * p * p * th.sin() * th.cos() - I3 * spin * p * th.sin()
            + M * G * H * th.sin())
            / i1;
        (w, acc)
    };
    let (h, steps) = (1.0e-5, 200_000);
    let (mut th, mut w) = (theta0, 0.0);
    let (mut lo, mut hi) = (th, th);
    let mut integral = 0.0;
    let mut maxima = Vec::new();
    for k in 0..steps {
        let (k1, l1) = f(th, w);
        let (k2, l2) = f(th + h / 2.0 * k1, w + h / 2.0 * l1);
        let (k3, l3) = f(th + h / 2.0 * k2, w + h / 2.0 * l2);
        let (k4, l4) = f(th + h * k3, w + h * l3);
        let (th1, w1) = (
            th + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4),
            w + h / 6.0 * (l1 + 2.0 * l2 + 2.0 * l3 + l4),
        );
        integral += h / 2.0 * (th + th1);
        if w > 0.0 && w1 <= 0.0 {
            // The zero of θ̇ between the two steps, by linear interpolation.
            let s = w / (w - w1);
            maxima.push((k as f64 + s) * h);
            hi = hi.max(th + s * h * w / 2.0);
        }
        if w < 0.0 && w1 >= 0.0 {
            let s = w / (w - w1);
            lo = lo.min(th + s * h * w / 2.0);
        }
        lo = lo.min(th1);
        hi = hi.max(th1);
        (th, w) = (th1, w1);
    }
    let period = (maxima[maxima.len() - 1] - maxima[0]) / (maxima.len() - 1) as f64;
    let (a, b) = (precession(lo), precession(hi));
    Reference {
        minimum: lo,
        maximum: hi,
        mean: integral / (h * steps as f64),
        period,
        precession: (a.min(b), a.max(b)),
    }
}

fn close(found: f64, expected: f64, tolerance: f64, what: &str) {
    assert!(
        (found - expected).abs() <= tolerance * expected.abs().max(1e-12),
        "{what}: {found} against {expected}"
    );
}

fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or(f64::NAN)
}

#[test]
fn the_tops_nutation_is_described_as_an_independent_integration_finds_it() {
    let found = run_json(&[
        "answer".as_ref(),
        problem("heavy-symmetric-top").as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    let answers = found["answers"].as_array().expect("answers");
    let d = answers
        .iter()
        .find(|a| a["kind"] == "describe")
        .expect("a describe answer");
    assert_eq!(d["coordinate"], "theta");
    assert_eq!(d["unit"], "rad");
    let r = reference();
    close(number(&d["minimum"]), r.minimum, 1e-6, "least tilt");
    close(number(&d["maximum"]), r.maximum, 1e-6, "greatest tilt");
    close(number(&d["mean"]), r.mean, 1e-6, "mean tilt");
    let amplitude = (r.maximum - r.minimum) / 2.0;
    close(number(&d["amplitude"]), amplitude, 1e-4, "amplitude");
    close(number(&d["period"]), r.period, 1e-6, "period");
    let psi = &d["rates"]["psi'"];
    close(
        number(&psi["minimum"]),
        r.precession.0,
        1e-6,
        "slowest precession",
    );
    close(
        number(&psi["maximum"]),
        r.precession.1,
        1e-6,
        "fastest precession",
    );
    assert_eq!(psi["keeps_sign"], true);
    // The simulated top spins faster than the linearization's 150 rad/s, so it nods
    // faster than the linearized period of the comparison question.
    let linearized = answers
        .iter()
        .find(|a| a["kind"] == "period")
        .expect("the comparison");
    assert!(number(&d["period"]) < number(&linearized["value"]));
}

#[test]
fn describe_names_a_coordinate() {
    let text = std::fs::read_to_string(problem("heavy-symmetric-top")).expect("readable");
    let mut p: Value = serde_json::from_str(&text).expect("json");
    p["find"]["questions"][5]["describe"] = serde_json::json!({ "coordinate": "spin" });
    let path = std::env::temp_dir().join(format!("mbd-describe-{}.json", std::process::id()));
    std::fs::write(&path, p.to_string()).expect("scratch");
    let out = crate::support::run(&["check".as_ref(), path.as_os_str()]);
    assert_eq!(out.status.code(), Some(1));
    let err =
        String::from_utf8_lossy(&out.stderr).to_string() + &String::from_utf8_lossy(&out.stdout);
    assert!(
        err.contains("find.questions[5].describe.coordinate"),
        "{err}"
    );
}
