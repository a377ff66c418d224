//! Step 5 in matrix form, `A x = b`: each column named by its unknown, each row by the
//! equation it comes from. The whole table when it fits the line; otherwise entry by entry,
//! a long right-hand side collected by the products of rates.

use super::context::{MatrixEntry, MatrixForm, WholeMatrix};
use super::long::{by_rates, LONG_EQUATION};
use super::prepare::printed_width;
use crate::equations::rows::Sum;
use crate::equations::Derivation;
use crate::symbolic::print::{latex, latex_name};
use crate::symbolic::Expr;

/// The most columns the whole table has.
const MOST_COLUMNS: usize = 6;
/// How many symbols the whole table may print across: about the width of the page.
const TABLE_WIDTH: usize = 70;

/// What names row `i` of the system: its number in step 5 and its equation, e.g.
/// `(2)\; B\colon \sum \mathbf{M}_{P} \cdot \hat{\mathbf{a}}_{z}` or, for Kane's rows,
/// `(1)\; F_{1} + F^{*}_{1}`.
pub fn row_label_tex(derivation: &Derivation, i: usize) -> String {
    let row = &derivation.rows[i];
    let problem = derivation.model.problem;
    let body = row
        .free_body
        .iter()
        .map(|b| latex_name(problem.body_name(*b)))
        .collect::<Vec<_>>()
        .join("{+}");
    let direction = row
        .direction
        .as_ref()
        .map(|d| format!(" \\cdot {}", d.latex))
        .unwrap_or_default();
    let what = match &row.sum {
        Sum::Force => format!("{body}\\colon \\sum \\mathbf{{F}}{direction}"),
        Sum::Moment { point, .. } => {
            let point = match point.strip_suffix('*') {
                Some(stem) => format!("{}^{{*}}", latex_name(stem)),
                None => latex_name(point),
            };
            format!("{body}\\colon \\sum \\mathbf{{M}}_{{{point}}}{direction}")
        }
        Sum::Generalized { .. } => {
            let r = derivation.rows[..=i]
                .iter()
                .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
                .count();
            format!("F_{{{r}}} + F^{{*}}_{{{r}}}")
        }
        Sum::Constraint { .. } => "\\text{constraint}".to_string(),
    };
    format!("({})\\; {what}", i + 1)
}

/// Step 5's `A x = b`; `by_entries` asks for the entries one by one (an equation refers to
/// them by name).
pub fn matrix(
    derivation: &Derivation,
    by_entries: bool,
    shown: impl Fn(&Expr) -> Expr,
) -> MatrixForm {
    let system = &derivation.system;
    let n = system.unknowns.len();
    let a: Vec<Vec<Expr>> = system
        .a
        .iter()
        .map(|row| row.iter().map(&shown).collect())
        .collect();
    let b: Vec<Expr> = system.b.iter().map(&shown).collect();
    let labels: Vec<String> = (0..a.len()).map(|i| row_label_tex(derivation, i)).collect();
    let x: Vec<String> = system
        .unknowns
        .iter()
        .map(|u| latex(&Expr::sym(u.clone())))
        .collect();
    let a_tex: Vec<Vec<String>> = a
        .iter()
        .map(|row| row.iter().map(latex).collect())
        .collect();
    let b_tex: Vec<String> = b.iter().map(latex).collect();
    if n <= MOST_COLUMNS && !by_entries {
        if let Some(whole) = whole(&labels, &x, &a_tex, &b_tex) {
            return MatrixForm {
                whole: Some(whole),
                entries: Vec::new(),
            };
        }
    }
    let mut entries = Vec::new();
    for (i, row) in a.iter().enumerate() {
        let mut label = labels[i].clone();
        let mut entry = |column: String, column_tex: String, value_tex: String| {
            entries.push(MatrixEntry {
                row: i + 1,
                column,
                value_tex,
                row_label_tex: std::mem::take(&mut label),
                column_tex,
            });
        };
        for (j, e) in row.iter().enumerate().filter(|(_, e)| !e.is_zero()) {
            // A symmetric entry refers to the one above the diagonal, written once.
            let mirror = a.get(j).and_then(|r| r.get(i));
            let value = if j < i && mirror == Some(e) {
                format!("A_{{{},{}}}", j + 1, i + 1)
            } else {
                a_tex[i][j].clone()
            };
            entry(
                (j + 1).to_string(),
                x[j].clone(),
                format!("A_{{{},{}}} = {value}", i + 1, j + 1),
            );
        }
        let groups = if b_tex[i].len() > 2 * LONG_EQUATION {
            by_rates(&b[i])
        } else {
            Vec::new()
        };
        let column_b = || "\\mathbf{b}".to_string();
        if groups.len() < 2 {
            entry(
                "b".into(),
                column_b(),
                format!("b_{{{}}} = {}", i + 1, b_tex[i]),
            );
            continue;
        }
        // Too long to read whole: b_i collected by the products of rates it holds, each
        // coefficient named and given after it.
        let name = |k: usize| format!("B_{{{},{k}}}", i + 1);
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
            format!("b_{{{}}} = {}", i + 1, sum.join(" + ")),
        );
        for (k, (_, coefficient)) in groups.iter().enumerate() {
            entry(
                "b".into(),
                column_b(),
                format!("{} = {}", name(k + 1), latex(coefficient)),
            );
        }
    }
    MatrixForm {
        whole: None,
        entries,
    }
}

/// The whole table, when it prints no wider than the line.
fn whole(labels: &[String], x: &[String], a: &[Vec<String>], b: &[String]) -> Option<WholeMatrix> {
    let widest = |column: &mut dyn Iterator<Item = &String>| {
        column.map(|t| printed_width(t)).max().unwrap_or(0) + 2
    };
    let mut width = widest(&mut labels.iter())
        + widest(&mut b.iter().chain(["\\mathbf{b}".to_string()].iter()));
    for j in 0..x.len() {
        width += widest(&mut a.iter().map(|row| &row[j]).chain([&x[j]]));
    }
    if width > TABLE_WIDTH {
        return None;
    }
    let column = |items: &[String]| {
        format!(
            "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
            items.join(" \\\\ ")
        )
    };
    let rows: Vec<String> = a.iter().map(|row| row.join(" & ")).collect();
    let mut table = format!(
        "\\begin{{array}}{{l|{}|c}} & {} & \\mathbf{{b}} \\\\ \\hline",
        "c".repeat(x.len()),
        x.join(" & ")
    );
    for (i, row) in a.iter().enumerate() {
        table.push_str(&format!(
            " {} & {} & {} \\\\",
            labels[i],
            row.join(" & "),
            b[i]
        ));
    }
    table.push_str(" \\end{array}");
    Some(WholeMatrix {
        a_tex: format!(
            "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
            rows.join(" \\\\ ")
        ),
        x_tex: column(x),
        b_tex: column(b),
        table_tex: table,
    })
}
