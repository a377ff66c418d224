//! A sum held as a map from monomial to coefficient, so that a rule finds the partners
//! of a term by hash lookup instead of by trying all pairs of terms.

use super::key::{hash_expr, same, KeyMap};
use crate::symbolic::build::{add, mul, pow};
use crate::symbolic::expr::{Expr, Func, Node};
use crate::symbolic::fast_hash::FastHasher;
use crate::symbolic::number::Number;
use std::hash::{Hash, Hasher};
use std::ops::{Add, Neg};

/// A monomial with its hash worked out once: the rules look the same partners up pass
/// after pass.
#[derive(Clone, Debug)]
pub(crate) struct Hashed {
    hash: u64,
    expr: Expr,
}

impl Hashed {
    /// `expr` with its hash.
    pub fn new(expr: Expr) -> Hashed {
        let mut state = FastHasher::default();
        hash_expr(&expr, &mut state);
        Hashed {
            hash: state.finish(),
            expr,
        }
    }
}

impl PartialEq for Hashed {
    fn eq(&self, other: &Hashed) -> bool {
        self.hash == other.hash && same(&self.expr, &other.expr)
    }
}

impl Eq for Hashed {}

impl Hash for Hashed {
    fn hash<H: Hasher>(&self, state: &mut H) {
        state.write_u64(self.hash);
    }
}

/// The terms of a sum: monomial (without its coefficient) to coefficient.
pub(crate) struct Terms {
    coefficients: KeyMap<Hashed, Number>,
    /// The monomials in the order they were first seen, so passes are deterministic
    /// (iterating the hash map would not be).
    order: Vec<Expr>,
}

/// Replacing some terms of a sum by equal ones, by one identity.
#[derive(Clone, Debug)]
pub(crate) struct Rewrite {
    /// The identity used, one of the constants of `steps`.
    pub rule: &'static str,
    /// Terms taken out: monomial and the part of its coefficient taken.
    pub remove: Vec<(Expr, Number)>,
    /// Terms put in: monomial and coefficient added.
    pub insert: Vec<(Expr, Number)>,
    /// Every monomial whose coefficient the rule looked at to choose this rewrite; while
    /// none of them changes, the rewrite and its gain stay exact.
    pub read: Vec<Expr>,
}

impl Rewrite {
    /// The removed terms as one expression.
    pub fn before(&self) -> Expr {
        add(self.remove.iter().map(|(m, c)| scaled(*c, m)))
    }

    /// The inserted terms as one expression.
    pub fn after(&self) -> Expr {
        add(self.insert.iter().map(|(m, c)| scaled(*c, m)))
    }

    /// The net change of each touched monomial, merged.
    fn deltas(&self) -> Vec<(&Expr, Number)> {
        let mut out: Vec<(&Expr, Number)> =
            Vec::with_capacity(self.remove.len() + self.insert.len());
        let changes = self
            .remove
            .iter()
            .map(|(m, c)| (m, c.neg()))
            .chain(self.insert.iter().map(|(m, c)| (m, *c)));
        for (m, d) in changes {
            match out.iter_mut().find(|(seen, _)| same(seen, m)) {
                Some(entry) => entry.1 = entry.1.add(d),
                None => out.push((m, d)),
            }
        }
        out
    }
}

/// `c * m` in canonical form.
fn scaled(c: Number, m: &Expr) -> Expr {
    mul([Expr::num(c), m.clone()])
}

/// How much shorter a rewrite makes a sum: terms and operations saved (negative when
/// it adds some). Ordered by terms first.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct Gain {
    /// Terms saved.
    pub terms: i64,
    /// Operations saved, counted as `Expr::operation_count` counts them.
    pub operations: i64,
}

impl Gain {
    /// Fewer terms and no more operations: what an identity that combines terms must give.
    /// Merely trading terms (`cos²x − sin²x → 2cos²x − 1`) is not a simplification.
    pub fn fewer_terms(self) -> bool {
        self.terms > 0 && self.operations >= 0
    }

    /// No more terms and fewer operations: what rewriting a term alone must give.
    pub fn fewer_operations(self) -> bool {
        self.terms >= 0 && self.operations > 0
    }
}

impl std::ops::AddAssign for Gain {
    fn add_assign(&mut self, other: Gain) {
        self.terms += other.terms;
        self.operations += other.operations;
    }
}

/// What the term `c * m` adds to the sum: one term, and its operations plus one for its
/// `+`. Summed over all terms this is the operation count of the sum plus one, so its
/// change over the touched terms is exactly how much shorter a rewrite makes the sum.
fn cost(c: Number, m: &Expr) -> Gain {
    let operations = if c.is_zero() {
        0
    } else if m.is_one() {
        1
    } else {
        1 + m.operation_count() as i64 + i64::from(!c.is_one())
    };
    Gain {
        terms: i64::from(!c.is_zero()),
        operations,
    }
}

