//! The words and numbers of the statics handout: the configuration sought (step 1), why
//! step 4 needs only positions, the equilibrium found with what holds it there (step 5),
//! its stability, and that the system stays at rest (step 6).

use crate::problem::{CoordinateKind, Problem};
use crate::render::context::{StaticFriction, StaticsView};
use crate::render::text::{MarkupLine, Math};
use crate::symbolic::{fixed, latex};
use crate::{Equilibrium, Stability, StabilityKind};

/// The statics of the handout of `problem` at `equilibrium`, `free` the coordinates whose
/// equilibrium value the equations find.
pub fn section(problem: &Problem, equilibrium: &Equilibrium, free: &[usize]) -> StaticsView {
    StaticsView {
        sought: MarkupLine::from(sought(problem, free, !equilibrium.motion.drives.is_empty())),
        kinematics_note: MarkupLine::from(
            "At rest every velocity and every acceleration is zero, so no body has an inertia force or torque: statics needs only the positions of the points where the forces act, with which step 2 writes them.",
        ),
        found: MarkupLine::from(found(problem, equilibrium, free)),
        state_tex: problem
            .coordinates
            .iter()
            .enumerate()
            .map(|(i, _)| {
                let unit = unit_tex(problem, i, false);
                Math::from(format!(
                    "{} = {}{unit}",
                    latex(&problem.coordinate_expr(i, 0)),
                    number(equilibrium.q[i])
                ))
            })
            .collect(),
        held_tex: held(problem, equilibrium),
        friction: friction(equilibrium),
        stability: MarkupLine::from(
            equilibrium
                .stability
                .as_ref()
                .map(|s| stability_words(s, free.is_empty()))
                .unwrap_or_default(),
        ),
        eigenvalues_tex: equilibrium
            .stability
            .as_ref()
            .map(eigenvalues)
            .unwrap_or_default(),
        rest_note: MarkupLine::from(rest(equilibrium)),
    }
}

/// −0 written as 0.
fn number(x: f64) -> String {
    fixed(if x == 0.0 { 0.0 } else { x })
}

/// The unit of coordinate `i`, or of the generalized force along it (`force`), in LaTeX
/// after a thin space; empty for none.
fn unit_tex(problem: &Problem, i: usize, force: bool) -> String {
    let c = &problem.coordinates[i];
    let unit = match (force, c.kind) {
        (true, CoordinateKind::Angle) => "N*m".to_string(),
        (true, CoordinateKind::Distance) => "N".to_string(),
        (false, _) => match (&c.unit, c.kind) {
            (Some(unit), _) => unit.clone(),
            (None, CoordinateKind::Angle) => "rad".into(),
            (None, CoordinateKind::Distance) => String::new(),
        },
    };
    if unit.is_empty() {
        return String::new();
    }
    format!("\\ {}", crate::render::unit_tex(&unit))
}

fn names_tex(problem: &Problem, indices: &[usize]) -> String {
    let names: Vec<String> = indices
        .iter()
        .map(|&i| format!("${}$", latex(&problem.coordinate_expr(i, 0))))
        .collect();
    names.join(", ")
}

fn sought(problem: &Problem, free: &[usize], held: bool) -> String {
    if free.is_empty() {
        let what = match held {
            true => "the reactions and the holding forces of the supports",
            false => "the reactions",
        };
        return format!("The system is at rest in the configuration given, which its supports, constraints and friction fix: what is sought are the forces that keep it there, {what}.");
    }
    format!(
        "The system is at rest: every coordinate keeps its value. Sought: the equilibrium configuration (the value of {} at which the forces on every body balance), the reactions there and whether the equilibrium is stable.",
        names_tex(problem, free)
    )
}

