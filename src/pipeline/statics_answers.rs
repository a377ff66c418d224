//! The questions of statics answered: `slips` and `tips` at the equilibrium nearest the
//! question's state (every friction site sticking), and `impending`, the value of a
//! constant at which slip or tipping impends there, by Newton's method on the constant,
//! each trial value's equilibrium found anew.

use super::statics::Statics;
use crate::error::Error;
use crate::numeric::{newton_solve, Answer, NewtonFailure, Quantity, SiteState};
use crate::problem::{Problem, ProblemError, ProblemErrors, Question, QuestionKind};
use nalgebra::DVector;

/// The value a `slips` answer is named by: |F|/(μ|N|).
pub const RATIO: &str = "ratio";
/// The value a `tips` answer is named by: the contact's normal force.
pub const NORMAL: &str = "normal";

fn failure(question: &Question, key: &str, message: String, hint: String) -> Error {
    let error = ProblemError {
        path: format!("{}.{key}", question.path),
        column: None,
        message,
        hint: Some(hint),
    };
    Error::Problem(ProblemErrors(vec![error]))
}

/// The question's configuration: the initial one with its `at.state` coordinates.
fn configuration(problem: &Problem, question: &Question) -> Vec<f64> {
    let mut q = problem.initial_state().q;
    for (entry, value) in question.at.state.iter().flatten() {
        if entry.order == 0 {
            q[entry.coordinate] = *value;
        }
    }
    q
}

/// The friction site `site` at `problem`'s equilibrium nearest the question's state, with
/// that state.
fn site_at_rest(
    statics: &Statics,
    problem: &Problem,
    question: &Question,
    site: usize,
    key: &str,
) -> Result<(SiteState, Vec<f64>, Vec<f64>), Error> {
    let name = problem.site_name(site);
    let sites = statics.friction_sites();
    if !sites.iter().any(|s| s == name) {
        let hint = match sites.is_empty() {
            true => "give the site a `friction` coefficient".to_string(),
            false => format!("name a site with friction: {}", sites.join(", ")),
        };
        return Err(failure(
            question,
            key,
            format!("`{name}` has no friction, so statics cannot say whether it slips or tips"),
            hint,
        ));
    }
    let q = configuration(problem, question);
    let e = statics.equilibrium(&q, "the question's state")?;
    let state = (e.motion.friction.iter())
        .find(|s| s.name == name)
        .cloned()
        .ok_or_else(|| {
            failure(
                question,
                key,
                format!("`{name}` is not solved for"),
                "check the problem".into(),
            )
        })?;
    Ok((state, e.q, e.rates))
}

/// |F| / (μ|N|), infinite where friction is needed and μ|N| is zero.
pub fn ratio(site: &SiteState) -> f64 {
    let force = site.friction();
    match (site.limit > 0.0, force == 0.0) {
        (true, _) => force / site.limit,
        (false, true) => 0.0,
        (false, false) => f64::INFINITY,
    }
}

/// Answers a question of statics (`slips`, `tips`, `impending`).
///
/// # Errors
/// A site without friction, no equilibrium near the question's state, or no value of the
/// constant found; each names the question's path.
pub fn answer(statics: &Statics, problem: &Problem, question: &Question) -> Result<Answer, Error> {
    let (values, q, rates) = match &question.kind {
        // A contact's normal force too: one that would have to pull says it is lost.
        QuestionKind::Slips { site } => {
            let (state, q, rates) = site_at_rest(statics, problem, question, *site, "slips")?;
            let mut values = vec![(Quantity::Named(RATIO.into()), ratio(&state))];
            if crate::numeric::one_sided(problem, *site) {
                values.push((Quantity::Named(NORMAL.into()), state.normal));
            }
            (values, q, rates)
        }
        QuestionKind::Tips { site } => {
            let (state, q, rates) = site_at_rest(statics, problem, question, *site, "tips")?;
            (
                vec![(Quantity::Named(NORMAL.into()), state.normal)],
                q,
                rates,
            )
        }
        QuestionKind::Impending { .. } => {
            let (value, q, rates) = impending(statics, problem, question)?;
            (vec![value], q, rates)
        }
        _ => {
            return Err(failure(
                question,
                "kind",
                "not a question of statics".into(),
                "ask it with `answer`".into(),
            ))
        }
    };
    Ok(Answer::at_state(values, 0.0, (q, rates)))
}

