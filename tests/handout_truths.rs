//! What a handout prints beside its numbers is true at the state it is printed for: the
//! skidding ball's rows are those that hold while it slides, a reaction's sense is read on
//! the free body of the body it acts on, a moment is about a point the figure
//! names, relations that hold in general are not said to hold at the start, the system
//! matrix's letter names nothing else, an elimination is shown, and an energy has its
//! datum. Numbers are checked against values worked out here.

use crate::support::{between, markdown_handout as handout, run_json};

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
fn a_reaction_on_a_body_inside_the_rows_free_bodies_is_drawn_on_it() {
    // Lagrange's rows take the cart and the disc together: the contact force is inside
    // them, so step 2 draws the disc alone for it, and the answer points there. Both
    // components came out positive: friction 2.18 N forward, normal 19.62 N up, on the
    // disc, said once in words.
    let lagrange = handout("disc-on-cart", "lagrange");
    let answers = between(&lagrange, "## Answers", "\n\n\n");
    assert!(!answers.contains("No free body drawn"), "{answers}");
    assert!(answers.contains("Free body D of step 2"), "{answers}");
    assert!(!answers.contains("acts as drawn"), "{answers}");
    // The sizes on the component lines, the words once after them without the numbers.
    assert!(
        answers.contains("\\cdot \\hat{\\mathbf{c}}_{x} = 2.18182\\ \\mathrm{N}"),
        "{answers}"
    );
    assert!(
        answers.contains("\\cdot \\hat{\\mathbf{c}}_{y} = 19.62\\ \\mathrm{N}"),
        "{answers}"
    );
    assert!(
        answers.contains("On the disc, the cart exerts friction along $+\\hat{\\mathbf{c}}_{x}$"),
        "{answers}"
    );
    assert!(
        answers.contains("a normal force up ($+\\hat{\\mathbf{c}}_{y}$)"),
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
    // The Motion Law writes every row out and prints no matrix form; Lagrange's is S x = b.
    let lagrange = handout("heavy-symmetric-top", "lagrange");
    assert!(lagrange.contains("\\mathbf{S}\\,\\mathbf{x} = \\mathbf{b}"));
    let text = handout("heavy-symmetric-top", "motion-law");
    let answers = between(&text, "## Answers", "\n3. ");
    // Derived, not evaluated: no right-hand side's number after the identity.
    assert!(!answers.contains("RHS"), "{answers}");
    // The check of the steady motion is shown from the rows: θ̇ = 0 clears rows (1) and (3),
    // and row (2) is the relation of answer 1.
    // The rows are written `… = 0`: no right side to speak of.
    assert!(
        answers.contains("rows (1) and (3) without a second derivative vanish"),
        "{answers}"
    );
    assert!(!answers.contains("right side"), "{answers}");
    assert!(
        answers.contains("row (2) add up to zero by the relation of answer 1"),
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
    assert!(answers.contains("Row (2) gives $F^{P}_{t}$"), "{answers}");
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
        between(&text, "## Step 6", "## Answers").contains("the work $W(t)$ done on it")
    };
    assert!(said("disc-on-cart"));
    assert!(said("gear-pair-torque"));
    assert!(!said("double-pendulum-rods"));
}

/// A constant's value in a bundled problem.
fn constant(name: &str, key: &str) -> f64 {
    let text = std::fs::read_to_string(crate::support::problem(name)).expect("readable");
    let problem: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    problem["constants"][key]["value"]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} of {name}"))
}

/// The number printed right after `before` (the first place it occurs in `text`).
fn number_after(text: &str, before: &str) -> f64 {
    let start = text
        .find(before)
        .unwrap_or_else(|| panic!("{before} in {text}"))
        + before.len();
    let digits: String = text[start..]
        .trim_start()
        .chars()
        .take_while(|c| c.is_ascii_digit() || matches!(c, '.' | '-'))
        .collect();
    digits
        .parse()
        .unwrap_or_else(|_| panic!("a number after {before}: {digits}"))
}

/// The skidding ball's forces said once in words, with the body they act on: sliding
/// friction μ m g = 0.2 · 7 · 9.81 = 13.734 N backward, against the slip, and the normal
/// force m g = 68.67 N up, worked here from the problem's constants. No sign lecture, and
/// no |N| (N names the Newtonian frame).
#[test]
fn the_balls_forces_are_said_in_words_on_the_ball() {
    let text = handout("bowling-ball", "motion-law");
    let answers = between(&text, "## Answers", "\n2. ");
    let (m, g, mu) = (
        constant("bowling-ball", "m"),
        constant("bowling-ball", "g"),
        constant("bowling-ball", "mu"),
    );
    let words = between(answers, "On the ball, the lane exerts", ".\n");
    // The sizes on the component lines; the words say what each is, not its size again.
    let friction = number_after(answers, "\\cdot \\hat{\\mathbf{n}}_{x} = ");
    assert!((friction + mu * m * g).abs() < 1e-9, "{answers}");
    assert!(words.contains("sliding friction along"), "{words}");
    assert!(
        words.contains("along $-\\hat{\\mathbf{n}}_{x}$ (against the slip)"),
        "{words}"
    );
    let normal = number_after(answers, "\\cdot \\hat{\\mathbf{n}}_{y} = ");
    assert!((normal - m * g).abs() < 1e-9, "{answers}");
    assert!(words.contains("a normal force up"), "{words}");
    assert!(!words.contains("\\mathrm{N}"), "{words}");
    assert!(words.contains("up ($+\\hat{\\mathbf{n}}_{y}$)"), "{words}");
    assert!(!text.contains("opposite to the arrow drawn"), "{answers}");
    assert!(!text.contains("as drawn"), "{answers}");
    assert!(!text.contains("|N|"), "μ|N| in {text}");
    // Step 1 names the surface, once for the one joint.
    assert_eq!(text.matches("rolls or slides on the lane").count(), 1);
    assert!(!text.contains("on the ground |"), "{text}");
}

