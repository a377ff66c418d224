//! `mbd-tutor variants`: 20 variants of a rod pendulum with three varied constants. Every
//! drawn value lies in its range on its grid; every key row is what `answer --format json`
//! gives for that variant's file, and the pendulum's θ'' is its closed form; one seed
//! gives the same bytes twice, another seed other numbers; every LaTeX file compiles.
//! Then the ranges' errors, and the requests refused.

use crate::support::handouts::two_at_a_time;
use crate::support::{pdflatex, pdflatex_present, run};
use serde_json::value::RawValue;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// A uniform rod of mass m and length L pinned at O, at angle θ from N.x, with m, L and g
/// varying (g on the default grid of 3 significant digits).
fn varied_rod() -> Value {
    json!({
        "title": "Rod pendulum",
        "statement": "A uniform rod of mass $m$ and length $L$ swings about a pin at O.",
        "dimension": 2,
        "constants": {
            "m": { "value": 1.5, "vary": [0.5, 2], "step": 0.1, "unit": "kg" },
            "L": { "value": 0.8, "vary": [0.4, 1.2], "step": 0.05, "unit": "m" },
            "g": { "value": 9.81, "vary": [9.7, 9.9], "unit": "m/s^2" }
        },
        "coordinates": { "theta": { "initial": -0.7, "rate": 1.3 } },
        "gravity": "-g*N.y",
        "bodies": { "B": { "mass": "m", "center": "L/2*B.x", "inertia": "m*L^2/12" } },
        "joints": [ { "name": "O", "type": "revolute", "parent": "N", "child": "B",
                      "coordinates": ["theta"] } ],
        "find": { "reactions": ["O"], "questions": [
            { "value": "theta''", "symbol": "\\ddot{\\theta}" },
            { "reaction": "O" },
            { "value": "m*L^2/3*theta''", "unit": "N m" }
        ] },
        "simulate": { "duration": 1, "output_step": 0.01 }
    })
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("mbd-variants-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch");
    dir
}

