//! The handout read as an instructor reads it: each answer a sentence of its own, an
//! integration's error not printed as digits, the words of a course (meshing teeth, a
//! slip velocity, a rate from a position constraint), the elimination to one equation
//! written where step 5 holds rows a reaction alone fills, the energy as T + V with its
//! numbers, and the listed solution with its units.

use crate::support::handouts::{bundled as handout, has, lacks};

/// An answer's value ends its sentence, and the LaTeX starts the next one on a new line
/// instead of running on after a quad.
#[test]
fn an_answer_is_a_sentence_followed_by_its_reason() {
    let name = "gear-pair-torque";
    let latex = handout(name, "newton-euler", "latex");
    has(
        &latex,
        "$\\ddot{q}_{A} = 225\\ \\mathrm{rad/s^{2}}$.\\par",
        name,
    );
    lacks(&latex, "\\mathrm{rad/s^{2}}$\\quad", name);
    let markdown = handout("double-pendulum-rods", "motion-law", "markdown");
    has(
        &markdown,
        "3. At $t = 0\\ \\mathrm{s}$ (the initial state): $E = -7.53656\\ \\mathrm{J}$.\n",
        name,
    );
    let html = handout(name, "newton-euler", "html");
    lacks(&html, "</math></p>\n<p>One degree", name);
}

/// The gear pair: meshing teeth, not a body rolling on a surface; the reactions the pins
/// alone carry are left out of the elimination, which Newton–Euler's seven rows now show
/// (row 7 gives q̈_B = −r_A q̈_A / r_B, row 6 the tooth force F = −I_B q̈_B / r_B, and row
/// 3 what is left: (I_A + I_B r_A²/r_B²) q̈_A = T); a row with its terms only reordered is
/// written once.
#[test]
fn the_gear_pair_meshes_and_eliminates_in_its_seven_rows() {
    let name = "gear-pair-torque";
    let text = handout(name, "newton-euler", "markdown");
    lacks(&text, "Rolling without slipping", name);
    has(&text, "The teeth do not slip at the mesh", name);
    lacks(&text, "is not needed", name);
    has(&text, "Row (7) gives $\\ddot{q}_{B}$", name);
    has(
        &text,
        "$$F^{P}_{t} = -\\frac{I_{B} \\ddot{q}_{B}}{r_{B}}$$",
        name,
    );
    has(&text, "Put into row (3)", name);
    lacks(
        &text,
        "with the reactions and the other accelerations eliminated",
        name,
    );
    // Row 6 as formed, −r_B F − I_B q̈_B = 0, is the simplified row reordered.
    lacks(
        &text,
        "$$\n-r_{B} F^{P}_{t} - I_{B} \\ddot{q}_{B} = 0\n$$",
        name,
    );
    // A disc rolling in a fixed cylinder has no teeth.
    let disc = handout("disc-in-cylinder", "lagrange", "markdown");
    has(&disc, "Rolling without slipping", "disc-in-cylinder");
    lacks(&disc, "teeth", "disc-in-cylinder");
}

/// The bowling ball's slip velocity is derived in step 1, before the answers use it:
/// v^P = v^{B*} + ω × r^{B*P} with r^{B*P} = −R n̂_y gives (ẋ + R θ̇) n̂_x.
#[test]
fn the_bowling_ball_derives_its_slip_velocity_before_the_answers() {
    let name = "bowling-ball";
    let text = handout(name, "motion-law", "markdown");
    let step1 = &text[..text.find("## Step 2").expect("step 2")];
    has(step1, "The slip velocity at the lane", name);
    has(
        step1,
        "(\\dot{x} + R \\dot{\\theta}) \\hat{\\mathbf{n}}_{x}",
        name,
    );
    lacks(step1, "= \\mathbf{0}", name);
    lacks(
        &text,
        "Solved one after another in the order step 3 gives",
        name,
    );
}

