//! The coordinates that the position constraints settle at a state, in symbols: at the
//! bottom of the cylinder (x = 0), x² + y² = (R − r)² gives y = −(R − r), so that a period
//! reads ω² = 2g/(3(R − r)) rather than ω² = −2gy/(3(R − r)²) "with y = −0.4 m".

use crate::equations::Derivation;
use crate::numeric::Answer;
use crate::symbolic::latex;
use crate::symbolic::partial;
use crate::symbolic::substitute;
use crate::symbolic::{eval, Values};
use crate::symbolic::{simplify, Expr, Node, Number, Symbol};

/// Coordinates written in symbols at a state, with the sentence that says why.
pub struct Settled {
    replaced: Vec<(Symbol, Expr)>,
    reasons: Vec<String>,
}

impl Settled {
    /// `e` with the settled coordinates put in.
    pub fn apply(&self, e: &Expr) -> Expr {
        let replaced = &self.replaced;
        simplify(&substitute(e, &|s| {
            (replaced.iter())
                .find(|(r, _)| r == s)
                .map(|(_, e)| e.clone())
        }))
    }

    /// `$x = 0$ and $x^{2} + y^{2} = (R - r)^{2}$ give $y = -(R - r)$`.
    pub fn sentence(&self) -> String {
        self.reasons.join(", and ")
    }
}

/// The coordinates other than `k` that `e` holds, each settled by a position constraint
/// once the coordinates that are zero at the answer's state are put in; `None` where one
/// is not, or where `e` with them put in does not keep its `value`.
pub fn on_constraints(
    derivation: &Derivation,
    answer: &Answer,
    e: &Expr,
    k: usize,
    value: f64,
) -> Option<Settled> {
    let problem = derivation.model.problem;
    let zero: Vec<Symbol> = (0..problem.coordinates.len())
        .filter(|&i| answer.q[i].abs() < 1e-12)
        .map(|i| problem.coordinate_symbol(i, 0))
        .collect();
    let zeroed = |x: &Expr| simplify(&substitute(x, &|s| zero.contains(s).then(Expr::zero)));
    let zero_tex: Vec<String> = (zero.iter())
        .map(|s| format!("{} = 0", latex(&Expr::sym(s.clone()))))
        .collect();
    let mut settled = Settled {
        replaced: Vec::new(),
        reasons: Vec::new(),
    };
    let wanted: Vec<usize> = (0..problem.coordinates.len())
        .filter(|&i| i != k && e.contains(&problem.coordinate_symbol(i, 0)))
        .collect();
    if wanted.is_empty() || zero.is_empty() {
        return None;
    }
    let constraints = &derivation.model.constraints;
    for i in wanted {
        let q = problem.coordinate_symbol(i, 0);
        let at = answer.q[i];
        let from_relation = constraints.relations.iter().find_map(|(_, relation)| {
            let root = on_square(&zeroed(&relation.square), &q, &relation.root, at)?;
            let tex = match at < 0.0 && relation.root.terms().len() > 1 {
                true => format!("-\\left({}\\right)", latex(&relation.root)),
                false => latex(&root),
            };
            Some((
                root,
                tex,
                relation.square.clone(),
                format!("${}$", relation.latex()),
            ))
        });
        let from_row = || {
            constraints.rows.iter().find_map(|row| {
                let p = row.position.as_ref()?;
                let root = on_line(&zeroed(p), &q)?;
                let tex = latex(&root);
                Some((root, tex, p.clone(), format!("${} = 0$", latex(p))))
            })
        };
        let (root, tex, source, why) = from_relation.or_else(from_row)?;
        let put: Vec<&String> = (zero.iter().zip(&zero_tex))
            .filter(|(s, _)| source.contains(s))
            .map(|(_, t)| t)
            .collect();
        let put = put
            .iter()
            .map(|t| t.as_str())
            .collect::<Vec<_>>()
            .join(",\\ ");
        settled.reasons.push(format!(
            "${put}$ and {why} giving ${} = {tex}$",
            latex(&Expr::sym(q.clone())),
        ));
        settled.replaced.push((q, root));
    }
    let mut v = Values::new();
    for c in &problem.constants {
        v.set(Symbol::Const(c.name.as_str().into()), c.value);
    }
    for (i, x) in answer.q.iter().enumerate() {
        v.set(problem.coordinate_symbol(i, 0), *x);
    }
    let kept = eval(&settled.apply(e), &v);
    ((kept - value).abs() <= 1e-9 * value.abs().max(1e-12)).then_some(settled)
}

/// `q` from `square = root²` where `square` is `q²` alone: ±root, the sign of `at`.
fn on_square(square: &Expr, q: &Symbol, root: &Expr, at: f64) -> Option<Expr> {
    let Node::Pow(base, exponent) = square.node() else {
        return None;
    };
    let is_q = base.as_symbol() == Some(q);
    if !is_q || exponent.as_number() != Some(Number::Ratio(2, 1)) {
        return None;
    }
    Some(match at < 0.0 {
        true => simplify(&-root),
        false => root.clone(),
    })
}

/// `q` from `p = 0` where `p` is linear in `q` with a slope free of it (its value is
/// checked with the rest).
fn on_line(p: &Expr, q: &Symbol) -> Option<Expr> {
    let slope = simplify(&partial(p, q).ok()?);
    if slope.is_zero() || slope.contains(q) || !slope.is_constant() {
        return None;
    }
    let rest = simplify(&(p - &(&slope * &Expr::sym(q.clone()))));
    if rest.contains(q) {
        return None;
    }
    let root = simplify(&(&-&rest / &slope));
    root.is_constant().then_some(root)
}
