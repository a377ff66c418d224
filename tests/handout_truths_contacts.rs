//! Contacts, friction and impacts said as they are: a smooth wall holds only the normal
//! component of its point's velocity, only a disc is said to roll, the sliding law is the
//! sizes first and then the signs of this state, an impact's words name only what the
//! problem has, the force a fixed rod exerts is the rod's, and the pictures draw the angle
//! from where the coordinate counts it and the surfaces the bodies touch. Numbers are
//! checked against values worked out here.

use crate::support::{between, markdown_handout as handout};

/// The first `<svg …>…</svg>` of `text` after `from`.
fn svg_after<'t>(text: &'t str, from: &str) -> &'t str {
    let rest = between(text, from, "\u{0}");
    let start = rest.find("<svg").expect("an svg");
    let end = rest[start..].find("</svg>").expect("its end") + start;
    &rest[start..end]
}

/// The number after `name="` in `element`.
fn attribute(element: &str, name: &str) -> f64 {
    let key = format!("{name}=\"");
    let at = element
        .find(&key)
        .unwrap_or_else(|| panic!("{key} in {element}"))
        + key.len();
    let end = element[at..].find('"').expect("closing quote") + at;
    element[at..end].parse().expect("a number")
}

#[test]
fn a_smooth_wall_holds_only_the_normal_component_and_nothing_rolls() {
    let text = handout("ladder-about-to-slip", "motion-law");
    let step1 = between(&text, "## Step 1", "## Step 2");
    // Nothing rolls: the top slides down the smooth wall, ẏ − lθ̇ sθ is not zero.
    assert!(!text.contains("Rolling without slipping"), "{step1}");
    assert!(!text.contains("a wheel"), "{text}");
    assert!(!text.contains("rolls without slipping"), "{text}");
    assert!(step1.contains("No penetration at the wall"), "{step1}");
    assert!(
        step1.contains(
            "{}^{N}\\mathbf{v}^{W} \\cdot \\hat{\\mathbf{n}}_{x} &= \\dot{x} - \\ell \\dot{\\theta} c_{\\theta} = 0"
        ),
        "{step1}"
    );
    assert!(
        !step1.contains("\\hat{\\mathbf{n}}_{y} = \\mathbf{0}"),
        "{step1}"
    );
    // A rolling disc still gets the whole vector.
    let coin = handout("rolling-coin", "lagrange");
    assert!(coin.contains("Rolling without slipping"), "{coin}");
}

#[test]
fn the_plan_says_the_rows_are_solved_together_when_none_gives_one_unknown() {
    let text = handout("ladder-about-to-slip", "motion-law");
    let plan = between(&text, "## Step 3", "## Step 4");
    assert!(!plan.contains("in the order ,"), "{plan}");
    assert!(plan.contains("are solved together"), "{plan}");
}

#[test]
fn the_sliding_law_is_the_sizes_then_the_signs_of_this_state() {
    // The collar: P sin β = 12.856 N > m g = 9.81 N, so the rod pushes it down:
    // F_y = m g − P sin β = −3.04575 N, and friction μ|F_y| = 0.913726 N against the
    // forward slip: F_x = μ F_y, whose sign is right only because F_y < 0.
    let text = handout("collar-on-rough-rod", "kane");
    let step5 = between(&text, "## Step 5", "## Step 6");
    let (m, p, beta, mu, g) = (1.0, 20.0, 40f64.to_radians(), 0.3, 9.81);
    let normal: f64 = m * g - p * beta.sin();
    assert!((normal + 3.04575).abs() < 1e-5, "{normal}");
    assert!(
        step5.contains(
            &format!("{:.6}", mu * normal.abs())
                .trim_end_matches('0')
                .to_string()
        ),
        "{step5}"
    );
    assert!(
        step5.contains(
            "\\left\\vert F^{S}_{x} \\right\\vert = \\mu \\left\\vert F^{S}_{y} \\right\\vert, \\quad F^{S}_{x} < 0,\\ F^{S}_{y} < 0 \\quad \\Rightarrow \\quad F^{S}_{x} = \\mu F^{S}_{y}"
        ),
        "{step5}"
    );
    assert!(
        !step5.contains("its sign from the slip's direction"),
        "{step5}"
    );
    // The ladder's floor pushes up: the same rule gives F_x = −μ F_y there.
    let ladder = handout("ladder-about-to-slip", "motion-law");
    assert!(
        ladder.contains(
            "F^{P}_{x} < 0,\\ F^{P}_{y} > 0 \\quad \\Rightarrow \\quad F^{P}_{x} = -\\mu F^{P}_{y}"
        ),
        "{ladder}"
    );
}