fn variants(problem: &Path, seed: &str, out: &Path) {
    let output = run(&[
        "variants".as_ref(),
        problem.as_os_str(),
        "--count".as_ref(),
        "20".as_ref(),
        "--seed".as_ref(),
        seed.as_ref(),
        "-o".as_ref(),
        out.as_os_str(),
    ]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// The key's header and rows.
fn key(dir: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(dir.join("key.csv")).expect("key.csv");
    let mut lines = text
        .lines()
        .map(|l| l.split(',').map(String::from).collect::<Vec<_>>());
    let header = lines.next().expect("a header");
    (header, lines.collect())
}

/// The files of a directory with their bytes, by name.
fn contents(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .expect("dir")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.is_file())
        .map(|p| {
            let bytes = std::fs::read(&p).expect("read");
            (p.file_name().unwrap().to_string_lossy().into_owned(), bytes)
        })
        .collect();
    files.sort();
    files
}

#[test]
fn twenty_variants_draw_on_their_grids_and_the_key_is_what_answer_gives() {
    let dir = scratch("twenty");
    let problem = dir.join("rod.json");
    std::fs::write(
        &problem,
        serde_json::to_string_pretty(&varied_rod()).unwrap(),
    )
    .unwrap();
    let first = dir.join("first");
    variants(&problem, "2026", &first);
    let (header, rows) = key(&first);
    assert_eq!(
        header,
        [
            "file",
            "seed",
            "redraws",
            "m",
            "L",
            "g",
            "\\ddot{\\theta}",
            "1.x@N",
            "1.y@N",
            "2"
        ]
    );
    assert_eq!(rows.len(), 20);
    let on_grid = |x: f64, origin: f64, step: f64, low: f64, high: f64, what: &str| {
        assert!(
            (low..=high).contains(&x),
            "{what} = {x} outside [{low}, {high}]"
        );
        let k = (x - origin) / step;
        assert!(
            (k - k.round()).abs() < 1e-9,
            "{what} = {x} is off the grid {step}"
        );
    };
    let mut drawn = Vec::new();
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(row[0], format!("variant-{:02}.json", i + 1));
        let number = |j: usize| -> f64 { row[j].parse().expect("a number") };
        let (m, l, g) = (number(3), number(4), number(5));
        on_grid(m, 0.5, 0.1, 0.5, 2.0, "m");
        on_grid(l, 0.4, 0.05, 0.4, 1.2, "L");
        // 3 significant digits: multiples of 0.01.
        on_grid(g, 0.0, 0.01, 9.7, 9.9, "g");
        drawn.push((m, l, g));
        // The variant's file: the problem with the drawn values, `vary` and `step` gone.
        let file = first.join(&row[0]);
        let variant: Value =
            serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
        let mut expected = varied_rod();
        for (name, value) in [("m", m), ("L", l), ("g", g)] {
            let fields = expected["constants"][name].as_object_mut().unwrap();
            fields.remove("vary");
            fields.remove("step");
            fields.insert("value".into(), json!(value));
        }
        assert_eq!(variant, expected, "{}", row[0]);
        // Each key row is `answer --format json` of the variant's file, number for number.
        let output = run(&[
            "answer".as_ref(),
            file.as_os_str(),
            "--format".as_ref(),
            "json".as_ref(),
        ]);
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        let printed = printed_answers(&output.stdout);
        assert_eq!(row[6..], printed, "{}", row[0]);
        // And θ'' is the closed form, −3 g cos θ / (2 L).
        let theta_dd = -3.0 * g / (2.0 * l) * (-0.7f64).cos();
        assert!(
            (number(6) - theta_dd).abs() < 1e-10 * theta_dd.abs(),
            "{}",
            row[0]
        );
        // Both handouts are there.
        for suffix in [".tex", "-student.tex"] {
            let name = row[0].replace(".json", suffix);
            assert!(first.join(&name).is_file(), "{name}");
        }
    }
    // The draws are not all alike.
    assert!(drawn.iter().any(|d| *d != drawn[0]));

    let again = dir.join("again");
    variants(&problem, "2026", &again);
    assert!(
        contents(&first) == contents(&again),
        "one seed, other bytes"
    );

    let other = dir.join("other");
    variants(&problem, "7", &other);
    let (_, other_rows) = key(&other);
    let constants =
        |rows: &[Vec<String>]| rows.iter().map(|r| r[3..6].to_vec()).collect::<Vec<_>>();
    assert_ne!(
        constants(&rows),
        constants(&other_rows),
        "another seed, the same numbers"
    );

    every_latex_file_compiles(&first);
}

/// The numbers of `answer --format json` as printed (not read back, which may move the
/// last digit): θ'', the reaction's x and y, the third value.
fn printed_answers(stdout: &[u8]) -> Vec<String> {
    type Fields<'a> = std::collections::HashMap<&'a str, &'a RawValue>;
    #[derive(serde::Deserialize)]
    struct Sheet<'a> {
        #[serde(borrow)]
        answers: Vec<Fields<'a>>,
    }
    let sheet: Sheet = serde_json::from_slice(stdout).expect("answer JSON");
    let a = &sheet.answers;
    let components: Fields = serde_json::from_str(a[1]["components"].get()).expect("components");
    [
        a[0]["value"],
        components["x"],
        components["y"],
        a[2]["value"],
    ]
    .iter()
    .map(|raw| raw.get().to_string())
    .collect()
}

/// Every `.tex` of `dir` compiles, two at a time.
fn every_latex_file_compiles(dir: &Path) {
    if !pdflatex_present("the variants' LaTeX") {
        return;
    }
    let files: Vec<PathBuf> = contents(dir)
        .into_iter()
        .filter(|(n, _)| n.ends_with(".tex"))
        .map(|(n, _)| dir.join(n))
        .collect();
    assert_eq!(
        files.len(),
        40,
        "a worked solution and a handout per variant"
    );
    let failed = two_at_a_time(&files, |tex| {
        let typeset = pdflatex(tex);
        if typeset.compiled() {
            return Vec::new();
        }
        vec![format!(
            "{} does not compile: {}",
            tex.display(),
            typeset.faults()
        )]
    });
    assert!(failed.is_empty(), "{}", failed.join("\n"));
}

