//! The Dormand–Prince 5(4) integrator with dense output (step 6).
//!
//! An explicit Runge–Kutta pair: each step takes seven derivative evaluations (six, since the
//! last of one step is the first of the next), advances with the fifth-order solution and
//! estimates its error from the embedded fourth-order one. The step size follows the error
//! estimate. Output at requested times comes from the method's continuous extension (a
//! fourth-order polynomial over each step), so the step size never has to hit them.
//!
//! Coefficients and the error norm follow Hairer, Nørsett and Wanner, *Solving Ordinary
//! Differential Equations I*, section II.5 and their code DOPRI5.

use std::fmt;

/// Step-size control settings.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Relative tolerance on each component; default 1e-9.
    pub rtol: f64,
    /// Absolute tolerance on each component; default 1e-9.
    pub atol: f64,
    /// Largest step (s); default infinite, i.e. limited only by the span integrated.
    pub max_step: f64,
    /// Smallest step (s) before giving up; default 0, i.e. limited only by floating point
    /// (16 ulp of the current time).
    pub min_step: f64,
    /// The first step (s); default `None`, chosen from the derivative at the start.
    pub initial_step: Option<f64>,
    /// Most steps, accepted and rejected, before giving up; default 10,000,000.
    pub max_steps: usize,
}

impl Default for Options {
    fn default() -> Self {
        Options::with_tolerance(1e-9)
    }
}

impl Options {
    /// Defaults with `atol = rtol = tolerance`.
    pub fn with_tolerance(tolerance: f64) -> Self {
        Options {
            rtol: tolerance,
            atol: tolerance,
            max_step: f64::INFINITY,
            min_step: 0.0,
            initial_step: None,
            max_steps: 10_000_000,
        }
    }
}

/// Why an integration stopped before the last output time.
#[derive(Clone, Debug, PartialEq)]
pub enum Stop<E> {
    /// The derivative function returned an error.
    Derivative(E),
    /// The step shrank below `min_step` or floating-point resolution at time `t`.
    StepUnderflow {
        /// The time reached (s).
        t: f64,
        /// The state there.
        y: Vec<f64>,
        /// The step that was too small (s).
        step: f64,
    },
    /// `max_steps` steps were taken; `t` and `y` are where they ended.
    TooManySteps { t: f64, y: Vec<f64>, steps: usize },
    /// The derivative at the start is not finite.
    NotFinite { t: f64, y: Vec<f64> },
    /// The arguments cannot be used: what is wrong.
    BadArguments(&'static str),
}

impl<E: fmt::Display> fmt::Display for Stop<E> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Stop::Derivative(e) => write!(f, "{e}"),
            Stop::StepUnderflow { t, step, .. } => {
                write!(f, "the step fell to {step:e} at t = {t}")
            }
            Stop::TooManySteps { t, steps, .. } => write!(f, "{steps} steps taken by t = {t}"),
            Stop::NotFinite { t, .. } => write!(f, "the derivative is not finite at t = {t}"),
            Stop::BadArguments(what) => write!(f, "{what}"),
        }
    }
}

/// Counts kept during an integration.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Steps accepted.
    pub accepted: usize,
    /// Steps rejected by the error test.
    pub rejected: usize,
    /// Calls of the derivative function.
    pub evaluations: usize,
}

/// The states at the output times reached, and why the integration stopped early, if it did.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution<E> {
    /// The output times reached, a prefix of those requested.
    pub times: Vec<f64>,
    /// The state at each of `times`.
    pub states: Vec<Vec<f64>>,
    /// `None` when every output time was reached.
    pub stop: Option<Stop<E>>,
    /// Step counts.
    pub stats: Stats,
}

// The Dormand–Prince tableau. Nodes c2..c6 (c7 = 1).
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
// The fifth-order weights (also the last stage's row: the pair is "first same as last").
const B1: f64 = 35.0 / 384.0;
const B3: f64 = 500.0 / 1113.0;
const B4: f64 = 125.0 / 192.0;
const B5: f64 = -2187.0 / 6784.0;
const B6: f64 = 11.0 / 84.0;
// Fifth- minus fourth-order weights: the local error estimate.
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;
// The continuous extension (Hairer's DOPRI5 `d` coefficients).
const D1: f64 = -12715105075.0 / 11282082432.0;
const D3: f64 = 87487479700.0 / 32700410799.0;
const D4: f64 = -10690763975.0 / 1880347072.0;
const D5: f64 = 701980252875.0 / 199316789632.0;
const D6: f64 = -1453857185.0 / 822651844.0;
const D7: f64 = 69997945.0 / 29380423.0;

