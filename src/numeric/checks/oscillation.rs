//! The small-oscillation check: the period of the equations of motion against the period
//! the energies give, found without them.
//!
//! The reference comes from the kinetic and potential energy alone (`equations::energy`,
//! compiled apart from `A` and `b`): the mass matrix M of T = ½ q'ᵀ M q' at the
//! equilibrium, the Hessian K of the potential there, and the natural frequencies ω, whose
//! squares are the eigenvalues of M⁻¹K. Only then are the equations of motion integrated,
//! from a small displacement along one mode, and the period measured on the motion. If the
//! equations are wrong (a sign, a factor, a missing term) the two periods differ.

use crate::numeric::check::{Check, CheckKind, Phrase, PERIOD_TOLERANCE};
use crate::numeric::integrate::{integrate, Options};
use crate::numeric::system::System;
use crate::numeric::SolveError;
use crate::symbolic::fixed;
use nalgebra::{DMatrix, DVector, SymmetricEigen};
use std::f64::consts::PI;

/// Most modes checked, the slowest first: each costs an integration over six periods.
pub const MODES_CHECKED: usize = 3;

/// Periods integrated for each mode.
const PERIODS: usize = 6;
/// Output samples per period (the crossings are found on the Hermite interpolant).
const SAMPLES_PER_PERIOD: usize = 400;
/// Size of the displacement along the mode: its largest component (rad or m).
const AMPLITUDE: f64 = 1e-3;

/// The linearized free vibration about a stable equilibrium at rest, from the energies
/// alone: T = ½ q'ᵀ M q' and V ≈ V₀ + ½ δqᵀ K δq.
#[derive(Clone, Debug, PartialEq)]
pub struct Modes {
    /// The coordinates where the potential is least, nearest the start (rad or m).
    pub equilibrium: Vec<f64>,
    /// M, the mass matrix of the kinetic energy there (kg, kg·m or kg·m²).
    pub mass: DMatrix<f64>,
    /// K, the Hessian of the potential energy there (N/m, N·m/rad, ...).
    pub stiffness: DMatrix<f64>,
    /// The natural frequencies, ascending (rad/s): ω² are the eigenvalues of M⁻¹K.
    pub omegas: Vec<f64>,
    /// The mode shapes in the same order, scaled so that φᵀ M φ = 1.
    pub shapes: Vec<DVector<f64>>,
}

/// The equilibrium nearest `q0` where the potential is least (Newton's method on ∇V = 0,
/// with central differences), and the modes there.
///
/// `None` when an energy cannot be evaluated, the search does not converge, M is not
/// positive definite (a coordinate that moves no mass, gimbal lock) or K is not (an
/// unstable or neutral equilibrium: nothing oscillates).
pub fn modes(system: &dyn System, q0: &[f64]) -> Option<Modes> {
    let n = system.coordinate_names().len();
    if n == 0 || q0.len() != n {
        return None;
    }
    let rest = vec![0.0; n];
    let potential = |q: &[f64]| -> Option<f64> {
        let (_, v) = system.energies(0.0, q, &rest).ok()?;
        v.is_finite().then_some(v)
    };
    let equilibrium = least_potential(&potential, q0)?;
    let stiffness = hessian(&potential, &equilibrium)?;
    let kinetic = |rates: &[f64]| -> Option<f64> {
        let (t, _) = system.energies(0.0, &equilibrium, rates).ok()?;
        t.is_finite().then_some(t)
    };
    let mass = mass_matrix(&kinetic, n)?;

    // K φ = ω² M φ, as the symmetric problem (L⁻¹ K L⁻ᵀ) y = ω² y with M = L Lᵀ, φ = L⁻ᵀ y.
    let l = mass.clone().cholesky()?.l();
    let l_inverse = l.try_inverse()?;
    let a = &l_inverse * &stiffness * l_inverse.transpose();
    let a = (&a + a.transpose()) * 0.5;
    let eigen = SymmetricEigen::new(a);
    let mut pairs: Vec<(f64, DVector<f64>)> = eigen
        .eigenvalues
        .iter()
        .zip(eigen.eigenvectors.column_iter())
        .map(|(&w2, y)| (w2, l_inverse.transpose() * y))
        .collect();
    pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let largest = pairs.last()?.0;
    // A neutral direction (a cart free to roll, a hanging body turning about the vertical)
    // shows as an eigenvalue at the level of the finite-difference Hessian's error, about
    // 1e-6 of the largest: a mode that slow would also take thousands of seconds to check.
    if !(pairs[0].0 > 1e-6 * largest && largest.is_finite()) {
        return None;
    }
    let (omegas, shapes) = pairs.into_iter().map(|(w2, s)| (w2.sqrt(), s)).unzip();
    Some(Modes {
        equilibrium,
        mass,
        stiffness,
        omegas,
        shapes,
    })
}

