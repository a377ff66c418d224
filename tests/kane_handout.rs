//! Kane's method as the worked solution shows it: the partial velocities and partial
//! angular velocities of the double pendulum, and its generalized active and inertia forces
//! each apart, read from the Markdown handout and held against a derivation by hand.
//!
//! The double pendulum (problems/double-pendulum-rods.json): rod A (m1, L1) pinned at O,
//! turning q1 about N.z; rod B (m2, L2) pinned at P = -L1 a_y, turning q2 about A.z; each
//! mass centre halfway down its rod, gravity -g n_y.
//!
//! By hand, with u_r = q_r':
//! - v^{A*} = (L1/2) q1' a_x, so v_1^{A*} = (L1/2) a_x, ω_1^A = a_z, and A does not move
//!   with u_2;
//! - v^{B*} = L1 q1' a_x + (L2/2)(q1' + q2') b_x, with a_x = cos q2 b_x - sin q2 b_y, so
//!   v_1^{B*} = (L2/2 + L1 cos q2) b_x - L1 sin q2 b_y, v_2^{B*} = (L2/2) b_x,
//!   ω_1^B = ω_2^B = b_z;
//! - F_r = -∂V/∂q_r with V = -m1 g (L1/2) cos q1 - m2 g (L1 cos q1 + (L2/2) cos(q1 + q2)):
//!   F_1 = -(L1 g m1/2) sin q1 - L1 g m2 sin q1 - (L2 g m2/2) sin(q1 + q2),
//!   F_2 = -(L2 g m2/2) sin(q1 + q2);
//! - F_2* = -v_2^{B*}·m2 a^{B*} - ω_2^B·I^B α^B with I^B = m2 L2²/12 and
//!   b_x·a^{B*} = L1 (q1'' cos q2 + q1'² sin q2) + (L2/2)(q1'' + q2''):
//!   F_2* = -(m2 L2²/3)(q1'' + q2'') - (L1 L2 m2/2)(q1'' cos q2 + q1'² sin q2);
//! - the auxiliary speeds along O's reaction give F_3 = F^O_x and
//!   F_4 = F^O_y - g m1 - g m2 (the pin force and the weights along n_x, n_y).

use mbd_tutor::equations::Method;
use mbd_tutor::render::{render, Format};
use mbd_tutor::symbolic::latex_unit_vector;
use std::path::Path;

/// Kane's worked handout of the bundled problem `name` (a file name), in Markdown.
pub(crate) fn markdown(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("problems")
        .join(name);
    let problem = mbd_tutor::problem::load_file(&path).expect("the problem loads");
    let solution = mbd_tutor::pipeline::work(&problem, Method::Kane)
        .map(|worked| mbd_tutor::solution::worked(&worked))
        .expect("Kane's method derives");
    render(&solution, Format::Markdown, None, false).expect("the handout renders")
}

/// The part of the handout from `start` to `end`.
pub(crate) fn section<'a>(text: &'a str, start: &str, end: &str) -> &'a str {
    let from = text.find(start).unwrap_or_else(|| panic!("no `{start}`"));
    let to = text[from..].find(end).map_or(text.len(), |i| from + i);
    &text[from..to]
}

