//! What a handout prints beside its numbers is true at the state it is printed for: the
//! skidding ball's rows are those that hold while it slides, a reaction's sense is said on
//! the body it acts on where no free body draws it, a moment is about a point the figure
//! names, relations that hold in general are not said to hold at the start, the system
//! matrix's letter names nothing else, an elimination is shown, and an energy has its
//! datum. Numbers are checked against values worked out here.

use crate::support::{explain, run_json};

/// The markdown handout of a bundled problem by `method`.
fn handout(name: &str, method: &str) -> String {
    explain(name, &["--method", method, "--format", "markdown"])
}

/// The text from `from` up to `to` (or the end).
fn between<'t>(text: &'t str, from: &str, to: &str) -> &'t str {
    let start = text
        .find(from)
        .unwrap_or_else(|| panic!("{from} in {text}"));
    let rest = &text[start..];
    &rest[..rest.find(to).unwrap_or(rest.len())]
}

#[test]
fn the_sliding_ball_is_solved_by_the_rows_that_hold_while_it_slides() {
    let text = handout("bowling-ball", "motion-law");
    let plan = between(&text, "## Step 3", "## Step 4");
    let step5 = between(&text, "## Step 5", "## Step 6");
    // ẍ + Rθ̈ = 0 holds only once it rolls: neither the plan nor step 5 gives it as a row.
    for part in [plan, step5] {
        assert!(
            !part.contains("R \\ddot{\\theta} + \\ddot{x} = 0"),
            "{part}"
        );
        assert!(part.contains("sliding friction at the lane"), "{part}");
    }
    assert!(step5.contains("F^{P}_{x} = -\\mu F^{P}_{y}"), "{step5}");
    assert!(!plan.contains("rows 3 to 4 together"), "{plan}");
    // The matrix's row (4) is the law: 1 under F_x, μ under F_y, 0 on the right. With it,
    // rows (2), (4) and (5) give N = m g, F = −μ m g and ẍ = −μ g, as worked by hand.
    assert!(step5.contains("(4) & 0 & 0 & 0 & 1 & \\mu & 0"), "{step5}");
    let (m, g, mu) = (7.0, 9.81_f64, 0.2);
    let friction = -mu * m * g;
    assert!(
        step5.contains(&format!("{}", (friction * 1e3_f64).round() / 1e3)),
        "{friction} in {step5}"
    );
    // Said once, in the Answers; each contact named with its article.
    assert!(!text.contains("Friction changes its mode"), "{text}");
    assert!(!text.contains(" at lane"), "{text}");
    let answers = between(&text, "## Answers", "\n3. ");
    assert!(!answers.contains("$\\mu N$"), "{answers}");
    assert_eq!(
        answers.matches("v_{\\mathrm{slip}} = ").count(),
        1,
        "{answers}"
    );
    assert!(!answers.contains("worked out below"), "{answers}");
}

#[test]
fn a_reaction_inside_a_composite_free_body_has_its_sense_in_words() {
    let kane = handout("disc-on-cart", "kane");
    let answers = between(&kane, "## Answers", "\n\n\n");
    assert!(!answers.contains("acts as drawn"), "{answers}");
    // Both components came out positive (friction 2.18 N, normal 19.62 N on the disc).
    assert!(
        answers.contains("it acts on D along $+\\hat{\\mathbf{c}}_{x}$"),
        "{answers}"
    );
    assert!(
        answers.contains("it acts on D along $+\\hat{\\mathbf{c}}_{y}$"),
        "{answers}"
    );
    // The cart carries the opposite force: −(2.18182, 19.62) in C's unit vectors.
    assert!(
        answers.contains("C carries the equal and opposite force"),
        "{answers}"
    );
    assert!(
        answers.contains("- 19.62 \\hat{\\mathbf{c}}_{y}"),
        "{answers}"
    );
}

#[test]
fn the_disc_in_the_cylinder_takes_moments_about_its_centre_by_name() {
    let text = handout("disc-in-cylinder", "motion-law");
    assert!(
        !text.contains("\\mathbf{M}_{J}"),
        "a moment about the joint's name"
    );
    assert!(text.contains("\\sum \\mathbf{M}_{D^{*}}"), "{text}");
    // r^{D*P} × F written out, reduced by x² + y² = (R − r)² to r F_t.
    let row = between(&text, "D\\colon \\sum \\mathbf{M}_{D^{*}}", "Simplified");
    assert!(
        row.contains("\\mathbf{r}^{D^{*} P} \\times \\mathbf{F}^{P}"),
        "{row}"
    );
    assert!(!text.contains("are written with it"), "{text}");
    // The relations hold in general; at the start every rate is zero (released at rest).
    assert!(text.contains("in general, $\\dot{y}"), "{text}");
    assert!(
        text.contains("at the initial state, $\\dot{y} = 0"),
        "{text}"
    );
}

