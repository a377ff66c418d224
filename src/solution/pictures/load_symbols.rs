//! The names a picture gives its loads: an applied force by the statement's symbol, a
//! weight by its factors.

use crate::problem::LoadKind;
use crate::symbolic::{latex, simplify, Expr};

/// The symbol an applied force or couple is named by in the statement (`P` of
/// `P*N.x`, also of `-P*N.x`, drawn the way it acts): its one coefficient when that is a
/// symbol or minus one; `None` for anything else (drawn with the load's name).
pub(super) fn magnitude_symbol(kind: &LoadKind) -> Option<Expr> {
    let (LoadKind::Force { vector, .. } | LoadKind::Torque { vector, .. }) = kind else {
        return None;
    };
    let [(_, _, c)] = vector.terms.as_slice() else {
        return None;
    };
    [c.clone(), simplify(&-c.clone())]
        .into_iter()
        .find(|e| e.as_symbol().is_some())
}

/// An expression as a factor of a product: in parentheses when it is a sum.
pub(super) fn factor_tex(e: &Expr) -> String {
    if e.terms().len() > 1 {
        format!("\\left({}\\right)", latex(e))
    } else {
        latex(e)
    }
}
