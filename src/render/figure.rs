//! A picture as the handout embeds it.

use super::text::{InlineSvg, LatexCode};
use serde::Serialize;

/// A picture of `mbd-tutor draw`, embedded: inline SVG (Markdown, HTML) and TikZ (LaTeX).
#[derive(Clone, Debug, Default, Serialize)]
pub struct Figure {
    /// The SVG element, its ids prefixed by the picture's name; empty when not drawn.
    pub svg_inline: InlineSvg,
    /// The same picture as a `tikzpicture`.
    pub picture_latex: LatexCode,
}
