//! Step 5 in matrix form, `A x = b`: each column named by its unknown, each row by the
//! equation it comes from. The whole table when it fits the line; otherwise entry by entry,
//! a long right-hand side collected by the products of rates.

use super::long::{by_rates, LONG_EQUATION};
use super::matrix_by_value::{b_texts, by_value_early, ENTRIES_BUDGET, MOST_COLUMNS};
use super::row_names::row_heading_tex;
use crate::equations::{Derivation, LinearSystem, Method};
use crate::plan::Sum;
use crate::problem::MatrixNames;
use crate::render::context::{MatrixEntry, MatrixForm, Named, WholeMatrix};
use crate::render::text::Math;
use crate::render::{
    pattern_tables, printed_width, value_tables, value_tex, whole_matrix as whole,
};
use crate::symbolic::{latex, latex_factored, Expr};

/// An entry this wide or narrower (in printed symbols) stays in a table by name.
const INLINE_ENTRY: usize = 4;
/// An entry longer than this keeps a display of its own when a row's entries are printed
/// one after another.
const SHORT_ENTRY: usize = 400;

/// The most entries listed one a line; past it, the short entries of a row are printed one
/// after another.
const MOST_LISTED: usize = 16;

/// Step 5's `A x = b`; `by_name[i]` tells whether step 5 writes row `i` with the entries'
/// names, and then they are listed one by one: the rows step 5 writes out in full are read
/// off there and not repeated. `initial` evaluates an entry at the initial state, for the
/// entries of a system too large to print whole (see [`ENTRIES_BUDGET`]).
pub fn matrix(
    derivation: &Derivation,
    by_name: &[bool],
    shown: impl Fn(&Expr) -> Expr,
    initial: impl Fn(&Expr) -> f64,
    sliding: &[super::sliding_rows::SlidingRow],
) -> MatrixForm {
    let names = MatrixNames::of(derivation.model.problem);
    // The tables head the right-hand side's column with its name.
    let header = |t: &str| t.replace(" & \\mathbf{b}", &format!(" & \\mathbf{{{}}}", names.b));
    let headed =
        |tables: Vec<String>| -> Vec<String> { tables.iter().map(|t| header(t)).collect() };
    let whole = |labels: &[String], x: &[String], a: &[Vec<String>], b: &[String]| {
        whole(labels, x, a, b).map(|mut w| {
            w.table_tex = Math::from(header(&w.table_tex));
            w
        })
    };
    let pattern_tables =
        |labels: &[String], a: &[Vec<Expr>], b: &[Expr]| headed(pattern_tables(labels, a, b));
    let by_entries = by_name.iter().any(|&b| b);
    let listed = |i: usize| !by_entries || by_name.get(i).copied().unwrap_or(true);
    let system = &super::kane::shown_system(derivation);
    let n = system.unknowns.len();
    // Kane's and Lagrange's rows written out whole in step 5 (see below).
    let whole_rows = matches!(derivation.method, Method::Kane | Method::Lagrange) && !by_entries;
    let may_go_by_value = !whole_rows && sliding.is_empty();
    if may_go_by_value && by_value_early(system, by_name, &listed, &shown) {
        return by_value(derivation, system, &initial, &headed);
    }
    let mut a: Vec<Vec<Expr>> = system
        .a
        .iter()
        .map(|row| row.iter().map(&shown).collect())
        .collect();
    let mut b: Vec<Expr> = system.b.iter().map(&shown).collect();
    super::sliding_rows::replace_in_matrix(&system.unknowns, &mut a, &mut b, sliding);
    // Each row by its equation in step 5, beside its number ("Row 2, B: ΣM_P · â_z").
    let labels: Vec<String> = (0..a.len())
        .map(|i| row_heading_tex(derivation, i))
        .collect();
    let x = unknowns_tex(system);
    // In the table a row is labelled by its number: step 5 heads each equation with it.
    let numbers = numbers_of(a.len());
    // Kane's rows stand whole in step 5, each written once, its mass matrix positive, and a
    // single row is its own solution. Up to six unknowns Kane's matrix is written out with
    // its entries, as the Motion Law's is, for a student to solve; past that Kane's rows are
    // the system as they stand (see `solve_words`), and Lagrange's matrix shows only where
    // its entries are (the structure of the solve).
    if whole_rows && a.len() < 2 {
        return MatrixForm::default();
    }
    let written_out = derivation.method == Method::Kane && n <= MOST_COLUMNS;
    if whole_rows && derivation.method == Method::Kane && !written_out {
        // Past six unknowns a student reads Kane's system off its rows and solves it
        // numerically, which the solve's words say: a pattern of dots would not help.
        return MatrixForm::default();
    }
    if whole_rows && !written_out {
        let six = lagrange_whole(&whole, (&a, &b), [&numbers, &labels, &x], &names, &listed);
        return six.unwrap_or_else(|| MatrixForm {
            pattern_tex: Math::all(pattern_tables(&numbers, &a, &b)),
            columns_tex: Math::all(columns(&names.x, &x)),
            ..MatrixForm::default()
        });
    }
    let a_tex: Vec<Vec<String>> = a
        .iter()
        .map(|row| row.iter().map(latex_factored).collect())
        .collect();
    // b collected by the products of rates, each coefficient's factor out, as step 5
    // writes an equation, when that is shorter.
    let b_tex = b_texts(&b);
    let b_names: Vec<String> = (1..=a.len())
        .map(|i| format!("{}_{{{i}}}", names.b))
        .collect();
    let mut table_with_b_by_name = None;
    if n <= MOST_COLUMNS && !by_entries {
        if let Some(whole) = whole(&numbers, &x, &a_tex, &b_tex) {
            return MatrixForm {
                whole: Some(whole),
                ..MatrixForm::default()
            };
        }
        // A right-hand side too wide for the table: b by name in it, its entries below.
        table_with_b_by_name = whole(&numbers, &x, &a_tex, &b_names);
    }
    // Entries too wide as well: every entry longer than a symbol or two by name, as a
    // textbook writes a larger system, the names defined below the table.
    let a_names = named_entries(&a, &a_tex, &names);
    // Wider still: the unknowns by column number, z_j, given below the table.
    let x_names: Vec<String> = (1..=n).map(|j| format!("{}_{{{j}}}", names.x)).collect();
    let (table_by_name, unknowns_by_number) = if table_with_b_by_name.is_some() {
        (None, false)
    } else if let Some(table) = whole(&numbers, &x, &a_names, &b_names) {
        (Some(table), false)
    } else {
        (whole(&numbers, &x_names, &a_names, &b_names), true)
    };
    let printed: usize = (0..a_tex.len())
        .filter(|&i| listed(i))
        .flat_map(|i| a_tex[i].iter().chain([&b_tex[i]]))
        .map(String::len)
        .sum();
    let named_rows = by_name.iter().filter(|&&named| named).count();
    if printed > ENTRIES_BUDGET && named_rows > 0 && 4 * named_rows <= a.len() {
        // Three rows in four or more are written out in step 5, the few others by their
        // coefficients' names, too long to print: those few by their values at the initial
        // state, the rest read off step 5, and the table of dots shows the whole. With more
        // rows by name, A and b by value are worth their space: a reader can solve them.
        let read_off: Vec<usize> = (0..a.len()).filter(|&i| !listed(i)).collect();
        let entries = entries_by_value(system, &labels, &names, &listed, &initial);
        return MatrixForm {
            pattern_tex: Math::all(pattern_tables(&numbers, &a, &b)),
            entries,
            columns_tex: Math::all(columns(&names.x, &x)),
            read_off_tex: Math::from(rows_tex(&read_off)),
            ..MatrixForm::default()
        };
    }
    if printed > ENTRIES_BUDGET {
        // A system this large is read by its numbers: A and b at the initial state as a
        // table, the rules saying what each entry is.
        return by_value(derivation, system, &initial, &headed);
    }
    // b's entries too long to read whole, collected by the products of rates they hold.
    let b_groups = b_groups(&b, &b_tex);
    let entries = entries_of(
        &a,
        (&a_tex, &b_tex),
        &b_groups,
        &labels,
        &x,
        &names,
        &listed,
    );
    if !by_entries && (table_by_name.is_some() || table_with_b_by_name.is_some()) {
        // Step 5 writes every row out, collected by its unknowns: a table of names whose
        // entries are listed below it would only write those rows a second time.
        return MatrixForm::default();
    }
    if let Some(table) = table_by_name {
        let entries = (entries, unknowns_by_number);
        return by_name_form(table, &a_names, &a_tex, &x, &names, entries);
    }
    let pattern = || pattern_tables(&numbers, &a, &b);
    listed_form(
        entries,
        (by_entries, &listed),
        a.len(),
        (names.x.as_str(), x.as_slice()),
        pattern,
    )
}

