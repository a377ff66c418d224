//! Named hostile inputs: deep nesting, huge text, huge exponents, NaN and infinity,
//! division by zero, bytes that are not UTF-8 and empty files. Each is read with the
//! library (no panic, an error that says where, within seconds) and the worst through the
//! binary as well (no crash: exit status 1 and a message).

use super::harness::within;
use super::properties::{loads_or_says_where, parses_or_says_where};
use super::scratch;
use mbd_tutor::problem::{load, load_file, ProblemError};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const LIMIT: Duration = Duration::from_secs(20);

/// A valid one-body problem with `MASS` and `TITLE` to be replaced.
const TEMPLATE: &str = r#"{
  "title": "TITLE",
  "dimension": 2,
  "constants": { "m": 1.0, "L": 1.0, "g": 9.81 },
  "coordinates": { "q1": { "initial": 0.1, "rate": 0.0 } },
  "gravity": "-g*N.y",
  "bodies": { "A": { "mass": "MASS", "center": "-L*A.y", "inertia": "0" } },
  "joints": [ { "name": "O", "type": "revolute", "parent": "N", "child": "A", "coordinates": ["q1"] } ],
  "loads": [ { "name": "push", "type": "force", "on": "A", "vector": "FORCE" } ]
}"#;

fn problem(title: &str, mass: &str, force: &str) -> String {
    TEMPLATE
        .replace("TITLE", title)
        .replace("MASS", mass)
        .replace("FORCE", force)
}

/// The errors of loading `text`, checked to be well formed, within [`LIMIT`].
fn errors(what: &str, text: String) -> Vec<ProblemError> {
    within(what, LIMIT, move || {
        if let Err(e) = loads_or_says_where(&text) {
            panic!("{e}");
        }
        load(&text).err().map(|e| e.0).unwrap_or_default()
    })
}

/// The one error of loading `text`, with its path and message.
fn only_error(what: &str, text: String) -> (String, String) {
    let errors = errors(what, text);
    assert_eq!(errors.len(), 1, "{what}: {errors:?}");
    (errors[0].path.clone(), errors[0].message.clone())
}

#[test]
fn the_template_is_valid() {
    assert!(errors("template", problem("t", "m", "0*N.x")).is_empty());
}