/// The rolling coin's energy: E = T + V written, T and V each with its number, and the
/// two adding to the E printed (0.727222 J); V = m g z, by the coordinate that is the
/// centre's height.
#[test]
fn the_energy_is_written_as_t_plus_v_with_its_numbers() {
    let name = "rolling-coin";
    let text = handout(name, "kane", "markdown");
    has(&text, "$E = T + V$", name);
    has(&text, "\\cdot \\mathbf{I}^{D} \\cdot", name);
    let number_before = |mark: &str| -> f64 {
        let end = text.find(mark).expect(mark);
        let start = text[..end].rfind(" = ").expect("a value") + 3;
        text[start..end].parse().expect("a number")
    };
    let kinetic = number_before("\\ \\mathrm{J}$ and $V = ");
    // The coordinate z is the height of the centre: V is written with it, not with a
    // second name for the same height.
    has(&text, "$V = m g z = ", name);
    assert!(!text.contains("h_{D^*}"), "{name}: the height named twice");
    let potential = number_before("\\ \\mathrm{J}$. $V$ is zero");
    assert!(
        (kinetic + potential - 0.727222).abs() < 2e-6,
        "{kinetic} + {potential}"
    );
}

/// Listed, each value of the solution carries its unit; "in SI units" is left for a
/// matrix of numbers.
#[test]
fn the_listed_solution_carries_its_units() {
    let name = "disc-in-cylinder";
    let text = handout(name, "lagrange", "markdown");
    has(&text, "$F^{P}_{t} = 0.40875\\ \\mathrm{N}$", name);
    has(&text, "$\\ddot{x} = -0.811088\\ \\mathrm{m/s^{2}}$", name);
    lacks(&text, "in SI units, the solution is", name);
}

/// The heavy top's linearized period says where it comes from, beside the simulated one,
/// and why the two differ: the simulation starts at ψ̇ = 3 rad/s with φ̇ = 150 rad/s, so at
/// the spin ω₃ = φ̇ + ψ̇ cos θ = 150 + 3 cos 0.5 = 152.633 rad/s (worked here from the
/// problem's initial state), not at the steady precession's ω₃ = 150 rad/s. The nutation
/// is said once, in words, with the answers' digits, not also as a list of values.
#[test]
fn a_linearized_period_says_it_is_about_the_state() {
    let name = "heavy-symmetric-top";
    let text = handout(name, "motion-law", "markdown");
    has(&text, "Linearized about this state", name);
    let spin = 150.0 + 3.0 * 0.5f64.cos();
    has(
        &text,
        "The motion simulated above starts at $\\Omega = 3\\ \\mathrm{rad/s}$",
        name,
    );
    has(&text, &format!("$\\omega_{{3}} = {spin:.3}"), name);
    has(&text, "not at this state's $\\Omega = 3.45313\\ \\mathrm{rad/s}$, $\\omega_{3} = 150\\ \\mathrm{rad/s}$", name);
    has(
        &text,
        "$\\tau = 0.120276\\ \\mathrm{s}$, differs from this one",
        name,
    );
    lacks(&text, "a motion that starts away from it need not", name);
    // The nutation in words only, to six figures.
    lacks(&text, "\\theta_{\\min} = ", name);
    has(
        &text,
        "$\\theta$ oscillates between $0.5\\ \\mathrm{rad}$ and $0.507095\\ \\mathrm{rad}$",
        name,
    );
    lacks(&text, "0.5071\\ ", name);
}

/// Step 6 in a course's words: numerical integration and its checks, with no tool's words;
/// the LaTeX legend says the inertia forces and torques are opposite to the kinetic
/// diagram's arrows, with the gyroscopic term only where a body turns in space.
#[test]
fn step_six_and_the_inertia_legend_in_a_courses_words() {
    for (name, method, spatial) in [
        ("double-pendulum-rods", "motion-law", false),
        ("heavy-symmetric-top", "motion-law", true),
    ] {
        let text = handout(name, method, "markdown");
        has(&text, "## Step 6. Numerical integration", name);
        has(&text, "\nChecks:\n", name);
        has(
            &text,
            "The equations of motion of step 5, integrated numerically from the initial state over",
            name,
        );
        for tool in [
            "Simulation and confirmation",
            "What confirms",
            "Integrating these equations",
        ] {
            lacks(&text, tool, name);
        }
        let latex = handout(name, method, "latex");
        let latex = latex.split_whitespace().collect::<Vec<_>>().join(" ");
        has(&latex, "\\section*{Step 6. Numerical integration}", name);
        has(&latex, "The inertia forces $-m\\,\\mathbf{a}^{*}$ and torques $-\\mathbf{I}\\cdot\\boldsymbol{\\alpha}", name);
        has(
            &latex,
            "are opposite to the kinetic diagram's arrows.",
            name,
        );
        lacks(&latex, "arrows reversed", name);
        let gyroscopic =
            "\\boldsymbol{\\omega}\\times\\mathbf{I}\\cdot\\boldsymbol{\\omega}$ are opposite";
        assert_eq!(
            latex.contains(gyroscopic),
            spatial,
            "{name}: the gyroscopic term"
        );
    }
}

