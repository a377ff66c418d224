//! Kane's handout with the dependent speeds finished on the loop: a partial velocity, a
//! generalized force or a row whose terms the position constraints of step 1 combine is
//! written as the constraints make it. The four-bar's `ṽ^{C*}_4 = (a cos q₂ − c cos(q₁ + q₂ −
//! q₃) − d cos(q₁ + q₂))/(2Δ) ĉ_y` is `−b/(2Δ) ĉ_y`, since the loop along `b̂_x` is zero; its
//! `ṽ^{C*}_5`, whose bracket is the loop along `b̂_y`, is zero, so that C does not move with
//! `u₅`. Every form is checked against the one it replaces at two states on the loop.

use crate::equations::{Derivation, Method};
use crate::mechanics::{Model, SiteKind, Vector};
use crate::problem::BodyId;
use crate::symbolic::{eval, simplify, Expr, Node, Symbol, Values};

/// The most rewrites of one expression (each one shortens it).
const MOST_REWRITES: usize = 12;

/// How closely two forms must agree on the loop: the loop is closed to about 1e-10, and a
/// term over `Δ` multiplies that by its size (a rewrite that is wrong differs by far more).
const LOOP_TOLERANCE: f64 = 1e-7;

/// The position constraints of step 1 and the states on the loop they are checked at.
pub struct OnTheLoop {
    rows: Vec<Expr>,
    states: Vec<Values>,
}

impl OnTheLoop {
    /// The loop of a Kane handout with dependent speeds written in symbols; `None` for any
    /// other handout, or where no two states on the loop are found.
    pub fn of(derivation: &Derivation) -> Option<OnTheLoop> {
        if derivation.method != Method::Kane {
            return None;
        }
        let speeds = (derivation.dependent_speeds.as_ref()).filter(|s| !s.at_each_state)?;
        let mut on_loop = OnTheLoop::of_model(&derivation.model)?;
        // `Δ` as step 5 says it is on the loop, `−b sin(q₁ + q₂ − q₃)`, where it cancels.
        if let Some(link) = super::kane_delta::on_the_loop(&derivation.model, speeds) {
            on_loop.rows.push(simplify(&(&link.delta - &link.equal)));
        }
        Some(on_loop)
    }

    /// The loop of `model`'s position constraints, whatever the method.
    pub fn of_model(model: &Model) -> Option<OnTheLoop> {
        let rows: Vec<Expr> = (model.constraints.rows.iter())
            .filter_map(|row| row.position.clone())
            .map(|p| simplify(&p))
            .filter(|p| p.any_symbol(&|s| matches!(s, Symbol::Coord(..))))
            .collect();
        if rows.is_empty() {
            return None;
        }
        let states = states_on_loop(model, &rows)?;
        // Each closed loop along every frame's axes: zero on the loop as well (the
        // four-bar's along n̂_x, a cos q₁ + b cos(q₁ + q₂) − c cos q₃ − d).
        let mut all = rows;
        for gap in closure_gaps(model) {
            let frames = std::iter::once(BodyId::GROUND).chain(model.order.iter().copied());
            for frame in frames {
                for axis in 0..3 {
                    let unit: [Expr; 3] = std::array::from_fn(|i| match i == axis {
                        true => Expr::one(),
                        false => Expr::zero(),
                    });
                    let along = simplify(&gap.dot(&Vector::new(frame, unit), &model.frames));
                    if along.any_symbol(&|s| matches!(s, Symbol::Coord(..)))
                        && !all.contains(&along)
                    {
                        all.push(along);
                    }
                }
            }
        }
        Some(OnTheLoop { rows: all, states })
    }

    /// The states on the loop (the start, then one with the free coordinates moved).
    pub fn states(&self) -> &[Values] {
        &self.states
    }

    /// `e` as short as the position constraints make it, equal to `e` on the loop; `e`
    /// itself where no constraint shortens it.
    pub fn reduce(&self, e: &Expr) -> Expr {
        let mut best = e.clone();
        if !best.any_symbol(&|s| matches!(s, Symbol::Coord(..))) {
            return best;
        }
        for _ in 0..MOST_REWRITES {
            let Some(shorter) = self.shorter(&best) else {
                break;
            };
            if !self.same(&shorter, &best) {
                break;
            }
            best = shorter;
        }
        best
    }

    /// Whether `a` and `b` agree at the states on the loop, to the closure's rounding.
    pub fn same(&self, a: &Expr, b: &Expr) -> bool {
        // The unknowns (a reaction, a second derivative) given values of their own.
        let mut free: Vec<Symbol> = Vec::new();
        for e in [a, b] {
            e.for_each_symbol(&mut |s| {
                let given = self.states.first().is_some_and(|v| !v.get(s).is_nan());
                if !given && !matches!(s, Symbol::Defined(_)) && !free.contains(s) {
                    free.push(s.clone());
                }
            });
        }
        self.states.iter().all(|state| {
            let mut state = state.clone();
            for (k, s) in free.iter().enumerate() {
                state.set(s.clone(), 0.37 + 0.29 * k as f64);
            }
            let (x, y) = (eval(a, &state), eval(b, &state));
            x.is_finite() && (x - y).abs() <= LOOP_TOLERANCE * (1.0 + y.abs())
        })
    }