// Step-size control: the usual safety factor and bounds on how fast the step may change.
const SAFETY: f64 = 0.9;
const SHRINK_MOST: f64 = 0.2;
const GROW_MOST: f64 = 10.0;

/// Integrates `y' = f(t, y)` from `(t0, y0)` and returns `y` at each of `outputs`.
///
/// `f(t, y, dy)` writes the derivative into `dy`. `outputs` must be finite, ascending and
/// not before `t0`; the last one is where the integration ends, and it is reached exactly.
///
/// # Errors
/// Never panics and never loops without bound: when `f` fails, the step collapses or the
/// step limit is hit, the result holds the outputs reached so far and a [`Stop`].
pub fn integrate<E, F>(
    mut f: F,
    t0: f64,
    y0: &[f64],
    outputs: &[f64],
    options: &Options,
) -> Solution<E>
where
    F: FnMut(f64, &[f64], &mut [f64]) -> Result<(), E>,
{
    let mut solution = Solution {
        times: Vec::new(),
        states: Vec::new(),
        stop: None,
        stats: Stats::default(),
    };
    if let Some(problem) = check_arguments(t0, y0, outputs, options) {
        solution.stop = Some(Stop::BadArguments(problem));
        return solution;
    }
    let n = y0.len();
    let mut next_output = 0;
    while next_output < outputs.len() && outputs[next_output] <= t0 {
        solution.times.push(outputs[next_output]);
        solution.states.push(y0.to_vec());
        next_output += 1;
    }
    let Some(&t_end) = outputs.last().filter(|_| next_output < outputs.len()) else {
        return solution;
    };

    let mut k = [(); 7].map(|()| vec![0.0; n]);
    let mut stage = vec![0.0; n];
    let mut y_new = vec![0.0; n];
    let mut y = y0.to_vec();
    let mut t = t0;

    solution.stats.evaluations += 1;
    if let Err(e) = f(t, &y, &mut k[0]) {
        solution.stop = Some(Stop::Derivative(e));
        return solution;
    }
    if k[0].iter().any(|v| !v.is_finite()) {
        solution.stop = Some(Stop::NotFinite { t, y });
        return solution;
    }
    let max_step = options.max_step.min(t_end - t0);
    let mut h = match options.initial_step {
        Some(h) => h.min(max_step),
        None => {
            let h0 = first_guess(&y, &k[0], max_step, options);
            combine(&mut stage, &y, h0, &[(1.0, &k[0][..])]);
            solution.stats.evaluations += 1;
            let (first, rest) = k.split_at_mut(1);
            match f(t + h0, &stage, &mut rest[0]) {
                Ok(()) => second_guess(&y, &first[0], &rest[0], h0, max_step, options),
                Err(_) => h0,
            }
        }
    };
    let mut just_rejected = false;
    // The derivative's latest error inside a trial step, reported if the steps collapse.
    let mut failure = None;

    loop {
        if solution.stats.accepted + solution.stats.rejected >= options.max_steps {
            solution.stop = Some(Stop::TooManySteps {
                t,
                y,
                steps: options.max_steps,
            });
            return solution;
        }
        // Stretch a step that would stop just short of the end, so no sliver step remains.
        let last = t + 1.01 * h >= t_end;
        if last {
            h = t_end - t;
        }
        let resolution = options
            .min_step
            .max(16.0 * f64::EPSILON * t.abs().max(t_end.abs()));
        if h <= resolution || h.is_nan() {
            solution.stop = Some(match failure {
                Some(e) => Stop::Derivative(e),
                None => Stop::StepUnderflow { t, y, step: h },
            });
            return solution;
        }

        let attempt = try_step(
            &mut f,
            t,
            h,
            &y,
            &mut k,
            &mut stage,
            &mut y_new,
            &mut solution.stats.evaluations,
        );
        let error = match attempt {
            Ok(()) => error_norm(&k, &y, &y_new, h, options),
            // A failure inside the step (a singular state, say) is treated like a large
            // error: shrinking the step closes in on the failing state, so the output
            // reaches as close to it as floating point allows.
            Err(e) => {
                failure = Some(e);
                f64::INFINITY
            }
        };

        if error <= 1.0 {
            solution.stats.accepted += 1;
            failure = None;
            let t_new = if last { t_end } else { t + h };
            let dense = Dense::new(&y, &y_new, &k, h);
            while next_output < outputs.len() && outputs[next_output] <= t_new {
                let at = outputs[next_output];
                solution.times.push(at);
                solution.states.push(if at == t_new {
                    y_new.clone()
                } else {
                    dense.at((at - t) / h)
                });
                next_output += 1;
            }
            if next_output == outputs.len() {
                return solution;
            }
            t = t_new;
            std::mem::swap(&mut y, &mut y_new);
            // First same as last: this step's final stage is the next one's first.
            k.swap(0, 6);
            let mut factor = (SAFETY * error.powf(-0.2)).clamp(SHRINK_MOST, GROW_MOST);
            if just_rejected {
                // Hairer's rule: right after a rejection, do not grow again at once.
                factor = factor.min(1.0);
            }
            just_rejected = false;
            h = (h * factor).min(max_step);
        } else {
            solution.stats.rejected += 1;
            // A NaN or infinite error (the derivative failed or blew up inside the step)
            // shrinks as much as allowed.
            let factor = if error.is_finite() {
                (SAFETY * error.powf(-0.2)).max(SHRINK_MOST)
            } else {
                SHRINK_MOST
            };
            h *= factor;
            just_rejected = true;
        }
    }
}

