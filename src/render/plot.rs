//! Line plots of a simulation: SVG for Markdown and HTML, pgfplots for LaTeX.
//!
//! Both are deterministic: the same data gives the same bytes.

use crate::numeric::format::fixed;
use plotters::prelude::*;
use std::fmt;

/// Most points per series in a pgfplots snippet; more only slows LaTeX down.
pub const PGFPLOTS_MAX_POINTS: usize = 400;

/// Size of the SVG plots, in pixels.
const SIZE: (u32, u32) = (720, 420);

/// Line colours, in series order (repeating past the end); distinguishable in print.
const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

/// A plot could not be drawn.
#[derive(Clone, Debug, PartialEq)]
pub enum PlotError {
    /// No series has a finite point.
    NoData {
        /// The plot's title.
        title: String,
    },
    /// The plotting library failed.
    Drawing {
        /// The plot's title.
        title: String,
        /// The library's message.
        message: String,
    },
}

impl fmt::Display for PlotError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PlotError::NoData { title } => {
                write!(f, "plot `{title}`: there is no finite point to plot")
            }
            PlotError::Drawing { title, message } => write!(f, "plot `{title}`: {message}"),
        }
    }
}

impl std::error::Error for PlotError {}

/// An SVG line plot of `series`, each a name and its `(x, y)` points, with a legend.
///
/// Non-finite points are left out. Text is written as SVG `<text>`, so no font files are
/// needed to draw or to view it.
///
/// # Errors
/// [`PlotError::NoData`] when there is no finite point; [`PlotError::Drawing`] if the
/// plotting library fails.
pub fn line_plot(
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[(String, Vec<(f64, f64)>)],
) -> Result<String, PlotError> {
    let (x_range, y_range) = ranges(series).ok_or_else(|| PlotError::NoData {
        title: title.into(),
    })?;
    let drawing = |message: String| PlotError::Drawing {
        title: title.into(),
        message,
    };
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(|e| drawing(e.to_string()))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 24))
            .margin(12)
            .x_label_area_size(50)
            .y_label_area_size(70)
            .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)
            .map_err(|e| drawing(e.to_string()))?;
        chart
            .configure_mesh()
            .x_desc(x_label)
            .y_desc(y_label)
            .x_label_formatter(&|x| tick(*x, x_range))
            .y_label_formatter(&|y| tick(*y, y_range))
            .light_line_style(TRANSPARENT)
            .label_style(("sans-serif", 15))
            .axis_desc_style(("sans-serif", 16))
            .draw()
            .map_err(|e| drawing(e.to_string()))?;
        for (index, (name, points)) in series.iter().enumerate() {
            let colour = COLOURS[index % COLOURS.len()];
            let finite = points
                .iter()
                .copied()
                .filter(|(x, y)| x.is_finite() && y.is_finite());
            chart
                .draw_series(LineSeries::new(finite, colour.stroke_width(2)))
                .map_err(|e| drawing(e.to_string()))?
                .label(name.as_str())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font(("sans-serif", 15))
            .draw()
            .map_err(|e| drawing(e.to_string()))?;
        root.present().map_err(|e| drawing(e.to_string()))?;
    }
    Ok(svg)
}

/// A tick label: [`fixed`], with round-off next to zero (`-2.2e-16`) shown as `0`.
fn tick(value: f64, range: (f64, f64)) -> String {
    let snapped = if value.abs() < 1e-9 * (range.1 - range.0) {
        0.0
    } else {
        value
    };
    fixed(snapped)
}

/// The x and y ranges covering every finite point, y padded by 5 % so lines clear the
/// frame; a flat range is widened so the axis has a length.
fn ranges(series: &[(String, Vec<(f64, f64)>)]) -> Option<((f64, f64), (f64, f64))> {
    let points = series
        .iter()
        .flat_map(|(_, p)| p)
        .filter(|(x, y)| x.is_finite() && y.is_finite());
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in points {
        (x0, x1, y0, y1) = (x0.min(x), x1.max(x), y0.min(y), y1.max(y));
    }
    if x0 > x1 {
        return None;
    }
    let widen = |low: f64, high: f64, pad: f64| {
        let span = high - low;
        if span > 1e-12 * low.abs().max(high.abs()) {
            (low - pad * span, high + pad * span)
        } else {
            let half = (0.1 * low.abs()).max(1.0);
            (low - half, high + half)
        }
    };
    Some((widen(x0, x1, 0.0), widen(y0, y1, 0.05)))
}

