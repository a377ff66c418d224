//! The linear system and the answers said truly: the column of unknowns named by one letter
//! that no coordinate uses, Lagrange's matrix of at most six unknowns printed, the distance
//! kept by a contact said as a replacement, and an answer in a moving frame's unit vectors
//! told how they lie at that instant.

use crate::support::markdown_handout;

#[test]
fn the_unknowns_by_column_take_the_column_s_letter_not_a_coordinate_s() {
    // The wheel's coordinate is x: the column is z, in the sentence and in the list.
    let text = markdown_handout("wheel-pendulum", "lagrange");
    assert!(
        text.contains("$\\mathbf{A}\\,\\mathbf{z} = \\mathbf{b}$"),
        "A z = b"
    );
    let line = (text.lines())
        .find(|l| l.starts_with("The unknowns by column:"))
        .expect("the unknowns by column");
    assert!(line.contains("$z_{1} = \\ddot{x}$"), "{line}");
    assert!(!line.contains("$x_{"), "{line}");
}

#[test]
fn lagrange_s_matrix_of_five_unknowns_is_printed() {
    let text = markdown_handout("disc-in-cylinder", "lagrange");
    let matrix = crate::support::between(&text, "in matrix form", "## Step 6");
    assert!(!matrix.contains("\\bullet"), "a pattern of dots: {matrix}");
    assert!(matrix.contains("\\begin{array}"), "{matrix}");
    // Row 3, θ's equation, holds r F_t^P: its entry in the column of F_t^P is r's multiple.
    assert!(matrix.contains("F^{P}_{t}"), "{matrix}");
}

#[test]
fn the_distance_the_contact_keeps_is_said_as_a_replacement() {
    let text = markdown_handout("disc-in-cylinder", "lagrange");
    assert!(!text.contains("not as a root of squares"));
    assert!(
        text.contains("From here on $\\sqrt{x^{2} + y^{2}}$ is replaced by $R - r$"),
        "{}",
        crate::support::between(&text, "Wherever the distance", "\n")
    );
}

#[test]
fn a_force_in_the_wheel_s_unit_vectors_says_how_they_lie() {
    let text = markdown_handout("wheel-pendulum", "lagrange");
    let answers = crate::support::between(&text, "## Answers", "\u{0}");
    let says = "At this instant $\\hat{\\mathbf{w}}_{x} = \\hat{\\mathbf{n}}_{x}$ and \
                $\\hat{\\mathbf{w}}_{y} = \\hat{\\mathbf{n}}_{y}$.";
    assert!(answers.contains(says), "{answers}");
    // The ground's force is in n̂: nothing to say for it.
    assert_eq!(answers.matches("At this instant").count(), 1, "{answers}");
}
