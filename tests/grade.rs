//! `mbd-tutor grade`: submissions written by hand for a compound pendulum, a cart–pendulum
//! and a double pendulum. Equivalent forms (scaled, rearranged, with the reactions to be
//! eliminated, trigonometric identities, vectors in another frame) are right; each typical
//! mistake is wrong with a diagnosis naming the term. The numbers written in the
//! submissions are checked against closed forms derived here by hand. Then the batch
//! against a key from `variants`, the JSON shape, and a submission that cannot be read.

use crate::support::{problem, run};
use mbd_tutor::equations::Method;
use mbd_tutor::grade::{grade, read, Item, Reference, Report, Verdict};
use std::path::{Path, PathBuf};

fn here(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/grade")
        .join(name)
}

fn graded(name: &str, submission: &str) -> Report {
    let problem = mbd_tutor::problem::load_file(&problem(name)).expect("the problem loads");
    let text = std::fs::read_to_string(here(submission)).expect("the submission");
    let reference = Reference::new(&problem, Method::MotionLaw).expect("derived");
    grade(&reference, &read(&text).expect("a submission"))
}

fn item<'r>(report: &'r Report, name: &str) -> &'r Item {
    report
        .items
        .iter()
        .find(|i| i.item == name)
        .unwrap_or_else(|| panic!("no item {name} in {}", report.text()))
}

/// `name` is wrong and its diagnosis says every one of `words`.
fn wrong_saying(report: &Report, name: &str, words: &[&str]) {
    let i = item(report, name);
    assert_eq!(i.verdict, Verdict::Wrong, "{name}: {}", report.text());
    for w in words {
        assert!(
            i.diagnosis.contains(w),
            "{name} should say `{w}`: {}",
            i.diagnosis
        );
    }
}

fn all_right(report: &Report) {
    for i in &report.items {
        assert_eq!(i.verdict, Verdict::Right, "{}", report.text());
    }
    assert_eq!(report.score(), report.out_of() as f64);
}

fn within(given: f64, expected: f64) -> bool {
    (given - expected).abs() <= 0.005 * expected.abs()
}

/// The compound pendulum of problems/compound-pendulum.json at θ = 1, θ' = −0.5:
/// θ'' = −3g/(2L) sin θ − 3cθ'/(mL²), and the pin force m a* − m g from a* of the centre
/// at L/2 from O.
fn compound_pendulum_by_hand() -> (f64, [f64; 2]) {
    let (m, l, c, g, th, w) = (2.0, 1.0, 0.05, 9.81f64, 1.0f64, -0.5);
    let a = -3.0 * g / (2.0 * l) * th.sin() - 3.0 * c * w / (m * l * l);
    let ax = l / 2.0 * (a * th.cos() - w * w * th.sin());
    let ay = l / 2.0 * (a * th.sin() + w * w * th.cos());
    (a, [m * ax, m * ay + m * g])
}

#[test]
fn compound_pendulum_equivalent_forms_are_right() {
    let (a, force) = compound_pendulum_by_hand();
    assert!(within(-12.345, a) && within(-6.8803, force[0]) && within(9.3673, force[1]));
    let report = graded("compound-pendulum", "compound-pendulum-right.json");
    all_right(&report);
    // Four equations, one of them for the q'' once the pin's two components are eliminated.
    assert_eq!(
        report
            .items
            .iter()
            .filter(|i| i.item.starts_with("equations"))
            .count(),
        4
    );
}

