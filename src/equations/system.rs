//! Assembling the chosen rows into the symbolic linear system `A x = b`.

use super::constraint_rows::constraint_equations;
use crate::mechanics::constraints::RowOrigin;
use crate::mechanics::independent::{DependentSpeeds, KeptForces};
use crate::mechanics::{MechanicsError, Model};
use crate::plan::forces::Action;
use crate::plan::planner::{self, Rejected};
pub use crate::plan::rows::Form;
use crate::plan::rows::{Equation, Inertia, LazyInertia};
use crate::plan::FreeBodies;
use crate::problem::Problem;
use crate::symbolic::budget;
use crate::symbolic::eval::Values;
use crate::symbolic::linear::linear_split;
use crate::symbolic::{Expr, Symbol};

/// The equation-forming method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Contact + distance + inertia forces = 0, about any point.
    MotionLaw,
    /// Every body a free body; all reactions unknown.
    NewtonEuler,
    /// Generalized active plus inertia forces.
    Kane,
    /// Lagrange's equations: `d/dt(∂L/∂q̇_r) − ∂L/∂q_r = Q_r`, with multipliers.
    Lagrange,
}

impl Method {
    /// Every method.
    pub const ALL: [Method; 4] = [
        Method::MotionLaw,
        Method::NewtonEuler,
        Method::Kane,
        Method::Lagrange,
    ];

    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::MotionLaw => "motion-law",
            Method::NewtonEuler => "newton-euler",
            Method::Kane => "kane",
            Method::Lagrange => "lagrange",
        }
    }

    /// The name as a course writes it.
    pub fn title(self) -> &'static str {
        match self {
            Method::MotionLaw => "the Motion Law",
            Method::NewtonEuler => "Newton–Euler",
            Method::Kane => "Kane's method",
            Method::Lagrange => "Lagrange's equations",
        }
    }
}

/// The symbolic linear system `A x = b`.
#[derive(Clone, Debug)]
pub struct LinearSystem {
    /// The unknowns `x`: every q'', then reaction components.
    pub unknowns: Vec<Symbol>,
    /// Row-major coefficients.
    pub a: Vec<Vec<Expr>>,
    /// Right-hand sides.
    pub b: Vec<Expr>,
}

/// Everything one method derives for one problem.
#[derive(Debug)]
pub struct Derivation<'p> {
    /// The kinematics.
    pub model: Model<'p>,
    /// The method.
    pub method: Method,
    /// Every force and couple, reactions included.
    pub actions: Vec<Action>,
    /// The inertia forces and torques ([`Self::inertia`]), written when first read.
    lazy_inertia: LazyInertia,
    /// The chosen rows; none where only the numbers were asked for and Kane's system was
    /// built by composite bodies alone ([`Rows::Compiled`], [`Rows::Fastest`]).
    pub rows: Vec<Equation>,
    /// The candidates rejected, with reasons (the Motion Law only).
    pub rejected: Vec<Rejected>,
    /// The assembled system.
    pub system: LinearSystem,
    /// The method whose equations `system` holds: `method`, or Kane's where Kane's system
    /// by composite bodies stands in for the numbers of another method ([`Rows::Fastest`]).
    pub system_method: Method,
    /// The same system with Kane's rows rebuilt by composite bodies, for evaluation (see
    /// [`super::composite`]): equal numbers, the mass matrix for n² work where `system`'s
    /// rows take n³, the rest for n where they take n². Only for Kane's method in
    /// [`Form::Numeric`], where it applies. Derivatives are taken of `system`: these rows
    /// nest named quantities through the whole tree, and a derivative multiplies a named
    /// quantity out.
    pub composite_system: Option<LinearSystem>,
    /// Joints whose reactions are unknowns of the system.
    pub reaction_joints: Vec<usize>,
    /// Kane's method on a constrained system: the independent speeds and `u_D = C u_I`
    /// its rows are formed with. `None` for the other methods, an unconstrained system, or
    /// one whose dependent speeds are too long to write (its rows then keep the
    /// constraint forces as unknowns).
    pub dependent_speeds: Option<DependentSpeeds>,
    /// Kane's method on a constrained system whose rows keep the constraint forces as
    /// unknowns: why the independent speeds are not taken alone.
    pub kept_forces: Option<KeptForces>,
}

