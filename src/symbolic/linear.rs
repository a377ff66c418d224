//! Coefficients of symbols that appear linearly: the q'' and the reactions.

use super::build::{add, mul};
use super::expr::{Expr, Node, Symbol};
use std::fmt;

/// A symbol that should appear linearly but does not.
#[derive(Clone, Debug, PartialEq)]
pub struct NotLinear {
    /// The symbol, printed.
    pub symbol: String,
    /// The offending term, printed.
    pub term: String,
}

impl fmt::Display for NotLinear {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "`{}` does not appear linearly in the term `{}`",
            self.symbol, self.term
        )
    }
}

/// Splits `e` into `Σ coefficients[i] * unknowns[i] + rest`.
///
/// # Errors
/// When an unknown appears squared, inside a function, or multiplied by another unknown.
pub fn linear_split(e: &Expr, unknowns: &[Symbol]) -> Result<(Vec<Expr>, Expr), NotLinear> {
    let mut rest = Vec::new();
    let coefficients = split(e, unknowns, Some(&mut rest))?;
    Ok((coefficients, add(rest)))
}

/// The coefficients of [`linear_split`] without the rest, which is most of the terms and
/// costs most of the work when only the coefficients are wanted (planning, ranks).
///
/// # Errors
/// As [`linear_split`].
pub fn linear_coefficients(e: &Expr, unknowns: &[Symbol]) -> Result<Vec<Expr>, NotLinear> {
    split(e, unknowns, None)
}

/// The coefficients of `unknowns` in `e`; the other terms go to `rest` when it is given.
fn split(
    e: &Expr,
    unknowns: &[Symbol],
    mut rest: Option<&mut Vec<Expr>>,
) -> Result<Vec<Expr>, NotLinear> {
    let mut coefficients: Vec<Vec<Expr>> = vec![Vec::new(); unknowns.len()];
    let index_of: std::collections::HashMap<&Symbol, usize> =
        unknowns.iter().enumerate().map(|(i, u)| (u, i)).collect();
    // The kinds of symbol among the unknowns (q'' and reactions, say): most symbols are ruled
    // out by their kind, without hashing their name.
    let mut coordinate_orders = [false; 3];
    let mut other_kinds = false;
    for u in unknowns {
        match u {
            Symbol::Coord(_, order) => coordinate_orders[(*order as usize).min(2)] = true,
            _ => other_kinds = true,
        }
    }
    let is_unknown = |s: &Symbol| {
        let possible = match s {
            Symbol::Coord(_, order) => coordinate_orders[(*order as usize).min(2)],
            Symbol::Const(_) => false,
            _ => other_kinds,
        };
        possible && index_of.contains_key(s)
    };
    let find = |factor: &Expr| -> Option<usize> {
        match factor.node() {
            // The common case, an atom, is one lookup rather than a search of every unknown.
            Node::Sym(s) if is_unknown(s) => index_of.get(s).copied(),
            Node::Num(_) | Node::Sym(Symbol::Const(_)) => None,
            // One walk to see whether any unknown is inside, then which.
            _ if !factor.any_symbol(&is_unknown) => None,
            _ => unknowns.iter().position(|u| factor.contains(u)),
        }
    };
    for term in e.terms() {
        let mut found: Option<(usize, usize)> = None;
        for (position, factor) in term.factors().iter().enumerate() {
            let Some(index) = find(factor) else {
                continue;
            };
            let is_plain = matches!(factor.node(), Node::Sym(s) if *s == unknowns[index]);
            if !is_plain || found.is_some() {
                return Err(NotLinear {
                    symbol: unknowns[index].clone().to_string(),
                    term: term.to_string(),
                });
            }
            found = Some((index, position));
        }
        match found {
            Some((index, position)) => {
                coefficients[index].push(product_without(term.factors(), position));
            }
            None => {
                if let Some(rest) = rest.as_deref_mut() {
                    rest.push(term.clone());
                }
            }
        }
    }
    Ok(coefficients.into_iter().map(add).collect())
}

/// The product of a term's factors but the one at `position`. The term is canonical, so
/// plain factors (symbols, functions, powers) after its coefficient are already in order
/// with distinct bases and make the product as they are: `mul` would sort and merge them
/// again to the same result, at a cost that dominated splitting a row.
fn product_without(factors: &[Expr], position: usize) -> Expr {
    let others: Vec<Expr> = factors
        .iter()
        .enumerate()
        .filter(|(i, _)| *i != position)
        .map(|(_, f)| f.clone())
        .collect();
    let plain = |f: &Expr| matches!(f.node(), Node::Sym(_) | Node::Func(..) | Node::Pow(..));
    let coefficient = |f: &Expr| f.as_number().is_some_and(|c| !c.is_one() && !c.is_zero());
    match others.as_slice() {
        [single] if plain(single) => single.clone(),
        [first, rest @ ..] if !rest.is_empty() && (plain(first) || coefficient(first)) => {
            if rest.iter().all(plain) {
                Expr::from_node(Node::Mul(others))
            } else {
                mul(others)
            }
        }
        _ => mul(others),
    }
}

impl fmt::Display for Symbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&super::print::plain(&Expr::sym(self.clone())))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::build::cos;

    #[test]
    fn splits_mass_matrix_rows() {
        let (a, b) = (Expr::coord("q1", 2), Expr::coord("q2", 2));
        let m = Expr::constant("m");
        let e = &(&m * &a) + &(cos(Expr::coord("q2", 0)) * b.clone()) + Expr::constant("g");
        let unknowns = [Symbol::Coord("q1".into(), 2), Symbol::Coord("q2".into(), 2)];
        let (coefficients, rest) = linear_split(&e, &unknowns).unwrap();
        assert_eq!(coefficients[0], m);
        assert_eq!(coefficients[1], cos(Expr::coord("q2", 0)));
        assert_eq!(rest, Expr::constant("g"));
        assert_eq!(linear_coefficients(&e, &unknowns).unwrap(), coefficients);
        assert!(linear_split(&(&a * &a), &unknowns).is_err());
    }

    #[test]
    fn a_product_but_one_factor_is_the_one_mul_makes() {
        let (q, a) = (Expr::coord("q1", 0), Expr::coord("q1", 2));
        let m = Expr::constant("m");
        let terms = [
            Expr::int(3) * m.clone() * cos(q.clone()) * a.clone(),
            &m * &a,
            Expr::int(-2) * a.clone(),
            a.clone(),
            crate::symbolic::pow(q.clone(), Expr::ratio(1, 2)) * m.clone() * a.clone(),
        ];
        for term in terms {
            for position in 0..term.factors().len() {
                let others = term.factors().iter().enumerate();
                let others = others
                    .filter(|(i, _)| *i != position)
                    .map(|(_, f)| f.clone());
                assert_eq!(product_without(term.factors(), position), mul(others));
            }
        }
    }
}
