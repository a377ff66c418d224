//! The worked solution: a Tera context and templates -> Markdown, LaTeX, HTML, plots.

pub mod plot;

use std::fmt;

/// A template failed to load or render.
#[derive(Debug)]
pub struct RenderError {
    /// The template's name.
    pub template: String,
    /// Tera's message, with its causes.
    pub message: String,
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "template `{}`: {}", self.template, self.message)
    }
}

impl std::error::Error for RenderError {}
