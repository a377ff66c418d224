//! The titles of step 6's plots where a fixed title would not say what is plotted: the
//! angles that move little, named by what they are ("Nutation angle against time"), and
//! the energy's plot, which says the range of a part lost under the others and what `K`
//! is where `T` names a torque.

use crate::problem::{CoordinateKind, Problem};
use crate::render::{PlotLabel as Label, Series};
use crate::symbolic::{fixed, latex_name};

/// A kinetic energy whose largest value is under this share of the plot's whole range
/// lies on the axis, and the total on the potential energy: its largest value is said in
/// the title.
const HIDDEN_SHARE: f64 = 0.03;

/// The words of a coordinate's description before its first comma, formula or "about"
/// (`nutation angle`, `tilt of the ring`), with "angle" after an angle's single word
/// (`lean angle`).
fn what_it_is(problem: &Problem, i: usize) -> Option<String> {
    let c = &problem.coordinates[i];
    let description = c.description.as_deref()?;
    let cut = [",", "$", " about ", " relative ", " from ", "("]
        .iter()
        .filter_map(|stop| description.find(stop))
        .min()
        .unwrap_or(description.len());
    let words = description[..cut].trim();
    if words.is_empty() || !words.chars().all(|ch| ch.is_alphabetic() || ch == ' ') {
        return None;
    }
    let angle = c.kind == CoordinateKind::Angle && !words.contains("angle") && !words.contains(' ');
    Some(match angle {
        true => format!("{words} angle"),
        false => words.to_string(),
    })
}

/// `Nutation angle against time`: a plot of angles of one range, on an axis of their own
/// beside angles of another, named by its description when it holds one angle; where it
/// holds several (their legend names them) or a description says nothing short, `Angles
/// against time` for the largest (`first`), the smaller ones by their number.
pub fn angles_of_a_range(problem: &Problem, series: &[Series], first: bool) -> String {
    let names: Option<Vec<String>> = (series.iter())
        .map(|s| {
            let i = (0..problem.coordinates.len())
                .find(|&i| s.name == Label::math(&latex_name(&problem.coordinates[i].name), ""))?;
            what_it_is(problem, i)
        })
        .collect();
    let words = match names {
        Some(mut names) if names.len() == 1 => names.remove(0),
        _ if first => "angles".to_string(),
        _ if series.len() == 1 => "the smaller angle".to_string(),
        _ => "the smaller angles".to_string(),
    };
    let mut chars = words.chars();
    let first = chars.next().map(|c| c.to_uppercase().to_string());
    format!(
        "{}{} against time",
        first.unwrap_or_default(),
        chars.as_str()
    )
}

/// `x` > 0 rounded up to two significant digits, as a bound is said (0.0308 → 0.031).
fn two_digits_up(x: f64) -> f64 {
    let step = 10f64.powi(x.log10().floor() as i32 - 1);
    let up = (x / step).ceil() * step;
    // Printed with the digits it has, not the round-off of the product.
    (up / step).round() * step
}

/// The largest value of a series less its smallest, and its largest.
fn span(series: &Series) -> (f64, f64) {
    let (low, high) = (series.points.iter())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p.1), h.max(p.1))
        });
    (high - low, high)
}

/// `Energy against time`, with the largest kinetic energy where its curve lies on the axis
/// (`T stays below 0.031 J, too small to show at this scale`), and what `K` is where `T` names a drive's torque.
pub fn energy(problem: &Problem, series: &[Series]) -> String {
    let named_t = problem.constants.iter().any(|c| c.name == "T");
    let kinetic = if named_t { "K" } else { "T" };
    let mut notes = Vec::new();
    if named_t {
        notes.push("K is the kinetic energy".to_string());
    }
    let whole = (series.iter()).flat_map(|s| s.points.iter().map(|p| p.1));
    let (low, high) = whole.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), y| {
        (l.min(y), h.max(y))
    });
    let kinetic_series = series.iter().find(|s| s.name == Label::math(kinetic, ""));
    if let Some((range, largest)) = kinetic_series.map(span) {
        // A kinetic energy of round-off (a body at rest) is no curve to look for.
        let whole = high - low;
        let hidden = largest > 1e-6 * whole && largest < HIDDEN_SHARE * whole && range > 0.0;
        if hidden {
            notes.push(format!(
                "{kinetic} stays below {} J, too small to show at this scale",
                fixed(two_digits_up(largest))
            ));
        }
    }
    match notes.is_empty() {
        true => "Energy against time".to_string(),
        false => format!("Energy against time ({})", notes.join("; ")),
    }
}
