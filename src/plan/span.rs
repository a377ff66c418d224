//! Rows as vectors of their coefficients: which chosen rows a left-out row combines, and
//! whether two rows say the same thing. The worked solution names them in its reasons.

/// The chosen rows (as indices of `chosen`, each its coefficients at every state) of which
/// `row` is a combination at `state`; empty when it is not one there (it follows from them
/// only on the unknowns of a block).
pub(super) fn combination_of(chosen: &[&[Vec<f64>]], row: &[Vec<f64>], state: usize) -> Vec<usize> {
    let target = nalgebra::DVector::from_column_slice(&row[state]);
    let columns: Vec<nalgebra::DVector<f64>> = chosen
        .iter()
        .map(|c| nalgebra::DVector::from_column_slice(&c[state]))
        .collect();
    if columns.is_empty() || target.norm() == 0.0 {
        return Vec::new();
    }
    let basis = nalgebra::DMatrix::from_columns(&columns);
    let Ok(weights) = basis.clone().svd(true, true).solve(&target, 1e-12) else {
        return Vec::new();
    };
    let scale = target.norm();
    if (&basis * &weights - &target).norm() > 1e-8 * scale {
        return Vec::new();
    }
    (0..columns.len())
        .filter(|&i| (weights[i] * columns[i].norm()).abs() > 1e-8 * scale)
        .collect()
}

/// Whether two rows' coefficients are multiples of each other at every state.
pub(super) fn parallel(a: &[Vec<f64>], b: &[Vec<f64>]) -> bool {
    a.iter().zip(b).all(|(a, b)| {
        let dot: f64 = a.iter().zip(b).map(|(x, y)| x * y).sum();
        let na = a.iter().map(|x| x * x).sum::<f64>().sqrt();
        let nb = b.iter().map(|x| x * x).sum::<f64>().sqrt();
        na > 0.0 && nb > 0.0 && (dot.abs() - na * nb).abs() <= 1e-9 * na * nb
    })
}
