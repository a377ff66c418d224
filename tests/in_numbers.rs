//! Step 5's linear system solved with numbers: the matrix and right-hand side at the
//! initial state and the solution vector, whose entries equal `solve`'s (by the same
//! method and by Newton–Euler's); the matrix times the vector gives the right-hand side;
//! an unknown that a row holds alone is written in closed form, checked against a hand
//! derivation; and Lagrange's reaction rows derived with their auxiliary coordinate.

use crate::support::{between, markdown_handout, solve};

/// A number as the handout prints it: `-1.5`, `2.5 \times 10^{-5}`.
fn number(text: &str) -> f64 {
    let text = text.trim().replace(" \\times 10^{", "e").replace('}', "");
    text.parse()
        .unwrap_or_else(|_| panic!("not a number: {text}"))
}

/// The cells of every `bmatrix` in `text`, in order, each as its rows of cells.
fn matrices(text: &str) -> Vec<Vec<Vec<String>>> {
    text.split("\\begin{bmatrix}")
        .skip(1)
        .map(|rest| {
            let inner = rest.split("\\end{bmatrix}").next().unwrap_or_default();
            inner
                .split("\\\\")
                .map(|row| row.split('&').map(|c| c.trim().to_string()).collect())
                .collect()
        })
        .collect()
}

/// Step 5's system in numbers: `A`, the unknowns' names, `b`, and the solution's values.
struct InNumbers {
    a: Vec<Vec<f64>>,
    names: Vec<String>,
    b: Vec<f64>,
    x: Vec<f64>,
}

/// The system in numbers of a Markdown handout, after its lead.
fn in_numbers(text: &str) -> InNumbers {
    let block = between(text, "in SI units,", "## Step 6");
    let found = matrices(block);
    assert!(found.len() >= 3, "the system: {block}");
    let column = |m: &Vec<Vec<String>>| -> Vec<String> { m.iter().map(|r| r[0].clone()).collect() };
    let values =
        |m: &Vec<Vec<String>>| -> Vec<f64> { column(m).iter().map(|c| number(c)).collect() };
    InNumbers {
        a: (found[0].iter())
            .map(|row| row.iter().map(|c| number(c)).collect())
            .collect(),
        names: column(&found[1]),
        b: values(&found[2]),
        x: match found.get(4) {
            Some(solution) => values(solution),
            // Too wide beside the system: `Its solution: $x_1 = v_1$, … and $x_n = v_n$.`
            None => between(block, "Its solution: ", ".\n")
                .split('$')
                .filter_map(|part| part.split_once(" = "))
                // Each value listed with its unit, `v\ \mathrm{N}`.
                .map(|(_, v)| number(v.split("\\ ").next().unwrap_or(v)))
                .collect(),
        },
    }
}

/// The value the handout's solution gives the unknown printed as `name`.
fn value(system: &InNumbers, name: &str) -> f64 {
    let j = (system.names.iter())
        .position(|n| n == name)
        .unwrap_or_else(|| panic!("{name} among {:?}", system.names));
    system.x[j]
}

/// Close to six significant digits, as the handout prints.
fn close(got: f64, want: f64, what: &str) {
    assert!(
        (got - want).abs() <= 2e-5 * (1.0 + want.abs()),
        "{what}: {got} against {want}"
    );
}

/// `A x = b` with the printed numbers, to their rounding.
fn residual_small(system: &InNumbers) {
    for (i, row) in system.a.iter().enumerate() {
        let ax: f64 = row.iter().zip(&system.x).map(|(a, x)| a * x).sum();
        let scale: f64 = 1.0
            + row
                .iter()
                .zip(&system.x)
                .map(|(a, x)| (a * x).abs())
                .sum::<f64>();
        assert!(
            (ax - system.b[i]).abs() <= 1e-4 * scale,
            "row {}: A x = {ax}, b = {}",
            i + 1,
            system.b[i]
        );
    }
}

