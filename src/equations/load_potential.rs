//! The potential of an applied force that has one: a force along a fixed direction of the
//! ground whose size depends only on the position of its point along that direction, as
//! a gas law pushing a piston (`F₀ (e/(h − x))^1.4` along n̂x on a piston at x). Its work is
//! then `−ΔV` with `V = −∫ f ds`, and it belongs to the potential energy with gravity and
//! the springs, not to the work of the applied loads.
//!
//! The integral is taken where the size is a sum of terms, each a constant times a power
//! of a linear function of the coordinate (`c (a + b s)^n`, n ≠ −1); the result is checked
//! by differentiating it back. A force of constant size is left to the applied loads: a
//! course counts its work.

use crate::mechanics::{vector_of, Model};
use crate::problem::{BodyId, ForcePoint, LoadKind};
use crate::symbolic::{add, eval, mul, partial, pow, simplify, Expr, Node, Number, Symbol};

/// The potential of load `index` where it is a force with one (see the module); `None`
/// otherwise.
pub fn force_potential(model: &Model, index: usize) -> Option<Expr> {
    let LoadKind::Force { on, at, vector } = &model.problem.loads.get(index)?.kind else {
        return None;
    };
    let frames = &model.frames;
    let force = vector_of(vector).components_in(BodyId::GROUND, frames);
    let force: Vec<Expr> = force.iter().map(simplify).collect();
    let moving = |s: &Symbol| !matches!(s, Symbol::Const(_) | Symbol::Coord(_, 0));
    if force.iter().any(|c| c.any_symbol(&moving)) {
        return None;
    }
    let mut along = force.iter().enumerate().filter(|(_, c)| !c.is_zero());
    let (axis, size) = along.next()?;
    if along.next().is_some() {
        return None;
    }
    let origin = &model.bodies[on.0].origin.position;
    let point = match at {
        ForcePoint::Point(p) => model.position(*p),
        ForcePoint::Offset(v) => origin.plus(&vector_of(v)),
    };
    let s = simplify(&point.components_in(BodyId::GROUND, frames)[axis]);
    let coordinate = only_coordinate(size)?;
    if only_coordinate(&s).as_ref() != Some(&coordinate) {
        return None;
    }
    let slope = simplify(&partial(&s, &coordinate).ok()?);
    if slope.is_zero() || slope.contains(&coordinate) {
        return None;
    }
    let generalized = simplify(&(size * &slope));
    let v = simplify(&-integral(&generalized, &coordinate)?);
    // Differentiated back, at the initial state and near it.
    let back = partial(&v, &coordinate).ok()?;
    let mut values = model.values.clone();
    let problem = model.problem;
    let c =
        (0..problem.coordinates.len()).find(|&i| problem.coordinate_symbol(i, 0) == coordinate)?;
    let q0 = problem.coordinates[c].initial;
    for q in [q0, q0 * 0.99 + 1e-3] {
        values.set(coordinate.clone(), q);
        let (want, got) = (eval(&generalized, &values), -eval(&back, &values));
        if !want.is_finite() || (want - got).abs() > 1e-9 * want.abs().max(1e-9) {
            return None;
        }
    }
    Some(v)
}

/// Whether load `index` keeps the total energy: a spring, a joint spring, or a force with a
/// potential.
pub fn has_potential(model: &Model, index: usize) -> bool {
    match model.problem.loads.get(index).map(|l| &l.kind) {
        Some(LoadKind::Spring { .. } | LoadKind::JointSpring { .. }) => true,
        Some(LoadKind::Force { .. }) => force_potential(model, index).is_some(),
        _ => false,
    }
}

/// The one coordinate `e` depends on, where there is exactly one.
fn only_coordinate(e: &Expr) -> Option<Symbol> {
    let mut found: Vec<Symbol> = Vec::new();
    e.for_each_symbol(&mut |s| {
        if matches!(s, Symbol::Coord(_, 0)) && !found.contains(s) {
            found.push(s.clone());
        }
    });
    (found.len() == 1).then(|| found.remove(0))
}

/// `∫ e dq` where each term of `e` is a constant times a power of a linear function of `q`.
fn integral(e: &Expr, q: &Symbol) -> Option<Expr> {
    if !e.contains(q) {
        return Some(e * &Expr::sym(q.clone()));
    }
    match e.node() {
        Node::Add(terms) => Some(add(terms
            .iter()
            .map(|t| integral(t, q))
            .collect::<Option<Vec<_>>>()?)),
        Node::Mul(factors) => {
            let (depends, constant): (Vec<&Expr>, Vec<&Expr>) =
                factors.iter().partition(|f| f.contains(q));
            let [one] = depends.as_slice() else {
                return None;
            };
            Some(mul(constant
                .into_iter()
                .cloned()
                .chain([integral(one, q)?])))
        }
        _ => {
            let (coefficient, base, power) = linear_power(e, q)?;
            let next = power + Number::int(1);
            let slope = simplify(&partial(&base, q).ok()?);
            if next.is_zero() {
                return None;
            }
            let over = &slope * &Expr::num(next);
            Some(mul([
                coefficient,
                pow(base, Expr::num(next)),
                pow(over, Expr::int(-1)),
            ]))
        }
    }
}

/// `e` as `c · L^n` with `L` linear in `q` and `c` free of it: `L`, `L^n`, or `(k L^m)^n`
/// (for a positive base, as a gas law's is).
fn linear_power(e: &Expr, q: &Symbol) -> Option<(Expr, Expr, Number)> {
    let linear = |l: &Expr| {
        partial(l, q)
            .ok()
            .map(|d| simplify(&d))
            .is_some_and(|d| !d.is_zero() && !d.contains(q))
    };
    if linear(e) {
        return Some((Expr::one(), e.clone(), Number::int(1)));
    }
    let Node::Pow(base, exponent) = e.node() else {
        return None;
    };
    let n = exponent.as_number()?;
    if linear(base) {
        return Some((Expr::one(), base.clone(), n));
    }
    let Node::Mul(factors) = base.node() else {
        return None;
    };
    let (depends, constant): (Vec<&Expr>, Vec<&Expr>) = factors.iter().partition(|f| f.contains(q));
    let [one] = depends.as_slice() else {
        return None;
    };
    let (inner, base, m) = linear_power(one, q)?;
    let coefficient = pow(
        mul(constant.into_iter().cloned().chain([inner])),
        exponent.clone(),
    );
    Some((coefficient, base, m * n))
}
