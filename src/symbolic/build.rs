//! The smart constructors that keep every expression canonical, and the operators.

use super::expr::{Expr, Func, Node};
use super::number::Number;
use std::cmp::Ordering;
use std::ops;
use std::ops::{Add, Mul};

/// The largest integer power of a sum that is expanded.
pub const MAX_EXPANDED_POWER: i64 = 8;

/// The most terms a power of a sum may expand to; a larger power stays a power (and the
/// parser refuses it, see [`is_refused_power`]).
pub const MAX_EXPANDED_TERMS: u64 = 10_000;

/// An upper bound on the terms of `(a_1 + … + a_n)^k`: the monomials of degree k in n
/// variables, C(n + k - 1, k), saturating.
pub fn expanded_terms(n: usize, k: i64) -> u64 {
    let (n, k) = (n as u64, k.max(0) as u64);
    let mut count: u64 = 1;
    for i in 0..k {
        count = count.saturating_mul(n + i) / (i + 1);
        if count > u64::MAX / 1024 {
            return u64::MAX;
        }
    }
    count
}

/// Whether `e` holds a power of a sum that was left unexpanded only because it would be
/// too large: the sign of an input that grows past the bound.
pub fn is_refused_power(e: &Expr) -> bool {
    match e.node() {
        Node::Pow(base, exponent) => {
            let refused = matches!(base.node(), Node::Add(_))
                && exponent
                    .as_number()
                    .and_then(Number::as_integer)
                    .is_some_and(|k| (2..=MAX_EXPANDED_POWER).contains(&k));
            refused || is_refused_power(base) || is_refused_power(exponent)
        }
        Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => {
            items.iter().any(is_refused_power)
        }
        Node::Num(_) | Node::Sym(_) => false,
    }
}

/// The canonical sum of `terms`.
pub fn add(terms: impl IntoIterator<Item = Expr>) -> Expr {
    // Past the work limit: see `budget`.
    if super::budget::exhausted() {
        return Expr::zero();
    }
    let mut constant = Number::ZERO;
    let mut monomials: Vec<Expr> = Vec::new();
    let mut push = |term: &Expr| match term.node() {
        Node::Num(n) => constant = constant.add(*n),
        _ => monomials.push(term.clone()),
    };
    for term in terms {
        match term.node() {
            Node::Add(inner) => inner.iter().for_each(&mut push),
            _ => push(&term),
        }
    }
    super::budget::charge(monomials.len() as u64);
    // Like terms end up next to each other; the sort is stable and finds the sorted runs
    // that sums being added already are, so adding two sums costs about their length.
    monomials.sort_by(|a, b| cmp_rest(rest_factors(a), rest_factors(b)));
    let mut out: Vec<Expr> = Vec::with_capacity(monomials.len() + 1);
    if !constant.is_zero() {
        out.push(Expr::num(constant));
    }
    let mut rest = monomials.as_slice();
    while let Some(first) = rest.first() {
        let key = rest_factors(first);
        let same = 1 + rest[1..]
            .iter()
            .take_while(|t| cmp_rest(rest_factors(t), key) == Ordering::Equal)
            .count();
        let (run, tail) = rest.split_at(same);
        rest = tail;
        if same == 1 {
            // Already canonical: kept as it is, without a new node.
            out.push(first.clone());
            continue;
        }
        let coefficient = run
            .iter()
            .fold(Number::ZERO, |sum, t| sum.add(coefficient_of(t)));
        if !coefficient.is_zero() {
            out.push(scale_factors(coefficient, key));
        }
    }
    match out.len() {
        0 => Expr::zero(),
        1 => out.pop().unwrap_or_else(Expr::zero),
        _ => Expr::from_node(Node::Add(out)),
    }
}

/// The numeric coefficient of a monomial.
fn coefficient_of(term: &Expr) -> Number {
    match term.node() {
        Node::Num(n) => *n,
        Node::Mul(factors) => factors[0].as_number().unwrap_or(Number::ONE),
        _ => Number::ONE,
    }
}

/// The factors of a monomial other than its numeric coefficient.
fn rest_factors(term: &Expr) -> &[Expr] {
    match term.node() {
        Node::Mul(factors) if factors[0].as_number().is_some() => &factors[1..],
        Node::Mul(factors) => factors,
        _ => std::slice::from_ref(term),
    }
}

