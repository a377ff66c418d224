//! Line plots of a simulation: SVG for Markdown and HTML, pgfplots for LaTeX.
//!
//! Both are deterministic: the same data gives the same bytes.

use crate::symbolic::fixed;
use plotters::coord::types::RangedCoordf64;
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

/// Line styles, in series order (repeating), so that lines lying on each other (E on V
/// where T is small) and lines printed in black and white are told apart, every line a
/// solid stroke or long dashes, none dotted like the grid: the SVG's dash pattern, its
/// stroke width and opacity, and the pgfplots style of each. The third (E = T + V) is a
/// wide, half-transparent band, so that V's dashes show through it where they coincide.
const DASHES: [(&str, u32, &str, &str); 4] = [
    ("", 2, "", "thick, solid"),
    ("9,5", 2, "", "thick, dashed"),
    ("", 7, "0.45", "line width=2.6pt, opacity=0.45, solid"),
    ("12,4,2,4", 3, "", "thick, dashdotted"),
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

/// A label in both outputs: Unicode text for the SVG picture (θ₁, E₀) and LaTeX text-mode
/// source for pgfplots (`$\theta_{1}$`).
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// What the SVG picture prints.
    pub text: String,
    /// LaTeX text-mode source: words as they are, symbols between `$`.
    pub tex: String,
}

impl Label {
    /// A symbol given as LaTeX math (without `$`), followed after a space by plain `words`
    /// such as a unit in parentheses, if any: `Label::math("E - E_{0}", "(J)")`.
    pub fn math(math: &str, words: &str) -> Label {
        if words.is_empty() {
            return Label {
                text: unicode_of(math),
                tex: format!("${math}$"),
            };
        }
        Label {
            text: format!("{} {words}", unicode_of(math)),
            tex: format!("${math}$ {}", escape_latex(words)),
        }
    }

    /// Plain words, the same in both outputs.
    pub fn words(words: &str) -> Label {
        Label {
            text: words.into(),
            tex: escape_latex(words),
        }
    }
}

/// One line of a plot: its legend and its `(x, y)` points.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// The legend entry.
    pub name: Label,
    /// The points; non-finite ones are left out.
    pub points: Vec<(f64, f64)>,
}

/// An SVG line plot of `series` with a legend.
///
/// Non-finite points are left out. Text is written as SVG `<text>`, so no font files are
/// needed to draw or to view it.
///
/// # Errors
/// [`PlotError::NoData`] when there is no finite point; [`PlotError::Drawing`] if the
/// plotting library fails.
pub fn line_plot(
    title: &str,
    x_label: &Label,
    y_label: &Label,
    series: &[Series],
) -> Result<String, PlotError> {
    let finite = series
        .iter()
        .flat_map(|s| &s.points)
        .filter(|(x, y)| x.is_finite() && y.is_finite());
    if finite.clone().next().is_none() {
        return Err(PlotError::NoData {
            title: title.into(),
        });
    }
    let x_range = padded_range(finite.clone().map(|p| p.0), 0.0);
    let y_range = padded_range(finite.map(|p| p.1), 0.05);
    let drawing = |message: String| PlotError::Drawing {
        title: title.into(),
        message,
    };
    let mut svg = String::new();
    {
        let root = titled_area(&mut svg, SIZE, title, 24).map_err(drawing)?;
        let mut chart =
            axes(&root, &x_label.text, &y_label.text, x_range, y_range).map_err(drawing)?;
        for (index, line) in series.iter().enumerate() {
            let colour = COLOURS[index % COLOURS.len()];
            let finite = line
                .points
                .iter()
                .copied()
                .filter(|(x, y)| x.is_finite() && y.is_finite());
            chart
                .draw_series(LineSeries::new(finite, colour.stroke_width(2)))
                .map_err(|e| drawing(e.to_string()))?
                .label(line.name.text.as_str())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 28, y)], colour.stroke_width(2))
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
    Ok(super::plot_scripts::lowered(&dashed(&svg, series.len())))
}

/// `svg` with the lines (and legend samples) of the first `count` series dashed as
/// [`DASHES`] says: plotters draws a series and its sample as polylines of its colour.
fn dashed(svg: &str, count: usize) -> String {
    let mut out = svg.to_string();
    for index in 0..count.min(COLOURS.len()) {
        let (pattern, width, opacity, _) = DASHES[index % DASHES.len()];
        let mut extra = String::new();
        if !pattern.is_empty() {
            extra.push_str(&format!(" stroke-dasharray=\"{pattern}\""));
        }
        if !opacity.is_empty() {
            extra.push_str(&format!(" stroke-opacity=\"{opacity}\""));
        }
        let width = format!("stroke-width=\"{width}\"");
        let RGBColor(r, g, b) = COLOURS[index];
        let stroke = format!("stroke=\"#{r:02X}{g:02X}{b:02X}\"");
        let mut next = String::with_capacity(out.len() + 64);
        let mut rest = out.as_str();
        while let Some(at) = rest.find("<polyline") {
            let end = at + rest[at..].find('>').unwrap_or(rest.len() - at);
            let tag = &rest[at..end];
            next.push_str(&rest[..at]);
            if tag.contains(&stroke) {
                let tag = tag.replacen("stroke-width=\"2\"", &width, 1);
                next.push_str(&tag.replacen(&stroke, &format!("{stroke}{extra}"), 1));
            } else {
                next.push_str(tag);
            }
            rest = &rest[end..];
        }
        next.push_str(rest);
        out = next;
    }
    out
}

