//! Lagrange's equations: one row per coordinate,
//! `d/dt(∂L/∂q̇_r) − ∂L/∂q_r = Q_r + Σ_k λ_k ∂f_k/∂q_r`, with `L = T − V`.
//!
//! `T` is every body's `½ m v*·v* + ½ ω·I·ω` from the velocities of step 4, `V` the
//! potential of gravity, springs and joint springs; `Q_r` the generalized forces of the
//! loads without a potential by virtual work ([`forces`]). A constraint enters with a
//! multiplier per row: a closure's or a contact's multipliers are the components of its
//! reaction (their virtual work along `∂v/∂q̇_r` is `Σ λ_k ∂f_k/∂q_r`, or the multiplier
//! times the coefficient of `q̇_r` of a nonholonomic row), and a row without a site (a
//! prescribed coordinate, a `position` or `velocity` entry) has its own multiplier or
//! drive. The constraint rows at the acceleration level close the system.
//!
//! A reaction of a tree joint does no work with the coordinates: it is found by relaxing
//! the joint, an auxiliary coordinate along (or about) each requested component, whose
//! equation at zero auxiliary coordinate and rate is the subtree's balance along it
//! (the same rows as Kane's auxiliary speeds).

pub(super) mod energy;
pub(super) mod forces;
pub(super) mod kinetic;
pub(super) mod long;

use super::unknowns::{Inputs, MethodRows, Setup};
use crate::mechanics::{same_at, sample_states, Form, MechanicsError, Model};
use crate::plan::{Action, Equation, Groups, Inertia, Sum};
use crate::symbolic::{Expr, Symbol};

/// What one coordinate's equation is made of, each term as the worked solution shows it.
#[derive(Clone, Debug)]
pub struct CoordinateTerms {
    /// ∂T/∂q̇_r.
    pub momentum: Expr,
    /// d/dt(∂T/∂q̇_r).
    pub momentum_rate: Expr,
    /// ∂T/∂q_r.
    pub kinetic_partial: Expr,
    /// ∂V/∂q_r.
    pub potential_partial: Expr,
    /// Q_r of the loads without a potential (friction included).
    pub generalized_force: Expr,
    /// The constraint forces' share: `Σ_k λ_k ∂f_k/∂q_r` and the nonholonomic rows' terms.
    pub multipliers: Expr,
    /// Whether ∂T/∂q̇_r, its time derivative and ∂T/∂q_r were formed to be written out;
    /// when not (too long, see [`long`]), they are zero here and step 5 names them only.
    pub written: bool,
}

/// Every coordinate's terms, in coordinate order, with the coordinates' rates (with declared
/// speeds, the rates are written with the speeds only in the rows, see `equations`).
///
/// # Errors
/// When a load or a velocity holds a function that has no derivative.
pub fn coordinate_terms(
    model: &Model,
    actions: &[Action],
    simplified: bool,
) -> Result<Vec<CoordinateTerms>, MechanicsError> {
    let energy = energy::derivatives(model, simplified)?;
    let loads = forces::generalized_forces(model, actions);
    Ok(energy
        .into_iter()
        .zip(loads)
        .map(|(e, (generalized_force, multipliers))| CoordinateTerms {
            momentum: e.momentum,
            momentum_rate: e.momentum_rate,
            kinetic_partial: e.kinetic_partial,
            potential_partial: e.potential_partial,
            generalized_force,
            multipliers,
            written: true,
        })
        .collect())
}

