//! Simplified expressions kept for the length of one worked solution: its steps simplify
//! the same sums again and again (a row's groups, the row, the matrix's entries, the
//! answers), and the result depends on the expression alone.
//!
//! Kept only inside [`with_simplify_memo`], so that nothing outlives one problem: a
//! quantity named once (a `Definition`) is the same by its name within one problem only.

use super::key::{Key, KeyMap};
use crate::symbolic::expr::Expr;
use std::cell::RefCell;

thread_local! {
    /// The expressions simplified so far in the current scope; `None` outside one.
    static KEPT: RefCell<Option<KeyMap<Key, Expr>>> = const { RefCell::new(None) };
}

/// Runs `f` with every [`simplify`](super::simplify) of an expression already simplified
/// in it answered from memory. Nested calls share the outermost scope.
pub fn with_simplify_memo<R>(f: impl FnOnce() -> R) -> R {
    /// Ends the scope also when `f` unwinds.
    struct Scope(bool);
    impl Drop for Scope {
        fn drop(&mut self) {
            if self.0 {
                KEPT.with(|kept| kept.borrow_mut().take());
            }
        }
    }
    let opened = KEPT.with(|kept| {
        let mut kept = kept.borrow_mut();
        let outermost = kept.is_none();
        if outermost {
            *kept = Some(KeyMap::default());
        }
        outermost
    });
    let _scope = Scope(opened);
    f()
}

/// `e` simplified earlier in this scope.
pub(super) fn kept(e: &Expr) -> Option<Expr> {
    KEPT.with(|kept| (kept.borrow().as_ref()).and_then(|map| map.get(&Key(e.clone())).cloned()))
}

/// Keeps `simpler` as `e` simplified, inside a scope. Nothing is kept once the symbolic
/// work has passed its limit: the builders then give zeros.
pub(super) fn keep(e: &Expr, simpler: &Expr) {
    if crate::symbolic::budget::exhausted() {
        return;
    }
    KEPT.with(|kept| {
        if let Some(map) = kept.borrow_mut().as_mut() {
            map.insert(Key(e.clone()), simpler.clone());
        }
    });
}

#[cfg(test)]
mod tests {
    use super::with_simplify_memo;
    use crate::symbolic::build::{add, cos, mul, sin};
    use crate::symbolic::{simplify, Expr};

    /// m·sin²q + m·cos²q + k: simplified to m + k, the same inside the scope as outside,
    /// and the second time inside it from memory (the very same expression).
    #[test]
    fn kept_results_are_the_simplified_ones() {
        let q = Expr::coord("q", 0);
        let (m, k) = (Expr::constant("m"), Expr::constant("k"));
        let e = add(vec![
            mul(vec![m.clone(), sin(q.clone()), sin(q.clone())]),
            mul(vec![m.clone(), cos(q.clone()), cos(q)]),
            k.clone(),
        ]);
        let outside = simplify(&e);
        assert_eq!(outside, add(vec![m, k]));
        let (first, second) = with_simplify_memo(|| {
            let first = simplify(&e);
            (first, with_simplify_memo(|| simplify(&e)))
        });
        assert_eq!(first, outside);
        assert!(std::rc::Rc::ptr_eq(&first.0, &second.0));
        // The scope is closed: a fresh result again.
        assert!(!std::rc::Rc::ptr_eq(&simplify(&e).0, &first.0));
    }
}
