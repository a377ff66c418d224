//! Compact equations: a spring's length, unit vector and rate are named once, so that the
//! handout stays small enough to read and to compile, and the numbers do not change.

use crate::support::{problem, solve_all};
use std::path::Path;
use std::process::{Command, Stdio};

/// `mbd-tutor explain NAME --format FORMAT` on standard output.
fn explain(name: &str, format: &str) -> String {
    crate::support::explain(name, &["--format", format])
}

/// Whether a "where" list of the Markdown solution defines `definition` (LaTeX, without
/// `$`) with a note containing `note`: on an entry of its own (`- $d$: note`) or among the
/// entries of one kind (`- note: $d$; $e$`).
fn defines(markdown: &str, definition: &str, note: &str) -> bool {
    let math = format!("${definition}$");
    markdown
        .lines()
        .any(|l| l.starts_with("- ") && l.contains(&math) && l.contains(note))
}

/// The rows of `A` and `b` by value in a Markdown solution, each row's numbers, `A`'s then
/// `b`'s: the tables of blocks of columns side by side, each row found by its label `(i)`;
/// a row a block leaves out is zero in all its columns.
fn value_table(markdown: &str) -> Vec<Vec<f64>> {
    let mut rows: Vec<Vec<f64>> = Vec::new();
    for table in markdown.lines().filter(|l| l.starts_with("\\begin{array}")) {
        let (head, body) = table.split_once("\\hline").expect("a header");
        let columns = head.matches(" & ").count();
        let width = rows.first().map_or(0, Vec::len);
        for row in body
            .trim_end_matches("\\end{array}")
            .split("\\\\")
            .filter(|row| !row.trim().is_empty())
        {
            let mut cells = row.split(" & ");
            let label = cells.next().expect("a label").trim();
            let i: usize = label
                .trim_start_matches('(')
                .trim_end_matches(')')
                .parse()
                .unwrap_or_else(|_| panic!("a row label: {label}"));
            if rows.len() < i {
                rows.resize(i, vec![0.0; width]);
            }
            let values: Vec<f64> = cells
                .map(|x| x.trim().parse().unwrap_or_else(|_| panic!("a number: {x}")))
                .collect();
            assert_eq!(values.len(), columns, "row {i}");
            rows[i - 1].truncate(width);
            rows[i - 1].resize(width, 0.0);
            rows[i - 1].extend(values);
        }
        for row in &mut rows {
            row.resize(width + columns, 0.0);
        }
    }
    assert!(!rows.is_empty(), "no table of A and b");
    rows
}

/// The solution of `A x = b`, `rows` being `[A | b]`, by Gaussian elimination with partial
/// pivoting.
fn solve_rows(mut rows: Vec<Vec<f64>>) -> Vec<f64> {
    let n = rows.len();
    for k in 0..n {
        let pivot = (k..n)
            .max_by(|&i, &j| rows[i][k].abs().total_cmp(&rows[j][k].abs()))
            .expect("a row");
        rows.swap(k, pivot);
        for i in k + 1..n {
            let factor = rows[i][k] / rows[k][k];
            let pivot_row = rows[k].clone();
            rows[i]
                .iter_mut()
                .zip(&pivot_row)
                .for_each(|(x, p)| *x -= factor * p);
        }
    }
    let mut x = vec![0.0; n];
    for k in (0..n).rev() {
        let known: f64 = (k + 1..n).map(|j| rows[k][j] * x[j]).sum();
        x[k] = (rows[k][n] - known) / rows[k][k];
    }
    x
}

/// The simplified equations (step 5) of a Markdown solution, one per entry, without `= 0`
/// (a row formed already simplified is written once).
fn simplified_equations(markdown: &str) -> Vec<String> {
    let lines: Vec<&str> = markdown.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let introduced = [
            "Simplified",
            "With the coefficients",
            "As formed, already simplified",
        ];
        if introduced.iter().any(|s| line.starts_with(s)) {
            let body = lines[i + 1..]
                .iter()
                .skip_while(|l| l.trim() == "$$" || l.trim().is_empty())
                .take_while(|l| l.trim() != "$$")
                .copied()
                .collect::<Vec<_>>()
                .join(" ");
            out.push(body.trim().trim_end_matches("= 0").trim().to_string());
        }
    }
    out
}