/// A contact with one tangent in a plane prints F_t (the names of the commands' output
/// stay `Ft1`); the rack's tooth force on the pinion is (T/r) M/(M + I/r²)... worked here:
/// the rack's acceleration ẍ = (T/r)/(M + I/r²) needs the force M ẍ from the pinion, so the
/// pinion feels M ẍ backward along r̂_x. Its dependent rate at the start has its unit.
#[test]
fn a_plane_contacts_tangent_is_f_t_and_the_racks_push_is_said() {
    for name in ["disc-in-cylinder", "gear-pair-torque", "rack-and-pinion"] {
        let text = handout(name, "motion-law");
        assert!(!text.contains("_{t1}"), "{name}");
    }
    let text = handout("rack-and-pinion", "motion-law");
    let (r, i, big_m, t) = (
        constant("rack-and-pinion", "r"),
        constant("rack-and-pinion", "I"),
        constant("rack-and-pinion", "M"),
        constant("rack-and-pinion", "T"),
    );
    let answers = between(&text, "## Answers", "\n\n\n");
    let words = between(
        answers,
        "On the pinion, the rack exerts",
        " Its component across",
    );
    let push = -number_after(answers, "\\cdot \\hat{\\mathbf{r}}_{x} = ");
    assert!(words.contains("a tangential tooth force along"), "{words}");
    let expected = big_m * (t / r) / (big_m + i / (r * r));
    assert!(
        (push - expected).abs() < 1e-4 * expected,
        "{push} {expected}"
    );
    assert!(words.contains("along $-\\hat{\\mathbf{r}}_{x}$"), "{words}");
    // θ̇ = ẋ/r at the start: 0.1/0.04 = 2.5 rad/s, with its unit.
    let rate = ((0.1 / r) * 1e6).round() / 1e6;
    assert!(
        text.contains(&format!(
            "at the initial state, $\\dot{{\\theta}} = {rate}\\ \\mathrm{{rad/s}}$"
        )),
        "{text}"
    );
}

