//! The eigen-analysis of a state matrix: eigenvalues ([`super::hqr`]), eigenvectors
//! (inverse iteration in complex arithmetic) and the modes of vibration.

use nalgebra::{Complex, DMatrix, DVector};

/// Real and imaginary parts smaller than this times the largest |λ| are round-off and
/// are shown as 0: a repeated eigenvalue of a Jordan block (an ignorable coordinate, a
/// free translation) is only found to about the square root of the machine precision.
pub const ROUND_OFF: f64 = 1e-7;

/// Two real parts within this (relative) are equal when sorting.
pub const TIE: f64 = 1e-9;

/// One eigenvalue with its eigenvector.
#[derive(Clone, Debug, PartialEq)]
pub struct Eigen {
    /// The eigenvalue λ, in 1/s.
    pub value: Complex<f64>,
    /// The eigenvector, in the order of the variables, scaled to length 1.
    pub vector: DVector<Complex<f64>>,
}

/// A mode of vibration: one complex-conjugate pair of eigenvalues.
#[derive(Clone, Debug, PartialEq)]
pub struct Mode {
    /// The eigenvalue with a positive imaginary part.
    pub value: Complex<f64>,
    /// |λ|/2π, in Hz.
    pub natural_frequency_hz: f64,
    /// Im λ/2π, in Hz.
    pub damped_frequency_hz: f64,
    /// −Re λ/|λ|.
    pub damping_ratio: f64,
    /// The eigenvector's coordinate part, scaled so that its largest component is 1.
    pub shape: Shape,
}

/// A mode shape.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// Every coordinate moves in phase or in opposition: one number per coordinate.
    Real(Vec<f64>),
    /// Magnitude and phase (rad) per coordinate.
    Complex(Vec<(f64, f64)>),
}

/// The eigenvalues and eigenvectors of `a`, sorted by real part (equal within [`TIE`]),
/// then by imaginary part; `None` when the iteration does not converge.
pub fn eigen(a: &DMatrix<f64>) -> Option<Vec<Eigen>> {
    let mut values = super::hqr::eigenvalues(a)?;
    let scale = values.iter().map(|v| v.norm()).fold(0.0, f64::max);
    let snap = |x: f64| if x.abs() <= ROUND_OFF * scale { 0.0 } else { x };
    for v in &mut values {
        *v = Complex::new(snap(v.re), snap(v.im));
    }
    sort(&mut values);
    let scale = scale.max(a.amax()).max(f64::MIN_POSITIVE);
    Some(
        values
            .into_iter()
            .map(|value| Eigen {
                value,
                vector: eigenvector(a, value, scale),
            })
            .collect(),
    )
}

/// Sorts by real part ascending; real parts equal within `TIE` (relative) by imaginary
/// part ascending.
pub fn sort(values: &mut [Complex<f64>]) {
    values.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
    let mut start = 0;
    while start < values.len() {
        let first = values[start].re;
        let mut end = start + 1;
        while end < values.len()
            && (values[end].re - first).abs() <= TIE * first.abs().max(values[end].re.abs())
        {
            end += 1;
        }
        values[start..end].sort_by(|a, b| a.im.total_cmp(&b.im));
        start = end;
    }
}

/// An eigenvector for `value` by inverse iteration, shifted a little off the eigenvalue
/// so that the complex LU does not break down.
fn eigenvector(a: &DMatrix<f64>, value: Complex<f64>, scale: f64) -> DVector<Complex<f64>> {
    let m = a.nrows();
    let shift = value + Complex::new(1e-10 * scale, 0.0);
    let shifted = DMatrix::from_fn(m, m, |i, j| {
        Complex::new(a[(i, j)], 0.0)
            - if i == j {
                shift
            } else {
                Complex::new(0.0, 0.0)
            }
    });
    let lu = shifted.lu();
    // A start that is not orthogonal to any eigenvector in practice, and deterministic.
    let mut v = DVector::from_fn(m, |i, _| {
        Complex::new(1.0 + 0.1 * i as f64, 0.05 * i as f64)
    });
    for _ in 0..3 {
        match lu.solve(&v) {
            Some(next) if next.iter().all(|x| x.re.is_finite() && x.im.is_finite()) => {
                let norm = next.norm();
                if norm == 0.0 {
                    break;
                }
                v = next.unscale(norm);
            }
            _ => break,
        }
    }
    v
}

/// The modes: one per eigenvalue with a positive imaginary part, in the order of the
/// eigenvalues; the shape is the first `coordinates` components of the eigenvector.
pub fn modes(eigen: &[Eigen], coordinates: usize) -> Vec<Mode> {
    eigen
        .iter()
        .filter(|e| e.value.im > 0.0)
        .map(|e| {
            let magnitude = e.value.norm();
            Mode {
                value: e.value,
                natural_frequency_hz: magnitude / std::f64::consts::TAU,
                damped_frequency_hz: e.value.im / std::f64::consts::TAU,
                damping_ratio: clean(-e.value.re / magnitude),
                shape: shape(&e.vector, coordinates),
            }
        })
        .collect()
}

