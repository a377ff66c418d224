//! mbd-tutor derives, solves and explains the equations of motion of systems of rigid
//! bodies joined by joints, the way a dynamics course teaches it.
//!
//! # Steps
//!
//! Data flows one way, each stage reading what the stages before it produced:
//! problem → model → plan → equations → numeric → solution → render.
//!
//! 1. [`problem`]: read the JSON problem and validate it into a typed
//!    [`Problem`](problem::Problem), every error at once with its path and a hint.
//! 2. [`mechanics`]: the model. Frames, unit vectors and coordinates (step 1); the sites
//!    (joints, closures, rolling contacts) with their reaction components; the constraints
//!    (closures, rolling contacts, constraint entries, prescribed motion) as rows, with
//!    the dependent coordinates and rates; declared generalized speeds, `u = W(q) q'` and
//!    its inverse; the kinematics of every body (step 4), written with the speeds.
//! 3. [`plan`]: every force and couple on every body (step 2, the free bodies), the rows
//!    of equations ([`plan::Equation`]), and the Motion Law planner's table (step 3).
//! 4. [`equations`]: Newton–Euler, the Motion Law, Kane's method and Lagrange's equations, each a
//!    [`Derivation`](equations::Derivation) with a linear system `A x = b` (step 5). Its
//!    unknowns are the q'' (the u' of declared speeds) and typed [`Unknown`](symbolic::Unknown)s: reaction components
//!    of sites, drives and multipliers, whose names and LaTeX come from the type. For the
//!    numbers, Kane's rows are also rebuilt by composite bodies (`equations::composite`),
//!    and for a large tree built that way alone, never formed.
//! 5. [`numeric`]: the equations compiled for numbers, the constraints' assembly, the
//!    linear solve, integration and its checks (steps 5, 6), and linearization.
//! 6. [`solution`]: the worked solution's content from what the stages gave
//!    ([`Worked`]): each step's rows, tables, where-lists and reasons, the
//!    pictures' scenes (`solution::pictures`: the configuration, the free-body diagrams and
//!    the motion), the answers and the checks.
//! 7. [`render`]: writes that content as Markdown, LaTeX or HTML through Tera templates,
//!    and the scenes as SVG and TikZ; it reads none of the stages before the solution.
//!
//! [`pipeline`] runs the stages for the commands in [`cmd`] (one thin file each):
//! `load`, `derive`, the [`Solver`](pipeline::Solver) and the [`Linearizer`](pipeline::Linearizer)
//! with the one place where a singular plan is planned again, the confirmation checks, and
//! [`run`](pipeline::run), the one orchestrator of a handout (`explain`, `serve`,
//! `variants`). [`symbolic`] is the computer-algebra core under
//! all of them; [`typeset`], the part of LaTeX math every format can set, is read by
//! `problem` (a question's symbol) and `render` alike.

pub mod cli;
pub mod cmd;
pub mod equations;
mod error;
pub mod grade;
pub mod input;
pub mod mechanics;
pub mod numeric;
pub mod output;
pub mod pipeline;
pub mod plan;
pub mod problem;
pub mod render;
pub mod solution;
pub mod symbolic;
pub mod typeset;

pub use error::{BatchError, Error, SubmissionError};
/// The statics handout's run ([`pipeline::run_at_rest`]): the equilibrium and what the
/// stages give there, which [`solution`] writes out.
pub use pipeline::{Equilibrium, Stability, StabilityKind, WorkedAtRest};
/// What a run of the stages gives the handout ([`pipeline::run`]): the worked solution's
/// data, which [`solution`] writes out.
pub use pipeline::{ImpactSolution, ImpactWorked, Job, Worked, NUMBERED_UNKNOWNS};
