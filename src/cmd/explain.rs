//! `mbd-tutor explain`: the worked solution of one problem, or of every problem in a
//! directory.

use crate::cli::{Common, ExplainArgs, FormatArg};
use crate::error::BatchError;
use crate::output::write_output;
use crate::render::text::FileName;
use crate::render::{self, Format, Solution};
use crate::solution;
use crate::Error;
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};

impl From<FormatArg> for Format {
    fn from(arg: FormatArg) -> Format {
        match arg {
            FormatArg::Markdown => Format::Markdown,
            FormatArg::Latex => Format::Latex,
            FormatArg::Html => Format::Html,
        }
    }
}

/// Runs `mbd-tutor explain`.
///
/// # Errors
/// For one file, whatever stops it (an invalid problem, equations that cannot be solved, a
/// template that fails, an unwritable output). For a directory, a [`BatchError`] listing
/// every problem that failed, after all the others were written.
pub fn run(args: ExplainArgs) -> Result<(), Error> {
    if args.common.problem.is_dir() {
        return run_directory(&args);
    }
    // One problem, then the process ends: what the handout's simplifications kept is
    // freed by the end of the process, not one expression at a time.
    crate::symbolic::leave_to_the_end();
    explain_file(&args, &args.common.problem, args.common.output.as_deref())
}

/// `NAME-student.EXT` beside `NAME.EXT`.
pub fn student_path(path: &Path) -> PathBuf {
    let name = match path.extension() {
        Some(ext) => format!("{}-student.{}", file_stem(path), ext.to_string_lossy()),
        None => format!("{}-student", file_stem(path)),
    };
    path.with_file_name(name)
}

/// Explains one problem into `output`; with `--both`, the student's handout too, beside it.
pub fn explain_file(
    args: &ExplainArgs,
    problem_path: &Path,
    output: Option<&Path>,
) -> Result<(), Error> {
    if let Some(output) = output {
        refuse_overwriting_input(problem_path, output)?;
    }
    if !args.both {
        return explain_version(args, problem_path, output, args.student);
    }
    let Some(output) = output else {
        return Err(Error::Usage(
            "--both writes two files: name the worked solution's with -o FILE".into(),
        ));
    };
    explain_version(args, problem_path, Some(output), false)?;
    explain_version(args, problem_path, Some(&student_path(output)), true)
}

/// A usage error, before anything is written, when a file this explanation would write (the
/// handout, the student's beside it, a plot `STEM-KIND.svg`) is the problem file.
fn refuse_overwriting_input(problem_path: &Path, output: &Path) -> Result<(), Error> {
    let student = student_path(output);
    crate::output::refuse_input(problem_path, &[output, &student])?;
    let Some(directory) = output.parent() else {
        return Ok(());
    };
    let directory = if directory.as_os_str().is_empty() {
        Path::new(".")
    } else {
        directory
    };
    let plots = format!("{}-", file_stem(output));
    crate::output::refuse_input_in(problem_path, directory, |name| {
        name.starts_with(&plots) && name.ends_with(".svg")
    })
}

/// Explains one problem into `output` (standard output when `None`); plots go beside it
/// as `STEM-KIND.svg`, `STEM` being the output's file name without extension.
fn explain_version(
    args: &ExplainArgs,
    problem_path: &Path,
    output: Option<&Path>,
    student: bool,
) -> Result<(), Error> {
    let (text, mut solution) = rendered(args, problem_path, output, student)?;
    if let Some(path) = output.filter(|_| args.format == FormatArg::Markdown) {
        // Only Markdown refers to plot files.
        render::draw_plots(&mut solution.simulation.plots, Format::Markdown);
        // The plots first, so that a document never refers to a plot that is not there.
        let directory = path.parent().unwrap_or(Path::new(""));
        for plot in solution
            .simulation
            .plots
            .iter()
            .filter(|p| !p.image_svg.is_empty() && !p.svg_file.is_empty())
        {
            write_output(
                Some(&directory.join(plot.svg_file.as_str())),
                plot.image_svg.as_bytes(),
            )?;
        }
    }
    write_output(output, text.as_bytes())
}

