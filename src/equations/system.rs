//! Assembling the chosen rows into the symbolic linear system `A x = b`.

use super::rows::{Equation, Inertia};
use crate::mechanics::{MechanicsError, Model};
use crate::plan::forces::{actions, reaction_symbol, Action};
use crate::plan::planner::{self, Rejected};
use crate::problem::Problem;
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
}

impl Method {
    /// Every method.
    pub const ALL: [Method; 3] = [Method::MotionLaw, Method::NewtonEuler, Method::Kane];

    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::MotionLaw => "motion-law",
            Method::NewtonEuler => "newton-euler",
            Method::Kane => "kane",
        }
    }

    /// The name as a course writes it.
    pub fn title(self) -> &'static str {
        match self {
            Method::MotionLaw => "the Motion Law",
            Method::NewtonEuler => "Newton–Euler",
            Method::Kane => "Kane's method",
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
    /// The inertia forces and torques.
    pub inertia: Inertia,
    /// The chosen rows.
    pub rows: Vec<Equation>,
    /// The candidates rejected, with reasons (the Motion Law only).
    pub rejected: Vec<Rejected>,
    /// The assembled system.
    pub system: LinearSystem,
    /// Joints whose reactions are unknowns of the system.
    pub reaction_joints: Vec<usize>,
}

/// The reaction unknowns of the given joints, in joint order.
pub fn reaction_unknowns(model: &Model, joints: &[usize]) -> Vec<Symbol> {
    joints
        .iter()
        .flat_map(|&j| {
            let name = &model.problem.joints[j].name;
            model.joints[j]
                .reactions
                .iter()
                .map(move |c| reaction_symbol(name, &c.label))
        })
        .collect()
}

/// Derives the equations of motion of `problem` by `method`.
///
/// # Errors
/// When the model cannot be built, the planner finds no complete set of rows, or an
/// unknown appears nonlinearly.
pub fn derive(problem: &Problem, method: Method) -> Result<Derivation<'_>, MechanicsError> {
    derive_at(problem, method, &[])
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

/// As [`derive`], with the Motion Law's plan also required to be nonsingular at `states`
/// where a plan can be (the other methods have no choice to make).
///
/// # Errors
/// As for [`derive`].
pub fn derive_at<'p>(
    problem: &'p Problem,
    method: Method,
    states: &[State],
) -> Result<Derivation<'p>, MechanicsError> {
    let model = Model::build(problem)?;
    let actions = actions(&model)?;
    let inertia = Inertia::of(&model);
    let accelerations: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|i| problem.coordinate_symbol(i, 2))
        .collect();
    let all_joints: Vec<usize> = (0..problem.joints.len()).collect();
    let every_unknown: Vec<Symbol> = accelerations
        .iter()
        .cloned()
        .chain(reaction_unknowns(&model, &all_joints))
        .collect();
    let reaction_joints: Vec<usize> = match method {
        Method::NewtonEuler => all_joints
            .iter()
            .copied()
            .filter(|&j| !model.joints[j].reactions.is_empty())
            .collect(),
        _ => problem.find_reactions.clone(),
    };
    let unknowns: Vec<Symbol> = accelerations
        .iter()
        .cloned()
        .chain(reaction_unknowns(&model, &reaction_joints))
        .collect();
    let (rows, rejected) = match method {
        Method::NewtonEuler => (
            super::newton_euler::equations(&model, &actions, &inertia, &every_unknown),
            vec![],
        ),
        Method::Kane => (
            super::kane::equations(&model, &actions, &inertia, &every_unknown, &reaction_joints),
            vec![],
        ),
        Method::MotionLaw => {
            let reactions = reaction_unknowns(&model, &all_joints);
            let candidates = planner::candidates(&model, &actions, &reactions);
            let required: Vec<Values> = states
                .iter()
                .map(|s| model.values_at(s.t, &s.q, &s.rates))
                .collect();
            let choice =
                planner::choose(&model, &actions, &inertia, candidates, &unknowns, &required);
            (choice.rows, choice.rejected)
        }
    };
    if rows.len() != unknowns.len() {
        let mut message = format!(
            "{} found {} independent equations for {} unknowns",
            method.title(),
            rows.len(),
            unknowns.len()
        );
        if let Some(name) = massless_coordinate(&model, &actions, &inertia, &accelerations) {
            message.push_str(&format!(
                ": the coordinate `{name}` moves nothing with mass or inertia, so `{name}''` is undetermined"
            ));
        }
        return Err(MechanicsError {
            path: "joints".into(),
            message,
            hint: Some(
                "a coordinate may move nothing with mass, or a reaction may be undetermined".into(),
            ),
        });
    }
    let system = assemble(&rows, &unknowns)?;
    Ok(Derivation {
        model,
        method,
        actions,
        inertia,
        rows,
        rejected,
        system,
        reaction_joints,
    })
}

/// A coordinate whose q'' has a zero coefficient in every one of Kane's rows (its column
/// of the mass matrix is zero), at generic states: the usual reason a plan falls short.
fn massless_coordinate(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    accelerations: &[Symbol],
) -> Option<String> {
    let rows = super::kane::equations(model, actions, inertia, accelerations, &[]);
    let states = planner::sample_states(model);
    let coefficients: Vec<Vec<f64>> = rows
        .iter()
        .flat_map(|row| planner::coefficient_rows(row, accelerations, &states))
        .collect();
    (0..accelerations.len())
        .find(|&i| coefficients.iter().all(|row| row[i].abs() < 1e-12))
        .map(|i| model.problem.coordinates[i].name.clone())
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