/// Kane's auxiliary speeds said plainly (the disc on a cart): their partial velocities are
/// those of the motion in which only their own constraint is relaxed.
#[test]
fn the_auxiliary_partial_velocities_are_said_plainly() {
    let name = "disc-on-cart";
    let text = handout(name, "kane", "markdown");
    has(&text, "The lines after them are for the auxiliary speeds: each one's partial velocities are those of the motion in which its own constraint alone is relaxed", name);
    lacks(&text, "an auxiliary speed's, in the lines after them", name);
}

/// The Motion Law's free-body table and its picture say the same: the inertia force and
/// torque are the kinetic diagram's turned round.
#[test]
fn the_inertia_rows_are_said_against_the_kinetic_diagram() {
    let name = "double-pendulum-rods";
    let text = handout(name, "motion-law", "markdown");
    has(
        &text,
        "| inertia force of A, opposite to its arrow in the kinetic diagram |",
        name,
    );
    has(
        &text,
        "| inertia torque of B (couple), opposite to its arrow in the kinetic diagram |",
        name,
    );
}

/// Course words in step 1 and 5: the coordinate table's column says the motion, the
/// matrix form is of the rows above.
#[test]
fn tables_and_the_matrix_form_in_course_words() {
    for name in ["double-pendulum-rods", "bowling-ball"] {
        let text = handout(name, "motion-law", "markdown");
        has(&text, "| Coordinate | Meaning | Motion |", name);
        lacks(&text, "| Joint |", name);
        lacks(&text, "rows numbered as in step 5", name);
    }
}

/// Step 5's rows as a student writes them. A row already in its simplest form is written
/// once with no words before it; Newton–Euler's moment rows write each reaction's r × F,
/// here the gear's (r^{B*P} × F^P) · n̂_z = −r_B F_t, with P at −r_B n̂_x from B* and the
/// tooth force along n̂_y; like terms are summed, −m1 g − m2 g as −g (m1 + m2).
#[test]
fn rows_are_finished_algebra_in_course_words() {
    let name = "gear-pair-torque";
    for format in ["markdown", "latex", "html"] {
        let text = handout(name, "newton-euler", format);
        lacks(&text, "simplest form", name);
    }
    let text = handout(name, "newton-euler", "markdown");
    has(
        &text,
        "**1. $A\\colon \\sum \\mathbf{F} \\cdot \\hat{\\mathbf{n}}_{x}$**\n\n$$\nF^{O_{A}}_{x} = 0\n$$",
        name,
    );
    has(
        &text,
        "(\\mathbf{r}^{B^{*} P} \\times (F^{P}_{t} \\hat{\\mathbf{n}}_{y})) \\cdot \\hat{\\mathbf{n}}_{z} &= -r_{B} F^{P}_{t}",
        name,
    );
    let name = "double-pendulum-rods";
    let text = handout(name, "motion-law", "markdown");
    has(&text, "F^{O}_{y} - g (m_{1} + m_{2}) - (", name);
    lacks(&text, "[-m_{1} g - m_{2} g]", name);
}

/// The four-bar's bars share one mass, m: the free body of all three writes m g, not an
/// undefined m_k. Its q̇3 is printed in the simplest form alone, the textbook's
/// ω_C = ω_A a sin(θ_B − θ_A)/(c sin(θ_B − θ_C)) with θ_B − θ_A = q2 and
/// Δ = −b sin(q1 + q2 − q3) on the loop: q̇3 = −a b sin q2/(c Δ) q̇1.
#[test]
fn the_four_bar_writes_its_mass_and_its_rates_once() {
    let name = "four-bar";
    let text = handout(name, "kane", "markdown");
    lacks(&text, "m_{k}", name);
    has(&text, "$-m\\, g \\hat{\\mathbf{n}}_{y}$", name);
    has(
        &text,
        "\\dot{q}_{3} &= -\\frac{a b \\sin(q_{2})}{c \\Delta} \\dot{q}_{1}",
        name,
    );
    lacks(&text, "\\dot{q}_{3} &= \\frac{a}{\\Delta}", name);
    has(&text, "$\\dot{q}_{3}$ is written with $", name);
}