#[test]
fn json_nested_10000_deep_is_an_error() {
    // serde_json stops at 128 levels, before any recursion of ours can overflow the stack.
    let deep = format!("{}{}", "[".repeat(10_000), "]".repeat(10_000));
    let (path, message) = only_error("10,000 arrays", deep);
    assert_eq!(path, "");
    assert!(message.contains("nested more than 128 levels"), "{message}");
    let objects = format!("{}1{}", r#"{"a":"#.repeat(10_000), "}".repeat(10_000));
    let (_, message) = only_error("10,000 objects", objects);
    assert!(message.contains("nested more than 128 levels"), "{message}");
    let inside = problem("t", "m", "0*N.x").replace(
        "\"dimension\": 2",
        &format!(
            "\"dimension\": {}2{}",
            "[".repeat(10_000),
            "]".repeat(10_000)
        ),
    );
    let (_, message) = only_error("10,000 arrays in a value", inside);
    assert!(message.contains("line 3"), "{message}");
}

#[test]
fn json_nested_within_the_limit_names_the_path() {
    let nested = format!("{}2{}", "[".repeat(100), "]".repeat(100));
    let text =
        problem("t", "m", "0*N.x").replace("\"dimension\": 2", &format!("\"dimension\": {nested}"));
    let (path, message) = only_error("100 arrays", text);
    assert_eq!(path, "dimension");
    assert!(message.contains("must be 2 or 3"), "{message}");
}

#[test]
fn expression_nested_10000_deep_is_an_error_with_a_column() {
    for (what, mass) in [
        (
            "parentheses",
            format!("{}m{}", "(".repeat(10_000), ")".repeat(10_000)),
        ),
        ("signs", format!("{}m", "-".repeat(10_000))),
        ("powers", format!("m{}", "^m".repeat(10_000))),
        (
            "functions",
            format!("{}m{}", "sin(".repeat(10_000), ")".repeat(10_000)),
        ),
    ] {
        let errors = errors(what, problem("t", &mass, "0*N.x"));
        assert_eq!(errors.len(), 1, "{what}: {errors:?}");
        assert_eq!(errors[0].path, "bodies.A.mass", "{what}");
        assert!(errors[0].column.is_some(), "{what}: {errors:?}");
        assert!(errors[0].message.contains("deep"), "{what}: {errors:?}");
    }
    let mut text = String::new();
    for _ in 0..10_000 {
        text.push('(');
    }
    parses_or_says_where(&text).unwrap_or_else(|e| panic!("{e}"));
}

#[test]
fn a_one_megabyte_string() {
    let huge = "x".repeat(1 << 20);
    // As a title it is only text: the problem is valid.
    assert!(errors("1 MB title", problem(&huge, "m", "0*N.x")).is_empty());
    // As an expression it is refused by length, not parsed.
    let long_sum = "m+".repeat(1 << 19) + "m";
    let (path, message) = only_error("1 MB expression", problem("t", &long_sum, "0*N.x"));
    assert_eq!(path, "bodies.A.mass");
    assert!(message.contains("bytes long"), "{message}");
    // As a key, and as a number literal of a million digits.
    let key = problem("t", "m", "0*N.x").replace("\"title\"", &format!("\"{huge}\": 1, \"title\""));
    let errors = errors("1 MB key", key);
    assert!(
        errors.iter().any(|e| e.message.contains("unknown key")),
        "{errors:?}"
    );
    let digits = "9".repeat(1 << 20);
    let number = problem("t", "m", "0*N.x").replace("\"m\": 1.0", &format!("\"m\": {digits}"));
    let (path, message) = only_error("a million digits", number);
    assert_eq!(path, "");
    assert!(message.contains("out of range"), "{message}");
}

#[test]
fn huge_exponents() {
    // m = L = 1 and g = 9.81: 1^1e308 is 1, a valid mass; the others overflow or vanish.
    assert!(errors("m^1e308", problem("t", "m^1e308", "0*N.x")).is_empty());
    for mass in ["2^1e308", "g^1e308", "2^99999999", "(g+L)^99999999"] {
        let errors = errors(mass, problem("t", mass, "0*N.x"));
        assert!(!errors.is_empty(), "{mass} accepted as a mass");
        assert!(
            errors.iter().all(|e| e.path == "bodies.A.mass"),
            "{mass}: {errors:?}"
        );
    }
    // Those that vanish make a mass 0, a massless body: valid as a value (the model then
    // refuses it when nothing fixes its coordinate), never a panic.
    for mass in ["2^(-9223372036854775807)", "g^-1e308"] {
        let errors = errors(mass, problem("t", mass, "0*N.x"));
        assert!(
            errors.iter().all(|e| e.path == "bodies.A.mass"),
            "{mass}: {errors:?}"
        );
    }
    // In a force the coordinates may appear: a huge power is kept, not expanded.
    for force in [
        "q1^99999999*N.x",
        "(q1+1)^99999999*N.x",
        "q1^1e308*N.x",
        "(sin(q1)+m)^99999999*N.x",
    ] {
        let _ = errors(force, problem("t", "m", force));
    }
}

#[test]
fn nan_and_infinity_are_not_numbers() {
    let base = problem("t", "m", "0*N.x");
    for (literal, expect) in [
        ("NaN", "not valid JSON"),
        ("Infinity", "not valid JSON"),
        ("-Infinity", "not valid JSON"),
        ("1e999", "out of range"),
    ] {
        let (path, message) = only_error(
            literal,
            base.replace("\"L\": 1.0", &format!("\"L\": {literal}")),
        );
        assert_eq!(path, "", "{literal}");
        assert!(message.contains(expect), "{literal}: {message}");
    }
    for literal in ["\"NaN\"", "\"inf\"", "\"Infinity\"", "\"1e999\""] {
        let (path, message) = only_error(
            literal,
            base.replace("\"L\": 1.0", &format!("\"L\": {literal}")),
        );
        assert_eq!(path, "constants.L", "{literal}");
        assert!(!message.is_empty());
    }
    for mass in ["1e999", "m*1e308*1e308", "NaN", "inf"] {
        let errors = errors(mass, problem("t", mass, "0*N.x"));
        assert!(!errors.is_empty(), "{mass} accepted as a mass");
        assert!(
            errors.iter().all(|e| e.path == "bodies.A.mass"),
            "{mass}: {errors:?}"
        );
    }
}

#[test]
fn division_by_zero_in_a_constant() {
    for mass in [
        "m/0", "m/(L-L)", "m/(L-1)", "1/(m-1)", "m/sin(0)", "ln(0)", "sqrt(-1)",
    ] {
        let errors = errors(mass, problem("t", mass, "0*N.x"));
        assert!(!errors.is_empty(), "{mass} accepted as a mass");
        assert!(
            errors.iter().all(|e| e.path == "bodies.A.mass"),
            "{mass}: {errors:?}"
        );
    }
    let errors = errors("m/0", problem("t", "m/0", "0*N.x"));
    assert_eq!(errors.len(), 1, "{errors:?}");
    assert!(errors[0].message.contains("evaluates to inf"), "{errors:?}");
    let hint = errors[0].hint.as_deref().unwrap_or_default();
    assert!(hint.contains("division by zero"), "{errors:?}");
}

/// Regression: `Number::powi` negated its exponent to take a reciprocal; for `i64::MIN`
/// that wrapped and it recursed until the stack overflowed (the process aborted, status
/// 134). Run in a child process so that such an abort cannot take the test binary along.
#[test]
fn the_smallest_integer_exponent_does_not_crash() {
    let (code, stderr) = binary_check(
        problem("t", "2^(-9223372036854775807-1)", "0*N.x").as_bytes(),
        "smallest-exponent",
    );
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stderr.contains("bodies.A.mass"), "{stderr}");
}