impl Terms {
    /// The terms of `e` (a sum, or a single term).
    pub fn new(e: &Expr) -> Terms {
        let mut terms = Terms {
            coefficients: KeyMap::default(),
            order: Vec::new(),
        };
        for term in e.terms() {
            let (c, m) = term.split_coefficient();
            terms.change(m, c);
        }
        terms
    }

    fn change(&mut self, m: Expr, delta: Number) {
        let key = Hashed::new(m);
        match self.coefficients.get_mut(&key) {
            Some(c) => *c = c.add(delta),
            None => {
                self.order.push(key.expr.clone());
                self.coefficients.insert(key, delta);
            }
        }
    }

    /// The coefficient of the monomial `m`, zero when absent.
    pub fn coefficient(&self, m: &Expr) -> Number {
        self.coefficient_of(&Hashed::new(m.clone()))
    }

    /// The coefficient of the monomial `m` whose hash is known, zero when absent.
    pub fn coefficient_of(&self, m: &Hashed) -> Number {
        self.coefficients.get(m).copied().unwrap_or(Number::ZERO)
    }

    /// The monomials with a non-zero coefficient, in a deterministic order.
    pub fn monomials(&self) -> Vec<Expr> {
        self.order
            .iter()
            .filter(|m| !self.coefficient(m).is_zero())
            .cloned()
            .collect()
    }

    /// How much shorter the sum gets by `rewrite`.
    pub fn gain(&self, rewrite: &Rewrite) -> Gain {
        let mut gain = Gain::default();
        for (m, d) in rewrite.deltas() {
            let old = self.coefficient(m);
            let (before, after) = (cost(old, m), cost(old.add(d), m));
            gain.terms += before.terms - after.terms;
            gain.operations += before.operations - after.operations;
        }
        gain
    }

    /// Applies `rewrite`.
    pub fn apply(&mut self, rewrite: &Rewrite) {
        let deltas: Vec<(Expr, Number)> = rewrite
            .deltas()
            .into_iter()
            .map(|(m, d)| (m.clone(), d))
            .collect();
        for (m, d) in deltas {
            self.change(m, d);
        }
    }

    /// The sum in canonical form.
    pub fn to_expr(&self) -> Expr {
        add(self.order.iter().filter_map(|m| {
            let c = self.coefficient(m);
            (!c.is_zero()).then(|| scaled(c, m))
        }))
    }
}

/// A positive integer power of `sin(arg)` or `cos(arg)` among the factors of a monomial.
#[derive(Clone, Debug)]
pub(crate) struct TrigFactor {
    /// `Func::Sin` or `Func::Cos`.
    pub func: Func,
    /// The argument.
    pub arg: Expr,
    /// The power, at least one.
    pub power: i64,
}

impl TrigFactor {
    /// `func(arg)`, to the first power.
    pub fn base(&self) -> Expr {
        Expr::from_node(Node::Func(self.func, vec![self.arg.clone()]))
    }
}

/// The sine and cosine factors of the monomial `m` with positive integer powers.
pub(crate) fn trig_factors(m: &Expr) -> Vec<TrigFactor> {
    let as_trig = |e: &Expr| match e.node() {
        Node::Func(f @ (Func::Sin | Func::Cos), args) if args.len() == 1 => {
            Some((*f, args[0].clone()))
        }
        _ => None,
    };
    m.factors()
        .iter()
        .filter_map(|factor| match factor.node() {
            Node::Pow(base, exponent) => {
                let power = exponent
                    .as_number()
                    .and_then(Number::as_integer)
                    .filter(|k| *k >= 1)?;
                let (func, arg) = as_trig(base)?;
                Some(TrigFactor { func, arg, power })
            }
            _ => as_trig(factor).map(|(func, arg)| TrigFactor {
                func,
                arg,
                power: 1,
            }),
        })
        .collect()
}

