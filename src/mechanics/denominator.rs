//! The common denominator of the dependent rates, named once: a textbook writes the
//! four-bar's `q̇₂ = −(d s₃/Δ) q̇₁` with `Δ = a sin(q₁ − q₃) + d s₃` defined beside it, not the
//! sum under every fraction of every Kane row, term by term.

use crate::symbolic::{add, func, mul, pow, simplify, Expr, Node, Symbol};

/// Each sum of the coordinates that divides some entry of `entries`, named `Δ` (`Δ₁`, `Δ₂`,
/// … when there are several), and the entries written with the names.
pub fn name_denominators(entries: &mut [&mut Expr]) {
    let mut sums: Vec<Expr> = Vec::new();
    for e in entries.iter() {
        denominators(e, &mut sums);
    }
    let named: Vec<(Expr, Expr)> = sums
        .iter()
        .enumerate()
        .map(|(k, sum)| {
            let (name, latex) = if sums.len() == 1 {
                ("Delta".to_string(), "\\Delta".to_string())
            } else {
                (format!("Delta{}", k + 1), format!("\\Delta_{{{}}}", k + 1))
            };
            let symbol = Expr::named(
                &name,
                &latex,
                "the common denominator of the dependent rates",
                sum.clone(),
            );
            (sum.clone(), symbol)
        })
        .collect();
    if named.is_empty() {
        return;
    }
    for e in entries.iter_mut() {
        let replaced = replace_sums(e, &named);
        if replaced != **e {
            **e = simplify(&replaced);
        }
    }
}

/// The fewest operations a sum must have to be named: one read at a glance, as the
/// slider-crank's `x − r cos q₁`, stays as it is.
const SHORTEST_NAMED: usize = 5;

/// The sums with a coordinate in them that `e` divides by, added to `out` once each.
fn denominators(e: &Expr, out: &mut Vec<Expr>) {
    match e.node() {
        Node::Pow(base, exponent) => {
            let negative = matches!(exponent.node(), Node::Num(n) if n.is_negative());
            let of_coordinates = base.any_symbol(&|s| matches!(s, Symbol::Coord(..)));
            if negative
                && matches!(base.node(), Node::Add(_))
                && of_coordinates
                && base.operation_count_capped(SHORTEST_NAMED) >= SHORTEST_NAMED
                && !out.contains(base)
            {
                out.push(base.clone());
            }
            denominators(base, out);
        }
        Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => {
            items.iter().for_each(|x| denominators(x, out))
        }
        Node::Num(_) | Node::Sym(_) => {}
    }
}

/// `e` with each sum of `named` replaced by its name.
fn replace_sums(e: &Expr, named: &[(Expr, Expr)]) -> Expr {
    if let Some((_, name)) = named.iter().find(|(sum, _)| sum == e) {
        return name.clone();
    }
    match e.node() {
        Node::Num(_) | Node::Sym(_) => e.clone(),
        Node::Add(terms) => add(terms.iter().map(|t| replace_sums(t, named))),
        Node::Mul(factors) => mul(factors.iter().map(|f| replace_sums(f, named))),
        Node::Pow(b, x) => pow(replace_sums(b, named), replace_sums(x, named)),
        Node::Func(f, args) => func(*f, args.iter().map(|a| replace_sums(a, named)).collect()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::{latex, sin};

    #[test]
    fn a_sum_of_the_coordinates_under_a_fraction_is_named_once() {
        // The four-bar's a sin(q1 − q3) + d sin(q3).
        let q1 = Expr::sym(Symbol::Coord("q1".into(), 0));
        let q3 = Expr::sym(Symbol::Coord("q3".into(), 0));
        let a = Expr::sym(Symbol::Const("a".into()));
        let d = Expr::sym(Symbol::Const("d".into()));
        let sum = &(&a * &sin(&q1 - &q3)) + &(&d * &sin(q3.clone()));
        let mut first = &d / &sum;
        let mut second = &(&q1 * &d) / &sum;
        name_denominators(&mut [&mut first, &mut second]);
        assert_eq!(latex(&first), "\\frac{d}{\\Delta}");
        assert!(latex(&second).contains("\\Delta"));
        // The numbers are unchanged: the name stands for the sum.
        let Node::Mul(factors) = first.node() else {
            panic!("d/Δ is a product");
        };
        assert!(factors
            .iter()
            .any(|f| f.any_symbol(&|s| matches!(s, Symbol::Defined(_)))));
    }

    #[test]
    fn a_short_or_constant_denominator_stays_as_it_is() {
        let x = Expr::sym(Symbol::Coord("x".into(), 0));
        let r = Expr::sym(Symbol::Const("r".into()));
        let mut short = &r / &(&x - &(&r * &crate::symbolic::cos(x.clone())));
        let before = short.clone();
        name_denominators(&mut [&mut short]);
        assert_eq!(short, before);
        let r = Expr::sym(Symbol::Const("r".into()));
        let big = Expr::sym(Symbol::Const("R".into()));
        let mut entry = &r / &(&big - &r);
        let before = entry.clone();
        name_denominators(&mut [&mut entry]);
        assert_eq!(entry, before);
    }
}
