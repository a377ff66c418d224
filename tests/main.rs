//! The integration tests, as one binary so that the suite links once.

mod invalid;
mod kinematics;
mod library;
mod methods;
mod render;
mod robustness;
mod support;
mod snapshots_by_problem;
