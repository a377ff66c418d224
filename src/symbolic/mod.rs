//! The computer-algebra core: expressions, parsing, d/dt, simplification, LaTeX,
//! and compilation to a flat numeric program.

pub mod budget;
pub mod build;
pub mod cancel;
pub mod collect;
mod collect_constants;
pub mod compile;
pub mod diff;
pub mod eval;
pub mod expr;
mod factor;
pub mod fast_hash;
pub mod format;
pub mod forward;
pub mod hint;
pub mod horner;
mod instr;
pub mod linear;
pub mod named;
pub mod natural;
pub mod number;
pub mod parse;
pub mod print;
pub mod relation;
pub mod roots;
mod runs;
mod schedule;
pub mod simplify;
pub mod style;
pub mod subst;
mod tex_name;

pub use build::{add, cos, func, mul, pow, sin, sqrt};
pub use expr::{
    Axis, Component, ComponentKind, Definition, Expr, Func, Name, Node, Symbol, Unknown,
};
pub use factor::pull_common_factor;
pub use number::Number;
pub use simplify::simplify;
