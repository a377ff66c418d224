//! `mbd-tutor variants`: homework with a key for every student. Each variant is the
//! problem with its varying constants drawn anew (`vary`, `step`), written as its own
//! problem file with its worked solution and student handout; `key.csv` lists every
//! variant's drawn constants and answers.
//!
//! A variant whose problem is invalid with the values drawn, or whose questions cannot be
//! answered (a singular plan, no steady root near the guess), is drawn again from its own
//! stream, and the key counts the redraws.

use super::explain;
use crate::cli::{Common, ExplainArgs, VariantsArgs};
use crate::output::write_output;
use crate::problem::variant::{self, SplitMix64};
use crate::problem::{Problem, ProblemError, ProblemErrors};
use crate::solution::{csv_cell, full_digits as full, key_columns};
use crate::Error;
use std::path::Path;

/// The most variants one run writes: each takes seconds, and a class is not larger.
pub const MAX_COUNT: usize = 500;

/// The most draws of one variant before the run gives up: the ranges then hold mostly
/// problems that cannot be solved.
const MAX_DRAWS: usize = 50;

/// The most draws of one variant that repeat an earlier variant's values before a repeat
/// is accepted (only when nearly every combination of the grids is taken).
const MAX_DUPLICATES: usize = 10_000;

/// One variant drawn and answered.
struct Variant {
    /// `variant-01`.
    stem: String,
    seed: u64,
    redraws: usize,
    values: Vec<(String, f64)>,
    /// The variant's problem file, as written.
    json: String,
    columns: Vec<(String, f64)>,
}

/// Runs `mbd-tutor variants`.
///
/// # Errors
/// A usage error for a count out of range, an output that is a file, or a problem with no
/// constant that varies or fewer different variants than asked; an invalid problem; a
/// variant that no draw could solve; an output that cannot be written.
pub fn run(args: VariantsArgs) -> Result<(), Error> {
    if !(1..=MAX_COUNT).contains(&args.count) {
        return Err(Error::Usage(format!(
            "--count {}: ask for 1 to {MAX_COUNT} variants",
            args.count
        )));
    }
    if args.output.is_file() {
        return Err(Error::Usage(format!(
            "-o {} is a file: name a directory for the variants and their key",
            args.output.display()
        )));
    }
    let (problem, raw) = read(&args.problem)?;
    let varied = variant::varied(&problem);
    if varied.is_empty() {
        return Err(no_range());
    }
    let distinct = variant::distinct(&varied);
    if distinct < args.count as u64 {
        return Err(Error::Usage(format!(
            "--count {}: the ranges allow only {distinct} different variants; widen a range or give a finer `step`",
            args.count
        )));
    }
    let method = super::method(args.method);
    let width = args.count.to_string().len().max(2);
    let mut seeds = SplitMix64::new(args.seed);
    let mut variants: Vec<Variant> = Vec::with_capacity(args.count);
    for i in 1..=args.count {
        let stem = format!("variant-{i:0width$}");
        let drawn = Drawn {
            problem: &problem,
            raw: &raw,
            varied: &varied,
            earlier: &variants,
        };
        variants.push(drawn.until_solved(stem, seeds.next_u64(), method)?);
    }
    let io = |path: &Path| {
        let path = path.to_path_buf();
        move |source| Error::Io { path, source }
    };
    // Nothing is written when one of the files about to be written is the problem itself.
    crate::output::refuse_input_in(&args.problem, &args.output, |name| {
        name == "key.csv"
            || variants.iter().any(|v| {
                name.strip_prefix(v.stem.as_str())
                    .is_some_and(|rest| rest.starts_with('.') || rest.starts_with('-'))
            })
    })?;
    std::fs::create_dir_all(&args.output).map_err(io(&args.output))?;
    let format: crate::render::Format = args.format.into();
    for v in &variants {
        let file = args.output.join(format!("{}.json", v.stem));
        write_output(Some(&file), v.json.as_bytes())?;
        let handout = args
            .output
            .join(format!("{}.{}", v.stem, format.extension()));
        explain::explain_file(&explain_args(&args, &file), &file, Some(&handout))?;
    }
    let key = key(&varied, &variants);
    write_output(Some(&args.output.join("key.csv")), key.as_bytes())
}

/// The problem, validated, and its JSON as written.
fn read(path: &Path) -> Result<(Problem, serde_json::Value), Error> {
    let problem = crate::pipeline::load(path)?;
    let text = crate::input::read_text_bounded(path, crate::input::MAX_PROBLEM_BYTES).map_err(
        |source| Error::Io {
            path: path.to_path_buf(),
            source,
        },
    )?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let raw = serde_json::from_str(text)
        .map_err(|e| Error::Problem(ProblemErrors(vec![ProblemError::file(e.to_string())])))?;
    Ok((problem, raw))
}