#[test]
fn compound_pendulum_mistakes_are_named() {
    let (a, _) = compound_pendulum_by_hand();
    assert!((-12.715 / a - 1.03).abs() < 1e-3, "the answer is 3 % off");
    let report = graded("compound-pendulum", "compound-pendulum-mistakes.json");
    wrong_saying(&report, "answers.0", &["3.0 %", "too large"]);
    assert_eq!(item(&report, "answers.1").verdict, Verdict::Missing);
    assert_eq!(item(&report, "answers.2").verdict, Verdict::Right);
    wrong_saying(&report, "accelerations.theta", &["factor 2", "sin(theta)"]);
    wrong_saying(
        &report,
        "equations[0]",
        &[
            "coefficient of theta''",
            "L^2*m/12",
            "L^2*m/3",
            "mass centre",
            "parallel-axis",
        ],
    );
    wrong_saying(
        &report,
        "equations[1]",
        &[
            "wrong sign",
            "sign of the moment of the weight of bar about O",
        ],
    );
    wrong_saying(
        &report,
        "equations[2]",
        &["factor 2", "the moment of the weight of bar about O"],
    );
    wrong_saying(
        &report,
        "equations[3]",
        &[
            "cosine where a sine",
            "the moment of the weight of bar about O",
        ],
    );
    wrong_saying(
        &report,
        "equations[4]",
        &["L^2*m/4", "inertia torque of bar", "missing"],
    );
    let syntax = item(&report, "equations[5]");
    assert_eq!(syntax.verdict, Verdict::Invalid);
    assert!(
        syntax.diagnosis.contains("column 37"),
        "{}",
        syntax.diagnosis
    );
    wrong_saying(
        &report,
        "kinematics.bar*.acceleration",
        &["along bar.y", "theta'^2", "missing"],
    );
    // Six equations written for one degree of freedom: none asked for beyond them.
    assert!(!report
        .items
        .iter()
        .any(|i| i.verdict == Verdict::Missing && i.item.starts_with("equations")));
}

/// The cart–pole of problems/cart-pole.json at θ = 0.3, x' = 0.2, θ' = −0.4, solved by hand:
/// (M + m) x'' − m L/2 cos θ θ'' = F − m L/2 sin θ θ'², −m L/2 cos θ x'' + m L²/3 θ'' =
/// m g L/2 sin θ; the pin's force on the pole m a* + m g N.y.
fn cart_pole_by_hand() -> (f64, f64, [f64; 2]) {
    let (big_m, m, l, f, g, th, w) = (1.0, 0.2, 0.8, 2.0, 9.81, 0.3f64, -0.4);
    let (a11, a12, b1) = (
        big_m + m,
        -m * l / 2.0 * th.cos(),
        f - m * l / 2.0 * th.sin() * w * w,
    );
    let (a21, a22, b2) = (a12, m * l * l / 3.0, m * g * l / 2.0 * th.sin());
    let det = a11 * a22 - a12 * a21;
    let x = (b1 * a22 - a12 * b2) / det;
    let t = (a11 * b2 - a21 * b1) / det;
    let ax = x - l / 2.0 * (th.cos() * t - th.sin() * w * w);
    let ay = -l / 2.0 * (th.sin() * t + th.cos() * w * w);
    (x, t, [m * ax, m * ay + m * g])
}

#[test]
fn cart_pole_reactions_are_eliminated_and_a_body_frame_labelled_n_is_named() {
    let (x, t, force) = cart_pole_by_hand();
    assert!(within(2.2686, x) && within(9.5003, t));
    assert!(within(-0.26858, force[0]) && within(1.72537, force[1]));
    let report = graded("cart-pole", "cart-pole-right.json");
    // Every item right; the track's reaction (question 3) is left unanswered.
    for i in &report.items {
        let expected = if i.item == "answers.3" {
            Verdict::Missing
        } else {
            Verdict::Right
        };
        assert_eq!(i.verdict, expected, "{}", report.text());
    }
    // The mistakes: x'' 3 % off; the pin's force in the pole's unit vectors, labelled N.
    let (s, c) = (0.3f64.sin(), 0.3f64.cos());
    let in_pole = [force[0] * c + force[1] * s, -force[0] * s + force[1] * c];
    assert!(within(0.25330, in_pole[0]) && within(1.72768, in_pole[1]));
    assert!((2.3367 / x - 1.03).abs() < 1e-3);
    let report = graded("cart-pole", "cart-pole-mistakes.json");
    wrong_saying(&report, "answers.0", &["3.0 %"]);
    assert_eq!(item(&report, "answers.1").verdict, Verdict::Right);
    wrong_saying(&report, "answers.2", &["pole's unit vectors", "labelled N"]);
    assert_eq!(item(&report, "equations[0]").verdict, Verdict::Right);
    assert_eq!(item(&report, "equations[1]").verdict, Verdict::Right);
}

