//! An expression of the equations of motion taken apart as a course compares two of them:
//! the coefficient of each unknown (the q'' and the reactions), the terms without rates
//! (weights, springs, loads) and the terms with rates (centripetal, Coriolis, dampers).

use super::reference::{Reference, Sample};
use crate::symbolic::{
    add, eval, func, linear_split, mul, pow, simplify, substitute, Expr, Func, Node, Symbol,
};

/// Which part of an expression.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Key {
    /// The coefficient of an unknown: a q'' or a reaction component.
    Unknown(Symbol),
    /// The terms without unknowns or rates.
    Free,
    /// The terms with rates and without unknowns.
    Rates,
}

impl Key {
    /// The part named for a student: "the coefficient of theta''", "the terms with rates".
    pub(super) fn phrase(&self) -> String {
        match self {
            Key::Unknown(s) => format!("the coefficient of {}", Expr::sym(s.clone())),
            Key::Free => "the terms without rates".into(),
            Key::Rates => "the terms with rates".into(),
        }
    }
}

/// One part of an expression, with its values at the sampled states.
#[derive(Clone, Debug)]
pub(super) struct Part {
    pub key: Key,
    pub expr: Expr,
    pub values: Vec<f64>,
}

/// The values of `e` at the sampled states (`free`: with the q'' drawn at random).
pub(super) fn values(e: &Expr, samples: &[Sample], free: bool) -> Vec<f64> {
    samples
        .iter()
        .map(|s| eval(e, if free { &s.free } else { &s.motion }))
        .collect()
}

/// The parts of `e`, in the problem's own symbols (see [`Reference::own_symbols`]): one per
/// unknown, then the terms without rates, then those with rates. `None` when an unknown
/// does not appear linearly.
pub(super) fn parts(e: &Expr, unknowns: &[Symbol], reference: &Reference) -> Option<Vec<Part>> {
    let (rates, samples) = (&reference.rates, &reference.samples);
    let e = reference.own_symbols(e);
    let (coefficients, rest) = linear_split(&e, unknowns).ok()?;
    let mut out: Vec<Part> = unknowns
        .iter()
        .zip(coefficients)
        .map(|(u, c)| (Key::Unknown(u.clone()), simplify(&c)))
        .map(|(key, expr)| part(key, expr, samples))
        .collect();
    let free = simplify(&substitute(&rest, &|s| rates.contains(s).then(Expr::zero)));
    let with_rates = simplify(&(rest - free.clone()));
    out.push(part(Key::Free, free, samples));
    out.push(part(Key::Rates, with_rates, samples));
    Some(out)
}

fn part(key: Key, expr: Expr, samples: &[Sample]) -> Part {
    let values = values(&expr, samples, true);
    Part { key, expr, values }
}

/// The largest value of any part: what "zero" is measured against.
pub(super) fn scale(parts: &[Part]) -> f64 {
    parts
        .iter()
        .map(|p| super::numbers::norm(&p.values))
        .fold(0.0, f64::max)
}

/// `e` with every sine made a cosine and every cosine a sine.
pub(super) fn swap_sine_cosine(e: &Expr) -> Expr {
    match e.node() {
        Node::Num(_) | Node::Sym(_) => e.clone(),
        Node::Add(terms) => add(terms.iter().map(swap_sine_cosine)),
        Node::Mul(factors) => mul(factors.iter().map(swap_sine_cosine)),
        Node::Pow(b, x) => pow(swap_sine_cosine(b), x.clone()),
        Node::Func(f, args) => {
            let swapped = match f {
                Func::Sin => Func::Cos,
                Func::Cos => Func::Sin,
                other => *other,
            };
            func(swapped, args.iter().map(swap_sine_cosine).collect())
        }
    }
}

/// Whether `e` holds a sine (`true`) or a cosine (`false`) first, if either.
pub(super) fn first_trig(e: &Expr) -> Option<bool> {
    match e.node() {
        Node::Num(_) | Node::Sym(_) => None,
        Node::Func(Func::Sin, _) => Some(true),
        Node::Func(Func::Cos, _) => Some(false),
        Node::Func(_, items) | Node::Add(items) | Node::Mul(items) => {
            items.iter().find_map(first_trig)
        }
        Node::Pow(b, x) => first_trig(b).or_else(|| first_trig(x)),
    }
}

/// The top-level terms of `e`, each with its values (`free`: q'' drawn at random).
pub(super) fn terms(e: &Expr, samples: &[Sample]) -> Vec<(Expr, Vec<f64>)> {
    e.terms()
        .iter()
        .map(|t| (t.clone(), values(t, samples, true)))
        .collect()
}
