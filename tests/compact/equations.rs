//! Steps 2, 3 and 5 of the handouts: rows, A x = b and the handout's size, each against a hand derivation.

use super::*;

#[test]
fn a_plate_on_two_springs_gives_a_small_handout_written_with_the_lengths() {
    let tex = explain("plate-on-two-springs", "latex");
    // Multiplied out, the spring lengths made this handout 6.5 MB with a 2 MB line.
    assert!(tex.len() < 80_000, "{} bytes", tex.len());
    let longest = tex.lines().map(str::len).max().unwrap_or(0);
    assert!(longest < 2_500, "a line of {longest} characters");
    assert!(tex.contains("\\ell_{1}") && tex.contains("\\hat{u}_{2y}"));
    // The definitions are listed once, next to the free bodies.
    assert_eq!(
        tex.matches("\\ell_{1} = \\sqrt{\\Delta_{1x}^{2} + \\Delta_{1y}^{2}}")
            .count(),
        1
    );
    let markdown = explain("plate-on-two-springs", "markdown");
    let equations = simplified_equations(&markdown);
    // F along n_x by hand: m x'' = -k1 (ℓ1 - l1) u1x - k2 (ℓ2 - l2) u2x.
    assert_eq!(
        equations[0],
        "-m \\ddot{x} - k_{1} \\hat{u}_{1x} (\\ell_{1} - l_{1}) - k_{2} \\hat{u}_{2x} (\\ell_{2} - l_{2})"
    );
    assert!(defines(
        &markdown,
        "\\Delta_{1x} = d + x - a c_{\\theta} - b s_{\\theta}",
        "of the vector from"
    ));
    if crate::support::pdflatex_present("the handout") {
        let dir = std::env::temp_dir().join(format!("mbd-tutor-compact-{}", std::process::id()));
        let count = pages(&dir, &tex);
        assert!((1..=12).contains(&count), "{count} pages");
    }
}

#[test]
fn the_plate_on_two_springs_accelerates_as_a_hand_calculation_says() {
    // At the initial state: x = 0.05, y = 0, theta = 0.2; corners (-+a, b) in the plate's
    // axes, anchors (-+d, e). Force on a corner k (ℓ - l0) û toward its anchor; moment
    // about the center r × F.
    let (m, inertia, a, b, d, e, g) = (2.0, 0.05, 0.25, 0.1, 0.5, 0.8, 9.81);
    let (x, y, theta): (f64, f64, f64) = (0.05, 0.0, 0.2);
    let (s, c) = theta.sin_cos();
    let mut force = [0.0, -m * g];
    let mut moment = 0.0;
    for (sign, k, l0) in [(-1.0, 150.0, 0.4), (1.0, 120.0, 0.45)] {
        let r = [sign * a * c - b * s, sign * a * s + b * c];
        let corner = [x + r[0], y + r[1]];
        let to_anchor = [sign * d - corner[0], e - corner[1]];
        let length = (to_anchor[0].powi(2) + to_anchor[1].powi(2)).sqrt();
        let f = [
            k * (length - l0) * to_anchor[0] / length,
            k * (length - l0) * to_anchor[1] / length,
        ];
        force[0] += f[0];
        force[1] += f[1];
        moment += r[0] * f[1] - r[1] * f[0];
    }
    let expected = [force[0] / m, force[1] / m, moment / inertia];
    for solution in solve_all("plate-on-two-springs", &[]) {
        for (name, want) in ["x", "y", "theta"].iter().zip(expected) {
            let got = solution.acc(name);
            assert!(
                (got - want).abs() < 1e-9 * want.abs().max(1.0),
                "{}: {name}'' = {got}, by hand {want}",
                solution.method
            );
        }
    }
}

#[test]
fn a_wall_spring_reads_as_minus_k_x() {
    let equations = simplified_equations(&explain("two-mass-spring-damper", "markdown"));
    // Cart A by hand: m1 x1'' = -k1 x1 - c1 x1' + k2 (x2 - x1) + c2 (x2' - x1'), collected
    // by x1'', then the rates, then the coordinates.
    assert_eq!(
        equations[0],
        "-m_{1} \\ddot{x}_{1} - (c_{1} + c_{2}) \\dot{x}_{1} + c_{2} \\dot{x}_{2} - (k_{1} + k_{2}) x_{1} + k_{2} x_{2}"
    );
}