/// One trial step of size `h` from `(t, y)`: fills the stages `k[1..]` and `y_new`, the
/// fifth-order solution; `k[0]` holds `f(t, y)` on entry.
#[allow(clippy::too_many_arguments)]
fn try_step<E, F>(
    f: &mut F,
    t: f64,
    h: f64,
    y: &[f64],
    k: &mut [Vec<f64>; 7],
    stage: &mut [f64],
    y_new: &mut [f64],
    evaluations: &mut usize,
) -> Result<(), E>
where
    F: FnMut(f64, &[f64], &mut [f64]) -> Result<(), E>,
{
    let [k1, k2, k3, k4, k5, k6, k7] = k;
    let mut f = |t: f64, y: &[f64], dy: &mut [f64]| {
        *evaluations += 1;
        f(t, y, dy)
    };
    combine(stage, y, h, &[(A21, &k1[..])]);
    f(t + C2 * h, stage, k2)?;
    combine(stage, y, h, &[(A31, &k1[..]), (A32, &k2[..])]);
    f(t + C3 * h, stage, k3)?;
    combine(
        stage,
        y,
        h,
        &[(A41, &k1[..]), (A42, &k2[..]), (A43, &k3[..])],
    );
    f(t + C4 * h, stage, k4)?;
    combine(
        stage,
        y,
        h,
        &[
            (A51, &k1[..]),
            (A52, &k2[..]),
            (A53, &k3[..]),
            (A54, &k4[..]),
        ],
    );
    f(t + C5 * h, stage, k5)?;
    combine(
        stage,
        y,
        h,
        &[
            (A61, &k1[..]),
            (A62, &k2[..]),
            (A63, &k3[..]),
            (A64, &k4[..]),
            (A65, &k5[..]),
        ],
    );
    f(t + h, stage, k6)?;
    combine(
        y_new,
        y,
        h,
        &[
            (B1, &k1[..]),
            (B3, &k3[..]),
            (B4, &k4[..]),
            (B5, &k5[..]),
            (B6, &k6[..]),
        ],
    );
    f(t + h, y_new, k7)
}

/// The reason the arguments cannot be used, if any.
fn check_arguments(
    t0: f64,
    y0: &[f64],
    outputs: &[f64],
    options: &Options,
) -> Option<&'static str> {
    if !t0.is_finite() || y0.iter().any(|v| !v.is_finite()) {
        return Some("the initial time and state must be finite");
    }
    if outputs.iter().any(|v| !v.is_finite() || *v < t0) || outputs.windows(2).any(|w| w[1] < w[0])
    {
        return Some("the output times must be finite, ascending and not before the start");
    }
    let positive = |x: f64| x > 0.0 && x.is_finite();
    let not_negative = |x: f64| x >= 0.0 && x.is_finite();
    if !positive(options.rtol) || !not_negative(options.atol) {
        return Some("the tolerances must be positive and finite");
    }
    // An infinite max_step means "no limit"; NaN fails both tests.
    if options.max_step.is_nan() || options.max_step <= 0.0 || !not_negative(options.min_step) {
        return Some("the step bounds must be positive");
    }
    if options.initial_step.is_some_and(|h| !positive(h)) {
        return Some("the initial step must be positive and finite");
    }
    None
}