#[test]
fn the_double_pendulums_partial_velocities_and_generalized_forces_are_shown_apart() {
    let text = markdown("double-pendulum-rods.json");
    let step5 = section(&text, "## Step 5", "## Step 6");
    let (a_x, a_z) = (latex_unit_vector("A", 0), latex_unit_vector("A", 2));
    let (b_x, b_y, b_z) = (
        latex_unit_vector("B", 0),
        latex_unit_vector("B", 1),
        latex_unit_vector("B", 2),
    );
    // Step 4 places each uniform rod's mass centre from its pin: halfway down the rod,
    // along minus the rod's y axis (the rods hang along −y at zero angle).
    let step4 = section(&text, "## Step 4", "## Step 5");
    let a_y = latex_unit_vector("A", 1);
    assert!(step4.contains(&format!(
        "\\mathbf{{r}}^{{O A^*}} = -\\frac{{L_{{1}}}}{{2}} {a_y}"
    )));
    assert!(step4.contains(&format!(
        "\\mathbf{{r}}^{{P B^*}} = -\\frac{{L_{{2}}}}{{2}} {b_y}"
    )));
    // The table: one line per speed and body that moves with it, the speed on its first.
    let table: Vec<&str> = step5
        .lines()
        .skip_while(|l| !l.starts_with("| Speed"))
        .skip(2)
        .take_while(|l| l.starts_with("| "))
        .collect();
    let expected = [
        format!(
            "| $u_{{1}} = \\dot{{q}}_{{1}}$ | A | ${{}}^{{N}}\\mathbf{{v}}^{{A^*}}_{{1}} = \\frac{{L_{{1}}}}{{2}} {a_x}$ | ${{}}^{{N}}\\boldsymbol{{\\omega}}^{{A}}_{{1}} = {a_z}$ |"
        ),
        format!(
            "|  | B | ${{}}^{{N}}\\mathbf{{v}}^{{B^*}}_{{1}} = (\\frac{{L_{{2}}}}{{2}} + L_{{1}} c_{{2}}) {b_x} - L_{{1}} s_{{2}} {b_y}$ | ${{}}^{{N}}\\boldsymbol{{\\omega}}^{{B}}_{{1}} = {b_z}$ |"
        ),
        format!(
            "| $u_{{2}} = \\dot{{q}}_{{2}}$ | B | ${{}}^{{N}}\\mathbf{{v}}^{{B^*}}_{{2}} = \\frac{{L_{{2}}}}{{2}} {b_x}$ | ${{}}^{{N}}\\boldsymbol{{\\omega}}^{{B}}_{{2}} = {b_z}$ |"
        ),
    ];
    assert_eq!(table, expected, "the table of partial velocities");
    // F_r and F_r* each on its own, then their sum.
    let shown = |tex: &str| format!("$$\n{tex}\n$$");
    let forces = [
        "F_{1} = -\\frac{L_{1} g}{2} (m_{1} + 2 m_{2}) s_{1} - \\frac{L_{2} m_{2} g}{2} s_{12}",
        "F_{2} = -\\frac{L_{2} m_{2} g}{2} s_{12}",
        "F_{3} = F^{O}_{x}",
        "F_{4} = F^{O}_{y} - g (m_{1} + m_{2})",
    ];
    for f in forces {
        assert!(step5.contains(&shown(f)), "missing {f}\n{step5}");
    }
    // F_2* body by body: B alone moves with u_2 (its part named in the first line), its dot
    // products multiplied out along b̂ (v_2^{B*} = (L2/2) b_x, ω_2^B = b_z), then the term
    // found by hand above.
    let inertia_2 = "\\begin{aligned} F^{*}_{2} &= F^{*}_{2,B} = \\mathbf{v}^{B^*}_{2} \\cdot \\mathbf{R}^{*}_{B} + \\boldsymbol{\\omega}^{B}_{2} \\cdot \\mathbf{M}^{*}_{B} \\\\ &= \\frac{L_{2}}{2}\\, \\left(";
    assert!(step5.contains(inertia_2), "F_2* written out\n{step5}");
    let by_hand = "&= -\\frac{L_{2} m_{2}}{6} (2 L_{2} + 3 L_{1} c_{2}) \\ddot{q}_{1} - \\frac{L_{2}^{2} m_{2}}{3} \\ddot{q}_{2} - \\frac{L_{1} L_{2} m_{2} s_{2}}{2} \\dot{q}_{1}^{2} \\end{aligned}";
    assert!(step5.contains(by_hand), "F_2* as by hand\n{step5}");
    // The products stand as a student writes them, with no bookkeeping beside them.
    assert!(!step5.contains("\\text{(along }"), "{step5}");
    // In the order a textbook gives them: F_r, then F_r*, then the sum.
    for r in 1..=4 {
        let active = step5.find(&format!("$$\nF_{{{r}}} = ")).expect("F_r");
        let inertia = step5
            .find(&format!("$$\nF^{{*}}_{{{r}}} = "))
            .or_else(|| step5.find(&format!("\\begin{{aligned}} F^{{*}}_{{{r}}} &= ")))
            .expect("F_r*");
        // A reaction after the first is solved as the first was, in short.
        let rest = &step5[inertia..];
        let sum = rest
            .find("Their sum")
            .or_else(|| rest.find("Solved likewise:"))
            .expect("the sum")
            + inertia;
        assert!(active < inertia && inertia < sum, "r = {r}");
    }
    // The speeds are the rates, u_r = q̇_r, said once before the rows: a row is headed r.
    assert!(step5.contains("u_r = \\dot{q}_r"), "{step5}");
    assert!(step5.contains("**1. $r = 1$**"), "{step5}");
    assert!(!step5.contains("(a generalized speed)"), "{step5}");
}

