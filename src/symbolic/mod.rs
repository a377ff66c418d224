//! The computer-algebra core: expressions, parsing, d/dt, simplification, LaTeX,
//! and compilation to a flat numeric program.
//!
//! Entry: [`Expr`] (with [`parse`], [`simplify`], [`time_derivative`], [`latex`]) and
//! [`Program`], the compiled form. The modules are private; what other stages use is
//! re-exported here. [`budget`] stays a module: its calls read as `budget::start()`.

pub mod budget;
mod build;
mod cancel;
mod collect;
mod collect_constants;
mod compile;
mod diff;
mod eval;
mod expr;
mod factor;
mod fast_hash;
mod format;
mod forward;
mod hint;
mod horner;
mod instr;
mod linear;
mod named;
mod natural;
mod number;
mod parse;
mod perfect_square;
mod print;
mod relation;
mod roots;
mod runs;
mod schedule;
mod simplify;
mod style;
mod subst;
mod tex_name;

pub use build::{add, cos, func, mul, pow, sin, sqrt};
pub use collect::{factored, latex_collected, latex_factored, latex_with_squares, sum_times};
pub use compile::Program;
pub use diff::{partial, time_derivative, DiffError};
pub use eval::{eval, Values};
pub use expr::{
    Axis, Component, ComponentKind, Definition, Expr, Func, Name, Node, Symbol, Unknown,
};
pub use factor::pull_common_factor;
pub use fast_hash::FastMap;
pub use format::{fixed, fixed_or_zero};
pub use hint::closest;
pub use linear::{linear_coefficients, linear_split};
pub use named::{as_shown, named_definitions};
pub use number::Number;
pub use parse::{parse, ParseError, Resolve};
pub use print::{latex, latex_name, latex_name_of, latex_unit_vector, list_by_runs, plain};
pub use relation::Relation;
pub use roots::roots_of_squares;
pub use simplify::{leave_to_the_end, simplify, with_simplify_memo};
pub use style::{decimal_literals, with_style, Style};
pub use subst::substitute;
