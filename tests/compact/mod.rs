//! Compact equations: a spring's length, unit vector and rate are named once, so that the
//! handout stays small enough to read and to compile, and the numbers do not change.

use crate::support::{problem, solve_all};
use std::path::Path;

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
/// (a row formed already simplified is written once, with no words before it).
fn simplified_equations(markdown: &str) -> Vec<String> {
    let lines: Vec<&str> = markdown.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let introduced = ["Simplified", "With the coefficients"];
        if introduced.iter().any(|s| line.starts_with(s)) || bare_row(&lines, i) {
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

/// Whether line `i` is the heading of a row formed already simplified: its one display
/// follows it directly and the next row or section follows that.
fn bare_row(lines: &[&str], i: usize) -> bool {
    let numbered = lines[i].starts_with("**") && lines[i].ends_with("**");
    let rest: Vec<&str> = lines[i + 1..]
        .iter()
        .copied()
        .filter(|l| !l.trim().is_empty())
        .collect();
    let Some(close) = rest.iter().skip(1).position(|l| l.trim() == "$$") else {
        return false;
    };
    let after = rest.get(close + 2).copied().unwrap_or("#");
    numbered && rest.first() == Some(&"$$") && (after.starts_with("**") || after.starts_with('#'))
}

/// Compiles `source` in `dir` and returns the number of pages.
fn pages(dir: &Path, source: &str) -> usize {
    std::fs::create_dir_all(dir).expect("scratch directory");
    let typeset = crate::support::pdflatex_source(dir, "x", source);
    assert!(typeset.compiled(), "does not compile: {}", typeset.faults());
    let count = typeset.pages();
    let _ = std::fs::remove_dir_all(dir);
    count
}

mod equations;
mod kinematics;