#[test]
fn the_other_methods_show_no_partial_velocities() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("problems/simple-pendulum.json");
    let problem = mbd_tutor::problem::load_file(&path).expect("the problem loads");
    for method in [Method::MotionLaw, Method::NewtonEuler] {
        let solution = mbd_tutor::pipeline::work(&problem, method)
            .map(|worked| mbd_tutor::solution::worked(&worked))
            .expect("derives");
        assert!(solution.partial_velocities.is_empty());
        assert!(solution.equations.iter().all(|e| e.active_tex.is_empty()));
    }
}

#[test]
fn a_long_partial_velocity_is_written_by_the_names_of_step_4() {
    // The bicycle's handlebar H: step 4 writes a^{H*} = Σ v_r q̈_r + ã with each partial
    // velocity's components named (∂a/∂q̈_r = ∂v/∂q̇_r), so the table gives the yaw rate's v^{H*} by those
    // names rather than multiplied out over a line and more, and defines each name once.
    let text = markdown("validation/whipple-bicycle.json");
    let row = "${}^{N}\\mathbf{v}^{H^*}_{\\dot{\\psi}} = v^{H^{*}}_{\\psi,x} \\hat{\\mathbf{h}}_{x} + v^{H^{*}}_{\\psi,y} \\hat{\\mathbf{h}}_{y} + v^{H^{*}}_{\\psi,z} \\hat{\\mathbf{h}}_{z}$";
    assert!(text.contains(row), "no table entry {row}");
    for axis in ["x", "y", "z"] {
        let name = format!("v^{{H^{{*}}}}_{{\\psi,{axis}}} = ");
        assert!(text.contains(&name), "{name} is not defined");
    }
}

/// The mass matrix by hand, from the kinetic energy T = ½ q̇ᵀ M q̇ of the two rods:
/// M11 = m1 L1²/3 + m2 (L1² + L2²/3 + L1 L2 cos q2), M12 = m2 (L2²/3 + L1 L2 cos q2 / 2),
/// M22 = m2 L2²/3, all positive. Kane's rows of the speeds are −(M q̈ + …) = 0, so the
/// handout writes them with the signs changed.
#[test]
fn kanes_rows_of_the_speeds_are_written_with_the_mass_matrix_positive() {
    let text = markdown("double-pendulum-rods.json");
    let step5 = section(&text, "## Step 5", "## Step 6");
    let row = |k: usize| {
        let row = section(step5, &format!("**{k}. "), &format!("**{}. ", k + 1));
        // The row's last display: its sum, or an auxiliary row's reaction solved for.
        let at = row.rfind("$$\n").expect("the row's equation") + 3;
        let from = row[..at - 3].rfind("$$\n").expect("its start") + 3;
        row[from..at - 3].trim().to_string()
    };
    let m11 = "\\left(\\frac{L_{1}^{2} m_{1}}{3} + L_{1}^{2} m_{2} + \\frac{L_{2}^{2} m_{2}}{3} + L_{1} L_{2} m_{2} c_{2}\\right) \\ddot{q}_{1}";
    let m12 = "\\frac{L_{2} m_{2}}{6} (2 L_{2} + 3 L_{1} c_{2})";
    let m22 = "\\frac{L_{2}^{2} m_{2}}{3} \\ddot{q}_{2}";
    let (row1, row2) = (row(1), row(2));
    assert!(
        row1.starts_with(&format!("{m11} + {m12} \\ddot{{q}}_{{2}}")),
        "{row1}"
    );
    assert!(
        row2.starts_with(&format!("{m12} \\ddot{{q}}_{{1}} + {m22}")),
        "{row2}"
    );
    // −q̇₁² + (q̇₁ + q̇₂)² collected as a textbook writes it.
    assert!(
        row1.contains("(\\dot{q}_{2}^{2} + 2 \\dot{q}_{1} \\dot{q}_{2})"),
        "{row1}"
    );
    // An auxiliary row's sum F_3 + F*_3 = 0 holds F^O_x alone: it is solved for it.
    assert!(row(3).starts_with("F^{O}_{x} = "), "{}", row(3));
    assert!(step5.contains("Kane's equation, simplified and rearranged"));
}