/// `out = y + h * sum(weight * k)`.
fn combine(out: &mut [f64], y: &[f64], h: f64, terms: &[(f64, &[f64])]) {
    for (i, slot) in out.iter_mut().enumerate() {
        let sum: f64 = terms.iter().map(|(weight, k)| weight * k[i]).sum();
        *slot = y[i] + h * sum;
    }
}

/// The root-mean-square of `v / (atol + rtol * |reference|)`.
fn scaled_rms(v: impl Iterator<Item = (f64, f64)>, n: usize, options: &Options) -> f64 {
    let sum: f64 = v
        .map(|(value, reference)| {
            let scale = options.atol + options.rtol * reference.abs();
            (value / scale).powi(2)
        })
        .sum();
    (sum / n.max(1) as f64).sqrt()
}

/// The estimated local error relative to the tolerance: the step is accepted when <= 1.
fn error_norm(k: &[Vec<f64>; 7], y: &[f64], y_new: &[f64], h: f64, options: &Options) -> f64 {
    let [k1, _, k3, k4, k5, k6, k7] = k;
    let terms = (0..y.len()).map(|i| {
        let e = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
        (e, y[i].abs().max(y_new[i].abs()))
    });
    scaled_rms(terms, y.len(), options)
}

/// A first step small enough that an explicit Euler step stays near the solution
/// (Hairer's HINIT, first half).
fn first_guess(y: &[f64], f0: &[f64], max_step: f64, options: &Options) -> f64 {
    let d0 = scaled_rms(y.iter().map(|v| (*v, *v)), y.len(), options);
    let d1 = scaled_rms(f0.iter().zip(y).map(|(d, v)| (*d, *v)), y.len(), options);
    let h0 = if d0 < 1e-10 || d1 < 1e-10 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    h0.min(max_step)
}

/// The first step from the estimated second derivative (Hairer's HINIT, second half).
fn second_guess(
    y: &[f64],
    f0: &[f64],
    f1: &[f64],
    h0: f64,
    max_step: f64,
    options: &Options,
) -> f64 {
    let d1 = scaled_rms(f0.iter().zip(y).map(|(d, v)| (*d, *v)), y.len(), options);
    let second = (0..y.len()).map(|i| ((f1[i] - f0[i]) / h0, y[i]));
    let d2 = scaled_rms(second, y.len(), options);
    let largest = d1.max(d2);
    let h1 = if largest <= 1e-15 || largest.is_nan() {
        (h0 * 1e-3).max(1e-6)
    } else {
        (0.01 / largest).powf(0.2)
    };
    (100.0 * h0).min(h1).min(max_step)
}

/// The continuous extension over one accepted step.
struct Dense {
    coefficients: [Vec<f64>; 5],
}