/// A whole matrix's table from its row labels, unknowns, entries and right-hand side.
type WholeTable<'w> = &'w dyn Fn(&[String], &[String], &[Vec<String>], &[String]) -> Option<W>;
use WholeMatrix as W;

/// Lagrange's matrix of at most six unknowns whole, for a student to solve: entries in the
/// table where they fit, else b by name, its entries below; `None` past six or too wide.
fn lagrange_whole(
    whole: WholeTable,
    (a, b): (&[Vec<Expr>], &[Expr]),
    [numbers, labels, x]: [&[String]; 3],
    names: &MatrixNames,
    listed: &impl Fn(usize) -> bool,
) -> Option<MatrixForm> {
    if x.len() > MOST_COLUMNS {
        return None;
    }
    let a_tex: Vec<Vec<String>> = (a.iter())
        .map(|row| row.iter().map(latex_factored).collect())
        .collect();
    let b_tex = b_texts(b);
    if let Some(table) = whole(numbers, x, &a_tex, &b_tex) {
        return Some(MatrixForm {
            whole: Some(table),
            ..MatrixForm::default()
        });
    }
    let b_names: Vec<String> = (1..=a.len())
        .map(|i| format!("{}_{{{i}}}", names.b))
        .collect();
    let table = whole(numbers, x, &a_tex, &b_names)?;
    let groups = b_groups(b, &b_tex);
    let entries = entries_of(a, (&a_tex, &b_tex), &groups, labels, x, names, listed);
    Some(by_name_form(
        table,
        &a_tex,
        &a_tex,
        x,
        names,
        (entries, false),
    ))
}

