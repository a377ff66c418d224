//! Step 5's system solved with numbers, as a student solves it on paper: its matrix and
//! right-hand side at the initial state of step 1 (up to four unknowns) beside the solution
//! there; an unknown that a row holds alone, in symbols before its number.

use super::answer_numbers::number_tex;
use super::solve_words::{is_reaction, row_list};
use crate::equations::{Derivation, LinearSystem};
use crate::render::context::InNumbers;
use crate::render::printed_width;
use crate::render::text::{MarkupLine, Math};
use crate::symbolic::{latex, simplify, substitute, Expr, Symbol};
use crate::Worked;

/// The widest display, in printed symbols, that holds the system and its solution side by
/// side; a wider one is split in two.
const WIDEST: usize = 70;
/// The longest closed form, in characters of LaTeX, worth writing in symbols.
const LONGEST_FORM: usize = 160;

/// A value as printed: `0` for what cancels to rounding.
fn value(x: f64) -> String {
    number_tex(if x.abs() < 1e-12 { 0.0 } else { x })
}

/// `\begin{bmatrix} a \\ b \end{bmatrix}` of rows of cells.
fn bmatrix(rows: &[Vec<String>]) -> String {
    let rows: Vec<String> = rows.iter().map(|r| r.join(" & ")).collect();
    format!(
        "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
        rows.join(" \\\\ ")
    )
}

/// A column of cells as a `bmatrix`.
fn column(cells: &[String]) -> String {
    let rows: Vec<Vec<String>> = cells.iter().map(|c| vec![c.clone()]).collect();
    bmatrix(&rows)
}

/// The printed width of a column of cells (its widest cell and the brackets).
fn width(cells: &[&String]) -> usize {
    cells.iter().map(|c| printed_width(c)).max().unwrap_or(0) + 2
}

/// Whether `x` solves the numbers `a x = b` to rounding, and gives the second derivatives
/// the solve of the whole handout found (`accelerations`, in coordinate order).
fn agrees(
    worked: &Worked,
    system: &LinearSystem,
    (a, b): (&[Vec<f64>], &[f64]),
    x: &[f64],
) -> bool {
    let residual_small = a.iter().zip(b).all(|(row, &bi)| {
        let terms: Vec<f64> = row.iter().zip(x).map(|(aij, xj)| aij * xj).collect();
        let scale = 1.0 + bi.abs() + terms.iter().map(|t| t.abs()).sum::<f64>();
        (terms.iter().sum::<f64>() - bi).abs() <= 1e-8 * scale
    });
    let problem = worked.derivation.model.problem;
    let same_accelerations = system.unknowns.iter().zip(x).all(|(u, &xj)| match u {
        Symbol::Coord(name, 2) => (0..problem.coordinates.len())
            .find(|&k| problem.coordinates[k].name.as_str() == &**name)
            .and_then(|k| worked.initial.accelerations.get(k))
            .is_some_and(|&found| (found - xj).abs() <= 1e-6 * (1.0 + found.abs())),
        _ => true,
    });
    residual_small && same_accelerations
}

/// The most unknowns whose block of rows is solved first, before the reactions.
const MOST_WRITTEN: usize = 6;
/// The most unknowns whose matrix is written with its numbers; past that, the matrix form
/// of step 5 shows the pattern, and the solution is written as a list.
const MOST_IN_MATRIX: usize = 4;