/// Runs `check` on `bytes` in a file; a run still going after [`LIMIT`] is killed and
/// fails the test.
fn binary_check(bytes: &[u8], test: &str) -> (Option<i32>, String) {
    let dir = scratch(test);
    let file = dir.join("problem.json");
    std::fs::write(&file, bytes).expect("the problem is written");
    let mut child = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .arg("check")
        .arg(&file)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let mut pipe = child.stderr.take().expect("piped");
    let reader = std::thread::spawn(move || {
        let mut text = String::new();
        let _ = std::io::Read::read_to_string(&mut pipe, &mut text);
        text
    });
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("waitable") {
            break status;
        }
        if started.elapsed() > LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{test}: check still running after {LIMIT:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let stderr = reader.join().unwrap_or_default();
    std::fs::remove_dir_all(&dir).expect("the scratch directory is removed");
    (status.code(), stderr)
}

#[test]
fn bytes_that_are_not_utf8() {
    let dir = scratch("not-utf8-library");
    for (name, bytes) in [
        ("latin1", b"{\"title\": \"caf\xe9\"}".to_vec()),
        ("lone continuation byte", b"\x80{}".to_vec()),
        ("utf16", b"\xff\xfe{\x00}\x00".to_vec()),
        ("bom then junk", b"\xef\xbb\xbf\xff".to_vec()),
    ] {
        let file = dir.join("problem.json");
        std::fs::write(&file, &bytes).expect("written");
        match load_file(&file) {
            Err(mbd_tutor::problem::LoadError::Invalid(errors)) => {
                assert_eq!(errors.0.len(), 1, "{name}");
                assert!(
                    errors.0[0].message.contains("not UTF-8"),
                    "{name}: {errors}"
                );
            }
            other => panic!("{name}: {other:?}"),
        }
    }
    std::fs::remove_dir_all(&dir).expect("removed");
    let (code, stderr) = binary_check(b"{\"title\": \"\xc3\x28\"}", "not-utf8-binary");
    assert_eq!(code, Some(1), "{stderr}");
    assert!(
        stderr.contains("not UTF-8 text: the byte at offset 11"),
        "{stderr}"
    );
}

#[test]
fn empty_files() {
    for (name, bytes) in [
        ("empty", &b""[..]),
        ("blank", b" \n\t\r\n"),
        ("bom only", b"\xef\xbb\xbf"),
    ] {
        let (code, stderr) = binary_check(bytes, &format!("empty-{}", name.replace(' ', "-")));
        assert_eq!(code, Some(1), "{name}: {stderr}");
        assert!(stderr.contains("the file is empty"), "{name}: {stderr}");
    }
}

#[test]
fn the_worst_cases_through_the_binary() {
    let cases = [
        (
            "deep-json",
            format!("{}{}", "[".repeat(10_000), "]".repeat(10_000)),
        ),
        (
            "deep-expression",
            problem(
                "t",
                &format!("{}m{}", "(".repeat(10_000), ")".repeat(10_000)),
                "0*N.x",
            ),
        ),
        ("huge-exponent", problem("t", "2^1e308", "q1^99999999*N.x")),
        ("division-by-zero", problem("t", "m/0", "0*N.x")),
    ];
    for (name, text) in cases {
        let (code, stderr) = binary_check(text.as_bytes(), name);
        assert_eq!(code, Some(1), "{name}: {stderr}");
        assert!(stderr.starts_with("error: "), "{name}: {stderr}");
        assert!(!stderr.contains("panicked"), "{name}: {stderr}");
    }
}

/// Regression: every expression is kept expanded, and nothing bounded the expansion: this
/// mass of 16 characters, (m + L + g + pi)^64, kept `check` busy for minutes. It is
/// refused with its path, like an expression that is too long.
#[test]
fn an_expression_that_expands_past_a_bound_is_refused() {
    let (code, stderr) = binary_check(
        problem("t", "((m+L+g+pi)^8)^8", "0*N.x").as_bytes(),
        "expansion",
    );
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stderr.contains("bodies.A.mass"), "{stderr}");
    assert!(stderr.contains("expands to too many terms"), "{stderr}");
}