impl Derivation<'_> {
    /// The inertia forces and torques of step 2.
    pub fn inertia(&self) -> &Inertia {
        self.lazy_inertia.get(&self.model)
    }
}

pub use crate::mechanics::sites::reaction_unknowns;

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

/// A state the equations will be solved at: time, coordinates and rates in coordinate order.
#[derive(Clone, Debug, PartialEq)]
pub struct State {
    /// Time `t`.
    pub t: f64,
    /// The coordinates.
    pub q: Vec<f64>,
    /// Their rates.
    pub rates: Vec<f64>,
}

/// What a derivation is for: the form its expressions take, which rows it forms, and the
/// states where the Motion Law's plan must be nonsingular where a plan can be (the other
/// methods have no choice to make).
#[derive(Clone, Copy, Debug)]
pub struct Request<'s> {
    /// For numbers or for the worked solution.
    pub form: Form,
    /// Which rows to form.
    pub rows: Rows,
    /// The states the plan must be nonsingular at.
    pub states: &'s [State],
}

/// Which rows a derivation forms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rows {
    /// Every row the method writes, for the worked solution and for comparisons.
    Formed,
    /// Only what is compiled for numbers: where Kane's system by composite bodies is the
    /// one compiled (a tree large enough, see [`super::composite::SMALL_PROGRAM`]), it is
    /// built directly and Kane's rows are never formed; the derivation's `rows` are then
    /// empty and its `system` is the composite one.
    Compiled,
    /// As `Compiled`, with Kane's system by composite bodies standing in for the rows of
    /// any method where it is built alone: an unconstrained tree large enough (see
    /// [`super::composite::system_alone`]). The q'' and the reactions are the method's own
    /// to rounding, and the composite system costs n² where the Motion Law's and
    /// Newton–Euler's rows cost n³ or more. The derivation keeps `method`; its
    /// `system_method` says whose equations its system holds.
    Fastest,
}

