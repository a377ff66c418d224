//! The kinds of question `period` and `show`, `about` a steady motion, and the Answers
//! numbered as the statement numbers its items: each number against a closed form
//! written here.

use crate::support::{all_problems, explain, problem, run};
use mbd_tutor::equations::Method;
use serde_json::{json, Value};
use std::f64::consts::PI;

/// `answer --format json` of a problem file, by `method`.
fn answers(path: &std::path::Path, method: Method) -> Vec<Value> {
    crate::support::answers_json(path, method.name())
}

fn close(found: f64, expected: f64, tolerance: f64, what: &str) {
    assert!(
        (found - expected).abs() <= tolerance * expected.abs(),
        "{what}: {found} against {expected}"
    );
}

fn scratch(name: &str, problem: &Value) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("mbd-questions-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch");
    let path = dir.join(format!("{name}.json"));
    std::fs::write(&path, problem.to_string()).expect("write");
    path
}

/// The disc rolling inside the cylinder, by every method: small oscillations about the
/// bottom. T = ½ m v² + ½ (m r²/2) (v/r)² = ¾ m v², V = m g (R − r)(1 − cos φ) with
/// v = (R − r) φ̇: ω² = g / ((3/2)(R − r)), T = 2π √(3(R − r)/(2g)).
#[test]
fn the_disc_in_the_cylinder_oscillates_with_the_closed_form_period() {
    let (r, big_r, g) = (0.1f64, 0.5f64, 9.81f64);
    let expected = 2.0 * PI * (3.0 * (big_r - r) / (2.0 * g)).sqrt();
    for method in Method::ALL {
        let found = answers(&problem("disc-in-cylinder"), method);
        let period = &found[3];
        assert_eq!(period["kind"], "period", "{}", method.name());
        assert_eq!(period["unit"], "s");
        close(
            period["value"].as_f64().expect("value"),
            expected,
            1e-6,
            method.name(),
        );
    }
    // The handout writes ω² = K/M in symbols before the number, and the period.
    let text = explain("disc-in-cylinder", &["--format", "markdown"]);
    let answers = &text[text.find("## Answers").expect("Answers")..];
    assert!(answers.contains("\\omega^{2} = \\frac{K}{M}"), "{answers}");
    assert!(
        answers.contains("\\tau = \\frac{2\\pi}{\\omega} = 1.55389"),
        "{answers}"
    );
    assert!(answers.contains("16.35\\ \\mathrm{s^{-2}}"), "{answers}");
    // τ is the period: T stays the kinetic energy of step 6.
    assert!(!answers.contains("T = \\frac{2\\pi}"), "{answers}");
    // The bottom put in by the constraint, in symbols: y = −(R − r), so that
    // ω² = g m/(R − r) / (3m/2) = 2g/(3(R − r)) and T = 2π √(3(R − r)/(2g)).
    assert!(answers.contains("y = -\\left(R - r\\right)"), "{answers}");
    assert!(answers.contains("\\frac{2 g}{3 (R - r)}"), "{answers}");
    assert!(!answers.contains("Kane's equation"), "{answers}");
    assert!(!answers.contains("the other values initial"), "{answers}");
    // Every acceleration asked: ÿ and θ̈ as well as ẍ, against energy: with the disc at
    // angle φ from the bottom, x = (R − r) sin φ, y = −(R − r) cos φ, released from rest,
    // φ̈ = −2g sin φ/(3(R − r)); ÿ = (R − r) sin φ φ̈, θ̈ = −(R − r) φ̈/r.
    let found = crate::questions::answers(&problem("disc-in-cylinder"), Method::MotionLaw);
    let phi = (0.05f64 / (big_r - r)).asin();
    let phidd = -2.0 * g * phi.sin() / (3.0 * (big_r - r));
    let xdd = (big_r - r) * phi.cos() * phidd;
    let ydd = (big_r - r) * phi.sin() * phidd;
    let thdd = -(big_r - r) * phidd / r;
    for (k, expected) in [(0, xdd), (1, ydd), (2, thdd)] {
        close(
            found[k]["value"].as_f64().expect("value"),
            expected,
            1e-6,
            "acceleration",
        );
    }
}