/// Regression: inputs on which the parser fuzz target ran for more than 10 s (nested
/// powers of sums, expanded without a bound). Each now finishes at once.
#[test]
fn fuzz_found_expansions_finish() {
    for text in [
        "((-.22^ ---t-3--t-3^-t-3^2 / 0)^4 +-t-3--t)^6 +--t)^6 +,440",
        "((0.22^ ---t-3-q1-t-3^2 / 0)^4 +---t-3--t)^4 tan20",
        "((0.2^2 +07^((0.2^2 ^1+107 +0)/3-0.3^2 / 0)^3 +42^2226 +5)/3-((0.2^2 +07+((0.2^2 \
         +07^((N.x^2  *---t-3--t)^2 *---11 +0)/3-0.3^2 / 0)^3 +42^2226 +5)/3-0.3^2 / 0)^4 \
         +07^223370.3^2 / 0)^4 +0t-7^2233-",
    ] {
        within(text, LIMIT, move || {
            parses_or_says_where(text).unwrap_or_else(|e| panic!("{e}"));
        });
    }
}

/// Regression: `Number::exact_sqrt` squared the rounded root of an `i64` to check it, and
/// for 9223372036854775807 the square overflowed: a panic where overflow is checked
/// (`cargo test` without `--release`, the fuzz build). Found by the parser fuzz target.
#[test]
fn the_square_root_of_the_largest_integer() {
    for text in [
        "sqrt(9223372036854775807)",
        "9223372036854775807^(1/2)",
        "9223372036854775807^(-1/2)",
    ] {
        parses_or_says_where(text).unwrap_or_else(|e| panic!("{e}"));
    }
}

/// The bound on expansion covers powers of sums but not products of them: each factor
/// below is 6,435 terms, under the bound, and their product keeps `check` busy for
/// minutes. Found after the bound on powers was added (the parser fuzz target timed out on
/// `m*L^3223372036^((036^((0.2^2 --t-3^2 / 0)^4 +…)^4 +…)^4`, which takes 2 s here).
#[test]
fn a_product_of_large_sums_is_refused() {
    let sum = "(m+L+g+pi+sin(m)+cos(m)+exp(m)+atan(m))^8";
    let (code, stderr) = binary_check(
        problem("t", &format!("{sum}*{sum}"), "0*N.x").as_bytes(),
        "product-of-sums",
    );
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stderr.contains("bodies.A.mass"), "{stderr}");
}