/// The four-bar's two closure rows are named by their directions; its rate relations are
/// said in symbols; the coupler's force on the rocker, given in B's unit vectors, is given
/// in N's too: turned by B's angle q₁ + q₂, worked here from the answer's numbers.
#[test]
fn the_four_bars_closure_rows_and_pin_force_are_named_in_full() {
    let text = handout("four-bar", "motion-law");
    let step1 = between(&text, "## Step 1", "## Step 2");
    for axis in ["x", "y"] {
        assert!(
            step1.contains(&format!(
                "\\text{{loop closure at R}}\\text{{, along }} \\hat{{\\mathbf{{b}}}}_{{{axis}}}"
            )),
            "{step1}"
        );
    }
    assert!(!text.contains("at the initial state, $\\dot{q}_{2} = -1.15"));
    assert!(text.contains("in general, $\\dot{q}_{2} = "), "{text}");
    let json = run_json(&[
        "answer".as_ref(),
        crate::support::problem("four-bar").as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    let r = &json["answers"][4];
    assert_eq!(r["frame"], "B");
    let (bx, by) = (
        r["components"]["x"].as_f64().expect("x"),
        r["components"]["y"].as_f64().expect("y"),
    );
    let angle = r["state"]["q1"].as_f64().expect("q1") + r["state"]["q2"].as_f64().expect("q2");
    let (nx, ny) = (
        bx * angle.cos() - by * angle.sin(),
        bx * angle.sin() + by * angle.cos(),
    );
    let answers = between(&text, "## Answers", "\n\n\n");
    let ground = between(answers, "Along the ground's unit vectors", "\n");
    let printed_x = number_after(ground, "\\hat{\\mathbf{n}}_{x} = ");
    let printed_y = number_after(ground, "\\hat{\\mathbf{n}}_{y} = ");
    assert!((printed_x - nx).abs() < 1e-4, "{ground}: {nx}");
    assert!((printed_y - ny).abs() < 1e-4, "{ground}: {ny}");
    let size = number_after(ground, "a force of $");
    assert!((size - nx.hypot(ny)).abs() < 1e-4, "{ground}");
}

/// The disc in the cylinder's moment row is written with x² + y² = (R − r)² used: r F_t,
/// not r x² F_t/(R − r)² + r y² F_t/(R − r)².
#[test]
fn the_disc_in_the_cylinder_moment_row_uses_the_distance_it_keeps() {
    let text = handout("disc-in-cylinder", "motion-law");
    let step5 = between(&text, "## Step 5", "## Step 6");
    assert!(!step5.contains("x^{2} F^{P}"), "{step5}");
    assert!(!step5.contains("y^{2} F^{P}"), "{step5}");
}

/// The gear's tooth force said as what it is (tangential, no pressure angle), and the
/// axles named as the statement names them.
#[test]
fn the_gears_tooth_force_is_tangential_and_its_axles_are_named_as_stated() {
    let text = handout("gear-pair-torque", "motion-law");
    let answers = between(&text, "## Answers", "\n\n\n");
    // T / (r_A (1 + (I_A/I_B)(r_B/r_A)²))... by hand: q̈_A = T/(I_A + I_B (r_A/r_B)²), and
    // the gear's own row I_B q̈_B = r_B F gives F = I_B (r_A/r_B) q̈_A / r_B.
    let c = |k: &str| constant("gear-pair-torque", k);
    let qa = c("T") / (c("IA") + c("IB") * (c("rA") / c("rB")).powi(2));
    let force = c("IB") * c("rA") / c("rB") * qa / c("rB");
    let words = between(
        answers,
        "On the gear, the pinion exerts",
        " Its component across",
    );
    // Its size on its component line (the gear's centre is level with the pinion's: the
    // force is vertical), the words after it without the number.
    assert!(words.contains("a tangential tooth force up"), "{words}");
    let said = number_after(answers, "\\cdot \\hat{\\mathbf{n}}_{y} = ");
    assert!((said - force).abs() < 1e-9 * force, "{said} {force}");
    assert!(
        answers.contains("is zero by assumption, not as a result: the pressure angle is neglected"),
        "{answers}"
    );
    assert!(
        text.contains("fixed axle at $O_A$"),
        "the statement's names"
    );
}

/// The top's tip force during steady precession said as it holds at every instant: a
/// vertical m g up and a horizontal m h Ω² sin θ toward the vertical through the tip; the
/// components of `answer` at ψ = 0 have that horizontal size, worked here with Ω = ψ̇ of
/// the steady motion found.
#[test]
fn the_tops_tip_force_is_said_by_its_vertical_and_horizontal_parts() {
    let text = handout("heavy-symmetric-top", "motion-law");
    let answers = between(&text, "## Answers", "\n4. ");
    let words = between(answers, "That is, a vertical force", ".\n");
    assert!(
        words.contains("toward the vertical through the tip"),
        "{words}"
    );
    assert!(words.contains("at every instant of this motion"), "{words}");
    assert!(words.contains("m g$ up"), "{words}");
    let json = run_json(&[
        "answer".as_ref(),
        crate::support::problem("heavy-symmetric-top").as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    let (m, h) = (
        constant("heavy-symmetric-top", "m"),
        constant("heavy-symmetric-top", "h"),
    );
    for found in json["answers"].as_array().expect("answers") {
        if found["kind"] != "reaction" {
            continue;
        }
        let c = |k: &str| found["components"][k].as_f64().expect(k);
        let omega = found["state"]["psi'"].as_f64().expect("ψ̇");
        let theta = found["state"]["theta"].as_f64().expect("θ");
        let horizontal = m * h * omega * omega * theta.sin();
        assert!((c("x").hypot(c("y")) - horizontal).abs() < 1e-6, "{found}");
        assert!((c("z") - m * constant("heavy-symmetric-top", "g")).abs() < 1e-9);
    }
}

/// The gear pair's animation turns the pinion one way throughout: it speeds up under its
/// torque (q̈_A = 225 rad/s²) until it turns more than half a turn between frames, and a
/// body whose angle were taken back to the nearest of the last frame's would be seen
/// turning back.
#[test]
fn a_fast_pinion_is_animated_turning_one_way() {
    let html = crate::support::explain(
        "gear-pair-torque",
        &["--method", "newton-euler", "--format", "html"],
    );
    let mut checked = 0;
    for piece in html.split("type=\"rotate\"").skip(1) {
        let values = piece.split("values=\"").nth(1).unwrap_or_default();
        let values = values.split('"').next().unwrap_or_default();
        let angles: Vec<f64> = values.split(';').filter_map(|v| v.parse().ok()).collect();
        let steps: Vec<f64> = angles.windows(2).map(|w| w[1] - w[0]).collect();
        let last = steps.last().copied().unwrap_or_default();
        if last.abs() > 180.0 {
            // A body that ends fast: every frame after its first turn goes the same way.
            let same_way = steps.iter().skip(2).all(|s| s * last > 0.0);
            assert!(same_way, "{values}");
            checked += 1;
        }
    }
    assert!(
        checked >= 1,
        "no body turns more than half a turn between frames"
    );
}
