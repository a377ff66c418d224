//! What a handout says once: no sentence of more than 80 characters twice in one handout
//! (every bundled problem, every method, Markdown), Kane's theory stated once with only the
//! terms that apply, Kane's inertia force of a speed body by body, and Kane's worksheet
//! with its own blanks.

use crate::support::handouts::handout_of;
use crate::support::{all_problems, explain};

/// The prose of a Markdown handout from step 1 on (the statement is the problem's own
/// words), without pictures, display math and table rows, cut into sentences.
fn sentences(markdown: &str) -> Vec<String> {
    let from = markdown.find("## Step 1").unwrap_or(0);
    let mut text = markdown[from..].to_string();
    for (open, close) in [("<svg", "</svg>"), ("$$", "$$")] {
        while let Some(start) = text.find(open) {
            let Some(length) = text[start + open.len()..].find(close) else {
                break;
            };
            let end = start + open.len() + length + close.len();
            text.replace_range(start..end, "\n");
        }
    }
    let mut out = Vec::new();
    for line in text.lines().map(str::trim).filter(|l| !l.starts_with('|')) {
        let mut rest = line;
        while !rest.is_empty() {
            let cut = [". ", ": ", "; ", "? "]
                .iter()
                .filter_map(|end| rest.find(end).map(|i| i + 1))
                .min()
                .unwrap_or(rest.len());
            out.push(rest[..cut].trim().to_string());
            rest = &rest[cut..];
        }
    }
    out
}

/// The first sentence over 80 characters that `markdown` says twice.
fn said_twice(markdown: &str) -> Option<String> {
    let mut seen = std::collections::HashSet::new();
    sentences(markdown)
        .into_iter()
        .filter(|s| s.chars().count() > 80)
        .find(|s| !seen.insert(s.clone()))
}

#[test]
fn the_sentence_finder_finds_a_repeated_sentence() {
    let long =
        "The reactions of the joints do no work with the speeds and drop out of every row here.";
    let text = format!("# T\n\nA long statement.\n\n## Step 1\n\n{long} Short one. {long}\n");
    assert_eq!(said_twice(&text).as_deref(), Some(long));
    let once = format!("## Step 1\n\n{long}\n\n$$\n{long}\n$$\n| {long} |\n");
    assert_eq!(said_twice(&once), None);
}

#[test]
fn no_long_sentence_is_said_twice_in_one_handout() {
    let mut handouts = 0;
    let mut repeated = Vec::new();
    for path in all_problems() {
        for method in ["newton-euler", "motion-law", "kane", "lagrange"] {
            let Some(text) = handout_of(&path, method, "markdown") else {
                continue;
            };
            handouts += 1;
            if let Some(sentence) = said_twice(&text) {
                repeated.push(format!("{} {method}: {sentence}", path.display()));
            }
        }
    }
    assert!(handouts >= 150, "only {handouts} handouts were written");
    assert!(repeated.is_empty(), "said twice:\n{}", repeated.join("\n"));
}

/// How many times `needle` occurs in `text`.
fn count(text: &str, needle: &str) -> usize {
    text.matches(needle).count()
}

#[test]
fn kane_states_its_theory_once_with_only_what_applies() {
    let kane = |name: &str| explain(name, &["--method", "kane", "--format", "markdown"]);
    // Rigid rods: the inertia torque is defined, once, with a body letter that is not one
    // of the rods' (A and B): D.
    let rods = kane("double-pendulum-rods");
    let torque = "\\mathbf{M}^{*}_{D} = -\\mathbf{I}^{D} \\cdot \\boldsymbol{\\alpha}^{D}";
    assert_eq!(count(&rods, torque), 1);
    assert_eq!(count(&rods, "\\sum_{B}"), 0);
    assert_eq!(
        count(
            &rods,
            "the generalized active force and the generalized inertia force"
        ),
        1
    );
    // A bob on a light rod is a particle: no inertia torque, no couple on a body.
    let bob = kane("simple-pendulum");
    assert_eq!(count(&bob, "\\mathbf{M}^{*}_{"), 0);
    assert_eq!(count(&bob, "a couple on body"), 0);
    // The plan speaks of auxiliary speeds only where a reaction is asked for.
    for name in [
        "simple-pendulum",
        "double-pendulum-rods",
        "four-bar",
        "rolling-coin",
    ] {
        let text = kane(name);
        assert_eq!(
            text.contains("one per requested reaction component"),
            text.contains("(an auxiliary speed"),
            "{name}"
        );
    }
}

#[test]
fn the_four_bars_inertia_force_is_shown_body_by_body() {
    // By hand: rod A (m, a) turns with q1 about its pin O, I_O = m a²/12 + m (a/2)² =
    // m a²/3, and its partial angular velocity for u1 = q1' is 1: F*_{1,A} = −(m a²/3) q1''.
    // Rod C (m, c) turns with q3 about its pin, I = m c²/3, and q3' = C_31 q1' with
    // C_31 = (a/Δ)(sin(q1 − q3) + d s1/c) from the velocity constraints (step 5):
    // F*_{1,C} = −(m c²/3) C_31 q3'' = −(a c m/(3Δ)) (c sin(q1 − q3) + d s1) q3''.
    let text = explain("four-bar", &["--method", "kane", "--format", "markdown"]);
    assert!(text.contains(
        "\\tilde{F}^{*}_{1} &= \\tilde{F}^{*}_{1,A} + \\tilde{F}^{*}_{1,B} + \\tilde{F}^{*}_{1,C}"
    ));
    // Each body's dot products multiplied out, then its term (f: the four-bar's pin is R).
    assert!(text.contains(
        "\\tilde{F}^{*}_{1,A} &= \\tilde{\\mathbf{v}}^{A^*}_{1} \\cdot \\mathbf{f}^{*}_{A}"
    ));
    assert!(text.contains("&= -\\frac{a^{2} m}{3} \\ddot{q}_{1} \\\\ \\tilde{F}^{*}_{1,B}"));
    assert!(text.contains("&= \\frac{a b c m \\sin(q_{2})}{3 \\Delta} \\ddot{q}_{3}"));
    assert!(!text.contains("\\tilde{F}^{*}_{1}\\ \\text{collected"));
}

#[test]
fn kanes_worksheet_has_its_partial_velocities_and_generalized_forces_to_fill_in() {
    let args = ["--method", "kane", "--format", "markdown", "--student"];
    let sheet = explain("double-pendulum-rods", &args);
    // Two speeds: u1 moves both rods, u2 only B: three lines of partial velocities,
    // then one line of F_r and F*_r per speed.
    assert!(sheet.contains("| Speed | Body | Partial velocity | Partial angular velocity |"));
    assert!(sheet.contains("| $u_{1} = \\dot{q}_{1}$ | A |  |  |"));
    assert!(sheet.contains("|  | B |  |  |"));
    assert!(sheet.contains("| $u_{2} = \\dot{q}_{2}$ | B |  |  |"));
    assert!(sheet.contains("| Speed | $F_r$ | $F^{*}_r$ |"));
    assert!(sheet.contains("| $u_{1} = \\dot{q}_{1}$ |  |  |\n| $u_{2} = \\dot{q}_{2}$ |  |  |\n"));
    assert!(!sheet.contains("Simulate the motion and check it."));
}