#[test]
fn indices_are_sorted_as_a_reader_counts() {
    let markdown = explain("validation/ten-link-chain", "markdown");
    // By hand: the last link turns at the sum of all ten relative rates, q1' to q10', a run
    // a textbook writes by its ends; the third at q1' + q2' + q3', written out. Each with its
    // angular acceleration on the same line, as a textbook sets two short results.
    let alpha = |k: usize, rates: &str| {
        format!("{{}}^{{N}}\\boldsymbol{{\\alpha}}^{{\\mathrm{{link}}_{{{k}}}}} = ({rates}) \\hat{{\\mathbf{{z}}}}_{{\\mathrm{{link}}_{{{k}}}}}")
    };
    for expected in [
        format!("{{}}^{{N}}\\boldsymbol{{\\omega}}^{{\\mathrm{{link}}_{{10}}}} = (\\dot{{q}}_{{1}} + \\cdots + \\dot{{q}}_{{10}}) \\hat{{\\mathbf{{z}}}}_{{\\mathrm{{link}}_{{10}}}}, \\qquad {}", alpha(10, "\\ddot{q}_{1} + \\cdots + \\ddot{q}_{10}")),
        format!("{{}}^{{N}}\\boldsymbol{{\\omega}}^{{\\mathrm{{link}}_{{3}}}} = (\\dot{{q}}_{{1}} + \\dot{{q}}_{{2}} + \\dot{{q}}_{{3}}) \\hat{{\\mathbf{{z}}}}_{{\\mathrm{{link}}_{{3}}}}, \\qquad {}", alpha(3, "\\ddot{q}_{1} + \\ddot{q}_{2} + \\ddot{q}_{3}")),
    ] {
        assert!(
            markdown.lines().any(|l| l.trim() == expected),
            "no line reads {expected}"
        );
    }
    assert!(!markdown.contains("q_{1} + q_{10}"));
    // Too large to print every entry as a formula, A and b are one table of their values at
    // the initial state. By hand: the last link about its joint is a rod about its end,
    // A_{10,10} = -m L²/3 = -1/12 (m = 1, L = 0.5); and A is symmetric, each row the moment
    // of the links outboard of a joint (the chain's mass matrix, negated).
    let a = value_table(&markdown);
    assert_eq!((a.len(), a[0].len()), (10, 11));
    assert!((a[9][9] + 1.0 / 12.0).abs() < 1e-6, "A_10,10 = {}", a[9][9]);
    for (i, row) in a.iter().enumerate() {
        for (j, x) in row.iter().enumerate().take(i) {
            let mirror = a[j][i];
            assert!(
                (x - mirror).abs() <= 1e-5 * x.abs().max(1e-3),
                "A_{i},{j} = {x} but A_{j},{i} = {mirror}"
            );
        }
    }
    // With A and b by value, the abbreviations listed are only those still printed: each
    // appears somewhere besides its definition.
    let line = markdown
        .lines()
        .find(|l| l.starts_with("Abbreviations:"))
        .expect("abbreviations");
    let others = markdown.replacen(line, "", 1);
    for definition in line.split("$, $") {
        let name = definition.trim_start_matches("Abbreviations: $");
        let name = name.split(" = ").next().expect("a name");
        assert!(others.contains(name), "{name} is listed but not used");
    }
    assert!(!line.contains("s_{23}"));
    // In the five-link chain, s_{23} = sin(q2 + q3), ...: the sines of sums of coordinates
    // by their indices, a run of five or more by its ends. They are many, so the handout
    // states their rule with the first, the first of a sum and the longest as examples.
    let five = explain("five-link-chain", "markdown");
    // The chain names a damping constant c: its abbreviations are S and C.
    let rule = "Abbreviations: $S$ and $C$ are the sine and cosine of the coordinate their subscript names, or of the sum of the coordinates it lists, as in $S_{1} = \\sin(q_{1})$, $S_{12} = \\sin(q_{1} + q_{2})$, $S_{1\\ldots 5} = \\sin(q_{1} + \\cdots + q_{5})$.";
    assert!(five.lines().any(|l| l == rule), "no line {rule}");
    assert!(
        five.contains("S_{23}"),
        "s_{{23}} follows the rule unlisted"
    );
}