/// The chart [`axes`] draws on: f64 by f64.
pub type Chart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The room around a plot, and the room for its y axis's labels, in pixels.
const MARGIN: u32 = 12;
const Y_LABEL_AREA: u32 = 70;

/// Where a plot's x axis runs, as fractions of the plot's width: the HTML page draws a
/// marker at a time on it.
pub fn x_axis_span() -> [f64; 2] {
    let width = f64::from(SIZE.0);
    [
        f64::from(MARGIN + Y_LABEL_AREA) / width,
        f64::from(SIZE.0 - MARGIN) / width,
    ]
}

/// A white drawing area of `size` pixels writing into `svg`, `title` set above it in a
/// sans-serif font of `font_size`: how every SVG plot starts.
pub fn titled_area<'b>(
    svg: &'b mut String,
    size: (u32, u32),
    title: &str,
    font_size: u32,
) -> Result<DrawingArea<SVGBackend<'b>, plotters::coord::Shift>, String> {
    let root = SVGBackend::with_string(svg, size).into_drawing_area();
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    root.titled(title, ("sans-serif", font_size))
        .map_err(|e| e.to_string())
}

/// A chart on `area` with its axes drawn as every SVG plot draws them: no minor grid, tick
/// labels at [`fixed`] precision, the axis descriptions `x_label` and `y_label`.
pub fn axes<'a, 'b>(
    area: &'a DrawingArea<SVGBackend<'b>, plotters::coord::Shift>,
    x_label: &str,
    y_label: &str,
    x_range: (f64, f64),
    y_range: (f64, f64),
) -> Result<Chart<'a, 'b>, String> {
    let mut chart = ChartBuilder::on(area)
        .margin(MARGIN)
        .x_label_area_size(50)
        .y_label_area_size(Y_LABEL_AREA)
        .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)
        .map_err(|e| e.to_string())?;
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
        .map_err(|e| e.to_string())?;
    Ok(chart)
}

/// A tick label: [`fixed`] as print shows it (`−2.5×10⁻⁸`), with round-off next to zero
/// (`-2.2e-16`) shown as `0`.
fn tick(value: f64, range: (f64, f64)) -> String {
    let snapped = if value.abs() < 1e-9 * (range.1 - range.0) {
        0.0
    } else {
        value
    };
    super::numbers::unicode_number(&fixed(snapped)).replace('-', "−")
}

/// The range covering the finite `values`, padded by `pad` of its span on each side so
/// lines clear the frame; a flat range is widened so the axis has a length, and no value
/// at all gives (-1, 1).
pub fn padded_range(values: impl Iterator<Item = f64>, pad: f64) -> (f64, f64) {
    let (low, high) = values
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
            (l.min(x), h.max(x))
        });
    if low > high {
        return (-1.0, 1.0);
    }
    let span = high - low;
    if span > 1e-12 * low.abs().max(high.abs()) {
        (low - pad * span, high + pad * span)
    } else {
        let half = (0.1 * low.abs()).max(1.0);
        (low - half, high + half)
    }
}

/// Simple LaTeX math as Unicode text: Greek letters as letters, `\mathrm{..}` upright, a
/// subscript of digits as subscript digits (`\theta_{1}` → θ₁, `E_{0}` → E₀); any other
/// subscript keeps its `_`.
pub fn unicode_of(math: &str) -> String {
    let mut out = String::new();
    let mut chars = math.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => {
                let command = crate::typeset::command_name(&mut chars);
                match crate::render::escape::greek_letter(&command) {
                    Some(letter) => out.push(letter),
                    None if command == "mathrm" || command == "mathbf" => {}
                    None => out.push_str(&command),
                }
            }
            '_' => {
                let braced = chars.peek() == Some(&'{');
                let mut sub = String::new();
                if braced {
                    chars.next();
                    for n in chars.by_ref() {
                        if n == '}' {
                            break;
                        }
                        sub.push(n);
                    }
                } else if let Some(n) = chars.next() {
                    sub.push(n);
                }
                if sub.chars().all(|d| d.is_ascii_digit() || d == ',') {
                    out.extend(sub.chars().map(subscript));
                } else {
                    out.push('_');
                    out.push_str(&unicode_of(&sub));
                }
            }
            '{' | '}' => {}
            '-' => out.push('−'),
            _ => out.push(c),
        }
    }
    out
}

/// A digit as its subscript character; anything else as it is.
fn subscript(d: char) -> char {
    d.to_digit(10)
        .and_then(|v| char::from_u32(0x2080 + v))
        .unwrap_or(d)
}

/// The most entries a row of a plot's legend holds when three plots share the page's
/// width: as wide as the plot.
const LEGEND_COLUMNS: usize = 4;