/// No negative zero: it reads as a sign error.
fn clean(x: f64) -> f64 {
    if x == 0.0 {
        0.0
    } else {
        x
    }
}

fn shape(vector: &DVector<Complex<f64>>, coordinates: usize) -> Shape {
    let part: Vec<Complex<f64>> = vector.iter().take(coordinates).copied().collect();
    let Some(largest) = part
        .iter()
        .copied()
        .reduce(|best, x| {
            if x.norm() > best.norm() * (1.0 + 1e-12) {
                x
            } else {
                best
            }
        })
        .filter(|x| x.norm() > 0.0)
    else {
        return Shape::Real(vec![0.0; part.len()]);
    };
    let scaled: Vec<Complex<f64>> = part.iter().map(|x| x / largest).collect();
    // A shape is real when every component is in phase or in opposition with the largest.
    if scaled
        .iter()
        .all(|x| x.im.abs() <= 1e-8 * x.norm().max(1e-8))
    {
        // Components tied with the largest within round-off stay within ±1.
        Shape::Real(
            scaled
                .iter()
                .map(|x| clean(snap_small(x.re.clamp(-1.0, 1.0))))
                .collect(),
        )
    } else {
        Shape::Complex(
            scaled
                .iter()
                .map(|x| {
                    (
                        snap_small(x.norm().min(1.0)),
                        clean(if snap_small(x.norm()) == 0.0 {
                            0.0
                        } else {
                            phase(*x)
                        }),
                    )
                })
                .collect(),
        )
    }
}

/// The phase of a component in (−π, π]; one in opposition within round-off is π, not
/// −π from an imaginary part of −0 or −1e−17 that another order of the same sums rounds
/// to +0.
fn phase(x: Complex<f64>) -> f64 {
    if x.im.abs() <= 1e-14 * x.norm() && x.re < 0.0 {
        std::f64::consts::PI
    } else {
        x.arg()
    }
}

/// Components of a unit-scaled shape below round-off are 0.
fn snap_small(x: f64) -> f64 {
    if x.abs() < 1e-12 {
        0.0
    } else {
        x
    }
}

/// Whether every eigenvalue has a real part at most `tolerance` times the largest |λ|.
pub fn is_stable(eigen: &[Eigen], tolerance: f64) -> bool {
    let scale = eigen.iter().map(|e| e.value.norm()).fold(0.0, f64::max);
    eigen.iter().all(|e| e.value.re <= tolerance * scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn values(a: &DMatrix<f64>) -> Vec<Complex<f64>> {
        eigen(a).unwrap().into_iter().map(|e| e.value).collect()
    }

    #[test]
    fn harmonic_oscillator() {
        // x'' = -4 x: λ = ±2i.
        let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -4.0, 0.0]);
        assert_eq!(
            values(&a),
            vec![Complex::new(0.0, -2.0), Complex::new(0.0, 2.0)]
        );
    }

    #[test]
    fn damped_oscillator_and_real_roots() {
        // x'' + 2 x' + 5 x = 0: λ = -1 ± 2i; x'' + 5 x' + 6 x = 0: λ = -3, -2.
        let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -5.0, -2.0]);
        let v = values(&a);
        assert!((v[0] - Complex::new(-1.0, -2.0)).norm() < 1e-12, "{v:?}");
        assert!((v[1] - Complex::new(-1.0, 2.0)).norm() < 1e-12, "{v:?}");
        let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -6.0, -5.0]);
        let v = values(&a);
        assert!(
            (v[0].re + 3.0).abs() < 1e-12 && (v[1].re + 2.0).abs() < 1e-12,
            "{v:?}"
        );
    }

    #[test]
    fn eigenvectors_satisfy_the_equation() {
        let a = DMatrix::from_row_slice(
            4,
            4,
            &[
                0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, -2.0, 1.0, -0.1, 0.0, 1.0, -2.0, 0.0, -0.1,
            ],
        );
        let ac = a.map(|x| Complex::new(x, 0.0));
        for e in eigen(&a).unwrap() {
            let residual = &ac * &e.vector - e.vector.scale(1.0).map(|x| x * e.value);
            assert!(residual.norm() < 1e-8, "{e:?}");
        }
    }

    #[test]
    fn sorting_ties_by_imaginary_part() {
        let mut v = vec![
            Complex::new(1.0, 0.0),
            Complex::new(-1.0, 3.0),
            Complex::new(-1.0 + 1e-12, -3.0),
        ];
        sort(&mut v);
        assert_eq!(v[0].im, -3.0);
        assert_eq!(v[1].im, 3.0);
        assert_eq!(v[2].re, 1.0);
    }
}
