//! Simplified expressions kept for the length of one worked solution: its steps simplify
//! the same sums again and again (a row's groups, the row, the matrix's entries, the
//! answers), and the result depends on the expression alone.
//!
//! Kept only inside [`with_simplify_memo`], so that nothing outlives one problem: a
//! quantity named once (a `Definition`) is the same by its name within one problem only.
//!
//! The sine-cosine pairs of each monomial (see `pairs`) are kept for the scope too: the
//! sums simplified in one worked solution share most of their monomials (a row, its two
//! halves `F_r` and `F*_r`, the row again with its roots of squares taken), and forming
//! the pairs, then dropping them, was the larger part of simplifying each.

use super::key::{Key, KeyMap};
use super::pairs::Pairs;
use crate::symbolic::expr::Expr;
use std::cell::RefCell;

thread_local! {
    /// The expressions simplified so far in the current scope; `None` outside one.
    static KEPT: RefCell<Option<KeyMap<Key, Expr>>> = const { RefCell::new(None) };
    /// The pairs formed so far in the current scope, without and with the double angle
    /// (which forms more of them); `None` outside a scope.
    static PAIRS: RefCell<Option<[Pairs; 2]>> = const { RefCell::new(None) };
    /// Whether what a scope kept is left to the end of the process (see
    /// [`leave_to_the_end`]).
    static LEFT: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// From now on, what a scope of [`with_simplify_memo`] kept is not freed when the scope
/// ends but left to the end of the process, which frees it at once: for a command that
/// writes one worked solution and exits. Freeing the millions of small expressions kept
/// for a large mechanism, one by one, took a tenth of its run. Not for a process that
/// goes on (a directory of problems, `serve`), whose memory would grow with every scope.
pub fn leave_to_the_end() {
    LEFT.with(|left| left.set(true));
}

/// Runs `f` with every [`simplify`](super::simplify) of an expression already simplified
/// in it answered from memory. Nested calls share the outermost scope.
pub fn with_simplify_memo<R>(f: impl FnOnce() -> R) -> R {
    /// Ends the scope also when `f` unwinds.
    struct Scope(bool);
    impl Drop for Scope {
        fn drop(&mut self) {
            if self.0 {
                let kept = KEPT.with(|kept| kept.borrow_mut().take());
                let pairs = PAIRS.with(|pairs| pairs.borrow_mut().take());
                if LEFT.with(std::cell::Cell::get) {
                    std::mem::forget((kept, pairs));
                }
            }
        }
    }
    let opened = KEPT.with(|kept| {
        let mut kept = kept.borrow_mut();
        let outermost = kept.is_none();
        if outermost {
            *kept = Some(KeyMap::default());
            PAIRS.with(|pairs| *pairs.borrow_mut() = Some(Default::default()));
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

/// The pairs kept in this scope for `double_angle` or not, taken out for one
/// simplification (`None` outside a scope); give them back with [`give_back_pairs`].
pub(super) fn take_pairs(double_angle: bool) -> Option<Pairs> {
    PAIRS.with(|pairs| {
        (pairs.borrow_mut().as_mut())
            .map(|kept| std::mem::take(&mut kept[usize::from(double_angle)]))
    })
}

/// Keeps `taken` (from [`take_pairs`], with what one simplification added) for the rest
/// of the scope. Nothing is kept once the symbolic work has passed its limit.
pub(super) fn give_back_pairs(double_angle: bool, taken: Pairs) {
    if crate::symbolic::budget::exhausted() {
        return;
    }
    PAIRS.with(|pairs| {
        if let Some(kept) = pairs.borrow_mut().as_mut() {
            let slot = &mut kept[usize::from(double_angle)];
            // A simplification inside this one (none today) gave its own back first: the
            // larger set stays.
            if slot.len() <= taken.len() {
                *slot = taken;
            }
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

    /// Sums that share monomials, simplified one after another in one scope (the later
    /// ones reading the sine-cosine pairs the earlier ones formed), come out as each does
    /// alone outside a scope, and as the identities give by hand:
    /// m L² (cos a cos b − sin a sin b) = m L² cos(a + b), and with the pair's partner
    /// missing, nothing to combine.
    #[test]
    fn shared_pairs_give_what_each_sum_gives_alone() {
        let (a, b) = (Expr::coord("a", 0), Expr::coord("b", 0));
        let (m, l) = (Expr::constant("m"), Expr::constant("L"));
        let weight = mul(vec![m.clone(), l.clone(), l.clone()]);
        let cc = mul(vec![weight.clone(), cos(a.clone()), cos(b.clone())]);
        let ss = mul(vec![weight.clone(), sin(a.clone()), sin(b.clone())]);
        let g = Expr::constant("g");
        let sums = [
            add(vec![cc.clone(), -ss.clone()]),
            add(vec![cc.clone(), g.clone()]),
            add(vec![cc.clone(), -ss.clone(), g.clone()]),
        ];
        let alone: Vec<Expr> = sums.iter().map(simplify).collect();
        let shared: Vec<Expr> = with_simplify_memo(|| sums.iter().map(simplify).collect());
        assert_eq!(shared, alone);
        let by_hand = mul(vec![weight, cos(add(vec![a, b]))]);
        assert_eq!(alone[0], by_hand);
        assert_eq!(alone[1], sums[1]);
        assert_eq!(alone[2], add(vec![by_hand, g]));
    }
}