/// The double pendulum's 4×4 by Kane's method: q̈ and the pivot's reaction as `solve`
/// finds them by Kane's and by Newton–Euler's method.
#[test]
fn the_double_pendulums_system_is_solved_with_the_numbers_of_solve() {
    let text = markdown_handout("double-pendulum-rods", "kane");
    let system = in_numbers(&text);
    assert_eq!(system.a.len(), 4);
    residual_small(&system);
    for method in ["kane", "newton-euler"] {
        let solved = solve("double-pendulum-rods", method, &[]);
        close(value(&system, "\\ddot{q}_{1}"), solved.acc("q1"), method);
        close(value(&system, "\\ddot{q}_{2}"), solved.acc("q2"), method);
        let force = solved.force("O");
        close(value(&system, "F^{O}_{x}"), force[0], method);
        close(value(&system, "F^{O}_{y}"), force[1], method);
    }
}

/// Lagrange's reaction rows introduce the auxiliary coordinate, write its equation with its
/// generalized force, set it to zero; their reaction is Newton–Euler's.
#[test]
fn lagranges_reaction_rows_are_derived_and_agree_with_newton_euler() {
    let text = markdown_handout("double-pendulum-rods", "lagrange");
    let step5 = between(&text, "## Step 5", "## Step 6");
    for words in [
        "by auxiliary coordinates $\\xi_{3}$ and $\\xi_{4}$, zero in the motion",
        "Q_{\\xi_{3}} - \\frac{\\partial V}{\\partial \\xi_{3}}",
        "Its equation at zero auxiliary coordinate and rate, solved for the reaction:",
    ] {
        assert!(step5.contains(words), "{words} in {step5}");
    }
    let system = in_numbers(&text);
    residual_small(&system);
    let solved = solve("double-pendulum-rods", "newton-euler", &[]);
    let force = solved.force("O");
    close(value(&system, "F^{O}_{x}"), force[0], "F_x");
    close(value(&system, "F^{O}_{y}"), force[1], "F_y");
}

/// The four-bar by Kane's method: the rows without a reaction give the second derivatives
/// first, a 3×3 in numbers, and they are `solve`'s (by the Motion Law's equations).
#[test]
fn the_four_bars_system_is_solved_with_the_numbers_of_solve() {
    let text = markdown_handout("four-bar", "kane");
    let system = in_numbers(&text);
    residual_small(&system);
    let solved = solve("four-bar", "motion-law", &[]);
    let accelerations = solved.json["accelerations"]
        .as_object()
        .expect("accelerations");
    let mut compared = 0;
    for (name, want) in accelerations {
        let tex = format!("\\ddot{{q}}_{{{}}}", name.trim_start_matches('q'));
        if system.names.contains(&tex) {
            close(
                value(&system, &tex),
                want.as_f64().unwrap_or(f64::NAN),
                name,
            );
            compared += 1;
        }
    }
    assert!(compared >= 2, "{:?}", system.names);
}

/// The simple pendulum's moment row about the pivot holds θ̈ alone: by hand,
/// m L² θ̈ = −m g L sin θ, so θ̈ = −(g/L) sin θ = −9.81 sin 0.6 / 0.8.
#[test]
fn a_row_that_holds_one_unknown_gives_it_in_closed_form() {
    let text = markdown_handout("simple-pendulum", "motion-law");
    let line = (text.lines())
        .find(|l| l.contains("holds $\\ddot{\\theta}$ alone"))
        .unwrap_or_else(|| panic!("no closed form: {text}"));
    let by_hand = -9.81 * 0.6f64.sin() / 0.8;
    let printed = line
        .rsplit(" = ")
        .next()
        .map(|t| number(t.trim_end_matches("$.")))
        .unwrap_or(f64::NAN);
    close(printed, by_hand, line);
    assert!(line.contains("\\sin") || line.contains("s_{"), "{line}");
    let system = in_numbers(&text);
    close(value(&system, "\\ddot{\\theta}"), by_hand, "the solution");
}

/// The solution is announced once: where the double pendulum's matrix is too wide to have
/// its solution beside it, the lead names the system only and "Its solution:" follows it.
#[test]
fn the_solution_in_numbers_is_announced_once() {
    for method in ["motion-law", "kane", "newton-euler", "lagrange"] {
        let text = markdown_handout("double-pendulum-rods", method);
        let block = between(&text, "## Step 5", "## Step 6");
        let said = block.to_lowercase().matches("solution").count();
        assert!(
            said <= 1,
            "{method}: the solution said {said} times: {block}"
        );
    }
}