/// A two-degree-of-freedom Kane handout writes its rows once: step 5 has them collected
/// by the q̈ with the mass matrix by hand (see above), so no table of named entries S_{i,j},
/// f_i writes them a second time, and no pattern of dots stands in for them.
#[test]
fn a_two_dof_kane_handout_writes_its_rows_once() {
    let text = markdown("double-pendulum-rods.json");
    assert!(!text.contains("\\bullet"));
    assert!(
        !text.contains("In matrix form"),
        "the rows are written twice"
    );
    for name in ["S_{1,1} = ", "S_{1,2} = ", "f_{2} = "] {
        assert!(!text.contains(name), "{name} repeats a row of step 5");
    }
    // The entries are read in the rows themselves: row 2 holds M12 q̈1 + M22 q̈2 and the
    // terms (L₂ m₂/2)(L₁ q̇₁² sin q2 + g sin(q1 + q2)) by hand.
    let step5 = section(&text, "## Step 5", "## Step 6");
    assert!(step5.contains("\\frac{L_{2}^{2} m_{2}}{3} \\ddot{q}_{2} + \\frac{L_{1} L_{2} m_{2} s_{2}}{2} \\dot{q}_{1}^{2} + \\frac{L_{2} m_{2} g}{2} s_{12} = 0"), "{step5}");
}

/// Kane and Levinson's auxiliary speed along F^O_x: O slides along n_x, every point of
/// A + B gains u₃ n_x, so v₃^{A*} = v₃^{B*} = n_x and ω₃ = 0; the pin P inside A + B does
/// no work; the system is block-triangular (q̈ from rows 1–2, then one force a row).
#[test]
fn the_auxiliary_speeds_show_their_augmented_velocities_and_the_order_of_the_solve() {
    let text = markdown("double-pendulum-rods.json");
    let n_x = latex_unit_vector("N", 0);
    let row3 = section(&text, "**3. ", "**4. ");
    assert!(row3.contains(&format!("Let $O$ slide with speed $u_{{3}}$ along ${n_x}$")));
    // The augmented velocity written out: A's centre, half a rod from O, moves at
    // (L₁/2) q̇₁ â_x by step 4, plus the give-way u₃ n̂_x.
    let a_x = latex_unit_vector("A", 0);
    assert!(row3.contains(&format!(
        "{{}}^{{N}}\\mathbf{{v}}^{{A^*}} = \\frac{{L_{{1}} \\dot{{q}}_{{1}}}}{{2}} {a_x} + u_{{3}}\\, {n_x}"
    )));
    assert!(row3.contains(&format!(
        "$\\mathbf{{v}}^{{A^*}}_{{3}} = \\mathbf{{v}}^{{B^*}}_{{3}} = {n_x}$, its partial angular velocities zero"
    )));
    assert!(row3.contains("The reaction at $P$, inside $A + B$, drops out"));
    assert!(row3.contains("at $u_{3} = 0$"));
    // The second component at O is told in short, referring to the first.
    let n_y = latex_unit_vector("N", 1);
    let row4 = section(&text, "**4. ", "In matrix form");
    assert!(row4.contains(&format!(
        "As in row 3, along ${n_y}$: the partial velocities of $u_{{4}}$ are $\\mathbf{{v}}^{{A^*}}_{{4}} = \\mathbf{{v}}^{{B^*}}_{{4}} = {n_y}$"
    )));
    let plan = section(&text, "## Step 3", "## Step 4");
    assert!(plan.contains("Rows 1 and 2 contain no reaction and give the second derivatives"));
    assert!(plan.contains("each of rows 3 and 4 then gives its one reaction"));
}