/// The text of one problem's handout in the chosen format, and the solution it was made
/// from (whose plots go beside `output`, when there is one). `serve` shows the same page.
///
/// # Errors
/// An invalid problem, equations that cannot be solved, a template that fails.
pub fn rendered(
    args: &ExplainArgs,
    problem_path: &Path,
    output: Option<&Path>,
    student: bool,
) -> Result<(String, Solution), Error> {
    let common = Common {
        problem: problem_path.to_path_buf(),
        ..args.common.clone()
    };
    let problem = super::load_with_overrides(&common)?;
    let linearize_at = match args.linearize.as_ref().filter(|_| !student) {
        Some(state) => Some(super::solve::initial_state(
            &problem,
            std::slice::from_ref(state),
        )?),
        None => None,
    };
    let job = crate::Job {
        method: super::method(args.common.method),
        student,
        linearize_at,
        motion: args.format == FormatArg::Html,
    };
    let settings = solution::Handout {
        every_rejected: args.verbose,
    };
    // A problem held still by its supports (every coordinate held, or solved from those
    // held) has nothing in motion: its worked solution is the statics one.
    let statics = args.statics || (args.linearize.is_none() && held_still(&problem));
    let mut solution = if statics {
        // The stages run at the equilibrium; the handout is written from what they gave.
        let rest = crate::pipeline::rest(&problem, job.method)?;
        let at_rest = crate::pipeline::run_at_rest(&rest, job.method, student)?;
        solution::statics_handout(&at_rest, student, &settings)
    } else {
        // Every stage runs here, once; the handout is written from what they gave.
        match (student, crate::pipeline::run(&problem, &job)) {
            // The student's version is the statement and the set-up even where the
            // equations cannot be derived or solved.
            (true, worked) => {
                solution::student(&problem, job.method, worked.ok().as_ref(), &settings)
            }
            // Its steps simplify the same sums again and again: each once.
            (false, worked) => {
                let worked = worked?;
                crate::symbolic::with_simplify_memo(|| solution::handout(&worked, &settings))
            }
        }
    };
    // Only Markdown refers to plot files: the HTML handout holds its plots (one file), the
    // LaTeX draws them. On standard output there is nowhere to put them either.
    let beside = output.filter(|_| args.format == FormatArg::Markdown);
    for plot in &mut solution.simulation.plots {
        plot.svg_file = FileName::from(
            beside
                .map(|path| format!("{}-{}.svg", file_stem(path), plot.kind))
                .unwrap_or_default(),
        );
    }
    let text = render::render(
        &solution,
        args.format.into(),
        args.templates.as_deref(),
        student,
    )?;
    Ok((text, solution))
}

/// Explains every `*.json` directly in the directory, in name order, into `-o DIR`,
/// going on past failures.
fn run_directory(args: &ExplainArgs) -> Result<(), Error> {
    let directory = &args.common.problem;
    let Some(out) = args.common.output.as_deref() else {
        return Err(Error::Usage(format!(
            "{} is a directory: name the output directory with -o DIR",
            directory.display()
        )));
    };
    let io = |path: &Path| {
        let path = path.to_path_buf();
        move |source| Error::Io { path, source }
    };
    let mut problems: Vec<PathBuf> = std::fs::read_dir(directory)
        .map_err(io(directory))?
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|path| path.is_file() && path.extension().is_some_and(|e| e == "json"))
        .collect();
    problems.sort();
    std::fs::create_dir_all(out).map_err(io(out))?;
    let format: Format = args.format.into();
    let mut progress = Progress::new(problems.len());
    let mut failures = Vec::new();
    for (index, path) in problems.iter().enumerate() {
        let stem = file_stem(path);
        progress.show(index, &stem);
        let target = out.join(format!("{stem}.{}", format.extension()));
        if let Err(error) = explain_file(args, path, Some(&target)) {
            failures.push((path.clone(), error.one_line()));
        }
    }
    progress.finish();
    if failures.is_empty() {
        Ok(())
    } else {
        Err(Error::Batch(BatchError {
            failures,
            total: problems.len(),
        }))
    }
}

/// Whether every coordinate of `problem` is held by a support or solved from the held
/// ones by the constraints (marked `dependent`, or chosen as the constraints fix them), at
/// least one held and no impact: a problem of statics, whatever the method.
fn held_still(problem: &crate::problem::Problem) -> bool {
    let coordinates = &problem.coordinates;
    if problem.impact.is_some() || !coordinates.iter().any(|c| c.held) {
        return false;
    }
    let solved = crate::mechanics::Model::build(problem)
        .map(|model| model.constraints.dependent.clone())
        .unwrap_or_default();
    (coordinates.iter().enumerate()).all(|(i, c)| c.held || c.dependent || solved.contains(&i))
}

/// The name of the file `path` without its extension (`solution` when it has none): the
/// stem of the written handout.
pub fn file_stem(path: &Path) -> String {
    path.file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "solution".into())
}

/// A one-line counter on standard error, shown only when it is a terminal.
struct Progress {
    total: usize,
    terminal: bool,
}

impl Progress {
    fn new(total: usize) -> Progress {
        Progress {
            total,
            terminal: std::io::stderr().is_terminal(),
        }
    }

    fn show(&mut self, index: usize, name: &str) {
        if self.terminal {
            let mut stderr = std::io::stderr().lock();
            let _ = write!(stderr, "\r\x1b[2K[{}/{}] {name}", index + 1, self.total);
            let _ = stderr.flush();
        }
    }

    fn finish(&mut self) {
        if self.terminal {
            let _ = write!(std::io::stderr().lock(), "\r\x1b[2K");
        }
    }
}
