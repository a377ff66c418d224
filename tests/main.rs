//! The integration tests, as one binary so that the suite links once.

mod invalid;
mod render;
