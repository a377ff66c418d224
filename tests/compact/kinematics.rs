//! Step 4 of the handouts: velocities and accelerations by name, from the pins, built on the parent's.

use super::*;

#[test]
fn a_chain_link_moves_with_its_pin_and_the_pin_with_the_one_before() {
    let markdown = explain("validation/ten-link-chain", "markdown");
    // By hand: link6 hangs along -y of its frame from its joint P6, P7 a length L further,
    // so r^{P6P7} = -L ŷ6 and, with ω6 = (q̇1 + … + q̇6) ẑ, ω6 × r = L (q̇1 + … + q̇6) x̂6;
    // from P7 to link7* is -(L/2) ŷ7, so ω7 × r = (L/2)(q̇1 + … + q̇7) x̂7. The pin's
    // acceleration adds α6 × r = L (q̈1 + … + q̈6) x̂6 and -ω6² r = L (q̇1 + … + q̇6)² ŷ6.
    for expected in [
        "{}^{N}\\mathbf{v}^{P_{7}} = {}^{N}\\mathbf{v}^{P_{6}} + L (\\dot{q}_{1} + \\cdots + \\dot{q}_{6}) \\hat{\\mathbf{x}}_{\\mathrm{link}_{6}}",
        "{}^{N}\\mathbf{a}^{P_{7}} = {}^{N}\\mathbf{a}^{P_{6}} + L (\\ddot{q}_{1} + \\cdots + \\ddot{q}_{6}) \\hat{\\mathbf{x}}_{\\mathrm{link}_{6}} + L (\\dot{q}_{1} + \\cdots + \\dot{q}_{6})^{2} \\hat{\\mathbf{y}}_{\\mathrm{link}_{6}}",
        "{}^{N}\\mathbf{v}^{\\mathrm{link}_{7}^*} = {}^{N}\\mathbf{v}^{P_{7}} + \\frac{L}{2} (\\dot{q}_{1} + \\cdots + \\dot{q}_{7}) \\hat{\\mathbf{x}}_{\\mathrm{link}_{7}}",
    ] {
        assert!(
            markdown.lines().any(|l| l.trim() == expected),
            "no line reads {expected}"
        );
    }
    // The free body of all ten links lists gravity once, for a link k, all of mass m: -m g n̂_y.
    assert!(markdown.contains(
        "| weight of each body k | $-m\\, g \\hat{\\mathbf{n}}_{y}$ | $\\text{at } k^*,\\; k \\in \\{\\mathrm{link}_{1}, "
    ));
    // link1 belongs to that free body only, so no row names it alone.
    assert!(!markdown.contains("gravity on link1 |"));
    assert!(!markdown.contains("inertia force of link1 |"));
}

#[test]
fn a_spherical_link_turns_with_its_parent_by_name() {
    let markdown = explain("validation/spherical-chain-3", "markdown");
    // B3 is B2 turned by q7 about x, q8 about the new y, q9 about the final z. Along b̂3z, by
    // hand: x̂2 · b̂3z = sin q8, ŷ2 · b̂3z = -sin q7 cos q8, ẑ2 · b̂3z = cos q7 cos q8, and the
    // rates add q̇7 sin q8 + q̇9.
    assert!(defines(
        &markdown,
        "\\omega^{B_{3}}_{z} = \\dot{q}_{9} + \\dot{q}_{7} s_{8} + \\omega^{B_{2}}_{x} s_{8} - \\omega^{B_{2}}_{y} s_{7} c_{8} + \\omega^{B_{2}}_{z} c_{7} c_{8}",
        "components of the angular velocity of B3:"
    ));
    // Step 4 writes the vector by those names.
    assert!(markdown.contains(
        "{}^{N}\\boldsymbol{\\omega}^{B_{3}} = \\omega^{B_{3}}_{x} \\hat{\\mathbf{b}}_{3,x} + \\omega^{B_{3}}_{y} \\hat{\\mathbf{b}}_{3,y} + \\omega^{B_{3}}_{z} \\hat{\\mathbf{b}}_{3,z}"
    ));
    // The mass centre's velocity is Σ v_r q̇_r with the partial velocities of its acceleration,
    // the positive terms first. B3* is at b3 b̂3y − (L3/2) b̂3z from its joint, so along b̂3x
    // q̇9 (about b̂3z) moves it by −b3 q̇9 and q̇8 (about c9 b̂3y + s9 b̂3x) by −(L3/2) q̇8 c9.
    assert!(markdown
        .contains("{}^{N}\\mathbf{v}^{B_{3}^*} = \\left(\\dot{q}_{1} v^{B_{3}^{*}}_{q_{1},x} + "));
    assert!(markdown.contains(
        " - b_{3} \\dot{q}_{9} - \\frac{L_{3} \\dot{q}_{8} c_{9}}{2}\\right) \\hat{\\mathbf{b}}_{3,x}"
    ));
}

