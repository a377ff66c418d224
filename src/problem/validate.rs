//! The checks that depend on the constants' values: masses not negative (zero only with
//! no inertia, a massless body), inertias physical,
//! axes not zero, nothing infinite. They run while reading and again after `--set`.

use super::expressions::ConstantValues;
use super::json::{key_path, Diagnostics};
use super::model::{Inertia, VectorExpr};
use crate::symbolic::{fixed, Expr};
use nalgebra::{Matrix3, SymmetricEigen};

/// The value of `e` if finite; records an error when it is not (`None` also when it
/// cannot be judged because a constant it names had its own error).
pub fn finite(
    e: &Expr,
    values: &ConstantValues,
    path: &str,
    diag: &mut Diagnostics,
) -> Option<f64> {
    let value = values.eval(e)?;
    if value.is_finite() {
        return Some(value);
    }
    diag.hint(
        path,
        format!(
            "`{e}` evaluates to {} with the constants' values",
            fixed(value)
        ),
        "look for a division by zero, or a square root or logarithm of a negative number",
    );
    None
}

/// The mass: finite and not negative (zero for a massless body: a light link or collar).
pub fn mass(e: &Expr, values: &ConstantValues, path: &str, diag: &mut Diagnostics) {
    if let Some(m) = finite(e, values, path, diag) {
        if m < 0.0 {
            diag.hint(
                path,
                format!("the mass must not be negative; `{e}` is {}", fixed(m)),
                "a particle has a positive mass; a light link or collar has mass 0",
            );
        }
    }
}

/// A massless body has no inertia either: mass 0 with a nonzero inertia is not a body.
/// (A positive mass with zero inertia is a particle, and stays allowed.)
pub fn massless_inertia(
    mass: &Expr,
    inertia: &Inertia,
    values: &ConstantValues,
    path: &str,
    diag: &mut Diagnostics,
) {
    if values.eval(mass) != Some(0.0) {
        return;
    }
    let components: Vec<&Expr> = match inertia {
        Inertia::Planar(e) => vec![e],
        Inertia::Spatial(m) => m.iter().flatten().collect(),
    };
    let nonzero = components
        .iter()
        .any(|e| values.eval(e).is_some_and(|v| v != 0.0));
    if nonzero {
        diag.hint(
            path,
            format!("the body has mass `{mass}` = 0 but a nonzero inertia"),
            "a massless body (a light link, collar or pulley) has inertia 0: omit `inertia`, or give the body its mass",
        );
    }
}

/// Every coefficient of `v` finite.
pub fn vector(v: &VectorExpr, values: &ConstantValues, path: &str, diag: &mut Diagnostics) {
    for (_, _, c) in &v.terms {
        finite(c, values, path, diag);
    }
}

/// An axis: finite and not zero. The frames of its terms are already known to be
/// aligned with one another, so components add by axis letter.
pub fn axis(v: &VectorExpr, values: &ConstantValues, path: &str, diag: &mut Diagnostics) {
    let mut sum = [0.0f64; 3];
    for (_, axis, c) in &v.terms {
        match finite(c, values, path, diag) {
            Some(value) => sum[usize::from(*axis).min(2)] += value,
            None => return,
        }
    }
    let length = sum.iter().map(|x| x * x).sum::<f64>().sqrt();
    if length == 0.0 || !length.is_normal() {
        // Named by its key: a joint's `axis`, a contact's `normal`.
        let key = path.rsplit('.').next().unwrap_or("axis");
        diag.hint(
            path,
            format!("the {key} is the zero vector"),
            "give a direction such as N.z",
        );
    }
}

const SPATIAL_KEYS: [[&str; 3]; 3] = [["xx", "xy", "zx"], ["xy", "yy", "yz"], ["zx", "yz", "zz"]];

/// The central inertia: finite, and physical (2D: not negative; 3D: principal moments
/// not negative and each at most the sum of the other two).
pub fn inertia(inertia: &Inertia, values: &ConstantValues, path: &str, diag: &mut Diagnostics) {
    match inertia {
        Inertia::Planar(e) => {
            if let Some(i) = finite(e, values, path, diag) {
                if i < 0.0 {
                    diag.hint(
                        path,
                        format!(
                            "the moment of inertia must not be negative; `{e}` is {}",
                            fixed(i)
                        ),
                        "use 0 for a particle",
                    );
                }
            }
        }
        Inertia::Spatial(m) => {
            let mut numbers = Matrix3::zeros();
            let mut complete = true;
            for (r, row) in m.iter().enumerate() {
                for (c, e) in row.iter().enumerate() {
                    // Each product of inertia appears twice; judge it once.
                    let value = if c < r {
                        Some(numbers[(c, r)])
                    } else {
                        finite(e, values, &key_path(path, SPATIAL_KEYS[r][c]), diag)
                    };
                    match value {
                        Some(v) => numbers[(r, c)] = v,
                        None => complete = false,
                    }
                }
            }
            if complete {
                principal_moments(&numbers, path, diag);
            }
        }
    }
}

