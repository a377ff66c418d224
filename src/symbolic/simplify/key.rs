//! Expressions as hash keys that stay cheap when the expressions are big.
//!
//! The terms of a mechanism's equations carry big shared factors (the `1/sqrt(...)` of a
//! spring's length, say) that would be hashed and compared in full at every lookup. A
//! [`Key`] hashes only a bounded prefix of the tree, and compares by pointer first at every
//! node, so shared subtrees cost nothing.

use crate::symbolic::expr::{Expr, Node};
use crate::symbolic::fast_hash::FastHasher;
use std::cmp::Ordering;
use std::collections::{HashMap, HashSet};
use std::hash::{BuildHasherDefault, Hash, Hasher};
use std::rc::Rc;

/// How many nodes of an expression its hash looks at, in pre-order. Enough to tell the
/// monomials of real equations apart; collisions beyond it cost an equality check.
const HASHED_NODES: u32 = 32;

/// A hash map keyed by expressions, with [`FastHasher`].
pub(crate) type KeyMap<K, V> = HashMap<K, V, BuildHasherDefault<FastHasher>>;
/// A hash set of expressions, with [`FastHasher`].
pub(crate) type KeySet<K> = HashSet<K, BuildHasherDefault<FastHasher>>;

/// An expression used as a key of a hash map or set.
#[derive(Clone, Debug)]
pub(crate) struct Key(pub Expr);

impl PartialEq for Key {
    fn eq(&self, other: &Key) -> bool {
        same(&self.0, &other.0)
    }
}

impl Eq for Key {}

impl Hash for Key {
    fn hash<H: Hasher>(&self, state: &mut H) {
        hash_expr(&self.0, state)
    }
}

impl PartialOrd for Key {
    fn partial_cmp(&self, other: &Key) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Key {
    fn cmp(&self, other: &Key) -> Ordering {
        self.0.cmp(&other.0)
    }
}

/// Structural equality, as `==` on expressions, but true at once for shared nodes.
pub(crate) fn same(a: &Expr, b: &Expr) -> bool {
    if Rc::ptr_eq(&a.0, &b.0) {
        return true;
    }
    let all =
        |x: &[Expr], y: &[Expr]| x.len() == y.len() && x.iter().zip(y).all(|(p, q)| same(p, q));
    match (a.node(), b.node()) {
        (Node::Num(x), Node::Num(y)) => x == y,
        (Node::Sym(x), Node::Sym(y)) => x == y,
        (Node::Add(x), Node::Add(y)) | (Node::Mul(x), Node::Mul(y)) => all(x, y),
        (Node::Pow(b1, e1), Node::Pow(b2, e2)) => same(b1, b2) && same(e1, e2),
        (Node::Func(f, x), Node::Func(g, y)) => f == g && all(x, y),
        _ => false,
    }
}

/// Hashes the first [`HASHED_NODES`] nodes of `e`; equal expressions hash equally.
pub(crate) fn hash_expr<H: Hasher>(e: &Expr, state: &mut H) {
    let mut budget = HASHED_NODES;
    hash_prefix(e, state, &mut budget);
}

fn hash_prefix<H: Hasher>(e: &Expr, state: &mut H, budget: &mut u32) {
    if *budget == 0 {
        return;
    }
    *budget -= 1;
    let mut items = |tag: u8, items: &[Expr], state: &mut H| {
        tag.hash(state);
        items.len().hash(state);
        for item in items {
            hash_prefix(item, state, budget);
        }
    };
    match e.node() {
        Node::Num(n) => {
            0u8.hash(state);
            n.to_f64().to_bits().hash(state);
        }
        Node::Sym(s) => {
            1u8.hash(state);
            s.hash(state);
        }
        Node::Add(terms) => items(2, terms, state),
        Node::Mul(factors) => items(3, factors, state),
        Node::Pow(b, x) => {
            4u8.hash(state);
            hash_prefix(b, state, budget);
            hash_prefix(x, state, budget);
        }
        Node::Func(f, args) => {
            f.hash(state);
            items(5, args, state);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::build::{add, cos, mul, sin};
    use std::hash::BuildHasher;

    fn hash(e: &Expr) -> u64 {
        BuildHasherDefault::<FastHasher>::default().hash_one(Key(e.clone()))
    }

    /// Equal expressions built separately (no shared nodes) are the same key with the same
    /// hash, also when they differ only beyond the hashed prefix.
    #[test]
    fn equal_expressions_are_equal_keys() {
        let build = |last: &str| {
            let long = add((0..40).map(|i| Expr::constant(&format!("c{i}"))));
            mul([sin(Expr::coord("q1", 0)), long, cos(Expr::constant(last))])
        };
        let (a, b, c) = (build("z"), build("z"), build("w"));
        assert!(same(&a, &b) && a == b);
        assert_eq!(hash(&a), hash(&b));
        assert!(!same(&a, &c) && a != c);
        assert_eq!(Key(a.clone()) == Key(c.clone()), a == c);
    }
}