#[test]
fn a_few_abbreviations_are_listed_one_by_one() {
    // The bicycle's ten sines and cosines, each of one angle, are listed whole.
    let markdown = explain("validation/whipple-bicycle", "markdown");
    let line = markdown
        .lines()
        .find(|l| l.starts_with("Abbreviations:"))
        .expect("abbreviations");
    assert!(
        line.starts_with("Abbreviations: $S_{\\psi} = \\sin(\\psi)$, $C_{\\psi} = \\cos(\\psi)$")
    );
    assert_eq!(line.matches(" = ").count(), 10, "{line}");
}

#[test]
fn a_long_equation_is_shown_with_the_matrix_entries_by_name() {
    // A row of A x = b for ten coordinates, every coefficient nonzero: too long to show
    // whole, it is shown by the names of its entries, the first two and the last.
    let ten = explain("validation/ten-link-chain", "markdown");
    let by_name: Vec<String> = simplified_equations(&ten)
        .into_iter()
        .filter(|e| e.starts_with("A_{"))
        .collect();
    assert_eq!(by_name.len(), 10);
    for e in by_name {
        let i = &e[3..e.find(',').unwrap_or(3)];
        let term = |j: usize| format!("A_{{{i},{j}}} \\ddot{{q}}_{{{j}}}");
        let expected = format!("{} + {} + \\cdots + {}", term(1), term(2), term(10));
        assert_eq!(e, format!("{expected} = b_{{{i}}}"));
    }
    assert!(ten.contains("With the coefficients of the matrix form below:"));
    let markdown = explain("five-link-chain", "markdown");
    // Step 5 writes every row out, so no table by name repeats them; the coefficient of
    // q̈₂ in row 1 is read there, by hand with the common factor L²m/6 out:
    // A₁₂ = -(L²m/6)(44 + 21 c₂ + …).
    assert!(!markdown.contains("(2) & A_{1,2} &"));
    assert!(!markdown.contains("$A_{1,2} = "));
    assert!(markdown.contains("- \\frac{L^{2} m}{6} (44 + 21 C_{2} + "));
    // The text's size: the pictures embedded as inline SVG are not equations.
    let mut text = markdown.clone();
    while let (Some(a), Some(b)) = (text.find("<svg"), text.find("</svg>")) {
        if b < a {
            break;
        }
        text.replace_range(a..b + "</svg>".len(), "");
    }
    assert!(text.len() < 80_000, "{} bytes", text.len());
    let tex = explain("five-link-chain", "latex");
    let longest = tex.lines().map(str::len).max().unwrap_or(0);
    assert!(longest < 2_500, "a line of {longest} characters");
}

#[test]
fn the_double_pendulum_reads_as_a_textbook_writes_it() {
    let markdown = explain("double-pendulum-rods", "markdown");
    let equations = simplified_equations(&markdown);
    // Rod B about P, by hand: -(m2 L2²/3)(q1'' + q2'') - m2 (L2/2) L1 (q1'' c2 + q1'² s2)
    // - m2 g (L2/2) s12 = 0, collected by q1'', q2'', then the rates, the common factor
    // -L2 m2/6 of q1'''s coefficient pulled out (the coefficients inside integers), sines
    // and cosines by their abbreviations.
    assert_eq!(
        equations[1],
        "-\\frac{L_{2} m_{2}}{6} (2 L_{2} + 3 L_{1} c_{2}) \\ddot{q}_{1} - \\frac{L_{2}^{2} m_{2}}{3} \\ddot{q}_{2} - \\frac{L_{1} L_{2} m_{2} s_{2}}{2} \\dot{q}_{1}^{2} - \\frac{L_{2} m_{2} g}{2} s_{12}"
    );
    // A + B about O, gravity's moment by hand: -m1 g (L1/2) s1 - m2 g (L1 s1 + (L2/2) s12),
    // the masses of s1's coefficient collected.
    assert!(equations[0].ends_with(
        "- \\frac{L_{1} g}{2} (m_{1} + 2 m_{2}) s_{1} - \\frac{L_{2} m_{2} g}{2} s_{12}"
    ));
    // Both rods along N.y: F^O_y - (m1 + m2) g + …, the masses collected.
    assert!(equations[3].ends_with("- g (m_{1} + m_{2})"));
    // The abbreviations are defined once, at the start of step 2 where steps 2 to 5 begin
    // to use them (this chain has no constraint in step 1), in the order of the
    // coordinates, the sums last.
    let line = "Abbreviations: $s_{1} = \\sin(q_{1})$, $c_{1} = \\cos(q_{1})$, $s_{2} = \\sin(q_{2})$, $c_{2} = \\cos(q_{2})$, $s_{12} = \\sin(q_{1} + q_{2})$, $c_{12} = \\cos(q_{1} + q_{2})$.";
    assert_eq!(markdown.matches(line).count(), 1);
    let step2 = markdown.find("## Step 2").expect("step 2");
    assert!(markdown.find(line).is_some_and(|i| i > step2));
    assert!(!markdown[..step2].contains("c_{1}"));
}