/// Whether pdflatex is here; CI must have it.
fn pdflatex_present() -> bool {
    let present = Command::new("pdflatex")
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok();
    assert!(
        present || std::env::var_os("CI").is_none(),
        "CI needs pdflatex"
    );
    present
}

/// Compiles `source` in `dir` and returns the number of pages.
fn pages(dir: &Path, source: &str) -> usize {
    std::fs::create_dir_all(dir).expect("scratch directory");
    std::fs::write(dir.join("x.tex"), source).expect("writable");
    let output = Command::new("pdflatex")
        .args([
            "-interaction=nonstopmode",
            "-halt-on-error",
            "-no-shell-escape",
            "x.tex",
        ])
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .expect("pdflatex runs");
    let log = std::fs::read_to_string(dir.join("x.log")).unwrap_or_default();
    assert!(
        output.status.success(),
        "does not compile: {:?}",
        log.lines()
            .filter(|l| l.starts_with('!'))
            .collect::<Vec<_>>()
    );
    let summary = log
        .lines()
        .find(|l| l.starts_with("Output written on"))
        .unwrap_or_default()
        .to_string();
    let count = summary
        .split('(')
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .unwrap_or(0);
    let _ = std::fs::remove_dir_all(dir);
    count
}

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
        "-m \\ddot{x} - k_{1} \\hat{u}_{1x} \\left(\\ell_{1} - l_{1}\\right) - k_{2} \\hat{u}_{2x} \\left(\\ell_{2} - l_{2}\\right)"
    );
    assert!(defines(
        &markdown,
        "\\Delta_{1x} = d + x - a c_{\\theta} - b s_{\\theta}",
        "of the vector from"
    ));
    if pdflatex_present() {
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
        "-m_{1} \\ddot{x}_{1} - \\left(c_{1} + c_{2}\\right) \\dot{x}_{1} + c_{2} \\dot{x}_{2} - \\left(k_{1} + k_{2}\\right) x_{1} + k_{2} x_{2}"
    );
}