/// A system this large read by its numbers: `A` and `b` at the initial state as a table
/// (each table `headed`), the rules saying what each entry is.
fn by_value(
    derivation: &Derivation,
    system: &LinearSystem,
    initial: &impl Fn(&Expr) -> f64,
    headed: &impl Fn(Vec<String>) -> Vec<String>,
) -> MatrixForm {
    let (numbers, x) = (numbers_of(system.a.len()), unknowns_tex(system));
    MatrixForm {
        value_tables_tex: Math::all(headed(value_tables(
            &numbers, &x, &system.a, &system.b, initial,
        ))),
        rules: coefficient_rules(derivation),
        ..MatrixForm::default()
    }
}

/// The unknowns' LaTeX, the columns' heads.
fn unknowns_tex(system: &LinearSystem) -> Vec<String> {
    (system.unknowns.iter())
        .map(|u| latex(&Expr::sym(u.clone())))
        .collect()
}

/// The rows' labels in a table, `(1)` to `(rows)`.
fn numbers_of(rows: usize) -> Vec<String> {
    (1..=rows).map(|i| format!("({i})")).collect()
}

/// The entries listed one by one (of `rows` rows), the rows step 5 writes out in full, not
/// `listed`, read off there; a long list gathered row by row. Where step 5 writes every
/// row out (not `by_entries`) and the list is long, the table of dots (`pattern`) instead.
fn listed_form(
    mut entries: Vec<MatrixEntry>,
    (by_entries, listed): (bool, &impl Fn(usize) -> bool),
    rows: usize,
    (letter, x): (&str, &[String]),
    pattern: impl FnOnce() -> Vec<String>,
) -> MatrixForm {
    let columns_tex = columns(letter, x);
    if !by_entries && entries.len() > MOST_LISTED {
        // Step 5 writes every row out, collected by its unknowns: listing the entries again
        // would repeat it. Where each row's unknowns are is the system's shape, which the
        // rows one by one do not show.
        return MatrixForm {
            pattern_tex: Math::all(pattern()),
            columns_tex: Math::all(columns_tex),
            ..MatrixForm::default()
        };
    }
    let read_off: Vec<usize> = (0..rows).filter(|&i| !listed(i)).collect();
    entries.retain(|e| listed(e.row - 1));
    let read_off_tex = rows_tex(&read_off);
    if entries.len() <= MOST_LISTED {
        return MatrixForm {
            whole: None,
            entries,
            read_off_tex: Math::from(read_off_tex),
            ..MatrixForm::default()
        };
    }
    MatrixForm {
        whole: None,
        entries: row_by_row(entries),
        columns_tex: Math::all(columns_tex),
        read_off_tex: Math::from(read_off_tex),
        ..MatrixForm::default()
    }
}

