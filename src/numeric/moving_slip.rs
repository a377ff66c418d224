//! A `slips` question asked of a moving state (a ball released skidding): whether the
//! friction site slides there. Statics answers a `slips` question at rest; in motion the
//! contact point's velocity along the surface decides first (a slip velocity that is not
//! zero is sliding, whatever the forces), and where it is zero the ratio |F|/(μ|N|) that
//! sticking needs decides, as at rest.

use super::friction::SiteState;
use super::quantity::Quantity;
use super::system::System;
use crate::problem::{Problem, Question, QuestionKind};

/// The name of the slip speed among a moving `slips` answer's values.
pub const SLIP: &str = "slip";

/// The name of the ratio |F|/(μ|N|) among a `slips` answer's values.
pub const RATIO: &str = "ratio";

/// The name of the normal force among a `slips` or `tips` answer's values.
pub const NORMAL: &str = "normal";

/// A slip speed below this (m/s) is no slip.
const STILL: f64 = 1e-9;

/// Whether `question` is a `slips` question asked of a moving state: at a time, at a
/// switch, after an impact, or at a state where some rate is not zero.
pub fn asked(problem: &Problem, question: &Question) -> bool {
    if !matches!(question.kind, QuestionKind::Slips { .. }) {
        return false;
    }
    let at = &question.at;
    if at.time.is_some_and(|t| t > 0.0) || at.switch.is_some() || at.after_impact {
        return true;
    }
    let mut rates: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    for (entry, value) in at.state.iter().flatten() {
        if entry.order == 1 {
            rates[entry.coordinate] = *value;
        }
    }
    rates.iter().any(|r| r.abs() > 0.0)
}

/// The ratio |F|/(μ|N|) and the slip speed of the site `site` of `problem` at the state:
/// the values of a moving `slips` answer. Sliding, the ratio is 1 (friction is μ|N|).
///
/// # Errors
/// A site without friction, or a state where the equations cannot be solved; in words.
pub fn values(
    problem: &Problem,
    system: &dyn System,
    site: usize,
    (t, q, rates): (f64, &[f64], &[f64]),
) -> Result<Vec<(Quantity, f64)>, (String, String)> {
    let state = site_state(problem, system, site, (t, q, rates), ("slips", "site"))?;
    let slip = state.slip.iter().map(|v| v * v).sum::<f64>().sqrt();
    // Still, but sticking failed its check (a hoop let go on a slope too steep for μ): the
    // ratio is the one sticking needed, above 1, not the sliding friction's.
    let (force, limit) = match &state.failed_stick {
        Some(stick) if slip <= STILL => (
            super::friction_vectors::norm(&stick.tangential),
            stick.limit,
        ),
        _ => (state.friction(), state.limit),
    };
    let ratio = match (limit > 0.0, force == 0.0) {
        (true, _) => force / limit,
        (false, true) => 0.0,
        (false, false) => f64::INFINITY,
    };
    let slip = if slip > STILL { slip } else { 0.0 };
    let mut found = vec![
        (Quantity::Named(RATIO.into()), ratio),
        (Quantity::Named(SLIP.into()), slip),
    ];
    if one_sided(problem, site) {
        found.push((Quantity::Named(NORMAL.into()), state.normal));
    }
    Ok(found)
}

/// The friction state of the site `site` at the state, for a question `asked` of a `what`
/// (`("slips", "site")`).
///
/// # Errors
/// A site without friction, or a state where the equations cannot be solved; in words.
fn site_state(
    problem: &Problem,
    system: &dyn System,
    site: usize,
    (t, q, rates): (f64, &[f64], &[f64]),
    (asked, what): (&str, &str),
) -> Result<SiteState, (String, String)> {
    let name = problem.site_name(site);
    let (states, _) = system
        .friction_at(t, q, rates, None)
        .map_err(|e| (format!("cannot answer: {e}"), "ask at another state".into()))?;
    let Some(state) = states.into_iter().find(|s| s.name == name) else {
        return Err((
            format!("`{name}` has no friction, so whether it {asked} cannot be asked"),
            format!("give the {what} a `friction` coefficient"),
        ));
    };
    Ok(state)
}

/// Whether the site `site` of `problem` can only push (a `contact` or a `rolling` disc on
/// its plane), so that a normal force that would have to pull loses the contact; a
/// slider's guide or a gear's teeth take either sense.
pub fn one_sided(problem: &Problem, site: usize) -> bool {
    use crate::problem::ConstraintKind::{Contact, Rolling};
    let first = problem.joints.len() + problem.closures.len();
    (site
        .checked_sub(first)
        .and_then(|k| problem.constraints.get(k)))
    .is_some_and(|c| matches!(c.kind, Contact { .. } | Rolling { .. }))
}

/// The normal force of the rough contact `site` of `problem` as the motion starts from
/// the state: the value of a `tips` answer where no equilibrium is near (a body let go
/// out of balance), negative where the contact would have to pull; then the contact
/// point's slip speed, which says the answer holds in motion, not at rest.
///
/// # Errors
/// A site without friction, or a state where the equations cannot be solved; in words.
pub fn normal(
    problem: &Problem,
    system: &dyn System,
    site: usize,
    (t, q, rates): (f64, &[f64], &[f64]),
) -> Result<Vec<(Quantity, f64)>, (String, String)> {
    let state = site_state(problem, system, site, (t, q, rates), ("tips", "contact"))?;
    let slip = state.slip.iter().map(|v| v * v).sum::<f64>().sqrt();
    Ok(vec![
        (Quantity::Named(NORMAL.into()), state.normal),
        (
            Quantity::Named(SLIP.into()),
            if slip > STILL { slip } else { 0.0 },
        ),
    ])
}

/// Whether a `slips` answer's values hold a normal force that would have to pull: the
/// contact is lost, and no friction can hold the body on it.
pub fn contact_lost(values: &[(Quantity, f64)]) -> bool {
    values
        .iter()
        .any(|(q, x)| matches!(q, Quantity::Named(n) if n == NORMAL) && *x < 0.0)
}

/// The slip speed of a moving `slips` answer's values, `None` for one answered at rest.
pub fn slip_speed(values: &[(Quantity, f64)]) -> Option<f64> {
    values
        .iter()
        .find(|(q, _)| matches!(q, Quantity::Named(n) if n == SLIP))
        .map(|(_, x)| *x)
}