fn found(problem: &Problem, equilibrium: &Equilibrium, free: &[usize]) -> String {
    if free.is_empty() {
        return "The configuration is the one given, so the equations of step 5 are linear in the reactions and holding forces; solved for them, at".into();
    }
    let names = names_tex(problem, free);
    match equilibrium.iterations {
        0 => format!(
            "The configuration given already satisfies the equilibrium equations for {names}, with the reactions and holding forces below:"
        ),
        n => format!(
            "The equilibrium equations are nonlinear in {names}. Solved by Newton's method, started from the configuration given and converged in {n} iteration{} (each step solves the equations linearized about the last estimate), they give the equilibrium:",
            if n == 1 { "" } else { "s" }
        ),
    }
}

/// The generalized force each held or prescribed coordinate's support supplies.
fn held(problem: &Problem, equilibrium: &Equilibrium) -> Vec<Math> {
    equilibrium
        .motion
        .drives
        .iter()
        .filter_map(|(name, x)| {
            let i = problem.coordinates.iter().position(|c| &c.name == name)?;
            let symbol = latex(&problem.coordinate_expr(i, 0));
            Some(Math::from(format!(
                "Q_{{{symbol}}} = {}{}",
                number(*x),
                unit_tex(problem, i, true)
            )))
        })
        .collect()
}

fn friction(equilibrium: &Equilibrium) -> Vec<StaticFriction> {
    equilibrium
        .motion
        .friction
        .iter()
        .map(|site| {
            let r = site.friction_ratio();
            StaticFriction {
                site: site.name.clone(),
                normal: number(site.normal),
                tangential: number(site.friction()),
                ratio: r.map_or("—".into(), number),
                verdict: match r {
                    Some(r) if r <= 1.0 => "friction holds it (it needs no more than μ times the normal force)".into(),
                    _ => "friction cannot hold it: the site slips (it would need more than μ times the normal force)".into(),
                },
            }
        })
        .collect()
}

/// The stability in words; `fixed` when friction and the constraints fix the configuration.
fn stability_words(stability: &Stability, fixed: bool) -> String {
    let all_zero = stability
        .eigenvalues
        .iter()
        .all(|&(re, im)| re == 0.0 && im == 0.0);
    if fixed && all_zero {
        return "While friction holds, no coordinate can move: every eigenvalue of the linearized equations is zero, and there is no motion near the equilibrium to call stable or unstable.".into();
    }
    match stability.kind {
        StabilityKind::Stable => "The equilibrium is stable: no eigenvalue of the equations linearized about it has a positive real part, and none is zero, so a small disturbance leaves the system oscillating about the equilibrium or returning to it.",
        StabilityKind::Unstable => "The equilibrium is unstable: an eigenvalue of the equations linearized about it has a positive real part, so a small disturbance grows and the system moves away.",
        StabilityKind::Neutral => "The equilibrium is neutral: an eigenvalue of the equations linearized about it is zero, so the linearization alone does not decide whether a small disturbance grows.",
    }
    .into()
}

fn eigenvalues(stability: &Stability) -> Vec<Math> {
    stability
        .eigenvalues
        .iter()
        .enumerate()
        .map(|(k, &(re, im))| {
            let value = match (number(re).as_str(), im) {
                (_, im) if number(im) == "0" => number(re),
                ("0", im) => format!("{}\\,i", number(im)),
                (re, im) if im < 0.0 => format!("{re} - {}\\,i", number(-im)),
                (re, im) => format!("{re} + {}\\,i", number(im)),
            };
            Math::from(format!("\\lambda_{{{}}} = {value}", k + 1))
        })
        .collect()
}

fn rest(equilibrium: &Equilibrium) -> String {
    let slips = equilibrium
        .motion
        .friction
        .iter()
        .any(|site| site.friction_ratio().is_none_or(|r| r > 1.0));
    let unstable = equilibrium
        .stability
        .as_ref()
        .is_some_and(|s| s.kind == StabilityKind::Unstable);
    if slips {
        "Nothing to integrate at rest, but friction cannot supply what rest needs (step 5): released here, the system would not stay at rest but slip.".into()
    } else if unstable {
        "Nothing to integrate: placed exactly here, the system stays at rest, but the equilibrium is unstable and the least disturbance starts a motion away from it.".into()
    } else {
        "Nothing to integrate: the forces balance, so the system placed here stays at rest.".into()
    }
}