/// A particle pendulum with a torsional spring at the pivot, about θ = 0:
/// m L² θ̈ = −m g L sin θ − k θ, so ω² = (k + m g L)/(m L²); and with a damper c the
/// damped frequency ω √(1 − ζ²), ζ = c / (2 √((k + m g L) m L²)).
#[test]
fn a_pendulum_on_a_spring_has_omega_squared_k_over_m() {
    let (m, l, g, k, c) = (0.5f64, 0.8f64, 9.81f64, 3.0f64, 0.05f64);
    let p = |damper: bool| {
        let mut p = json!({
            "title": "Pendulum on a spring",
            "dimension": 2,
            "constants": { "m": m, "L": l, "g": g, "k": k, "c": c },
            "coordinates": { "theta": { "initial": 0.3, "rate": 0 } },
            "gravity": "-g*N.y",
            "bodies": { "bob": { "mass": "m" } },
            "joints": [ { "name": "O", "type": "revolute", "parent": "N", "child": "bob",
                          "axis": "N.z", "child_at": "L*bob.y", "coordinates": ["theta"] } ],
            "loads": [ { "type": "joint_spring", "joint": "O", "coordinate": "theta", "stiffness": "k", "rest": "0" } ],
            "find": { "questions": [
                { "text": "Find the period of small oscillations about $\\theta = 0$.",
                  "period": { "coordinate": "theta" }, "at": { "state": { "theta": 0, "theta'": 0 } } } ] }
        });
        if damper {
            p["loads"].as_array_mut().expect("loads").push(
                json!({ "type": "joint_damper", "joint": "O", "coordinate": "theta", "coefficient": "c" }),
            );
        }
        p
    };
    let omega = ((k + m * g * l) / (m * l * l)).sqrt();
    let path = scratch("spring-pendulum", &p(false));
    for method in Method::ALL {
        let found = answers(&path, method);
        close(
            found[0]["value"].as_f64().expect("T"),
            2.0 * PI / omega,
            1e-9,
            "period",
        );
        close(
            found[0]["angular_frequency"].as_f64().expect("w"),
            omega,
            1e-9,
            "omega",
        );
    }
    let out = run(&[
        "explain".as_ref(),
        path.as_os_str(),
        "--format".as_ref(),
        "markdown".as_ref(),
    ]);
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(text.contains("\\omega^{2} = \\frac{K}{M}"), "{text}");
    let damped = scratch("damped-pendulum", &p(true));
    let zeta = c / (2.0 * ((k + m * g * l) * m * l * l).sqrt());
    let found = answers(&damped, Method::Kane);
    close(
        found[0]["damping_ratio"].as_f64().expect("zeta"),
        zeta,
        1e-9,
        "damping ratio",
    );
    close(
        found[0]["value"].as_f64().expect("T"),
        2.0 * PI / (omega * (1.0 - zeta * zeta).sqrt()),
        1e-9,
        "damped period",
    );
}

/// An unstable state has no period: exit 1, the question's path and a hint.
#[test]
fn a_period_about_an_unstable_state_is_refused_with_its_path() {
    let p = json!({
        "title": "Inverted pendulum",
        "dimension": 2,
        "constants": { "m": 1, "L": 1, "g": 9.81 },
        "coordinates": { "theta": { "initial": 0.1 } },
        "gravity": "-g*N.y",
        "bodies": { "bob": { "mass": "m" } },
        "joints": [ { "name": "O", "type": "revolute", "parent": "N", "child": "bob",
                      "axis": "N.z", "child_at": "L*bob.y", "coordinates": ["theta"] } ],
        "find": { "questions": [ { "value": "theta''" },
            { "period": {}, "at": { "state": { "theta": PI, "theta'": 0 } } } ] }
    });
    let path = scratch("inverted", &p);
    let out = run(&["answer".as_ref(), path.as_os_str()]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("find.questions[1]") && stderr.contains("unstable"),
        "{stderr}"
    );
}

