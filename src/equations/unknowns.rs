//! What every method starts from: the accelerations, the reaction sites, the unknowns and
//! the constraint rows ([`Setup`]), and the rows a method hands back ([`MethodRows`]).

use super::constraint_rows::constraint_equations;
use super::method::Method;
use crate::mechanics::{
    reaction_unknowns, DependentSpeeds, KeptForces, MechanicsError, Model, RowOrigin,
};
use crate::plan::{Action, Equation, Inertia, Rejected};
use crate::problem::{Problem, State};
use crate::symbolic::Symbol;

/// What a method's rows are written from: the model, its free bodies (step 2), and the
/// states where the Motion Law's plan must be nonsingular.
pub(super) struct Inputs<'a, 'p> {
    /// The kinematics, as the method sees them.
    pub model: &'a Model<'p>,
    /// Every force and couple, reactions included.
    pub actions: &'a [Action],
    /// The inertia forces and torques, written.
    pub inertia: &'a Inertia,
    /// The states the plan must be nonsingular at.
    pub states: &'a [State],
}

/// The unknowns and the given rows, before a method chooses its own.
pub(super) struct Setup {
    /// The q'' (or the u' of declared speeds).
    pub accelerations: Vec<Symbol>,
    /// Every site with a reaction.
    pub all_sites: Vec<usize>,
    /// The closures and contacts among them.
    pub loop_sites: Vec<usize>,
    /// Drives and multipliers: what enforces constraint rows without a site.
    pub enforcing: Vec<Symbol>,
    /// The accelerations, every reaction and what enforces the constraints.
    pub every_unknown: Vec<Symbol>,
    /// The sites whose reactions the method solves for.
    pub reaction_joints: Vec<usize>,
    /// The method's unknowns.
    pub unknowns: Vec<Symbol>,
    /// The reaction components a friction force is written with, solved for by Kane's and
    /// Lagrange's rows though not requested.
    pub kept: Vec<Symbol>,
    /// The constraint rows and the rows of contacts that stick.
    pub given: Vec<Equation>,
}

impl Setup {
    /// The unknowns of `method` for `model`, and the constraint rows.
    ///
    /// # Errors
    /// When a constraint row is not linear in the unknowns.
    pub fn new(model: &Model, method: Method) -> Result<Setup, MechanicsError> {
        let problem = model.problem;
        let accelerations: Vec<Symbol> = problem.speed_symbols(2);
        let all_sites: Vec<usize> = (0..model.sites.len())
            .filter(|&j| !model.sites[j].reactions.is_empty())
            .collect();
        // Reactions at closures and contacts are unknowns of Kane's rows too: with the
        // tree's speeds they do work.
        let loop_sites: Vec<usize> = all_sites
            .iter()
            .copied()
            .filter(|&j| j >= problem.joints.len())
            .collect();
        let enforcing = constraint_unknowns(model);
        let every_unknown: Vec<Symbol> = accelerations
            .iter()
            .cloned()
            .chain(reaction_unknowns(model, &all_sites))
            .chain(enforcing.iter().cloned())
            .collect();
        let mut setup = Setup {
            accelerations,
            all_sites,
            loop_sites,
            enforcing,
            every_unknown,
            reaction_joints: Vec::new(),
            unknowns: Vec::new(),
            kept: Vec::new(),
            given: Vec::new(),
        };
        setup.reaction_joints = match method {
            Method::NewtonEuler => setup.all_sites.clone(),
            Method::Kane | Method::Lagrange => kane_reaction_joints(problem, &setup.loop_sites),
            Method::MotionLaw => problem.find_reactions.clone(),
        };
        // Friction is proportional to a normal force: every method solves for it, Kane's
        // rows for it and the friction force alone (`kept`).
        if !matches!(method, Method::Kane | Method::Lagrange) {
            super::friction::require_sites(model, &mut setup.reaction_joints);
        }
        setup.unknowns = setup.unknowns_of(model, &setup.reaction_joints);
        if matches!(method, Method::Kane | Method::Lagrange) {
            let asked = reaction_unknowns(model, &setup.reaction_joints);
            setup.kept = super::friction::kept_forces(model, &asked);
        }
        setup.unknowns.extend(setup.kept.iter().cloned());
        setup.given = constraint_equations(model.constraints.rows.iter(), &setup.every_unknown)?;
        (setup.given).extend(super::friction::stick_equations(
            model,
            &setup.every_unknown,
        )?);
        Ok(setup)
    }

    /// The accelerations, the reactions at `sites` and what enforces the constraints.
    pub fn unknowns_of(&self, model: &Model, sites: &[usize]) -> Vec<Symbol> {
        (self.accelerations.iter().cloned())
            .chain(reaction_unknowns(model, sites))
            .chain(self.enforcing.iter().cloned())
            .collect()
    }

    /// The requested reactions of the tree's joints.
    pub fn tree_requested(&self, problem: &Problem) -> Vec<usize> {
        (self.reaction_joints.iter().copied())
            .filter(|&j| j < problem.joints.len())
            .collect()
    }

    /// The rows of a method that writes its own besides the given ones (all but the
    /// Motion Law, whose plan places the given rows among its own).
    pub fn with_given(self, rows: Vec<Equation>) -> MethodRows {
        MethodRows {
            rows: rows.into_iter().chain(self.given).collect(),
            rejected: Vec::new(),
            unknowns: self.unknowns,
            reaction_joints: self.reaction_joints,
            dependent_speeds: None,
            kept_forces: None,
        }
    }
}

/// What every method hands back: its rows and the unknowns they are solved for.
pub(super) struct MethodRows {
    /// The chosen rows, the constraint rows among them.
    pub rows: Vec<Equation>,
    /// The candidates rejected, with reasons (the Motion Law only).
    pub rejected: Vec<Rejected>,
    /// The unknowns, in the order of the system's columns.
    pub unknowns: Vec<Symbol>,
    /// The sites whose reactions are unknowns.
    pub reaction_joints: Vec<usize>,
    /// Kane's independent speeds, when its rows are formed with them.
    pub dependent_speeds: Option<DependentSpeeds>,
    /// Why Kane's rows keep the constraint forces, when they do.
    pub kept_forces: Option<KeptForces>,
}

/// The unknowns that enforce constraint rows without a site: drives and multipliers.
fn constraint_unknowns(model: &Model) -> Vec<Symbol> {
    model
        .constraints
        .rows
        .iter()
        .filter(|r| !matches!(r.origin, RowOrigin::Site { .. }))
        .map(|r| r.unknown.clone())
        .collect()
}

/// The joints whose reactions are unknowns of Kane's rows: the requested tree joints, then
/// every closure and contact (with the tree's speeds they do work).
pub(super) fn kane_reaction_joints(problem: &Problem, loop_sites: &[usize]) -> Vec<usize> {
    let tree = problem.joints.len();
    let requested = problem.find_reactions.iter().copied().filter(|&j| j < tree);
    requested.chain(loop_sites.iter().copied()).collect()
}