type Found = ((Quantity, f64), Vec<f64>, Vec<f64>);

/// The value of the constant at which slip (|F| − μ|N| = 0) or tipping (N = 0) impends.
fn impending(statics: &Statics, problem: &Problem, question: &Question) -> Result<Found, Error> {
    let QuestionKind::Impending {
        constant,
        site,
        tips,
        guess,
    } = question.kind
    else {
        return Err(failure(
            question,
            "impending",
            "not an impending question".into(),
            String::new(),
        ));
    };
    let name = problem.constants[constant].name.clone();
    let site_name = problem.site_name(site).to_string();
    let sites = statics.friction_sites();
    if !sites.contains(&site_name) {
        let hint = match sites.is_empty() {
            true => "give the site a `friction` coefficient: statics finds the forces at rest with it sticking".to_string(),
            false => format!("name a site with friction: {}", sites.join(", ")),
        };
        return Err(failure(
            question,
            "impending.at",
            format!(
                "`{site_name}` has no friction, so neither slip nor tipping can be found there"
            ),
            hint,
        ));
    }
    // The site at rest with the constant set to `value`.
    let at = |value: f64| -> Option<(SiteState, Vec<f64>, Vec<f64>)> {
        let mut swept = problem.clone();
        crate::problem::apply_overrides(&mut swept, &[(name.clone(), value)]).ok()?;
        let q = configuration(&swept, question);
        let e = statics.with_problem(&swept).equilibrium(&q, "").ok()?;
        let state = (e.motion.friction.iter()).find(|s| s.name == site_name)?;
        let state = match state.shared && !tips {
            true => together(&e.motion.friction),
            false => state.clone(),
        };
        Some((state, e.q, e.rates))
    };
    // Slip: |F|/(μ|N|) − 1, whose only zero is the one sought (|F| − μ|N| also vanishes
    // where a shared split leaves a site without load); tipping: N.
    let condition = |s: &SiteState| match tips {
        true => Some(s.normal),
        false => (s.limit > 0.0).then(|| s.friction() / s.limit - 1.0),
    };
    let f = |u: &DVector<f64>| {
        let (state, _, _) = at(u[0])?;
        Some(DVector::from_element(1, condition(&state)?))
    };
    let start = guess.unwrap_or(problem.constants[constant].value);
    let what = if tips { "tipping" } else { "slip" };
    let root = newton_solve(f, DVector::from_element(1, start)).map_err(|e| {
        let message = match e {
            NewtonFailure::NotSolvable => format!(
                "the forces at rest cannot be found with {name} = {}",
                crate::symbolic::fixed(start)
            ),
            NewtonFailure::NoRoot { left, iterations } => format!(
                "no value of {name} found at which {what} impends at {site_name}: after {iterations} Newton iterations {} is still {}",
                if tips { "the normal force (N)" } else { "|F|/(μ|N|) − 1" },
                crate::symbolic::fixed(left)
            ),
        };
        failure(
            question,
            "impending",
            message,
            "give a `guess` nearer the value, or check that the constant changes the forces at the site".into(),
        )
    })?;
    let value = root.u[0];
    let (_, q, rates) = at(value).ok_or_else(|| {
        failure(
            question,
            "impending",
            format!("the forces at rest cannot be found with {name} = {value}"),
            "give another `guess`".into(),
        )
    })?;
    Ok(((Quantity::Named(name), value), q, rates))
}

/// The sites that share their forces at rest (rough contacts of one body on one surface,
/// whose split statics does not fix) taken as one: the sums of their friction and normal
/// forces, so that slip impends, as a textbook takes it, when the whole friction reaches μ
/// times the whole normal force, whether or not one of the contacts would have lifted.
fn together(sites: &[SiteState]) -> SiteState {
    let shared: Vec<&SiteState> = sites.iter().filter(|s| s.shared).collect();
    let mut whole = shared[0].clone();
    for site in &shared[1..] {
        for (t, u) in whole.tangential.iter_mut().zip(&site.tangential) {
            *t += u;
        }
        whole.normal += site.normal;
    }
    whole.limit = whole.coefficient * whole.normal.abs();
    whole
}
