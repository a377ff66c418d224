//! The plots of a handout drawn in the format asked: the SVG document for HTML and
//! Markdown, the pgfplots picture for LaTeX, from each plot's format-neutral data.

use super::context::Plot;
use super::plot::{line_plot, pgfplots};
use super::text::{LatexCode, SvgDocument};
use super::Format;

/// Writes each plot of `plots` that has its data as `format` shows it: the SVG document for
/// HTML and Markdown (its file), the pgfplots picture for LaTeX.
pub fn draw(plots: &mut [Plot], format: Format) {
    for plot in plots {
        let Some(data) = &plot.data else { continue };
        match format {
            Format::Latex => {
                plot.image_latex = LatexCode::from(pgfplots(
                    &data.x_label,
                    &data.y_label,
                    &data.series,
                    data.plots_in_row,
                ));
            }
            Format::Html | Format::Markdown => {
                let svg = line_plot(&plot.title, &data.x_label, &data.y_label, &data.series);
                plot.image_svg = SvgDocument::from(svg.unwrap_or_default());
            }
        }
    }
}
