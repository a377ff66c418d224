//! The sentences an instructor would otherwise edit before handing a handout out: none of
//! them false, none boiler-plate. Every bundled handout is read for the sentences that
//! must not appear (a remark on prescribed motion where nothing is prescribed, a joint
//! named by a letter and its kind, the Answers' "in the state of answer 1"); the problems
//! where a sentence was wrong are read for the right one, its numbers checked against
//! values worked out here.

use crate::support::handouts::{handout_of, two_at_a_time};
use crate::support::{explain, run_json};
use serde_json::Value;
use std::path::Path;

/// The methods whose handouts are scanned: the Motion Law's and Kane's share every
/// sentence read here with the other two.
const SCANNED: [&str; 2] = ["motion-law", "kane"];

/// The kinds of joint, as the problem format spells them.
const JOINT_KINDS: [&str; 8] = [
    "revolute",
    "prismatic",
    "cylindrical",
    "planar",
    "universal",
    "spherical",
    "free",
    "weld",
];

/// Whether the problem prescribes a motion: a coordinate's `motion` written with `t`, or a
/// `position` or `velocity` constraint written with it.
fn prescribes_motion(problem: &Value) -> bool {
    let with_t = |e: &Value| {
        e.as_str().is_some_and(|s| {
            s.split(|c: char| !c.is_alphanumeric() && c != '_')
                .any(|w| w == "t")
        })
    };
    let coordinates = problem["coordinates"].as_object().into_iter().flatten();
    let driven = coordinates.into_iter().any(|(_, c)| with_t(&c["motion"]));
    let constraints = problem["constraints"].as_array().into_iter().flatten();
    let written = constraints
        .into_iter()
        .any(|c| with_t(&c["expression"]) || with_t(&c["position"]) || with_t(&c["velocity"]));
    driven || written
}

/// The markdown handout of `path` by `method`; `None` where the method is refused.
fn handout(path: &Path, method: &str) -> Option<String> {
    handout_of(path, method, "markdown")
}

/// What is wrong in one handout of a problem, `None` where nothing is.
fn wrong_sentences(text: &str, problem: &Value) -> Vec<String> {
    let mut wrong = Vec::new();
    if !prescribes_motion(problem) && text.contains("where motion is prescribed") {
        wrong.push("terms of time where nothing is prescribed".to_string());
    }
    for kind in JOINT_KINDS {
        if text.contains(&format!(" ({kind}) |")) || text.contains(&format!(" ({kind}),")) {
            wrong.push(format!("a joint named by its kind, ({kind})"));
        }
    }
    for boiler in [
        "In the state of answer",
        "At the state given above",
        "The components not listed are zero",
        "first switches between sticking and slipping",
        "taken as the dependent ones because",
        "follows from the names",
        "The equations of motion derived by",
        "keep the disc on the plane",
        "its line of centres is a unit vector",
        // A later auxiliary row of the same free body does not say again which bodies move:
        // with the four-bar's u₅, C stays still.
        "Again only B and C move",
        // A skidding ball's rate and slip fall while it slides: "grows" was false.
        "each rate grows linearly",
        "the rate has grown from its start",
        // The solve and the simulation said as a program runs them, not as a course does.
        "Solved in two stages",
        "solved in two stages",
        "which no configuration makes zero",
        "Where it is zero the constraints",
        "their block in these",
        "parts in 10",
        "of its scale",
        "The plots show the state every",
        "are integrated in time",
        "Runge",
        "solved from the constraints at every step",
        "each column of",
        "signs changed so that the mass matrix",
        "The same state as in answer",
        "Angles that move little",
        "both with",
    ] {
        if text.contains(boiler) {
            wrong.push(format!("`{boiler}`"));
        }
    }
    wrong
}

/// Every bundled problem's handouts, two at a time.
#[test]
fn no_bundled_handout_holds_a_sentence_an_instructor_would_cut() {
    let jobs: Vec<(std::path::PathBuf, &str)> = (crate::support::all_problems().into_iter())
        .flat_map(|p| SCANNED.iter().map(move |m| (p.clone(), *m)))
        .collect();
    let found = two_at_a_time(&jobs, |(path, method)| {
        let Some(text) = handout(path, method) else {
            return Vec::new();
        };
        let problem: Value =
            serde_json::from_str(&std::fs::read_to_string(path).expect("readable")).expect("JSON");
        let name = path.file_stem().unwrap_or_default().to_string_lossy();
        (wrong_sentences(&text, &problem).into_iter())
            .map(|w| format!("{name} ({method}): {w}"))
            .collect()
    });
    assert!(found.is_empty(), "{}", found.join("\n"));
}

