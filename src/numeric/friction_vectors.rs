//! The small vector arithmetic of the friction sites: a normal's sign, a direction along
//! a slip or a held force, lengths and dot products of component lists.

/// N as reported: its one component, signed; the magnitude of two.
pub(super) fn signed_normal(components: &[f64]) -> f64 {
    match components {
        [n] => *n,
        _ => norm(components),
    }
}

/// N's unit direction among its components; `held` where N is zero. With one component,
/// its sign (zero counts as positive, as the first guess).
pub(super) fn direction_of(components: &[f64], held: &[f64]) -> Vec<f64> {
    if let [n] = components {
        return vec![if *n < 0.0 { -1.0 } else { 1.0 }];
    }
    let size = norm(components);
    if size > 0.0 {
        components.iter().map(|c| c / size).collect()
    } else {
        held.to_vec()
    }
}

/// Whether two unit directions agree: exactly for a sign, to rounding for two components.
pub(super) fn same_direction(a: &[f64], b: &[f64]) -> bool {
    match (a, b) {
        ([x], [y]) => x == y,
        _ => a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-13),
    }
}

/// The first unit vector among `n` components, the first guess of N's direction.
pub(super) fn first_unit(n: usize) -> Vec<f64> {
    (0..n).map(|i| if i == 0 { 1.0 } else { 0.0 }).collect()
}

pub(super) fn norm(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

pub(super) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}