#[test]
fn the_rolling_coin_has_no_root_of_a_square() {
    let markdown = explain("rolling-coin", "markdown");
    // √(cos²θ) = cos θ while the coin stands (cos θ > 0 at the start), as a 1-D spring's
    // |a + x| is shown as a + x; and (sin²φ + cos²φ)² = 1 inside the constraints.
    assert!(!markdown.contains("\\sqrt"), "a square root is left");
    // Step 1's constraints use the abbreviations, listed just before their table.
    assert!(markdown.contains(
        "| $\\text{no penetration at the floor}$ | position | $z - R c_{\\theta} = 0$ |"
    ));
    let abbreviations = markdown.find("Abbreviations: ").expect("abbreviations");
    let table = markdown
        .find("| Constraint | Level | Equation |")
        .expect("constraints");
    let step2 = markdown.find("## Step 2").expect("step 2");
    assert!(abbreviations < table && table < step2);
    // The velocity constraint along N.x, by hand, ẋ = R c_ψ (φ̇ + ψ̇ s_θ) + R θ̇ s_ψ c_θ,
    // differentiated in time, the rates of one coefficient together:
    let expected = "-R c_{\\psi} \\ddot{\\phi} - R s_{\\theta} c_{\\psi} \\ddot{\\psi} - R s_{\\psi} c_{\\theta} \\ddot{\\theta} + \\ddot{x} + R s_{\\psi} s_{\\theta} (\\dot{\\psi}^{2} + \\dot{\\theta}^{2}) + R s_{\\psi} \\dot{\\phi} \\dot{\\psi} - 2 R c_{\\psi} c_{\\theta} \\dot{\\psi} \\dot{\\theta}";
    assert!(simplified_equations(&markdown)
        .iter()
        .any(|e| e == expected));
}

#[test]
fn decimals_the_problem_writes_stay_decimals() {
    let markdown = explain("floating-plate-springs", "markdown");
    // The anchor A1 is written `-0.4*N.x + 1.0*N.y`, the corner C1 `-w/2*plate.x +
    // h/2*plate.y`: by hand Δ1x = x - (w/2) cos θ - (h/2) sin θ + 0.4, the 0.4 as written
    // and the halves as fractions, as written.
    assert!(defines(
        &markdown,
        "\\Delta_{1x} = 0.4 + x - \\frac{h S_{\\theta}}{2} - \\frac{w C_{\\theta}}{2}",
        "of the vector from"
    ));
    assert!(!markdown.contains("\\frac{2}{5}"));
}

#[test]
fn a_long_rolling_constraint_reads_as_the_contact_points_velocity() {
    let markdown = explain("validation/whipple-bicycle", "markdown");
    let point = "{}^{N}\\mathbf{v}^{\\mathrm{front}_{\\mathrm{contact}}}";
    // The front contact's two rolling rows: its velocity along n̂x and along n̂y.
    for axis in ["x", "y"] {
        let row = format!("| ${point} \\cdot \\hat{{\\mathbf{{n}}}}_{{{axis}}} = 0$ |");
        assert!(markdown.contains(&row), "no row {row}");
    }
    // The velocity itself once, as a textbook forms a point of the wheel's: by hand
    // ᴺv^P = ᴺv^{F*} + ᴺω^F × r^{F*P}, the arm r_F long along the ground normal's part in
    // the wheel's plane, (C₃₁ f̂x + C₃₃ f̂z)/σ_F.
    let definition = format!(
        "{point} = {{}}^{{N}}\\mathbf{{v}}^{{F^*}} + {{}}^{{N}}\\boldsymbol{{\\omega}}^{{F}} \\times \\mathbf{{r}}^{{F^* \\mathrm{{front}}_{{\\mathrm{{contact}}}}}}"
    );
    assert_eq!(markdown.matches(&definition).count(), 1, "{definition}");
    let arm = "= \\frac{r_{F} {}^{N}C^{F}_{31}}{\\sigma_{F}} \\hat{\\mathbf{f}}_{x} + \\frac{r_{F} {}^{N}C^{F}_{33}}{\\sigma_{F}} \\hat{\\mathbf{f}}_{z}$";
    assert!(markdown.contains(arm), "no arm {arm}");
}