/// The order of two monomials' non-numeric parts, exactly as `Expr::cmp` orders them once
/// built (a single factor is itself, several are a product), without building them.
fn cmp_rest(a: &[Expr], b: &[Expr]) -> Ordering {
    match (a, b) {
        ([x], [y]) => x.cmp(y),
        ([x], _) if !matches!(x.node(), Node::Mul(_)) => x.rank().cmp(&Expr::MUL_RANK),
        (_, [y]) if !matches!(y.node(), Node::Mul(_)) => Expr::MUL_RANK.cmp(&y.rank()),
        _ => {
            let (a, b) = (flatten_single(a), flatten_single(b));
            a.len().cmp(&b.len()).then_with(|| a.cmp(b))
        }
    }
}

fn flatten_single(factors: &[Expr]) -> &[Expr] {
    match factors {
        [single] => single.factors(),
        _ => factors,
    }
}

/// `coefficient` times the product of `factors` (canonical, without a coefficient).
fn scale_factors(coefficient: Number, factors: &[Expr]) -> Expr {
    match (factors, coefficient.is_one()) {
        ([], _) => Expr::num(coefficient),
        ([single], true) => single.clone(),
        (_, true) => Expr::from_node(Node::Mul(factors.to_vec())),
        _ => {
            let mut all = Vec::with_capacity(factors.len() + 1);
            all.push(Expr::num(coefficient));
            all.extend(factors.iter().cloned());
            Expr::from_node(Node::Mul(all))
        }
    }
}

/// The canonical, expanded product of `factors`.
pub fn mul(factors: impl IntoIterator<Item = Expr>) -> Expr {
    if super::budget::exhausted() {
        return Expr::zero();
    }
    let mut coefficient = Number::ONE;
    // (base, exponent, the factor as given)
    let mut powers: Vec<(Expr, Expr, Expr)> = Vec::new();
    let mut sums: Vec<Expr> = Vec::new();
    let mut visit = |factor: &Expr, coefficient: &mut Number| match factor.node() {
        Node::Num(n) => *coefficient = coefficient.mul(*n),
        Node::Add(_) => sums.push(factor.clone()),
        Node::Pow(base, exponent) => powers.push((base.clone(), exponent.clone(), factor.clone())),
        _ => powers.push((factor.clone(), Expr::one(), factor.clone())),
    };
    for factor in factors {
        match factor.node() {
            Node::Mul(inner) => inner.iter().for_each(|f| visit(f, &mut coefficient)),
            _ => visit(&factor, &mut coefficient),
        }
    }
    if coefficient.is_zero() {
        return Expr::zero();
    }
    super::budget::charge((powers.len() + sums.len()) as u64);
    if !sums.is_empty()
        && powers
            .iter()
            .any(|(b, _, _)| matches!(b.node(), Node::Add(_)))
    {
        // A sum meeting a power of itself merges with it, S · S⁻¹ = 1, rather than being
        // multiplied out over it.
        sums.retain(|sum| {
            let meets = powers.iter().any(|(b, e, _)| {
                b == sum
                    && e.as_number()
                        .and_then(Number::as_integer)
                        .is_some_and(|k| k < 0)
            });
            if meets {
                powers.push((sum.clone(), Expr::one(), sum.clone()));
            }
            !meets
        });
    }
    powers.sort_by(|a, b| a.0.cmp(&b.0));
    let mut rebuilt: Vec<Expr> = Vec::with_capacity(powers.len());
    let mut needs_another_pass = false;
    let mut rest = powers.as_slice();
    while let Some((base, _, _)) = rest.first() {
        let same = rest
            .iter()
            .take_while(|(b, _, _)| b.cmp(base) == Ordering::Equal)
            .count();
        let (run, tail) = rest.split_at(same);
        rest = tail;
        let factor = if same == 1 {
            // A factor that meets no other of its base stays as it was given.
            run[0].2.clone()
        } else {
            let exponent = add(run.iter().map(|(_, e, _)| e.clone()));
            if exponent.is_zero() {
                continue;
            }
            if exponent.is_one() {
                base.clone()
            } else {
                pow(base.clone(), exponent)
            }
        };
        match factor.node() {
            Node::Num(n) => coefficient = coefficient.mul(*n),
            Node::Sym(_) | Node::Func(..) | Node::Pow(..) => rebuilt.push(factor),
            _ => {
                needs_another_pass = true;
                rebuilt.push(factor)
            }
        }
    }
    if needs_another_pass {
        rebuilt.push(Expr::num(coefficient));
        rebuilt.extend(sums);
        return mul(rebuilt);
    }
    if sums.len() == 1 && rebuilt.is_empty() {
        // A number times a sum: scaling every coefficient keeps the terms' order.
        return scale_sum(coefficient, &sums[0]);
    }
    if let Some(sum) = sums.pop() {
        // Distribute over the first sum; the recursion expands the others.
        let mut rest = rebuilt;
        rest.push(Expr::num(coefficient));
        rest.extend(sums);
        let rest = mul(rest);
        return add(sum.terms().iter().map(|t| mul([t.clone(), rest.clone()])));
    }
    if coefficient.is_zero() {
        return Expr::zero();
    }
    match (rebuilt.len(), coefficient.is_one()) {
        (0, _) => Expr::num(coefficient),
        (1, true) => rebuilt.pop().unwrap_or_else(Expr::one),
        (_, true) => Expr::from_node(Node::Mul(rebuilt)),
        (_, false) => {
            let mut all = vec![Expr::num(coefficient)];
            all.extend(rebuilt);
            Expr::from_node(Node::Mul(all))
        }
    }
}