/// `$a$, $b$ and $c$`.
fn math_list(items: &[String]) -> String {
    let items: Vec<String> = items.iter().map(|u| format!("${u}$")).collect();
    match items.as_slice() {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

/// The rows and columns whose matrix is written: the whole system up to six unknowns;
/// past that, the rows without a reaction, where they are as many as the second
/// derivatives (at most six), which they give first.
fn written_block(system: &LinearSystem) -> Option<(Vec<usize>, Vec<usize>)> {
    let n = system.unknowns.len();
    if n <= MOST_WRITTEN {
        return Some(((0..n).collect(), (0..n).collect()));
    }
    let reactions: Vec<usize> = (0..n)
        .filter(|&j| is_reaction(&system.unknowns[j]))
        .collect();
    let accelerations: Vec<usize> = (0..n).filter(|j| !reactions.contains(j)).collect();
    let free: Vec<usize> = (0..system.a.len())
        .filter(|&i| reactions.iter().all(|&j| system.a[i][j].is_zero()))
        .collect();
    let fits = free.len() == accelerations.len() && !free.is_empty() && free.len() <= MOST_WRITTEN;
    fits.then_some((free, accelerations))
}

/// Step 5's system with its numbers at the initial state and its solution (past six
/// unknowns, the block of the rows without a reaction, solved first, then the reactions);
/// empty where there is no such block, the system is not solved at that state, or a
/// contact slides there (its row is then the sliding law). `shown` gives an entry as step
/// 5 prints it, `initial` its value at the initial state.
pub fn in_numbers(
    worked: &Worked,
    shown: &impl Fn(&Expr) -> Expr,
    initial: &impl Fn(&Expr) -> f64,
    sliding: bool,
) -> InNumbers {
    let Some(x) = worked.initial_unknowns.as_ref() else {
        return InNumbers::default();
    };
    let system = super::kane::shown_system(&worked.derivation);
    if sliding || x.len() != system.unknowns.len() {
        return InNumbers::default();
    }
    let Some((rows, columns)) = written_block(&system) else {
        return InNumbers::default();
    };
    let a: Vec<Vec<f64>> = (system.a.iter())
        .map(|row| row.iter().map(initial).collect())
        .collect();
    let b: Vec<f64> = system.b.iter().map(initial).collect();
    if !agrees(worked, &system, (&a, &b), x) {
        return InNumbers::default();
    }
    let all_names: Vec<String> = (system.unknowns.iter())
        .map(|u| latex(&Expr::sym(u.clone())))
        .collect();
    let names: Vec<String> = columns.iter().map(|&j| all_names[j].clone()).collect();
    let a_tex: Vec<Vec<String>> = (rows.iter())
        .map(|&i| columns.iter().map(|&j| value(a[i][j])).collect())
        .collect();
    let b_tex: Vec<String> = rows.iter().map(|&i| value(b[i])).collect();
    let x_tex: Vec<String> = columns.iter().map(|&j| value(x[j])).collect();
    let system_tex = format!(
        "{} {} = {}",
        bmatrix(&a_tex),
        column(&names),
        column(&b_tex)
    );
    let solution_tex = format!("{} = {}", column(&names), column(&x_tex));
    let widths: usize = (0..names.len())
        .map(|k| width(&a_tex.iter().map(|r| &r[k]).collect::<Vec<_>>()))
        .sum();
    let names_width = width(&names.iter().collect::<Vec<_>>());
    let b_width = width(&b_tex.iter().collect::<Vec<_>>());
    let x_width = width(&x_tex.iter().collect::<Vec<_>>());
    let total = widths + 2 * names_width + b_width + x_width + 8;
    // Listed, each value carries its unit; only the matrix needs "in SI units".
    let units = units(worked, &system.unknowns);
    let pairs: Vec<String> = (columns.iter().zip(&names).zip(&x_tex))
        .map(|((&j, n), v)| format!("{n} = {v}{}", units[j]))
        .collect();
    let mut lead_text = lead(worked, &system, &rows, &names);
    // The matrix beside its solution where it fits in a line, above it where not (up to
    // four unknowns); else the solution listed after the lead, as the matrix form above
    // shows the pattern.
    let mut closed = Vec::new();
    // Entries in powers of ten make a matrix a student would not write: listed instead.
    let plain = !a_tex.iter().flatten().any(|cell| cell.contains("\\times"));
    let displays = match (names.len() <= MOST_IN_MATRIX, total <= WIDEST, plain) {
        (true, true, _) => vec![format!(
            "{system_tex} \\quad \\Rightarrow \\quad {solution_tex}"
        )],
        (true, false, true) => {
            // The solution follows the matrix: the lead announces the system only.
            lead_text = lead_text.replace("the system and its solution:", "the system:");
            closed.push(format!("Its solution: {}.", math_list(&pairs)));
            vec![system_tex]
        }
        _ => {
            let in_si = units.iter().any(String::is_empty);
            lead_text = listed_lead(&system, &rows, &pairs, in_si);
            Vec::new()
        }
    };
    closed.extend(closed_forms(worked, &system, shown, x));
    let rest: Vec<usize> = (0..system.a.len()).filter(|i| !rows.contains(i)).collect();
    if !rest.is_empty() {
        // The reactions from the other rows, with the second derivatives found.
        let others: Vec<String> = (0..system.unknowns.len())
            .filter(|j| !columns.contains(j))
            .map(|j| format!("{} = {}{}", all_names[j], value(x[j]), units[j]))
            .collect();
        let (verb, list) = (
            if rest.len() == 1 { "gives" } else { "give" },
            math_list(&others),
        );
        let rows_word = if rest.len() == 1 { "row" } else { "rows" };
        let then = format!("{rows_word} {} {verb} {list}.", row_list(&rest));
        match displays.is_empty() {
            // The listed solution and the reactions after it in one sentence.
            true => lead_text = format!("{}; with these, {then}", lead_text.trim_end_matches('.')),
            false => closed.push(format!("With these, {then}")),
        }
    }
    let problem = worked.derivation.model.problem;
    let gives_accelerations = (0..problem.coordinates.len())
        .all(|k| names.contains(&latex(&problem.coordinate_expr(k, 2))));
    InNumbers {
        gives_accelerations,
        in_order: rows.len() < system.a.len(),
        lead: MarkupLine::from(lead_text),
        displays_tex: Math::all(displays),
        closed_forms: MarkupLine::all(closed),
    }
}

/// What is solved: the rows together for their unknowns, in numbers at the initial state.
fn lead(worked: &Worked, system: &LinearSystem, rows: &[usize], names: &[String]) -> String {
    let state = "At the initial state of step 1, in SI units,";
    if rows.len() < system.a.len() {
        // Why these rows come first, said here once: the order's sentence is left out.
        return format!(
            "{state} rows {}, which hold no reaction, give {} first:",
            row_list(rows),
            math_list(names)
        );
    }
    if super::solve_words::order(&worked.derivation).is_some() {
        // The order of the solve is said above.
        return format!("{state} the system and its solution:");
    }
    match rows.len() {
        1 => format!("{state} row (1) gives {}:", math_list(names)),
        n => format!(
            "{state} rows (1) to ({n}) are solved together for {}:",
            math_list(names)
        ),
    }
}

/// What is solved, with the solution listed: past four unknowns, no matrix of numbers.
/// The rows solved first are named here, with why (the order's sentence is left out).
fn listed_lead(system: &LinearSystem, rows: &[usize], pairs: &[String], in_si: bool) -> String {
    let state = match in_si {
        true => "At the initial state of step 1, in SI units,",
        false => "At the initial state of step 1,",
    };
    match rows.len() < system.a.len() {
        true => format!(
            "{state} rows {}, which hold no reaction, give {}.",
            row_list(rows),
            math_list(pairs)
        ),
        false => format!("{state} the solution is {}.", math_list(pairs)),
    }
}

/// Step 5's sentences after its rows, less what the solution in numbers says again: the
/// order of the solve (the rows without a reaction first, then the others) when the
/// numbers are solved in that order, and that the rows are solved with the numbers of the
/// initial state when they are.
pub fn said_once(notes: &mut Vec<MarkupLine>, derivation: &Derivation, numbers: &InNumbers) {
    if numbers.lead.is_empty() {
        return;
    }
    if numbers.in_order {
        if let Some(order) = super::solve_words::order(derivation) {
            notes.retain(|n| n.as_str() != order);
        }
    }
    let long = super::kane_system::rows_are_the_system(derivation);
    let short = super::kane_system::rows_are_linear(derivation);
    if let (Some(long), Some(short)) = (long, short) {
        for n in notes.iter_mut() {
            if n.as_str() == long {
                *n = MarkupLine::from(short.clone());
            }
        }
    }
}

/// The unit of each unknown as markup after its value (`\ \mathrm{m/s^{2}}`): a
/// coordinate's second derivative in the coordinate's unit, a reaction force in N, a
/// moment in N m; empty where there is none to give (a multiplier).
fn units(worked: &Worked, unknowns: &[Symbol]) -> Vec<String> {
    use crate::symbolic::{ComponentKind, Unknown};
    let problem = worked.derivation.model.problem;
    let coordinate = |name: &str| (problem.coordinates.iter()).position(|c| c.name == name);
    let unit = |u: &Symbol| -> Option<String> {
        match u {
            Symbol::Coord(name, 2) => {
                coordinate(name).map(|i| crate::numeric::coordinate_unit(problem, i, 2))
            }
            Symbol::Unknown(Unknown::Reaction { component, .. }) => match component.kind {
                ComponentKind::Force => Some("N".into()),
                ComponentKind::Moment => Some("N m".into()),
            },
            Symbol::Unknown(Unknown::Drive { coordinate: c, .. }) => {
                coordinate(c).map(|i| match problem.coordinates[i].kind {
                    crate::problem::CoordinateKind::Angle => "N m".into(),
                    crate::problem::CoordinateKind::Distance => "N".into(),
                })
            }
            _ => None,
        }
    };
    (unknowns.iter())
        .map(|u| {
            unit(u).map_or(String::new(), |t| {
                format!("\\ {}", crate::render::unit_tex(&t))
            })
        })
        .collect()
}

/// The rates that are zero at the initial state, each as the zero it is replaced by.
fn zero_rates(worked: &Worked) -> Vec<Symbol> {
    let problem = worked.derivation.model.problem;
    (0..problem.coordinates.len())
        .filter(|&k| worked.rates0.get(k).is_some_and(|&r| r == 0.0))
        .map(|k| problem.coordinate_symbol(k, 1))
        .collect()
}

/// Each unknown a row holds alone, with the rates that are zero at the initial state set
/// to zero: `x_j = b_i / a_ij` in symbols, then its number (the solution's `x_j`, which
/// the form gives to rounding, or the form is not written).
fn closed_forms(
    worked: &Worked,
    system: &LinearSystem,
    shown: &impl Fn(&Expr) -> Expr,
    x: &[f64],
) -> Vec<String> {
    let zero = zero_rates(worked);
    let model = &worked.derivation.model;
    let at_start = model.values_at(0.0, &worked.q0, &worked.rates0);
    let at_rest = |e: &Expr| simplify(&substitute(e, &|s| zero.contains(s).then(Expr::zero)));
    let mut given: Vec<usize> = Vec::new();
    let mut out = Vec::new();
    for (i, row) in system.a.iter().enumerate() {
        let entries: Vec<Expr> = row.iter().map(|e| at_rest(&shown(e))).collect();
        let nonzero: Vec<usize> = (0..entries.len())
            .filter(|&j| !entries[j].is_zero())
            .collect();
        let [j] = nonzero[..] else { continue };
        if given.contains(&j) {
            continue;
        }
        let (aij, bi) = (&entries[j], at_rest(&shown(&system.b[i])));
        let form = simplify(&(&bi / aij));
        // The coefficient written with a leading plus sign: −b/−a as b/a.
        let negative = aij.terms()[0].split_coefficient().0.is_negative();
        let (bi, aij) = match negative {
            true => (simplify(&-&bi), simplify(&-aij)),
            false => (bi, aij.clone()),
        };
        let number = crate::symbolic::eval(&form, &at_start);
        if (number - x[j]).abs() > 1e-6 * (1.0 + x[j].abs()) {
            continue;
        }
        let form_tex = [
            format!("\\frac{{{}}}{{{}}}", latex(&bi), latex(&aij)),
            latex(&form),
        ]
        .into_iter()
        .min_by_key(String::len)
        .unwrap_or_default();
        if form_tex.len() > LONGEST_FORM || form.is_constant() {
            continue;
        }
        given.push(j);
        let unknown = latex(&Expr::sym(system.unknowns[j].clone()));
        // The rates this row holds that are zero at the initial state, by name.
        let held: Vec<String> = (zero.iter())
            .filter(|z| {
                (row.iter().chain([&system.b[i]])).any(|e| shown(e).any_symbol(&|s| s == *z))
            })
            .map(|z| latex(&Expr::sym(z.clone())))
            .collect();
        let state = match held.is_empty() {
            true => String::new(),
            false => format!("at the initial state, where ${} = 0$, ", held.join(" = ")),
        };
        out.push(format!(
            "Row ({}) holds ${unknown}$ alone: {state}${unknown} = {form_tex} = {}$.",
            i + 1,
            value(x[j])
        ));
    }
    out
}
