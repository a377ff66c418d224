//! Numbers: evaluation, the linear solve, integration and the confirmation checks
//! (steps 5 and 6).

pub mod format;