#[test]
fn indices_are_sorted_as_a_reader_counts() {
    let markdown = explain("validation/ten-link-chain", "markdown");
    // By hand: the last link turns at the sum of all ten relative rates, q1' to q10', a run
    // a textbook writes by its ends; the third at q1' + q2' + q3', written out. Each with its
    // angular acceleration on the same line, as a textbook sets two short results.
    let alpha = |k: usize, rates: &str| {
        format!("{{}}^{{N}}\\boldsymbol{{\\alpha}}^{{\\mathrm{{link}}_{{{k}}}}} = \\left({rates}\\right) \\hat{{\\mathbf{{z}}}}_{{\\mathrm{{link}}_{{{k}}}}}")
    };
    for expected in [
        format!("{{}}^{{N}}\\boldsymbol{{\\omega}}^{{\\mathrm{{link}}_{{10}}}} = \\left(\\dot{{q}}_{{1}} + \\cdots + \\dot{{q}}_{{10}}\\right) \\hat{{\\mathbf{{z}}}}_{{\\mathrm{{link}}_{{10}}}}, \\qquad {}", alpha(10, "\\ddot{q}_{1} + \\cdots + \\ddot{q}_{10}")),
        format!("{{}}^{{N}}\\boldsymbol{{\\omega}}^{{\\mathrm{{link}}_{{3}}}} = \\left(\\dot{{q}}_{{1}} + \\dot{{q}}_{{2}} + \\dot{{q}}_{{3}}\\right) \\hat{{\\mathbf{{z}}}}_{{\\mathrm{{link}}_{{3}}}}, \\qquad {}", alpha(3, "\\ddot{q}_{1} + \\ddot{q}_{2} + \\ddot{q}_{3}")),
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
    let rule = "Abbreviations: $s$ and $c$ are the sine and cosine of the coordinate their subscript names, or of the sum of the coordinates it lists, as in $s_{1} = \\sin(q_{1})$, $s_{12} = \\sin\\left(q_{1} + q_{2}\\right)$, $s_{1\\ldots 5} = \\sin\\left(q_{1} + \\cdots + q_{5}\\right)$.";
    assert!(five.lines().any(|l| l == rule), "no line {rule}");
    assert!(
        five.contains("s_{23}"),
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
        line.starts_with("Abbreviations: $s_{\\psi} = \\sin(\\psi)$, $c_{\\psi} = \\cos(\\psi)$")
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
    // The mass matrix is symmetric: in the table by name, the entry below the diagonal is
    // the one above, defined once.
    assert!(markdown.contains("(2) & A_{1,2} &"));
    assert!(!markdown.contains("$A_{2,1} = "));
    // By hand, with the common factor L²m/6 out: A₁₂ = -(L²m/6)(44 + 21 c₂ + …).
    assert!(markdown.contains("$A_{1,2} = -\\frac{L^{2} m}{6} \\left(44 + 21 c_{2} + "));
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
        "-\\frac{L_{2} m_{2}}{6} \\left(2 L_{2} + 3 L_{1} c_{2}\\right) \\ddot{q}_{1} - \\frac{L_{2}^{2} m_{2}}{3} \\ddot{q}_{2} - \\frac{L_{1} L_{2} m_{2} s_{2}}{2} \\dot{q}_{1}^{2} - \\frac{L_{2} g m_{2}}{2} s_{12}"
    );
    // A + B about O, gravity's moment by hand: -m1 g (L1/2) s1 - m2 g (L1 s1 + (L2/2) s12),
    // the masses of s1's coefficient collected.
    assert!(equations[0].ends_with(
        "- \\frac{L_{1} g}{2} \\left(m_{1} + 2 m_{2}\\right) s_{1} - \\frac{L_{2} g m_{2}}{2} s_{12}"
    ));
    // Both rods along N.y: F^O_y - (m1 + m2) g + …, the masses collected.
    assert!(equations[3].ends_with("- g \\left(m_{1} + m_{2}\\right)"));
    // The abbreviations are defined once, at the start of step 2 where steps 2 to 5 begin
    // to use them (this chain has no constraint in step 1), in the order of the
    // coordinates, the sums last.
    let line = "Abbreviations: $s_{1} = \\sin(q_{1})$, $c_{1} = \\cos(q_{1})$, $s_{2} = \\sin(q_{2})$, $c_{2} = \\cos(q_{2})$, $s_{12} = \\sin\\left(q_{1} + q_{2}\\right)$, $c_{12} = \\cos\\left(q_{1} + q_{2}\\right)$.";
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
        "| $\\text{rolling constraint at floor} \\cdot \\hat{\\mathbf{n}}_{z}$ | position | $z - R c_{\\theta} = 0$ |"
    ));
    let abbreviations = markdown.find("Abbreviations: ").expect("abbreviations");
    let table = markdown
        .find("| Constraint | Level | Equation |")
        .expect("constraints");
    let step2 = markdown.find("## Step 2").expect("step 2");
    assert!(abbreviations < table && table < step2);
    // The velocity constraint along N.x, by hand, ẋ = R c_ψ (φ̇ + ψ̇ s_θ) + R θ̇ s_ψ c_θ,
    // differentiated in time:
    let expected = "-R c_{\\psi} \\ddot{\\phi} - R s_{\\theta} c_{\\psi} \\ddot{\\psi} - R s_{\\psi} c_{\\theta} \\ddot{\\theta} + \\ddot{x} + R s_{\\psi} s_{\\theta} \\dot{\\psi}^{2} + R s_{\\psi} s_{\\theta} \\dot{\\theta}^{2} + R s_{\\psi} \\dot{\\phi} \\dot{\\psi} - 2 R c_{\\psi} c_{\\theta} \\dot{\\psi} \\dot{\\theta}";
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
        "\\Delta_{1x} = 0.4 + x - \\frac{h s_{\\theta}}{2} - \\frac{w c_{\\theta}}{2}",
        "of the vector from"
    ));
    assert!(!markdown.contains("\\frac{2}{5}"));
}

