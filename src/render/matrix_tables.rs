//! Step 5's `A x = b` laid out as tables: whole, with a column per unknown and a row per
//! equation; by the values of its entries at the initial state; or by where it is not zero.

use super::context::WholeMatrix;
use super::math_width::printed_width;
use super::numbers::math_number;
use super::text::Math;
use crate::symbolic::{fixed_or_zero, Expr};

/// How many symbols the whole table may print across: about the width of the page.
const TABLE_WIDTH: usize = 70;

/// The most columns of numbers a table by value prints across the page; a wider system is
/// printed in blocks of columns, as a printed matrix is.
const MOST_VALUE_COLUMNS: usize = 12;

/// The most columns and rows of a table of where `A` is not zero: a column is a dot,
/// narrow, and the rows are those a page holds.
const MOST_PATTERN_COLUMNS: usize = 44;

const MOST_PATTERN_ROWS: usize = 60;

/// An entry's value at the initial state, as the tables and lists of values print it.
pub fn value_tex(initial: &impl Fn(&Expr) -> f64, e: &Expr) -> String {
    math_number(&fixed_or_zero(initial(e)))
}

/// Where `A` and `b` are not zero, a dot in a table for each, columns by number (in blocks
/// of at most `MOST_PATTERN_COLUMNS`), rows by their number in step 5: the shape of the
/// system, such as Newton–Euler's reactions shared by two bodies' rows.
pub fn pattern_tables(labels: &[String], a: &[Vec<Expr>], b: &[Expr]) -> Vec<String> {
    let dot = |e: &Expr| {
        if e.is_zero() {
            String::new()
        } else {
            "\\bullet".to_string()
        }
    };
    let n = a.first().map_or(0, Vec::len);
    let column_blocks = n.div_ceil(MOST_PATTERN_COLUMNS).max(1);
    let width = n.div_ceil(column_blocks);
    let row_blocks = a.len().div_ceil(MOST_PATTERN_ROWS).max(1);
    let height = a.len().div_ceil(row_blocks);
    let mut tables = Vec::new();
    for k in 0..column_blocks {
        let columns = k * width..((k + 1) * width).min(n);
        let heads: Vec<String> = columns.clone().map(|j| (j + 1).to_string()).collect();
        for rows in (0..row_blocks).map(|r| r * height..((r + 1) * height).min(a.len())) {
            let block: Vec<Vec<String>> = a[rows.clone()]
                .iter()
                .map(|row| row[columns.clone()].iter().map(dot).collect())
                .collect();
            let b_dots: Vec<String> = b[rows.clone()].iter().map(dot).collect();
            let b_column = (k + 1 == column_blocks).then_some(&b_dots[..]);
            tables.push(array(&labels[rows], &heads, &block, b_column));
        }
    }
    tables
}

/// `A` and `b` at the initial state as tables laid out as [`whole`] lays out the formulas,
/// in blocks of at most `MOST_VALUE_COLUMNS` columns of about equal width, `b` in the
/// last. A block leaves out the rows that are zero in all its columns, as a printed sparse
/// matrix does: a floating body's rows are zero under a chain's q̈, and a reaction's column
/// is zero but in the rows of the bodies it acts on.
pub fn value_tables(
    labels: &[String],
    x: &[String],
    a: &[Vec<Expr>],
    b: &[Expr],
    initial: &impl Fn(&Expr) -> f64,
) -> Vec<String> {
    let value = |e: &Expr| value_tex(initial, e);
    let a_values: Vec<Vec<String>> = a
        .iter()
        .map(|row| row.iter().map(value).collect())
        .collect();
    let b_values: Vec<String> = b.iter().map(value).collect();
    let blocks = x.len().div_ceil(MOST_VALUE_COLUMNS).max(1);
    let width = x.len().div_ceil(blocks);
    (0..blocks)
        .map(|k| {
            let columns = k * width..((k + 1) * width).min(x.len());
            let last = k + 1 == blocks;
            let zero = |i: usize| {
                a_values[i][columns.clone()].iter().all(|v| v == "0")
                    && (!last || b_values[i] == "0")
            };
            let mut rows: Vec<usize> = (0..a.len()).filter(|&i| !zero(i)).collect();
            if rows.is_empty() {
                rows = (0..a.len()).collect();
            }
            let pick = |items: &[String]| -> Vec<String> {
                rows.iter().map(|&i| items[i].clone()).collect()
            };
            let block: Vec<Vec<String>> = rows
                .iter()
                .map(|&i| a_values[i][columns.clone()].to_vec())
                .collect();
            let b_column = last.then(|| pick(&b_values));
            array(&pick(labels), &x[columns], &block, b_column.as_deref())
        })
        .collect()
}

/// The whole table, when it prints no wider than the line.
pub fn whole(
    labels: &[String],
    x: &[String],
    a: &[Vec<String>],
    b: &[String],
) -> Option<WholeMatrix> {
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
    Some(WholeMatrix {
        a_tex: Math::from(format!(
            "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
            rows.join(" \\\\ ")
        )),
        x_tex: Math::from(column(x)),
        b_tex: Math::from(column(b)),
        table_tex: Math::from(array(labels, x, a, Some(b))),
    })
}

/// `A`'s columns `x` (and `b` last, when given) as one `array`, a column per unknown
/// headed by it, a row per equation led by its label.
fn array(labels: &[String], x: &[String], a: &[Vec<String>], b: Option<&[String]>) -> String {
    let b_head = if b.is_some() { " & \\mathbf{b}" } else { "" };
    let mut table = format!(
        "\\begin{{array}}{{l|{}{}}} & {}{b_head} \\\\ \\hline",
        "c".repeat(x.len()),
        if b.is_some() { "|c" } else { "" },
        x.join(" & ")
    );
    // An empty cell is a bare `&`: a table of dots is mostly empty cells.
    let cells = |row: &[String]| -> String {
        row.iter()
            .map(|c| match c.as_str() {
                "" => "&".to_string(),
                c => format!("& {c} "),
            })
            .collect()
    };
    for (i, row) in a.iter().enumerate() {
        let b_entry = b.map_or(String::new(), |b| cells(&b[i..=i]));
        table.push_str(&format!(" {} {}{b_entry}\\\\", labels[i], cells(row)));
    }
    table.push_str(" \\end{array}");
    table
}