#[test]
fn the_rod_exerts_the_collars_force_and_the_side_it_bears_on_is_said() {
    let text = handout("collar-on-rough-rod", "kane");
    let answers = between(&text, "## Answers", "\u{0}");
    assert!(!answers.contains("the ground exerts"), "{answers}");
    assert!(
        answers.contains("On the collar, the rod exerts sliding friction"),
        "{answers}"
    );
    // Pushed down by the rod, the collar presses up on the rod's underside.
    assert!(answers.contains("bears on the underside"), "{answers}");
    // β is given in degrees by the statement: printed so beside its radians.
    let step1 = between(&text, "## Step 1", "## Step 2");
    assert!(step1.contains("0.698132 (40°)"), "{step1}");
}

#[test]
fn the_ladder_answers_whether_friction_can_hold_it() {
    // Sticking needs F = 29.4722 N > μ N = 0.3 × 98.1 N = 29.43 N: it cannot hold.
    let (m, g, mu) = (10.0, 9.81_f64, 0.3);
    let theta = 31f64.to_radians();
    let needed = m * g * theta.tan() / 2.0;
    assert!(needed > mu * m * g, "{needed}");
    let text = handout("ladder-about-to-slip", "motion-law");
    let answers = between(&text, "## Answers", "\u{0}");
    assert!(
        answers.contains("Friction cannot hold the ladder at rest"),
        "{answers}"
    );
    let step5 = between(&text, "## Step 5", "## Step 6");
    assert!(
        step5.contains(&format!("{:.4}", needed)),
        "{needed} in {step5}"
    );
}

#[test]
fn the_impact_names_only_what_the_problem_has_and_solves_in_symbols() {
    let text = handout("impact-struck-rod", "motion-law");
    let impact = between(&text, "## The impact", "## Step 6");
    for absent in ["springs", "pendulum", "collision", "each reaction"] {
        assert!(!impact.contains(absent), "{absent} in {impact}");
    }
    // cos θ at θ = 0 is 1: the moment of the blow about the centre is J L/2.
    assert!(!impact.contains("\\cos(\\theta)"), "{impact}");
    // Δẏ = J/m = 1.5 m/s and Δθ̇ = 6J/(mL) = 7.5 rad/s, in symbols then in numbers.
    let (m, l, j) = (2.0, 1.2, 3.0);
    assert!(
        impact.contains("\\Delta \\dot{y} = \\frac{J}{m}"),
        "{impact}"
    );
    assert!(
        impact.contains("\\Delta \\dot{\\theta} = \\frac{6 J}{L m}"),
        "{impact}"
    );
    assert!(
        impact.contains(&format!("\\dot{{y}}^{{+}} = {}", j / m)),
        "{impact}"
    );
    assert!(
        impact.contains(&format!("\\dot{{\\theta}}^{{+}} = {}", 6.0 * j / (m * l))),
        "{impact}"
    );
    // The kinetic energy asked is an answer: T = 2 J²/m = 9 J.
    let answers = between(&text, "## Answers", "\u{0}");
    assert!(
        answers.contains("\\dot{x} = 0\\ \\mathrm{m/s}"),
        "{answers}"
    );
    assert!(
        answers.contains(&format!("{}\\ \\mathrm{{J}}", 2.0 * j * j / m)),
        "{answers}"
    );
    // No software notation for a direction.
    assert!(!text.contains("N.x"), "{text}");
}

