//! Triples of components in one frame's unit vectors, and their products: the algebra
//! under both the rotations and the vectors that span frames.

use crate::symbolic::{add, mul, Expr};

/// Three components in one frame's unit vectors.
pub type Components = [Expr; 3];

/// The zero triple.
pub fn zero3() -> Components {
    [Expr::zero(), Expr::zero(), Expr::zero()]
}

/// `a × b` of two triples in the same frame.
pub fn cross3(a: &Components, b: &Components) -> Components {
    // `x*y - z*w` as one sum with the sign folded into the product, so that a long `w`
    // is multiplied out once, not once and then again to negate it.
    let minus = Expr::int(-1);
    let term = |x: &Expr, y: &Expr, z: &Expr, w: &Expr| {
        add([
            mul([x.clone(), y.clone()]),
            mul([minus.clone(), z.clone(), w.clone()]),
        ])
    };
    [
        term(&a[1], &b[2], &a[2], &b[1]),
        term(&a[2], &b[0], &a[0], &b[2]),
        term(&a[0], &b[1], &a[1], &b[0]),
    ]
}

/// `a · b` of two triples in the same frame.
pub fn dot3(a: &Components, b: &Components) -> Expr {
    add([&a[0] * &b[0], &a[1] * &b[1], &a[2] * &b[2]])
}

/// The number of terms in a triple: a measure of the work of multiplying it out.
pub fn size(c: &Components) -> usize {
    c.iter().map(|e| e.terms().len()).sum()
}
