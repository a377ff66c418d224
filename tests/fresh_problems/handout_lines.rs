//! Lines of handouts that said something other than a course says: a `tips` answered with
//! which contact is lost, at rest or as the motion starts; the student's worksheet naming
//! bodies by the worked solution's letters; Lagrange's matrix rule naming its own method.

use super::fixture;
use crate::support::{explain, explain_file, run};

/// `explain` of tests/fresh_problems/NAME.json with `args`.
fn explained(name: &str, args: &[&str]) -> String {
    explain_file(&fixture(name), args)
}

/// The Answers' part of a handout.
fn answers(text: &str) -> &str {
    text.split("## Answers").nth(1).expect("the Answers")
}

/// The crate pushed at 0.9 m by 80 N: its back corner would need F_n = (m g w/2 − P h)/w,
/// a pull; the twisted bar's foot still pushes as it starts to turn.
#[test]
fn a_tips_answer_names_the_contact_lost_and_when() {
    let (m, g, w, h, p) = (20.0, 9.81, 0.6, 0.9, 80.0);
    let back: f64 = (m * g * w / 2.0 - p * h) / w;
    let text = explained("crate-pushed-high", &["--set", "P=80,h=0.9"]);
    let part = answers(&text);
    assert!(!part.contains("rest needs"), "{part}");
    assert!(
        part.contains("yes: at rest the contact at the back would have to pull, so it is lost"),
        "{part}"
    );
    assert!(
        part.contains(&format!("F_{{n}} = {:.1}", back)),
        "the normal force {back:.1} N in {part}"
    );
    let text = explained("rod-twisted-on-rough-floor", &[]);
    let part = answers(&text);
    assert!(
        part.contains("no: as the motion starts the contact at the foot pushes"),
        "{part}"
    );
    let first = part.split("\n2.").next().expect("the first answer");
    assert!(
        first.contains("(the initial state)") && !first.contains("every friction site sticking"),
        "answered as it starts: {first}"
    );
}

/// The wedge and the block are W and B in the worked solution's frame table: the same in
/// the student's.
#[test]
fn the_students_worksheet_names_bodies_by_the_worked_solutions_letters() {
    for method in crate::support::METHODS {
        let worked = explain("block-on-wedge", &["--method", method]);
        let student = explain("block-on-wedge", &["--method", method, "--student"]);
        // The first column of the frame table, below its heading.
        let frames = |text: &str| -> Vec<String> {
            (text.lines())
                .skip_while(|l| !l.starts_with("| Frame"))
                .skip(2)
                .take_while(|l| l.starts_with('|'))
                .map(|l| l.split('|').nth(1).unwrap_or("").trim().to_string())
                .collect()
        };
        let (w, s) = (frames(&worked), frames(&student));
        assert_eq!(w, ["N", "W", "B"], "{method}: the worked solution's frames");
        assert_eq!(w, s, "{method}: the frames are named alike");
    }
}

/// The six spherical links' system is given by its values; Lagrange's rule beside them
/// is its own equation's, with the mass matrix's sign, not Kane's row.
#[test]
fn lagranges_matrix_rule_names_its_own_equation() {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/browser/six-spherical-links.json");
    let out = run(&[
        std::ffi::OsStr::new("explain"),
        path.as_os_str(),
        std::ffi::OsStr::new("--method"),
        std::ffi::OsStr::new("lagrange"),
    ]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).expect("UTF-8");
    assert!(!text.contains("Kane"), "Lagrange's handout names Kane");
    let rule = (text.lines())
        .find(|l| l.contains("in Lagrange's equation of coordinate r"))
        .expect("the rule of the entries");
    assert!(rule.contains("_{rj} = \\sum_{k}"), "positive: {rule}");
}