#[test]
fn the_ladder_angle_is_drawn_from_the_vertical_and_its_surfaces_are_drawn() {
    let text = handout("ladder-about-to-slip", "motion-law");
    let svg = svg_after(&text, "## Step 1");
    // The dashed line the θ arc starts from leaves the mass centre straight up.
    let cm = between(svg, "id=\"configuration-cm-L\"", "/>");
    // Paths round their coordinates to a tenth.
    let short = |x: f64| format!("{x:.1}").trim_end_matches(".0").to_string();
    let (cx, cy) = (short(attribute(cm, "cx")), short(attribute(cm, "cy")));
    let up = format!("M{cx} {cy}l0-");
    assert!(
        svg.lines()
            .any(|l| l.contains(&up) && l.contains("stroke-dasharray")),
        "{up} in {svg}"
    );
    // Not from the horizontal through it, as before.
    assert!(
        !svg.lines()
            .any(|l| l.contains(&format!("M{cx} {cy}l4")) && l.contains("dasharray")),
        "{svg}"
    );
    // The wall and the floor the ladder touches are drawn.
    assert_eq!(svg.matches("<g class=\"ground\">").count(), 2, "{svg}");
}

#[test]
fn the_collar_picture_labels_no_angle_that_is_held_at_zero() {
    let text = handout("collar-on-rough-rod", "kane");
    let svg = svg_after(&text, "## Step 1");
    assert!(!svg.contains(">θ</text>"), "{svg}");
    // The fixed rod it slides on is drawn through it and out past both its sides, a plain
    // line (not hatched ground) at the height of its centre.
    let block = between(svg, "data-shape=\"block\"", "</g>");
    let outline = between(block, "d=\"M", "z");
    let width: f64 = between(outline, "l", " ")[1..]
        .parse()
        .expect("the block's width");
    let cm = between(svg, "id=\"configuration-cm-C\"", "/>");
    let cy = format!("{:.1}", attribute(cm, "cy"));
    let rod = svg
        .lines()
        .filter_map(|l| l.strip_prefix("<path d=\"M"))
        .filter_map(|l| l.split_once('l'))
        .find(|(start, rest)| start.ends_with(&format!(" {cy}")) && rest.contains(" 0\""))
        .unwrap_or_else(|| panic!("a rod through y = {cy} in {svg}"));
    let length: f64 = rod.1.split(' ').next().unwrap().parse().unwrap();
    assert!(length > 1.5 * width, "{length} {width}");
    assert_eq!(svg.matches("<g class=\"ground\">").count(), 0, "{svg}");
}

#[test]
fn the_struck_rod_shows_its_blow() {
    let text = handout("impact-struck-rod", "motion-law");
    let svg = svg_after(&text, "## Step 1");
    // J acts up at the end toward +n̂x: the arrow's label is J, at the rod's right end.
    assert!(svg.contains("data-label=\"J\""), "{svg}");
    let statement = between(&text, "# ", "## Step 1");
    assert!(statement.contains("right end"), "{statement}");
}

/// The row a sentence cites as `row (k)`: step 5's heading of row k.
fn cited_heading<'t>(text: &'t str, sentence_part: &str) -> &'t str {
    let at = text.find(sentence_part).expect(sentence_part) + sentence_part.len();
    let k: String = text[at..]
        .chars()
        .take_while(char::is_ascii_digit)
        .collect();
    let step5 = between(text, "## Step 5", "## Step 6");
    let heading = format!("**{k}. ");
    between(step5, &heading, "\n")
}

#[test]
fn sticking_writes_its_no_slip_row_and_cites_the_row_it_stands_in_for() {
    // The ladder: the floor's slip velocity ẋ + l θ̇ c_θ (step 1), differentiated:
    // ẍ + l c_θ θ̈ − l s_θ θ̇² = 0. The collar: its slip velocity along the rod is ẋ, so ẍ = 0.
    for (name, method, row) in [
        (
            "ladder-about-to-slip",
            "motion-law",
            "\\ell c_{\\theta} \\ddot{\\theta} + \\ddot{x} - \\ell s_{\\theta} \\dot{\\theta}^{2} = 0",
        ),
        ("collar-on-rough-rod", "kane", "\\ddot{x} = 0"),
    ] {
        let text = handout(name, method);
        let friction = between(&text, "**Friction at", "## Step 6");
        // No row number is called the no-slip condition: step 5 prints the sliding law.
        assert!(!friction.contains("no-slip condition ("), "{friction}");
        let said = between(friction, "Assume that it sticks", "Solved with it");
        assert!(said.contains(row), "{name}: {row} in {said}");
        let heading = cited_heading(&text, "in place of row (");
        assert!(heading.contains("sliding friction"), "{name}: {heading}");
        let again = cited_heading(&text, "the sliding law, row (");
        assert!(again.contains("sliding friction"), "{name}: {again}");
    }
}