/// Each listed row's nonzero entries of `A`, and its `b`, by their values at the initial
/// state (`initial`), the row labelled by its equation.
fn entries_by_value(
    system: &LinearSystem,
    labels: &[String],
    names: &MatrixNames,
    listed: &impl Fn(usize) -> bool,
    initial: &impl Fn(&Expr) -> f64,
) -> Vec<MatrixEntry> {
    let value = |e: &Expr| value_tex(initial, e);
    (0..system.a.len())
        .filter(|&i| listed(i))
        .map(|i| {
            let mut values: Vec<String> = system.a[i]
                .iter()
                .enumerate()
                .filter(|(_, e)| !e.is_zero())
                .map(|(j, e)| format!("{}_{{{},{}}} = {}", names.a, i + 1, j + 1, value(e)))
                .collect();
            values.push(format!(
                "{}_{{{}}} = {}",
                names.b,
                i + 1,
                value(&system.b[i])
            ));
            MatrixEntry {
                row: i + 1,
                row_label_tex: Math::from(labels[i].clone()),
                values_tex: Math::all(values),
                ..MatrixEntry::default()
            }
        })
        .collect()
}

/// Each entry of `b` too long to read whole (its text in `b_tex`), collected by the
/// products of rates it holds; empty for the others.
fn b_groups(b: &[Expr], b_tex: &[String]) -> Vec<Vec<(Expr, Expr)>> {
    b.iter()
        .zip(b_tex)
        .map(|(e, text)| {
            if text.len() > 2 * LONG_EQUATION {
                by_rates(e)
            } else {
                Vec::new()
            }
        })
        .collect()
}

/// The entries listed one by one: each row's nonzero entries of `A` (a symmetric one by its
/// mirror's name) and its `b`, a long `b` by the products of rates in `b_groups`.
fn entries_of(
    a: &[Vec<Expr>],
    (a_tex, b_tex): (&[Vec<String>], &[String]),
    b_groups: &[Vec<(Expr, Expr)>],
    labels: &[String],
    x: &[String],
    names: &MatrixNames,
    listed: &impl Fn(usize) -> bool,
) -> Vec<MatrixEntry> {
    let mut entries = Vec::new();
    for (i, row) in a.iter().enumerate() {
        let mut label = labels[i].clone();
        let mut entry = |column: String, column_tex: String, value_tex: String| {
            entries.push(MatrixEntry {
                row: i + 1,
                column,
                value_tex: Math::from(value_tex),
                row_label_tex: Math::from(std::mem::take(&mut label)),
                column_tex: Math::from(column_tex),
                values_tex: Vec::new(),
            });
        };
        for (j, e) in row.iter().enumerate().filter(|(_, e)| !e.is_zero()) {
            // A symmetric entry refers to the one above the diagonal, written once.
            let mirror = a.get(j).and_then(|r| r.get(i));
            let value = if j < i && mirror == Some(e) && listed(j) {
                format!("{}_{{{},{}}}", names.a, j + 1, i + 1)
            } else {
                a_tex[i][j].clone()
            };
            entry(
                (j + 1).to_string(),
                x[j].clone(),
                format!("{}_{{{},{}}} = {value}", names.a, i + 1, j + 1),
            );
        }
        let groups = &b_groups[i];
        let column_b = || format!("\\mathbf{{{}}}", names.b);
        if groups.len() < 2 {
            entry(
                "b".into(),
                column_b(),
                format!("{}_{{{}}} = {}", names.b, i + 1, b_tex[i]),
            );
            continue;
        }
        // Too long to read whole: b_i collected by the products of rates it holds, each
        // coefficient named and given after it.
        let name = |k: usize| format!("{}_{{{},{k}}}", names.b, i + 1);
        let sum: Vec<String> = groups
            .iter()
            .enumerate()
            .map(|(k, (rates, _))| {
                if rates.is_one() {
                    name(k + 1)
                } else {
                    format!("{} \\, {}", name(k + 1), latex(rates))
                }
            })
            .collect();
        entry(
            "b".into(),
            column_b(),
            format!("{}_{{{}}} = {}", names.b, i + 1, sum.join(" + ")),
        );
        for (k, (_, coefficient)) in groups.iter().enumerate() {
            entry(
                "b".into(),
                column_b(),
                format!("{} = {}", name(k + 1), latex_factored(coefficient)),
            );
        }
    }
    entries
}