/// A bob on a light rod is a two-force member: every force but the pin's acts at the bob,
/// so the pin's force lies along the rod. Kane's auxiliary speed along the rod brings in
/// the tension alone; by hand, along the rod toward O, T − m g cos θ = m L θ̇² (the
/// centripetal acceleration), so T = m (g cos θ + L θ̇²) = 4.14827 N at θ = 0.6, θ̇ = 0.5.
#[test]
fn a_bob_on_a_light_rod_has_its_tension_as_kanes_unknown() {
    let text = markdown("simple-pendulum.json");
    // A bob has no central inertia: step 4 heads it as the particle it is.
    assert!(section(&text, "## Step 4", "## Step 5").contains("**Particle "));
    let step5 = section(&text, "## Step 5", "## Step 6");
    assert!(
        step5.contains("u_{2}\\text{, for } T^{O}$"),
        "no auxiliary speed for T^O"
    );
    assert!(step5.contains("is a two-force member"));
    // The row solved for its one reaction, as the hand derivation above gives it.
    assert!(step5.contains("T^{O} = L m \\dot{\\theta}^{2} + m g c_{\\theta}"));
    let (m, g, l, theta, rate): (f64, f64, f64, f64, f64) = (0.5, 9.81, 0.8, 0.6, 0.5);
    let tension = m * (g * theta.cos() + l * rate * rate);
    let row = step5
        .lines()
        .find(|l| l.starts_with("| $T^{O}$ | "))
        .expect("T^O's value at the start");
    let value: f64 = row.split('|').nth(2).unwrap().trim().parse().unwrap();
    assert!(
        (value - tension).abs() < 1e-5 * tension,
        "{value} against {tension}"
    );
}

/// The double pendulum of particles as Kane and Levinson augment it: letting O give way
/// along rod 1 adds u₃ p̂₁ᵧ to every point of both bobs, so by hand
/// ᴺv^{P1} = L₁ q̇₁ p̂₁ₓ + u₃ p̂₁ᵧ and ᴺv^{P2} = ᴺv^{P1} + L₂ q̇₂ p̂₂ₓ; letting Q give way
/// along rod 2 moves the second bob alone, ᴺv^{P2} = ᴺv^{P1} + L₂ q̇₂ p̂₂ₓ + u₄ p̂₂ᵧ.
/// Each row then gives its rod's tension.
#[test]
fn the_particles_augmented_velocities_are_written_as_equations() {
    let text = markdown("validation/double-pendulum-particles-absolute.json");
    let (p1x, p1y) = (latex_unit_vector("P1", 0), latex_unit_vector("P1", 1));
    let (p2x, p2y) = (latex_unit_vector("P2", 0), latex_unit_vector("P2", 1));
    // A particle is a point, named without the mass centre's star.
    let (v1, v2) = ("{}^{N}\\mathbf{v}^{P_{1}}", "{}^{N}\\mathbf{v}^{P_{2}}");
    let row3 = section(&text, "**3. ", "**4. ");
    assert!(row3.contains(&format!(
        "{v1} = L_{{1}} \\dot{{q}}_{{1}} {p1x} + u_{{3}}\\, {p1y},\\; {v2} = {v1} + L_{{2}} \\dot{{q}}_{{2}} {p2x}$"
    )));
    assert!(row3.contains("solved for the reaction"));
    let row4 = section(&text, "**4. ", "In matrix form");
    assert!(row4.contains(&format!(
        "{v2} = {v1} + L_{{2}} \\dot{{q}}_{{2}} {p2x} + u_{{4}}\\, {p2y}$"
    )));
}

#[test]
fn a_particle_has_no_angular_velocity_and_a_light_link_is_headed_so() {
    // A particle's turning carries no inertia: step 4 gives its velocity and acceleration
    // alone, as a textbook does for the bobs of a double pendulum.
    let text = markdown("validation/double-pendulum-particles-absolute.json");
    let step4 = section(&text, "## Step 4", "## Step 5");
    assert!(step4.contains("**Particle P1**"), "{step4}");
    assert!(!step4.contains("\\boldsymbol{\\omega}"), "{step4}");
    assert!(!step4.contains("\\boldsymbol{\\alpha}"), "{step4}");
    // The light connecting rod of a slider-crank is no particle: it turns, as the loop says.
    let text = markdown("slider-crank-light-rod.json");
    let step4 = section(&text, "## Step 4", "## Step 5");
    assert!(step4.contains("**Light body B**"), "{step4}");
    assert!(step4.contains(
        "{}^{N}\\boldsymbol{\\omega}^{B} = (\\dot{q}_{1} + \\dot{q}_{2}) \\hat{\\mathbf{b}}_{z}"
    ));
}