/// A LaTeX `tikzpicture` with a pgfplots `axis` holding one `\addplot` per series.
///
/// Each series is thinned to at most [`PGFPLOTS_MAX_POINTS`] points (keeping the first and
/// the last) and printed with [`fixed`] precision. Title, labels and series names are
/// escaped as LaTeX text. Non-finite points are left out. The document needs
/// `\usepackage{pgfplots}`.
pub fn pgfplots(
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[(String, Vec<(f64, f64)>)],
) -> String {
    let mut text = String::from("\\begin{tikzpicture}\n\\begin{axis}[\n");
    text.push_str(&format!("  title={{{}}},\n", escape_latex(title)));
    text.push_str(&format!("  xlabel={{{}}},\n", escape_latex(x_label)));
    text.push_str(&format!("  ylabel={{{}}},\n", escape_latex(y_label)));
    text.push_str("  width=12cm, height=7cm, grid=major,\n  legend pos=outer north east,\n]\n");
    for (name, points) in series {
        let finite: Vec<(f64, f64)> = points
            .iter()
            .copied()
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect();
        text.push_str("\\addplot+[mark=none] coordinates {\n");
        for (x, y) in thin(&finite, PGFPLOTS_MAX_POINTS) {
            text.push_str(&format!("  ({},{})\n", fixed(x), fixed(y)));
        }
        text.push_str("};\n");
        text.push_str(&format!("\\addlegendentry{{{}}}\n", escape_latex(name)));
    }
    text.push_str("\\end{axis}\n\\end{tikzpicture}\n");
    text
}

/// At most `most` points of `points` (never fewer than two), evenly spaced by index,
/// always with the first and the last.
fn thin(points: &[(f64, f64)], most: usize) -> Vec<(f64, f64)> {
    let most = most.max(2);
    if points.len() <= most {
        return points.to_vec();
    }
    let last = points.len() - 1;
    (0..most).map(|i| points[i * last / (most - 1)]).collect()
}

/// `text` with LaTeX's special characters escaped, for use in text mode.
fn escape_latex(text: &str) -> String {
    let mut escaped = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '\\' => escaped.push_str("\\textbackslash{}"),
            '~' => escaped.push_str("\\textasciitilde{}"),
            '^' => escaped.push_str("\\textasciicircum{}"),
            '#' | '$' | '%' | '&' | '_' | '{' | '}' => {
                escaped.push('\\');
                escaped.push(c);
            }
            _ => escaped.push(c),
        }
    }
    escaped
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sine() -> Vec<(String, Vec<(f64, f64)>)> {
        let points: Vec<(f64, f64)> = (0..=500)
            .map(|i| i as f64 * 0.01)
            .map(|t| (t, (3.0 * t).sin()))
            .collect();
        let cosine: Vec<(f64, f64)> = points.iter().map(|(t, _)| (*t, (3.0 * t).cos())).collect();
        vec![("q1".to_string(), points), ("q_2".to_string(), cosine)]
    }

    #[test]
    fn svg_is_deterministic_and_labelled() {
        let first = line_plot("Coordinates", "t (s)", "value", &sine()).unwrap();
        let second = line_plot("Coordinates", "t (s)", "value", &sine()).unwrap();
        assert_eq!(first, second);
        assert!(first.starts_with("<svg"), "{}", &first[..60]);
        assert!(first.trim_end().ends_with("</svg>"));
        assert!(!first.contains("e-16"), "round-off in a tick label");
        for text in [
            "\nCoordinates\n",
            "\nt (s)\n",
            "\nq1\n",
            "\nq_2\n",
            "\n0\n",
            "<polyline",
        ] {
            assert!(first.contains(text), "missing {text}");
        }
    }

    #[test]
    fn svg_of_nothing_is_an_error() {
        let empty = vec![("q1".to_string(), vec![(f64::NAN, 1.0)])];
        assert!(matches!(
            line_plot("Empty", "t", "q", &empty),
            Err(PlotError::NoData { .. })
        ));
        // A flat line still gets an axis.
        let flat = vec![("q1".to_string(), vec![(0.0, 2.0), (1.0, 2.0)])];
        assert!(line_plot("Flat", "t", "q", &flat).is_ok());
    }

    #[test]
    fn pgfplots_is_thinned_and_escaped() {
        let text = pgfplots("Energy & more", "t (s)", "E (J)", &sine());
        assert!(text.starts_with("\\begin{tikzpicture}\n\\begin{axis}["));
        assert!(text.contains("title={Energy \\& more}"));
        assert!(text.contains("\\addlegendentry{q\\_2}"));
        assert_eq!(text.matches("\\addplot").count(), 2);
        let points = text.lines().filter(|l| l.starts_with("  (")).count();
        assert_eq!(points, 2 * PGFPLOTS_MAX_POINTS);
        // First and last points kept, at fixed precision: sin(15) = 0.650288...
        assert!(text.contains("  (0,0)\n"));
        assert!(text.contains("  (5,0.650288)\n"));
    }

    #[test]
    fn thinning_keeps_ends() {
        let points: Vec<(f64, f64)> = (0..10).map(|i| (i as f64, 0.0)).collect();
        assert_eq!(
            thin(&points, 4),
            vec![(0.0, 0.0), (3.0, 0.0), (6.0, 0.0), (9.0, 0.0)]
        );
        assert_eq!(thin(&points, 20).len(), 10);
        assert_eq!(thin(&points, 1), vec![(0.0, 0.0), (9.0, 0.0)]);
    }
}
