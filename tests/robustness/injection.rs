//! The probe's payloads that reached an output: a question's symbol with HTML in it, a
//! key.csv cell a spreadsheet takes for a formula, `a^'` that stops pdflatex, units in
//! Greek letters and signs, and a body name too long for a file name.

use super::scratch;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn run(args: &[&std::ffi::OsStr]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn pendulum() -> Value {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/simple-pendulum.json"
    ))
    .expect("read");
    serde_json::from_str(&text).expect("JSON")
}

fn write(dir: &Path, name: &str, problem: &Value) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, serde_json::to_string_pretty(problem).expect("JSON")).expect("written");
    path
}

#[test]
fn a_symbol_that_is_not_math_is_refused_with_its_path() {
    let dir = scratch("symbol");
    for symbol in [
        "<img src=x onerror=alert(1)>",
        "</script>",
        "a^'",
        "$x$",
        "@SUM(A1)",
    ] {
        let mut problem = pendulum();
        problem["find"]["questions"][2]["symbol"] = Value::from(symbol);
        let file = write(&dir, "p.json", &problem);
        let output = run(&["check".as_ref(), file.as_os_str()]);
        let message = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(1), "{symbol}: {message}");
        assert!(
            message.contains("find.questions[2].symbol"),
            "{symbol}: {message}"
        );
        assert!(message.contains("hint:"), "{symbol}: {message}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn key_csv_cells_are_never_formulas() {
    let dir = scratch("key-formula");
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/simple-pendulum.json"
    ))
    .expect("read");
    let mut problem: Value = serde_json::from_str(&text).expect("JSON");
    problem["constants"]["m"] =
        serde_json::json!({ "value": 0.5, "vary": [0.4, 0.6], "step": 0.1 });
    problem["find"]["questions"][2]["symbol"] = Value::from("=1+1");
    problem["find"]["questions"][3]["symbol"] = Value::from("-x");
    let file = write(&dir, "p.json", &problem);
    let out = dir.join("hw");
    let output = run(&[
        "variants".as_ref(),
        file.as_os_str(),
        "--count".as_ref(),
        "2".as_ref(),
        "--format".as_ref(),
        "markdown".as_ref(),
        "-o".as_ref(),
        out.as_os_str(),
    ]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let key = std::fs::read_to_string(out.join("key.csv")).expect("key.csv");
    for line in key.lines() {
        for cell in line.split(',') {
            let cell = cell.trim_matches('"');
            let formula = cell.starts_with(['=', '+', '-', '@']) && cell.parse::<f64>().is_err();
            assert!(!formula, "a formula cell `{cell}` in {key}");
        }
    }
    assert!(key.contains("'=1+1") && key.contains("'-x"), "{key}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn latex_sets_scripts_units_and_long_names() {
    let dir = scratch("typeset");
    let mut problem = pendulum();
    problem["statement"] = Value::from("A pendulum: $a^'$, $x^$ and $b_}$ are text; $a<b$ too.");
    problem["constants"]["L"]["unit"] = Value::from("μm");
    problem["constants"]["m"]["unit"] = Value::from("Ω");
    problem["coordinates"]["theta"]["unit"] = Value::from("°");
    let long = "a".repeat(250);
    let bob = problem["bodies"]["bob"].take();
    problem["bodies"] = serde_json::json!({ long.clone(): bob });
    problem["joints"][0]["child"] = Value::from(long.clone());
    problem["joints"][0]["child_at"] = Value::from(format!("L*{long}.y"));
    let file = write(&dir, "p.json", &problem);
    let tex = dir.join("p.tex");
    let output = run(&[
        "explain".as_ref(),
        file.as_os_str(),
        "--format".as_ref(),
        "latex".as_ref(),
        "-o".as_ref(),
        tex.as_os_str(),
    ]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let text = std::fs::read_to_string(&tex).expect("written");
    assert!(!text.contains("a^'"), "a^' reached TeX as math");
    let pictures = dir.join("pictures");
    let output = run(&[
        "draw".as_ref(),
        file.as_os_str(),
        "-o".as_ref(),
        pictures.as_os_str(),
    ]);
    assert!(
        output.status.success(),
        "draw with a 250-letter body: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    let names: Vec<String> = std::fs::read_dir(&pictures)
        .expect("pictures")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    assert!(
        names.len() >= 2 && names.iter().all(|n| n.len() <= 110),
        "{names:?}"
    );
    if !crate::support::pdflatex_present("units and scripts") {
        return;
    }
    let typeset = crate::support::pdflatex(&dir.join("p.tex"));
    assert!(typeset.compiled(), "{}", typeset.faults());
    let _ = std::fs::remove_dir_all(&dir);
}
