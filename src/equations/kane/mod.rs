//! Kane's method: one row per generalized speed, F_r + F_r* = 0, from the partial
//! velocities and partial angular velocities; requested reactions through auxiliary speeds.

use crate::mechanics::{ComponentKind, Components, DotSum, Form, Model, Vector};
use crate::plan::{
    is_external, is_joint_load, joint_load_generalized_forces, load_generalized_forces, Action,
    ActionKind, Category, Equation, Groups, Inertia, Source, Sum,
};

pub(super) mod constrained;
pub(super) mod loads;
mod moved;
mod rows;

use crate::symbolic::{add, linear_split, Expr, Symbol};
pub(super) use rows::{rows, view};

/// The partial velocities of a vector linear in the rates: one vector per rate.
pub fn partials(v: &Vector, rates: &[Symbol]) -> Vec<Vector> {
    let mut out = vec![Vector::zero(); rates.len()];
    for (frame, components) in v.parts() {
        let split: Vec<Vec<Expr>> = components
            .iter()
            .map(|c| {
                linear_split(c, rates)
                    .map(|(coefficients, _)| coefficients)
                    .unwrap_or_else(|_| vec![Expr::zero(); rates.len()])
            })
            .collect();
        for (r, slot) in out.iter_mut().enumerate() {
            let c: Components = std::array::from_fn(|i| split[i][r].clone());
            *slot = slot.plus(&Vector::new(*frame, c));
        }
    }
    out
}

/// Partial velocities of the bodies' origins and partial angular velocities, per speed;
/// in spatial problems also those of the mass centres in each body's own unit vectors.
struct Partials {
    origin: Vec<Vec<Vector>>,
    omega: Vec<Vec<Vector>>,
    /// Indexed by body, then speed: ∂a*/∂q̈_r, which equals ∂v*/∂q̇_r. Read off the
    /// accelerations the inertia forces use, these are the named coefficients there, so
    /// `v_r · (-m a*)` is three products of names, not products of direction cosines
    /// multiplied out across the chain. Empty for a planar body whose acceleration is short,
    /// which is read as the student writes it.
    center_own: Vec<Vec<Vector>>,
    /// ∂α/∂q̈_r = ∂ω/∂q̇_r likewise, in the body's own unit vectors.
    omega_own: Vec<Vec<Vector>>,
}

/// The coefficients of the accelerations in each of `vectors`, a vector per acceleration;
/// none for a body that `wanted` leaves out.
fn own_partials(
    vectors: &[Vector],
    accelerations: &[Symbol],
    wanted: impl Fn(usize) -> bool,
) -> Vec<Vec<Vector>> {
    let body = |(index, v): (usize, &Vector)| {
        if wanted(index) {
            partials(v, accelerations)
        } else {
            Vec::new()
        }
    };
    vectors.iter().enumerate().map(body).collect()
}

/// Kane's rows, one per coordinate, and one per requested reaction component (the
/// augmented form: with constraints, their forces are unknowns of every row), and one per
/// `kept` component of a tree joint's reaction not requested (a rough slider's normal
/// force, which its friction is written with).
pub fn equations(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    unknowns: &[Symbol],
    (reaction_joints, kept): (&[usize], &[Symbol]),
) -> Vec<Equation> {
    let groups = generalized_groups(model, actions, inertia, Workless::TreeReactions);
    let rates: Vec<Symbol> = model.problem.speed_symbols(1);
    let mut rows: Vec<Equation> = groups
        .into_iter()
        .zip(&rates)
        .map(|(groups, rate)| generalized_row(model, rate.to_string(), groups, unknowns))
        .collect();
    for &j in reaction_joints {
        rows.extend(auxiliary_rows(model, actions, inertia, unknowns, (j, None)));
    }
    for j in kept_joints(model, reaction_joints, kept) {
        rows.extend(auxiliary_rows(
            model,
            actions,
            inertia,
            unknowns,
            (j, Some(kept)),
        ));
    }
    rows
}

/// The tree joints, not among `requested`, with a reaction component in `kept`.
pub(crate) fn kept_joints(model: &Model, requested: &[usize], kept: &[Symbol]) -> Vec<usize> {
    (0..model.problem.joints.len())
        .filter(|j| !requested.contains(j))
        .filter(|&j| {
            let site = &model.sites[j];
            (site.reactions.iter()).any(|c| kept.contains(&c.unknown(&site.name)))
        })
        .collect()
}

