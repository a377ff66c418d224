//! The record of which identity was used where, for the worked solution.

use crate::symbolic::expr::Expr;
use std::fmt;

/// `sin²x + cos²x = 1`, used in any of its forms.
pub const PYTHAGORAS: &str = "sin²+cos²=1";
/// `cos(a+b) = cos a cos b − sin a sin b`.
pub const COS_SUM: &str = "cos(a+b) = cos a cos b − sin a sin b";
/// `cos(a−b) = cos a cos b + sin a sin b`.
pub const COS_DIFFERENCE: &str = "cos(a−b) = cos a cos b + sin a sin b";
/// `sin(a+b) = sin a cos b + cos a sin b`.
pub const SIN_SUM: &str = "sin(a+b) = sin a cos b + cos a sin b";
/// `sin(a−b) = sin a cos b − cos a sin b`.
pub const SIN_DIFFERENCE: &str = "sin(a−b) = sin a cos b − cos a sin b";
/// `sin 2a = 2 sin a cos a`, used only when asked for (see `Options::double_angle`).
pub const DOUBLE_ANGLE: &str = "sin 2a = 2 sin a cos a";

/// One use of an identity: the terms `before` were replaced by the equal terms `after`.
///
/// `before` and `after` are only the terms the identity touched (times their common
/// cofactor), not the whole expression, so a worked solution can show
/// `m L² sin²q₁ + m L² cos²q₁ = m L²` and name the identity beside it.
#[derive(Clone, Debug, PartialEq)]
pub struct Step {
    /// The identity used, one of the constants of this module (e.g. [`PYTHAGORAS`]).
    pub rule: &'static str,
    /// The terms as they were.
    pub before: Expr,
    /// The terms that replaced them.
    pub after: Expr,
}

impl fmt::Display for Step {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {}   [{}]", self.before, self.after, self.rule)
    }
}
