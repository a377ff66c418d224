//! The integration tests, as one binary so that the suite links once.

mod agreement;
mod answers;
mod bicycle;
mod checks;
mod compact;
mod composite;
mod constraints;
mod draw;
mod invalid;
mod kane_handout;
mod kinematics;
mod library;
mod linearize;
mod long_rows;
mod mathml;
mod matrix_pattern;
mod methods;
mod pipeline;
mod planner;
mod render;
mod robustness;
mod rows_as_formed;
mod snapshots_by_problem;
mod speeds;
mod support;
mod svg_reader;
