//! The eigenvalues of a sweep against the swept constant: the real parts above (with the
//! stability boundary Re λ = 0), the imaginary parts below. Deterministic SVG, in the
//! style of [`crate::render::plot`].

use crate::numeric::Linearization;
use crate::render::{axes, padded_range, titled_area, unicode_of, PlotError};
use crate::symbolic::latex_name;
use plotters::prelude::*;

/// Size of the picture, in pixels.
const SIZE: (u32, u32) = (720, 640);

const POINT: RGBColor = RGBColor(31, 119, 180);
const BOUNDARY: RGBColor = RGBColor(214, 39, 40);

/// The SVG picture of `results`, one per value of `name` in `values`.
///
/// # Errors
/// [`PlotError::NoData`] when there is no finite eigenvalue; [`PlotError::Drawing`] if the
/// plotting library fails.
pub fn sweep_plot(
    title: &str,
    name: &str,
    values: &[f64],
    results: &[Linearization],
) -> Result<String, PlotError> {
    let name = &unicode_of(&latex_name(name));
    let part = |f: fn(&nalgebra::Complex<f64>) -> f64| -> Vec<(f64, f64)> {
        values
            .iter()
            .zip(results)
            .flat_map(|(x, l)| l.eigen.iter().map(move |e| (*x, f(&e.value))))
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect()
    };
    let re = part(|c| c.re);
    let im = part(|c| c.im);
    if re.is_empty() {
        return Err(PlotError::NoData {
            title: title.into(),
        });
    }
    let drawing = |message: String| PlotError::Drawing {
        title: title.into(),
        message,
    };
    let mut svg = String::new();
    {
        let heading = format!("{title}: eigenvalues against {name}");
        let root = titled_area(&mut svg, SIZE, &heading, 22).map_err(drawing)?;
        let panels = root.split_evenly((2, 1));
        let x_range = padded_range(values.iter().copied(), 0.0);
        for (panel, (points, label)) in panels
            .iter()
            .zip([(&re, "Re λ (1/s)"), (&im, "Im λ (1/s)")])
        {
            let y_range = padded_range(points.iter().map(|p| p.1).chain([0.0]), 0.05);
            let mut chart = axes(panel, name, label, x_range, y_range).map_err(drawing)?;
            chart
                .draw_series(LineSeries::new(
                    [(x_range.0, 0.0), (x_range.1, 0.0)],
                    BOUNDARY.stroke_width(1),
                ))
                .map_err(|e| drawing(e.to_string()))?;
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 3, POINT.filled())))
                .map_err(|e| drawing(e.to_string()))?;
        }
        root.present().map_err(|e| drawing(e.to_string()))?;
    }
    Ok(svg)
}
