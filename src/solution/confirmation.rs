//! Step 6 in a course's words: that the equations of motion are integrated, and for each
//! confirmation check one sentence of physics saying what confirms the motion (energy
//! constant where only conservative forces do work, the constraints held, the other methods'
//! second derivatives the same). The checks are computed as before; only their report is
//! written here, without their thresholds or a verdict.

use crate::numeric::Trajectory;
use crate::numeric::{Check, CheckKind};
use crate::problem::{Problem, SimulateSettings};
use crate::render::literal_with_numbers;
use crate::symbolic::fixed;

/// How step 6 integrates the equations, in one sentence a textbook prints: from where and
/// for how long (no integration method, step or tolerance, which a student need not read).
pub fn integration(problem: &Problem, settings: &SimulateSettings) -> String {
    let coordinates = &problem.coordinates;
    let driven = coordinates.iter().any(|c| c.motion.is_some());
    let integrated = (coordinates.iter()).any(|c| c.motion.is_none() && !c.dependent);
    if !integrated {
        return format!(
            "The drive prescribes the whole motion; the plots below show it over {} s.",
            num(settings.duration),
        );
    }
    let start = if problem.impact.is_some() {
        "the state just after the impact"
    } else {
        "the initial state"
    };
    let drive = match driven {
        true => ", the driven coordinates following their prescribed motion,",
        false => "",
    };
    format!(
        "The equations of motion of step 5, integrated numerically from {start} over {} \
         s{drive}, give the plots below.",
        num(settings.duration),
    )
}

/// One sentence of physics for `check`, as markup: what must hold and how the motion
/// holds it, with the numbers a student can read off the plots. `fallback` is the check's
/// own sentence, said when the motion does not hold it.
pub fn sentence(check: &Check, trajectory: &Trajectory, fallback: &str) -> String {
    let said = match check.kind {
        CheckKind::EnergyConservation => energy_constant(trajectory, check.passed),
        CheckKind::EnergyNeverRises => energy_falls(trajectory, check),
        CheckKind::ConstraintDrift if check.passed => {
            Some("The constraints of step 1 hold along the whole motion.".to_string())
        }
        CheckKind::EnergyBalanceWithDrives if check.passed => Some(
            "The drives do work on the system, so its total energy changes by exactly that \
             work: $E(t) - E(0)$ equals the work of the drives' forces over the same time, \
             all along the motion."
                .to_string(),
        ),
        CheckKind::ContactsPress if check.passed => Some(
            "Every contact presses on its surface along the whole motion (its normal force \
             stays positive), so the body never leaves it and the contact's equations hold \
             throughout."
                .to_string(),
        ),
        _ => None,
    };
    said.unwrap_or_else(|| fallback.to_string())
}

/// The energy balance with the applied forces and couples, as markup: their work `W` by
/// the end of the run and the largest `|E(t) − E(0) − W(t)|`; `None` without the energies.
pub fn work_balance(
    problem: &Problem,
    trajectory: &Trajectory,
    work: &[f64],
    held: bool,
) -> Option<String> {
    let (worst, at) = crate::numeric::largest_imbalance(trajectory, work)?;
    let (end_t, end_w) = (trajectory.rows.last()?[0], *work.last()?);
    let who = applied_loads(problem);
    let rough = (problem.constraints.iter().map(|c| &c.friction))
        .chain(problem.joints.iter().map(|j| &j.friction))
        .chain(problem.closures.iter().map(|j| &j.friction))
        .any(Option::is_some);
    // Friction's work is its force's dot product with the slip velocity.
    let (who, slip) = match rough {
        true => (
            format!(
                "{} and friction do",
                who.trim_end_matches(" does").trim_end_matches(" do")
            ),
            "; friction's with the slip velocity",
        ),
        false => (who, ""),
    };
    let head = format!(
        "{who} work on the system, and every other force that does work has a potential, so \
         its total energy changes by exactly the work $W(t)$ done on it, the integral over \
         time of the power (a force's dot product with the velocity of its point, a torque's \
         with the angular velocity of its body{slip}): by $t = {}$ s, $W = {}$ J",
        fixed(end_t),
        num(end_w),
    );
    if !held {
        return Some(format!(
            "{head}, yet $E(t) - E(0) - W(t)$ reaches {} J at $t = {}$ s: these equations do \
             not keep the balance.",
            num(worst),
            fixed(at)
        ));
    }
    // A difference at the round-off of the energies is no number to print: its digits are
    // noise. A larger one is said to two figures.
    let scale = work.iter().fold(0.0f64, |m, w| m.max(w.abs()));
    if worst <= 1e-12 * scale {
        return Some(format!(
            "{head}, and along the motion $E(t) - E(0)$ equals $W(t)$ to within round-off."
        ));
    }
    Some(format!(
        "{head}, and along the motion $E(t) - E(0)$ differs from $W(t)$ by at most {} J.",
        num(format!("{worst:.1e}").parse().unwrap_or(worst))
    ))
}

