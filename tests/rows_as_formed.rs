//! Step 5's rows as formed: the forces as the free-body diagram gives them, and a long
//! inertia force or torque by the names of step 4 instead of multiplied out, as a textbook
//! writes `ΣF·x̂ − m a*·x̂ = 0` before simplifying it.

/// `mbd-tutor explain NAME --method METHOD --format FORMAT` on standard output.
fn explain(name: &str, method: &str, format: &str) -> String {
    crate::support::explain(name, &["--method", method, "--format", format])
}

/// The row as formed under the Markdown heading that starts with `heading`: the first
/// display after it.
fn row_as_formed(markdown: &str, heading: &str) -> String {
    let start = markdown
        .find(heading)
        .unwrap_or_else(|| panic!("no heading {heading}"));
    let rest = &markdown[start..];
    let open = rest.find("$$\n").expect("a display") + 3;
    let close = rest[open..].find("\n$$").expect("its end");
    rest[open..open + close].to_string()
}

#[test]
fn a_long_inertia_force_is_written_by_the_acceleration_of_step_4() {
    let markdown = explain("validation/ten-link-chain", "newton-euler", "markdown");
    // By hand: the pin forces at P7 and P8 in link 7's frame, gravity along x̂ of link 7
    // (whose angle is q1 + … + q7), and the inertia force −m a*·x̂, whose a* step 4 gives.
    let heading =
        "**19. $\\mathrm{link}_{7}\\colon \\sum \\mathbf{F} \\cdot \\hat{\\mathbf{x}}_{\\mathrm{link}_{7}}$**";
    assert_eq!(
        row_as_formed(&markdown, heading),
        "[-F^{P_{8}}_{x} + F^{P_{7}}_{x} c_{7} + F^{P_{7}}_{y} s_{7}] - m g s_{1\\ldots 7} - m\\, {}^{N}\\mathbf{a}^{\\mathrm{link}_{7}^*} \\cdot \\hat{\\mathbf{x}}_{\\mathrm{link}_{7}} = 0"
    );
    assert!(
        markdown.contains("{}^{N}\\mathbf{a}^{\\mathrm{link}_{7}^*} = "),
        "step 4 defines the acceleration the row names"
    );
}

#[test]
fn a_short_inertia_force_stays_multiplied_out() {
    let markdown = explain("validation/ten-link-chain", "newton-euler", "markdown");
    // Link 1 turns about a fixed pin: m a*·x̂ = m (L/2) q̈1 in one term.
    let heading =
        "**1. $\\mathrm{link}_{1}\\colon \\sum \\mathbf{F} \\cdot \\hat{\\mathbf{x}}_{\\mathrm{link}_{1}}$**";
    assert_eq!(
        row_as_formed(&markdown, heading),
        "[-F^{P_{2}}_{x} + F^{O}_{x} c_{1} + F^{O}_{y} s_{1}] - m g s_{1} - \\frac{L m \\ddot{q}_{1}}{2} = 0"
    );
}

#[test]
fn a_planar_inertia_torque_is_alpha_dot_i_alone() {
    let markdown = explain("validation/ten-link-chain", "newton-euler", "markdown");
    // In a plane ω × I·ω is normal to ω, so only I·α has a part along n̂z: for the rod
    // about its centre, I = m L²/12 and α = (q̈1 + … + q̈7) n̂z, summed as one product.
    let heading = "**21. $\\mathrm{link}_{7}\\colon \\sum \\mathbf{M}_{\\mathrm{link}_{7}^{*}} \\cdot \\hat{\\mathbf{n}}_{z}$**";
    assert_eq!(
        row_as_formed(&markdown, heading),
        "\\left[-\\frac{L F^{P_{8}}_{x}}{2} - \\frac{L F^{P_{7}}_{x} c_{7}}{2} - \\frac{L F^{P_{7}}_{y} s_{7}}{2}\\right] - \\frac{L^{2} m}{12} (\\ddot{q}_{1} + \\cdots + \\ddot{q}_{7}) = 0"
    );
}

#[test]
fn a_spatial_inertia_torque_keeps_the_gyroscopic_term() {
    let markdown = explain("validation/all-joints-3d", "newton-euler", "markdown");
    let torque = "- ( \\mathbf{I}^{D} \\cdot \\boldsymbol{\\alpha}^{D} + \\boldsymbol{\\omega}^{D} \\times \\mathbf{I}^{D} \\cdot \\boldsymbol{\\omega}^{D} ) \\cdot \\hat{\\mathbf{d}}_{x} = 0";
    assert!(markdown.contains(torque), "no row ends in {torque}");
}

#[test]
fn a_group_of_many_names_its_inertia_forces_by_a_sum_over_its_bodies() {
    let markdown = explain("validation/ten-link-chain", "motion-law", "markdown");
    // The Motion Law's free body link4 + … + link10 about P4, seven bodies: the moments of
    // their inertia forces as a sum over the named set, each r × m a* from step 4.
    let named = "- \\sum_{k \\in \\{\\mathrm{link}_{4}, \\ldots, \\mathrm{link}_{10}\\}} ";
    let moment = "( \\mathbf{r}^{P_{4} k^*} \\times m_{k}\\, {}^{N}\\mathbf{a}^{k^*} ) \\cdot \\hat{\\mathbf{n}}_{z}";
    assert!(
        markdown
            .lines()
            .any(|l| l.contains(&format!("{named}{moment}"))),
        "no row names the moments of its bodies' inertia forces"
    );
}

