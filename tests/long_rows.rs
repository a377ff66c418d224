//! A large system's step 5 says each thing once: a generalized force too long to print is
//! named, not redefined; a row in vector form that repeats an earlier one along another
//! axis refers to it; A by value leaves out the rows a block of columns does not touch; a
//! displayed simplified row opens with its note; and Kane's auxiliary rows at one joint say
//! once what their speed does.

/// The all-joints mechanism's handout by `method`, in `format`.
fn all_joints(method: &str, format: &str) -> String {
    crate::support::explain(
        "validation/all-joints-3d",
        &["--method", method, "--format", format],
    )
}

/// Step 5's row headings of a Markdown handout: (number, free body) for each.
fn row_free_bodies(markdown: &str) -> Vec<(usize, String)> {
    markdown
        .lines()
        .filter_map(|l| {
            let rest = l.strip_prefix("**")?;
            let (number, rest) = rest.split_once(". $")?;
            let (free_body, _) = rest.split_once("\\colon")?;
            Some((number.parse().ok()?, free_body.to_string()))
        })
        .collect()
}

#[test]
fn a_block_of_a_by_value_leaves_out_the_rows_of_a_body_its_unknowns_do_not_move() {
    // The plate F hangs from the turntable's rim on a spring: a spring's force depends on
    // where the bodies are, not on how they accelerate, so none of F's own rows holds a
    // q̈ of the chain A…E. The first block of A's columns (the chain's q̈) leaves those rows
    // out, and lists each of the chain's rows.
    let markdown = all_joints("motion-law", "markdown");
    let rows = row_free_bodies(&markdown);
    let plate: Vec<usize> = rows
        .iter()
        .filter(|(_, body)| body == "F")
        .map(|(i, _)| *i)
        .collect();
    assert_eq!(plate.len(), 6, "{rows:?}");
    let first = markdown
        .lines()
        .find(|l| l.starts_with("\\begin{array}"))
        .expect("a table by value");
    assert!(first.contains("\\ddot{q}_{A}"), "{first}");
    for i in plate {
        assert!(!first.contains(&format!("({i}) &")), "row {i} in {first}");
    }
    for (i, body) in &rows {
        if body.contains("A + B") || body.contains("E") {
            assert!(first.contains(&format!("({i}) &")), "row {i} missing");
        }
    }
}

#[test]
fn a_moment_row_along_another_axis_refers_to_the_first_of_its_vector_form() {
    // Rows 22 and 23 take moments of the whole chain about O along n_x and n_y, as row 10
    // does along e_O; each is too long to print, so the vector form is printed once.
    let markdown = all_joints("motion-law", "markdown");
    for row in [22, 23] {
        let heading = format!("**{row}. $A + B + C + D + E + G\\colon \\sum \\mathbf{{M}}_{{O}}");
        let at = markdown.find(&heading).expect("the row");
        let body = &markdown[at..at + 400];
        assert!(
            body.contains("Formed as row 10, along this row's direction."),
            "{body}"
        );
    }
    let vector_forms = markdown
        .matches("\\sum \\mathbf{M}_{O} - \\sum_{k \\in \\{A, B, C, D, E, G\\}}")
        .count();
    assert_eq!(vector_forms, 1);
}

#[test]
fn a_generalized_force_too_long_to_print_is_named_not_redefined() {
    // Kane's F*_r is defined once, above the rows; a row whose F*_r is too long to print
    // names it rather than writing the sum out again.
    let latex = all_joints("kane", "latex");
    // The letter of a body is one the problem does not use (here J), and so is the
    // force's (f: the problem prints R).
    let definition = "\\sum_{J} \\left(\\mathbf{v}^{J^*}_r \\cdot \\mathbf{f}^{*}_{J}";
    assert_eq!(latex.matches(definition).count(), 1);
    assert!(latex.contains("F^{*}_{1}\\ \\text{(a long expression, not written out)}"));
    assert!(!latex.contains("\\mathbf{v}^{B^*}_{1} \\cdot"));
}

#[test]
fn a_displayed_simplified_row_opens_with_its_note() {
    // Row 24 of the all-joints mechanism by Newton–Euler, D's moments about D* along d_z,
    // is too long for a line once simplified: its display starts with the note, which
    // then does not stand on a line of its own above it.
    let latex = all_joints("newton-euler", "latex");
    let at = latex
        .find("\\steprow{24. $D\\colon \\sum \\mathbf{M}_{D^{*}} \\cdot \\hat{\\mathbf{d}}_{z}$}")
        .expect("row 24");
    let end = latex[at + 1..].find("\\steprow{25.").expect("row 25") + at + 1;
    let row = &latex[at..end];
    assert!(
        row.contains("\\begin{multline*}\n\\text{Simplified:}\\quad -\\frac{L^{2} m"),
        "{row}"
    );
    // Said once in the display (the inline form, used when the row fits a line, has its own).
    assert_eq!(row.matches("\\text{Simplified:}").count(), 1, "{row}");
}

#[test]
fn an_auxiliary_row_after_the_first_at_a_joint_refers_to_it() {
    // Kane's rows 16 to 20 bring in the five reactions at O through auxiliary speeds that
    // each move the whole chain A…G against the joint: said at row 16, referred to after.
    let markdown = all_joints("kane", "markdown");
    let full = "(an auxiliary speed: it moves A + B + C + D + E + G against the joint)";
    assert_eq!(markdown.matches(full).count(), 1);
    assert!(markdown.contains(&format!(
        "$r = 16\\colon\\; u_{{16}}\\text{{, for }} F^{{O}}_{{x}}$ {full}"
    )));
    for row in 17..=20 {
        let heading = format!("**{row}. $r = {row}\\colon\\; u_{{{row}}}\\text{{, for }} ");
        let at = markdown.find(&heading).expect("the row");
        let line = markdown[at..].lines().next().unwrap_or_default();
        assert!(
            line.ends_with("(an auxiliary speed, as in row 16)**"),
            "{line}"
        );
    }
    // The joint W's rows refer to the first of theirs.
    assert!(markdown.contains("(an auxiliary speed: it moves G against the joint"));
    assert!(markdown.contains("(an auxiliary speed, as in row 21)"));
}