/// `m · base^k` for a monomial `m` without coefficient and a sine or cosine `base`.
///
/// The factors of a canonical product are sorted by base, so this edits the sorted list
/// (a binary search and a copy of the `Rc`s) instead of forming a general product: rules
/// build several such monomials for every pair of factors of every term.
pub(crate) fn times_power(m: &Expr, base: &Expr, k: i64) -> Expr {
    let general = || {
        mul([m.clone(), pow(base.clone(), Expr::int(k))])
            .split_coefficient()
            .1
    };
    let factors: &[Expr] = if m.is_one() { &[] } else { m.factors() };
    fn base_of(f: &Expr) -> &Expr {
        match f.node() {
            Node::Pow(b, _) => b,
            _ => f,
        }
    }
    let power = |n: i64| {
        if n == 1 {
            base.clone()
        } else {
            pow(base.clone(), Expr::int(n))
        }
    };
    let mut out: Vec<Expr> = factors.to_vec();
    match factors.binary_search_by(|f| base_of(f).cmp(base)) {
        Ok(i) => {
            let old = match factors[i].node() {
                Node::Pow(_, e) => match e.as_number().and_then(Number::as_integer) {
                    Some(n) => n,
                    None => return general(),
                },
                _ => 1,
            };
            match old + k {
                0 => {
                    out.remove(i);
                }
                n => out[i] = power(n),
            }
        }
        Err(i) => out.insert(i, power(k)),
    }
    match out.len() {
        0 => Expr::one(),
        1 => out.pop().unwrap_or_else(Expr::one),
        _ => Expr::from_node(Node::Mul(out)),
    }
}

/// `m · e` for a monomial `m` without coefficient and `e` a number times at most one sine
/// or cosine (what `sin(a−b)` and its siblings build), split into coefficient and monomial.
pub(crate) fn times_trig(m: &Expr, e: &Expr) -> (Number, Expr) {
    let (k, atom) = e.split_coefficient();
    match atom.node() {
        _ if k.is_zero() || atom.is_one() => (k, m.clone()),
        Node::Func(Func::Sin | Func::Cos, _) => (k, times_power(m, &atom, 1)),
        _ => mul([m.clone(), e.clone()]).split_coefficient(),
    }
}

/// Whether `e` holds a sine or cosine anywhere, i.e. whether any rule here can apply.
pub(crate) fn has_trig(e: &Expr) -> bool {
    match e.node() {
        Node::Num(_) | Node::Sym(_) => false,
        Node::Func(Func::Sin | Func::Cos, _) => true,
        Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => items.iter().any(has_trig),
        Node::Pow(b, x) => has_trig(b) || has_trig(x),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::build::{cos, sin};

    /// Editing the sorted factor list must give exactly what the general product gives.
    #[test]
    fn times_power_agrees_with_the_canonical_product() {
        let (x, y) = (Expr::coord("q1", 0), Expr::coord("q2", 0));
        let (m, l) = (Expr::constant("m"), Expr::constant("L"));
        let spring = pow(&x * &x + Expr::constant("a"), Expr::ratio(-1, 2));
        let monomials = [
            Expr::one(),
            m.clone(),
            mul([m.clone(), l.clone(), Expr::coord("q1", 1)]),
            mul([m.clone(), sin(x.clone()), cos(y.clone())]),
            mul([l.clone(), pow(sin(x.clone()), Expr::int(3)), spring.clone()]),
            mul([pow(cos(x.clone()), Expr::int(-1)), sin(&x + &y)]),
            spring,
        ];
        let bases = [
            sin(x.clone()),
            cos(x.clone()),
            sin(y.clone()),
            cos(&x + &y),
            sin(&x + &y),
        ];
        for monomial in &monomials {
            for base in &bases {
                for k in [-3, -2, -1, 1, 2] {
                    let general = mul([monomial.clone(), pow(base.clone(), Expr::int(k))]);
                    assert_eq!(
                        times_power(monomial, base, k),
                        general,
                        "{monomial} * ({base})^{k}"
                    );
                }
            }
        }
    }

    #[test]
    fn trig_factors_finds_positive_integer_powers_only() {
        let x = Expr::coord("q1", 0);
        let e = mul([
            Expr::constant("m"),
            pow(sin(x.clone()), Expr::int(2)),
            cos(x.clone()),
            pow(cos(Expr::coord("q2", 0)), Expr::int(-1)),
        ]);
        let found: Vec<(Func, i64)> = trig_factors(&e).iter().map(|t| (t.func, t.power)).collect();
        assert_eq!(found, [(Func::Sin, 2), (Func::Cos, 1)]);
    }

    #[test]
    fn gain_counts_terms_and_operations() {
        let x = Expr::coord("q1", 0);
        let (s2, c2) = (
            pow(sin(x.clone()), Expr::int(2)),
            pow(cos(x.clone()), Expr::int(2)),
        );
        let terms = Terms::new(&(&s2 + &c2));
        let rewrite = Rewrite {
            rule: "test",
            remove: vec![(s2.clone(), Number::ONE), (c2.clone(), Number::ONE)],
            insert: vec![(Expr::one(), Number::ONE)],
            read: vec![],
        };
        // sin(q1)^2 + cos(q1)^2 takes 5 operations, 1 takes none.
        assert_eq!(
            terms.gain(&rewrite),
            Gain {
                terms: 1,
                operations: 5
            }
        );
    }
}