/// Kane's row of `groups` for the speed named `speed`: every body in it.
pub(crate) fn generalized_row(
    model: &Model,
    speed: String,
    groups: Groups,
    unknowns: &[Symbol],
) -> Equation {
    let expression = groups.total();
    Equation {
        free_body: model.order.clone(),
        sum: Sum::Generalized { speed },
        direction: None,
        unknowns: crate::plan::unknowns_in(&expression, unknowns),
        groups,
        expression,
    }
}

/// Which forces do no work with the speeds the rows are formed for, and are left out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Workless {
    /// The reactions of the tree's joints: with the coordinates' rates as speeds, the
    /// reactions at closures and contacts, and what enforces the other constraints, do work.
    TreeReactions,
    /// Every reaction and every force that enforces a constraint: with the independent
    /// speeds, they do none (Kane & Levinson, ch. 4). The rows are then combined by the
    /// dependent speeds before any is used.
    EveryConstraintForce,
}

/// The generalized active and inertia forces of every speed, `F_r` and `F_r^*` in groups,
/// without the forces `workless` names.
pub(crate) fn generalized_groups(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    workless: Workless,
) -> Vec<Groups> {
    let problem = model.problem;
    let frames = &model.frames;
    let rates: Vec<Symbol> = problem.speed_symbols(1);
    let accelerations: Vec<Symbol> = problem.speed_symbols(2);
    let own = |body: usize| !model.is_planar() || inertia.compact[body];
    let partial = Partials {
        origin: model
            .bodies
            .iter()
            .map(|b| partials(&b.origin.velocity, &rates))
            .collect(),
        omega: model
            .bodies
            .iter()
            .map(|b| partials(&b.omega, &rates))
            .collect(),
        center_own: own_partials(&inertia.acceleration, &accelerations, own),
        omega_own: own_partials(&inertia.alpha, &accelerations, own),
    };
    let joint_loads = match workless {
        Workless::TreeReactions => {
            let mut q = joint_load_generalized_forces(model);
            // A rough slider's friction is the one part of a tree joint's reaction that
            // does work with the coordinates' rates.
            crate::equations::friction::add_friction_forces(model, &mut q, true);
            q
        }
        Workless::EveryConstraintForce => {
            let mut q = load_generalized_forces(model);
            // Friction does work wherever its site slips: the slip rates stay speeds.
            crate::equations::friction::add_friction_forces(model, &mut q, false);
            q
        }
    };
    let generalized_joint_loads = speeds_forces(model, joint_loads);
    let all_bodies: Vec<_> = model.order.clone();
    let mut out = Vec::with_capacity(rates.len());
    for (r, joint_load) in generalized_joint_loads.iter().enumerate() {
        let velocity_of = |body: crate::problem::BodyId, offset: &Components| -> Vector {
            let w = &partial.omega[body.0][r];
            partial.origin[body.0][r].plus(&w.cross(&Vector::new(body, offset.clone()), frames))
        };
        let (mut contact, mut distance) = (vec![joint_load.clone()], Vec::new());
        for action in actions {
            let workless = match (workless, action.source) {
                (Workless::TreeReactions, Source::Reaction(j)) => j < problem.joints.len(),
                (Workless::EveryConstraintForce, Source::Reaction(_)) => true,
                _ => false,
            };
            if workless || is_joint_load(model, action) {
                // Reactions at the tree's joints do no work with these speeds; joint loads
                // (and what enforces a constraint row without a site) are taken above.
                continue;
            }
            let term = match &action.kind {
                // For the numbers, a force at a mass centre dots the centre's named partial
                // velocity, three products, instead of the lever arms of every joint inboard.
                ActionKind::Force { offset, force }
                    if inertia.form == Form::Numeric
                        && !partial.center_own[action.body.0].is_empty()
                        && *offset == model.bodies[action.body.0].center_offset =>
                {
                    force.dot(&partial.center_own[action.body.0][r], frames)
                }
                ActionKind::Force { offset, force } => {
                    force.dot(&velocity_of(action.body, offset), frames)
                }
                ActionKind::Couple { torque } => {
                    torque.dot(&partial.omega[action.body.0][r], frames)
                }
            };
            match action.category {
                Category::Contact => contact.push(term),
                Category::Distance => distance.push(term),
            }
        }
        let mut inertia_force = DotSum::new(frames);
        let mut inertia_torque = Vec::new();
        for &body in &all_bodies {
            if partial.center_own[body.0].is_empty() {
                let center = &model.bodies[body.0].center_offset;
                inertia_force.add(&velocity_of(body, center), &inertia.force[body.0]);
                inertia_torque.push(inertia.torque[body.0].dot(&partial.omega[body.0][r], frames));
            } else {
                // Both in the body's own unit vectors: three products each.
                inertia_force.add(&partial.center_own[body.0][r], &inertia.force[body.0]);
                inertia_torque
                    .push(inertia.torque[body.0].dot(&partial.omega_own[body.0][r], frames));
            }
        }
        out.push(Groups {
            contact: add(contact),
            distance: add(distance),
            inertia_force: inertia_force.total(),
            inertia_torque: add(inertia_torque),
        });
    }
    out
}

