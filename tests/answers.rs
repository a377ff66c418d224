//! `find.questions` and the handout's Answers: each answer against a closed form or a hand
//! derivation written here; bad questions; the student's handout; both versions compile.

mod bundled;

use crate::support::{pdflatex, pdflatex_present, problem, run};
use mbd_tutor::equations::Method;
use mbd_tutor::numeric::{answer_all, Answer};
use mbd_tutor::pipeline::{derive, Purpose, Solver};
use mbd_tutor::problem::{load, Problem};
use serde_json::{json, Value};

/// A particle pendulum of length L with an optional torsional spring at the pivot.
fn pendulum(questions: Value, spring: Option<(f64, f64)>) -> Value {
    let mut p = json!({
        "title": "Pendulum",
        "dimension": 2,
        "constants": { "m": 0.5, "L": 0.8, "g": 9.81, "k": 3.0, "theta0": 0.9 },
        "coordinates": { "theta": { "initial": 0.6, "rate": 0.5 } },
        "gravity": "-g*N.y",
        "bodies": { "bob": { "mass": "m" } },
        "joints": [ { "name": "O", "type": "revolute", "parent": "N", "child": "bob",
                      "axis": "N.z", "child_at": "L*bob.y", "coordinates": ["theta"] } ],
        "find": { "reactions": ["O"], "questions": questions }
    });
    if let Some((k, rest)) = spring {
        p["constants"]["k"] = json!(k);
        p["constants"]["theta0"] = json!(rest);
        p["loads"] = json!([{ "type": "joint_spring", "joint": "O", "coordinate": "theta",
                              "stiffness": "k", "rest": "theta0" }]);
    }
    p
}

fn answers_of(problem: &Problem) -> Vec<Answer> {
    mbd_tutor::pipeline::answers(problem, Method::MotionLaw).expect("answers")
}

fn load_value(value: &Value) -> Problem {
    load(&value.to_string()).expect("a valid problem")
}

fn close(got: f64, want: f64, tol: f64, what: &str) {
    assert!(
        (got - want).abs() <= tol * want.abs().max(1.0),
        "{what}: got {got}, want {want}"
    );
}

/// The Answers give a value by its `symbol`, a short expression as itself and a long one
/// by its number alone; the state's values carry their units; round-off of zero is 0.
#[test]
fn answers_name_a_value_by_its_symbol_and_never_print_round_off() {
    let energy = "m*L^2*theta'^2/2 - m*g*L*cos(theta) + 0*m*g*L*sin(theta)^2";
    let p = load_value(&pendulum(
        json!([
            { "value": energy, "unit": "J", "symbol": "E" },
            { "value": energy, "unit": "J" },
            { "value": "theta'" },
            { "value": "theta'' + g/L*sin(theta)", "unit": "rad/s^2",
              "at": { "state": { "theta": 0.3, "theta'": 0 } } }
        ]),
        None,
    ));
    let answers = answers_of(&p);
    let views = mbd_tutor::solution::answers_section(&p, &answers);
    // E = m L² θ'²/2 − m g L cos θ at θ = 0.6, θ' = 0.5, by hand.
    let (m, l, g) = (0.5, 0.8, 9.81);
    let e = m * l * l * 0.25 / 2.0 - m * g * l * 0.6f64.cos();
    close(answers[0].values[0].1, e, 1e-12, "E");
    assert_eq!(
        views[0].values_tex,
        vec![format!("E = {}\\ \\mathrm{{J}}", fixed(e))]
    );
    assert_eq!(
        views[1].values_tex,
        vec![format!("{}\\ \\mathrm{{J}}", fixed(e))]
    );
    assert_eq!(
        views[2].values_tex,
        vec!["\\dot{\\theta} = 0.5\\ \\mathrm{rad/s}"]
    );
    // θ'' = −(g/L) sin θ exactly, so the sum is round-off of zero.
    assert_eq!(
        views[3].values_tex,
        vec!["\\ddot{\\theta} + \\frac{g \\sin(\\theta)}{L} = 0\\ \\mathrm{rad/s^{2}}"]
    );
    assert!(
        views[3].at_tex.contains("\\theta = 0.3\\ \\mathrm{rad}"),
        "{}",
        views[3].at_tex
    );
}