#[test]
fn a_spherical_links_acceleration_is_built_on_its_joint_points() {
    let markdown = explain("validation/spherical-chain-3", "markdown");
    // B2* is at r' = a2 b̂2x + b2 b̂2y − (L2/2) b̂2z from the joint S2. By hand, along b̂2z:
    // the joint point's acceleration carried in (ẑ2 in B1's unit vectors is s5, −s4 c5,
    // c4 c5 for the x-y-z angles q4, q5, q6), (α̃ × r')_z = b2 α̃x − a2 α̃y, and
    // (ω × (ω × r'))_z = a2 ωx ωz + b2 ωy ωz + (L2/2)(ωx² + ωy²).
    assert!(markdown.contains(
        "$\\tilde{a}^{B_{2}^{*}}_{z} = \\frac{L_{2} {\\omega^{B_{2}}_{x}}^{2}}{2} + \\frac{L_{2} {\\omega^{B_{2}}_{y}}^{2}}{2} - a_{2} \\tilde{\\alpha}^{B_{2}}_{y} + b_{2} \\tilde{\\alpha}^{B_{2}}_{x} + \\tilde{a}^{S_{2}}_{x} s_{5} + a_{2} \\omega^{B_{2}}_{x} \\omega^{B_{2}}_{z} + b_{2} \\omega^{B_{2}}_{y} \\omega^{B_{2}}_{z} - \\tilde{a}^{S_{2}}_{y} s_{4} c_{5} + \\tilde{a}^{S_{2}}_{z} c_{4} c_{5}$"
    ));
    // The joint point's is the parent's mass centre's and the parent's turning across to it.
    assert!(markdown.contains("$\\tilde{a}^{S_{2}}_{x} = \\tilde{a}^{B_{1}^{*}}_{x} + "));
}

#[test]
fn a_planar_chain_is_computed_by_names_and_printed_whole() {
    use mbd_tutor::equations::Method;
    use mbd_tutor::numeric::Compiled;
    use mbd_tutor::pipeline::{derive, Purpose};
    let chain = mbd_tutor::problem::load_file(&problem("validation/ten-link-chain")).unwrap();
    let q: Vec<f64> = (0..10).map(|i| 0.3 - 0.17 * f64::from(i)).collect();
    let rates: Vec<f64> = (0..10).map(|i| 0.5 - 0.11 * f64::from(i)).collect();
    for method in Method::ALL {
        // For numbers, the outer links' accelerations have named parts built on the parent's
        // (unless whole is smaller); the handout writes them whole. The q'' are the same to
        // rounding, and the program no larger.
        let numeric = Compiled::new(&derive(&chain, method, Purpose::Numbers).unwrap());
        let handout = Compiled::new(&derive(&chain, method, Purpose::Handout).unwrap());
        let (a, b) = (
            numeric.motion(0.0, &q, &rates).unwrap(),
            handout.motion(0.0, &q, &rates).unwrap(),
        );
        for (x, y) in a.accelerations.iter().zip(&b.accelerations) {
            assert!(
                (x - y).abs() <= 1e-9 * (1.0 + y.abs()),
                "{method:?}: {x} and {y}"
            );
        }
        assert!(
            numeric.operation_count() <= handout.operation_count(),
            "{method:?}: {} operations, the handout's {}",
            numeric.operation_count(),
            handout.operation_count()
        );
    }
    let markdown = explain("validation/ten-link-chain", "markdown");
    assert!(!markdown.contains("\\tilde{a}"));
}

