//! A small drawing of a mode shape: one bar per coordinate, its height the coordinate's
//! share of the motion (the largest is 1), and for a complex shape its phase above it.
//! The same bars as SVG for HTML and Markdown and as TikZ for LaTeX.

use crate::numeric::Shape;
use crate::render::context::Figure;
use crate::render::text::{InlineSvg, LatexCode};

/// Bar width and spacing (SVG pixels); the bars reach `HEIGHT` above or below the axis.
const STEP: f64 = 56.0;
const HEIGHT: f64 = 40.0;

/// The figure of mode `index` (from 1) of shape `shape` over the coordinates `names`.
pub fn figure(names: &[String], shape: &Shape, index: usize) -> Figure {
    let bars: Vec<(String, f64, Option<f64>)> = match shape {
        Shape::Real(values) => names
            .iter()
            .zip(values)
            .map(|(n, v)| (n.clone(), *v, None))
            .collect(),
        Shape::Complex(values) => names
            .iter()
            .zip(values)
            .map(|(n, (magnitude, phase))| (n.clone(), *magnitude, Some(*phase)))
            .collect(),
    };
    Figure {
        svg_inline: InlineSvg::from(svg(&bars, index)),
        picture_latex: LatexCode::from(tikz(&bars)),
    }
}

fn svg(bars: &[(String, f64, Option<f64>)], index: usize) -> String {
    let width = STEP * bars.len() as f64 + 40.0;
    let height = 2.0 * HEIGHT + 60.0;
    let axis = HEIGHT + 24.0;
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{width}\" height=\"{height}\" viewBox=\"0 0 {width} {height}\" class=\"mode-shape\" id=\"mode-{index}\">\n"
    );
    out.push_str(&format!(
        "<line x1=\"10\" y1=\"{axis}\" x2=\"{}\" y2=\"{axis}\" stroke=\"#555\" stroke-width=\"1\"/>\n",
        width - 10.0
    ));
    for (k, (name, value, phase)) in bars.iter().enumerate() {
        let x = 30.0 + STEP * k as f64;
        let h = value * HEIGHT;
        let (top, size) = if h >= 0.0 { (axis - h, h) } else { (axis, -h) };
        out.push_str(&format!(
            "<rect x=\"{x}\" y=\"{top:.2}\" width=\"{}\" height=\"{size:.2}\" fill=\"#4a78a8\"/>\n",
            STEP * 0.5
        ));
        out.push_str(&format!(
            "<text x=\"{:.1}\" y=\"{}\" font-size=\"12\" text-anchor=\"middle\" font-family=\"serif\">{}</text>\n",
            x + STEP * 0.25,
            height - 6.0,
            name
        ));
        if let Some(phase) = phase {
            out.push_str(&format!(
                "<text x=\"{:.1}\" y=\"12\" font-size=\"10\" text-anchor=\"middle\" font-family=\"serif\">{:.0}°</text>\n",
                x + STEP * 0.25,
                phase.to_degrees()
            ));
        }
    }
    out.push_str("</svg>");
    out
}

fn tikz(bars: &[(String, f64, Option<f64>)]) -> String {
    let mut out = String::from("\\begin{tikzpicture}[x=1.1cm,y=0.8cm]\n");
    out.push_str(&format!(
        "\\draw[gray] (-0.2,0) -- ({:.2},0);\n",
        bars.len() as f64 * 1.0 + 0.2
    ));
    for (k, (name, value, phase)) in bars.iter().enumerate() {
        let x = k as f64 + 0.2;
        out.push_str(&format!(
            "\\fill[blue!55!gray] ({x:.2},0) rectangle ({:.2},{:.4});\n",
            x + 0.5,
            value
        ));
        let label = name.replace('_', "\\_");
        out.push_str(&format!(
            "\\node[below] at ({:.2},-1.05) {{\\small ${label}$}};\n",
            x + 0.25
        ));
        if let Some(phase) = phase {
            out.push_str(&format!(
                "\\node[above] at ({:.2},1.05) {{\\scriptsize ${:.0}^\\circ$}};\n",
                x + 0.25,
                phase.to_degrees()
            ));
        }
    }
    out.push_str("\\end{tikzpicture}\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bars_follow_the_shape() {
        let names = vec!["q1".to_string(), "q2".to_string()];
        let f = figure(&names, &Shape::Real(vec![1.0, -0.5]), 1);
        // The first bar rises 40 px above the axis at y = 64; the second falls 20 px.
        assert!(f
            .svg_inline
            .contains("y=\"24.00\" width=\"28\" height=\"40.00\""));
        assert!(f
            .svg_inline
            .contains("y=\"64.00\" width=\"28\" height=\"20.00\""));
        assert!(f.picture_latex.contains("rectangle (0.70,1.0000)"));
        assert!(f.picture_latex.contains("rectangle (1.70,-0.5000)"));
    }
}