/// The errors `check` gives for a constant `m` written as `fields`.
fn range_errors(fields: Value) -> String {
    let mut problem = varied_rod();
    problem["constants"]["m"] = fields;
    let errors = mbd_tutor::problem::load(&problem.to_string()).expect_err("invalid");
    errors.to_string()
}

#[test]
fn a_range_that_cannot_be_drawn_from_is_an_error_with_its_path_and_a_hint() {
    let cases = [
        (
            json!({ "value": 1, "vary": [2, 0.5] }),
            "constants.m.vary",
            "above its high end",
        ),
        (
            json!({ "value": 1, "vary": [1, 1] }),
            "constants.m.vary",
            "one value",
        ),
        (
            json!({ "value": 1, "vary": [0.5, 2], "step": 0 }),
            "constants.m.step",
            "must be positive",
        ),
        (
            json!({ "value": 1, "vary": [0.5, 2], "step": -0.1 }),
            "constants.m.step",
            "must be positive",
        ),
        (
            json!({ "value": 1, "vary": [0.5, 2], "step": 5 }),
            "constants.m.step",
            "wider than the range",
        ),
        (
            json!({ "value": 3, "vary": [0.5, 2] }),
            "constants.m.value",
            "outside its range",
        ),
        (
            json!({ "value": 1, "step": 0.1 }),
            "constants.m.step",
            "without `vary`",
        ),
        (
            json!({ "value": 1, "vary": [0.5] }),
            "constants.m.vary",
            "expected [low, high]",
        ),
        (
            json!({ "value": 1, "vary": [0.5, "2"] }),
            "constants.m.vary[1]",
            "expected a number",
        ),
        (
            json!({ "value": 1, "vary": [0.5, 2], "stepp": 0.1 }),
            "constants.m.stepp",
            "did you mean `step`?",
        ),
    ];
    for (fields, path, message) in cases {
        let text = range_errors(fields.clone());
        assert!(
            text.contains(path) && text.contains(message),
            "{fields}: {text}"
        );
        assert!(
            text.contains("hint") || text.contains("did you mean"),
            "{fields}: no hint in {text}"
        );
    }
}

#[test]
fn the_schema_describes_vary_and_step() {
    let schema: Value = serde_json::from_slice(&run(&["schema"]).stdout).expect("json");
    let constant = &schema["properties"]["constants"]["additionalProperties"]["oneOf"][1];
    assert_eq!(constant["properties"]["vary"]["minItems"], 2);
    assert_eq!(constant["properties"]["step"]["exclusiveMinimum"], 0);
}

#[test]
fn absurd_requests_are_refused_before_any_work() {
    let dir = scratch("refused");
    let problem = dir.join("rod.json");
    std::fs::write(
        &problem,
        serde_json::to_string_pretty(&varied_rod()).unwrap(),
    )
    .unwrap();
    let fixed = dir.join("fixed.json");
    std::fs::write(
        &fixed,
        crate::support::problem("simple-pendulum")
            .to_str()
            .map(std::fs::read_to_string)
            .unwrap()
            .unwrap(),
    )
    .unwrap();
    let out = dir.join("out");
    let refused = |problem: &Path, count: &str, expected: &str, status: i32| {
        let output = run(&[
            "variants".as_ref(),
            problem.as_os_str(),
            "--count".as_ref(),
            count.as_ref(),
            "-o".as_ref(),
            out.as_os_str(),
        ]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(status), "{count}: {stderr}");
        assert!(stderr.contains(expected), "{count}: {stderr}");
        assert!(!out.exists(), "nothing is written");
    };
    refused(&problem, "0", "ask for 1 to 500", 2);
    refused(&problem, "1000000", "ask for 1 to 500", 2);
    refused(&fixed, "3", "no constant declares a range", 1);
    let mut narrow = varied_rod();
    for name in ["m", "L", "g"] {
        narrow["constants"][name] = json!({ "value": 1, "vary": [1, 1.1], "step": 0.1 });
    }
    std::fs::write(&problem, narrow.to_string()).unwrap();
    refused(&problem, "9", "only 8 different variants", 2);
}