#[test]
fn the_system_matrix_is_named_by_a_letter_no_frame_uses() {
    for method in ["motion-law", "newton-euler", "lagrange"] {
        let text = handout("heavy-symmetric-top", method);
        assert!(text.contains("| A |"), "the Resal frame A: {method}");
        assert!(!text.contains("\\mathbf{A}\\,\\mathbf{x}"), "{method}");
        assert!(!text.contains("(none)"), "{method}");
    }
    // The Motion Law writes every row out and prints no matrix form; Lagrange's is S x = f.
    let lagrange = handout("heavy-symmetric-top", "lagrange");
    assert!(lagrange.contains("\\mathbf{S}\\,\\mathbf{x} = \\mathbf{f}"));
    let text = handout("heavy-symmetric-top", "motion-law");
    let answers = between(&text, "## Answers", "\n3. ");
    // Derived, not evaluated: no right-hand side's number after the identity.
    assert!(!answers.contains("RHS"), "{answers}");
    // The check of the steady motion is shown from the rows: θ̇ = 0 clears rows (1) and (3),
    // and row (2) is the identity of answer 1.
    assert!(answers.contains("rows (1) and (3) vanish"), "{answers}");
    assert!(
        answers.contains("row (2) is zero by the identity of answer 1"),
        "{answers}"
    );
}

#[test]
fn the_gear_pairs_elimination_is_shown_and_its_force_given_on_both_wheels() {
    let text = handout("gear-pair-torque", "motion-law");
    let answers = between(&text, "## Answers", "\n\n\n");
    assert!(
        answers.contains("Row (3) gives $\\ddot{q}_{B}$"),
        "{answers}"
    );
    assert!(answers.contains("Row (2) gives $F^{P}_{t1}$"), "{answers}");
    assert!(answers.contains("Put into row (1)"), "{answers}");
    // q̈_A = T / (I_A + I_B (r_A/r_B)²), worked here from the problem's values.
    let json = run_json(&[
        "answer".as_ref(),
        crate::support::problem("gear-pair-torque").as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    let found = json["answers"][0]["value"].as_f64().expect("q̈_A");
    let problem: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(crate::support::problem("gear-pair-torque")).expect("readable"),
    )
    .expect("JSON");
    let c = |k: &str| problem["constants"][k]["value"].as_f64().expect(k);
    let expected = c("T") / (c("IA") + c("IB") * (c("rA") / c("rB")).powi(2));
    assert!(
        (found - expected).abs() < 1e-9 * expected,
        "{found} {expected}"
    );
    // The pinion carries the opposite of the tooth force on the gear.
    assert!(
        answers.contains("A carries the equal and opposite force"),
        "{answers}"
    );
    assert!(answers.contains("-15 \\hat{\\mathbf{n}}_{y}"), "{answers}");
    assert!(answers.contains("enter no answer"), "{answers}");
}

#[test]
fn an_energy_says_where_its_potential_is_zero() {
    for method in ["motion-law", "kane"] {
        let text = handout("double-pendulum-rods", method);
        let answers = between(&text, "## Answers", "\n\n\n");
        assert!(
            answers.contains("$V$ is zero at the height of O."),
            "{method}: {answers}"
        );
    }
    // A joint's axis that no row uses is not named.
    for name in ["rack-and-pinion", "disc-on-cart"] {
        let text = handout(name, "motion-law");
        assert!(
            !text.contains("Unit vectors along the joints' axes"),
            "{name}"
        );
    }
}

/// The energy step 6 says is traded between T and V: a fast top started with θ̇ = 0 keeps
/// nearly all its kinetic energy in its spin and nods a little, so what passes between T
/// and V is a small part of T₀ (the largest T, printed before, is T₀ itself). By hand:
/// T₀ = ½[(I_t + m h²) ψ̇² sin²θ + I₃ (φ̇ + ψ̇ cos θ)²] at θ = 0.5, ψ̇ = 3, φ̇ = 150.
#[test]
fn the_energy_traded_between_t_and_v_is_what_passes_between_them() {
    let (m, h, i3, it) = (0.5f64, 0.04f64, 0.0004f64, 0.00025f64);
    let (theta, psi_rate, phi_rate) = (0.5f64, 3.0f64, 150.0f64);
    let t0 = 0.5
        * ((it + m * h * h) * psi_rate.powi(2) * theta.sin().powi(2)
            + i3 * (phi_rate + psi_rate * theta.cos()).powi(2));
    let text = handout("heavy-symmetric-top", "motion-law");
    let step6 = between(&text, "## Step 6", "## Answers");
    let said = step6
        .split(" J is traded between")
        .next()
        .and_then(|s| s.rsplit(' ').next())
        .and_then(|n| n.parse::<f64>().ok())
        .unwrap_or_else(|| panic!("the energy traded in {step6}"));
    assert!(
        said > 0.0 && said < 0.01 * t0,
        "{said} J traded against T₀ = {t0} J"
    );
}

/// A driven system's energy changes by the work of its loads: the cart pulled by P gains
/// P ẋ per second, so step 6 says why its E rises; a free double pendulum keeps its E and
/// says nothing of loads.
#[test]
fn a_driven_systems_energy_is_said_to_change_by_the_loads_work() {
    let said = |name: &str| {
        let text = handout(name, "motion-law");
        between(&text, "## Step 6", "## Answers").contains("do work on it")
    };
    assert!(said("disc-on-cart"));
    assert!(said("gear-pair-torque"));
    assert!(!said("double-pendulum-rods"));
}
