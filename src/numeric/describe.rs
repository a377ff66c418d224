//! A simulated coordinate's motion described (`describe`): its least and greatest value
//! over the run, its mean over time, its amplitude, the period measured between its
//! successive maxima, and the range of other rates over the same run.
//!
//! The run is the problem's simulation from the initial state up to `at.time` (default
//! `simulate.duration`), sampled at `simulate.output_step` (at most 1/2000 of the run).
//! Between samples the coordinate is the quintic through its value, rate and second
//! derivative at both ends: an extreme is where that curve's slope vanishes, so the
//! numbers do not depend on the sampling beyond the integration tolerance. A rate's range
//! is found the same way from the cubic through the rate and its derivative. The mean is
//! the integral over the run (trapezoids corrected by the end slopes, exact for cubics)
//! divided by its length.

use super::simulate::{simulate, Trajectory};
use super::system::System;
use crate::problem::SimulateSettings;

/// What the description of one coordinate found, in the coordinate's units.
#[derive(Clone, Debug, PartialEq)]
pub struct Description {
    /// The least value over the run.
    pub minimum: f64,
    /// The greatest value over the run.
    pub maximum: f64,
    /// The mean over time.
    pub mean: f64,
    /// Half of maximum − minimum.
    pub amplitude: f64,
    /// The mean time between successive maxima (s), where there are two or more.
    pub period: Option<f64>,
    /// The times of the maxima (s).
    pub maxima: Vec<f64>,
    /// For each other rate asked: its least and greatest value over the run.
    pub rates: Vec<(f64, f64)>,
    /// The length of the run (s).
    pub duration: f64,
}

/// Coefficients (in s ∈ [0, 1], lowest power first) of the quintic through the value,
/// slope and curvature `(p, m, a)` at both ends of an interval of length `h`.
fn quintic(start: (f64, f64, f64), end: (f64, f64, f64), h: f64) -> [f64; 6] {
    let (p0, m0, a0) = (start.0, start.1 * h, start.2 * h * h);
    let (p1, m1, a1) = (end.0, end.1 * h, end.2 * h * h);
    [
        p0,
        m0,
        a0 / 2.0,
        -10.0 * p0 - 6.0 * m0 - 1.5 * a0 + 0.5 * a1 - 4.0 * m1 + 10.0 * p1,
        15.0 * p0 + 8.0 * m0 + 1.5 * a0 - a1 + 7.0 * m1 - 15.0 * p1,
        -6.0 * p0 - 3.0 * m0 - 0.5 * a0 + 0.5 * a1 - 3.0 * m1 + 6.0 * p1,
    ]
}

/// The cubic through the value and slope at both ends, as [`quintic`] writes it.
fn cubic(start: (f64, f64), end: (f64, f64), h: f64) -> [f64; 6] {
    let (p0, m0, p1, m1) = (start.0, start.1 * h, end.0, end.1 * h);
    [
        p0,
        m0,
        -3.0 * p0 - 2.0 * m0 + 3.0 * p1 - m1,
        2.0 * p0 + m0 - 2.0 * p1 + m1,
        0.0,
        0.0,
    ]
}

fn value(c: &[f64; 6], s: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, x| acc * s + x)
}

fn slope(c: &[f64; 6], s: f64) -> f64 {
    (1..6).rev().fold(0.0, |acc, k| acc * s + k as f64 * c[k])
}