/// `coefficient` times a sum, term by term.
fn scale_sum(coefficient: Number, sum: &Expr) -> Expr {
    if coefficient.is_one() {
        return sum.clone();
    }
    let underflows = sum
        .terms()
        .iter()
        .any(|t| coefficient_of(t).mul(coefficient).is_zero());
    if underflows {
        return add(sum
            .terms()
            .iter()
            .map(|t| mul([Expr::num(coefficient), t.clone()])));
    }
    let terms = sum
        .terms()
        .iter()
        .map(|t| match t.node() {
            Node::Num(n) => Expr::num(n.mul(coefficient)),
            _ => scale_factors(coefficient.mul(coefficient_of(t)), rest_factors(t)),
        })
        .collect();
    Expr::from_node(Node::Add(terms))
}

/// The canonical power `base^exponent`.
pub fn pow(base: Expr, exponent: Expr) -> Expr {
    if super::budget::exhausted() {
        return Expr::zero();
    }
    if exponent.is_zero() {
        return Expr::one();
    }
    if exponent.is_one() {
        return base;
    }
    let integer = exponent.as_number().and_then(Number::as_integer);
    match (base.node(), exponent.as_number()) {
        (Node::Num(b), Some(e)) => {
            if let Some(k) = e.as_integer() {
                if let Some(value) = b.powi(k) {
                    return Expr::num(value);
                }
            } else if e == Number::Ratio(1, 2) {
                if let Some(root) = b.exact_sqrt() {
                    return Expr::num(root);
                }
            } else if e == Number::Ratio(-1, 2) {
                if let Some(root) = b.exact_sqrt().and_then(Number::recip) {
                    return Expr::num(root);
                }
            }
        }
        (Node::Mul(factors), _) if integer.is_some() => {
            return mul(factors.iter().map(|f| pow(f.clone(), exponent.clone())));
        }
        (Node::Pow(inner_base, inner_exp), _) if integer.is_some() => {
            return pow(inner_base.clone(), mul([inner_exp.clone(), exponent]));
        }
        (Node::Add(terms), _) => {
            let small = |k: &i64| {
                (2..=MAX_EXPANDED_POWER).contains(k)
                    && expanded_terms(terms.len(), *k) <= MAX_EXPANDED_TERMS
            };
            if let Some(k) = integer.filter(small) {
                return mul(std::iter::repeat_n(base, k as usize));
            }
        }
        _ => {}
    }
    Expr::from_node(Node::Pow(base, exponent))
}

/// Whether `e` is written with a leading minus sign, so that odd functions can pull it out.
pub fn has_negative_sign(e: &Expr) -> bool {
    match e.node() {
        Node::Num(n) => n.is_negative(),
        Node::Mul(_) => e.split_coefficient().0.is_negative(),
        Node::Add(terms) => terms
            .iter()
            .find(|t| t.as_number().is_none())
            .is_some_and(|t| t.split_coefficient().0.is_negative()),
        _ => false,
    }
}