/// A pin's reaction is answered by its two forces; its moment about the pin's axis is no
/// unknown (exactly 0) and is left out, with a note.
#[test]
fn a_pins_reaction_is_answered_without_its_free_moment() {
    let p = load_value(&pendulum(
        json!([{ "reaction": "O", "at": { "state": { "theta": 0.0, "theta'": 0.0 } } }]),
        None,
    ));
    let answers = answers_of(&p);
    let views = mbd_tutor::solution::answers_section(&p, &answers);
    // Hanging at rest: the pin holds the weight, F_y = m g = 4.905 N, F_x = 0.
    let fy = answers[0]
        .values
        .iter()
        .find(|(n, _)| n.to_string().ends_with("force.y"))
        .expect("F_y")
        .1;
    close(fy, 0.5 * 9.81, 1e-12, "F_y");
    assert_eq!(views[0].values_tex.len(), 2, "{:?}", views[0].values_tex);
    assert!(views[0]
        .values_tex
        .iter()
        .all(|v| v.starts_with("\\mathbf{F}")));
    // F_y = m g > 0 holds the weight up, said once in words, its size on its line only;
    // F_x is zero and not said. The moment about the free axis, exactly zero, is left out
    // without a word.
    assert!(views[0].note.is_empty(), "{}", views[0].note);
    let words = views[0].steps[0].text.as_str();
    assert!(words.contains("a force up ($+"), "{words}");
    assert!(!words.contains(&fixed(0.5 * 9.81)), "{words}");
    assert!(
        !words.contains("along $+\\hat{\\mathbf{n}}_{x}$"),
        "{words}"
    );
}

fn fixed(x: f64) -> String {
    mbd_tutor::symbolic::fixed(x)
}

#[test]
fn a_pendulums_acceleration_and_tension_at_a_state_match_the_hand_derivation() {
    let p = load_value(&pendulum(
        json!([
            { "value": "theta''", "at": { "state": { "theta": 1.1, "theta'": -2.0 } } },
            { "value": "m*(g*cos(theta) + L*theta'^2)", "unit": "N",
              "at": { "state": { "theta": 1.1, "theta'": -2.0 } } },
            { "reaction": "O", "at": { "state": { "theta": 1.1, "theta'": -2.0 } } }
        ]),
        None,
    ));
    let a = answers_of(&p);
    let (m, l, g, th, w) = (0.5, 0.8, 9.81, 1.1f64, -2.0f64);
    // theta'' = -g/L sin(theta); the rod pulls the bob toward O with T = m (g cos + L w^2).
    close(a[0].values[0].1, -g / l * th.sin(), 1e-12, "theta''");
    let tension = m * (g * th.cos() + l * w * w);
    close(a[1].values[0].1, tension, 1e-12, "tension");
    // The force on the bob from O is T along the rod, from the bob toward O.
    let (fx, fy) = (-tension * th.sin(), tension * th.cos());
    let get = |name: &str| {
        a[2].values
            .iter()
            .find(|(n, _)| n.to_string() == name)
            .map(|(_, v)| *v)
            .expect(name)
    };
    close(get("O.force.x"), fx, 1e-10, "F_x");
    close(get("O.force.y"), fy, 1e-10, "F_y");
}

#[test]
fn an_oscillators_position_at_a_time_matches_the_closed_form() {
    let p = load_value(&json!({
        "title": "Mass on a spring",
        "dimension": 2,
        "constants": { "m": 2.0, "k": 50.0 },
        "coordinates": { "x": { "initial": 0.1, "rate": 0.3 } },
        "bodies": { "cart": { "mass": "m" } },
        "joints": [ { "name": "slide", "type": "prismatic", "parent": "N", "child": "cart",
                      "axis": "N.x", "coordinates": ["x"] } ],
        "loads": [ { "type": "joint_spring", "joint": "slide", "coordinate": "x", "stiffness": "k" } ],
        "find": { "questions": [
            { "value": "x", "at": { "time": 1.3 } },
            { "value": "x'", "at": { "time": 1.3 } },
            { "value": "m*x'^2/2 + k*x^2/2", "unit": "J", "at": { "time": 2.0 } }
        ] },
        "simulate": { "tolerance": 1e-11 }
    }));
    let a = answers_of(&p);
    let w = (50.0f64 / 2.0).sqrt();
    let (x0, v0, t) = (0.1, 0.3, 1.3);
    assert!(a[0].simulated);
    close(
        a[0].values[0].1,
        x0 * (w * t).cos() + v0 / w * (w * t).sin(),
        1e-8,
        "x(t)",
    );
    close(
        a[1].values[0].1,
        -x0 * w * (w * t).sin() + v0 * (w * t).cos(),
        1e-8,
        "x'(t)",
    );
    close(
        a[2].values[0].1,
        2.0 * v0 * v0 / 2.0 + 50.0 * x0 * x0 / 2.0,
        1e-8,
        "energy",
    );
}