/// Minimizes `v` from `q0`: Newton steps where the Hessian is positive definite, otherwise
/// steepest descent, halving any step that raises `v`.
fn least_potential(v: &dyn Fn(&[f64]) -> Option<f64>, q0: &[f64]) -> Option<Vec<f64>> {
    let mut q = q0.to_vec();
    for _ in 0..100 {
        let gradient = gradient(v, &q)?;
        let hessian = hessian(v, &q)?;
        let mut step = match hessian.clone().cholesky() {
            Some(c) => -c.solve(&gradient),
            None => {
                let curvature = hessian.amax().max(f64::MIN_POSITIVE);
                -gradient / curvature
            }
        };
        let scale = q.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        // The central differences leave the gradient about 1e-10 of the energy: stop well
        // above that floor, far below the amplitude of the oscillation (1e-3).
        if step.amax() <= 1e-8 * scale {
            return Some(q);
        }
        let here = v(&q)?;
        for _ in 0..40 {
            let trial: Vec<f64> = q.iter().zip(step.iter()).map(|(a, b)| a + b).collect();
            // Rounding makes V flat near the minimum: allow it to stay level.
            if v(&trial)? <= here + 1e-12 * here.abs().max(f64::MIN_POSITIVE) {
                break;
            }
            step *= 0.5;
        }
        for (x, dx) in q.iter_mut().zip(step.iter()) {
            *x += dx;
        }
        if !q.iter().all(|x| x.is_finite()) {
            return None;
        }
    }
    None
}

/// The finite-difference step for coordinate value `x`.
fn step_for(x: f64, relative: f64) -> f64 {
    relative * x.abs().max(1.0)
}

fn shifted(q: &[f64], moves: &[(usize, f64)]) -> Vec<f64> {
    let mut q = q.to_vec();
    for &(i, h) in moves {
        q[i] += h;
    }
    q
}

/// ∇v at `q` by central differences.
fn gradient(v: &dyn Fn(&[f64]) -> Option<f64>, q: &[f64]) -> Option<DVector<f64>> {
    let mut g = DVector::zeros(q.len());
    for i in 0..q.len() {
        let h = step_for(q[i], 1e-5);
        g[i] = (v(&shifted(q, &[(i, h)]))? - v(&shifted(q, &[(i, -h)]))?) / (2.0 * h);
    }
    Some(g)
}

/// The Hessian of `v` at `q` by central differences.
fn hessian(v: &dyn Fn(&[f64]) -> Option<f64>, q: &[f64]) -> Option<DMatrix<f64>> {
    let n = q.len();
    let center = v(q)?;
    let mut k = DMatrix::zeros(n, n);
    for i in 0..n {
        let hi = step_for(q[i], 1e-4);
        k[(i, i)] =
            (v(&shifted(q, &[(i, hi)]))? - 2.0 * center + v(&shifted(q, &[(i, -hi)]))?) / (hi * hi);
        for j in 0..i {
            let hj = step_for(q[j], 1e-4);
            let corner = |si: f64, sj: f64| v(&shifted(q, &[(i, si * hi), (j, sj * hj)]));
            let value = (corner(1.0, 1.0)? - corner(1.0, -1.0)? - corner(-1.0, 1.0)?
                + corner(-1.0, -1.0)?)
                / (4.0 * hi * hj);
            k[(i, j)] = value;
            k[(j, i)] = value;
        }
    }
    Some(k)
}

