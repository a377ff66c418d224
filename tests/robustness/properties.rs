//! Generated cases: the expression parser and the problem reader never panic or hang, and
//! every error they report says where.
//!
//! The counts below add up to 14,300 cases; `PROPTEST_CASES=N` runs N cases in each suite
//! instead (the long campaign in TESTING.md).

use super::generate::{self, CONSTANTS, COORDINATES, FRAMES};
use super::harness::check;
use super::{mutate, problem_texts};
use mbd_tutor::symbolic::{latex, parse, plain, Expr, ParseError, Resolve, Symbol};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use serde_json::Value;

/// A small name scope: three constants, two coordinates with rates, time and two frames.
struct Scope;

impl Resolve for Scope {
    fn name(&self, name: &str, primes: u8, column: usize) -> Result<Expr, ParseError> {
        if CONSTANTS.contains(&name) && primes == 0 {
            Ok(Expr::constant(name))
        } else if COORDINATES.contains(&name) && primes <= 2 {
            Ok(Expr::coord(name, primes))
        } else if name == "t" && primes == 0 {
            Ok(Expr::time())
        } else {
            Err(ParseError::new(column, format!("unknown name `{name}`")))
        }
    }

    fn unit_vector(&self, frame: &str, axis: &str, column: usize) -> Result<Expr, ParseError> {
        let index = ["x", "y", "z"].iter().position(|a| *a == axis);
        match index {
            Some(i) if FRAMES.contains(&frame) => {
                Ok(Expr::sym(Symbol::UnitVector(frame.into(), i as u8)))
            }
            _ => Err(ParseError::new(
                column,
                format!("no unit vector `{frame}.{axis}`"),
            )),
        }
    }
}

/// Parses `text`: a result, or an error whose column lies inside the text (or just past
/// its end) with a message. A result must print as LaTeX without panicking.
pub fn parses_or_says_where(text: &str) -> Result<(), TestCaseError> {
    match parse(text, &Scope) {
        Ok(e) => {
            let _ = latex(&e);
            let _ = plain(&e);
            Ok(())
        }
        Err(e) => {
            let end = text.chars().count() + 1;
            prop_assert!(
                (1..=end).contains(&e.column),
                "column {} outside 1..={end} for {text:?}: {}",
                e.column,
                e.message
            );
            prop_assert!(!e.message.is_empty(), "an empty message for {text:?}");
            Ok(())
        }
    }
}

/// Loads `text`: a problem, or errors that each name a JSON path, except that a text that
/// is not JSON, or whose top level is not an object, gets one error about the file.
pub fn loads_or_says_where(text: &str) -> Result<(), TestCaseError> {
    let Err(errors) = mbd_tutor::problem::load(text) else {
        return Ok(());
    };
    let report = errors.to_string();
    prop_assert!(!errors.0.is_empty(), "an error without errors: {report}");
    prop_assert!(errors.0.iter().all(|e| !e.message.is_empty()), "{report}");
    let pathless = errors.0.iter().filter(|e| e.path.is_empty()).count();
    match serde_json::from_str::<Value>(text) {
        // Not JSON: one error about the file.
        Err(_) => prop_assert!(errors.0.len() == 1 && pathless == 1, "{report}"),
        // Every error names its path.
        Ok(Value::Object(_)) => prop_assert!(pathless == 0, "errors without a JSON path: {report}"),
        // The top level is not an object: that one error has no path; repeated keys
        // inside it still name theirs.
        Ok(_) => prop_assert!(pathless == 1, "{report}"),
    }
    Ok(())
}

#[test]
fn parser_on_token_soup() {
    check(
        "parser_on_token_soup",
        3_000,
        generate::token_soup,
        |text| parses_or_says_where(text),
    );
}

#[test]
fn parser_on_well_formed_expressions() {
    check(
        "parser_on_well_formed_expressions",
        2_000,
        generate::well_formed,
        |text| parses_or_says_where(text),
    );
}

#[test]
fn reader_on_random_json() {
    check(
        "reader_on_random_json",
        1_500,
        generate::json_value,
        |value| loads_or_says_where(&mutate::write(value)),
    );
}

#[test]
fn reader_on_problem_shaped_json() {
    check(
        "reader_on_problem_shaped_json",
        1_500,
        generate::problem_shaped,
        |value| loads_or_says_where(&mutate::write(value)),
    );
}

fn mutated_problems() -> impl Strategy<Value = (usize, Vec<(usize, generate::Mutation)>)> {
    (
        any::<usize>(),
        proptest::collection::vec(generate::mutation(), 1..5),
    )
}

#[test]
fn reader_on_mutated_problems() {
    let texts = problem_texts();
    let originals: Vec<Value> = texts
        .iter()
        .map(|(name, text)| {
            serde_json::from_str(text).unwrap_or_else(|e| panic!("{name} is not JSON: {e}"))
        })
        .collect();
    check(
        "reader_on_mutated_problems",
        4_000,
        mutated_problems,
        move |(which, mutations)| {
            let mut value = originals[which % originals.len()].clone();
            for (at, mutation) in mutations {
                mutate::apply(&mut value, *at, mutation);
            }
            loads_or_says_where(&mutate::write(&value))
        },
    );
}