#[test]
fn rows_written_out_in_step_5_are_not_listed_again_in_the_matrix() {
    let markdown = explain("two-wheeled-cart", "markdown");
    let sentence = "Rows (1)–(11), (13) are written out in full in step 5";
    assert!(markdown.contains(sentence), "no sentence {sentence}");
    let read_off: Vec<usize> = (1..=11).chain([13]).collect();
    // Step 5's heading of row i, and what follows it up to the next row.
    let row = |i: usize| -> &str {
        let start = markdown
            .find(&format!("\n**{i}. "))
            .unwrap_or_else(|| panic!("no row {i} in step 5"));
        let rest = &markdown[start + 1..];
        let end = rest[1..].find("\n**").map_or(rest.len(), |e| e + 1);
        &rest[..end]
    };
    for i in 1..=13 {
        let listed = markdown.contains(&format!("\nRow {i}, "));
        // The system matrix's letter is one the problem leaves free (A or S).
        let by_names = ["A", "S"]
            .iter()
            .any(|a| row(i).contains(&format!("{a}_{{{i},")));
        // A row is listed entry by entry exactly when step 5 writes it with A's names.
        assert_eq!(listed, by_names, "row {i}");
        assert_eq!(listed, !read_off.contains(&i), "row {i}");
    }
}

#[test]
fn a_reaction_acts_at_its_joint_by_name() {
    let markdown = explain("five-link-chain", "markdown");
    // The free body link2 + … + link5 is cut at P2: the reaction of link1 on link2 acts at
    // the pin P2, which is also link2's origin, where an offset would read as 0.
    assert!(markdown.contains(
        "| reaction force at $P_{2}$, of $\\mathrm{link}_{1}$ on $\\mathrm{link}_{2}$ | $F^{P_{2}}_{x} \\hat{\\mathbf{x}}_{\\mathrm{link}_{1}} + F^{P_{2}}_{y} \\hat{\\mathbf{y}}_{\\mathrm{link}_{1}}$ | $\\text{at } P_{2}$ |"
    ));
    assert!(!markdown.contains("$\\text{at } \\mathbf{0}$"));
    // Gravity acts at each link's mass centre, named as such (link5* alone on its own).
    assert!(markdown.contains(
        "| weight of link5 | $-m g \\hat{\\mathbf{n}}_{y}$ | $\\text{at } \\mathrm{link}_{5}^*$ |"
    ));
}

#[test]
fn a_row_formed_already_simplified_is_written_once() {
    let markdown = explain("two-mass-spring-damper", "markdown");
    // Cart A along N.y, by hand: the track's reaction holds its weight, F_y - m1 g = 0, as
    // formed; written once, not again as "simplified", with no words before it.
    let row = "**3. $A\\colon \\sum \\mathbf{F} \\cdot \\hat{\\mathbf{n}}_{y}$**\n\n$$\nF^{\\mathrm{trackA}}_{y} - m_{1} g = 0\n$$\n\n**4.";
    assert!(markdown.contains(row), "row 3 is not written once");
}

#[test]
fn a_group_of_links_is_named_by_its_ends_where_the_pictures_are_not_named() {
    let markdown = explain("validation/ten-link-chain", "markdown");
    // Step 5 heads the row of links 2 to 10 about P2 by the ends of the run, and its free
    // body's forces are given for a link k of {link2, …, link10}.
    assert!(markdown.contains(
        "**2. $\\mathrm{link}_{2} + \\cdots + \\mathrm{link}_{10}\\colon \\sum \\mathbf{M}_{P_{2}} \\cdot \\hat{\\mathbf{n}}_{z}$**"
    ));
    assert!(markdown.contains("k \\in \\{\\mathrm{link}_{2}, \\ldots, \\mathrm{link}_{10}\\}"));
    // The plan's table and step 2's headings name every link: the pictures are named so.
    assert!(markdown.contains(
        "### Free body $\\mathrm{link}_{2} + \\mathrm{link}_{3} + \\mathrm{link}_{4} + "
    ));
    assert!(markdown.contains(
        "| $\\mathrm{link}_{2} + \\mathrm{link}_{3} + \\mathrm{link}_{4} + \\mathrm{link}_{5} + "
    ));
}

