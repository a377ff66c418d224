//! Every given value of a bundled problem is in its statement: each constant, and each
//! initial value and rate of a coordinate the problem gives (not one solved from the
//! constraints), appears there by its value (as written, in scientific notation, or an
//! angle in degrees) or by its symbol in the statement's math. A value written as an
//! expression of constants is given when those constants are.

use crate::support::all_problems;
use serde_json::Value;

const GREEK: [&str; 19] = [
    "alpha", "beta", "gamma", "delta", "epsilon", "theta", "phi", "psi", "omega", "mu", "tau",
    "sigma", "rho", "eta", "kappa", "lambda", "nu", "xi", "zeta",
];

/// How a statement may write the symbol `name` in its math: `mA` as `m_A` or `m_{A}`,
/// `alpha` as `\alpha`.
fn symbols(name: &str) -> Vec<String> {
    let tex = |part: &str| {
        if GREEK.contains(&part) {
            format!("\\{part}")
        } else {
            part.to_string()
        }
    };
    let mut out = vec![name.to_string(), tex(name)];
    for k in 1..name.len() {
        let (head, tail) = name.split_at(k);
        out.push(format!("{}_{tail}", tex(head)));
        out.push(format!("{}_{{{tail}}}", tex(head)));
    }
    out
}

/// How a statement may write the number `v`, spaces removed.
fn numbers(v: f64) -> Vec<String> {
    let mut out = vec![format!("{v}")];
    if v != 0.0 {
        let exponent = v.abs().log10().floor() as i32;
        let mantissa = v / 10f64.powi(exponent);
        let mantissa = format!("{}", (mantissa * 1e6).round() / 1e6);
        for times in ["\\times", "×", "\\cdot"] {
            out.push(format!("{mantissa}{times}10^{{{exponent}}}"));
        }
        let degrees = v.to_degrees();
        if (degrees - degrees.round()).abs() < 1e-3 {
            let d = degrees.round() as i64;
            out.extend([
                format!("{d}°"),
                format!("{d}^\\circ"),
                format!("{d}^{{\\circ}}"),
            ]);
        }
    }
    out
}

/// The statement's math, `$…$` pieces joined.
fn math(statement: &str) -> String {
    statement
        .split('$')
        .skip(1)
        .step_by(2)
        .collect::<Vec<_>>()
        .join(" ")
}

/// Whether `symbol` stands alone in `math`: no letter or backslash before, no letter after.
fn stands_alone(math: &str, symbol: &str) -> bool {
    math.match_indices(symbol).any(|(at, _)| {
        let before = math[..at].chars().next_back();
        let after = math[at + symbol.len()..].chars().next();
        !before.is_some_and(|c| c.is_ascii_alphabetic() || c == '\\')
            && !after.is_some_and(|c| c.is_ascii_alphabetic())
    })
}

/// Whether the number `written` stands alone in `text`: no digit or point on either side.
fn number_alone(text: &str, written: &str) -> bool {
    let digit = |c: Option<char>| c.is_some_and(|c| c.is_ascii_digit() || c == '.');
    text.match_indices(written).any(|(at, _)| {
        !digit(text[..at].chars().next_back()) && !digit(text[at + written.len()..].chars().next())
    })
}

/// The value of a constant or coordinate entry (a number, or an object with `key`).
fn value_of(entry: &Value, key: &str) -> Option<Value> {
    match entry {
        Value::Object(map) => map.get(key).cloned(),
        other if key == "value" => Some(other.clone()),
        _ => None,
    }
}

