//! The period of small oscillations about a state (a `period` question): from the
//! linearization's eigenvalues, the mode asked for (the one a named coordinate moves most
//! in, else the slowest), its period 2π/ω_d.

use super::linearize::modes::{is_stable, Shape};
use super::linearize::Linearization;
use crate::problem::{ProblemError, Question};

/// The linearization about a state `t`, `q`, `rates`, or why it could not be made.
pub type Linearize<'a> = dyn Fn(f64, &[f64], &[f64]) -> Result<Linearization, String> + 'a;

/// An oscillation found.
#[derive(Clone, Debug, PartialEq)]
pub struct Period {
    /// The period, seconds: 2π/ω_d.
    pub period: f64,
    /// The damped angular frequency ω_d = Im λ, rad/s.
    pub damped: f64,
    /// The natural angular frequency |λ|, rad/s.
    pub natural: f64,
    /// The damping ratio −Re λ/|λ|.
    pub damping_ratio: f64,
    /// Which mode (from 1, slowest first among the oscillations), and how many there are.
    pub mode: (usize, usize),
    /// The independent coordinates the linearization is in, by name.
    pub coordinates: Vec<String>,
}

/// Why there is no period to give: the message and a hint.
pub type NoPeriod = (String, String);

/// The period of the oscillation of `l` that `coordinate` (a name) moves most in, else of
/// the slowest oscillation.
///
/// # Errors
/// An unstable state, a state about which nothing oscillates, or a coordinate that is not
/// one of the independent coordinates of the linearization.
pub fn period(l: &Linearization, coordinate: Option<&str>) -> Result<Period, NoPeriod> {
    let n = l.variables.len() / 2;
    let coordinates: Vec<String> = l.variables[..n].to_vec();
    if !is_stable(&l.eigen, 1e-9) {
        return Err((
            "the state is unstable: small disturbances grow, and there is no oscillation about it"
                .into(),
            "ask about a stable equilibrium or steady motion (`mbd-tutor linearize` gives the eigenvalues)"
                .into(),
        ));
    }
    let scale = l.eigen.iter().map(|e| e.value.norm()).fold(0.0, f64::max);
    // A Jordan block of an ignorable coordinate leaves round-off in the imaginary part.
    let mut oscillations: Vec<_> = (l.modes.iter())
        .filter(|m| m.value.im > 1e-7 * scale)
        .collect();
    oscillations.sort_by(|a, b| a.value.im.total_cmp(&b.value.im));
    if oscillations.is_empty() {
        return Err((
            "nothing oscillates about this state: every eigenvalue of the linearization is real"
                .into(),
            "ask about a stable equilibrium or steady motion".into(),
        ));
    }
    let index = match coordinate {
        None => 0,
        Some(name) => {
            let Some(k) = coordinates.iter().position(|c| c == name) else {
                return Err((
                    format!("`{name}` is not an independent coordinate of the linearization"),
                    format!("name one of {}", coordinates.join(", ")),
                ));
            };
            let moved = |shape: &Shape| match shape {
                Shape::Real(v) => v[k].abs(),
                Shape::Complex(v) => v[k].0,
            };
            // The mode it moves most in; among equals, the slowest.
            let mut best = 0;
            for (i, m) in oscillations.iter().enumerate() {
                if moved(&m.shape) > moved(&oscillations[best].shape) * (1.0 + 1e-9) {
                    best = i;
                }
            }
            best
        }
    };
    let mode = oscillations[index];
    Ok(Period {
        period: std::f64::consts::TAU / mode.value.im,
        damped: mode.value.im,
        natural: mode.value.norm(),
        damping_ratio: mode.damping_ratio,
        mode: (index + 1, oscillations.len()),
        coordinates,
    })
}

/// The oscillation a `period` question asks for, about the state `t`, `q`, `rates`.
pub(super) fn asked(
    question: &Question,
    linearize: Option<&Linearize>,
    (t, q, rates): (f64, &[f64], &[f64]),
    coordinate: Option<&str>,
) -> Result<Period, ProblemError> {
    let Some(linearize) = linearize else {
        return Err(failure(
            question,
            "a period needs the linearization, which is not at hand here",
            "answer the question with `mbd-tutor answer` or `explain`",
        ));
    };
    let l = linearize(t, q, rates).map_err(|e| {
        failure(
            question,
            &format!("cannot linearize here: {e}"),
            "ask about a state where the equations can be solved",
        )
    })?;
    period(&l, coordinate).map_err(|(message, hint)| failure(question, &message, &hint))
}

fn failure(question: &Question, message: &str, hint: &str) -> ProblemError {
    ProblemError {
        path: question.path.clone(),
        column: None,
        message: message.to_string(),
        hint: Some(hint.to_string()),
    }
}
