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
    // C stays still with u5 (ṽ^{C*}_5 and ω̃^C_5 vanish on the loop, see below): said once.
    assert!(
        row5.contains("Only $B$ moves with $u_{5}$ ($B$ moves and turns); $C$ does not move, its partial velocities zero on the loop, and adds nothing to"),
        "{row5}"
    );
    assert!(row5.contains(
        "As in row 4, of the constraint forces only the pair at $R$ does work with $u_{5}$."
    ));
    // O's rows say how each body moves and which force does work: O slid along n_x
    // carries A unturned; B moves and turns (ω_B = −cos q3/Δ); C turns about its pin Q.
    let row2 = section(&text, "**2. $r = 2", "**3. $r = 3");
    assert!(
        row2.contains("$A$ slides without turning, $B$ moves and turns, and $C$ turns about $Q$."),
        "{row2}"
    );
    assert!(
        row2.contains("only $F^{O}_{x}$ does work with it"),
        "{row2}"
    );
    // The plan names, for the rows of the pin at R, the bodies they move cut at R (with
    // u₅ only B moves, and C adds nothing): F^R is the pair either side of the cut, drawn on
    // free body C; B + C taken whole, which does not show it, is not drawn.
    let plan = section(&text, "## Step 3", "## Step 4");
    for r in [4, 5] {
        let row = format!(
            "| $B + C\\text{{, cut at }}R$ | $\\tilde{{F}}_{{{r}}} + \\tilde{{F}}^{{*}}_{{{r}}} = 0$ |"
        );
        assert!(plan.contains(&row), "{row}\n{plan}");
    }
    assert!(!text.contains("### Free body $B + C$"));
}

#[test]
fn every_speeds_partial_velocities_are_in_the_table() {
    let text = kane("four-bar.json");
    let step5 = section(&text, "## Step 5", "## Step 6");
    // Each auxiliary speed by the force it brings in, in words, not an arrow.
    for speed in [
        "$u_{2}\\text{, for } F^{O}_{x}$",
        "$u_{3}\\text{, for } F^{O}_{y}$",
        "$u_{4}\\text{, for } F^{R}_{x}$",
        "$u_{5}\\text{, for } F^{R}_{y}$",
    ] {
        assert!(step5.contains(speed), "{speed}");
    }
    assert!(!text.contains("\\to F"), "{step5}");
    // Finished on the loop (see `the_partial_velocities_are_finished_on_the_loop`).
    for entry in [
        "{}^{N}\\tilde{\\mathbf{v}}^{C^*}_{4} = -\\frac{b}{2 \\Delta} \\hat{\\mathbf{c}}_{y}",
        "{}^{N}\\tilde{\\boldsymbol{\\omega}}^{C}_{4} = -\\frac{b}{c \\Delta} \\hat{\\mathbf{c}}_{z}",
        "{}^{N}\\tilde{\\mathbf{v}}^{B^*}_{5} = -\\frac{1}{2} \\hat{\\mathbf{b}}_{y}",
        "{}^{N}\\tilde{\\boldsymbol{\\omega}}^{B}_{5} = -\\frac{1}{b} \\hat{\\mathbf{b}}_{z}",
    ] {
        assert!(step5.contains(entry), "{entry}\n{step5}");
    }
    // C does not move with u5: no line of its own, only R's relative to B.
    assert!(!step5.contains("\\tilde{\\mathbf{v}}^{C^*}_{5}"), "{step5}");
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
            // A does not move with u4 and u5, nor C with u5.
            let moves = r <= 3 || (body == "B") || (body == "C" && r == 4);
            assert_eq!(step5.contains(&part), moves, "{part}");
        }
    }
}