/// Step 3 and 5: the equations of motion of `model` by `method`, from its free bodies
/// (step 2): the method's rows (for the Motion Law, the rows its planner chooses),
/// assembled into `A x = b`.
///
/// # Errors
/// When the planner finds no complete set of rows, or an unknown appears nonlinearly.
pub fn write_equations<'p>(
    model: Model<'p>,
    free_bodies: FreeBodies,
    method: Method,
    request: Request<'_>,
) -> Result<Derivation<'p>, MechanicsError> {
    let Request {
        form,
        rows: wanted,
        states,
    } = request;
    let FreeBodies { actions, inertia } = free_bodies;
    let problem = model.problem;
    budget::step(match method {
        Method::MotionLaw => "writing the Motion Law's candidate rows (step 3)",
        Method::NewtonEuler => "writing the Newton–Euler rows (step 3)",
        Method::Kane => "writing Kane's generalized forces (step 3)",
        Method::Lagrange => "writing Lagrange's equations (step 3)",
    });
    // The q'' — or the u' of declared speeds.
    let accelerations: Vec<Symbol> = problem.speed_symbols(2);
    let all_sites: Vec<usize> = (0..model.sites.len())
        .filter(|&j| !model.sites[j].reactions.is_empty())
        .collect();
    // Reactions at closures and contacts are unknowns of Kane's rows too: with the tree's
    // speeds they do work.
    let loop_sites: Vec<usize> = all_sites
        .iter()
        .copied()
        .filter(|&j| j >= problem.joints.len())
        .collect();
    let enforcing = constraint_unknowns(&model);
    let every_unknown: Vec<Symbol> = accelerations
        .iter()
        .cloned()
        .chain(reaction_unknowns(&model, &all_sites))
        .chain(enforcing.iter().cloned())
        .collect();
    let mut reaction_joints: Vec<usize> = match method {
        Method::NewtonEuler => all_sites.clone(),
        Method::Kane | Method::Lagrange => kane_reaction_joints(problem, &loop_sites),
        Method::MotionLaw => problem.find_reactions.clone(),
    };
    // Friction is proportional to a normal force: every method solves for it, Kane's
    // rows for it and the friction force alone (`kept`).
    if !matches!(method, Method::Kane | Method::Lagrange) {
        super::friction::require_sites(&model, &mut reaction_joints);
    }
    let unknowns_of = |sites: &[usize]| -> Vec<Symbol> {
        accelerations
            .iter()
            .cloned()
            .chain(reaction_unknowns(&model, sites))
            .chain(enforcing.iter().cloned())
            .collect()
    };
    let mut unknowns = unknowns_of(&reaction_joints);
    let kept = match method {
        Method::Kane | Method::Lagrange => {
            super::friction::kept_forces(&model, &reaction_unknowns(&model, &reaction_joints))
        }
        _ => Vec::new(),
    };
    unknowns.extend(kept.iter().cloned());
    let mut given = constraint_equations(model.constraints.rows.iter(), &every_unknown)?;
    given.extend(super::friction::stick_equations(&model, &every_unknown)?);
    let composite_alone = match (method, form, wanted) {
        (_, Form::Numeric, Rows::Fastest) | (Method::Kane, Form::Numeric, Rows::Compiled) => {
            // Kane's reactions: the requested ones, where every other method's are too
            // (`system_alone` applies to trees alone, without closures or contacts).
            let joints = kane_reaction_joints(problem, &loop_sites);
            let kane_unknowns = unknowns_of(&joints);
            super::composite::system_alone(&model, &actions, &kane_unknowns, &joints)
                .map(|system| (system, joints))
        }
        _ => None,
    };
    if let Some((system, reaction_joints)) = composite_alone {
        return Ok(Derivation {
            model,
            method,
            actions,
            lazy_inertia: inertia,
            rows: Vec::new(),
            rejected: Vec::new(),
            system,
            system_method: Method::Kane,
            composite_system: None,
            reaction_joints,
            dependent_speeds: None,
            kept_forces: None,
        });
    }
    let inertia = inertia.into_written(&model);
    // With constraints, Kane's rows are formed with the independent speeds, and no
    // constraint force is an unknown but those asked for.
    let written = match method {
        Method::Kane if !model.constraints.is_empty() => {
            budget::step("writing the dependent speeds u_D = C u_I (step 3)");
            DependentSpeeds::written(&model)
        }
        _ => Ok(None),
    };
    let (dependent_speeds, kept_forces) = match written {
        Ok(speeds) => (speeds, None),
        Err(why) => (None, Some(why)),
    };
    if let Some(speeds) = &dependent_speeds {
        budget::step("writing Kane's equations with independent speeds (step 3)");
        reaction_joints = problem.find_reactions.clone();
        let asked = reaction_unknowns(&model, &reaction_joints);
        let kept = super::friction::kept_forces(&model, &asked);
        unknowns =
            super::kane::constrained::unknowns(&model, &accelerations, &reaction_joints, &kept);
        let request = super::kane::constrained::Request {
            speeds,
            reactions: &reaction_joints,
            kept: &kept,
            unknowns: &unknowns,
        };
        let rows = super::kane::constrained::equations(&model, &actions, &inertia, &request);
        let mut given = constraint_equations(model.constraints.rows.iter(), &unknowns)?;
        given.extend(super::friction::stick_equations(&model, &unknowns)?);
        let rows: Vec<Equation> = rows.into_iter().chain(given).collect();
        return finish(
            model,
            method,
            actions,
            inertia,
            (rows, vec![]),
            unknowns,
            reaction_joints,
            (dependent_speeds, None),
            form,
        );
    }
    let (rows, rejected) = match method {
        Method::NewtonEuler => (
            super::newton_euler::equations(&model, &actions, &inertia, &every_unknown),
            vec![],
        ),
        Method::Kane => {
            let tree_requested: Vec<usize> = reaction_joints
                .iter()
                .copied()
                .filter(|&j| j < problem.joints.len())
                .collect();
            (
                super::kane::equations(
                    &model,
                    &actions,
                    &inertia,
                    &every_unknown,
                    (&tree_requested, &kept),
                ),
                vec![],
            )
        }
        Method::Lagrange => {
            let tree_requested: Vec<usize> = reaction_joints
                .iter()
                .copied()
                .filter(|&j| j < problem.joints.len())
                .collect();
            let rows = super::lagrange::equations(
                &model,
                &actions,
                &inertia,
                &every_unknown,
                (&tree_requested, &kept),
            )?;
            (rows, vec![])
        }
        Method::MotionLaw => {
            let reactions = reaction_unknowns(&model, &all_sites);
            let candidates = planner::candidates(&model, &actions, &reactions);
            let required: Vec<Values> = states
                .iter()
                .map(|s| model.values_at(s.t, &s.q, &s.rates))
                .collect();
            // The plan for `wanted` unknowns, with `given` rows (the constraints).
            let plan = |wanted: &[Symbol], given: &[Equation]| {
                planner::choose(
                    &model,
                    &actions,
                    &inertia,
                    candidates.clone(),
                    wanted,
                    given,
                    &required,
                )
            };
            let mut choice = plan(&unknowns, &given);
            if choice.rows.len() < unknowns.len() && !loop_sites.is_empty() {
                // No free body avoids every reaction of the loop: solve for them too.
                for &j in &loop_sites {
                    if !reaction_joints.contains(&j) {
                        reaction_joints.push(j);
                    }
                }
                unknowns = unknowns_of(&reaction_joints);
                choice = plan(&unknowns, &given);
            }
            // Sticking may leave the friction forces undetermined (two rough contacts of
            // one body share one no-slip motion), sliding not: plan by the sliding law's
            // rows, then write the stick rows back for the numbers to exchange.
            let by_sliding = |unknowns: &[Symbol], choice: planner::Choice| {
                if choice.rows.len() == unknowns.len() || model.constraints.friction.is_empty() {
                    return choice;
                }
                let again = plan(
                    unknowns,
                    &super::friction::sliding_stand_ins(&model, &given, unknowns),
                );
                if again.rows.len() == unknowns.len() {
                    planner::Choice {
                        rows: super::friction::stick_rows_back(again.rows, &given),
                        rejected: again.rejected,
                    }
                } else {
                    choice
                }
            };
            choice = by_sliding(&unknowns, choice);
            if choice.rows.len() < unknowns.len() {
                // A contact keeps a group of bodies from being one free body (its rows
                // would hold only where the contact holds), so a requested reaction may
                // have no row without another one (a cart's rail, with a block held on
                // the cart by a contact and carried by a light slider): solve for every
                // reaction then, as Newton-Euler does.
                let every = unknowns_of(&all_sites);
                let again = plan(&every, &given);
                let again = by_sliding(&every, again);
                if again.rows.len() == every.len() {
                    reaction_joints = all_sites.clone();
                    unknowns = every;
                    choice = again;
                }
            }
            (choice.rows, choice.rejected)
        }
    };
    // The Motion Law's plan places the constraint rows among its own.
    let rows: Vec<Equation> = match method {
        Method::MotionLaw => rows,
        _ => rows.into_iter().chain(given).collect(),
    };
    finish(
        model,
        method,
        actions,
        inertia,
        (rows, rejected),
        unknowns,
        reaction_joints,
        (None, kept_forces),
        form,
    )
}

