//! The unit vectors of a centre kept at a distance from a fixed axis (a disc rolling inside
//! a cylinder): ê_r = (x n̂_x + y n̂_y)/(R − r) along the line of centres and
//! ê_t = n̂_z × ê_r = (−y n̂_x + x n̂_y)/(R − r) along the common tangent, defined once in
//! step 1 and used to name the directions of the contact's rows ("no slip at the contact,
//! along ê_t") instead of writing them out in n̂.

use crate::mechanics::{Model, Vector};
use crate::problem::{BodyId, JointKind, Problem};
use crate::symbolic::{latex, latex_unit_vector, simplify, Expr, Relation};

/// The coordinates whose squares are the terms of `relation`'s square, each along `n̂_x` or
/// `n̂_y` of a planar joint on the ground: `(coordinate, axis)` per term; `None` where a term
/// is not such a square.
pub(super) fn planar_squares(
    problem: &Problem,
    relation: &Relation,
) -> Option<Vec<(usize, usize)>> {
    (relation.square.terms().iter())
        .map(|term| {
            let i = (0..problem.coordinates.len()).find(|&i| {
                let q = problem.coordinate_expr(i, 0);
                simplify(&(&q * &q)) == *term
            })?;
            let c = &problem.coordinates[i];
            let joint = &problem.joints[c.joint];
            let along = joint.kind == JointKind::Planar && joint.parent == BodyId::GROUND;
            (along && c.index_in_joint <= 1).then_some((i, c.index_in_joint))
        })
        .collect()
}

/// The coordinates along `n̂_x`, `n̂_y` of a planar joint on the ground whose squares make
/// a kept distance's square, and that distance: `(x, y, R − r)`.
fn polar(model: &Model) -> Option<(Expr, Expr, Expr)> {
    let problem = model.problem;
    (model.constraints.relations.iter()).find_map(|(_, relation)| {
        let squares = planar_squares(problem, relation)?;
        let mut found: [Option<Expr>; 2] = [None, None];
        for &(i, axis) in &squares {
            found[axis] = Some(problem.coordinate_expr(i, 0));
        }
        let [Some(x), Some(y)] = found else {
            return None;
        };
        (squares.len() == 2).then(|| (x, y, relation.root.clone()))
    })
}

/// `ê_t = \frac{-y n̂_x + x n̂_y}{R - r}`, the definition said beside ê_r's; `None` where
/// the problem keeps no such distance.
pub fn tangent_definition(model: &Model) -> Option<String> {
    let (x, y, root) = polar(model)?;
    Some(format!(
        "\\hat{{\\mathbf{{e}}}}_{{t}} = \\frac{{-{} {} + {} {}}}{{{}}}",
        latex(&y),
        latex_unit_vector("N", 0),
        latex(&x),
        latex_unit_vector("N", 1),
        latex(&root)
    ))
}

/// `v` named by ±ê_r or ±ê_t where it is one of them.
pub fn named(model: &Model, v: &Vector) -> Option<String> {
    let (x, y, root) = polar(model)?;
    let c = v.components_in(BodyId::GROUND, &model.frames);
    let is = |target: [Expr; 2]| {
        simplify(&c[2]).is_zero()
            && (0..2).all(|k| simplify(&(&c[k] - &(&target[k] / &root))).is_zero())
    };
    let minus = |e: &Expr| simplify(&(&Expr::int(-1) * e));
    let candidates = [
        ("\\hat{\\mathbf{e}}_{r}", [x.clone(), y.clone()]),
        ("-\\hat{\\mathbf{e}}_{r}", [minus(&x), minus(&y)]),
        ("\\hat{\\mathbf{e}}_{t}", [minus(&y), x.clone()]),
        ("-\\hat{\\mathbf{e}}_{t}", [y.clone(), minus(&x)]),
    ];
    candidates
        .into_iter()
        .find(|(_, target)| is(target.clone()))
        .map(|(name, _)| name.to_string())
}