impl Dense {
    fn new(y: &[f64], y_new: &[f64], k: &[Vec<f64>; 7], h: f64) -> Self {
        let [k1, _, k3, k4, k5, k6, k7] = k;
        let n = y.len();
        let mut c = [(); 5].map(|()| vec![0.0; n]);
        for i in 0..n {
            let difference = y_new[i] - y[i];
            let bspl = h * k1[i] - difference;
            c[0][i] = y[i];
            c[1][i] = difference;
            c[2][i] = bspl;
            c[3][i] = difference - h * k7[i] - bspl;
            c[4][i] =
                h * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i]);
        }
        Dense { coefficients: c }
    }

    /// The state at the fraction `theta` (0 ..= 1) of the step.
    fn at(&self, theta: f64) -> Vec<f64> {
        let [c0, c1, c2, c3, c4] = &self.coefficients;
        let rest = 1.0 - theta;
        (0..c0.len())
            .map(|i| c0[i] + theta * (c1[i] + rest * (c2[i] + theta * (c3[i] + rest * c4[i]))))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::{integrate, Options, Stop};
    use std::convert::Infallible;

    /// `0, step, 2 step, ..., count step`, each computed as a product so none drifts.
    fn grid(step: f64, count: usize) -> Vec<f64> {
        (0..=count).map(|i| i as f64 * step).collect()
    }

    #[test]
    fn exponential_decay_matches_closed_form() {
        let times = grid(0.1, 50);
        let decay = |_: f64, y: &[f64], dy: &mut [f64]| -> Result<(), Infallible> {
            dy[0] = -2.0 * y[0];
            Ok(())
        };
        let solution = integrate(decay, 0.0, &[3.0], &times, &Options::with_tolerance(1e-10));
        assert!(solution.stop.is_none());
        assert_eq!(
            solution.times, times,
            "outputs fall exactly on the grid, end inclusive"
        );
        for (t, y) in solution.times.iter().zip(&solution.states) {
            let exact = 3.0 * (-2.0 * t).exp();
            assert!((y[0] - exact).abs() < 1e-9, "t = {t}: {} vs {exact}", y[0]);
        }
    }

    /// x'' = -w^2 x over 100 periods; the global error stays near the tolerance times the
    /// number of periods, and the dense output between steps is as good as the steps.
    #[test]
    fn harmonic_oscillator_over_many_periods() {
        let w = 3.0;
        let period = 2.0 * std::f64::consts::PI / w;
        let times = grid(period / 20.0, 2000);
        let oscillator = |_: f64, y: &[f64], dy: &mut [f64]| -> Result<(), Infallible> {
            dy[0] = y[1];
            dy[1] = -w * w * y[0];
            Ok(())
        };
        let solution = integrate(
            oscillator,
            0.0,
            &[1.0, 0.0],
            &times,
            &Options::with_tolerance(1e-10),
        );
        assert!(solution.stop.is_none());
        assert_eq!(solution.times.len(), 2001);
        let worst = solution
            .times
            .iter()
            .zip(&solution.states)
            .map(|(t, y)| {
                (y[0] - (w * t).cos())
                    .abs()
                    .max((y[1] + w * (w * t).sin()).abs() / w)
            })
            .fold(0.0, f64::max);
        assert!(worst < 1e-7, "worst error {worst}");
    }

    /// With a loose tolerance the steps are long, so most outputs come from the continuous
    /// extension; they are as accurate as the steps themselves.
    #[test]
    fn dense_output_between_steps() {
        let times = grid(0.001, 2000);
        let rhs = |_: f64, y: &[f64], dy: &mut [f64]| -> Result<(), Infallible> {
            dy[0] = y[1];
            dy[1] = -y[0];
            Ok(())
        };
        let solution = integrate(
            rhs,
            0.0,
            &[1.0, 0.0],
            &times,
            &Options::with_tolerance(1e-6),
        );
        assert!(solution.stats.accepted < 100, "{:?}", solution.stats);
        for (t, y) in solution.times.iter().zip(&solution.states) {
            assert!((y[0] - t.cos()).abs() < 1e-5, "t = {t}");
        }
    }

    /// The error estimate drives the step: a fifth-order method needs about 10 times the
    /// steps for a 1e5 times smaller tolerance, and the error follows the tolerance.
    #[test]
    fn step_size_follows_tolerance() {
        let run = |tolerance: f64| {
            let rhs = |_: f64, y: &[f64], dy: &mut [f64]| -> Result<(), Infallible> {
                dy[0] = y[1];
                dy[1] = -y[0];
                Ok(())
            };
            let solution = integrate(
                rhs,
                0.0,
                &[0.0, 1.0],
                &[10.0],
                &Options::with_tolerance(tolerance),
            );
            let error = (solution.states[0][0] - 10f64.sin()).abs();
            (solution.stats.accepted as f64, error)
        };
        let (loose_steps, loose_error) = run(1e-5);
        let (tight_steps, tight_error) = run(1e-10);
        let ratio = tight_steps / loose_steps;
        assert!((6.0..16.0).contains(&ratio), "step ratio {ratio}");
        assert!(
            loose_error < 1e-4 && tight_error < 1e-9,
            "{loose_error} {tight_error}"
        );
        assert!(tight_error < loose_error / 1e3);
    }

    #[test]
    fn max_step_is_respected() {
        let rhs = |_: f64, _: &[f64], dy: &mut [f64]| -> Result<(), Infallible> {
            dy[0] = 1.0;
            Ok(())
        };
        let options = Options {
            max_step: 0.1,
            ..Options::with_tolerance(1e-6)
        };
        let solution = integrate(rhs, 0.0, &[0.0], &[1.0], &options);
        assert!(solution.stats.accepted >= 10, "{:?}", solution.stats);
        assert!((solution.states[0][0] - 1.0).abs() < 1e-12);
    }

    /// y' = y^2, y(0) = 1 is 1/(1 - t): it blows up at t = 1, and the integrator must say
    /// so rather than loop.
    #[test]
    fn blow_up_reports_step_underflow() {
        let rhs = |_: f64, y: &[f64], dy: &mut [f64]| -> Result<(), Infallible> {
            dy[0] = y[0] * y[0];
            Ok(())
        };
        let solution = integrate(
            rhs,
            0.0,
            &[1.0],
            &grid(0.25, 8),
            &Options::with_tolerance(1e-9),
        );
        assert_eq!(solution.times, vec![0.0, 0.25, 0.5, 0.75]);
        assert!((solution.states[3][0] - 4.0).abs() < 1e-7);
        match solution.stop {
            Some(Stop::StepUnderflow { t, .. }) => assert!((t - 1.0).abs() < 1e-6, "t = {t}"),
            other => panic!("expected a step underflow, got {other:?}"),
        }
        assert!(solution.stats.accepted + solution.stats.rejected < 10_000);
    }

    #[test]
    fn step_limit_stops_the_run() {
        let rhs = |_: f64, y: &[f64], dy: &mut [f64]| -> Result<(), Infallible> {
            dy[0] = y[1];
            dy[1] = -1e4 * y[0];
            Ok(())
        };
        let options = Options {
            max_steps: 50,
            ..Options::with_tolerance(1e-9)
        };
        let solution = integrate(rhs, 0.0, &[1.0, 0.0], &grid(1.0, 100), &options);
        assert!(
            matches!(solution.stop, Some(Stop::TooManySteps { steps: 50, .. })),
            "{:?}",
            solution.stop
        );
        assert_eq!(solution.times, vec![0.0]);
    }

    #[test]
    fn derivative_error_keeps_rows_so_far() {
        let rhs = |t: f64, y: &[f64], dy: &mut [f64]| {
            if t > 0.55 {
                return Err(format!("singular at t = {t}"));
            }
            dy[0] = -y[0];
            Ok(())
        };
        let solution = integrate(
            rhs,
            0.0,
            &[1.0],
            &grid(0.1, 10),
            &Options::with_tolerance(1e-9),
        );
        assert!(matches!(solution.stop, Some(Stop::Derivative(_))));
        // The steps close in on t = 0.55, so every output before it is there.
        assert_eq!(solution.times, grid(0.1, 5));
        for (t, y) in solution.times.iter().zip(&solution.states) {
            assert!((y[0] - (-t).exp()).abs() < 1e-9);
        }
    }

    #[test]
    fn non_finite_start_and_bad_arguments_are_reported() {
        let nan = |_: f64, _: &[f64], dy: &mut [f64]| -> Result<(), Infallible> {
            dy[0] = f64::NAN;
            Ok(())
        };
        let solution = integrate(nan, 0.0, &[1.0], &[0.0, 1.0], &Options::default());
        assert!(matches!(solution.stop, Some(Stop::NotFinite { .. })));
        assert_eq!(solution.times, vec![0.0]);
        let solution = integrate(nan, 0.0, &[1.0], &[1.0, 0.5], &Options::default());
        assert!(matches!(solution.stop, Some(Stop::BadArguments(_))));
    }

    /// A derivative that turns NaN partway shrinks the step until it underflows: no hang.
    #[test]
    fn nan_inside_the_run_ends_without_hanging() {
        let rhs = |t: f64, _: &[f64], dy: &mut [f64]| -> Result<(), Infallible> {
            dy[0] = if t > 0.3 { f64::NAN } else { 1.0 };
            Ok(())
        };
        let solution = integrate(rhs, 0.0, &[0.0], &grid(0.1, 10), &Options::default());
        match solution.stop {
            Some(Stop::StepUnderflow { t, .. }) => assert!((t - 0.3).abs() < 1e-12, "t = {t}"),
            other => panic!("expected a step underflow, got {other:?}"),
        }
        // The steps only approach t = 0.3, so the output there is never reached.
        assert_eq!(solution.times, grid(0.1, 2));
    }
}