/// M from T(q') = ½ q'ᵀ M q' (+ terms linear in q' and a constant, which cancel) by
/// polarization with unit rates: exact, since T is quadratic in the rates.
fn mass_matrix(t: &dyn Fn(&[f64]) -> Option<f64>, n: usize) -> Option<DMatrix<f64>> {
    let rates = |moves: &[(usize, f64)]| t(&shifted(&vec![0.0; n], moves));
    let at_rest = rates(&[])?;
    let mut m = DMatrix::zeros(n, n);
    for i in 0..n {
        m[(i, i)] = rates(&[(i, 1.0)])? + rates(&[(i, -1.0)])? - 2.0 * at_rest;
        for j in 0..i {
            let value = (rates(&[(i, 1.0), (j, 1.0)])? - rates(&[(i, 1.0), (j, -1.0)])?
                + rates(&[(i, -1.0), (j, -1.0)])?
                - rates(&[(i, -1.0), (j, 1.0)])?)
                / 4.0;
            m[(i, j)] = value;
            m[(j, i)] = value;
        }
    }
    Some(m)
}

/// The small-oscillation check: the period of the equations of motion about the stable
/// equilibrium nearest `q0`, started along each of the `MODES_CHECKED` slowest modes,
/// against 2π/ω from the energies ([`modes`]). With dampers (one coordinate only) the
/// motion's decay rate σ is measured too, and its undamped period 2π/sqrt(ω_d² + σ²)
/// compared.
///
/// `None` when not applicable: a system that can gain energy, dampers with more than one
/// coordinate (the modes then mix), no stable equilibrium, or damping so strong that the
/// motion dies out within the periods integrated.
pub fn small_oscillation(system: &dyn System, q0: &[f64]) -> Option<Check> {
    let names = system.coordinate_names();
    let conservative = system.is_conservative();
    if !conservative && (!system.has_dissipation_only() || names.len() != 1) {
        return None;
    }
    let modes = modes(system, q0)?;
    if !conservative && too_damped(system, &modes) {
        return None;
    }
    let mut at: Vec<Phrase> = Vec::new();
    for (k, (name, &value)) in names.iter().zip(&modes.equilibrium).enumerate() {
        // What the search leaves of an equilibrium at zero is rounding: print it as 0.
        let value = if value.abs() < 1e-7 { 0.0 } else { value };
        let comma = if k == 0 { "" } else { ", " };
        at.push(Phrase::text(comma));
        at.push(Phrase::coordinate(name, 0));
        at.push(Phrase::text(format!(" = {}", fixed(value))));
    }
    let about = |rest: Vec<Phrase>| -> Vec<Phrase> {
        std::iter::once(Phrase::text("about the equilibrium "))
            .chain(at.iter().cloned())
            .chain(rest)
            .collect()
    };
    let checked = modes.omegas.len().min(MODES_CHECKED);
    let mut worst: Option<(f64, usize, Measured)> = None;
    for mode in 0..checked {
        let measured = match measure(system, &modes, mode, !conservative) {
            Ok(measured) => measured,
            Err(why) => {
                let detail = format!(
                    ", the small oscillation in mode {} (ω = {} rad/s from the energies) {why}",
                    mode + 1,
                    fixed(modes.omegas[mode])
                );
                return Some(Check::phrased(
                    CheckKind::SmallOscillationPeriod,
                    f64::INFINITY,
                    PERIOD_TOLERANCE,
                    about(vec![Phrase::text(detail)]),
                ));
            }
        };
        let expected = 2.0 * PI / modes.omegas[mode];
        let error = (measured.period - expected).abs() / expected;
        let error = if error.is_nan() { f64::INFINITY } else { error };
        if worst.as_ref().is_none_or(|w| error > w.0) {
            worst = Some((error, mode, measured));
        }
    }
    let (error, mode, measured) = worst?;
    let omega = modes.omegas[mode];
    let expected = 2.0 * PI / omega;
    let motion = match measured.decay {
        None => format!("measures T = {} s", fixed(measured.period)),
        Some(sigma) => format!(
            "measures the damped period {} s and the decay rate σ = {} 1/s, so the undamped T = \
             2π/sqrt(ω_d² + σ²) = {} s",
            fixed(measured.damped_period),
            fixed(sigma),
            fixed(measured.period)
        ),
    };
    let phrases = if names.len() == 1 {
        about(vec![
            Phrase::text(format!(
                ", the energies give m = {} (T = m ",
                fixed(modes.mass[(0, 0)])
            )),
            Phrase::coordinate(&names[0], 1),
            Phrase::text(format!(
                "²/2) and k = {} (V ≈ k δ",
                fixed(modes.stiffness[(0, 0)])
            )),
            Phrase::coordinate(&names[0], 0),
            Phrase::text(format!(
                "²/2), so ω = {} rad/s and T = 2π/ω = {} s; a small oscillation of the \
                 equations of motion (amplitude {}) over {} periods {motion}",
                fixed(omega),
                fixed(expected),
                fixed(AMPLITUDE),
                measured.periods,
            )),
        ])
    } else {
        // Which modes were checked, in words that fit their number.
        let which = match (checked == modes.omegas.len(), checked) {
            (true, 2) => format!("of the two, mode {} differs more", mode + 1),
            (true, _) => format!("of them, mode {} differs most", mode + 1),
            (false, _) => format!("of the {checked} slowest, mode {} differs most", mode + 1),
        };
        about(vec![Phrase::text(format!(
            ", the energies give {} modes (ω² the eigenvalues of M⁻¹K, M from the kinetic \
             energy, K the Hessian of the potential); {which}: ω = {} rad/s and \
             T = 2π/ω = {} s, and a small oscillation of the equations of motion along it \
             (largest component {}) over {} periods {motion}",
            modes.omegas.len(),
            fixed(omega),
            fixed(expected),
            fixed(AMPLITUDE),
            measured.periods,
        ))])
    };
    Some(Check::phrased(
        CheckKind::SmallOscillationPeriod,
        error,
        PERIOD_TOLERANCE,
        phrases,
    ))
}

