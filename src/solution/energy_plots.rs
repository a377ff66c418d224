//! Step 6's energy plots, each quantity on an axis where it shows: the energies themselves
//! where every curve that moves spans a visible part of the axis, else their changes from
//! the start (`T`, `V − V₀`, `E − E₀`), and a change still too small beside the others on an
//! axis of its own (a ladder that slips loses 0.049 J while its kinetic energy stays under
//! 0.0002 J).

use crate::render::{PlotLabel as Label, Series};

/// The least share of its axis's range a curve that moves must span to be seen.
pub const VISIBLE_SHARE: f64 = 0.05;

/// A plot: its kind (the file's name), its title, its vertical axis's label and its curves.
pub type EnergyPlot = (String, String, Label, Vec<Series>);

/// The largest value of `series` less its smallest, and its smallest and largest.
pub fn range(series: &Series) -> (f64, f64, f64) {
    let (low, high) = (series.points.iter())
        .filter(|p| p.1.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p.1), h.max(p.1))
        });
    if low > high {
        return (0.0, 0.0, 0.0);
    }
    (high - low, low, high)
}

/// The range of the vertical axis that holds `series`: their largest value less their
/// smallest.
pub fn axis_span(series: &[Series]) -> f64 {
    let (low, high) = series
        .iter()
        .map(range)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), (_, lo, hi)| {
            (l.min(lo), h.max(hi))
        });
    if low > high {
        0.0
    } else {
        high - low
    }
}

/// Whether `series` moves by more than round-off against `scale`, the largest size of the
/// energies: a constant energy is a flat line, which is what is said of it.
pub fn moves(series: &Series, scale: f64) -> bool {
    range(series).0 > 1e-6 * scale.max(1e-12)
}

/// Whether every curve of `series` that moves spans [`VISIBLE_SHARE`] of their axis.
pub fn all_visible(series: &[Series], scale: f64) -> bool {
    let span = axis_span(series);
    (series.iter())
        .filter(|s| moves(s, scale))
        .all(|s| range(s).0 >= VISIBLE_SHARE * span)
}

/// The largest size of the values of `series`.
fn size(series: &[Series]) -> f64 {
    (series.iter())
        .flat_map(|s| s.points.iter().map(|p| p.1.abs()))
        .filter(|x| x.is_finite())
        .fold(0.0, f64::max)
}

/// The energy's plots from `energies` (kinetic, potential and total, with their legends'
/// symbols `kinetic`, `V` and `total`), `title` the plot's title where the energies
/// themselves are plotted.
pub fn energy_plots(energies: Vec<Series>, kinetic: &str, title: String) -> Vec<EnergyPlot> {
    let scale = size(&energies);
    if energies.is_empty() || all_visible(&energies, scale) {
        return vec![("energy".into(), title, Label::words("energy (J)"), energies)];
    }
    // Each energy less its value at the start, named as what it is.
    let changes: Vec<Series> = (energies.iter())
        .map(|s| {
            let start = s.points.first().map_or(0.0, |p| p.1);
            let symbol = match s.name == Label::math(kinetic, "") {
                true => kinetic,
                false if s.name == Label::math("V", "") => "V",
                false => "E",
            };
            if start.abs() <= 1e-9 * scale.max(1e-12) {
                return Series {
                    name: Label::math(symbol, ""),
                    points: s.points.clone(),
                };
            }
            Series {
                name: Label::math(&format!("{symbol} - {symbol}_{{0}}"), ""),
                points: s.points.iter().map(|&(t, e)| (t, e - start)).collect(),
            }
        })
        .collect();
    // The smallest curve that moves yet lies flat beside the others, on an axis of its own.
    let mut shared = changes;
    let mut alone: Vec<Series> = Vec::new();
    while !all_visible(&shared, scale) && shared.len() > 1 {
        let smallest = (0..shared.len())
            .filter(|&k| moves(&shared[k], scale))
            .min_by(|&a, &b| range(&shared[a]).0.total_cmp(&range(&shared[b]).0));
        match smallest {
            Some(k) => alone.push(shared.remove(k)),
            None => break,
        }
    }
    let mut plots = vec![(
        "energy".to_string(),
        match kinetic {
            "K" => "Energy changes from the start (K is the kinetic energy)".to_string(),
            _ => "Energy changes from the start".to_string(),
        },
        Label::words("energy change (J)"),
        shared,
    )];
    for (k, series) in alone.into_iter().enumerate() {
        let what = match series.name.tex.replace('$', "") {
            s if s.starts_with(kinetic) => "kinetic energy",
            s if s.starts_with('V') => "potential energy",
            _ => "total energy",
        };
        let title = match series.name.tex.contains("_{0}") {
            true => format!("Change of the {what} from the start"),
            false if what == "kinetic energy" => format!("Kinetic energy {kinetic} against time"),
            false => format!("The {what} against time"),
        };
        plots.push((
            format!("energy-{}", k + 2),
            title,
            Label::words("energy (J)"),
            vec![series],
        ));
    }
    plots
}
