//! The four-bar linkage by Kane's method (problems/four-bar.json), read from the Markdown
//! handout and held against a derivation by hand; and Kane's letters in every handout.
//!
//! The four-bar: crank A (a) pinned at O, coupler B (b) pinned to A at P, rocker C (c)
//! pinned at Q, a distance d from O along n_x; B and C pinned at R, which closes the loop
//! a a_x + b b_x − c c_x − d n_x = 0. One independent speed u1 = q1'; the reactions at O
//! and R asked for come with the auxiliary speeds u2, u3 (O) and u4, u5 (R).
//!
//! By hand:
//! - the loop dotted with c_y: a sin(q1 − q3) + b sin(q1 + q2 − q3) + d sin q3 = 0, so
//!   Δ = a sin(q1 − q3) + d sin q3 = −b sin(q1 + q2 − q3) on the loop;
//! - u2 slides O along n_x with A and B, and C turns to keep R closed: R's velocity on B,
//!   n_x + ω_B b b_y, equals R's on C, ω_C c c_y. Dotted with c_x (c_y·c_x = 0,
//!   b_y·c_x = −sin(q1 + q2 − q3)): cos q3 − ω_B b sin(q1 + q2 − q3) = 0, so
//!   ω_B = cos q3 / (b sin(q1 + q2 − q3)) = −cos q3 / Δ;
//! - u4 lets R on C part from R on B by a unit along b_x, every other constraint kept:
//!   ^B v^R_4 = b_x, and likewise ^B v^R_5 = b_y;
//! - the pin force at R is inside B + C, the bodies u4 moves: free body C draws it.

use crate::kane_handout::{markdown as kane, section};

#[test]
fn the_pin_force_at_r_is_found_on_the_free_body_that_draws_it() {
    let text = kane("four-bar.json");
    let row4 = section(&text, "**4. $r = 4", "**5. $r = 5");
    assert!(
        row4.contains("drawn on free body $C$ of step 2, and its opposite on $B$"),
        "{row4}"
    );
    // B + C's free body draws the pins P and Q, which do no work with u4.
    assert!(!row4.contains("free body $B + C$"), "{row4}");
    let row5 = section(&text, "**5. $r = 5", "**6.");
    assert!(row5.contains(
        "As in row 4, of the constraint forces only the pair at $R$ does work with $u_{5}$."
    ));
    // C stays still with u5: which bodies move is not said again.
    assert!(!row5.contains("Again only"), "{row5}");
    // O's rows say how the pin gives way and which force does work.
    let row2 = section(&text, "**2. $r = 2", "**3. $r = 3");
    assert!(
        row2.contains(
            "$O$ slides with $u_{2}$ along $\\hat{\\mathbf{n}}_{x}$, $A$ and $B$ with it"
        ),
        "{row2}"
    );
    assert!(
        row2.contains("only $F^{O}_{x}$ does work with it"),
        "{row2}"
    );
}

#[test]
fn every_speeds_partial_velocities_are_in_the_table() {
    let text = kane("four-bar.json");
    let step5 = section(&text, "## Step 5", "## Step 6");
    for speed in [
        "$u_{2} \\to F^{O}_{x}$",
        "$u_{3} \\to F^{O}_{y}$",
        "$u_{4} \\to F^{R}_{x}$",
        "$u_{5} \\to F^{R}_{y}$",
    ] {
        assert!(step5.contains(speed), "{speed}");
    }
    // O slid along n_x carries A with it, unturned; B turns by −cos q3/Δ (see above).
    assert!(step5.contains("{}^{N}\\tilde{\\mathbf{v}}^{A^*}_{2} = \\hat{\\mathbf{n}}_{x}"));
    assert!(step5.contains(
        "{}^{N}\\tilde{\\boldsymbol{\\omega}}^{B}_{2} = -\\frac{\\cos(q_{3})}{\\Delta} \\hat{\\mathbf{b}}_{z}"
    ));
    // The auxiliary speed's partial velocity at R is the unit vector relaxed.
    assert!(step5.contains("{}^{B}\\tilde{\\mathbf{v}}^{R}_{4} = \\hat{\\mathbf{b}}_{x}"));
    assert!(step5.contains("{}^{B}\\tilde{\\mathbf{v}}^{R}_{5} = \\hat{\\mathbf{b}}_{y}"));
    // Each auxiliary row's inertia force body by body, not left to the sum.
    assert!(!step5.contains("collected in their sum below"), "{step5}");
    for r in 2..=5 {
        for body in ["A", "B", "C"] {
            let part = format!("\\tilde{{F}}^{{*}}_{{{r},{body}}}");
            // A does not move with u4 and u5.
            assert_eq!(step5.contains(&part), r <= 3 || body != "A", "{part}");
        }
    }
}

#[test]
fn the_two_forms_of_the_dependent_rates_are_linked_on_the_loop() {
    let text = kane("four-bar.json");
    let step5 = section(&text, "## Step 5", "## Step 6");
    assert!(step5.contains(
        "These are the rates of step 1: on the loop $\\Delta = -b \\sin\\left(q_{1} + q_{2} - q_{3}\\right)$, since the loop dotted with $\\hat{\\mathbf{c}}_{y}$ is zero."
    ));
    assert!(step5.contains(
        "at $\\Delta = 0$, that is where $\\sin\\left(q_{1} + q_{2} - q_{3}\\right) = 0$,"
    ));
    // Numerically at the start (q1 = 1.2 and the loop closed there): the two are equal.
    let (a, b, d) = (0.1f64, 0.3f64, 0.3f64);
    let (q1, q2, q3) = (1.2f64, -0.650_53f64, 1.602_5f64);
    let delta = a * (q1 - q3).sin() + d * q3.sin();
    assert!((delta + b * (q1 + q2 - q3).sin()).abs() < 1e-4, "{delta}");
}

#[test]
fn kanes_rows_are_numbered_one_way() {
    for (name, numbers) in [("four-bar.json", "1"), ("disc-on-cart.json", "1, 2")] {
        let text = kane(name);
        let equations = format!("\\tilde{{F}}^*_r = 0 \\; (r = {numbers})$");
        assert!(text.contains(&equations), "{name}");
        assert!(text.contains("**1. $r = 1\\colon\\; u_{1} = "), "{name}");
    }
}

#[test]
fn kanes_letters_name_nothing_else_in_the_handout() {
    for name in [
        "four-bar.json",
        "disc-on-cart.json",
        "double-pendulum-rods.json",
        "rolling-coin.json",
    ] {
        let text = kane(name);
        // T and E are the kinetic and total energy of step 6, R a pin or a radius.
        for clash in ["\\mathbf{T}_{", "\\mathbf{T}^{*}", "\\sum_{E}", "m_E"] {
            assert!(!text.contains(clash), "{name}: {clash}");
        }
    }
    // The four-bar's pin is R: a force is f.
    let text = kane("four-bar.json");
    assert!(!text.contains("\\mathbf{R}_{") && !text.contains("\\mathbf{R}^{*}"));
    assert!(text.contains("with $\\mathbf{f}_K$ a force applied at the point $K$, $\\mathbf{M}_H$ a couple on body $H$"));
    assert!(text.contains("\\tilde{\\mathbf{v}}^{A^*}_{1} \\cdot \\mathbf{f}^{*}_{A} + \\tilde{\\boldsymbol{\\omega}}^{A}_{1} \\cdot \\mathbf{M}^{*}_{A}"));
}