#[test]
fn the_friction_needed_at_rest_is_derived_in_symbols() {
    // The collar at rest with ẍ = ÿ = 0: ΣF_x gives F_x = −P cos β, ΣF_y gives
    // F_y = m g − P sin β; it sticks while P cos β ≤ μ (P sin β − m g), since F_y < 0.
    let (m, p, beta, mu, g) = (1.0, 20.0, 40f64.to_radians(), 0.3, 9.81);
    let (needed, pressing) = (p * beta.cos(), p * beta.sin() - m * g);
    assert!(needed > mu * pressing, "{needed} {pressing}");
    let collar = handout("collar-on-rough-rod", "kane");
    let friction = between(&collar, "**Friction at", "## Step 6");
    let symbols = between(friction, "In symbols", "In numbers");
    assert!(
        symbols.contains("F^{S}_{x} = -P \\cos(\\beta), \\quad F^{S}_{y} = -P \\sin(\\beta) + m g"),
        "{symbols}"
    );
    assert!(
        symbols.contains("= P \\cos(\\beta) \\le \\mu \\left\\vert F^{S}_{y}\\right\\vert  = \\mu (P \\sin(\\beta) - m g)"),
        "{symbols}"
    );
    // And the numbers that follow are those of the symbols.
    assert!(
        friction.contains(&format!("{needed:.4}")),
        "{needed} in {friction}"
    );
}

#[test]
fn a_collar_on_a_rod_is_guided_and_closes_no_loop() {
    let text = handout("collar-on-rough-rod", "kane");
    for absent in ["loop", "s_{\\theta} = 0"] {
        assert!(!text.contains(absent), "{absent} in {text}");
    }
    let step1 = between(&text, "## Step 1", "## Step 2");
    assert!(
        step1.contains("the rod keeps the collar on its line"),
        "{step1}"
    );
    assert!(
        step1.contains("the rod stops the collar turning"),
        "{step1}"
    );
    assert!(step1.contains("| $\\theta = 0$ |"), "{step1}");
    assert!(
        step1.contains("S is the point of the collar on the rod."),
        "{step1}"
    );
    // A four-bar's closure joins a chain of bodies: a loop.
    let four_bar = handout("four-bar", "kane");
    assert!(four_bar.contains("loop closure at R"), "{four_bar}");
}

#[test]
fn every_coordinate_of_a_joint_has_its_motion_and_the_rolling_rate_is_derived_first() {
    let text = handout("bowling-ball", "motion-law");
    let step1 = between(&text, "## Step 1", "## Step 2");
    // Each its own: the height held by the contact, the angle turning with the ball.
    for (q, motion) in [
        ("y", "held by the contact of the ball with the lane"),
        ("\\theta", "the ball turns"),
    ] {
        let row = between(step1, &format!("| ${q}$ |"), "\n");
        assert!(row.contains(motion), "{row}");
    }
    // ẋ at the switch: v₀ − μ g t at t = 2v₀/(7μg) is 5v₀/7, derived, then the simulation.
    let answers = between(&text, "## Answers", "\u{0}");
    let derived = answers.find("\\frac{5 v_{0}}{7}").expect("5v0/7");
    let checked = answers
        .find("gives the same rate")
        .expect("the simulation's check");
    assert!(derived < checked, "{answers}");
}

#[test]
fn a_zero_slip_velocity_is_not_said_to_stick_and_constants_are_named() {
    // A contact at rest may still slip: the ladder starts at rest and slides at once.
    let ladder = handout("ladder-about-to-slip", "motion-law");
    assert!(!ladder.contains("once it is zero"), "{ladder}");
    assert!(
        ladder.contains("only while friction can hold it"),
        "{ladder}"
    );
    // The collar's moment of inertia is a constant of the problem, I, not a number.
    let collar = handout("collar-on-rough-rod", "kane");
    assert!(!collar.contains("20000"), "{collar}");
    assert!(
        collar.contains("\\tilde{F}^{*}_{3} &= -I \\ddot{\\theta}"),
        "{collar}"
    );
    assert!(collar.contains("The collar is at rest relative to the surface"));
    // The cart only translates: its unit vectors equal N's at every instant.
    let cart = handout("disc-on-cart", "kane");
    assert!(cart.contains(": C does not turn."), "{cart}");
    assert!(
        !cart.contains("At this instant $\\hat{\\mathbf{c}}"),
        "{cart}"
    );
}