static DERIVED: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

/// Mutations that keep most problems valid: numbers made extreme, strings and numbers
/// swapped for others of the same document, a token inserted into a string.
fn gentle_mutations() -> impl Strategy<Value = (usize, Vec<(usize, generate::Mutation)>)> {
    let gentle = prop_oneof![
        any::<usize>().prop_map(generate::Mutation::Borrow),
        proptest::sample::select(&["0", "-", "*0", "+q1", "*1e300", "/0", "^9"][..])
            .prop_map(|t| generate::Mutation::Perturb(t.to_string())),
        generate::json_number().prop_map(generate::Mutation::Replace),
    ];
    (
        any::<usize>(),
        proptest::collection::vec((any::<usize>(), gentle), 1..3),
    )
}

/// The small bundled problems, whose derivation takes milliseconds.
const SMALL: [&str; 5] = [
    "simple-pendulum",
    "double-pendulum-rods",
    "two-mass-spring-damper",
    "compound-pendulum",
    "cart-pole",
];

/// Mutated small problems that still load go through the whole derivation and a solve
/// at their initial state: an error is fine, a panic or a hang is not.
#[test]
fn pipeline_on_mutated_small_problems() {
    use mbd_tutor::equations::Method;
    use mbd_tutor::numeric::Compiled;
    use mbd_tutor::pipeline::{derive, Purpose};
    let originals: Vec<Value> = problem_texts()
        .iter()
        .filter(|(name, _)| SMALL.iter().any(|s| name.ends_with(&format!("/{s}.json"))))
        .map(|(_, text)| serde_json::from_str(text).expect("JSON"))
        .collect();
    assert_eq!(originals.len(), SMALL.len());
    check(
        "pipeline_on_mutated_small_problems",
        300,
        gentle_mutations,
        move |(which, mutations)| {
            let mut value = originals[which % originals.len()].clone();
            for (at, mutation) in mutations {
                mutate::apply(&mut value, *at, mutation);
            }
            let Ok(problem) = mbd_tutor::problem::load(&mutate::write(&value)) else {
                return Ok(());
            };
            DERIVED.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let method = Method::ALL[which % Method::ALL.len()];
            if let Ok(derivation) = derive(&problem, method, Purpose::Rows) {
                let q: Vec<f64> = problem.initial_coordinates();
                let rates: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
                let _ = Compiled::new(&derivation).solve(0.0, &q, &rates);
            }
            Ok(())
        },
    );
    eprintln!(
        "derived {}",
        DERIVED.load(std::sync::atomic::Ordering::Relaxed)
    );
}

/// A compiled program gives what walking the expression gives: the compiler's sharing,
/// factoring and reordering change the order of additions, never the value.
pub fn compiles_to_the_same_value(text: &str) -> Result<(), TestCaseError> {
    use mbd_tutor::symbolic::{eval, Program, Values};
    let Ok(e) = parse(text, &Scope) else {
        return Ok(());
    };
    if e.any_symbol(&|s| matches!(s, Symbol::UnitVector(..))) {
        return Ok(());
    }
    let mut inputs = vec![Symbol::Time];
    let mut values = vec![0.7];
    for (i, name) in ["m", "L", "g"].iter().enumerate() {
        inputs.push(Symbol::Const((*name).into()));
        values.push(1.3 + 0.4 * i as f64);
    }
    for (i, name) in COORDINATES.iter().enumerate() {
        for order in 0..3u8 {
            inputs.push(Symbol::Coord((*name).into(), order));
            values.push(0.45 - 0.8 * i as f64 + 0.3 * order as f64);
        }
    }
    let mut walk = Values::new();
    for (symbol, value) in inputs.iter().zip(&values) {
        walk.set(symbol.clone(), *value);
    }
    let expected = eval(&e, &walk);
    let got = Program::compile(&inputs, std::slice::from_ref(&e)).eval(&values)[0];
    // Terms of 1e13 or more that cancel leave no digits of the result to compare: the order
    // of the additions decides them.
    let huge_term = text
        .split(|c: char| !c.is_ascii_digit())
        .any(|digits| digits.len() > 12);
    if expected.is_finite() && expected.abs() < 1e12 && !huge_term {
        prop_assert!(
            (got - expected).abs() <= 1e-9 * (1.0 + expected.abs()),
            "compiled {got} but the tree walk gives {expected} for {text:?}"
        );
    }
    Ok(())
}

#[test]
fn compiled_programs_agree_with_the_tree_walk() {
    check(
        "compiled_programs_agree_with_the_tree_walk",
        2_000,
        generate::well_formed,
        |text| compiles_to_the_same_value(text),
    );
}
