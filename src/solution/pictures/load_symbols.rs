//! The names a picture gives its loads: an applied force by the statement's symbol, a
//! weight by its factors.

use crate::problem::{BodyId, LoadKind};
use crate::symbolic::{latex, simplify, Expr, Func, Node};

/// The symbol an applied force or couple is named by in the statement (`P` of
/// `P*N.x`, also of `-P*N.x`, drawn the way it acts): its one coefficient when that is a
/// symbol or minus one; `None` for anything else (drawn with the load's name).
pub(super) fn magnitude_symbol(kind: &LoadKind) -> Option<Expr> {
    let (LoadKind::Force { vector, .. } | LoadKind::Torque { vector, .. }) = kind else {
        return None;
    };
    if let Some(polar) = polar(kind) {
        return Some(polar.magnitude);
    }
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

/// A force written by its size and its angle, as a statement gives a pull `P` at the angle
/// `β` above a line: `P cos(β) ê_i + P sin(β) ê_j` of one frame.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Polar {
    /// The size's symbol (`P`).
    pub magnitude: Expr,
    /// The angle's symbol (`β`), measured from `ê_i` towards `ê_j`.
    pub angle: Expr,
    /// The frame of `ê_i` and `ê_j`.
    pub frame: BodyId,
    /// The axes `i` and `j` (0 1 2 for x y z).
    pub axes: (u8, u8),
}

/// The [`Polar`] form of a force, `None` when it is not written as one.
pub(super) fn polar(kind: &LoadKind) -> Option<Polar> {
    let LoadKind::Force { vector, .. } = kind else {
        return None;
    };
    let [(f1, i, c1), (f2, j, c2)] = vector.terms.as_slice() else {
        return None;
    };
    if f1 != f2 || i == j {
        return None;
    }
    // Each coefficient the product of one symbol and the cosine (sine) of one symbol.
    let split = |c: &Expr, func: Func| -> Option<(Expr, Expr)> {
        let [a, b] = c.factors() else {
            return None;
        };
        let turned = |e: &Expr| match e.node() {
            Node::Func(f, args) if *f == func && args.len() == 1 => {
                args[0].as_symbol().map(|_| args[0].clone())
            }
            _ => None,
        };
        match (a.as_symbol(), b.as_symbol()) {
            (Some(_), None) => Some((a.clone(), turned(b)?)),
            (None, Some(_)) => Some((b.clone(), turned(a)?)),
            _ => None,
        }
    };
    let (size, angle) = split(c1, Func::Cos)?;
    let (size2, angle2) = split(c2, Func::Sin)?;
    (size == size2 && angle == angle2).then_some(Polar {
        magnitude: size,
        angle,
        frame: *f1,
        axes: (*i, *j),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::{ForcePoint, PointRef, VectorExpr};
    use crate::symbolic::{cos, sin};

    fn force(terms: Vec<(u8, Expr)>) -> LoadKind {
        LoadKind::Force {
            on: BodyId(1),
            at: ForcePoint::Point(PointRef::MassCenter(BodyId(1))),
            vector: VectorExpr {
                terms: terms
                    .into_iter()
                    .map(|(a, c)| (BodyId::GROUND, a, c))
                    .collect(),
            },
        }
    }

    /// `P cos(β) n̂_x + P sin(β) n̂_y` is the pull P at β from n̂_x towards n̂_y; the
    /// sine and cosine the other way round, two sizes, or one term are not.
    #[test]
    fn a_pull_at_an_angle_is_named_by_its_size_and_angle() {
        let (p, q, beta) = (
            Expr::constant("P"),
            Expr::constant("Q"),
            Expr::constant("beta"),
        );
        let pull = force(vec![
            (0, p.clone() * cos(beta.clone())),
            (1, p.clone() * sin(beta.clone())),
        ]);
        let found = polar(&pull).expect("a polar pull");
        assert_eq!(
            (found.magnitude.clone(), found.angle, found.axes),
            (p.clone(), beta.clone(), (0, 1))
        );
        assert_eq!(magnitude_symbol(&pull), Some(p.clone()));
        let swapped = force(vec![
            (0, p.clone() * sin(beta.clone())),
            (1, p.clone() * cos(beta.clone())),
        ]);
        assert_eq!(polar(&swapped), None);
        let two = force(vec![
            (0, p.clone() * cos(beta.clone())),
            (1, q * sin(beta.clone())),
        ]);
        assert_eq!(polar(&two), None);
        assert_eq!(magnitude_symbol(&two), None);
        assert_eq!(polar(&force(vec![(0, p.clone())])), None);
        assert_eq!(magnitude_symbol(&force(vec![(0, p.clone())])), Some(p));
    }
}