fn no_range() -> Error {
    let mut error = ProblemError::file("no constant declares a range to draw its variants from");
    error.path = "constants".into();
    error.hint = Some(
        "give a constant a range, e.g. \"m\": { \"value\": 2, \"vary\": [1.5, 3], \"step\": 0.1 }"
            .into(),
    );
    Error::Problem(ProblemErrors(vec![error]))
}

/// What a variant is drawn from, and the variants drawn before it.
struct Drawn<'a> {
    problem: &'a Problem,
    raw: &'a serde_json::Value,
    varied: &'a [(String, crate::problem::Grid)],
    earlier: &'a [Variant],
}

impl Drawn<'_> {
    /// Draws variant `stem` from its own stream until its values differ from every earlier
    /// variant's (two students, two sets of numbers), its problem is valid and every
    /// question is answered. Only the draws that could not be solved count as redraws.
    fn until_solved(
        &self,
        stem: String,
        seed: u64,
        method: crate::equations::Method,
    ) -> Result<Variant, Error> {
        let mut random = SplitMix64::new(seed);
        let mut last = String::new();
        let mut redraws = 0;
        let mut duplicates = 0;
        while redraws < MAX_DRAWS {
            let values = variant::draw(self.varied, &mut random);
            if self.earlier.iter().any(|v| v.values == values) && duplicates < MAX_DUPLICATES {
                duplicates += 1;
                continue;
            }
            let mut json = serde_json::to_string_pretty(&variant::with_values(self.raw, &values))
                .unwrap_or_default();
            json.push('\n');
            // The variant is read back from its own text, as `answer` reads its file.
            let solved = crate::problem::load(&json)
                .and_then(|mut p| crate::problem::apply_overrides(&mut p, &[]).map(|()| p))
                .map_err(Error::Problem)
                .and_then(|p| crate::pipeline::answers(&p, method).map(|a| key_columns(&p, &a)));
            match solved {
                Ok(columns) => {
                    return Ok(Variant {
                        stem,
                        seed,
                        redraws,
                        values,
                        json,
                        columns,
                    })
                }
                Err(error) => last = error.one_line(),
            }
            redraws += 1;
        }
        let mut error = ProblemError::file(format!(
            "{stem}: none of {MAX_DRAWS} draws could be solved; the last: {last}"
        ));
        error.path = "constants".into();
        error.hint = Some(format!(
            "narrow the ranges to values where `{}` solves",
            self.problem.title
        ));
        Err(Error::Problem(ProblemErrors(vec![error])))
    }
}

/// The arguments of `explain --both` for one variant's file.
fn explain_args(args: &VariantsArgs, file: &Path) -> ExplainArgs {
    ExplainArgs {
        common: Common {
            problem: file.to_path_buf(),
            method: args.method,
            set: Vec::new(),
            output: None,
            max_bodies: crate::cli::MAX_BODIES,
            max_coordinates: crate::cli::MAX_COORDINATES,
            max_work: crate::symbolic::budget::DEFAULT_LIMIT / 1_000_000,
        },
        format: args.format,
        templates: None,
        student: false,
        both: true,
        linearize: None,
        verbose: false,
        statics: false,
    }
}

/// `key.csv`: a header, then one row per variant: its file, its seed, its redraws, the
/// constants drawn, then every answer.
fn key(varied: &[(String, crate::problem::Grid)], variants: &[Variant]) -> String {
    let mut header: Vec<String> = ["file", "seed", "redraws"].map(String::from).to_vec();
    header.extend(varied.iter().map(|(name, _)| name.clone()));
    if let Some(first) = variants.first() {
        header.extend(first.columns.iter().map(|(name, _)| name.clone()));
    }
    let mut out = line(&header);
    for v in variants {
        let mut row = vec![
            format!("{}.json", v.stem),
            v.seed.to_string(),
            v.redraws.to_string(),
        ];
        row.extend(v.values.iter().map(|(_, x)| full(*x)));
        row.extend(v.columns.iter().map(|(_, x)| full(*x)));
        out.push_str(&line(&row));
    }
    out
}

fn line(cells: &[String]) -> String {
    let cells: Vec<String> = cells.iter().map(|c| csv_cell(c)).collect();
    format!("{}\n", cells.join(","))
}
