//! Kane's method behind the one signature of every method: its view of the model, and
//! its rows, formed with the independent speeds where a constrained system's dependent
//! speeds can be written, with the coordinates' rates otherwise.

use super::super::unknowns::{Inputs, MethodRows, Setup};
use super::constrained;
use crate::mechanics::{reaction_unknowns, DependentSpeeds, MechanicsError, Model};
use crate::plan::Equation;
use crate::symbolic::budget;

/// Kane's view of the model: an auxiliary speed along a light rod brings in its tension
/// alone, and a light rod's closure carries its tension alone.
pub(in crate::equations) fn view(model: &mut Model) {
    crate::mechanics::along_members(model);
    crate::mechanics::closures_along_rods(model);
}

/// Kane's rows and their unknowns. With constraints, the rows are formed with the
/// independent speeds, and no constraint force is an unknown but those asked for.
///
/// # Errors
/// When a constraint row is not linear in the unknowns.
pub(in crate::equations) fn rows(
    inputs: &Inputs,
    setup: Setup,
) -> Result<MethodRows, MechanicsError> {
    let model = inputs.model;
    let written = match model.constraints.is_empty() {
        true => Ok(None),
        false => {
            budget::step("writing the dependent speeds u_D = C u_I (step 3)");
            DependentSpeeds::written(model)
        }
    };
    let (dependent_speeds, kept_forces) = match written {
        Ok(speeds) => (speeds, None),
        Err(why) => (None, Some(why)),
    };
    if let Some(speeds) = dependent_speeds {
        return by_independent_speeds(inputs, &setup, speeds);
    }
    let tree_requested = setup.tree_requested(model.problem);
    let rows = super::equations(
        model,
        inputs.actions,
        inputs.inertia,
        &setup.every_unknown,
        (&tree_requested, &setup.kept),
    );
    let mut out = setup.with_given(rows);
    out.kept_forces = kept_forces;
    Ok(out)
}

/// Kane's rows with the independent speeds `u_D = C u_I`: the constraint forces asked for
/// (and those a friction force is written with) are the only reactions among the unknowns.
fn by_independent_speeds(
    inputs: &Inputs,
    setup: &Setup,
    speeds: DependentSpeeds,
) -> Result<MethodRows, MechanicsError> {
    budget::step("writing Kane's equations with independent speeds (step 3)");
    let model = inputs.model;
    let reaction_joints = model.problem.find_reactions.clone();
    let asked = reaction_unknowns(model, &reaction_joints);
    let kept = super::super::friction::kept_forces(model, &asked);
    let unknowns = constrained::unknowns(model, &setup.accelerations, &reaction_joints, &kept);
    let request = constrained::Request {
        speeds: &speeds,
        reactions: &reaction_joints,
        kept: &kept,
        unknowns: &unknowns,
    };
    let rows = constrained::equations(model, inputs.actions, inputs.inertia, &request);
    // The constraint rows and the stick rows at the acceleration level, as the set-up
    // differentiated them: only their unknowns are Kane's fewer ones.
    let given = (setup.given.iter())
        .map(|row| Equation {
            unknowns: crate::plan::unknowns_in(&row.expression, &unknowns),
            ..row.clone()
        })
        .collect::<Vec<_>>();
    Ok(MethodRows {
        rows: rows.into_iter().chain(given).collect(),
        rejected: Vec::new(),
        unknowns,
        reaction_joints,
        dependent_speeds: Some(speeds),
        kept_forces: None,
    })
}