/// The loads that do work without a potential, named as a course does: "The applied
/// couple does", "The applied forces and torques do".
fn applied_loads(problem: &Problem) -> String {
    use crate::problem::{CoordinateKind, LoadKind};
    let (mut forces, mut couples) = (0, 0);
    for load in &problem.loads {
        match &load.kind {
            LoadKind::Force { .. } => forces += 1,
            LoadKind::Torque { .. } => couples += 1,
            LoadKind::JointActuator { coordinate, .. } => {
                match problem.coordinates[*coordinate].kind {
                    CoordinateKind::Angle => couples += 1,
                    _ => forces += 1,
                }
            }
            _ => {}
        }
    }
    match (forces, couples) {
        (0, 1) => "The applied torque does".into(),
        (0, _) => "The applied torques do".into(),
        (1, 0) => "The applied force does".into(),
        (_, 0) => "The applied forces do".into(),
        (1, 1) => "The applied force and torque do".into(),
        _ => "The applied forces and torques do".into(),
    }
}

/// `x` as [`fixed`] writes it, as markup: a number in scientific notation as math.
fn num(x: f64) -> String {
    literal_with_numbers(&fixed(x))
}

/// `x` to three significant figures: an extreme read off the plotted samples (every
/// 0.01 s) is good to about that, not to six.
fn three_figures(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return num(x);
    }
    let decimals = (2 - x.abs().log10().floor() as i32).max(0) as usize;
    literal_with_numbers(&format!("{x:.decimals$}"))
}

/// The energy's columns: E relative to the start, and the energy the motion trades between
/// T and V (the larger of the ranges of T and V: the largest T is not traded where the
/// motion starts moving, as a spinning top's).
fn energies(trajectory: &Trajectory) -> Option<(Vec<(f64, f64)>, f64)> {
    let total = trajectory.series("total")?;
    let kinetic = trajectory.series("kinetic")?;
    let potential = trajectory.series("potential")?;
    let first = total.first()?.1;
    let change = total.iter().map(|&(t, e)| (t, e - first)).collect();
    Some((change, range(&kinetic).max(range(&potential))))
}

/// The largest value of a series less its smallest.
pub(super) fn range(series: &[(f64, f64)]) -> f64 {
    let (low, high) = (series.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
        (l.min(p.1), h.max(p.1))
    });
    high - low
}

/// Energy constant: every force that does work has a potential.
fn energy_constant(trajectory: &Trajectory, held: bool) -> Option<String> {
    let (change, traded) = energies(trajectory)?;
    let (at, worst) = (change.iter()).fold((0.0, 0.0f64), |best, &(t, d)| {
        if d.abs() > best.1 {
            (t, d.abs())
        } else {
            best
        }
    });
    let head = "Every force that does work on the system has a potential, so its total energy \
                $E = T + V$ must stay constant";
    if !held {
        return Some(format!(
            "{head}; along the motion, however, $E(t) - E(0)$ reaches {} J at $t = {}$ s, \
             against about {} J traded between $T$ and $V$: these equations do not keep it.",
            num(worst),
            fixed(at),
            three_figures(traded)
        ));
    }
    Some(format!(
        "{head}, and along the motion it does, while about {} J is traded between $T$ and $V$ \
         (the energy plot).",
        three_figures(traded)
    ))
}

/// Energy never rising: dampers and sliding friction only take energy away.
fn energy_falls(trajectory: &Trajectory, check: &Check) -> Option<String> {
    let (change, _) = energies(trajectory)?;
    let who = if check.detail().starts_with("sliding friction") {
        "Sliding friction only takes energy away"
    } else {
        "The dampers only take energy away"
    };
    let (end_t, end) = *change.last()?;
    let mut lowest = 0.0f64;
    let (mut rise, mut at) = (0.0f64, 0.0);
    for &(t, e) in &change {
        lowest = lowest.min(e);
        if e - lowest > rise {
            (rise, at) = (e - lowest, t);
        }
    }
    let how = if check.passed {
        "it never rises".to_string()
    } else {
        format!(
            "yet it rises by {} J at $t = {}$ s, which no damper or friction can do",
            num(rise),
            fixed(at)
        )
    };
    let change = if end < 0.0 {
        format!("fallen by {} J", num(-end))
    } else {
        format!("changed by {} J", num(end))
    };
    Some(format!(
        "{who}, so the total energy $E = T + V$ can only fall: by $t = {}$ s it has \
         {change}, and {how} (the energy plots).",
        fixed(end_t),
    ))
}