/// The heavy top: "show that m g h = Ω (I₃ ω₃ − I₁ Ω cos θ)" derived from the θ equation
/// with θ̈ = 0, checked at the slow steady precession; the nutation about it has
/// ω² = Ω² sin²θ + (I₃ω₃ − 2 I₁ Ω cos θ)²/I₁² (θ equation linearized with p_ψ and ω₃ held:
/// ∂ψ̇/∂θ = (I₃ω₃ − 2 I₁ Ω cos θ)/(I₁ sin θ)).
#[test]
fn the_heavy_top_shows_its_steady_precession_and_nods_at_the_closed_form_rate() {
    let (m, h, i3, it, g, theta, spin) = (0.5, 0.04, 4.0e-4, 2.5e-4, 9.81, 0.5f64, 150.0);
    let i1 = it + m * h * h;
    let (a, b, c) = (i1 * theta.cos(), -i3 * spin, m * g * h);
    let slow = (-b - (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
    let fast = (-b + (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
    let nutation = (slow * slow * theta.sin().powi(2)
        + ((i3 * spin - 2.0 * i1 * slow * theta.cos()) / i1).powi(2))
    .sqrt();
    for method in Method::ALL {
        let found = answers(&problem("heavy-symmetric-top"), method);
        let shown = &found[0];
        assert_eq!(shown["kind"], "show");
        assert_eq!(shown["holds"], true);
        close(
            shown["rhs"].as_f64().expect("rhs"),
            m * g * h,
            1e-9,
            "right side",
        );
        // The force at the tip, both precessions: m h sin θ Ω² toward the axis, m g up.
        for (k, rate) in [(3, slow), (4, fast)] {
            let force = &found[k]["components"];
            let (x, y) = (
                force["x"].as_f64().expect("x"),
                force["y"].as_f64().expect("y"),
            );
            let horizontal = x.hypot(y);
            close(
                horizontal,
                m * h * theta.sin() * rate * rate,
                1e-6,
                "toward the axis",
            );
        }
        let period = &found[6];
        assert_eq!(period["kind"], "period");
        close(
            period["angular_frequency"].as_f64().expect("w"),
            nutation,
            1e-6,
            "nutation",
        );
        close(
            period["value"].as_f64().expect("T"),
            2.0 * PI / nutation,
            1e-6,
            "period",
        );
    }
    let text = explain("heavy-symmetric-top", &["--format", "markdown"]);
    let answers = &text[text.find("## Answers").expect("Answers")..];
    for needed in [
        "Equation (2) of step 5",
        // The conditions of steady precession, stated and put in, in symbols.
        "\\dot{\\theta} = 0,\\ \\ddot{\\theta} = 0,\\ \\ddot{\\psi} = 0,\\ \\ddot{\\phi} = 0",
        "do not appear in it",
        "Where $s_{\\theta} \\neq 0$, divided by it",
        // Derived to the form asked, the working ends there.
        "it is the relation asked",
        // In the statement's names, the spin put in, to the stated form.
        "\\dot{\\phi} = \\omega_{3} - \\Omega c_{\\theta}",
        "h m g = \\Omega (I_{3} \\omega_{3} - I_{1} \\Omega c_{\\theta})",
        // The rates from the quadratic, in closed form, not by a search.
        "\\mp \\sqrt{I_{3}^{2} \\omega_{3}^{2} - 4 I_{1} h m g c_{\\theta}}",
        &format!("{slow:.5}"),
        "yes, the motion is steady",
    ] {
        assert!(answers.contains(needed), "{needed}: {answers}");
    }
    // The derivation is in symbols: no number of a state before the check.
    let derivation = &answers[answers.find("Equation (2)").expect("derived")
        ..answers
            .find("it is the relation asked")
            .expect("derived to the end")];
    for number in ["0.5", "3.45", "146.9", "150"] {
        assert!(!derivation.contains(number), "{number}: {derivation}");
    }
    assert!(!answers.contains("search"), "{answers}");
    assert!(!answers.contains("holds there to"), "{answers}");
}

/// The numbered items of a statement: lines that start with `N.`.
fn statement_items(statement: &str) -> Vec<u32> {
    statement
        .lines()
        .filter_map(|line| {
            let (number, rest) = line.trim_start().split_once(". ")?;
            (!rest.is_empty()).then(|| number.parse().ok())?
        })
        .collect()
}

/// Items a worked solution answers in its steps, not by a number: equations to write,
/// a simulation to run, a sweep to make.
const ANSWERED_BY_THE_STEPS: [(&str, u32); 16] = [
    ("five-link-chain", 1),
    ("spherical-pendulum", 1),
    ("torque-free-body-speeds", 1),
    ("two-mass-spring-damper", 1),
    ("torque-free-body", 3),
    ("sleeping-top", 1),
    ("sleeping-top", 2),
    ("block-on-rough-slide", 3),
    ("slider-crank-light-rod", 2),
    // The impact's step: its impulses, the energy lost, how the contact point moves.
    ("impact-double-pendulum", 2),
    ("impact-falling-plank", 2),
    ("impact-spinning-disc", 1),
    ("impact-struck-pendulum", 2),
    ("impact-struck-rod", 2),
    // The statics: the stability of each rest, the forces at both edges.
    ("statics-torsion-pendulum", 2),
    ("statics-tall-block", 1),
];

/// Every bundled problem: the Answers' numbers are the statement's items, in order, each
/// item with at least one answer.
#[test]
fn every_statement_item_has_an_answer_numbered_as_the_statement() {
    let validation = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems/validation");
    let mut paths = all_problems();
    paths.extend(
        (std::fs::read_dir(validation)
            .expect("problems/validation")
            .map(|e| e.expect("entry").path()))
        .filter(|p| p.extension().is_some_and(|e| e == "json")),
    );
    for path in paths {
        let problem = mbd_tutor::problem::load_file(&path).expect("valid");
        let name = path
            .file_stem()
            .expect("name")
            .to_string_lossy()
            .to_string();
        let items = statement_items(problem.statement.as_deref().unwrap_or(""));
        let labels = mbd_tutor::solution::answer_labels(&problem);
        let numbers: Vec<u32> = labels.iter().filter_map(|l| l.parse().ok()).collect();
        if items.is_empty() {
            continue;
        }
        let wanted: Vec<u32> = (items.iter().copied())
            .filter(|&i| !ANSWERED_BY_THE_STEPS.contains(&(name.as_str(), i)))
            .collect();
        for item in &wanted {
            assert!(
                numbers.contains(item),
                "{name}: item {item} has no answer ({labels:?})"
            );
        }
        for number in &numbers {
            assert!(
                items.contains(number),
                "{name}: answer {number} is not an item of the statement"
            );
        }
    }
}