#[test]
fn a_pendulum_with_a_spring_finds_its_equilibrium() {
    let p = load_value(&pendulum(
        json!([{ "steady": { "unknowns": ["theta"] }, "at": { "state": { "theta": 0.3, "theta'": 0 } } }]),
        Some((3.0, 0.9)),
    ));
    let a = answers_of(&p);
    let th = a[0].values[0].1;
    // Equilibrium by hand: k (theta - theta0) + m g L sin(theta) = 0.
    let residual = 3.0 * (th - 0.9) + 0.5 * 9.81 * 0.8 * th.sin();
    assert!(residual.abs() < 1e-9, "theta = {th}, residual {residual}");
    assert!(th > 0.0 && th < 0.9, "theta = {th}");
}

#[test]
fn the_heavy_top_precesses_steadily_at_the_closed_form_rates() {
    let text = std::fs::read_to_string(problem("heavy-symmetric-top")).expect("readable");
    let p = load(&text).expect("valid");
    let a = answers_of(&p);
    // m g h = W (I3 w3 - I1 W cos(theta)), I1 = It + m h^2, w3 = 150, theta = 0.5.
    let (m, g, h, i3, it, w3, th) = (0.5, 9.81, 0.04, 4e-4, 2.5e-4, 150.0, 0.5f64);
    let i1 = it + m * h * h;
    let (qa, qb, qc) = (i1 * th.cos(), -i3 * w3, m * g * h);
    let disc = (qb * qb - 4.0 * qa * qc).sqrt();
    let (slow, fast) = ((-qb - disc) / (2.0 * qa), (-qb + disc) / (2.0 * qa));
    close(a[1].values[0].1, slow, 1e-8, "slow precession");
    close(a[2].values[0].1, fast, 1e-8, "fast precession");
    close(a[1].values[1].1 + slow * th.cos(), w3, 1e-10, "spin held");
    // The floor carries the weight; horizontally it supplies m h sin(theta) W^2, the
    // centripetal force of the mass center's circle (sign by the geometry at psi = 0).
    let fz = a[3]
        .values
        .iter()
        .find(|(n, _)| n.to_string() == "tip.force.z")
        .expect("z")
        .1;
    let fy = a[3]
        .values
        .iter()
        .find(|(n, _)| n.to_string() == "tip.force.y")
        .expect("y")
        .1;
    close(fz, m * g, 1e-5, "vertical force");
    close(
        fy.abs(),
        m * h * th.sin() * slow * slow,
        1e-4,
        "horizontal force",
    );
}

fn first_error(value: &Value) -> (String, String, String) {
    let errors = load(&value.to_string()).expect_err("invalid").0;
    let e = &errors[0];
    (
        e.path.clone(),
        e.message.clone(),
        e.hint.clone().unwrap_or_default(),
    )
}

