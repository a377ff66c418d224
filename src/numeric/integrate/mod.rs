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
//!
//! | file | what |
//! |---|---|
//! | `mod.rs` | the options, the result, and the driver [`integrate`] |
//! | `dormand_prince.rs` | the tableau, one trial step, the local error estimate |
//! | `dense_output.rs` | the continuous extension, for output between step ends |
//! | `step_size.rs` | the first step and how fast the step may change |

mod dense_output;
mod dormand_prince;
mod step_size;

use dense_output::Dense;
use dormand_prince::{combine, error_norm, try_step};
use std::fmt;
use step_size::{first_guess, second_guess, GROW_MOST, SAFETY, SHRINK_MOST};

/// An instant where a switching function fell to zero.
#[derive(Clone, Debug, PartialEq)]
pub struct Event {
    /// The time (s), the first at which the function is zero or below.
    pub t: f64,
    /// The state there.
    pub y: Vec<f64>,
    /// Which functions fell, by index.
    pub which: Vec<usize>,
}

/// The first instant within a step at which a switching function falls from positive to
/// zero or below: bisection on the dense output, from the values at the step's two ends.
fn locate<G>(
    events: &mut G,
    dense: &Dense,
    t: f64,
    h: f64,
    before: &[f64],
    after: &[f64],
) -> Option<(f64, Vec<f64>, Vec<usize>)>
where
    G: FnMut(f64, &[f64]) -> Vec<f64>,
{
    let falls = |now: &[f64]| -> Vec<usize> {
        (0..before.len().min(now.len()))
            .filter(|&i| before[i] > 0.0 && now[i] <= 0.0)
            .collect()
    };
    if falls(after).is_empty() {
        return None;
    }
    let (mut low, mut high) = (0.0f64, 1.0f64);
    let resolution = 1e-13 * (1.0 + t.abs()) / h.abs().max(f64::MIN_POSITIVE);
    while high - low > resolution {
        let middle = 0.5 * (low + high);
        let now = events(t + middle * h, &dense.at(middle));
        if falls(&now).is_empty() {
            low = middle;
        } else {
            high = middle;
        }
    }
    let y = dense.at(high);
    let which = falls(&events(t + high * h, &y));
    let which = if which.is_empty() {
        falls(after)
    } else {
        which
    };
    Some((t + high * h, y, which))
}

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
    /// Where a switching function fell to zero, ending the run early (see
    /// [`integrate_until`]).
    pub event: Option<Event>,
    /// `None` when every output time was reached.
    pub stop: Option<Stop<E>>,
    /// Step counts.
    pub stats: Stats,
}

/// Integrates `y' = f(t, y)` from `(t0, y0)` and returns `y` at each of `outputs`.
///
/// `f(t, y, dy)` writes the derivative into `dy`. `outputs` must be finite, ascending and
/// not before `t0`; the last one is where the integration ends, and it is reached exactly.
///
/// # Errors
/// Never panics and never loops without bound: when `f` fails, the step collapses or the
/// step limit is hit, the result holds the outputs reached so far and a [`Stop`].
pub fn integrate<E, F>(f: F, t0: f64, y0: &[f64], outputs: &[f64], options: &Options) -> Solution<E>
where
    F: FnMut(f64, &[f64], &mut [f64]) -> Result<(), E>,
{
    integrate_until(f, |_, _| Vec::new(), t0, y0, outputs, options)
}

/// As [`integrate`], stopping early at the first instant one of the switching functions
/// `events(t, y)` falls from positive to zero or below: located on the step's dense output
/// by bisection (to about 1e-13 of the step's time), and kept in [`Solution::event`] with
/// the rows up to it. An empty list from `events` means none can fall.
// A numerical recipe, kept as one loop as its sources write it: Dormand–Prince 5(4) with
// Hairer's step-size control (Hairer, Nørsett & Wanner, Solving ODEs I, II.4 and II.6).
#[allow(clippy::too_many_lines)]
pub fn integrate_until<E, F, G>(
    mut f: F,
    mut events: G,
    t0: f64,
    y0: &[f64],
    outputs: &[f64],
    options: &Options,
) -> Solution<E>
where
    F: FnMut(f64, &[f64], &mut [f64]) -> Result<(), E>,
    G: FnMut(f64, &[f64]) -> Vec<f64>,
{
    let mut solution = Solution {
        times: Vec::new(),
        states: Vec::new(),
        event: None,
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
    let mut switching = events(t, &y);

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
            let mut t_new = if last { t_end } else { t + h };
            let dense = Dense::new(&y, &y_new, &k, h);
            let after = events(t_new, &y_new);
            let event = locate(&mut events, &dense, t, h, &switching, &after);
            if let Some((at, _, _)) = &event {
                t_new = *at;
            }
            while next_output < outputs.len() && outputs[next_output] <= t_new {
                let at = outputs[next_output];
                solution.times.push(at);
                solution.states.push(if at == t_new && event.is_none() {
                    y_new.clone()
                } else {
                    dense.at((at - t) / h)
                });
                next_output += 1;
            }
            if let Some((t, y, which)) = event {
                solution.event = Some(Event { t, y, which });
                return solution;
            }
            if next_output == outputs.len() {
                return solution;
            }
            switching = after;
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

#[cfg(test)]
mod tests;