/// What of `problem` its statement does not give, e.g. `mA = 0.5`.
fn missing(problem: &Value) -> Vec<String> {
    let statement = problem["statement"].as_str().unwrap_or_default();
    let flat: String = (statement.replace("\\,", "").replace("\\ ", ""))
        .chars()
        .filter(|c| !c.is_whitespace())
        .collect();
    let math = math(statement);
    let constants: Vec<&String> = (problem["constants"].as_object())
        .map(|c| c.keys().collect())
        .unwrap_or_default();
    let by_symbol = |name: &str| symbols(name).iter().any(|s| stands_alone(&math, s));
    // A coordinate's value is given by its number: its symbol is in any statement that
    // names the coordinate. A constant's may be given by its symbol.
    let given = |name: Option<&str>, value: &Value| match value {
        Value::Number(n) => {
            let v = n.as_f64().unwrap_or(f64::NAN);
            // A zero is given by "at rest", "no", "from rest".
            v == 0.0
                || numbers(v).iter().any(|w| number_alone(&flat, w))
                || name.is_some_and(by_symbol)
        }
        // An expression of constants is given with them (each checked as a constant).
        Value::String(text) => text
            .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .filter(|w| w.starts_with(|c: char| c.is_ascii_alphabetic()))
            .filter(|w| !["pi", "sin", "cos", "sqrt"].contains(w))
            .all(|w| constants.iter().any(|c| c.as_str() == w)),
        _ => true,
    };
    let mut out = Vec::new();
    for (name, entry) in problem["constants"].as_object().into_iter().flatten() {
        if let Some(value) = value_of(entry, "value").filter(|v| !given(Some(name), v)) {
            out.push(format!("{name} = {value}"));
        }
    }
    for (name, entry) in problem["coordinates"].as_object().into_iter().flatten() {
        if entry["dependent"] == true {
            continue;
        }
        for key in ["initial", "rate"] {
            let value = value_of(entry, key).unwrap_or(Value::from(0));
            let zero = value.as_f64() == Some(0.0);
            // A rate solved from the constraints is not given.
            let solved = key == "rate" && entry["dependent_rate"] == true;
            if !zero && !solved && !given(None, &value) {
                out.push(format!("{name} {key} = {value}"));
            }
        }
    }
    out
}

#[test]
fn a_value_is_found_by_its_number_or_its_symbol() {
    let problem: Value = serde_json::from_str(
        r#"{"statement": "Given $m_A = 0.5$ kg, $\\alpha = 30^\\circ$ and $I = 2 \\times 10^{-4}$, released at $x = 0.05$ m:",
            "constants": {"mA": 0.5, "alpha": {"value": 0.5235987755982988}, "I": 0.0002, "mB": 3},
            "coordinates": {"x": {"initial": 0.05, "rate": 8}, "y": {"initial": 1, "dependent": true}}}"#,
    )
    .expect("json");
    assert_eq!(missing(&problem), ["mB = 3", "x rate = 8"]);
    assert!(stands_alone("m_A = 1", "m_A") && !stands_alone("\\mu_A", "u_A"));
    assert!(number_alone("x=0.3m", "0.3") && !number_alone("30^\\circ", "3"));
}

#[test]
fn every_bundled_statement_gives_every_value_of_its_problem() {
    let mut wrong = Vec::new();
    for path in all_problems() {
        let text = std::fs::read_to_string(&path).expect("readable");
        let problem: Value = serde_json::from_str(&text).expect("json");
        if problem["statement"].as_str().is_none() {
            continue;
        }
        for item in missing(&problem) {
            wrong.push(format!("{}: {item}", path.display()));
        }
    }
    assert!(
        wrong.is_empty(),
        "not in the statement:\n{}",
        wrong.join("\n")
    );
}

/// A question whose value is an expression (`x'' + s''`) names its unit: the answer is
/// printed with it (`1.09091 m/s²`), which the program cannot tell from a sum alone.
#[test]
fn every_bundled_question_of_an_expression_names_its_unit() {
    let mut wrong = Vec::new();
    for path in all_problems() {
        let text = std::fs::read_to_string(&path).expect("readable");
        let problem: Value = serde_json::from_str(&text).expect("json");
        let questions = problem["find"]["questions"].as_array().cloned();
        for question in questions.unwrap_or_default() {
            let Some(value) = question["value"].as_str() else {
                continue;
            };
            let expression = value.contains([' ', '+', '-', '*', '/', '^']);
            if expression && question.get("unit").is_none() {
                wrong.push(format!("{}: {value}", path.display()));
            }
        }
    }
    assert!(wrong.is_empty(), "no unit:\n{}", wrong.join("\n"));
}