#[test]
fn bad_questions_are_errors_with_the_json_path_and_a_hint() {
    let cases = [
        (
            json!([{ "value": "thta''" }]),
            "find.questions[0].value",
            "theta",
        ),
        (
            json!([{ "reaction": "P" }]),
            "find.questions[0].reaction",
            "",
        ),
        (
            json!([{ "value": "theta", "reaction": "O" }]),
            "find.questions[0]",
            "exactly one",
        ),
        (
            json!([{ "text": "What?" }]),
            "find.questions[0]",
            "exactly one",
        ),
        (
            json!([{ "value": "theta", "at": { "time": -1 } }]),
            "find.questions[0].at.time",
            "0 or more",
        ),
        (
            json!([{ "value": "theta", "at": { "state": { "tehta": 1 } } }]),
            "find.questions[0].at.state.tehta",
            "theta",
        ),
        (
            json!([{ "steady": { "unknowns": ["phi'"] } }]),
            "find.questions[0].steady.unknowns[0]",
            "theta",
        ),
        (
            json!([{ "steady": { "unknowns": ["theta", "theta'"], "zero": ["theta''"] } }]),
            "find.questions[0].steady",
            "no more unknowns",
        ),
        (
            json!([{ "value": "theta", "when": 1 }]),
            "find.questions[0].when",
            "",
        ),
        (json!({ "value": "theta" }), "find.questions", ""),
    ];
    for (questions, path, hint) in cases {
        let (got_path, message, got_hint) = first_error(&pendulum(questions.clone(), None));
        assert_eq!(got_path, path, "{questions}: {message}");
        assert!(got_hint.contains(hint), "{questions}: hint `{got_hint}`");
    }
    // A reaction that exists but is not requested says how to request it.
    let mut p = pendulum(json!([{ "reaction": "O" }]), None);
    p["find"]["reactions"] = json!([]);
    let (path, _, hint) = first_error(&p);
    assert_eq!(path, "find.questions[0].reaction");
    assert!(hint.contains("find.reactions"), "{hint}");
}