    /// Whether `e` is zero at the states on the loop, to the closure's rounding.
    pub fn is_zero(&self, e: &Expr) -> bool {
        self.same(e, &Expr::zero())
    }

    /// `e − λ φ` for the constraint `φ` and the multiple `λ` that removes a term of `e`
    /// against a term of `φ`, the shortest that is shorter than `e`.
    fn shorter(&self, e: &Expr) -> Option<Expr> {
        let mut best: Option<(usize, Expr)> = None;
        let size = e.operation_count();
        let terms = e.terms().to_vec();
        for phi in &self.rows {
            for pivot in phi.terms() {
                if !pivot.any_symbol(&|s| matches!(s, Symbol::Coord(..))) {
                    continue;
                }
                for term in &terms {
                    let lambda = simplify(&(term / pivot));
                    if !divides(&lambda, term) {
                        continue;
                    }
                    let candidate = simplify(&(e - &(&lambda * phi)));
                    let count = candidate.operation_count();
                    let shortest = best.as_ref().map_or(size, |(c, _)| *c);
                    if count < shortest {
                        best = Some((count, candidate));
                    }
                }
            }
        }
        best.map(|(_, e)| e)
    }
}

/// Each closure's gap, the point on the parent less the point on the child: zero on the
/// loop.
fn closure_gaps(model: &Model) -> Vec<Vector> {
    (model.sites.iter())
        .filter(|s| matches!(s.kind, SiteKind::Closure(_)))
        .map(|site| {
            let on_parent = model.point_on(site.parent, &site.parent_offset);
            on_parent.position.minus(&site.point.position)
        })
        .collect()
}

/// Whether `lambda` (a term divided by a constraint's term) is free of denominators with
/// a coordinate that the term did not have: the constraint's term divides the term.
fn divides(lambda: &Expr, term: &Expr) -> bool {
    let under = |e: &Expr| -> Vec<Expr> {
        (e.factors().iter())
            .filter(|f| matches!(f.node(), Node::Pow(_, x) if matches!(x.node(), Node::Num(n) if n.is_negative())))
            .filter(|f| f.any_symbol(&|s| matches!(s, Symbol::Coord(..))))
            .cloned()
            .collect()
    };
    let had = under(term);
    under(lambda).iter().all(|f| had.contains(f))
}

/// The start with the loop closed, and a second state on the loop: the coordinates the
/// constraints leave free moved by a little, the dependent ones solved for again.
fn states_on_loop(model: &Model, rows: &[Expr]) -> Option<Vec<Values>> {
    let start = crate::mechanics::sample_states(model).into_iter().next()?;
    let problem = model.problem;
    let n = problem.coordinates.len();
    let q: Vec<f64> = (0..n)
        .map(|i| start.get(&problem.coordinate_symbol(i, 0)))
        .collect();
    let rates: Vec<f64> = (0..n)
        .map(|i| start.get(&problem.coordinate_symbol(i, 1)))
        .collect();
    let dependent = &model.constraints.dependent;
    let moved: Vec<f64> = (q.iter().enumerate())
        .map(|(i, &value)| match dependent.contains(&i) {
            true => value,
            false => value + 0.13,
        })
        .collect();
    Some(vec![
        closed(model, rows, &q, &rates)?,
        closed(model, rows, &moved, &rates)?,
    ])
}

/// The state at coordinates `q` and `rates` with the dependent coordinates solved for so
/// that every constraint of `rows` holds; `None` where Newton's method finds no root.
fn closed(model: &Model, rows: &[Expr], q: &[f64], rates: &[f64]) -> Option<Values> {
    let dependent = &model.constraints.dependent;
    let at = |u: &nalgebra::DVector<f64>| -> Values {
        let mut q = q.to_vec();
        for (k, &d) in dependent.iter().enumerate() {
            q[d] = u[k];
        }
        model.values_at(0.0, &q, rates)
    };
    let holds = |values: &Values| (rows.iter()).all(|row| eval(row, values).abs() < 1e-9);
    if dependent.is_empty() {
        // Nothing to solve for: the rows hold at `q` or nowhere near it.
        let values = model.values_at(0.0, q, rates);
        return holds(&values).then_some(values);
    }
    let u0 = nalgebra::DVector::from_iterator(dependent.len(), dependent.iter().map(|&d| q[d]));
    let residual = |u: &nalgebra::DVector<f64>| {
        let values = at(u);
        let r: Vec<f64> = rows.iter().map(|row| eval(row, &values)).collect();
        (r.iter().all(|x| x.is_finite())).then(|| nalgebra::DVector::from_vec(r))
    };
    let root = crate::numeric::newton_solve(residual, u0).ok()?;
    let values = at(&root.u);
    holds(&values).then_some(values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn divides_rejects_a_new_denominator() {
        let a = Expr::constant("a");
        let q = Expr::coord("q", 0);
        let c = crate::symbolic::cos(q.clone());
        let term = &a * &c;
        assert!(divides(&simplify(&(&term / &c)), &term));
        let s = crate::symbolic::sin(q);
        assert!(!divides(&simplify(&(&term / &s)), &term));
    }
}
