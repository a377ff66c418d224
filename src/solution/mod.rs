//! The worked solution's content (step by step, as a textbook prints it), prepared from what
//! the stages before gave: the problem, the model, the plan, the equations, the solution at
//! the initial state, the simulation and its checks ([`crate::Worked`]): a pure function of
//! them, deriving, solving and simulating nothing.
//!
//! [`worked`] fills a [`Solution`](crate::render::Solution): each step's rows as formed and simplified with their
//! headings, the where-lists, the rejections chosen to show, the tables, the pictures'
//! scenes (laid out, [`pictures`]), the answers and the checks. [`crate::render`] only writes
//! it; this stage is the last one that reads the derivation.

mod aligned;
pub mod answer_sheet;
pub mod answers;
mod auxiliary;
mod build;
mod closed_form;
mod closure_loops;
mod confirmation;
mod constancy;
mod constrained;
pub mod derived;
mod direction;
pub mod eigen_plot;
mod frames;
mod free_bodies;
mod friction;
mod handout;
mod impact;
mod independent;
mod initial_state;
mod kane;
mod kane_bodies;
mod kane_dots;
mod kane_theory;
mod kinematics;
mod lagrange;
mod light_rods;
pub mod linearization;
mod long;
mod loops;
mod matrix;
mod mode_shape;
mod named_identity;
mod on_constraint;
pub mod pictures;
mod question_answers;
mod question_steps;
mod rejected;
mod relations;
pub mod row_view;
mod settled;
mod simulation;
pub mod solve_words;
mod speeds;
mod spin_frames;
mod stability_answers;
mod static_answers;
pub mod statics;
mod switch_steps;
mod tex;
pub mod written_out;

pub use build::{setup, solution as worked};
pub use handout::{handout, student, Handout};
pub use tex::style_of;