/// Whether damping would take the motion below a thousandth of its amplitude within the
/// periods integrated, judged from the equations' own −∂q''/∂q' (this decides only whether
/// the check applies; it never enters the comparison).
fn too_damped(system: &dyn System, modes: &Modes) -> bool {
    let q = &modes.equilibrium;
    let n = q.len();
    let h = 1e-6;
    let rate = |s: f64| -> Option<DVector<f64>> {
        let rates = vec![s; n];
        let a = system.accelerations(0.0, q, &rates).ok()?;
        Some(DVector::from_vec(a))
    };
    let Some(slope) = rate(h).zip(rate(-h)).map(|(p, m)| (p - m) / (2.0 * h)) else {
        return true;
    };
    let sigma = slope.iter().fold(0.0f64, |w, x| w.max(x.abs())) / 2.0;
    let period = 2.0 * PI / modes.omegas[0];
    let decay = sigma * period * PERIODS as f64;
    decay.is_nan() || decay > 1e3f64.ln()
}

/// What the motion of the equations showed.
struct Measured {
    /// The undamped period (s): the measured one, or 2π/sqrt(ω_d² + σ²) with damping.
    period: f64,
    /// The period between crossings (s).
    damped_period: f64,
    /// σ (1/s), when measured.
    decay: Option<f64>,
    /// Periods between the first and the last crossing.
    periods: usize,
}