/// How many symbols a row of a legend may print when four plots share the width, each entry
/// counted with its line's sample as four.
const LEGEND_ROOM_OF_FOUR: usize = 20;

/// How many entries of `series` a row of the legend holds, `plots_in_row` plots sharing the
/// page's width: as many as fit the plot's width.
fn legend_columns(series: &[Series], plots_in_row: usize) -> usize {
    let most = if plots_in_row < 4 {
        LEGEND_COLUMNS
    } else {
        let widest = series
            .iter()
            .map(|s| super::math_width::printed_width(&s.name.tex.replace('$', "")) + 4)
            .max()
            .unwrap_or(4);
        LEGEND_ROOM_OF_FOUR / widest
    };
    most.min(series.len()).max(1)
}

/// A LaTeX `tikzpicture` with a pgfplots `axis` holding one `\addplot` per series.
///
/// Each series is thinned to at most [`PGFPLOTS_MAX_POINTS`] points (keeping the first and
/// the last) and printed with [`fixed`] precision. The labels and legends are LaTeX
/// already. No title: the figure's caption says what the plot shows. Non-finite points are left out. The
/// document needs `\usepackage{pgfplots}`.
pub fn pgfplots(
    x_label: &Label,
    y_label: &Label,
    series: &[Series],
    plots_in_row: usize,
) -> String {
    let mut text = String::from("\\begin{tikzpicture}\n\\begin{axis}[\n");
    text.push_str(&format!("  xlabel={{{}}},\n", x_label.tex));
    text.push_str(&format!("  ylabel={{{}}},\n", y_label.tex));
    // Three or four plots side by side on the page, each with its legend under it, small:
    // the rows of a legend are lower than a second row of plots. The legend hangs a fixed
    // 31 pt under the axis, below its tick labels and the time's title, whatever the
    // plot's height left the axis. The width is the page's
    // to set (`\pgfplotsset{width=…}`), by how many plots share the row.
    // Two to a row are wide, and lower than wide, as a time history reads: half their
    // width (an axis as high as wide took a fifth of the page for two curves); three or
    // four are lower still.
    let height = if plots_in_row <= 2 { "3.6cm" } else { "2.9cm" };
    text.push_str(&format!(
        "  height={height}, grid=major, major grid style={{black!15}},\n"
    ));
    text.push_str("  tick label style={font=\\footnotesize}, label style={font=\\small},\n");
    text.push_str(&format!(
        "  xticklabel style={{/pgf/number format/precision={}}}, yticklabel style={{/pgf/number format/precision={}}},\n",
        tick_precision(series.iter().flat_map(|s| s.points.iter().map(|p| p.0))),
        tick_precision(series.iter().flat_map(|s| s.points.iter().map(|p| p.1)))
    ));
    text.push_str(&format!(
        "  legend columns={}, legend style={{font=\\scriptsize, at={{(0.5,0)}}, anchor=north, yshift=-31pt, /tikz/every even column/.append style={{column sep=0.3em}}}},\n",
        legend_columns(series, plots_in_row)
    ));
    text.push_str("]\n");
    for (index, line) in series.iter().enumerate() {
        let finite: Vec<(f64, f64)> = line
            .points
            .iter()
            .copied()
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect();
        text.push_str(&format!(
            "\\addplot+[mark=none, {}] coordinates {{\n",
            DASHES[index % DASHES.len()].3
        ));
        for (x, y) in thin(&finite, PGFPLOTS_MAX_POINTS) {
            text.push_str(&format!("  ({},{})\n", fixed(x), fixed(y)));
        }
        text.push_str("};\n");
        text.push_str(&format!("\\addlegendentry{{{}}}\n", line.name.tex));
    }
    text.push_str("\\end{axis}\n\\end{tikzpicture}\n");
    text
}

/// The digits after the point a tick label needs for neighbouring ticks to differ
/// (`0.5, 0.501, 0.502`, not `0.5, 0.5, 0.5`): about five ticks span the values, and the
/// label shows one digit finer than their step; at least pgfplots' own two.
fn tick_precision(values: impl Iterator<Item = f64>) -> usize {
    let (low, high) = values
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
            (l.min(x), h.max(x))
        });
    let step = (high - low) / 5.0;
    if !(step > 0.0 && step.is_finite()) {
        return 2;
    }
    ((-step.log10()).ceil() + 1.0).clamp(2.0, 8.0) as usize
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

/// User text as LaTeX text-mode source.
fn escape_latex(text: &str) -> String {
    crate::render::escape::latex(text, crate::render::escape::Lines::One)
}

#[cfg(test)]
mod tests;

/// What one plot shows, format-neutral: the axes' labels, the series, and how many plots
/// share a row of the page.
#[derive(Clone, Debug, PartialEq)]
pub struct PlotData {
    /// The horizontal axis' label.
    pub x_label: Label,
    /// The vertical axis' label.
    pub y_label: Label,
    /// The curves.
    pub series: Vec<Series>,
    /// How many plots share a row of the page (LaTeX).
    pub plots_in_row: usize,
}
