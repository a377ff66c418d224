//! Substitution of symbols by expressions.

use super::build::{add, func, mul, pow};
use super::expr::{Expr, Node, Symbol};
use super::fast_hash::FastMap;
use std::rc::Rc;

/// `e` with every symbol for which `replace` returns `Some` replaced, re-canonicalized.
///
/// A subtree shared by several parents (a named quantity's value, a factor common to many
/// terms) is substituted once: the answer depends on the subtree alone.
pub fn substitute(e: &Expr, replace: &dyn Fn(&Symbol) -> Option<Expr>) -> Expr {
    let mut done = Done::default();
    substitute_in(e, replace, &mut done)
}

/// The subtrees of one substitution already substituted, by the address of their node:
/// every key is a node of the expression being substituted, alive for the whole call.
type Done = FastMap<*const Node, Expr>;

fn substitute_in(e: &Expr, replace: &dyn Fn(&Symbol) -> Option<Expr>, done: &mut Done) -> Expr {
    match e.node() {
        Node::Num(_) => return e.clone(),
        Node::Sym(s) if !matches!(s, Symbol::Defined(_)) => {
            return replace(s).unwrap_or_else(|| e.clone())
        }
        _ => {}
    }
    let key = Rc::as_ptr(&e.0);
    if let Some(result) = done.get(&key) {
        return result.clone();
    }
    let mut each = |x: &Expr| substitute_in(x, replace, done);
    let result = match e.node() {
        Node::Sym(s @ Symbol::Defined(d)) => match replace(s) {
            Some(replaced) => replaced,
            None => {
                // A definition that changes is replaced by what it now stands for.
                let value = each(d.value());
                if Rc::ptr_eq(&value.0, &d.value().0) || value == *d.value() {
                    e.clone()
                } else {
                    value
                }
            }
        },
        Node::Add(terms) => add(terms.iter().map(&mut each).collect::<Vec<_>>()),
        Node::Mul(factors) => mul(factors.iter().map(&mut each).collect::<Vec<_>>()),
        Node::Pow(b, x) => {
            let b = each(b);
            pow(b, each(x))
        }
        Node::Func(f, args) => func(*f, args.iter().map(&mut each).collect()),
        Node::Num(_) | Node::Sym(_) => e.clone(),
    };
    done.insert(key, result.clone());
    result
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::build::sin;

    #[test]
    fn substitutes_and_simplifies() {
        let q = Expr::coord("q", 0);
        let e = sin(q.clone()) + q.clone();
        let zero = substitute(&e, &|s| matches!(s, Symbol::Coord(..)).then(Expr::zero));
        assert!(zero.is_zero());
    }

    /// `e_{k+1} = sin(e_k) + cos(e_k)`, forty levels deep, each level holding the one
    /// below twice: 2^40 paths through a tree of 120 nodes. With `q̇ → 0` it must equal the
    /// same nest built on `c` alone, as writing `c` for `c + q̇` before nesting gives.
    #[test]
    fn a_shared_subtree_is_substituted_once() {
        use crate::symbolic::build::cos;
        let nest = |start: Expr| (0..40).fold(start, |e, _| sin(e.clone()) + cos(e));
        let c = Expr::constant("c");
        let rate = Expr::coord("q", 1);
        let e = nest(&c + &rate);
        let at_rest = substitute(&e, &|s| matches!(s, Symbol::Coord(_, 1)).then(Expr::zero));
        assert_eq!(at_rest, nest(c));
    }
}
