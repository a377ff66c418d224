//! Step 0: JSON -> a validated [`Problem`].
//!
//! [`load`] reads the text into a JSON value (noting repeated keys), declares every name,
//! then reads each section, collecting every error with its JSON path, the column inside
//! an expression and a hint. A problem comes back only when there is no error at all.
//!
//! Conventions beyond the format page, documented here because they are choices:
//! - in a 2D problem a revolute joint without an `axis` turns about `N.z`;
//! - a body without `inertia` has zero central inertia; a `points` entry without `at`
//!   is the body's origin;
//! - `gravity` uses constants only, and is written in unit vectors that do not turn
//!   relative to `N`;
//! - a position (`center`, `at`, `child_at`, a point's `at`) is written in unit vectors
//!   that do not turn relative to its body (the body's own, or those of bodies joined to
//!   it by prismatic and weld joints only), and an axis likewise relative to the parent;
//! - in 2D, positions, forces and gravity have no z component, and torques only one;
//! - a force names a point fixed on the body it acts on;
//! - keys that do not apply to a joint's type (`axis` on a spherical joint) are errors.

mod bodies;
mod constraints;
mod error;
mod expressions;
mod friction;
mod gear;
mod graph;
mod held;
mod impact;
mod impulsive;
mod initial;
mod joints;
mod json;
mod load;
mod loads;
mod matrix_names;
mod model;
mod names;
mod question_kinds;
mod question_model;
mod question_motion;
mod questions;
mod read;
mod reader;
mod schema;
mod settings;
mod shapes;
mod speeds;
mod state;
mod static_questions;
mod validate;
mod validated;
pub mod variant;
mod vary;
mod vector_value;

pub use error::{LoadError, ProblemError, ProblemErrors};
pub use expressions::axis_index;
pub use impact::{Collision, Impact, Impulse};
pub use impulsive::Impulsive;
pub use load::{apply_overrides, load, load_file};
pub use matrix_names::{free_letter, MatrixNames};
pub use model::*;
pub use question_model::*;
pub use schema::SCHEMA;
pub use state::State;
pub use validated::Problem;
pub use vary::{Grid, Vary};
pub use vector_value::VectorQuantity;

#[cfg(test)]
mod tests;