#[test]
fn a_steady_motion_that_cannot_be_found_is_an_error_not_a_panic() {
    // A pendulum without a spring has no equilibrium at which theta'' = 0 can be made by its
    // rate alone: theta'' = -g/L sin(theta) does not depend on theta'.
    let p = load_value(&pendulum(
        json!([{ "steady": { "unknowns": ["theta'"] }, "at": { "state": { "theta": 0.5 } } }]),
        None,
    ));
    let derivation = derive(&p, Method::MotionLaw, Purpose::Numbers).expect("derives");
    let solver = Solver::new(&p, &derivation);
    let e = answer_all(&p, &solver).expect_err("no steady motion");
    assert_eq!(e.path, "find.questions[0]");
    assert!(e.hint.is_some());
    let dir = std::env::temp_dir().join(format!("mbd-answers-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch");
    let file = dir.join("p.json");
    std::fs::write(&file, p_text(&p_json_no_steady())).expect("writable");
    let out = run(&["explain".as_ref(), file.as_os_str()]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("find.questions[0]"), "{stderr}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_drive_is_the_torque_of_a_prescribed_motion_and_an_error_elsewhere() {
    // The pendulum driven at theta = 0.6 + 0.5 t: the motor holds it against gravity with
    // the torque m g L sin(theta) (theta'' = 0).
    let mut p = pendulum(json!([{ "drive": "theta" }]), None);
    p["coordinates"]["theta"] = json!({ "motion": "0.6 + 0.5*t" });
    let a = answers_of(&load_value(&p));
    close(
        a[0].values[0].1,
        0.5 * 9.81 * 0.8 * 0.6f64.sin(),
        1e-12,
        "drive",
    );
    // A free coordinate has no drive.
    let free = load_value(&pendulum(json!([{ "drive": "theta" }]), None));
    let derivation = derive(&free, Method::MotionLaw, Purpose::Numbers).expect("derives");
    let e = answer_all(&free, &Solver::new(&free, &derivation)).expect_err("not prescribed");
    assert_eq!(e.path, "find.questions[0]");
    assert!(e.message.contains("not prescribed"), "{}", e.message);
}

fn p_json_no_steady() -> Value {
    pendulum(
        json!([{ "steady": { "unknowns": ["theta'"] }, "at": { "state": { "theta": 0.5 } } }]),
        None,
    )
}

fn p_text(v: &Value) -> String {
    serde_json::to_string_pretty(v).expect("JSON")
}

fn explain(args: &[&std::ffi::OsStr]) -> String {
    let out = run(args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

#[test]
fn the_student_handout_has_blanks_for_every_step_and_no_answers() {
    let path = problem("simple-pendulum");
    for format in ["markdown", "latex", "html"] {
        let args = [
            "explain".as_ref(),
            path.as_os_str(),
            "--student".as_ref(),
            "--format".as_ref(),
            format.as_ref(),
        ];
        let student = explain(&args);
        for heading in [
            "Step 5",
            "Step 6",
            "Answers",
            "Find the angular acceleration",
        ] {
            assert!(student.contains(heading), "{format}: no `{heading}`");
        }
        // theta'' = -g/L sin(0.6) - ... = -6.92393 and the tension are not given away.
        assert!(
            !student.contains("6.92393"),
            "{format} gives an answer away"
        );
        assert!(
            !student.contains("3.42372"),
            "{format} gives a reaction away"
        );
        let worked = explain(
            &args[..2]
                .iter()
                .chain(&args[3..])
                .copied()
                .collect::<Vec<_>>(),
        );
        assert!(
            worked.contains("6.92393"),
            "{format}: the worked solution answers"
        );
    }
}

#[test]
fn both_versions_come_from_one_run_and_compile() {
    let present = pdflatex_present("the answers' handouts");
    let dir = std::env::temp_dir().join(format!("mbd-both-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch");
    for name in ["simple-pendulum", "heavy-symmetric-top"] {
        let out_file = dir.join(format!("{name}.tex"));
        let out = run(&[
            "explain".as_ref(),
            problem(name).as_os_str(),
            "--format".as_ref(),
            "latex".as_ref(),
            "--both".as_ref(),
            "-o".as_ref(),
            out_file.as_os_str(),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let student = dir.join(format!("{name}-student.tex"));
        let worked = std::fs::read_to_string(&out_file).expect("worked solution");
        let handout = std::fs::read_to_string(&student).expect("student handout");
        assert!(worked.contains("\\section*{Answers}") && handout.contains("\\section*{Answers}"));
        // theta'' of the pendulum, the fast precession of the top: answered once only.
        let answer = if name == "heavy-symmetric-top" {
            "61.6608"
        } else {
            "6.92393"
        };
        assert!(
            worked.contains(answer) && !handout.contains(answer),
            "{name}"
        );
        if present {
            for (what, file) in [("worked solution", &out_file), ("handout", &student)] {
                let typeset = pdflatex(file);
                assert!(
                    typeset.compiled(),
                    "{name}: the {what} does not compile: {}",
                    typeset.faults()
                );
            }
        }
    }
    // Without -o there is nowhere to put two files.
    let out = run(&[
        "explain".as_ref(),
        problem("simple-pendulum").as_os_str(),
        "--both".as_ref(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let _ = std::fs::remove_dir_all(&dir);
}

fn bundled_answers(name: &str) -> Vec<Answer> {
    let text = std::fs::read_to_string(problem(name)).expect("readable");
    answers_of(&load(&text).expect("valid"))
}

#[test]
fn the_bundled_steady_questions_match_their_closed_forms() {
    // Two carts on springs under a steady push F0: x1 = F0/k1, x2 = F0/k1 + F0/k2.
    let a = bundled_answers("two-mass-spring-damper");
    let statics = a.last().expect("the static deflections");
    close(statics.values[0].1, 5.0 / 200.0, 1e-9, "x1");
    close(statics.values[1].1, 5.0 / 200.0 + 5.0 / 100.0, 1e-9, "x2");
    // The gyroscope's steady precession with the axle horizontal: psi' = m g d / (Is s).
    let a = bundled_answers("gyroscope-gimbal");
    close(
        a[0].values[0].1,
        0.4 * 9.81 * 0.02 / (2.0e-4 * 300.0),
        1e-9,
        "psi'",
    );
    // The block on the wedge: the textbook's closed forms.
    let a = bundled_answers("block-on-wedge");
    let (m, big_m, g, alpha) = (1.0, 5.0, 9.81, std::f64::consts::PI / 6.0);
    let d = big_m + m * alpha.sin().powi(2);
    close(
        a[0].values[0].1,
        -m * g * alpha.sin() * alpha.cos() / d,
        1e-10,
        "x''",
    );
    close(
        a[1].values[0].1,
        (big_m + m) * g * alpha.sin() / d,
        1e-10,
        "s''",
    );
    // The double pendulum's energy, written by hand in the problem, is the same after 4 s.
    let a = bundled_answers("double-pendulum-rods");
    close(a[3].values[0].1, a[4].values[0].1, 1e-7, "energy after 4 s");
}
