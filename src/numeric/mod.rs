//! Numbers: evaluation, the linear solve, integration and the confirmation checks
//! (steps 5 and 6).
//!
//! Entry: [`Compiled`] (a derivation compiled for numbers) and [`System`] (its solve at a
//! state), [`simulate`], [`confirm`] (the checks), [`Linearization`], [`answer_all`]. The
//! modules are private; what other stages use is re-exported here.

mod answer_frame;
mod answer_units;
mod answers;
mod assemble;
mod check;
mod checks;
mod constraint_checks;
mod describe;
mod describe_answer;
mod evaluate;
mod frame;
mod friction;
mod friction_vectors;
mod friction_work;
mod impact;
mod inputs;
mod integrate;
mod linear;
mod linearize;
mod load_work;
mod moving_slip;
mod newton;
mod period;
mod quantity;
mod recursive;
mod reduce;
mod simulate;
mod speeds;
mod stability_edge;
mod steady;
mod system;
mod vector_value;
mod work_along;

pub use answer_frame::{
    reaction_frame, reaction_frame_named, rotation_between as answer_frame_rotation,
};
pub use answers::{
    answer_all, answer_all_with, coordinate_unit, entry_name, holds, is_free_moment,
    unit as answer_unit, vector_axes, Answer, Quantity,
};
pub use checks::{confirm, modes, small_oscillation, Check, CheckKind, Derived, Phrase};
pub use constraint_checks::drive_energy_check;
pub use describe::{describe_run, Description};
pub use describe_answer::described;
pub use evaluate::{Compiled, Motion, StateSolution};
pub use frame::{Frame, DEFAULT_FPS};
pub use friction::{Held, Mode as FrictionMode, SiteState};
pub use impact::{CollisionImpulse, Contact, Mode as ImpactMode};
pub use linear::solve_linear;
pub use linearize::hqr::eigenvalues;
pub use linearize::jacobian::input_values;
pub use linearize::modes::{is_stable, sort as sort_modes, Shape, ROUND_OFF};
pub use linearize::{jacobian_of, Jacobian, Linearization, ModalAnalysis};
pub use load_work::{largest_imbalance, load_work, load_work_check};
pub use moving_slip::{asked, contact_lost, one_sided, slip_speed};
pub use newton::{solve as newton_solve, NewtonFailure};
pub use recursive::is_faster;
pub use reduce::Reducer;
pub use simulate::{
    full_precision, output_times, simulate, simulate_with_limits, Limits, Trajectory, MAX_ROWS,
};
pub use stability_edge::{edges, name as edge_name, Edge};
pub use system::{Evaluation, ReactionColumn, System};
pub use vector_value::{components as vector_components, At as VectorAt};

use std::fmt;

/// The equations could not be solved at some state.
#[derive(Clone, Debug, PartialEq)]
pub enum SolveError {
    /// The system matrix is singular at the state described.
    SingularSystem {
        /// The state, e.g. `t = 0, q1 = 0.3, q1' = 0`.
        state: String,
        /// Which unknowns are involved, when known.
        detail: String,
    },
    /// A value came out NaN or infinite.
    NotFinite {
        /// The state.
        state: String,
        /// What was not finite.
        what: String,
    },
    /// The integrator's step shrank below what floating point can resolve: the motion
    /// changes too fast to follow there (often a singularity of the equations).
    StepSizeUnderflow {
        /// The state where the step collapsed.
        state: String,
        /// The last step size tried, in seconds.
        step: f64,
    },
    /// The integrator reached its limit on the number of steps.
    TooManySteps {
        /// The state reached.
        state: String,
        /// The limit.
        steps: usize,
    },
    /// The run would write more rows than the limit allows.
    TooManyRows {
        /// duration / output_step, rounded up, plus one.
        rows: f64,
        /// The limit.
        limit: usize,
    },
    /// The simulation settings or the initial state cannot be used.
    BadSimulation {
        /// What is wrong.
        what: String,
    },
    /// A rolling disc lies flat on its plane: its contact point is undefined.
    FlatDisc {
        /// The rolling contact's name.
        constraint: String,
    },
    /// The constraints could not be met by the dependent coordinates (or rates).
    Assembly {
        /// The constraint with the largest residual, e.g. `R.Fx`.
        constraint: String,
        /// Its residual.
        residual: f64,
    },
}

impl fmt::Display for SolveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SolveError::SingularSystem { state, detail } => {
                write!(f, "the equations are singular at {state}: {detail}")
            }
            SolveError::NotFinite { state, what } => write!(f, "{what} is not finite at {state}"),
            SolveError::StepSizeUnderflow { state, step } => write!(
                f,
                "the integration step fell to {step:e} s at {state}: the motion changes too fast \
                 to follow there (a singular configuration, or a tolerance too tight)"
            ),
            SolveError::TooManySteps { state, steps } => write!(
                f,
                "the integration stopped after {steps} steps at {state}: shorten `duration` or \
                 loosen `tolerance`"
            ),
            SolveError::TooManyRows { rows, limit } => write!(
                f,
                "the simulation would write {rows} rows, more than the limit of {limit}: \
                 shorten `duration` or lengthen `output_step`"
            ),
            SolveError::BadSimulation { what } => write!(f, "cannot simulate: {what}"),
            SolveError::FlatDisc { constraint } => write!(
                f,
                "the contact point of the rolling constraint `{constraint}` is undefined: the \
                 disc's axle is parallel to the plane's normal, so the disc lies flat (hint: \
                 start with the disc standing or leaning, not flat)"
            ),
            SolveError::Assembly {
                constraint,
                residual,
            } => write!(
                f,
                "the constraints cannot be met: `{constraint}` keeps a residual of {residual:e} \
                 (hint: start nearer a closed configuration, with the dependent coordinates' \
                 `initial` values close to where the loop closes)"
            ),
        }
    }
}

impl std::error::Error for SolveError {}