/// A constraint differentiated with nothing formed before it (the bowling ball's lane,
/// ÿ = 0) is written once, with no "Simplified:" leading it; the sliding law is said in
/// its row of step 5 and only referred to where the friction at the lane is found.
#[test]
fn a_row_alone_is_not_said_simplified_and_the_sliding_law_once() {
    let name = "bowling-ball";
    let latex = handout(name, "motion-law", "latex");
    has(&latex, "\\ddot{y} = 0", name);
    lacks(&latex, "{}{Simplified:}", name);
    lacks(&latex, "\\text{Simplified:}\\quad \\ddot{y} = 0", name);
    let markdown = handout(name, "motion-law", "markdown");
    lacks(&markdown, "Simplified:\n\n$$\n\\ddot{y} = 0", name);
    let words = "μ times the normal force";
    let times = markdown.matches(words).count();
    // Row 4 says the law; the answers' working says it once more for answer 1's reason
    // and answer 3's, but the friction found at the lane refers to row 4 instead.
    let friction = &markdown[markdown.find("Friction at the lane").expect("friction")..];
    let friction = &friction[..friction.find("$$").unwrap_or(friction.len())];
    assert!(!friction.contains(words), "{name}: {friction}");
    assert!(friction.contains("the sliding law"), "{name}: {friction}");
    assert!(times >= 1, "{name}: the law is said in step 5");
    // Row 4, the sliding law in place of the no-slip row, says the law before its equation.
    has(
        &markdown,
        "Sliding friction is μ times the normal force in size and points against the slip",
        name,
    );
}

/// Every answer states its value once: answer 2 of the bowling ball (ẍ = −1.962 m/s²)
/// at its head, its working ending with the closed form ẍ = −g μ; and the instant it rolls
/// (t = 1.16499 s) likewise, t = 2 v₀/(7 g μ). Each number printed once in the Answers.
#[test]
fn an_answer_states_its_value_once() {
    let name = "bowling-ball";
    for format in ["latex", "markdown", "html"] {
        let text = handout(name, "motion-law", format);
        let answers = &text[text.rfind("Answers").expect("answers")..];
        // The instant is said twice: as answer 3's value and as where the speed is asked.
        for (number, most) in [("1.962", 1), ("5.71429", 1), ("1.16499", 2)] {
            let count = answers.matches(number).count();
            assert!(
                count <= most,
                "{name} {format}: {number} said {count} times"
            );
        }
        assert!(
            answers.contains("1.962") && answers.contains("1.16499"),
            "{name} {format}: the values are kept"
        );
    }
    let latex = handout(name, "motion-law", "latex");
    has(&latex, "\\ddot{x} = -g \\mu\n\\]", name);
    has(&latex, "$\\ddot{x} = -1.962\\ \\mathrm{m/s^{2}}$", name);
}

/// The four-bar's auxiliary speeds: where their partial velocities come from (the
/// dependent rates each one's motion fixes, with q̇₁ held at zero), and each body's part
/// of F̃*_r for them multiplied out by name before its value, not given as a result alone.
#[test]
fn the_four_bars_auxiliary_partial_velocities_and_parts_are_derived() {
    let name = "four-bar";
    let latex = handout(name, "kane", "latex").replace('\n', " ");
    has(
        &latex,
        "With the independent rates held, $\\dot{q}_{1} = 0$",
        name,
    );
    has(&latex, "$u_{2}$: $\\dot{q}_{2} = ", name);
    has(&latex, "read off as its coefficient", name);
    // F̃*_{3,B} opens with its products by name, then its value.
    let at = latex.find("\\tilde{F}^{*}_{3,B} &=").expect("F*_{3,B}");
    let line = &latex[at..at + 400];
    assert!(
        line.contains("\\left(\\mathbf{f}^{*}_{B} \\cdot \\hat{\\mathbf{b}}_{x}\\right)")
            || line.contains("\\left(\\mathbf{R}^{*}_{B} \\cdot \\hat{\\mathbf{b}}_{x}\\right)"),
        "{name}: {line}"
    );
}

/// Every coordinate's Motion cell says what that coordinate does: the ball's height is
/// held by the contact, its angle turns; none reads "as for x".
#[test]
fn each_coordinate_says_its_own_motion() {
    let name = "bowling-ball";
    let text = handout(name, "motion-law", "markdown");
    lacks(&text, "as for $x$", name);
    has(
        &text,
        "| held by the contact of the ball with the lane |",
        name,
    );
    has(&text, "| the ball turns |", name);
}