/// Lagrange's rows: one per coordinate, then one per requested reaction component of a
/// tree joint (by relaxing the joint), then one per `kept` component (a rough slider's
/// normal force, which its friction is written with).
///
/// The groups of a row: `contact` the generalized forces `Q_r` and the multipliers' terms,
/// `distance` `−∂V/∂q_r`, `inertia_force` `−(d/dt(∂T/∂q̇_r) − ∂T/∂q_r)`; their sum is zero.
/// For the numbers the kinetic terms come from [`kinetic`], the translation in
/// `inertia_force` and the rotation in `inertia_torque`.
///
/// With the rows, each coordinate's terms where the rows were formed from them (the worked
/// solution's form, which step 5 shows term by term); none for the numbers.
///
/// # Errors
/// As for [`coordinate_terms`].
pub fn equations(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    unknowns: &[Symbol],
    (reaction_joints, kept): (&[usize], &[Symbol]),
) -> Result<(Vec<Equation>, Vec<CoordinateTerms>), MechanicsError> {
    let mut terms = Vec::new();
    let all_groups = if kinetic::applies(model, inertia) {
        kinetic::numeric_groups(model, actions, inertia)?
    } else if long::applies(model, inertia)? {
        let (groups, long_terms) = long::groups(model, actions, inertia)?;
        terms = long_terms;
        groups
    } else {
        terms = coordinate_terms(model, actions, inertia.form == Form::Handout)?;
        let groups = terms
            .iter()
            .map(|t| Groups {
                contact: &t.generalized_force + &t.multipliers,
                distance: -t.potential_partial.clone(),
                inertia_force: -(&t.momentum_rate - &t.kinetic_partial),
                inertia_torque: Expr::zero(),
            })
            .collect();
        if inertia.form != Form::Handout {
            terms.clear();
        }
        groups
    };
    let problem = model.problem;
    let mut states = None;
    let second_rates = energy::second_rates_as_speeds(model);
    let mut rows = Vec::with_capacity(all_groups.len());
    for (r, groups) in all_groups.into_iter().enumerate() {
        let groups = match &second_rates {
            Some(replace) => Groups {
                contact: replace(&groups.contact),
                distance: replace(&groups.distance),
                inertia_force: replace(&groups.inertia_force),
                inertia_torque: groups.inertia_torque,
            },
            None => groups,
        };
        let expression = groups.total();
        // A coordinate that moves nothing with mass, and along which no force does work
        // (a light rod's turn about its pin, the rod's tension across it), has the row
        // 0 = 0: the constraints fix its motion instead.
        let states = states.get_or_insert_with(|| sample_states(model));
        if same_at(&expression, &Expr::zero(), states) {
            continue;
        }
        rows.push(Equation {
            free_body: model.order.clone(),
            sum: Sum::Generalized {
                speed: problem.coordinate_symbol(r, 1).to_string(),
            },
            direction: None,
            unknowns: crate::plan::unknowns_in(&expression, unknowns),
            groups,
            expression,
        });
    }
    let relaxed = |j, only| {
        crate::equations::kane::auxiliary_rows(model, actions, inertia, unknowns, (j, only))
    };
    for &j in reaction_joints {
        rows.extend(relaxed(j, None));
    }
    for j in crate::equations::kane::kept_joints(model, reaction_joints, kept) {
        rows.extend(relaxed(j, Some(kept)));
    }
    Ok((rows, terms))
}

/// Lagrange's view of the model: along a light rod the relaxed joint brings in its tension
/// alone, and a light rod's closure carries its tension alone.
pub(super) fn view(model: &mut Model) {
    crate::mechanics::along_members(model);
    crate::mechanics::closures_along_rods(model);
}

/// Lagrange's rows: one per coordinate and one per requested reaction of a tree joint,
/// then the constraint rows; with each coordinate's terms in the worked solution's form.
///
/// # Errors
/// As for [`equations`].
pub(super) fn rows(
    inputs: &Inputs,
    setup: Setup,
) -> Result<(MethodRows, Vec<CoordinateTerms>), MechanicsError> {
    let model = inputs.model;
    let tree_requested = setup.tree_requested(model.problem);
    let (rows, terms) = equations(
        model,
        inputs.actions,
        inputs.inertia,
        &setup.every_unknown,
        (&tree_requested, &setup.kept),
    )?;
    Ok((setup.with_given(rows), terms))
}