/// The whole table with the long entries by name (`a_names`), those of `A` defined below
/// it and `b`'s entries after them; the unknowns listed by column where the table heads
/// them by number.
fn by_name_form(
    table: WholeMatrix,
    a_names: &[Vec<String>],
    a_tex: &[Vec<String>],
    x: &[String],
    names: &MatrixNames,
    (entries, unknowns_by_number): (Vec<MatrixEntry>, bool),
) -> MatrixForm {
    let mut defined = Vec::new();
    for (i, row) in a_names.iter().enumerate() {
        for (j, name) in row.iter().enumerate() {
            if *name == format!("{}_{{{},{}}}", names.a, i + 1, j + 1) {
                defined.push(MatrixEntry {
                    row: i + 1,
                    column: (j + 1).to_string(),
                    value_tex: Math::from(format!("{name} = {}", a_tex[i][j])),
                    column_tex: Math::from(x[j].clone()),
                    ..MatrixEntry::default()
                });
            }
        }
    }
    defined.extend(
        entries
            .into_iter()
            .filter(|e| e.column == "b")
            .map(|e| MatrixEntry {
                row_label_tex: Math::from(String::new()),
                ..e
            }),
    );
    MatrixForm {
        whole: Some(table),
        entries: defined,
        columns_tex: if unknowns_by_number {
            Math::all(columns(&names.x, x))
        } else {
            Vec::new()
        },
        ..MatrixForm::default()
    }
}

/// The unknowns by column, for a table that heads them by number: `x_{1} = \\ddot{q}_{1}`,
/// `letter` the column's name (`z` where a coordinate is `x`).
fn columns(letter: &str, x: &[String]) -> Vec<String> {
    x.iter()
        .enumerate()
        .map(|(j, x)| format!("{letter}_{{{}}} = {x}", j + 1))
        .collect()
}

/// Row numbers as a reader lists them, runs joined by an en dash (LaTeX `--`):
/// `(1)--(9), (24)--(26)`.
fn rows_tex(rows: &[usize]) -> String {
    let mut runs: Vec<(usize, usize)> = Vec::new();
    for &i in rows {
        match runs.last_mut() {
            Some((_, end)) if *end + 1 == i => *end = i,
            _ => runs.push((i, i)),
        }
    }
    let run = |(a, b): (usize, usize)| match b - a {
        0 => format!("({})", a + 1),
        1 => format!("({}), ({})", a + 1, b + 1),
        _ => format!("({})--({})", a + 1, b + 1),
    };
    runs.into_iter().map(run).collect::<Vec<_>>().join(", ")
}

/// The entries of `A` as a table by name prints them: 0, a symbol or two as it is
/// (`m`, `-1`), any other by its name `A_{i,j}`; an entry below the diagonal equal to its
/// mirror by its mirror's name.
fn named_entries(a: &[Vec<Expr>], a_tex: &[Vec<String>], names: &MatrixNames) -> Vec<Vec<String>> {
    a_tex
        .iter()
        .enumerate()
        .map(|(i, row)| {
            row.iter()
                .enumerate()
                .map(|(j, text)| {
                    let mirror = a.get(j).and_then(|r| r.get(i));
                    if a[i][j].is_zero() {
                        "0".to_string()
                    } else if printed_width(text) <= INLINE_ENTRY {
                        text.clone()
                    } else if j < i && mirror == Some(&a[i][j]) {
                        format!("{}_{{{},{}}}", names.a, j + 1, i + 1)
                    } else {
                        format!("{}_{{{},{}}}", names.a, i + 1, j + 1)
                    }
                })
                .collect()
        })
        .collect()
}

