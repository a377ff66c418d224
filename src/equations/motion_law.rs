//! The Motion Law: contact, distance and inertia forces on a chosen free body sum to zero,
//! along a chosen direction or about a chosen point. The planner (step 3, [`crate::plan`])
//! chooses the free bodies and directions whose rows hold the fewest unknowns; this module
//! asks it for a complete set and widens the unknowns where none exists.

use super::unknowns::{Inputs, MethodRows, Setup};
use crate::mechanics::{reaction_unknowns, Model};
use crate::plan::{candidates, choose, Choice, Equation};
use crate::symbolic::{Symbol, Values};

/// The Motion Law's view of the model: a light rod's closure carries its tension alone.
pub(super) fn view(model: &mut Model) {
    crate::mechanics::closures_along_rods(model);
}

/// The Motion Law's rows: those its planner chooses, the constraint rows placed among them.
pub(super) fn rows(inputs: &Inputs, setup: Setup) -> MethodRows {
    let model = inputs.model;
    let (all_sites, loop_sites, given) = (&setup.all_sites, &setup.loop_sites, &setup.given);
    let mut reaction_joints = setup.reaction_joints.clone();
    let mut unknowns = setup.unknowns.clone();
    let reactions = reaction_unknowns(model, all_sites);
    let candidates = candidates(model, inputs.actions, &reactions);
    let required: Vec<Values> = (inputs.states.iter())
        .map(|s| model.values_at(s.t, &s.q, &s.rates))
        .collect();
    // The plan for `wanted` unknowns, with `given` rows (the constraints).
    let plan = |wanted: &[Symbol], given: &[Equation]| {
        let candidates = candidates.clone();
        choose(
            model,
            inputs.actions,
            inputs.inertia,
            candidates,
            wanted,
            given,
            &required,
        )
    };
    // Sticking may leave the friction forces undetermined (two rough contacts of one body
    // share one no-slip motion), sliding not: plan by the sliding law's rows, then write
    // the stick rows back for the numbers to exchange.
    let by_sliding = |unknowns: &[Symbol], choice: Choice| {
        if choice.rows.len() == unknowns.len() || model.constraints.friction.is_empty() {
            return choice;
        }
        let again = plan(
            unknowns,
            &super::friction::sliding_stand_ins(model, given, unknowns),
        );
        if again.rows.len() == unknowns.len() {
            Choice {
                rows: super::friction::stick_rows_back(again.rows, given),
                rejected: again.rejected,
            }
        } else {
            choice
        }
    };
    let mut choice = plan(&unknowns, given);
    if choice.rows.len() < unknowns.len() && !loop_sites.is_empty() {
        // No free body avoids every reaction of the loop: solve for them too.
        for &j in loop_sites {
            if !reaction_joints.contains(&j) {
                reaction_joints.push(j);
            }
        }
        unknowns = setup.unknowns_of(model, &reaction_joints);
        choice = plan(&unknowns, given);
    }
    choice = by_sliding(&unknowns, choice);
    if choice.rows.len() < unknowns.len() {
        // A contact keeps a group of bodies from being one free body (its rows would hold
        // only where the contact holds), so a requested reaction may have no row without
        // another one (a cart's rail, with a block held on the cart by a contact and
        // carried by a light slider): solve for every reaction then, as Newton-Euler does.
        let every = setup.unknowns_of(model, all_sites);
        let again = plan(&every, given);
        let again = by_sliding(&every, again);
        if again.rows.len() == every.len() {
            reaction_joints = all_sites.clone();
            unknowns = every;
            choice = again;
        }
    }
    MethodRows {
        rows: choice.rows,
        rejected: choice.rejected,
        unknowns,
        reaction_joints,
        dependent_speeds: None,
        kept_forces: None,
    }
}
