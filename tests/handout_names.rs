//! Names as a course writes them: the statement's point O and a letter for a body named by
//! a word (the heavy top), the sines and cosines of a problem that names a length c written
//! so that they cannot be read as it (the four-bar), and the dependent rates in symbols
//! (the disc rolling in a cylinder).

use crate::support::run;

/// The Markdown handout of a bundled problem by `method`.
fn handout(name: &str, method: &str) -> String {
    let path = format!("{}/problems/{name}.json", env!("CARGO_MANIFEST_DIR"));
    let out = run(&["explain", &path, "--method", method, "--format", "markdown"]);
    assert!(
        out.status.success(),
        "{name}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn the_heavy_top_is_written_with_the_statements_point_o_and_a_letter() {
    let text = handout("heavy-symmetric-top", "motion-law");
    // The statement's fixed point O, the top's frame B: never the words as scripts.
    assert!(text.contains("F^{O}_{x}"), "no F^O_x");
    assert!(text.contains("\\hat{\\mathbf{x}}_{B}"), "no x̂_B");
    assert!(text.contains("B^*") || text.contains("B^{*}"), "no B*");
    assert!(
        text.contains("| the top (B) |"),
        "step 1 does not say that B is the top"
    );
    assert!(
        text.contains("turns freely about point O of the ground"),
        "the joint is not named O"
    );
    for word in ["\\mathrm{tip}", "\\mathrm{top}"] {
        assert!(!text.contains(word), "{word} is still printed");
    }
}

#[test]
fn a_contact_named_by_a_word_is_a_point_with_a_note() {
    let text = handout("bowling-ball", "motion-law");
    assert!(text.contains("P is the point of contact at the lane."));
    assert!(
        text.contains("| contact force at $P$ |"),
        "the force table's label"
    );
    assert!(text.contains("| weight of B |"));
}

#[test]
fn the_four_bars_cosines_are_not_read_as_its_rocker_length() {
    // The rocker's length is c and a body is C: the sines and cosines are written out.
    let text = handout("four-bar", "motion-law");
    assert!(
        !text.contains("c_{1} = "),
        "c₁ abbreviates a cosine beside the length c"
    );
    assert!(text.contains("c \\cos(q_{1} + q_{2} - q_{3})"));
}

#[test]
fn the_disc_in_the_cylinder_relates_its_rates_in_symbols() {
    // The centre stays on x² + y² = (R − r)², so x ẋ + y ẏ = 0: ẏ = −x ẋ / y, written in
    // symbols rather than as a number times ẋ at the start.
    let text = handout("disc-in-cylinder", "motion-law");
    assert!(
        text.contains("\\dot{y} = -\\frac{x \\dot{x}}{y}"),
        "the relation of the rates is not in symbols"
    );
    assert!(!text.contains("0.125988 \\dot{x}"));
}