/// The short entries of each row gathered into one, to be printed one after another; a
/// long one keeps a display of its own.
fn row_by_row(entries: Vec<MatrixEntry>) -> Vec<MatrixEntry> {
    let mut rows: Vec<MatrixEntry> = Vec::new();
    for entry in entries {
        if entry.value_tex.len() > SHORT_ENTRY {
            rows.push(entry);
            continue;
        }
        match rows.last_mut() {
            Some(last) if last.row == entry.row && !last.values_tex.is_empty() => {
                last.values_tex.push(entry.value_tex)
            }
            _ => rows.push(MatrixEntry {
                values_tex: vec![entry.value_tex],
                value_tex: Math::from(String::new()),
                column: String::new(),
                column_tex: Math::from(String::new()),
                ..entry
            }),
        }
    }
    rows
}

/// What the coefficient of each kind of unknown is in each kind of row, in the partial
/// velocities of the bodies `k` of the row's free body.
fn coefficient_rules(derivation: &Derivation) -> Vec<Named> {
    let names = MatrixNames::of(derivation.model.problem);
    let (a, b) = (names.a.as_str(), names.b.as_str());
    let rule = |note: &str, tex: &str| {
        let tex = match tex.split_once("_{") {
            Some(("A", rest)) => format!("{a}_{{{rest}"),
            Some(("b", rest)) => format!("{b}_{{{rest}"),
            _ => tex.to_string(),
        };
        Named::new(&tex, note)
    };
    let mut rules = Vec::new();
    let sums = |wanted: fn(&Sum) -> bool| derivation.rows.iter().any(|r| wanted(&r.sum));
    if sums(|s| matches!(s, Sum::Force)) {
        rules.push(rule(
            "the coefficient of an acceleration in a sum of forces along a direction d",
            "A_{ij} = -\\sum_{k} m_{k}\\, \\mathbf{v}^{k^*}_{j} \\cdot \\hat{\\mathbf{d}}",
        ));
    }
    if sums(|s| matches!(s, Sum::Moment { .. })) {
        rules.push(rule(
            "in a sum of moments about a point P along d",
            "A_{ij} = -\\sum_{k} \\left( \\mathbf{r}^{P k^*} \\times m_{k} \\mathbf{v}^{k^*}_{j} + \\mathbf{I}^{k} \\cdot \\boldsymbol{\\omega}^{k}_{j} \\right) \\cdot \\hat{\\mathbf{d}}",
        ));
    }
    if sums(|s| matches!(s, Sum::Generalized { .. })) {
        // Lagrange's row d/dt(∂L/∂q̇_r) − ∂L/∂q_r = Q_r has the mass matrix with its own
        // sign; Kane's F_r + F*_r = 0 has it with the opposite one.
        let sum = "\\sum_{k} \\left( m_{k}\\, \\mathbf{v}^{k^*}_{r} \\cdot \\mathbf{v}^{k^*}_{j} + \\boldsymbol{\\omega}^{k}_{r} \\cdot \\mathbf{I}^{k} \\cdot \\boldsymbol{\\omega}^{k}_{j} \\right)";
        rules.push(match derivation.method {
            Method::Lagrange => rule(
                "in Lagrange's equation of coordinate r",
                &format!("A_{{rj}} = {sum}"),
            ),
            _ => rule("in Kane's row r", &format!("A_{{rj}} = -{sum}")),
        });
    }
    rules.push(rule(
        "the coefficient of a reaction component: its unit force (or the moment of it about P) along d; and the right-hand side",
        "b_{i} = -\\left( \\text{row } i \\right)_{\\ddot{q} = 0,\\ \\text{reactions} = 0}",
    ));
    rules
}
