//! The solve of step 5 said in words: which unknowns come first, and the singular
//! configuration named from the determinant of the constraint rows' block; and a
//! closure's vector loop with its derivative written in step 1.

use crate::support::{explain, problem};
use mbd_tutor::equations::Method;
use mbd_tutor::solution::constraint_block;
use mbd_tutor::symbolic::eval;

#[test]
fn the_four_bars_constraint_block_is_singular_with_coupler_and_rocker_in_line() {
    // By hand: the closure's rows at the acceleration level are the loop's components along
    // b̂_x and b̂_y; in q̈₂ and q̈₃ their block is [[0, c sin φ], [−b, c cos φ]] with
    // φ = q₁ + q₂ − q₃ the angle between the coupler B and the rocker C: det = b c sin φ.
    let text = std::fs::read_to_string(problem("four-bar")).expect("readable");
    let p = mbd_tutor::problem::load(&text).expect("valid");
    let derivation =
        mbd_tutor::pipeline::derive(&p, Method::MotionLaw, mbd_tutor::pipeline::Purpose::Handout)
            .expect("derives");
    let (_, _, det) = constraint_block(&derivation).expect("a block of the constraint rows");
    let (b, c): (f64, f64) = (0.3, 0.25);
    let at = |q: [f64; 3]| {
        let values = derivation.model.values_at(0.0, &q, &[0.0; 3]);
        eval(&det, &values)
    };
    for q in [[1.2_f64, -0.65, 1.6], [0.3, 0.4, -0.2], [2.0, 1.0, 0.5]] {
        let by_hand = b * c * (q[0] + q[1] - q[2]).sin();
        assert!(
            (at(q) - by_hand).abs() < 1e-12,
            "{q:?}: {} against {by_hand}",
            at(q)
        );
    }
    // Zero where the coupler and the rocker are in line, q₃ = q₁ + q₂ (or opposite).
    assert!(at([0.7, 0.2, 0.9]).abs() < 1e-12);
    assert!(at([0.7, 0.2, 0.9 + std::f64::consts::PI]).abs() < 1e-12);
    let handout = explain(
        "four-bar",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(
        handout.contains("This fails where $\\sin\\left(q_{1} + q_{2} - q_{3}\\right) = 0$, the bodies $B$ and $C$ in line"),
        "the singular configuration is named"
    );
}

#[test]
fn rows_without_reactions_are_solved_first() {
    // The double pendulum's moment rows about O and P hold no reaction: they give q̈₁, q̈₂;
    // the force rows then give the pin's reaction.
    let handout = explain(
        "double-pendulum-rods",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(handout.contains(
        "Rows (1) and (2) contain no reaction and give $\\ddot{q}_{1}$ and $\\ddot{q}_{2}$; rows (3) and (4) then give $F^{O}_{x}$ and $F^{O}_{y}$."
    ));
    assert!(!handout.contains("two stages"));
}

#[test]
fn the_four_bars_loop_and_its_derivative_are_written() {
    // O to P along the crank (a â_x), P to R along the coupler (b b̂_x), back from R to Q
    // down the rocker (c ĉ_x) and from Q home to O along the ground (d n̂_x).
    let handout = explain(
        "four-bar",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(handout.contains(
        "\\mathbf{r}^{O P} + \\mathbf{r}^{P R} - \\mathbf{r}^{Q R} - \\mathbf{r}^{O Q} &= a \\hat{\\mathbf{a}}_{x} + b \\hat{\\mathbf{b}}_{x} - c \\hat{\\mathbf{c}}_{x} - d \\hat{\\mathbf{n}}_{x} = \\mathbf{0}"
    ));
    assert!(handout.contains(
        "a \\dot{q}_{1} \\hat{\\mathbf{a}}_{y} + b (\\dot{q}_{1} + \\dot{q}_{2}) \\hat{\\mathbf{b}}_{y} - c \\dot{q}_{3} \\hat{\\mathbf{c}}_{y} = \\mathbf{0}"
    ));
    for format in ["latex", "html"] {
        let text = explain("four-bar", &["--method", "motion-law", "--format", format]);
        assert!(
            text.contains("differentiated in N (the velocity constraints)"),
            "{format}"
        );
    }
}

#[test]
fn a_constant_determinant_is_not_said() {
    // By hand: the gear pair's meshing row r_A q̇_A + r_B q̇_B = 0 gives q̈_B with the
    // coefficient −r_B, a pitch radius: no configuration makes it zero, and a student
    // needs no word of it.
    let handout = explain(
        "gear-pair-torque",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(!handout.contains("determinant"));
    assert!(!handout.contains("\\neq 0"));
    assert!(!handout.contains("singular configuration"));
}
