//! Sentences of the handouts an instructor found untrue or not in a course's words, each
//! checked where it is printed: the drivers' work checked in step 6, a mesh's zero normal
//! component said to be an assumption, a constraint row written with its signs turned, one
//! name for a pin, the generalized force on the constraint, the condition in plain terms,
//! one order of the rows, the dependent rates in full, the letters of `A x = b` free of
//! the coordinates, and a minus sign for a negative number.

use crate::support::handouts::{bundled as handout, has, lacks};

/// Step 6 of a driven system states the work of its loads and the balance, not "as the
/// energy plot shows": the rack's torque does W = T θ = 31.0119 J in 1 s (the closed form
/// is checked in `load_work`).
#[test]
fn step_six_checks_the_work_of_the_applied_loads() {
    for (name, work) in [
        ("rack-and-pinion", "$W = 31.0119$ J"),
        ("gear-pair-torque", "$W = 142.2$ J"),
        ("disc-on-cart", "$W = 23.2364$ J"),
    ] {
        let text = handout(name, "motion-law", "markdown");
        lacks(&text, "as the energy plot shows", name);
        has(&text, work, name);
        // Its difference is the round-off of the sums: said so, not printed as noise.
        has(&text, "equals $W(t)$ to within round-off", name);
        lacks(&text, "10^{-1", name);
    }
}

#[test]
fn a_zero_normal_component_of_a_mesh_is_said_to_be_an_assumption() {
    for name in ["rack-and-pinion", "gear-pair-torque"] {
        let text = handout(name, "motion-law", "markdown");
        has(&text, "is zero by assumption, not as a result", name);
    }
}

#[test]
fn the_gear_pair_names_its_pins_one_way_and_turns_the_signs_of_its_row() {
    let text = handout("gear-pair-torque", "newton-euler", "markdown");
    let name = "gear-pair-torque";
    has(&text, "$r_{A} \\dot{q}_{A} + r_{B} \\dot{q}_{B} = 0$", name);
    lacks(
        &text,
        "$-r_{A} \\dot{q}_{A} - r_{B} \\dot{q}_{B} = 0$",
        name,
    );
    has(&text, "at pin $O_{A}$", name);
    lacks(&text, "pin OA", name);
    has(&text, "opposite to that on B (Newton's third law)", name);
}

#[test]
fn the_disc_in_a_cylinder_writes_its_forces_on_the_motion() {
    let name = "disc-in-cylinder";
    let text = handout(name, "lagrange", "markdown");
    has(&text, "Q_{3}\\colon\\; r F^{P}_{t}", name);
    lacks(&text, "(x^{2} + y^{2}) F^{P}_{t}", name);
    has(&text, "wherever $y \\neq 0$", name);
    has(&text, "$\\lambda_{1} = ", name);
    // The coordinates are x and y: the column of unknowns takes another letter.
    lacks(&text, "\\,\\mathbf{x} = ", name);
    has(&text, "\\,\\mathbf{z} = ", name);
}

#[test]
fn the_heavy_top_finishes_its_algebra_and_names_its_body_by_its_letter() {
    let name = "heavy-symmetric-top";
    let text = handout(name, "motion-law", "markdown");
    lacks(&text, "s_{\\theta}^{3}", name);
    lacks(&text, "**Body top**", name);
    has(&text, "**Body B**", name);
    lacks(&text, "the joint's other angles", name);
}

#[test]
fn the_bowling_ball_gives_its_order_and_its_sliding_law_once() {
    let name = "bowling-ball";
    let text = handout(name, "motion-law", "markdown");
    // Step 5 says the sliding law stands in place of row (4); the solve does not again,
    // nor does it print the law a second time.
    has(
        &text,
        "row (4) above, the sliding law, stands in its place",
        name,
    );
    let law = "\\Rightarrow \\quad F^{P}_{x} = -\\mu F^{P}_{y}";
    assert_eq!(
        text.matches(law).count(),
        1,
        "{name}: the sliding law said once"
    );
    lacks(&text, "is the sliding law, not the no-slip condition", name);
    lacks(&text, "in the order of step 3", name);
}

#[test]
fn the_disc_on_a_cart_lists_every_dependent_rate() {
    let name = "disc-on-cart";
    let text = handout(name, "kane", "markdown");
    has(
        &text,
        "Dependent rates: $\\dot{h}$ (the position constraints differentiated in time) and \
         $\\dot{\\theta}$ (solved from the velocity constraints)",
        name,
    );
    lacks(
        &text,
        "(solved from the velocity constraints): $\\dot{h}$",
        name,
    );
}

#[test]
fn a_negative_number_in_the_text_has_a_minus_sign() {
    let name = "disc-in-cylinder";
    let latex = handout(name, "lagrange", "latex");
    lacks(&latex, "-{}0.396863", name);
    has(&latex, "$-0.396863$ m", name);
    let html = handout(name, "lagrange", "html");
    lacks(&html, ">-0.396863 m", name);
    has(&html, "−0.396863 m", name);
}