#[test]
fn a_partial_angular_velocity_the_same_for_several_speeds_is_written_once() {
    let markdown = explain("validation/spherical-chain-3", "markdown");
    // For a speed of B1's joint, B3's partial angular velocity is B2's carried across the
    // joint of B3: along b̂3z, by hand, ω^{B2}_r · b̂3z with b̂3z = s8 x̂2 - s7 c8 ŷ2 + c7 c8 ẑ2
    // (x-y-z angles q7, q8, q9). Written once, with the speeds it holds for.
    assert!(defines(
        &markdown,
        "\\omega^{B_{3}}_{r,z} = \\omega^{B_{2}}_{r,x} s_{8} - \\omega^{B_{2}}_{r,y} s_{7} c_{8} + \\omega^{B_{2}}_{r,z} c_{7} c_{8} \\quad (r = q_{1}, q_{2})",
        "partial angular velocities of B3:"
    ));
    assert!(!markdown.contains("\\omega^{B_{3}}_{q_{1},z} ="));
}

#[test]
fn the_bicycles_front_wheel_lean_is_named_once() {
    let markdown = explain("validation/whipple-bicycle", "markdown");
    // By hand: the front wheel's centre sits r_F above its contact along the part of the
    // ground normal in the wheel's plane, n − (n·f̂_y) f̂_y, of length
    // √(C₃₁² + C₃₃²) (the cosines of N.z with F.x and F.z): named σ_F, the contact's
    // height term is r_F σ_F, and the root is written once, in its definition.
    assert!(markdown
        .contains("- $\\sigma_{F} = \\sqrt{{{}^{N}C^{F}_{31}}^{2} + {{}^{N}C^{F}_{33}}^{2}}$"));
    assert!(markdown.contains("- r_{F} \\sigma_{F} + "));
    // The contact's arm from the wheel's centre along f̂_z: r_F C₃₃/σ_F.
    assert!(markdown.contains("\\frac{r_{F} {}^{N}C^{F}_{33}}{\\sigma_{F}} \\hat{\\mathbf{f}}_{z}"));
    assert_eq!(markdown.matches("\\sqrt").count(), 1);
}

#[test]
fn a_long_chain_of_rotations_is_composed_by_name() {
    let markdown = explain("validation/all-joints-3d", "markdown");
    // By hand, E on a z-x-y spherical joint: ᴰC^E = R_z(qE1) R_x(qE2) R_y(qE3), whose first
    // entry is c₁c₃ − s₁s₂s₃; and ᴺC^E = ᴺC^D ᴰC^E entry by entry, three products of names
    // (ᴺC^D₁₂ = −sin(qA + qC) cos qD1 and ᴰC^E₃₁ = −sin qE3 cos qE2, one term each, unnamed).
    assert!(defines(
        &markdown,
        "{}^{D}C^{E}_{11} = \\cos(q_{E1}) \\cos(q_{E3}) - \\sin(q_{E1}) \\sin(q_{E2}) \\sin(q_{E3})",
        "direction cosines:"
    ));
    assert!(defines(
        &markdown,
        "{}^{N}C^{E}_{11} = {}^{D}C^{E}_{11} {}^{N}C^{D}_{11} - {}^{D}C^{E}_{21} \\sin(q_{A} + q_{C}) \\cos(q_{D1}) - {}^{N}C^{D}_{13} \\sin(q_{E3}) \\cos(q_{E2})",
        "direction cosines:"
    ));
    // Step 2's forces on E use its partial angular velocities; for qA and qC, both turns
    // about parallel z axes, they are the same and written once, for r = qA, qC.
    assert!(markdown
        .lines()
        .any(|l| l.starts_with("- partial angular velocities of E:")
            && l.contains("\\omega^{E}_{r,y} =")
            && l.contains("\\quad (r = q_{A}, q_{C})$")));
    // B slides along A.x without turning: B's cosines are A's, named once as ᴬC^E.
    assert!(markdown.contains("{}^{A}C^{E}_{31}"));
    assert!(!markdown.contains("{}^{B}C^{E}"));
}