#[test]
fn the_latex_handout_states_the_pictures_legend_once() {
    let tex = explain("validation/ten-link-chain", "latex");
    // Ten free-body pictures; the legend once, in step 2's text, not under each of them.
    assert_eq!(tex.matches("\\subsection*{Free body").count(), 10);
    // (Before the heading, a box only measured, for the room kept with it, holds it too.)
    let step2 = tex.find("Step 2. Free bodies").expect("step 2");
    assert_eq!(tex[step2..].matches("Not to scale").count(), 1);
    assert!(tex[..step2].contains("\\setbox\\leadbox"));
    // The SVG pictures keep it: a picture read alone must say what its arrows mean.
    let markdown = explain("validation/ten-link-chain", "markdown");
    assert_eq!(markdown.matches(">Not to scale").count(), 10);
}

#[test]
fn a_right_hand_side_is_collected_by_the_rates() {
    let markdown = explain("five-link-chain", "markdown");
    // Row 1 of the five-link chain as step 5 writes it, collected by the rates: the
    // damper's c q̇₁, then each square of a link's angular velocity with its coefficient's
    // factor L²m/2 out, gravity last.
    assert!(markdown.contains(
        "- c \\dot{q}_{1} - \\frac{L^{2} m}{2} (7 S_{2} + 5 S_{23} + 3 S_{234} + S_{2345}) \\dot{q}_{1}^{2} + "
    ));
    assert!(markdown
        .contains("(\\dot{q}_{1} + \\cdots + \\dot{q}_{5})^{2} - \\frac{9 L m g}{2} S_{1} - "));
}

#[test]
fn a_wide_system_by_value_is_printed_in_blocks_that_solve_to_the_accelerations() {
    let markdown = explain("validation/all-joints-3d", "markdown");
    // 26 unknowns: A in blocks of 9, 9 and 8 columns, b beside the last.
    assert_eq!(
        markdown
            .matches("\\begin{array}{l\\vert ccccccccc}")
            .count(),
        2
    );
    assert!(markdown.contains("\\begin{array}{l\\vert cccccccc\\vert c}"));
    let rows = value_table(&markdown);
    assert_eq!((rows.len(), rows[0].len()), (26, 27));
    // The tables evaluate the handout's formulas; the accelerations printed below them come
    // from the numeric equations. The first fifteen unknowns are the q'' of that table.
    let x = solve_rows(rows);
    let printed: Vec<f64> = markdown
        .lines()
        .skip_while(|l| !l.starts_with("At the initial state"))
        .filter(|l| l.starts_with("| $\\ddot"))
        .map(|l| {
            l.split(" | ")
                .nth(1)
                .expect("a value")
                .trim()
                .parse()
                .expect("a number")
        })
        .collect();
    assert_eq!(printed.len(), 15);
    for (got, want) in x.iter().zip(&printed) {
        assert!(
            (got - want).abs() < 1e-4 * want.abs().max(1.0),
            "{got} vs {want}"
        );
    }
}

#[test]
fn a_moment_about_a_bodys_own_mass_centre_has_no_moment_of_its_inertia_force() {
    // Newton–Euler's row of H's moments about H* along ĥ_y is long enough to be formed in
    // vector form; about H* itself, the arm of −m_H a^{H*} is zero, so only the inertia
    // torque is subtracted: ĥ_y · (Σ M_{H*} − (I·α + ω × I·ω)) = 0.
    let markdown =
        crate::support::explain("validation/whipple-bicycle", &["--method", "newton-euler"]);
    let row = "\\hat{\\mathbf{h}}_{y} \\cdot \\left( \\sum \\mathbf{M}_{H^{*}} - ( \\mathbf{I}^{H} \\cdot \\boldsymbol{\\alpha}^{H} + \\boldsymbol{\\omega}^{H} \\times \\mathbf{I}^{H} \\cdot \\boldsymbol{\\omega}^{H} ) \\right) = 0";
    assert!(markdown.contains(row), "no {row}");
    assert!(!markdown.contains("\\mathbf{r}^{H^{*} H^*}"));
}
