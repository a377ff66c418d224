//! A force asked for is drawn on the body it acts on, in every method: the disc on the cart
//! (problems/disc-on-cart.json) gets free body D with the contact force at U, and its
//! answer points to it; Kane's auxiliary speeds of the contact force move the disc alone.
//! The rolling coin's Kane handout writes its vectors in the lean frame, and its table of
//! partial velocities lists each line once.

use crate::support::{between, markdown_handout as handout};

#[test]
fn the_disc_on_the_cart_is_drawn_alone_with_the_force_asked_for_in_every_method() {
    for method in ["kane", "motion-law", "newton-euler", "lagrange"] {
        let text = handout("disc-on-cart", method);
        let step2 = between(&text, "## Step 2", "## Step 3");
        let disc = between(step2, "### Free body $D$", "\n### ");
        // The contact force's two unknown components act on D at U.
        assert!(
            disc.contains("F^{U}_{x} \\hat{\\mathbf{c}}_{x} + F^{U}_{y} \\hat{\\mathbf{c}}_{y}"),
            "{method}: {disc}"
        );
        assert!(disc.contains("$\\text{at } U$"), "{method}: {disc}");
        let answers = between(&text, "## Answers", "\n\n\n");
        assert!(
            !answers.contains("No free body drawn"),
            "{method}: {answers}"
        );
        assert!(
            answers.contains("Free body D of step 2 shows this force on D, at U."),
            "{method}: {answers}"
        );
    }
}

/// By hand: u₃ lets ṡ + R θ̇ = 0 give way alone (θ̇ = u₃/R, every other rate zero), u₄ lets
/// ḣ = 0 give way (ḣ = u₄): either moves the disc and not the cart, so the rows of the
/// contact force are the disc's free body's.
#[test]
fn kanes_auxiliary_speeds_of_the_contact_move_the_disc_alone() {
    let text = handout("disc-on-cart", "kane");
    let plan = between(&text, "## Step 3", "## Step 4");
    let rows: Vec<&str> = plan
        .lines()
        .filter(|l| l.contains("\\tilde{F}_{"))
        .collect();
    assert_eq!(rows.len(), 4, "{plan}");
    for (row, bodies) in rows.iter().zip(["$C + D$", "$C + D$", "$D$", "$D$"]) {
        assert!(row.starts_with(&format!("| {bodies} |")), "{row}");
    }
    let step5 = between(&text, "## Step 5", "## Step 6");
    assert!(
        step5.contains("Only $D$ moves with $u_{3}$: free body $D$ of step 2"),
        "{step5}"
    );
    // Each velocity in the unit vectors of its own frame: those in N in n̂, the contact
    // point's relative to the cart in ĉ.
    let table = between(step5, "| Speed |", "\n\n");
    for line in table.lines() {
        for cell in line
            .split(" | ")
            .filter(|c| c.contains("\\tilde{\\mathbf{v}}"))
        {
            let in_c = cell.contains("{}^{C}");
            assert_eq!(cell.contains("\\hat{\\mathbf{c}}"), in_c, "{cell}");
            assert_eq!(
                cell.contains("\\hat{\\mathbf{n}}"),
                !in_c && !cell.contains("\\mathbf{0}"),
                "{cell}"
            );
        }
    }
    assert!(
        table.contains("{}^{C}\\tilde{\\mathbf{v}}^{U}_{3} = \\hat{\\mathbf{c}}_{x}"),
        "{table}"
    );
    assert!(table.contains("\\tilde{\\mathbf{v}}^{C^*}_{1} = \\hat{\\mathbf{n}}_{x}"));
}

/// The coin's contact point is straight below its centre in the lean frame A (after ψ and θ,
/// not φ): r^{D*P} = −R â_z, and about A the disc's rates are θ̇ â_x, (φ̇ + ψ̇ sθ) â_y and
/// ψ̇ cθ â_z, so the spin angle φ appears in no vector of the handout.
#[test]
fn the_rolling_coins_vectors_are_written_in_its_lean_frame() {
    let text = handout("rolling-coin", "kane");
    assert!(text.contains("\\mathbf{r}^{D^* P} &= -R \\hat{\\mathbf{a}}_{z}"));
    for spin in ["s_{\\phi}", "c_{\\phi}", "\\sin(\\phi)", "\\cos(\\phi)"] {
        assert!(!text.contains(spin), "{spin} in the coin's handout");
    }
    let step5 = between(&text, "## Step 5", "## Step 6");
    // ω̃₂ = â_x: leaning turns the disc about â_x; ṽ₂ = −R â_y, the centre about P.
    assert!(step5.contains("\\tilde{\\boldsymbol{\\omega}}^{D}_{2} = \\hat{\\mathbf{a}}_{x}"));
    assert!(step5.contains("\\tilde{\\mathbf{v}}^{D^*}_{2} = -R \\hat{\\mathbf{a}}_{y}"));
}

/// The coin's auxiliary speeds move it without turning (ω̃ = 0), its centre and its contact
/// point alike: each speed has one line, none printed twice.
#[test]
fn no_line_of_the_coins_partial_velocities_is_printed_twice() {
    let text = handout("rolling-coin", "kane");
    let table = between(&text, "| Speed |", "\n\n");
    let lines: Vec<&str> = table.lines().skip(2).collect();
    assert_eq!(lines.len(), 6, "{table}");
    for r in 4..=6 {
        let said = |what: &str| table.matches(&format!("}}_{{{r}}} = {what}")).count();
        assert_eq!(said(""), 2, "speed {r}: {table}");
    }
    assert!(!table.contains("\\tilde{\\mathbf{v}}^{P}"), "{table}");
}