#[test]
fn an_acceleration_that_cancels_prints_as_zero() {
    // Upright and running straight, the Whipple bicycle is in steady motion: by symmetry
    // every q'' is zero (Meijaard et al. 2007 linearize about this state). Evaluated, the
    // sums cancel to about 1e-15; the handout prints 0, not the rounding error.
    let markdown = explain("validation/whipple-bicycle", "markdown");
    let values: Vec<&str> = markdown
        .lines()
        .skip_while(|l| !l.starts_with("At the initial state"))
        .filter(|l| l.starts_with("| $\\ddot"))
        .map(|l| l.split(" | ").nth(1).expect("a value").trim())
        .collect();
    assert_eq!(values.len(), 9);
    assert!(values.iter().all(|v| *v == "0"), "{values:?}");
}

#[test]
fn two_rates_that_turn_together_are_squared_as_one() {
    // Link C of the all-joints mechanism turns about ĉ_z at q̇_A + q̇_C (the turntable's
    // rate plus its own), its centre L/2 along ĉ_x from the slider: by hand, the centre's
    // centripetal acceleration is −(L/2)(q̇_A + q̇_C)² ĉ_x, not the square multiplied out.
    let markdown = crate::support::explain(
        "validation/all-joints-3d",
        &["--method", "newton-euler", "--format", "markdown"],
    );
    let step4 = &markdown[markdown.find("## Step 4").expect("step 4")..];
    assert!(step4.contains(
        "{}^{N}\\mathbf{a}^{C^*} = {}^{N}\\mathbf{a}^{B^*} + \\ddot{s}_{C} \\hat{\\mathbf{b}}_{z} - \\frac{L}{2} (\\dot{q}_{A} + \\dot{q}_{C})^{2} \\hat{\\mathbf{c}}_{x}"
    ));
    assert!(!markdown.contains("\\dot{q}_{A}^{2} + \\dot{q}_{C}^{2} + 2 \\dot{q}_{A} \\dot{q}_{C}"));
    // Step 5 collects a row's rates the same way: D hangs from C, so D's rows hold the
    // square of C's rate, (…)(q̇_A + q̇_C)², beside q̇_D1² and the other products.
    let step5 = &markdown[markdown.find("## Step 5").expect("step 5")..];
    assert!(step5.contains("(\\dot{q}_{A} + \\dot{q}_{C})^{2} + "));
    // A "where" list's definition keeps its terms, the square of C's rate written as one:
    // the joint point K's acceleration without the q'' along D's x axis.
    let definition = step4
        .lines()
        .find(|l| l.contains("\\tilde{a}^{K}_{x} = "))
        .expect("K's acceleration");
    assert!(definition.contains(
        "+ \\frac{L \\sin(q_{D2}) \\cos^{2}(q_{D1}) \\cos(q_{D2})}{2} (\\dot{q}_{A} + \\dot{q}_{C})^{2}"
    ));
}

#[test]
fn a_damper_on_a_long_chain_grows_at_the_ends_relative_velocity_along_its_unit_vector() {
    // The air damper of all-joints-3d runs from N.o to the tip of the pendulum E, five
    // joints out: ℓ̇ = û · (ᴺv^tip − ᴺv^{N.o}), three products once the relative velocity's
    // components (in frame E, as û's) are named. Multiplied out it was 56 terms.
    let markdown = explain("validation/all-joints-3d", "markdown");
    assert!(defines(
        &markdown,
        "\\dot{\\ell}_{2} = \\Delta v_{2x} \\hat{u}_{2x} + \\Delta v_{2y} \\hat{u}_{2y} + \\Delta v_{2z} \\hat{u}_{2z}",
        "rate at which the distance from N.o to tip grows"
    ));
    assert!(markdown.lines().any(|l| l.starts_with("- ")
        && l.contains("of the velocity of tip relative to N.o")
        && l.contains("$\\Delta v_{2x} = ")));
    // A spring between a body and the ground keeps its short rate written out.
    let plate = explain("plate-on-two-springs", "markdown");
    assert!(!plate.contains("\\Delta v_{"));
}