fn principal_moments(matrix: &Matrix3<f64>, path: &str, diag: &mut Diagnostics) {
    let mut moments: Vec<f64> = SymmetricEigen::new(*matrix)
        .eigenvalues
        .iter()
        .copied()
        .collect();
    moments.sort_by(f64::total_cmp);
    let scale = moments.iter().fold(0.0f64, |a, m| a.max(m.abs()));
    // Round-off in the eigenvalues is relative to the largest moment.
    let tolerance = 1e-9 * scale;
    let shown: Vec<String> = moments.iter().map(|m| fixed(*m)).collect();
    if moments[0] < -tolerance {
        diag.hint(
            path,
            format!(
                "the inertia is not physical: its principal moments are {}, and one is negative",
                shown.join(", ")
            ),
            "check the signs; `xy`, `yz`, `zx` are tensor elements (minus the products of inertia)",
        );
    } else if moments[2] > moments[0] + moments[1] + tolerance {
        diag.hint(
            path,
            format!(
                "the inertia is not physical: its principal moments {} break the triangle inequality ({} > {} + {})",
                shown.join(", "),
                shown[2],
                shown[0],
                shown[1]
            ),
            "no rigid body has one principal moment larger than the sum of the other two",
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spatial(xx: f64, yy: f64, zz: f64, xy: f64) -> Inertia {
        let n = Expr::real;
        let zero = Expr::zero;
        Inertia::Spatial([
            [n(xx), n(xy), zero()],
            [n(xy), n(yy), zero()],
            [zero(), zero(), n(zz)],
        ])
    }

    fn errors(inertia_value: &Inertia) -> Vec<String> {
        let mut diag = Diagnostics::default();
        inertia(
            inertia_value,
            &ConstantValues::default(),
            "bodies.A.inertia",
            &mut diag,
        );
        diag.errors.into_iter().map(|e| e.message).collect()
    }

    #[test]
    fn physical_inertias_pass() {
        // A thin rod along x: moments 0, I, I; the triangle holds with equality.
        assert!(errors(&spatial(0.0, 1.0, 1.0, 0.0)).is_empty());
        // A thin plate in the xy plane: Izz = Ixx + Iyy, again equality.
        assert!(errors(&spatial(1.0, 2.0, 3.0, 0.0)).is_empty());
        assert!(errors(&Inertia::Planar(Expr::zero())).is_empty());
    }

    #[test]
    fn unphysical_inertias_fail() {
        assert!(errors(&spatial(1.0, 1.0, 3.0, 0.0))[0].contains("triangle"));
        assert!(errors(&spatial(-1.0, 1.0, 1.0, 0.0))[0].contains("negative"));
        // Diagonal fine, but the product makes a principal moment 1 - 2 = -1.
        assert!(errors(&spatial(1.0, 1.0, 1.5, 2.0))[0].contains("negative"));
        assert!(errors(&Inertia::Planar(Expr::int(-1)))[0].contains("negative"));
    }

    #[test]
    fn masses_and_axes() {
        let values = ConstantValues::default();
        let mut diag = Diagnostics::default();
        mass(&Expr::int(-1), &values, "m", &mut diag);
        mass(&Expr::int(0), &values, "m", &mut diag);
        mass(&Expr::int(2), &values, "m", &mut diag);
        let zero_axis = VectorExpr::default();
        axis(&zero_axis, &values, "a", &mut diag);
        let messages: Vec<&str> = diag.errors.iter().map(|e| e.message.as_str()).collect();
        assert_eq!(messages.len(), 2, "{messages:?}");
        assert!(messages[0].contains("negative") && messages[1].contains("zero"));
    }

    #[test]
    fn a_massless_body_has_no_inertia() {
        let values = ConstantValues::default();
        let check = |m: i64, inertia: &Inertia| {
            let mut diag = Diagnostics::default();
            massless_inertia(
                &Expr::int(m),
                inertia,
                &values,
                "bodies.A.inertia",
                &mut diag,
            );
            diag.errors.len()
        };
        assert_eq!(check(0, &Inertia::Planar(Expr::zero())), 0);
        assert_eq!(check(0, &spatial(0.0, 0.0, 0.0, 0.0)), 0);
        assert_eq!(check(0, &Inertia::Planar(Expr::int(1))), 1);
        assert_eq!(check(0, &spatial(0.0, 0.0, 0.0, 0.5)), 1);
        // A particle: positive mass, no inertia.
        assert_eq!(check(2, &Inertia::Planar(Expr::zero())), 0);
    }
}
