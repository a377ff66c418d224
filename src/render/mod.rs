//! Writing the worked solution: its content ([`Solution`], filled by the solution stage,
//! `crate::solution`) through a Tera template into Markdown, LaTeX or HTML, its pictures'
//! scenes into SVG and TikZ ([`draw`]), its plots into SVG and pgfplots (`plot`).
//!
//! Nothing here derives, solves or simulates, and nothing here reads the stages before the
//! solution: it writes what it is given. [`render`] puts a [`Solution`] through one of the
//! templates in `templates/`, which are embedded in the binary; an instructor can restyle a
//! handout by passing a directory of replacements.
//!
//! Entry: [`render()`] and the document it writes: [`Solution`] and its parts
//! ([`context`]), typed text ([`text`]), pictures ([`draw`]). The other modules are
//! private; what the solution uses is re-exported here.

mod by_speed;
mod compiled;
pub mod context;
pub mod draw;
mod escape;
mod figure;
mod flat_brackets;
mod impact;
mod labelled_rows;
mod line_break;
mod markup;
mod math_width;
mod mathml;
mod matrix_tables;
mod numbers;
mod plan_table;
mod plot;
mod plot_scripts;
mod plots_drawn;
mod prepare;
mod sample;
mod sections;
mod shown_names;
mod tex_wrap;
pub mod text;
mod units;
mod where_list;
mod word_scripts;

pub use by_speed::merged as merged_by_speed;
pub use context::Solution;
pub use escape::{html as escape_html, latex as escape_latex, Lines};
pub use impact::{ImpactSection, ImpactStep};
pub use line_break::{break_into_lines, DISPLAY_LIMIT, LINE_SYMBOLS};
pub use markup::{blocks, inlines, literal, literal_with_numbers, Block, Inline};
pub use math_width::{printed_width, symbols};
pub use matrix_tables::{pattern_tables, value_tables, value_tex, whole as whole_matrix};
pub use plan_table::columns as plan_columns;
pub use plot::{
    axes, padded_range, titled_area, unicode_of, x_axis_span, Label as PlotLabel, PlotData,
    PlotError, Series,
};
pub use plots_drawn::draw as draw_plots;
pub use sample::sample;
pub use sections::{
    AnswerStep, AnswerView, EigenvalueRow, LinearizationSection, MatrixEntries, ModeRow,
};
pub use units::unit_tex;
pub use where_list::grouped as grouped_definitions;
pub use word_scripts::subscripts_in_words;

use std::fmt;
use std::path::Path;

/// A template failed to load or render.
#[derive(Debug)]
pub struct RenderError {
    /// The template's name.
    pub template: String,
    /// What went wrong, e.g. Tera's own message ("Failed to render …").
    pub message: String,
    /// Tera's error, whose causes say why: [`std::error::Error::source`] gives them.
    pub cause: Option<tera::Error>,
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "template `{}`: {}", self.template, self.message)
    }
}

impl std::error::Error for RenderError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        // `message` is the Tera error's own text; its causes come next.
        self.cause.as_ref().and_then(|e| e.source())
    }
}

/// The output formats of `mbd-tutor explain`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Markdown with `$…$` and `$$…$$` math (GitHub, pandoc).
    Markdown,
    /// A standalone LaTeX article for pdflatex.
    Latex,
    /// One self-contained HTML page with MathML.
    Html,
}

impl Format {
    /// The file extension, without the dot.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Markdown => "md",
            Format::Latex => "tex",
            Format::Html => "html",
        }
    }

    /// The template's file name in `templates/` (and in a `--templates` directory).
    pub fn template_name(self) -> &'static str {
        match self {
            Format::Markdown => "solution.md.tera",
            Format::Latex => "solution.tex.tera",
            Format::Html => "solution.html.tera",
        }
    }

    /// The template embedded in the binary.
    fn embedded(self) -> &'static str {
        match self {
            Format::Markdown => include_str!("../../templates/solution.md.tera"),
            Format::Latex => include_str!("../../templates/solution.tex.tera"),
            Format::Html => include_str!("../../templates/solution.html.tera"),
        }
    }
}

/// Renders the worked solution, or with `student` the handout (the statement and the
/// set-up, with blank tables to fill in).
///
/// `templates` is a directory whose `solution.md.tera`, `solution.tex.tera` or
/// `solution.html.tera`, when present, replaces the embedded one. Templates see the
/// [`Solution`] with its text already escaped for the format; see [`context`].
///
/// # Errors
/// When `templates` is not a directory, or the replacement template cannot be read, does
/// not parse, or fails to render; the error names the template and gives Tera's whole
/// chain of causes.
pub fn render(
    solution: &Solution,
    format: Format,
    templates: Option<&Path>,
    student: bool,
) -> Result<String, RenderError> {
    let name = format.template_name();
    let error = |message: String| RenderError {
        template: name.to_string(),
        message,
        cause: None,
    };
    if let Some(dir) = templates.filter(|dir| !dir.is_dir()) {
        // A mistyped directory must not silently fall back to the built-in templates.
        return Err(error(format!(
            "the templates directory {} does not exist",
            dir.display()
        )));
    }
    let override_path = templates
        .map(|dir| dir.join(name))
        .filter(|path| path.is_file());
    let (source, shown_name) = match &override_path {
        Some(path) => {
            let source = crate::input::read_text_bounded(path, crate::input::MAX_TEMPLATE_BYTES)
                .map_err(|e| error(format!("cannot read {}: {e}", path.display())))?;
            (Some(source), path.display().to_string())
        }
        None => (None, name.to_string()),
    };
    let error = |message: String| RenderError {
        template: shown_name.clone(),
        message,
        cause: None,
    };
    let tera_error = |e: tera::Error| RenderError {
        template: shown_name.clone(),
        message: e.to_string(),
        cause: Some(e),
    };
    // Compiled once per process (see `compiled`): `variants` and `serve` render many.
    let tera = match (&override_path, &source) {
        (Some(path), Some(source)) => compiled::replacement(format, path, source),
        _ => compiled::embedded(format),
    }
    .map_err(tera_error)?;
    // The plots given as data are drawn here, in the format asked: the Markdown refers to
    // their files, which `explain` writes beside it.
    let drawn;
    let to_draw = format != Format::Markdown;
    let solution = match to_draw && solution.simulation.plots.iter().any(|p| p.data.is_some()) {
        true => {
            let mut copy = solution.clone();
            plots_drawn::draw(&mut copy.simulation.plots, format);
            drawn = copy;
            &drawn
        }
        false => solution,
    };
    let context = prepare::context(solution, format, student).map_err(|e| error(e.to_string()))?;
    let text = tera.render(name, &context).map_err(tera_error)?;
    Ok(match format {
        Format::Latex => tex_wrap::short_source_lines(&text),
        Format::Html => word_scripts::subscripts_in_words(&text),
        Format::Markdown => text,
    })
}