#[test]
fn a_long_acceleration_is_written_by_the_partial_velocities() {
    let markdown = explain("validation/whipple-bicycle", "markdown");
    // B* moves as v^{B*} = Σ_r v^{B*}_r q̇_r (the rates' coefficients), so by the rule of
    // differentiation a^{B*} = Σ_r v^{B*}_r q̈_r + ã^{B*}: the q̈ have the velocity's
    // coefficients, and only the rest, ã, is new, named component by component in B.
    let rule = "{}^{N}\\mathbf{a}^{B^*} = \\sum_{r} {}^{N}\\mathbf{v}^{B^*}_{r}\\, \\ddot{q}_{r} + \\tilde{a}^{B^{*}}_{x} \\hat{\\mathbf{b}}_{x} + \\tilde{a}^{B^{*}}_{y} \\hat{\\mathbf{b}}_{y} + \\tilde{a}^{B^{*}}_{z} \\hat{\\mathbf{b}}_{z}";
    assert!(markdown.contains(rule), "no {rule}");
    assert!(markdown.contains("{}^{N}\\mathbf{v}^{B^*} = (\\dot{\\psi} v^{B^{*}}_{\\psi,x}"));
    // The where list says once what v_r is.
    assert_eq!(
        markdown
            .matches("- ${}^{N}\\mathbf{v}^{P}_{r} = \\partial\\, {}^{N}\\mathbf{v}^{P} / \\partial \\dot{q}_{r}$: the partial velocities of each mass centre and joint point")
            .count(),
        1
    );
    // The head's acceleration is long written out; its rest, ã^{head}, is named in the
    // where list (B's steer joint point), so step 4 writes it by the same rule.
    // The point named by the word head is printed by a letter, P.
    let head = "{}^{N}\\mathbf{a}^{P} = \\sum_{r} {}^{N}\\mathbf{v}^{P}_{r}\\, \\ddot{q}_{r} + \\tilde{a}^{P}_{x} \\hat{\\mathbf{b}}_{x}";
    assert!(markdown.contains(head), "no {head}");
}

#[test]
fn the_double_pendulums_second_rod_moves_with_its_pin() {
    let markdown = explain("double-pendulum-rods", "markdown");
    // By hand: the pin P is L1 along -â_y from O, so v^P = ω^A × r^{OP} = L1 q̇1 â_x and
    // a^P = L1 q̈1 â_x + L1 q̇1² â_y; B* is L2/2 along -b̂_y from P, so
    // v^{B*} = v^P + (L2/2)(q̇1 + q̇2) b̂_x, never v^{A*} + … .
    let pin = "{}^{N}\\mathbf{v}^{P} = L_{1} \\dot{q}_{1} \\hat{\\mathbf{a}}_{x}, \\qquad {}^{N}\\mathbf{a}^{P} = L_{1} \\ddot{q}_{1} \\hat{\\mathbf{a}}_{x} + L_{1} \\dot{q}_{1}^{2} \\hat{\\mathbf{a}}_{y}";
    let center = "{}^{N}\\mathbf{v}^{B^*} = {}^{N}\\mathbf{v}^{P} + \\frac{L_{2}}{2} (\\dot{q}_{1} + \\dot{q}_{2}) \\hat{\\mathbf{b}}_{x}";
    for expected in [pin, center] {
        assert!(
            markdown.lines().any(|l| l.trim() == expected),
            "no line reads {expected}"
        );
    }
    assert!(!markdown.contains("\\mathbf{v}^{B^*} = {}^{N}\\mathbf{v}^{A^*}"));
}
