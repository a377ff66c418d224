//! Step 1 gives the assembled initial state: for every bundled constrained problem, the
//! coordinate table's values and rates are `solve --format json`'s state to the digits
//! printed, a dependent one marked † (solved from the constraints or the loop's closure),
//! with a note under the table that says what the mark means.

use crate::support::{all_problems, run, run_json};
use serde_json::Value;

/// Whether a problem has anything to assemble: closures, constraints or a motion.
fn constrained(problem: &Value) -> bool {
    let listed = |key: &str| problem[key].as_array().is_some_and(|a| !a.is_empty());
    let moved = problem["coordinates"]
        .as_object()
        .is_some_and(|c| c.values().any(|c| c.get("motion").is_some()));
    listed("closures") || listed("constraints") || moved
}

/// The coordinate names in the order `solve` lists them (its text's table).
fn names(path: &std::path::Path) -> Vec<String> {
    let out = run(&["solve".as_ref(), path.as_os_str()]);
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    text.lines()
        .skip_while(|l| !l.starts_with("coordinate"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .map(|l| l.split_whitespace().next().unwrap_or_default().to_string())
        .collect()
}

/// Step 1's coordinate table: each row's value and rate cells.
fn table(markdown: &str) -> Vec<(String, String)> {
    let start = markdown
        .find("| Coordinate |")
        .expect("the coordinate table");
    markdown[start..]
        .lines()
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            let cells: Vec<&str> = l.trim_matches('|').split(" | ").collect();
            let n = cells.len();
            (
                cells[n - 2].trim().to_string(),
                cells[n - 1].trim().to_string(),
            )
        })
        .collect()
}

/// The number a cell starts with, and half a unit of its last printed digit.
fn printed(cell: &str) -> (f64, f64) {
    let number = cell.split_whitespace().next().expect("a number");
    let (mantissa, exponent) = match number.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().expect("exponent")),
        None => (number, 0),
    };
    let decimals = mantissa.split_once('.').map_or(0, |(_, d)| d.len()) as i32;
    let value: f64 = number
        .parse()
        .unwrap_or_else(|_| panic!("`{number}` in `{cell}`"));
    (value, 0.5 * 10f64.powi(exponent - decimals) * (1.0 + 1e-9))
}

#[test]
fn step_one_gives_the_assembled_state_of_every_constrained_problem() {
    let mut checked = 0;
    for path in all_problems() {
        let problem: Value =
            serde_json::from_str(&std::fs::read_to_string(&path).expect("read")).expect("json");
        if !constrained(&problem) {
            continue;
        }
        let solved = run_json(&[
            "solve".as_ref(),
            path.as_os_str(),
            "--format".as_ref(),
            "json".as_ref(),
        ]);
        let out = run(&["explain".as_ref(), path.as_os_str()]);
        assert!(out.status.success(), "{}", path.display());
        let text = String::from_utf8_lossy(&out.stdout).into_owned();
        let rows = table(&text);
        let given_problem = mbd_tutor::problem::load_file(&path).expect("a bundled problem");
        let names = names(&path);
        assert_eq!(rows.len(), names.len(), "{}", path.display());
        for (name, (value, rate)) in names.iter().zip(&rows) {
            for (cell, key, given) in [
                (value, name.clone(), "initial"),
                (rate, format!("{name}'"), "rate"),
            ] {
                let expected = solved["state"][&key].as_f64().expect("state");
                let (shown, half) = printed(cell);
                assert!(
                    (shown - expected).abs() <= half,
                    "{}: {key} printed `{cell}`, solved {expected}",
                    path.display()
                );
                // And printed to the handout's six significant digits: a starting guess
                // written short (q₂ = −0.65 for −0.65053, z = 0.1 for 0.0955336) is
                // within half its own last digit, but not the assembled value.
                assert!(
                    (shown - expected).abs() <= 5.000_001e-6 * expected.abs() + 1e-9,
                    "{}: {key} printed `{cell}`, not the solved {expected} to six digits",
                    path.display()
                );
                // A value other than the one the problem gives (a rate solved from the
                // velocity constraints, the gear's q̇_B = −2 rad/s where none is given) is
                // marked as solved too.
                // As the problem gives it (an expression of constants evaluated, left out 0).
                let coordinate = (given_problem.coordinates.iter())
                    .find(|c| c.name == *name)
                    .expect("a coordinate of the problem");
                let written = if given == "rate" {
                    coordinate.rate
                } else {
                    coordinate.initial
                };
                let solved = (written - expected).abs() > 1e-9;
                let dependent = problem["coordinates"][name]["dependent"] == true;
                // ‡: a prescribed motion's value at the start.
                if solved && !cell.ends_with(['†', '‡']) {
                    panic!(
                        "{}: {key} printed `{cell}` unmarked, not the {given} given ({written})",
                        path.display()
                    );
                }
                if dependent {
                    assert!(cell.ends_with('†'), "{}: {cell}", path.display());
                    assert!(
                        text.contains("In the table of coordinates, †: solved from"),
                        "{}: no note says what † means",
                        path.display()
                    );
                }
                // A mark, never words, after the unit: the narrow column does not wrap.
                assert!(!cell.contains('('), "{}: {cell}", path.display());
            }
        }
        checked += 1;
    }
    assert!(checked >= 10, "only {checked} constrained problems");
}