#[test]
fn prescribed_motion_is_read_from_the_problem() {
    let driven: Value = serde_json::json!({ "coordinates": { "q": { "motion": "w*t" } } });
    let held: Value = serde_json::json!({ "coordinates": { "q": { "motion": "0.3" } } });
    let rheonomic: Value =
        serde_json::json!({ "constraints": [ { "type": "position", "expression": "x - v*t" } ] });
    assert!(prescribes_motion(&driven));
    assert!(!prescribes_motion(&held));
    assert!(prescribes_motion(&rheonomic));
}

/// The text of the Answers section.
fn answers(text: &str) -> &str {
    let at = text.find("## Answers").expect("an Answers section");
    &text[at..]
}

#[test]
fn the_skidding_ball_is_solved_with_the_sliding_law_not_the_no_slip_row() {
    let text = explain(
        "bowling-ball",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(
        !text.contains("Rows (1), (3) and (4) hold no reaction"),
        "{text}"
    );
    assert!(
        text.contains(
            "the no-slip condition does not hold; row (4) above, the sliding law, stands in its place"
        ),
        "the sliding order is not said"
    );
    // The table of initial values is whole: ẍ and θ̈ beside ÿ.
    let table = &text[text.find("At the initial state:").expect("the table")..];
    let table = &table[..table.find("## Step 6").expect("step 6")];
    for name in ["\\ddot{x}", "\\ddot{y}", "\\ddot{\\theta}"] {
        assert!(
            table.contains(&format!("| ${name}$ |")),
            "{name} in {table}"
        );
    }
    // ẍ = −μ g while it slides, θ̈ = −(5/2) μ g / R: from the sliding law and the moment
    // about the centre, worked here.
    let (mu, g, r) = (0.2, 9.81, 0.11);
    for value in [-mu * g, -2.5 * mu * g / r] {
        let printed = format!("{}", (value * 1e4_f64).round() / 1e4);
        assert!(table.contains(&printed), "{printed} in {table}");
    }
    assert!(answers(&text).contains("stops slipping and starts to roll"));
}

#[test]
fn an_answer_at_the_same_state_does_not_say_it_again() {
    let text = explain(
        "double-pendulum-rods",
        &["--method", "motion-law", "--format", "markdown"],
    );
    let answers = answers(&text);
    // Said at the start, and again where the energy is checked at two instants: its
    // first value is at the start, which answer 2's line does not say for it.
    assert_eq!(
        answers.matches("(the initial state)").count(),
        2,
        "{answers}"
    );
    assert!(
        answers.contains("3. At $t = 0\\ \\mathrm{s}$ (the initial state): $E ="),
        "{answers}"
    );
    // The later energy says its instant and how it was reached, once.
    assert!(
        answers.contains("At $t = 4\\ \\mathrm{s}$ (simulated from the initial state):"),
        "{answers}"
    );
    assert!(!answers.contains("After 4 s:"), "{answers}");
    // The energy at the start comes before the one after 4 s, neither restated.
    assert!(!answers.contains("At the start:"), "{answers}");
}

#[test]
fn the_disc_in_the_cylinder_finishes_its_algebra_with_the_distance_kept() {
    let text = explain(
        "disc-in-cylinder",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(text.contains(
        "$\\hat{\\mathbf{e}}_{r} = \\frac{x \\hat{\\mathbf{n}}_{x} + y \\hat{\\mathbf{n}}_{y}}{R - r}$ is a unit vector"
    ));
    // With x² + y² = (R − r)², θ̇ = ẋ y/(r(R − r)) + x² ẋ/(r y (R − r)) is (R − r) ẋ/(r y).
    let relation = text
        .lines()
        .find(|l| l.contains("in general, $\\dot{y}"))
        .expect("the dependent rates");
    let theta = &relation[relation.find("$\\dot{\\theta} = ").expect("θ̇")..];
    assert!(!theta.contains(" + "), "θ̇ not finished: {theta}");
    assert!(
        theta.contains("(R - r)") && theta.contains("r y"),
        "{theta}"
    );
    // Each acceleration asked in a sentence of its own, not run on into its answer.
    assert!(
        !answers(&text).contains("acceleration,"),
        "a run-on question"
    );
}

#[test]
fn constraints_name_the_bodies_they_hold_and_one_level_is_not_a_column() {
    let text = explain(
        "rack-and-pinion",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(
        text.contains("The joints keep the pinion on the rack"),
        "{text}"
    );
    let four_bar = explain(
        "four-bar",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(!four_bar.contains("| Level |"), "a column of one level");
    // A problem with velocity and position constraints keeps the column.
    let coin = explain(
        "rolling-coin",
        &["--method", "kane", "--format", "markdown"],
    );
    assert_eq!(
        coin.contains("| Level |"),
        coin.contains("| position |") && coin.contains("| velocity |")
    );
}

#[test]
fn a_joint_is_named_in_words() {
    let ball = explain(
        "bowling-ball",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(
        ball.contains("| the ball rolls or slides on the lane |"),
        "{ball}"
    );
    let coin = explain(
        "rolling-coin",
        &["--method", "kane", "--format", "markdown"],
    );
    assert!(coin.contains("| the disc rolls on the floor |"), "{coin}");
}

/// The components of the tip's force and the precession rate of an `answer --format json`
/// answer.
fn tip_force(answer: &Value) -> ([f64; 3], f64) {
    let c = &answer["components"];
    let number = |v: &Value| v.as_f64().unwrap_or(f64::NAN);
    let f = [number(&c["x"]), number(&c["y"]), number(&c["z"])];
    (f, number(&answer["state"]["psi'"]))
}

#[test]
fn the_tops_force_in_steady_precession_is_derived_in_closed_form() {
    let text = explain(
        "heavy-symmetric-top",
        &["--method", "motion-law", "--format", "markdown"],
    );
    let answers = answers(&text);
    assert!(answers.contains("Newton's second law"), "{answers}");
    // Each precession rate once in its answer: derived, not listed above the derivation.
    let slow = &answers[answers.find("the slow precession").expect("slow")..];
    let slow = &slow[..slow.find("the fast precession").expect("fast")];
    assert_eq!(slow.matches("3.45313").count(), 1, "{slow}");
    // F = m g n̂_z + m h sin θ Ω² toward the axis, against the numbers `answer` gives.
    let json = run_json(&[
        "answer".as_ref(),
        crate::support::problem("heavy-symmetric-top").as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    let list = json["answers"].as_array().expect("answers");
    let (m, g, h, theta) = (0.5, 9.81, 0.04, 0.5_f64);
    for k in [3, 4] {
        let (f, omega) = tip_force(&list[k]);
        let horizontal = (f[0].powi(2) + f[1].powi(2)).sqrt();
        let expected = m * h * theta.sin() * omega * omega;
        assert!(
            (horizontal - expected).abs() < 1e-4 * expected,
            "{horizontal} {expected}"
        );
        assert!((f[2] - m * g).abs() < 1e-9, "{}", f[2]);
    }
}

/// The conditional sentences of step 5 hold only where true. The skidding ball has one
/// constraint row (its contact's ÿ = 0; the no-slip row gives way to the sliding law), so
/// no "as are rows … after it", and no dependent rate that follows an independent one
/// (ẏ = 0 whatever ẋ, θ̇): no "velocity constraints give the dependent rates". The
/// four-bar's loop closes along b̂x and b̂y, two constraint rows; the rack's pinion turns
/// with the rack, θ̇ = ẋ/r.
#[test]
fn conditional_sentences_of_step_5_are_printed_exactly_where_true() {
    let after_it = "(differentiated to the acceleration level, as ";
    let dependent = "The velocity constraints give the dependent rates";
    for method in ["motion-law", "newton-euler", "kane", "lagrange"] {
        let ball = explain(
            "bowling-ball",
            &["--method", method, "--format", "markdown"],
        );
        assert!(!ball.contains(after_it), "bowling-ball ({method})");
        assert!(!ball.contains(dependent), "bowling-ball ({method})");
        // Kane's handout says its dependent speeds in its own words.
        let rack = explain(
            "rack-and-pinion",
            &["--method", method, "--format", "markdown"],
        );
        assert!(
            method == "kane" || rack.contains(dependent),
            "rack-and-pinion ({method})"
        );
    }
    let ball = explain(
        "bowling-ball",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(ball.contains("(differentiated to the acceleration level)"));
    let rack = explain(
        "rack-and-pinion",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(rack.contains("$\\dot{\\theta} = \\frac{\\dot{x}}{r}$"));
    let four_bar = explain(
        "four-bar",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(four_bar.contains(after_it));
}

/// The energy of the double pendulum by hand (V zero at O, q measured from the downward
/// vertical): T = ½ (m₁L₁²/3) q̇₁² + ½ m₂ |v^{B*}|² + ½ (m₂L₂²/12)(q̇₁ + q̇₂)², with
/// |v^{B*}|² = L₁²q̇₁² + (L₂/2)²(q̇₁ + q̇₂)² + L₁L₂ q̇₁(q̇₁ + q̇₂) cos q₂, and
/// V = −m₁g(L₁/2) cos q₁ − m₂g(L₁ cos q₁ + (L₂/2) cos(q₁ + q₂)). The answer gives E on its
/// line, once, and says it stays constant without a bound of the simulation's rounding.
#[test]
fn a_constant_energy_is_said_by_its_value_in_joules() {
    let (m1, l1, m2, l2, g) = (1.2_f64, 0.6_f64, 0.8_f64, 0.4_f64, 9.81_f64);
    let (q1, q2, u1, u2) = (0.7_f64, -0.4_f64, 1.0_f64, -0.5_f64);
    let w = u1 + u2;
    let vb2 = l1 * l1 * u1 * u1 + (l2 / 2.0).powi(2) * w * w + l1 * l2 * u1 * w * q2.cos();
    let t =
        0.5 * (m1 * l1 * l1 / 3.0) * u1 * u1 + 0.5 * m2 * vb2 + 0.5 * (m2 * l2 * l2 / 12.0) * w * w;
    let v =
        -m1 * g * (l1 / 2.0) * q1.cos() - m2 * g * (l1 * q1.cos() + (l2 / 2.0) * (q1 + q2).cos());
    let by_hand = t + v;
    for method in SCANNED {
        let text = explain(
            "double-pendulum-rods",
            &["--method", method, "--format", "markdown"],
        );
        let answers = answers(&text);
        // The value on its line, once; the yes says it stays constant.
        let at = answers.find("$E = ").expect("the energy's line") + "$E = ".len();
        let printed: String = answers[at..]
            .chars()
            .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | '-'))
            .collect();
        let value: f64 = printed.parse().expect("a number");
        assert!((value - by_hand).abs() < 1e-5, "{value} against {by_hand}");
        // Its change is the simulation's error, not the mechanics: not printed.
        assert!(
            answers.contains("Yes: $E$ stays constant, to within the accuracy of the simulation."),
            "{answers}"
        );
        // T and V as a student writes them, each with its number at the start.
        let number_before = |mark: &str| -> f64 {
            let end = answers.find(mark).expect(mark);
            let start = answers[..end].rfind(" = ").expect("a value") + 3;
            answers[start..end].parse().expect("a number")
        };
        assert!(answers.contains("$E = T + V$"), "{answers}");
        assert!(
            answers.contains("\\mathbf{v}^{B^*}\\vert ^{2}"),
            "{answers}"
        );
        let kinetic = number_before("\\ \\mathrm{J}$ and $V = ");
        let potential = number_before("\\ \\mathrm{J}$, each $h$");
        assert!((kinetic - t).abs() < 1e-5, "T {kinetic} against {t}");
        assert!((potential - v).abs() < 1e-5, "V {potential} against {v}");
    }
}

/// Step 6's plots say what they hold: the top's small angle by its name in the problem
/// (θ, "nutation angle"), the disc in the cylinder's energies, small beside V's size, by
/// their changes from the start; and where T names the torque
/// (the gear pair), what K is.
#[test]
fn step_6s_plot_titles_say_what_is_plotted() {
    let top = explain(
        "heavy-symmetric-top",
        &["--method", "motion-law", "--format", "latex"],
    );
    assert!(top.contains("Nutation angle against time"));
    let coin = explain("rolling-coin", &["--method", "kane", "--format", "latex"]);
    assert!(coin.contains("Lean angle against time"));
    let disc = explain(
        "disc-in-cylinder",
        &["--method", "motion-law", "--format", "latex"],
    );
    // Its energies move little beside V's size: their changes from the start are plotted.
    assert!(
        disc.contains("Energy changes from the start"),
        "the energies on an axis where T does not show"
    );
    let pendulum = explain(
        "double-pendulum-rods",
        &["--method", "motion-law", "--format", "latex"],
    );
    // T and V each swing over a visible part of the axis: the energies themselves.
    assert!(pendulum.contains("Energy against time"));
    assert!(!pendulum.contains("\\addlegendentry{$T - T_{0}$}"));
    let gear = explain(
        "gear-pair-torque",
        &["--method", "motion-law", "--format", "latex"],
    );
    assert!(gear.contains("Energy against time (K is the kinetic energy)"));
}

/// Up to four bodies the Motion Law's rows write each body's inertia terms out, as a
/// textbook does: the double pendulum's moment about O holds r^{OA*} × m₁ a^{A*} and
/// r^{OB*} × m₂ a^{B*}, and no sum over a set.
#[test]
fn a_few_bodies_are_written_term_by_term() {
    let text = explain(
        "double-pendulum-rods",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(
        !text.contains("\\sum_{k \\in"),
        "a sum over a set of two bodies"
    );
    assert!(text.contains("\\mathbf{r}^{O A^*} \\times m_{1}\\, {}^{N}\\mathbf{a}^{A^*} + \\mathbf{r}^{O B^*} \\times m_{2}\\, {}^{N}\\mathbf{a}^{B^*}"));
    assert!(text.contains("m_{1}\\, {}^{N}\\mathbf{a}^{A^*} + m_{2}\\, {}^{N}\\mathbf{a}^{B^*}"));
}
