//! The square root of a sum that is the square of a sum, up to its sign:
//! `a² + x₁² + x₂² − 2a x₁ + 2a x₂ − 2x₁x₂ = (a − x₁ + x₂)²`, as the length of a spring
//! along a line is written before the worked solution gives it its sign.

use super::build::{add, mul};
use super::expr::Expr;
use super::simplify::{simplify, square_root_of_square};

/// The most terms squared that are tried (2^(n−1) choices of sign).
const MOST_SQUARES: usize = 6;

/// `M` when `e` simplifies to `M²` for a sum `M` of terms whose squares are terms of `e`
/// (each cross term `2 Mᵢ Mⱼ` among the rest): the square root up to its sign. `None`
/// otherwise, and for a single term (see `square_root_of_square`).
pub fn square_root_of_sum(e: &Expr) -> Option<Expr> {
    let e = simplify(e);
    let terms = e.terms();
    if terms.len() < 3 {
        return None;
    }
    let roots: Vec<Expr> = terms.iter().filter_map(square_root_of_square).collect();
    // n squares and their n(n − 1)/2 cross terms: every term of the sum.
    let n = roots.len();
    if !(2..=MOST_SQUARES).contains(&n) || n + n * (n - 1) / 2 != terms.len() {
        return None;
    }
    (0..1u32 << (n - 1)).find_map(|signs| {
        let m =
            add(roots
                .iter()
                .enumerate()
                .map(|(i, r)| match i > 0 && signs >> (i - 1) & 1 == 1 {
                    true => mul([Expr::int(-1), r.clone()]),
                    false => r.clone(),
                }));
        simplify(&(&(&m * &m) - &e)).is_zero().then_some(m)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_of_a_sum_multiplied_out_gives_back_the_sum() {
        let (a, x1, x2) = (
            Expr::constant("a"),
            Expr::coord("x1", 0),
            Expr::coord("x2", 0),
        );
        let m = add([a.clone(), mul([Expr::int(-1), x1.clone()]), x2.clone()]);
        let square = simplify(&(&m * &m));
        let root = square_root_of_sum(&square).expect("a perfect square");
        assert!(simplify(&(&root - &m)).is_zero() || simplify(&(&root + &m)).is_zero());
        // a² + x₁² + x₁ x₂ is no square.
        let not = add([&a * &a, &x1 * &x1, &x1 * &x2]);
        assert_eq!(square_root_of_sum(&not), None);
    }
}
