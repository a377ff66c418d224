//! Steps 1 and 4: frames, unit vectors, dyadics and joints -> the kinematics of every body.
//!
//! Entry: [`Model::build_for`] (the problem and a [`Form`] in, every body's ω, α and
//! every point's v, a out, with the [`Constraints`] and the [`Site`]s). The modules are
//! private; what other stages use is re-exported here.

mod angular;
mod build;
mod compact;
mod components;
mod constraint_rows;
mod constraints;
mod denominator;
mod dependent;
mod dot_sum;
mod error;
mod frames;
mod friction;
mod gear;
mod independent;
mod inverse_by_minors;
mod joints;
mod light_rod;
mod massless;
mod model;
mod on_parent;
mod point;
mod resal;
mod site;
mod sites;
mod speeds;
mod two_force;
mod vector;

pub use compact::{named_components, Built, Kind, Quantity, AXES, MAX_EXPANDED_TERMS};
pub use constraint_rows::{drive_symbol, ConstraintRow, Constraints, FrictionSite, RowOrigin};
pub use dependent::pick;
pub use dot_sum::DotSum;
pub use error::MechanicsError;
pub use frames::{apply, Frames, Matrix};
pub use independent::{DependentSpeeds, KeptForces};
pub use joints::{ComponentKind, ReactionComponent};
pub use light_rod::closures_along_rods;
pub use massless::{
    is_massless, is_particle, is_point_particle, massless_body_moved_by, undetermined,
};
pub use model::{same_at, sample_states, BodyState, Form, JointModel, Model};
pub use on_parent::{angular, center, split};
pub use point::PointMotion;
pub use site::{Site, SiteKind};
pub use sites::reaction_unknowns;
pub use two_force::along_members;
pub use vector::{cross3, dot3, own_components, size, vector_of, zero3, Components, Vector};