/// The four-bar's loop closed at the crank angle `q1`: (q2, q3) by Newton's method from
/// the problem's guess, for a = 0.1, b = 0.3, c = 0.25, d = 0.3.
fn four_bar_closed(q1: f64) -> (f64, f64) {
    let (a, b, c, d) = (0.1, 0.3, 0.25, 0.3);
    let (mut q2, mut q3) = (-0.65f64, 1.6f64);
    for _ in 0..50 {
        // a e(q1) + b e(q1 + q2) - c e(q3) - d n_x = 0, e(θ) = (cos θ, sin θ).
        let f = [
            a * q1.cos() + b * (q1 + q2).cos() - c * q3.cos() - d,
            a * q1.sin() + b * (q1 + q2).sin() - c * q3.sin(),
        ];
        let j = [
            [-b * (q1 + q2).sin(), c * q3.sin()],
            [b * (q1 + q2).cos(), -c * q3.cos()],
        ];
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        q2 -= (f[0] * j[1][1] - f[1] * j[0][1]) / det;
        q3 -= (j[0][0] * f[1] - j[1][0] * f[0]) / det;
    }
    (q2, q3)
}

#[test]
fn the_four_bars_dependent_rates_share_one_named_denominator() {
    let text = markdown("four-bar.json");
    // As a textbook writes it: Δ defined once, where the dependent rates first use it.
    assert!(text.contains(
        "over the common denominator $\\Delta = d \\sin(q_{3}) + a \\sin\\left(q_{1} - q_{3}\\right)$:"
    ));
    assert!(!text.contains("the common denominator of the dependent rates"));
    assert!(text.contains("\\dot{q}_{2} &= -\\frac{d \\sin(q_{3})}{\\Delta} \\dot{q}_{1}"));
    // q3' in its simplest form alone, −a b sin q2/(c Δ) q1', the loop's identity said after.
    assert!(text.contains("\\dot{q}_{3} &= -\\frac{a b \\sin(q_{2})}{c \\Delta} \\dot{q}_{1}"));
    // By hand: the velocity loop a q1' e⊥(q1) + b (q1' + q2') e⊥(q1 + q2) = c q3' e⊥(q3),
    // solved for q2' and q3' with q1' = 1 at a closed state, against the printed relation.
    let (a, b, c, d) = (0.1, 0.3, 0.25, 0.3);
    for q1 in [1.0f64, 1.2, 1.4] {
        let (q2, q3) = four_bar_closed(q1);
        let q12 = q1 + q2;
        // [-b s12, c s3; b c12, -c c3] (q2', q3') = (a s1 + b s12, -a c1 - b c12)
        let m = [
            [-b * q12.sin(), c * q3.sin()],
            [b * q12.cos(), -c * q3.cos()],
        ];
        let r = [a * q1.sin() + b * q12.sin(), -a * q1.cos() - b * q12.cos()];
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        let rate2 = (r[0] * m[1][1] - m[0][1] * r[1]) / det;
        let rate3 = (m[0][0] * r[1] - m[1][0] * r[0]) / det;
        let delta = a * (q1 - q3).sin() + d * q3.sin();
        // On the motion Δ is the determinant of the loop's columns of q2', q3' over b c.
        assert!((delta + b * (q12 - q3).sin()).abs() < 1e-9);
        let printed2 = -d * q3.sin() / delta;
        let printed3 = -a * b * q2.sin() / (c * delta);
        assert!(
            (rate2 - printed2).abs() < 1e-9,
            "q2' {rate2} against {printed2}"
        );
        assert!(
            (rate3 - printed3).abs() < 1e-9,
            "q3' {rate3} against {printed3}"
        );
    }
}

/// The disc on a cart (problems/disc-on-cart.json): cart C (mass M, no rotational inertia)
/// slides along n_x (x); disc D (m, R, I = m R²/2) at s along the cart, h above its top,
/// turned θ; it rolls at U, so ṡ + R θ̇ = 0 and h = R; the contact force is asked for.
#[test]
fn the_matrix_of_the_dependent_rates_keeps_one_letter_that_names_no_body() {
    let text = markdown("disc-on-cart.json");
    let step5 = section(&text, "## Step 5", "## Step 6");
    // The relations are written out, ḣ = 0 and θ̇ = −ṡ/R: no matrix is named for them, and
    // the cart's letter C names nothing else.
    assert!(!step5.contains("\\dot{q}_D = "), "{step5}");
    assert!(!step5.contains("\\ddot{q}_D = "), "{step5}");
    assert!(
        step5.contains("\\dot{\\theta} &= -\\frac{1}{R} \\dot{s}"),
        "{step5}"
    );
    assert!(!step5.contains("= C\\,"), "{step5}");
    // The cart slides without turning: its partial angular velocity is zero, not "a
    // particle".
    assert!(step5.contains("{}^{N}\\tilde{\\boldsymbol{\\omega}}^{C}_{1} = \\mathbf{0}"));
    assert!(!text.contains("(a particle)"), "{step5}");
}