#[test]
fn double_pendulum_missing_velocity_term_and_one_equation_for_two() {
    all_right(&graded(
        "double-pendulum-rods",
        "double-pendulum-right.json",
    ));
    let report = graded("double-pendulum-rods", "double-pendulum-mistakes.json");
    assert_eq!(item(&report, "equations[0]").verdict, Verdict::Right);
    wrong_saying(
        &report,
        "equations[1]",
        &[
            "about P",
            "q1'^2",
            "centripetal term of B's acceleration",
            "missing",
        ],
    );
    let report = graded("double-pendulum-rods", "double-pendulum-one-equation.json");
    assert_eq!(item(&report, "equations[0]").verdict, Verdict::Right);
    let more = item(&report, "equations[1]");
    assert_eq!(more.verdict, Verdict::Missing);
    assert!(
        more.diagnosis.contains("1 of the 2") && more.diagnosis.contains("1 more"),
        "{}",
        more.diagnosis
    );
    assert_eq!((report.score(), report.out_of()), (1.0, 2));
}

/// A reference made for the questions a class answers works out those alone, and the
/// same as the reference for every question: the double pendulum's q1'' and q2'' at the
/// start (questions 0 and 1), not the energy after 4 s of motion (question 4), which the
/// whole reference integrates to.
#[test]
fn a_reference_for_the_questions_asked_answers_them_as_the_whole() {
    let path = problem("double-pendulum-rods");
    let problem = mbd_tutor::problem::load_file(&path).expect("the problem loads");
    let whole = Reference::new(&problem, Method::MotionLaw).expect("derived");
    let asked = Reference::answering(&problem, Method::MotionLaw, &[0, 1]).expect("derived");
    let (whole, asked) = (whole.answers.expect("all"), asked.answers.expect("asked"));
    assert_eq!((whole.len(), asked.len()), (5, 5));
    assert!(whole.iter().all(Option::is_some));
    assert!(whole[4]
        .as_ref()
        .is_some_and(|a| a.simulated && a.time == 4.0));
    assert_eq!(asked[..2], whole[..2]);
    assert!(asked[2..].iter().all(Option::is_none));
    // Nothing asked, nothing worked out.
    let none = Reference::answering(&problem, Method::MotionLaw, &[]).expect("derived");
    assert!(none.answers.expect("none").iter().all(Option::is_none));
    let submission = read(r#"{"answers": {"1": 0.0, "3": 1.0}}"#).expect("a submission");
    assert_eq!(mbd_tutor::grade::asked_questions([&submission]), [1, 3]);
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mbd-grade-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch");
    dir
}

fn ok(args: &[&std::ffi::OsStr]) -> Vec<u8> {
    let out = run(args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

#[test]
fn batch_grades_three_variants_against_the_key() {
    let dir = scratch("batch");
    let variants = dir.join("variants");
    let problem = here("compound-pendulum-varied.json");
    let count = ["--count", "3", "--seed", "7", "--format", "markdown", "-o"];
    let mut args: Vec<&std::ffi::OsStr> = vec!["variants".as_ref(), problem.as_os_str()];
    args.extend(count.iter().map(std::ffi::OsStr::new));
    args.push(variants.as_os_str());
    ok(&args);
    // ℓ_e = 2L/3 with L = 1 m in every variant (m and c vary): the key says so.
    let key = std::fs::read_to_string(variants.join("key.csv")).expect("key");
    let header: Vec<&str> = key.lines().next().unwrap().split(',').collect();
    let column = header
        .iter()
        .position(|h| h.contains("ell"))
        .expect("the ℓ_e column");
    for row in key.lines().skip(1) {
        let value: f64 = row.split(',').nth(column).unwrap().parse().unwrap();
        assert!((value - 2.0 / 3.0).abs() < 1e-6, "{row}");
    }
    let grades = dir.join("grades.csv");
    let key_path = variants.join("key.csv");
    let batch = here("batch");
    ok(&[
        "grade".as_ref(),
        "--batch".as_ref(),
        batch.as_os_str(),
        "--key".as_ref(),
        key_path.as_os_str(),
        "-o".as_ref(),
        grades.as_os_str(),
    ]);
    let text = std::fs::read_to_string(&grades).expect("grades.csv");
    let rows: Vec<Vec<&str>> = text.lines().map(|l| l.split(',').collect()).collect();
    let header = &rows[0];
    let at = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .unwrap_or_else(|| panic!("{name} in {text}"))
    };
    assert_eq!(rows.len(), 4, "{text}");
    let (answer, equation, score) = (at("answers.2"), at("equations[0]"), at("score"));
    let by_student = |s: &str| {
        rows.iter()
            .find(|r| r[0] == s)
            .unwrap_or_else(|| panic!("{s} in {text}"))
    };
    assert_eq!(by_student("ana")[answer], "1.0");
    assert_eq!(by_student("ben")[answer], "0.0", "the one wrong answer");
    // A name that would start a formula is neutralised.
    let cleo = by_student("'=cleo");
    assert_eq!(
        (cleo[answer], cleo[equation], cleo[score]),
        ("1.0", "1.0", "2.0")
    );
    let _ = std::fs::remove_dir_all(&dir);
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write");
    path
}

#[test]
fn json_shape_determinism_and_unreadable_submissions() {
    let problem = problem("compound-pendulum");
    let submission = here("compound-pendulum-mistakes.json");
    let args: Vec<&std::ffi::OsStr> = vec![
        "grade".as_ref(),
        problem.as_os_str(),
        submission.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ];
    let first = ok(&args);
    assert_eq!(first, ok(&args), "the same bytes every run");
    let value: serde_json::Value = serde_json::from_slice(&first).expect("JSON");
    assert_eq!(value["student"], "mistakes");
    let items = value["items"].as_array().expect("items");
    assert_eq!(value["out_of"].as_u64(), Some(items.len() as u64));
    let total: f64 = items.iter().map(|i| i["score"].as_f64().unwrap()).sum();
    assert_eq!(value["score"].as_f64(), Some(total));
    for i in items {
        let verdict = i["verdict"].as_str().unwrap();
        assert!(["right", "wrong", "missing", "invalid"].contains(&verdict));
        assert!(i["item"].is_string() && i["diagnosis"].is_string());
    }
    let dir = scratch("bad");
    for (text, path) in [
        ("{ \"equations\": 3 }", "equations"),
        ("{ \"equation\": [] }", "equation"),
        ("[", ""),
    ] {
        let bad = write(&dir, "bad.json", text);
        let out = run(&["grade".as_ref(), problem.as_os_str(), bad.as_os_str()]);
        assert_eq!(out.status.code(), Some(1));
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(path) && stderr.contains("hint"), "{stderr}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn equations_that_say_nothing_or_have_no_value_are_wrong() {
    let problem = mbd_tutor::problem::load_file(&problem("compound-pendulum")).expect("loads");
    let reference = Reference::new(&problem, Method::MotionLaw).expect("derived");
    let text = r#"{ "equations": ["0 = 0", "1/(L - L)*theta'' = 0", "sqrt(-L)*theta'' = 1", "sin(theta'') = 0"],
                    "accelerations": { "theta": "sqrt(-g)" } }"#;
    let report = grade(&reference, &read(text).expect("a submission"));
    wrong_saying(&report, "equations[0]", &["0 = 0"]);
    for name in ["equations[1]", "equations[2]", "accelerations.theta"] {
        let i = item(&report, name);
        assert_ne!(i.verdict, Verdict::Right, "{}", report.text());
    }
    wrong_saying(&report, "equations[3]", &["linear"]);
    // None of them determines θ'': one more equation is asked for.
    assert_eq!(item(&report, "equations[4]").verdict, Verdict::Missing);
}
