//! The notation of a course in the handout: ℓ where the statement writes ℓ, the inertia
//! torque as −I·α − ω × I·ω with the kinetic diagram's I^A α^A named as the tables name
//! it, a couple acting anywhere on its body, and answers that say at which state they are
//! (the slow precession of answer 3, the start of an energy check).

use crate::support::handouts::{bundled as handout, has, lacks};

/// The ladder's statement writes ℓ: so do its tables and equations, in every exporter.
#[test]
fn the_ladder_prints_its_half_length_as_the_statement_does() {
    let name = "ladder-about-to-slip";
    let markdown = handout(name, "motion-law", "markdown");
    has(&markdown, "| $\\ell$ | 1.5 | $\\mathrm{m}$ |", name);
    has(&markdown, "y - \\ell c_{\\theta} = 0", name);
    lacks(&markdown, "| $l$ |", name);
    let latex = handout(name, "motion-law", "latex");
    has(&latex, "$\\ell$ & $1.5$", name);
    let html = handout(name, "motion-law", "html");
    has(&html, "<mi>ℓ</mi>", name);
    let statics = handout("statics-ladder", "motion-law", "markdown");
    has(&statics, "| $\\ell$ |", "statics-ladder");
}

/// −I·α (and −ω × I·ω in space), never −α·I; the kinetic diagram's couple I^A α^A.
#[test]
fn the_inertia_torque_is_written_as_textbooks_write_it() {
    let name = "gear-pair-torque";
    let text = handout(name, "newton-euler", "markdown");
    has(
        &text,
        "$-\\mathbf{I}^{A} \\cdot \\boldsymbol{\\alpha}^{A}$ | $\\text{anywhere on } A$ |",
        name,
    );
    lacks(&text, "\\boldsymbol{\\alpha}^{A} \\cdot \\mathbf{I}", name);
    has(&text, "data-label=\"I^A α^A\"", name);
    let latex = handout("four-bar", "motion-law", "latex");
    has(&latex, "{$I^{A} \\alpha^{A}$}", "four-bar");
    lacks(&latex, "I^{A^{*}} \\alpha", "four-bar");
    let coin = handout("rolling-coin", "kane", "markdown");
    has(
        &coin,
        "-\\mathbf{I}^{D} \\cdot \\boldsymbol{\\alpha}^{D} - \\boldsymbol{\\omega}^{D} \\times \\mathbf{I}^{D} \\cdot \\boldsymbol{\\omega}^{D}",
        "rolling-coin",
    );
    lacks(&coin, "\\boldsymbol{\\alpha}^{D} \\cdot", "rolling-coin");
}

/// A couple's place is its body, its kind in the force's column: never "couple" as a place.
#[test]
fn a_couple_acts_anywhere_on_its_body() {
    for (name, method) in [
        ("gear-pair-torque", "newton-euler"),
        ("disc-in-cylinder", "lagrange"),
        ("rack-and-pinion", "motion-law"),
    ] {
        let text = handout(name, method, "markdown");
        lacks(&text, "$\\text{couple}$", name);
        has(&text, " (couple)", name);
    }
    let gears = handout("gear-pair-torque", "newton-euler", "markdown");
    has(
        &gears,
        "| drive (couple) | $T \\hat{\\mathbf{n}}_{z}$ | $\\text{anywhere on } A$ |",
        "gear-pair-torque",
    );
    has(
        &gears,
        "Newton–Euler takes every body as a free body, with its force rows and its moment rows",
        "gear-pair-torque",
    );
}

/// The top's period is about the slow precession of answer 3, which holds two states; the
/// simulated nutation is not preceded by its question and gives its amplitude once.
#[test]
fn the_top_names_the_precession_its_nutations_are_about() {
    let name = "heavy-symmetric-top";
    let text = handout(name, "motion-law", "markdown");
    has(
        &text,
        "At the state of answer 3, during the slow precession.",
        name,
    );
    has(&text, "(the slow precession, a steady motion).", name);
    lacks(&text, "kept constant", name);
    lacks(&text, "(amplitude", name);
    let answers = &text[text.find("## Answers").expect("the answers")..];
    lacks(answers, "Simulate the top", name);
    has(&text, "4. At $0 \\le t \\le 2\\ \\mathrm{s}$", name);
    // The linearization is about the slow precession (Ω = 3.45 rad/s): 51.1 rad/s, not
    // the 59.0 rad/s about the fast one.
    has(&text, "\\omega = 51.1089\\ \\mathrm{rad/s}", name);
}