/// The table's lines of speed `r`: from its heading `u_{r}` to the next speed's.
fn speed_lines(step5: &str, r: usize) -> Vec<&str> {
    let head = format!("| $u_{{{r}}}");
    let mut lines = step5.lines().skip_while(|l| !l.starts_with(&head));
    let first = lines.next().into_iter();
    first
        .chain(lines.take_while(|l| l.starts_with("|  |")))
        .collect()
}

#[test]
fn the_auxiliary_speeds_of_a_contact_force_have_their_partial_velocities_shown() {
    let text = markdown("disc-on-cart.json");
    let step5 = section(&text, "## Step 5", "## Step 6");
    let n_y = latex_unit_vector("N", 1);
    let d_z = latex_unit_vector("D", 2);
    // By hand: u3 lets the no-slip condition ṡ + R θ̇ = 0 give way alone (ẋ = ṡ = ḣ = 0),
    // ṡ + R θ̇ = u3, so θ̇ = u3/R: D* does not move, D turns (1/R) d_z, and D's point at U
    // slides along c_x = n_x relative to the cart.
    let u3 = speed_lines(step5, 3);
    assert_eq!(u3.len(), 2, "{u3:?}");
    assert!(u3[0].contains("u_{3}\\text{, for } F^{U}_{x}"), "{}", u3[0]);
    assert!(u3[0].contains("{}^{N}\\tilde{\\mathbf{v}}^{D^*}_{3} = \\mathbf{0}"));
    assert!(u3[0].contains(&format!(
        "{{}}^{{N}}\\tilde{{\\boldsymbol{{\\omega}}}}^{{D}}_{{3}} = \\frac{{1}}{{R}} {d_z}"
    )));
    // Relative to the cart, in the cart's unit vectors.
    let c_x = latex_unit_vector("C", 0);
    assert!(u3[1].contains(&format!(
        "{{}}^{{C}}\\tilde{{\\mathbf{{v}}}}^{{U}}_{{3}} = {c_x}"
    )));
    // u4 lets h grow alone: D moves n_y, without turning, and so does its point at U,
    // which relative to the cart is written in the cart's c_y.
    let u4 = speed_lines(step5, 4);
    assert_eq!(u4.len(), 2, "{u4:?}");
    let c_y = latex_unit_vector("C", 1);
    assert!(u4[1].contains(&format!(
        "{{}}^{{C}}\\tilde{{\\mathbf{{v}}}}^{{U}}_{{4}} = {c_y}"
    )));
    assert!(u4[0].contains(&format!(
        "{{}}^{{N}}\\tilde{{\\mathbf{{v}}}}^{{D^*}}_{{4}} = {n_y}"
    )));
    assert!(u4[0].contains("{}^{N}\\tilde{\\boldsymbol{\\omega}}^{D}_{4} = \\mathbf{0}"));
    // So F̃3 = n_x · F^U = F^U_x and F̃3* = ω̃3 · τ*_D = (1/R)(−(m R²/2) θ̈) = −(R m/2) θ̈,
    // formed body by body as the independent speeds' are.
    let row3 = section(step5, "**3.", "**4.");
    assert!(row3.contains("\\tilde{F}_{3} = F^{U}_{x}"), "{row3}");
    assert!(row3.contains(
        "\\tilde{\\mathbf{v}}^{D^*}_{3} \\cdot \\mathbf{f}^{*}_{D} + \\tilde{\\boldsymbol{\\omega}}^{D}_{3} \\cdot \\boldsymbol{\\Gamma}^{*}_{D}"
    ));
    assert!(row3.contains("= -\\frac{R m}{2} \\ddot{\\theta}"), "{row3}");
    // F̃4 = n_y · (F^U − m g n_y) and F̃4* = −m ḧ.
    let row4 = section(step5, "**4.", "**5.");
    assert!(row4.contains("\\tilde{F}_{4} = F^{U}_{y} - m g"), "{row4}");
    assert!(row4.contains("= -m \\ddot{h}"), "{row4}");
}