#[test]
fn the_two_forms_of_the_dependent_rates_are_linked_on_the_loop() {
    let text = kane("four-bar.json");
    let step5 = section(&text, "## Step 5", "## Step 6");
    assert!(step5.contains(
        "These are the rates of step 1: on the loop $\\Delta = -b \\sin\\left(q_{1} + q_{2} - q_{3}\\right)$, since the loop dotted with $\\hat{\\mathbf{c}}_{y}$ is zero"
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

/// The four-bar closed by hand at crank angle `q1`: R where the circles about P (radius b)
/// and Q (radius c) meet, on the upper side as assembled; `(q2, q3)`.
fn closed(q1: f64) -> (f64, f64) {
    let (a, b, c, d) = (0.1f64, 0.3f64, 0.25f64, 0.3f64);
    let p = (a * q1.cos(), a * q1.sin());
    let (dx, dy) = (d - p.0, -p.1);
    let l = (dx * dx + dy * dy).sqrt();
    // Along P→Q a distance s, then h across: s = (b² − c² + l²)/(2l), h = √(b² − s²).
    let s = (b * b - c * c + l * l) / (2.0 * l);
    let h = (b * b - s * s).sqrt();
    let (ux, uy) = (dx / l, dy / l);
    let r = (p.0 + s * ux - h * uy, p.1 + s * uy + h * ux);
    let q12 = (r.1 - p.1).atan2(r.0 - p.0);
    let q3 = r.1.atan2(r.0 - d);
    (q12 - q1, q3)
}

#[test]
fn the_partial_velocities_are_finished_on_the_loop() {
    // At the start (q1 = 1.2) and at a second closed state, each form the handout prints
    // equals the one before the loop's constraints were used (Δ = a sin(q1 − q3) + d sin q3):
    // the loop along b_x is −a cos q2 + d cos(q1 + q2) + c cos(q1 + q2 − q3) − b = 0, along
    // b_y a sin q2 − d sin(q1 + q2) − c sin(q1 + q2 − q3) = 0, and Δ = −b sin(q1 + q2 − q3).
    let (a, b, c, d) = (0.1f64, 0.3f64, 0.25f64, 0.3f64);
    let (q2, q3) = closed(1.2);
    assert!(
        (q2 + 0.650_53).abs() < 1e-4 && (q3 - 1.602_5).abs() < 1e-4,
        "{q2} {q3}"
    );
    for q1 in [1.2f64, 0.9] {
        let (q2, q3) = closed(q1);
        let delta = a * (q1 - q3).sin() + d * q3.sin();
        let s123 = (q1 + q2 - q3).sin();
        let c123 = (q1 + q2 - q3).cos();
        let pairs = [
            // ṽ^{C*}_4 along c_y and ω̃^C_4: the brackets are −b by the loop along b_x.
            (
                (a * q2.cos() - c * c123 - d * (q1 + q2).cos()) / (2.0 * delta),
                -b / (2.0 * delta),
            ),
            (
                -(c123 - a * q2.cos() / c + d * (q1 + q2).cos() / c) / delta,
                -b / (c * delta),
            ),
            // ṽ^{C*}_5 and ω̃^C_5: the loop along b_y, zero.
            (
                (c * s123 + d * (q1 + q2).sin() - a * q2.sin()) / (2.0 * delta),
                0.0,
            ),
            (
                (s123 - a * q2.sin() / c + d * (q1 + q2).sin() / c) / delta,
                0.0,
            ),
            // ṽ^{B*}_5 and ω̃^B_5, with Δ = −b sin(q1 + q2 − q3).
            (b * s123 / (2.0 * delta), -0.5),
            (s123 / delta, -1.0 / b),
        ];
        for (k, (before, after)) in pairs.iter().enumerate() {
            assert!((before - after).abs() < 1e-9, "{q1}: {k}: {before} {after}");
        }
    }
}

#[test]
fn both_forms_of_the_dependent_rates_are_linked_with_every_loop_row_they_need() {
    // Step 1's q3' = a sin q2/(c sin(q1 + q2 − q3)) q1' and step 5's
    // q3' = a (c sin(q1 − q3) + d sin q1)/(c Δ) q1' agree by Δ = −b sin(q1 + q2 − q3) (the
    // loop along c_y) and c sin(q1 − q3) + d sin q1 = −b sin q2 (the loop along a_y:
    // a a_x·a_y + b sin q2 − c sin(q3 − q1) + d sin q1 = 0).
    let text = kane("four-bar.json");
    let step5 = section(&text, "## Step 5", "## Step 6");
    let a_y = "\\hat{\\mathbf{a}}_{y}";
    assert!(
        step5.contains(&format!("since the loop dotted with ${a_y}$ is zero")),
        "{step5}"
    );
    // Δ is defined where the rates first use it, not in step 4.
    assert!(
        step5.contains("over the common denominator $\\Delta = "),
        "{step5}"
    );
    assert!(!section(&text, "## Step 4", "## Step 5").contains("\\Delta"));
    let (a, b, c, d) = (0.1f64, 0.3f64, 0.25f64, 0.3f64);
    for q1 in [1.2f64, 0.9] {
        let (q2, q3) = closed(q1);
        assert!((c * (q1 - q3).sin() + d * q1.sin() + b * q2.sin()).abs() < 1e-12);
        let delta = a * (q1 - q3).sin() + d * q3.sin();
        let step1 = a * q2.sin() / (c * (q1 + q2 - q3).sin());
        let step5 = a * (c * (q1 - q3).sin() + d * q1.sin()) / (c * delta);
        assert!((step1 - step5).abs() < 1e-9, "{step1} {step5}");
    }
}