/// The bowling ball slides: its free body draws the friction as the unknown F^P_x the table
/// and the plan carry (red, a reaction), against the slip and signed as it points, and the
/// legend says so; the sliding law is row (4), printed once, and answer 2's values, derived
/// in their working, are said there only: ẍ = −μ g = −0.2 · 9.81 = −1.962 m/s² once.
#[test]
fn a_sliding_friction_is_one_unknown_in_picture_table_and_rows_said_once() {
    let text = handout("bowling-ball", "motion-law");
    let picture = svg_after(&text, "### Free body $B$");
    assert!(
        picture.contains("data-kind=\"reaction\" data-label=\"-F^P_x\""),
        "{picture}"
    );
    assert!(!picture.contains("μ F"), "{picture}");
    assert!(
        picture.contains("Unknowns (red) along + axes, sliding friction against the slip;"),
        "{picture}"
    );
    let plan = between(&text, "## Step 3", "## Step 4");
    assert!(plan.contains("F^{P}_{x}, F^{P}_{y}"), "{plan}");
    let law = "\\Rightarrow \\quad F^{P}_{x} = -\\mu F^{P}_{y}";
    assert_eq!(text.matches(law).count(), 1, "{text}");
    let answers = between(&text, "## Answers", "\u{0}");
    let xdd = -0.2 * 9.81;
    let said = format!("{xdd:.3}\\ \\mathrm{{m/s^{{2}}}}");
    assert!(answers.contains(&said), "{answers}");
}

/// The disc in the cylinder: the position constraint says what it holds in the problem's
/// radii (the centres stay R − r apart), and the contact force has one name in the table of
/// forces and in the table of generalized forces; the stiffness of its small oscillations
/// is defined one way.
#[test]
fn the_disc_in_the_cylinder_names_its_constraint_and_its_force_once() {
    let text = handout("disc-in-cylinder", "lagrange");
    assert!(
        text.contains("\\text{the centres stay } R - r \\text{ apart}"),
        "{text}"
    );
    assert!(!text.contains("distance between the centres at"), "{text}");
    assert!(!text.contains("reaction at contact"), "{text}");
    let forces = between(&text, "| Load | Point |", "Each constraint row");
    assert!(forces.contains("| contact force at $P$ |"), "{forces}");
    // Answer 2's stiffness is defined once: from the energies, K = d²V/dx².
    let answers = between(&text, "## Answers", "\u{0}");
    assert!(
        answers.contains("$K = \\mathrm{d}^{2} V/\\mathrm{d} x^{2}$, both evaluated"),
        "{answers}"
    );
    assert!(
        !answers.contains("minus the derivative of the right side"),
        "{answers}"
    );
}

/// The collar on the rough rod: step 6 checks the energy against the work of the rope and
/// of friction, W(t), with its number: by hand, from rest with ẍ = (P cos β + μ F_y)/m
/// constant, W(1 s) = (P cos β + μ F_y) ẍ / 2 = m ẍ² / 2, the kinetic energy at 1 s.
#[test]
fn the_collars_energy_is_checked_against_the_work_of_rope_and_friction() {
    let text = handout("collar-on-rough-rod", "kane");
    let (m, p, beta, mu, g) = (1.0f64, 20.0f64, 40f64.to_radians(), 0.3, 9.81);
    let normal = m * g - p * beta.sin();
    let xdd = (p * beta.cos() - mu * normal.abs()) / m;
    let work = m * xdd * xdd / 2.0;
    let step6 = between(&text, "## Step 6", "## Answers");
    assert!(
        step6.contains("The applied force and friction do work on the system"),
        "{step6}"
    );
    assert!(!step6.contains("changes by their work"), "{step6}");
    let at = step6.find("$W = ").expect("W said") + 5;
    let said: f64 = step6[at..]
        .split('$')
        .next()
        .expect("W")
        .parse()
        .expect("a number");
    assert!(
        (said - work).abs() < 1e-4 * work,
        "W = {said}, by hand {work}"
    );
    assert!(step6.contains("equals $W(t)$"), "{step6}");
}