/// The rows checked against the unknowns and assembled into the system.
#[allow(clippy::too_many_arguments)]
fn finish<'p>(
    model: Model<'p>,
    method: Method,
    actions: Vec<Action>,
    inertia: Inertia,
    (rows, rejected): (Vec<Equation>, Vec<Rejected>),
    unknowns: Vec<Symbol>,
    reaction_joints: Vec<usize>,
    (dependent_speeds, kept_forces): (Option<DependentSpeeds>, Option<KeptForces>),
    form: Form,
) -> Result<Derivation<'p>, MechanicsError> {
    let accelerations: Vec<Symbol> = model.problem.speed_symbols(2);
    // Loads that use rates (dampers) are written with the speeds too.
    let rows = match &model.speeds {
        Some(speeds) => rows
            .into_iter()
            .map(|row| row.map_expressions(|e| speeds.to_speeds(e)))
            .collect(),
        None => rows,
    };
    // Written with what holds on the motion (a gear's unit line of centres), where the
    // rows are evaluated.
    let rows: Vec<Equation> = rows
        .into_iter()
        .map(|row| super::on_motion::row(&model, row, &unknowns))
        .collect();
    if rows.len() != unknowns.len() {
        let mut message = format!(
            "{} found {} independent equations for {} unknowns",
            method.title(),
            rows.len(),
            unknowns.len()
        );
        let mut path = "joints".to_string();
        if let Some(i) = massless_coordinate(&model, &actions, &inertia, &accelerations) {
            let name = &model.problem.coordinates[i].name;
            match crate::mechanics::massless::massless_body_moved_by(&model, i) {
                Some(body) => {
                    let body = model.problem.body(body);
                    path = format!("{}.mass", body.path);
                    message.push_str(": ");
                    message.push_str(&crate::mechanics::massless::undetermined(name, &body.name));
                }
                None => message.push_str(&format!(
                    ": the coordinate `{name}` moves nothing with mass or inertia, so `{name}''` is undetermined"
                )),
            }
        }
        return Err(MechanicsError {
            path,
            message,
            hint: Some(
                "a coordinate may move nothing with mass, or a reaction may be undetermined".into(),
            ),
        });
    }
    budget::step("assembling the linear system (step 5)");
    let system = assemble(&rows, &unknowns)?;
    let composite_system = match (method, form) {
        (Method::Kane, Form::Numeric) => {
            super::composite::system(&model, &actions, &system, &reaction_joints)
        }
        _ => None,
    };
    Ok(Derivation {
        model,
        method,
        actions,
        lazy_inertia: LazyInertia::written(inertia),
        rows,
        rejected,
        system,
        system_method: method,
        composite_system,
        reaction_joints,
        dependent_speeds,
        kept_forces,
    })
}