/// Integrates the equations of motion from the equilibrium displaced along mode `mode`,
/// at rest, and measures the period of the modal coordinate η = φᵀ M δq.
fn measure(
    system: &dyn System,
    modes: &Modes,
    mode: usize,
    damped: bool,
) -> Result<Measured, String> {
    let n = modes.equilibrium.len();
    let shape = &modes.shapes[mode];
    let expected = 2.0 * PI / modes.omegas[mode];
    let start: Vec<f64> = modes
        .equilibrium
        .iter()
        .zip(shape.iter())
        .map(|(q, s)| q + AMPLITUDE * s / shape.amax())
        .chain(std::iter::repeat_n(0.0, n))
        .collect();
    let samples = SAMPLES_PER_PERIOD * PERIODS;
    let spacing = expected / SAMPLES_PER_PERIOD as f64;
    let times: Vec<f64> = (0..=samples).map(|i| i as f64 * spacing).collect();
    let rhs = |t: f64, y: &[f64], dy: &mut [f64]| -> Result<(), SolveError> {
        let a = system.accelerations(t, &y[..n], &y[n..])?;
        dy[..n].copy_from_slice(&y[n..]);
        for (d, a) in dy[n..]
            .iter_mut()
            .zip(a.iter().chain(std::iter::repeat(&f64::NAN)))
        {
            *d = *a;
        }
        Ok(())
    };
    let solution = integrate(rhs, 0.0, &start, &times, &Options::with_tolerance(1e-12));
    if let Some(stop) = solution.stop {
        return Err(format!("could not be integrated: {stop}"));
    }
    let projector = &modes.mass * shape;
    let project = |v: &[f64]| -> f64 { v.iter().zip(projector.iter()).map(|(a, b)| a * b).sum() };
    let eta: Vec<f64> = solution
        .states
        .iter()
        .map(|y| {
            let d: Vec<f64> = y[..n]
                .iter()
                .zip(&modes.equilibrium)
                .map(|(q, e)| q - e)
                .collect();
            project(&d)
        })
        .collect();
    let rate: Vec<f64> = solution.states.iter().map(|y| project(&y[n..])).collect();
    let crossings = crossings(&solution.times, &eta, &rate);
    let (first, last) = match crossings.as_slice() {
        [first, .., last] if crossings.len() >= 3 => (*first, *last),
        _ => {
            return Err(format!(
                "crosses its equilibrium going down only {} times in {PERIODS} expected periods",
                crossings.len()
            ))
        }
    };
    let periods = crossings.len() - 1;
    let damped_period = (last.time - first.time) / periods as f64;
    if !damped {
        return Ok(Measured {
            period: damped_period,
            damped_period,
            decay: None,
            periods,
        });
    }
    // η = A e^(−σt) cos(ω_d t + ϕ): at a downward crossing |η'| = A ω_d e^(−σt).
    let slope = |c: &Crossing| -> Result<f64, String> {
        let i = c.index;
        let mut ends = [0.0; 2];
        for (end, k) in ends.iter_mut().zip([i - 1, i]) {
            let y = &solution.states[k];
            let a = system
                .accelerations(solution.times[k], &y[..n], &y[n..])
                .map_err(|e| format!("could not be evaluated: {e}"))?;
            *end = project(&a);
        }
        let dt = solution.times[i] - solution.times[i - 1];
        Ok(hermite(rate[i - 1], rate[i], ends[0] * dt, ends[1] * dt, c.fraction).abs())
    };
    let sigma = (slope(&first)? / slope(&last)?).ln() / (last.time - first.time);
    let omega_d = 2.0 * PI / damped_period;
    Ok(Measured {
        period: 2.0 * PI / (omega_d * omega_d + sigma * sigma).sqrt(),
        damped_period,
        decay: Some(sigma),
        periods,
    })
}

/// One downward zero crossing: between samples `index − 1` and `index`, at `fraction` of
/// the way, which is `time`.
#[derive(Clone, Copy)]
struct Crossing {
    index: usize,
    fraction: f64,
    time: f64,
}

/// The cubic Hermite interpolant at `s` ∈ [0, 1] of values `p0`, `p1` with derivatives
/// (times the interval) `m0`, `m1`.
fn hermite(p0: f64, p1: f64, m0: f64, m1: f64, s: f64) -> f64 {
    let (s2, s3) = (s * s, s * s * s);
    (2.0 * s3 - 3.0 * s2 + 1.0) * p0
        + (s3 - 2.0 * s2 + s) * m0
        + (-2.0 * s3 + 3.0 * s2) * p1
        + (s3 - s2) * m1
}

fn crossings(times: &[f64], x: &[f64], v: &[f64]) -> Vec<Crossing> {
    let mut crossings = Vec::new();
    for i in 1..times.len().min(x.len()).min(v.len()) {
        if !(x[i - 1] > 0.0 && x[i] <= 0.0) {
            continue;
        }
        let dt = times[i] - times[i - 1];
        let (p0, p1, m0, m1) = (x[i - 1], x[i], v[i - 1] * dt, v[i] * dt);
        let (mut low, mut high) = (0.0, 1.0);
        for _ in 0..60 {
            let middle = 0.5 * (low + high);
            if hermite(p0, p1, m0, m1, middle) > 0.0 {
                low = middle;
            } else {
                high = middle;
            }
        }
        let fraction = 0.5 * (low + high);
        crossings.push(Crossing {
            index: i,
            fraction,
            time: times[i - 1] + fraction * dt,
        });
    }
    crossings
}

/// The times where `x` crosses zero going down, found on the cubic Hermite interpolant of
/// the samples `x` with derivatives `v` at `times` (accurate to the fourth power of the
/// sample spacing, so the period is measured far more finely than the samples).
#[cfg(test)]
pub fn downward_crossings(times: &[f64], x: &[f64], v: &[f64]) -> Vec<f64> {
    crossings(times, x, v).into_iter().map(|c| c.time).collect()
}

#[cfg(test)]
mod tests;