#[test]
fn kanes_formula_names_its_point_by_a_letter_the_problem_does_not_use() {
    // The double pendulum's pin is P, the rolling coin's contact point is printed P; the
    // coin's radius is R, so its force letter is f (see kane_four_bar.rs).
    for (name, force) in [
        ("double-pendulum-rods.json", "R"),
        ("rolling-coin.json", "f"),
    ] {
        let text = markdown(name);
        assert!(
            text.contains(&format!(
                "with $\\mathbf{{{force}}}_Q$ a force applied at the point $Q$"
            )),
            "{name}"
        );
        assert!(!text.contains("applied at the point $P$"), "{name}");
        assert!(
            text.contains(&format!(
                "\\mathbf{{v}}^{{Q}}_r \\cdot \\mathbf{{{force}}}_{{Q}}"
            )),
            "{name}"
        );
    }
}

#[test]
fn kanes_system_of_nine_unknowns_is_its_rows_not_a_pattern_of_dots() {
    let text = markdown("rolling-coin.json");
    let step5 = section(&text, "## Step 5", "## Step 6");
    assert!(!step5.contains("\\bullet"), "{step5}");
    assert!(step5.contains("The 9 rows are linear in the 9 unknowns."));
    assert!(!step5.contains("minus the rest"), "{step5}");
    // Said once: the solution in numbers names the rows without a reaction, solved first,
    // and the rows that then give the reactions; no sentence before it says so again.
    assert!(
        step5.contains("At the initial state of step 1, rows (1), (2), (3), (7), (8) and (9), which hold no reaction, give"),
        "{step5}"
    );
    assert!(
        step5.contains("with these, rows (4), (5) and (6) give"),
        "{step5}"
    );
    assert!(!step5.contains("contain no reaction"), "{step5}");
    assert!(!step5.contains("solved with the numbers"), "{step5}");
}

#[test]
fn the_rolling_coins_no_slip_rows_come_from_the_contact_points_velocity() {
    let text = markdown("rolling-coin.json");
    let step1 = section(&text, "## Step 1", "## Step 2");
    let display = section(step1, "Rolling without slipping", "| Constraint");
    let a_z = latex_unit_vector("A", 2);
    // By hand: A, the lean frame after ψ about n_z and θ about the new x, has the axle a_y;
    // the contact point lies down the disc's plane, r = −R a_z, whatever the spin φ (in D,
    // turned φ about a_y, it would be R s_φ d_x − R c_φ d_z).
    assert!(display.contains(&format!("\\mathbf{{r}}^{{D^* P}} &= -R {a_z}")));
    assert!(display.contains(
        "{}^{N}\\mathbf{v}^{P} &= {}^{N}\\mathbf{v}^{D^*} + {}^{N}\\boldsymbol{\\omega}^{D} \\times \\mathbf{r}^{D^* P}"
    ));
    // ω = ψ' n_z + θ' e_x + φ' e_y; with e_x = (c_ψ, s_ψ, 0), e_z = (s_ψ s_θ, −c_ψ s_θ, c_θ)
    // in N, ω × r = −R (ψ' n_z × e_z − θ' e_y + φ' e_x): along n_x
    // −R (ψ' s_θ c_ψ + θ' s_ψ c_θ + φ' c_ψ), along n_z R θ' s_θ; with v^{D*} = (x', y', z').
    assert!(display.contains(&format!(
        "(\\dot{{x}} - R \\dot{{\\phi}} c_{{\\psi}} - R \\dot{{\\psi}} s_{{\\theta}} c_{{\\psi}} - R \\dot{{\\theta}} s_{{\\psi}} c_{{\\theta}}) {}",
        latex_unit_vector("N", 0)
    )));
    assert!(display.contains(&format!(
        "(\\dot{{z}} + R \\dot{{\\theta}} s_{{\\theta}}) {} = \\mathbf{{0}}",
        latex_unit_vector("N", 2)
    )));
}

#[test]
fn a_contact_that_may_slide_is_not_said_to_roll_without_slipping() {
    // The bowling ball slides at the start (v0 ≠ R ω0): its no-slip row does not hold yet,
    // so no vector equation says that its contact point is at rest.
    let text = markdown("bowling-ball.json");
    let step1 = section(&text, "## Step 1", "## Step 2");
    assert!(!step1.contains("Rolling without slipping"), "{step1}");
    // The disc on the cart rolls throughout: its contact point's equation is there.
    let text = markdown("disc-on-cart.json");
    assert!(section(&text, "## Step 1", "## Step 2").contains("Rolling without slipping"));
}