/// Generalized forces on the coordinates as generalized forces of the speeds: with declared
/// speeds `∂q'_s/∂u_r = W⁻¹[s][r]`, so `F_r = Σ_s Q_s W⁻¹[s][r]`; otherwise unchanged.
fn speeds_forces(model: &Model, q: Vec<Expr>) -> Vec<Expr> {
    let Some(speeds) = &model.speeds else {
        return q;
    };
    (0..q.len())
        .map(|r| {
            let f = add(q.iter().zip(&speeds.inverse).map(|(qs, row)| qs * &row[r]));
            speeds.to_speeds(&crate::symbolic::simplify(&f))
        })
        .collect()
}

/// Rows for an auxiliary speed along each reaction component of joint `j` (those in
/// `only`, where given): the subtree outboard of the joint moves rigidly along (or about)
/// the component's direction.
pub(crate) fn auxiliary_rows(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    unknowns: &[Symbol],
    (j, only): (usize, Option<&[Symbol]>),
) -> Vec<Equation> {
    let frames = &model.frames;
    let joint = &model.problem.joints[j];
    let subtree = model.subtree(j);
    let pivot = model.sites[j].point.position.clone();
    let mut rows = Vec::new();
    let site = &model.sites[j];
    for component in &site.reactions {
        let unknown = component.unknown(&site.name);
        if only.is_some_and(|only| !only.contains(&unknown)) {
            continue;
        }
        if crate::equations::friction::is_slider_friction(model, j, &unknown) {
            // Along the axis the auxiliary speed would be the joint's own: the row is the
            // coordinate's.
            continue;
        }
        let is_force = component.kind == ComponentKind::Force;
        let d = &component.direction;
        let velocity_at = |position: &Vector| -> Vector {
            if is_force {
                d.clone()
            } else {
                d.cross(&position.minus(&pivot), frames)
            }
        };
        let omega = if is_force { Vector::zero() } else { d.clone() };
        let (mut contact, mut distance) = (Vec::new(), Vec::new());
        for action in actions.iter().filter(|a| is_external(a, &subtree)) {
            let term = match &action.kind {
                ActionKind::Force { offset, force } => force.dot(
                    &velocity_at(&model.position_on(action.body, offset)),
                    frames,
                ),
                ActionKind::Couple { torque } => torque.dot(&omega, frames),
            };
            match action.category {
                Category::Contact => contact.push(term),
                Category::Distance => distance.push(term),
            }
        }
        let (mut inertia_force, mut inertia_torque) = (Vec::new(), Vec::new());
        for &body in &subtree {
            let center = &model.bodies[body.0].center.position;
            inertia_force.push(inertia.force[body.0].dot(&velocity_at(center), frames));
            inertia_torque.push(inertia.torque[body.0].dot(&omega, frames));
        }
        let groups = Groups {
            contact: add(contact),
            distance: add(distance),
            inertia_force: add(inertia_force),
            inertia_torque: add(inertia_torque),
        };
        let expression = groups.total();
        rows.push(Equation {
            free_body: subtree.clone(),
            sum: Sum::Generalized {
                speed: format!("u({}.{})", joint.name, component.component()),
            },
            direction: None,
            unknowns: crate::plan::unknowns_in(&expression, unknowns),
            groups,
            expression,
        });
    }
    rows
}