/// The canonical function application.
pub fn func(f: Func, args: Vec<Expr>) -> Expr {
    if super::budget::exhausted() {
        return Expr::zero();
    }
    let single = args.len() == 1;
    if single {
        let arg = &args[0];
        if arg.is_zero() {
            match f {
                Func::Sin
                | Func::Tan
                | Func::Asin
                | Func::Atan
                | Func::Sqrt
                | Func::Abs
                | Func::Sign => return Expr::zero(),
                Func::Cos | Func::Exp => return Expr::one(),
                _ => {}
            }
        }
        if f == Func::Sqrt {
            return pow(arg.clone(), Expr::ratio(1, 2));
        }
        let odd = matches!(
            f,
            Func::Sin | Func::Tan | Func::Asin | Func::Atan | Func::Sign
        );
        if (odd || f == Func::Cos || f == Func::Abs) && has_negative_sign(arg) {
            let flipped = func(f, vec![-arg.clone()]);
            return if odd { -flipped } else { flipped };
        }
    }
    Expr::from_node(Node::Func(f, args))
}

/// `sin(x)`.
pub fn sin(x: Expr) -> Expr {
    func(Func::Sin, vec![x])
}

/// `cos(x)`.
pub fn cos(x: Expr) -> Expr {
    func(Func::Cos, vec![x])
}

/// `sqrt(x)`.
pub fn sqrt(x: Expr) -> Expr {
    pow(x, Expr::ratio(1, 2))
}

impl ops::Add for Expr {
    type Output = Expr;
    fn add(self, rhs: Expr) -> Expr {
        add([self, rhs])
    }
}
impl ops::Add for &Expr {
    type Output = Expr;
    fn add(self, rhs: &Expr) -> Expr {
        add([self.clone(), rhs.clone()])
    }
}
impl ops::Sub for Expr {
    type Output = Expr;
    fn sub(self, rhs: Expr) -> Expr {
        add([self, -rhs])
    }
}
impl ops::Sub for &Expr {
    type Output = Expr;
    fn sub(self, rhs: &Expr) -> Expr {
        add([self.clone(), -rhs.clone()])
    }
}
impl ops::Mul for Expr {
    type Output = Expr;
    fn mul(self, rhs: Expr) -> Expr {
        mul([self, rhs])
    }
}
impl ops::Mul for &Expr {
    type Output = Expr;
    fn mul(self, rhs: &Expr) -> Expr {
        mul([self.clone(), rhs.clone()])
    }
}
impl ops::Div for Expr {
    type Output = Expr;
    fn div(self, rhs: Expr) -> Expr {
        mul([self, pow(rhs, Expr::int(-1))])
    }
}
impl ops::Div for &Expr {
    type Output = Expr;
    fn div(self, rhs: &Expr) -> Expr {
        mul([self.clone(), pow(rhs.clone(), Expr::int(-1))])
    }
}
impl ops::Neg for Expr {
    type Output = Expr;
    fn neg(self) -> Expr {
        mul([Expr::int(-1), self])
    }
}
impl ops::Neg for &Expr {
    type Output = Expr;
    fn neg(self) -> Expr {
        mul([Expr::int(-1), self.clone()])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn x() -> Expr {
        Expr::constant("x")
    }
    fn y() -> Expr {
        Expr::constant("y")
    }

    #[test]
    fn like_terms_collect() {
        assert_eq!(x() + x(), Expr::int(2) * x());
        assert!((x() - x()).is_zero());
        assert_eq!(x() + y(), y() + x());
    }

    #[test]
    fn products_expand_and_combine_powers() {
        let lhs = (x() + y()) * (x() - y());
        let rhs = x() * x() - y() * y();
        assert_eq!(lhs, rhs);
        assert_eq!(x() / x(), Expr::one());
        let s = x() + y();
        assert_eq!(s.clone() / s.clone(), Expr::one());
        assert_eq!(
            mul([s.clone(), x(), pow(s.clone(), Expr::int(-2))]),
            x() * pow(s.clone(), Expr::int(-1))
        );
        assert_eq!(
            pow(x() + y(), Expr::int(2)),
            x() * x() + Expr::int(2) * x() * y() + y() * y()
        );
    }

    #[test]
    fn odd_and_even_functions_take_the_sign_out() {
        assert_eq!(sin(-x()), -sin(x()));
        assert_eq!(cos(y() - x()), cos(x() - y()));
    }
}