/// The joints whose reactions are unknowns of Kane's rows: the requested tree joints, then
/// every closure and contact (with the tree's speeds they do work).
fn kane_reaction_joints(problem: &Problem, loop_sites: &[usize]) -> Vec<usize> {
    let tree = problem.joints.len();
    let requested = problem.find_reactions.iter().copied().filter(|&j| j < tree);
    requested.chain(loop_sites.iter().copied()).collect()
}

/// A coordinate whose q'' has a zero coefficient in every one of Kane's rows (its column
/// of the mass matrix is zero), at generic states: the usual reason a plan falls short.
fn massless_coordinate(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    accelerations: &[Symbol],
) -> Option<usize> {
    let rows = super::kane::equations(model, actions, inertia, accelerations, (&[], &[]));
    let states = planner::sample_states(model);
    let coefficients: Vec<Vec<f64>> = rows
        .iter()
        .flat_map(|row| planner::coefficient_rows(row, accelerations, &states))
        .collect();
    (0..accelerations.len()).find(|&i| coefficients.iter().all(|row| row[i].abs() < 1e-12))
}

fn assemble(rows: &[Equation], unknowns: &[Symbol]) -> Result<LinearSystem, MechanicsError> {
    let mut a = Vec::with_capacity(rows.len());
    let mut b = Vec::with_capacity(rows.len());
    for row in rows {
        let (coefficients, rest) =
            linear_split(&row.expression, unknowns).map_err(|e| MechanicsError {
                path: "loads".into(),
                message: e.to_string(),
                hint: Some("loads may not depend on second rates".into()),
            })?;
        a.push(coefficients);
        b.push(-rest);
    }
    Ok(LinearSystem {
        unknowns: unknowns.to_vec(),
        a,
        b,
    })
}
