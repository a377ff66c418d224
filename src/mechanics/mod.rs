//! Steps 1 and 4: frames, unit vectors, dyadics and joints -> the kinematics of every body.

pub mod angular;
pub mod build;
pub mod compact;
pub mod components;
pub mod constraint_rows;
pub mod constraints;
pub mod denominator;
pub mod dependent;
pub mod dot_sum;
pub mod error;
pub mod frames;
pub mod friction;
pub mod gear;
pub mod independent;
pub mod inverse_by_minors;
pub mod joints;
pub mod light_rod;
pub mod massless;
pub mod model;
pub mod on_parent;
pub mod point;
pub mod resal;
pub mod site;
pub mod sites;
pub mod speeds;
pub mod two_force;
pub mod vector;

pub use error::MechanicsError;
pub use model::{BodyState, Form, JointModel, Model};
pub use point::PointMotion;
pub use vector::Vector;