/// An energy checked at the start and after 4 s says the start too, though answer 2 was
/// at it; one body's kinetic energy is T, not T_D and T = T_D.
#[test]
fn an_item_at_two_states_says_both() {
    let name = "double-pendulum-rods";
    let text = handout(name, "motion-law", "markdown");
    has(
        &text,
        "3. At $t = 0\\ \\mathrm{s}$ (the initial state): $E = -7.53656\\ \\mathrm{J}$.",
        name,
    );
    has(
        &text,
        "At $t = 4\\ \\mathrm{s}$ (simulated from the initial state): $E = -7.53656",
        name,
    );
    let disc = handout("disc-in-cylinder", "lagrange", "markdown");
    lacks(&disc, "T = T_{D}", "disc-in-cylinder");
    has(
        &disc,
        "$$\nT = \\frac{1}{2} m \\, {}^{N}\\mathbf{v}^{D^*}",
        "disc-in-cylinder",
    );
    let latex = handout("disc-in-cylinder", "lagrange", "latex");
    has(
        &latex,
        "(the state the small oscillations are about). One degree",
        "disc-in-cylinder",
    );
    lacks(&latex, "about): One degree", "disc-in-cylinder");
}

/// The cart's frame C writes a velocity relative to C with ĉ; the disc centre's sum of
/// accelerations keeps the question that calls it absolute.
#[test]
fn the_disc_on_the_cart_says_its_frames() {
    let name = "disc-on-cart";
    let text = handout(name, "kane", "markdown");
    has(
        &text,
        "${}^{C}\\tilde{\\mathbf{v}}^{U}_{3} = \\hat{\\mathbf{c}}_{x}$",
        name,
    );
    has(
        &text,
        "The absolute acceleration of the disc's centre (in N), $\\ddot{x} + \\ddot{s}$:",
        name,
    );
    has(
        &text,
        "$\\ddot{s} + \\ddot{x} = 1.09091\\ \\mathrm{m/s^{2}}$",
        name,
    );
}

/// The coin's ẏ is solved from the constraints like ẋ and ż; its frames come before its
/// constants, as in every handout.
#[test]
fn the_coin_marks_every_solved_rate_and_lists_frames_first() {
    let name = "rolling-coin";
    let text = handout(name, "kane", "markdown");
    has(
        &text,
        "| $y$ | $y$ of the centre | as for $x$ | $\\mathrm{m}$ | 0 m | 0 m/s† |",
        name,
    );
    for name in ["rolling-coin", "disc-on-cart", "double-pendulum-rods"] {
        let latex = handout(name, "kane", "latex");
        let frames = latex.find("Frame & Unit vectors").expect("the frames");
        let constants = latex.find("Constant & Value").expect("the constants");
        let coordinates = latex.find("Coordinate & Meaning").expect("the coordinates");
        // The picture's macro sets its arguments in its own order: read the macro's.
        let beside = latex.contains(
            "\\noindent\\ignorespaces#2\\par\\medskip\n      \\noindent\\begin{minipage}",
        );
        assert!(
            beside,
            "{name}: the frames over the constants beside a wide picture"
        );
        assert!(
            frames < constants && constants < coordinates,
            "{name}: frames, constants, coordinates"
        );
    }
}

/// The pin force on rod B of the double pendulum says who exerts it and along whose unit
/// vectors it is resolved; the weights' moments are written out as cross products beside
/// the inertia forces', each worked to its value (−L1 m1 g s1/2 for rod A about O).
#[test]
fn the_pin_force_and_the_weights_moments_are_said_in_full() {
    let name = "double-pendulum-rods";
    let text = crate::support::handouts::bundled(name, "motion-law", "markdown");
    assert!(
        text.contains("| reaction force at $P$, of A on B, in A's unit vectors |"),
        "the pin force on B"
    );
    assert!(
        text.contains(
            "(\\mathbf{r}^{O A^*} \\times (-m_{1} g \\hat{\\mathbf{n}}_{y})) \\cdot \\hat{\\mathbf{n}}_{z} &= -\\frac{L_{1} m_{1} g}{2} s_{1}"
        ),
        "rod A's weight about O"
    );
    assert!(
        text.contains("(\\mathbf{r}^{P B^*} \\times (-m_{2} g \\hat{\\mathbf{n}}_{y}))"),
        "rod B's weight about P"
    );
}
