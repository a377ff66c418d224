//! The work of the applied forces and couples along a run (a torque turning a pinion, a
//! force pulling a cart): their power `F · v_P + M · ω`, written from the kinematics and not
//! from the equations of motion, integrated over the motion. Where every other force that
//! does work has a potential, the total energy changes by exactly that work, which step 6
//! checks.

use super::check::{Check, CheckKind, ENERGY_TOLERANCE};
use super::friction_work::friction_power;
use super::inputs::state_symbols;
use super::simulate::Trajectory;
use super::work_along::{work_along, Imbalance};
use crate::mechanics::{Form, Model, Vector};
use crate::plan::{ActionKind, Source};
use crate::problem::{LoadKind, Problem};
use crate::symbolic::{add, fixed, Expr, Program};

/// The power of the applied forces, couples and joint actuators of `problem`, as one
/// expression of the constants, the state and `t`; `None` where there are none, or where
/// another load also does work without a potential (a damper) or a coordinate is driven:
/// the energy then does not change by their work alone. Friction's power, which needs the
/// friction forces of the run, is `friction_power`'s.
pub fn applied_power(problem: &Problem) -> Option<Expr> {
    let any_applied = (problem.loads.iter()).any(|l| {
        matches!(
            l.kind,
            LoadKind::Force { .. } | LoadKind::Torque { .. } | LoadKind::JointActuator { .. }
        )
    });
    if !any_applied {
        return None;
    }
    let model = Model::build(problem).ok()?;
    // A force with a potential (a gas law) is in V with the springs, not applied.
    let conservative = |i: usize| crate::equations::has_potential(&model, i);
    let applied = |i: usize| {
        matches!(
            problem.loads[i].kind,
            LoadKind::Force { .. } | LoadKind::Torque { .. } | LoadKind::JointActuator { .. }
        ) && !conservative(i)
    };
    let loads = 0..problem.loads.len();
    if !loads.clone().any(applied) || !loads.clone().all(|i| applied(i) || conservative(i)) {
        return None;
    }
    let driven = problem.coordinates.iter().any(|c| c.motion.is_some());
    if driven {
        return None;
    }
    let actions = crate::plan::free_bodies(&model, Form::Handout)
        .ok()?
        .actions;
    let frames = &model.frames;
    let mut terms = Vec::new();
    for action in &actions {
        let Source::Load(i) = action.source else {
            continue;
        };
        if !matches!(
            problem.loads[i].kind,
            LoadKind::Force { .. } | LoadKind::Torque { .. }
        ) || conservative(i)
        {
            continue;
        }
        let body = &model.bodies[action.body.0];
        terms.push(match &action.kind {
            ActionKind::Force { offset, force } => {
                let arm = Vector::new(action.body, offset.clone());
                let velocity = body.origin.velocity.plus(&body.omega.cross(&arm, frames));
                force.dot(&velocity, frames)
            }
            ActionKind::Couple { torque } => torque.dot(&body.omega, frames),
        });
    }
    for load in &problem.loads {
        if let LoadKind::JointActuator { .. } = load.kind {
            let (_, c, value) = crate::plan::joint_load_value(problem, &load.kind)?;
            terms.push(&value * &problem.coordinate_expr(c, 1));
        }
    }
    Some(add(terms))
}

/// The work `W(t)` of the applied loads (their power from the kinematics) and of friction
/// (see `friction_power`) from the start to each row of `trajectory` (J), integrated over each output step by three-point
/// Gauss–Legendre on the quintic through the coordinates, rates and accelerations at its
/// ends; `None` where it does not apply.
pub fn load_work(problem: &Problem, trajectory: &Trajectory) -> Option<Vec<f64>> {
    let power = applied_power(problem)?;
    let mut friction = friction_power(problem, trajectory)?;
    let program = Program::compile(&state_symbols(problem), &[power]);
    let columns: Vec<[usize; 3]> = (problem.coordinates.iter())
        .map(|c| {
            let name = &c.name;
            Some([
                trajectory.column(name)?,
                trajectory.column(&format!("{name}'"))?,
                trajectory.column(&format!("{name}''"))?,
            ])
        })
        .collect::<Option<_>>()?;
    let constants: Vec<f64> = problem.constants.iter().map(|c| c.value).collect();
    let mut scratch = Vec::new();
    let mut power_at = |t: f64, state: &[(f64, f64)]| {
        let mut inputs = constants.clone();
        inputs.extend(state.iter().map(|s| s.0));
        inputs.extend(state.iter().map(|s| s.1));
        inputs.push(t);
        let mut out = [0.0];
        program.run(&inputs, &mut scratch, &mut out);
        out[0]
    };
    let work = work_along(&trajectory.rows, &columns, |t, state| {
        Some(power_at(t, state) + friction(t, state)?)
    })?;
    // A system left at rest (a block that friction holds) has no work to balance.
    let kinetic = trajectory.column("kinetic")?;
    let still = (trajectory.rows.iter().map(|r| r[kinetic]))
        .chain(work.iter().copied())
        .all(|e| e.abs() < STILL);
    (work.iter().all(|w| w.is_finite()) && !still).then_some(work)
}

/// An energy (J) below which a run neither moves nor works: at rest all along.
const STILL: f64 = 1e-9;

/// The largest `|E(t) − E(0) − W(t)|` over the rows, with its time: what the energy
/// balance with the applied loads leaves.
pub fn largest_imbalance(trajectory: &Trajectory, work: &[f64]) -> Option<(f64, f64)> {
    Imbalance::of(trajectory, work).map(|i| (i.worst, i.at))
}

/// The energy balance with the applied forces and couples: `E(t) − E(0) = W(t)` along the
/// run, relative to the larger of the kinetic energy and the work.
pub fn load_work_check(problem: &Problem, trajectory: &Trajectory) -> Option<Check> {
    let work = load_work(problem, trajectory)?;
    let Imbalance { worst, at, scale } = Imbalance::of(trajectory, &work)?;
    Some(Check::new(
        CheckKind::EnergyBalanceWithLoads,
        worst / scale,
        ENERGY_TOLERANCE,
        format!(
            "the total energy differs from its initial value plus the applied loads' work by at most {} J (at t = {} s) on an energy scale of {} J",
            fixed(worst),
            fixed(at),
            fixed(scale)
        ),
    ))
}