#[test]
fn a_chain_link_moves_with_its_pin_and_the_pin_with_the_one_before() {
    let markdown = explain("validation/ten-link-chain", "markdown");
    // By hand: link6 hangs along -y of its frame from its joint P6, P7 a length L further,
    // so r^{P6P7} = -L ŷ6 and, with ω6 = (q̇1 + … + q̇6) ẑ, ω6 × r = L (q̇1 + … + q̇6) x̂6;
    // from P7 to link7* is -(L/2) ŷ7, so ω7 × r = (L/2)(q̇1 + … + q̇7) x̂7. The pin's
    // acceleration adds α6 × r = L (q̈1 + … + q̈6) x̂6 and -ω6² r = L (q̇1 + … + q̇6)² ŷ6.
    for expected in [
        "{}^{N}\\mathbf{v}^{P_{7}} = {}^{N}\\mathbf{v}^{P_{6}} + L \\left(\\dot{q}_{1} + \\cdots + \\dot{q}_{6}\\right) \\hat{\\mathbf{x}}_{\\mathrm{link}_{6}}",
        "{}^{N}\\mathbf{a}^{P_{7}} = {}^{N}\\mathbf{a}^{P_{6}} + L \\left(\\ddot{q}_{1} + \\cdots + \\ddot{q}_{6}\\right) \\hat{\\mathbf{x}}_{\\mathrm{link}_{6}} + L \\left(\\dot{q}_{1} + \\cdots + \\dot{q}_{6}\\right)^{2} \\hat{\\mathbf{y}}_{\\mathrm{link}_{6}}",
        "{}^{N}\\mathbf{v}^{\\mathrm{link}_{7}^*} = {}^{N}\\mathbf{v}^{P_{7}} + \\frac{L}{2} \\left(\\dot{q}_{1} + \\cdots + \\dot{q}_{7}\\right) \\hat{\\mathbf{x}}_{\\mathrm{link}_{7}}",
    ] {
        assert!(
            markdown.lines().any(|l| l.trim() == expected),
            "no line reads {expected}"
        );
    }
    // The free body of all ten links lists gravity once, for a link k: -m_k g n̂_y.
    assert!(markdown.contains(
        "| distance: gravity on each body k | $-m_{k}\\, g \\hat{\\mathbf{n}}_{y}$ | $\\text{at } k^*,\\; k \\in \\{\\mathrm{link}_{1}, "
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
    use mbd_tutor::numeric::evaluate::Compiled;
    use mbd_tutor::pipeline::{derive, derive_for_handout};
    let chain = mbd_tutor::problem::load_file(&problem("validation/ten-link-chain")).unwrap();
    let q: Vec<f64> = (0..10).map(|i| 0.3 - 0.17 * f64::from(i)).collect();
    let rates: Vec<f64> = (0..10).map(|i| 0.5 - 0.11 * f64::from(i)).collect();
    for method in Method::ALL {
        // For numbers, the outer links' accelerations have named parts built on the parent's
        // (unless whole is smaller); the handout writes them whole. The q'' are the same to
        // rounding, and the program no larger.
        let numeric = Compiled::new(&derive(&chain, method).unwrap());
        let handout = Compiled::new(&derive_for_handout(&chain, method).unwrap());
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
        let by_names = row(i).contains(&format!("A_{{{i},"));
        // A row is listed entry by entry exactly when step 5 writes it with A's names.
        assert_eq!(listed, by_names, "row {i}");
        assert_eq!(listed, !read_off.contains(&i), "row {i}");
    }
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
fn a_reaction_acts_at_its_joint_by_name() {
    let markdown = explain("five-link-chain", "markdown");
    // The free body link2 + … + link5 is cut at P2: the reaction of link1 on link2 acts at
    // the pin P2, which is also link2's origin, where an offset would read as 0.
    assert!(markdown.contains(
        "| contact: reaction at P2 | $F^{P_{2}}_{x} \\hat{\\mathbf{x}}_{\\mathrm{link}_{1}} + F^{P_{2}}_{y} \\hat{\\mathbf{y}}_{\\mathrm{link}_{1}}$ | $\\text{at } P_{2}$ |"
    ));
    assert!(!markdown.contains("$\\text{at } \\mathbf{0}$"));
    // Gravity acts at each link's mass centre, named as such (link5* alone on its own).
    assert!(markdown.contains("| distance: gravity on link5 | $-g m \\hat{\\mathbf{n}}_{y}$ | $\\text{at } \\mathrm{link}_{5}^*$ |"));
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
        "{}^{D}C^{E}_{11} = c_{q_{E1}} c_{q_{E3}} - s_{q_{E1}} s_{q_{E2}} s_{q_{E3}}",
        "direction cosines:"
    ));
    assert!(defines(
        &markdown,
        "{}^{N}C^{E}_{11} = {}^{D}C^{E}_{11} {}^{N}C^{D}_{11} - {}^{D}C^{E}_{21} s_{q_{A},q_{C}} c_{q_{D1}} - {}^{N}C^{D}_{13} s_{q_{E3}} c_{q_{E2}}",
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
fn a_row_formed_already_simplified_is_written_once() {
    let markdown = explain("two-mass-spring-damper", "markdown");
    // Cart A along N.y, by hand: the track's reaction holds its weight, F_y - m1 g = 0, as
    // formed; written once, not again as "simplified".
    let row = "**3. $A\\colon \\sum \\mathbf{F} \\cdot \\hat{\\mathbf{n}}_{y}$**\n\nAs formed, already simplified:\n\n$$\nF^{\\mathrm{trackA}}_{y} - g m_{1} = 0\n$$\n\n**4.";
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
    assert_eq!(tex.matches("Not to scale").count(), 1);
    let step2 = tex.find("Step 2. Free bodies").expect("step 2");
    assert!(tex.find("Not to scale").is_some_and(|i| i > step2));
    // The SVG pictures keep it: a picture read alone must say what its arrows mean.
    let markdown = explain("validation/ten-link-chain", "markdown");
    assert_eq!(markdown.matches(">Not to scale").count(), 10);
}

#[test]
fn a_right_hand_side_is_collected_by_the_rates() {
    let markdown = explain("five-link-chain", "markdown");
    // b₁ of the five-link chain as step 5 writes an equation: the damper's c q̇₁, then each
    // square of a link's angular velocity with its coefficient's factor L²m/2 out, gravity
    // last.
    assert!(markdown.contains(
        "- $b_{1} = c \\dot{q}_{1} + \\frac{L^{2} m}{2} \\left(7 s_{2} + 5 s_{23} + 3 s_{234} + s_{2345}\\right) \\dot{q}_{1}^{2} + "
    ));
    assert!(markdown.contains(
        "\\left(\\dot{q}_{1} + \\cdots + \\dot{q}_{5}\\right)^{2} + \\frac{9 L g m}{2} s_{1} + "
    ));
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
        "{}^{N}\\mathbf{a}^{C^*} = {}^{N}\\mathbf{a}^{B^*} + \\ddot{s}_{C} \\hat{\\mathbf{b}}_{z} - \\frac{L}{2} \\left(\\dot{q}_{A} + \\dot{q}_{C}\\right)^{2} \\hat{\\mathbf{c}}_{x}"
    ));
    assert!(!markdown.contains("\\dot{q}_{A}^{2} + \\dot{q}_{C}^{2} + 2 \\dot{q}_{A} \\dot{q}_{C}"));
    // Step 5 collects a row's rates the same way: D hangs from C, so D's rows hold the
    // square of C's rate, (…)(q̇_A + q̇_C)², beside q̇_D1² and the other products.
    let step5 = &markdown[markdown.find("## Step 5").expect("step 5")..];
    assert!(step5.contains("\\left(\\dot{q}_{A} + \\dot{q}_{C}\\right)^{2} + "));
    // A "where" list's definition keeps its terms, the square of C's rate written as one:
    // the joint point K's acceleration without the q'' along D's x axis.
    let definition = step4
        .lines()
        .find(|l| l.contains("\\tilde{a}^{K}_{x} = "))
        .expect("K's acceleration");
    assert!(definition.contains(
        "+ \\frac{L s_{q_{D2}} c_{q_{D1}}^{2} c_{q_{D2}}}{2} \\left(\\dot{q}_{A} + \\dot{q}_{C}\\right)^{2}"
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
    assert!(markdown.contains("{}^{N}\\mathbf{v}^{B^*} = \\left(\\dot{\\psi} v^{B^{*}}_{\\psi,x}"));
    // The where list says once what v_r is.
    assert_eq!(
        markdown
            .matches("- ${}^{N}\\mathbf{v}^{k^*}_{r} = \\partial\\, {}^{N}\\mathbf{v}^{k^*} / \\partial \\dot{q}_{r}$: the partial velocities")
            .count(),
        1
    );
}

#[test]
fn a_moment_about_a_bodys_own_mass_centre_has_no_moment_of_its_inertia_force() {
    // Newton–Euler's row of H's moments about H* along ĥ_y is long enough to be formed in
    // vector form; about H* itself, the arm of −m_H a^{H*} is zero, so only the inertia
    // torque is subtracted: ĥ_y · (Σ M_{H*} − (α·I + ω × I·ω)) = 0.
    let markdown =
        crate::support::explain("validation/whipple-bicycle", &["--method", "newton-euler"]);
    let row = "\\hat{\\mathbf{h}}_{y} \\cdot \\left( \\sum \\mathbf{M}_{H^{*}} - \\left( \\boldsymbol{\\alpha}^{H} \\cdot \\mathbf{I}^{H} + \\boldsymbol{\\omega}^{H} \\times \\mathbf{I}^{H} \\cdot \\boldsymbol{\\omega}^{H} \\right) \\right) = 0";
    assert!(markdown.contains(row), "no {row}");
    assert!(!markdown.contains("\\mathbf{r}^{H^{*} H^*}"));
}

#[test]
fn the_double_pendulums_second_rod_moves_with_its_pin() {
    let markdown = explain("double-pendulum-rods", "markdown");
    // By hand: the pin P is L1 along -â_y from O, so v^P = ω^A × r^{OP} = L1 q̇1 â_x and
    // a^P = L1 q̈1 â_x + L1 q̇1² â_y; B* is L2/2 along -b̂_y from P, so
    // v^{B*} = v^P + (L2/2)(q̇1 + q̇2) b̂_x, never v^{A*} + … .
    let pin = "{}^{N}\\mathbf{v}^{P} = L_{1} \\dot{q}_{1} \\hat{\\mathbf{a}}_{x}, \\qquad {}^{N}\\mathbf{a}^{P} = L_{1} \\ddot{q}_{1} \\hat{\\mathbf{a}}_{x} + L_{1} \\dot{q}_{1}^{2} \\hat{\\mathbf{a}}_{y}";
    let center = "{}^{N}\\mathbf{v}^{B^*} = {}^{N}\\mathbf{v}^{P} + \\frac{L_{2}}{2} \\left(\\dot{q}_{1} + \\dot{q}_{2}\\right) \\hat{\\mathbf{b}}_{x}";
    for expected in [pin, center] {
        assert!(
            markdown.lines().any(|l| l.trim() == expected),
            "no line reads {expected}"
        );
    }
    assert!(!markdown.contains("\\mathbf{v}^{B^*} = {}^{N}\\mathbf{v}^{A^*}"));
}
