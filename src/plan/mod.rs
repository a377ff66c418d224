//! Steps 2 and 3: the free bodies and the planner's table of equations.

pub mod choose;
pub mod forces;
pub mod planner;
pub mod rejection;
pub mod rows;
mod span;