/// Where the slope of `c` vanishes in [0, 1], given that it changes sign there: bisection.
fn flat_point(c: &[f64; 6]) -> f64 {
    let (mut lo, mut hi) = (0.0, 1.0);
    let rising = slope(c, 0.0) > 0.0;
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if (slope(c, mid) > 0.0) == rising {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The polynomial between two rows (the rows and the interval's length).
type Interpolant = dyn Fn(&[f64], &[f64], f64) -> [f64; 6];

/// The extremes of one column over the rows: `(least, greatest, times of the interior
/// maxima)`, with the interpolant that `curve` builds for each interval.
fn extremes(rows: &[Vec<f64>], curve: &Interpolant, column: usize) -> (f64, f64, Vec<f64>) {
    let first = rows[0][column];
    let (mut least, mut greatest) = (first, first);
    let mut maxima = Vec::new();
    for pair in rows.windows(2) {
        let (a, b) = (pair[0].as_slice(), pair[1].as_slice());
        let h = b[0] - a[0];
        least = least.min(b[column]);
        greatest = greatest.max(b[column]);
        let c = curve(a, b, h);
        let (d0, d1) = (slope(&c, 0.0), slope(&c, 1.0));
        if d0 * d1 >= 0.0 {
            continue;
        }
        let s = flat_point(&c);
        let x = value(&c, s);
        least = least.min(x);
        greatest = greatest.max(x);
        if d0 > 0.0 {
            maxima.push(a[0] + s * h);
        }
    }
    (least, greatest, maxima)
}

/// The integral of a column over the run, by trapezoids corrected with the end slopes.
fn integral(rows: &[Vec<f64>], column: usize, slope_column: usize) -> f64 {
    rows.windows(2)
        .map(|p| {
            let h = p[1][0] - p[0][0];
            h / 2.0 * (p[0][column] + p[1][column])
                + h * h / 12.0 * (p[0][slope_column] - p[1][slope_column])
        })
        .sum()
}

/// Describes coordinate `k` over the run `trajectory`, with the ranges of the rates of the
/// coordinates `others`.
pub fn describe_run(trajectory: &Trajectory, k: usize, others: &[usize]) -> Option<Description> {
    let n = trajectory.coordinates;
    let rows = &trajectory.rows;
    let duration = rows.last()?[0] - rows.first()?[0];
    if rows.len() < 2 || duration <= 0.0 {
        return None;
    }
    let (q, rate, second) = (1 + k, 1 + n + k, 1 + 2 * n + k);
    let through = move |a: &[f64], b: &[f64], h: f64| {
        quintic((a[q], a[rate], a[second]), (b[q], b[rate], b[second]), h)
    };
    let (minimum, maximum, maxima) = extremes(rows, &through, q);
    let period = match maxima.as_slice() {
        [first, .., last] => Some((last - first) / (maxima.len() - 1) as f64),
        _ => None,
    };
    let rates = (others.iter())
        .map(|&j| {
            let (r, d) = (1 + n + j, 1 + 2 * n + j);
            let through = move |a: &[f64], b: &[f64], h: f64| cubic((a[r], a[d]), (b[r], b[d]), h);
            let (lo, hi, _) = extremes(rows, &through, r);
            (lo, hi)
        })
        .collect();
    Some(Description {
        minimum,
        maximum,
        mean: integral(rows, q, rate) / duration,
        amplitude: (maximum - minimum) / 2.0,
        period,
        maxima,
        rates,
        duration,
    })
}

/// Simulates `system` from `q0`, `rates0` over `duration` (the problem's tolerance and
/// output step, at most `duration / 2000`) and describes coordinate `k`.
///
/// # Errors
/// The simulation's failure, or its stopping before the end, as a message.
pub fn describe(
    system: &dyn System,
    (q0, rates0): (&[f64], &[f64]),
    settings: &SimulateSettings,
    (k, others): (usize, &[usize]),
) -> Result<Description, String> {
    let run = SimulateSettings {
        duration: settings.duration,
        output_step: settings.output_step.min(settings.duration / 2000.0),
        tolerance: settings.tolerance,
    };
    let trajectory = simulate(system, q0, rates0, &run).map_err(|e| e.to_string())?;
    if let Some(stopped) = &trajectory.stopped {
        return Err(format!("the simulation stopped early: {stopped}"));
    }
    describe_run(&trajectory, k, others)
        .ok_or_else(|| "the simulation gave fewer than two instants".to_string())
}