#[test]
fn a_group_of_four_writes_its_inertia_forces_body_by_body() {
    let markdown = explain("validation/ten-link-chain", "motion-law", "markdown");
    // link7 + … + link10 about P7, four bodies of mass m: each term written out, as a
    // textbook writes a few, with no sum over a set.
    let terms: Vec<String> = (7..=10)
        .map(|k| {
            format!(
                "\\mathbf{{r}}^{{P_{{7}} \\mathrm{{link}}_{{{k}}}^*}} \\times m\\, {{}}^{{N}}\\mathbf{{a}}^{{\\mathrm{{link}}_{{{k}}}^*}}"
            )
        })
        .collect();
    let written = format!(
        "- ( {} ) \\cdot \\hat{{\\mathbf{{n}}}}_{{z}}",
        terms.join(" + ")
    );
    assert!(markdown.contains(&written), "no row writes {written}");
    assert!(!markdown.contains("\\sum_{k \\in \\{\\mathrm{link}_{7}"));
}

#[test]
fn a_free_body_table_gives_a_planar_inertia_torque_as_i_dot_alpha() {
    // A planar body's inertia is a moment about the normal, along which ω lies, so
    // ω × I·ω is zero; in space it stays.
    let planar = explain("validation/ten-link-chain", "newton-euler", "markdown");
    assert!(planar.contains("| inertia torque of link4 (couple), opposite to its arrow in the kinetic diagram | $-\\mathbf{I}^{\\mathrm{link}_{4}} \\cdot \\boldsymbol{\\alpha}^{\\mathrm{link}_{4}}$ | $\\text{anywhere on } \\mathrm{link}_{4}$ |"));
    let spatial = explain("validation/all-joints-3d", "newton-euler", "markdown");
    assert!(spatial.contains("| inertia torque of D (couple), opposite to its arrow in the kinetic diagram | $-\\mathbf{I}^{D} \\cdot \\boldsymbol{\\alpha}^{D} - \\boldsymbol{\\omega}^{D} \\times \\mathbf{I}^{D} \\cdot \\boldsymbol{\\omega}^{D}$ | $\\text{anywhere on } D$ |"));
}

/// The simplified row under the Markdown heading that starts with `heading`.
fn row_simplified(markdown: &str, heading: &str) -> String {
    let start = markdown
        .find(heading)
        .unwrap_or_else(|| panic!("no heading {heading}"));
    let rest = &markdown[start..];
    let after = rest.find("Simplified:").expect("a simplified row");
    row_as_formed(&rest[after..], "Simplified:")
}

#[test]
fn second_derivatives_sharing_a_coefficient_are_written_once_with_their_sum() {
    let markdown = explain("validation/ten-link-chain", "newton-euler", "markdown");
    // By hand: about its own mass centre, link 10 (a rod, I = m L²/12) turns at
    // q̈1 + … + q̈10; only the pin force at P10, half a length away, has a moment.
    let heading = "**30. $\\mathrm{link}_{10}\\colon \\sum \\mathbf{M}";
    assert_eq!(
        row_simplified(&markdown, heading),
        "-\\frac{L^{2} m}{12} (\\ddot{q}_{1} + \\cdots + \\ddot{q}_{10}) - \\frac{L c_{10}}{2} F^{P_{10}}_{x} - \\frac{L s_{10}}{2} F^{P_{10}}_{y} = 0"
    );
}

#[test]
fn the_plan_writes_a_run_of_second_derivatives_by_its_ends() {
    let markdown = explain("validation/ten-link-chain", "newton-euler", "markdown");
    // Link 7's force along its x̂ holds the q̈ of links 1 to 7 and the pins at P7 and P8.
    let row = "| $\\mathrm{link}_{7}$ | $\\sum \\mathbf{F}$ | $\\hat{\\mathbf{x}}_{\\mathrm{link}_{7}}$ | $\\ddot{q}_{1}, \\dots, \\ddot{q}_{7}, F^{P_{7}}_{x}, F^{P_{7}}_{y}, F^{P_{8}}_{x}$ |";
    assert!(markdown.lines().any(|l| l == row), "no plan row {row}");
}

#[test]
fn a_contact_group_is_written_with_sin_squared_plus_cos_squared_as_one() {
    let markdown = explain("validation/all-joints-3d", "newton-euler", "markdown");
    // By hand: the universal joint U's couple M^U_1 acts about its first axis, which has
    // the component cos q_{D2} along d̂z once sin² q_{D1} + cos² q_{D1} = 1 is applied; no
    // other contact force has a moment about D* along d̂z.
    let heading = "**24. $D\\colon \\sum \\mathbf{M}_{D^{*}} \\cdot \\hat{\\mathbf{d}}_{z}$**";
    assert_eq!(
        row_as_formed(&markdown, heading),
        "M^{U}_{1} \\cos(q_{D2}) - ( \\mathbf{I}^{D} \\cdot \\boldsymbol{\\alpha}^{D} + \\boldsymbol{\\omega}^{D} \\times \\mathbf{I}^{D} \\cdot \\boldsymbol{\\omega}^{D} ) \\cdot \\hat{\\mathbf{d}}_{z} = 0"
    );
}

#[test]
fn the_constraint_rows_say_once_that_they_are_differentiated() {
    // The four-bar's loop closes at R along b̂x and b̂y: two rows, differentiated twice in time
    // so that they hold the q''. The first says so for both; the second is headed by what it
    // constrains alone.
    let markdown = explain("four-bar", "newton-euler", "markdown");
    let first = "**10. $\\text{loop closure at R}\\text{, along } \\hat{\\mathbf{b}}_{x}$ (differentiated to the acceleration level, as is row 11)**";
    let second = "**11. $\\text{loop closure at R}\\text{, along } \\hat{\\mathbf{b}}_{y}$**";
    assert!(markdown.contains(first), "no {first}");
    assert!(markdown.contains(second), "no {second}");
}
