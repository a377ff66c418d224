//! The eigenvalues of a general real matrix: balancing, reduction to Hessenberg form by
//! stabilized elimination, then the shifted QR iteration with Francis double steps (the
//! EISPACK `balanc`, `elmhes`, `hqr` sequence, as in Numerical Recipes §11.5–11.6).
//!
//! nalgebra's real Schur form does not converge on some of the state matrices met here
//! (a spinning rigid body with an ignorable angle), so the classic algorithm is used.

// The loops index rows and columns together, as the algorithm is written.
#![allow(clippy::needless_range_loop)]

use nalgebra::{Complex, DMatrix};

/// Most QR iterations for one eigenvalue before giving up.
const MAX_ITERATIONS: usize = 60;

/// The eigenvalues of `a`, a complex pair as `re − i·im` then `re + i·im`; `None` when the
/// iteration does not converge or a value is not finite.
pub fn eigenvalues(a: &DMatrix<f64>) -> Option<Vec<Complex<f64>>> {
    let n = a.nrows();
    // 1-based, as the algorithm is written, to keep its index arithmetic recognizable.
    let mut h = vec![vec![0.0; n + 1]; n + 1];
    for i in 0..n {
        for j in 0..n {
            h[i + 1][j + 1] = a[(i, j)];
        }
    }
    if h.iter().flatten().any(|x| !x.is_finite()) {
        return None;
    }
    balance(&mut h, n);
    hessenberg(&mut h, n);
    let values = hqr(&mut h, n)?;
    values
        .iter()
        .all(|v| v.re.is_finite() && v.im.is_finite())
        .then_some(values)
}

/// Scales rows and columns by powers of 2 (exact similarity transforms) so that each
/// row and its column have comparable norms.
fn balance(a: &mut [Vec<f64>], n: usize) {
    const RADIX: f64 = 2.0;
    let square = RADIX * RADIX;
    let mut done = false;
    while !done {
        done = true;
        for i in 1..=n {
            let (mut r, mut c) = (0.0, 0.0);
            for j in 1..=n {
                if j != i {
                    c += a[j][i].abs();
                    r += a[i][j].abs();
                }
            }
            if c != 0.0 && r != 0.0 {
                let mut g = r / RADIX;
                let mut f = 1.0;
                let s = c + r;
                while c < g {
                    f *= RADIX;
                    c *= square;
                }
                g = r * RADIX;
                while c > g {
                    f /= RADIX;
                    c /= square;
                }
                if (c + r) / f < 0.95 * s {
                    done = false;
                    let g = 1.0 / f;
                    for j in 1..=n {
                        a[i][j] *= g;
                    }
                    for row in a.iter_mut().skip(1) {
                        row[i] *= f;
                    }
                }
            }
        }
    }
}

/// Reduces to upper Hessenberg form by elimination with pivoting; the entries below the
/// subdiagonal are set to zero.
fn hessenberg(a: &mut [Vec<f64>], n: usize) {
    for m in 2..n {
        let mut x = 0.0f64;
        let mut pivot = m;
        for j in m..=n {
            if a[j][m - 1].abs() > x.abs() {
                x = a[j][m - 1];
                pivot = j;
            }
        }
        if pivot != m {
            for j in (m - 1)..=n {
                let t = a[pivot][j];
                a[pivot][j] = a[m][j];
                a[m][j] = t;
            }
            for row in a.iter_mut().skip(1) {
                row.swap(pivot, m);
            }
        }
        if x != 0.0 {
            for i in (m + 1)..=n {
                let mut y = a[i][m - 1];
                if y != 0.0 {
                    y /= x;
                    a[i][m - 1] = y;
                    for j in m..=n {
                        a[i][j] -= y * a[m][j];
                    }
                    for j in 1..=n {
                        a[j][m] += y * a[j][i];
                    }
                }
            }
        }
    }
    for (i, row) in a.iter_mut().enumerate().skip(1) {
        for x in row.iter_mut().take(i.saturating_sub(1)).skip(1) {
            *x = 0.0;
        }
    }
}

fn sign(a: f64, b: f64) -> f64 {
    if b >= 0.0 {
        a.abs()
    } else {
        -a.abs()
    }
}

/// The eigenvalues of an upper Hessenberg matrix (destroyed).
// A numerical recipe port (EISPACK's hqr, as in Numerical Recipes §11.6), kept whole.
#[allow(clippy::many_single_char_names, clippy::too_many_lines)]
fn hqr(a: &mut [Vec<f64>], n: usize) -> Option<Vec<Complex<f64>>> {
    let mut wr = vec![0.0; n + 1];
    let mut wi = vec![0.0; n + 1];
    let mut norm = 0.0;
    for i in 1..=n {
        for j in i.saturating_sub(1).max(1)..=n {
            norm += a[i][j].abs();
        }
    }
    let mut nn = n;
    let mut t = 0.0;
    let (mut p, mut q, mut r): (f64, f64, f64);
    while nn >= 1 {
        let mut its = 0;
        loop {
            let mut l = nn;
            while l >= 2 {
                let mut s = a[l - 1][l - 1].abs() + a[l][l].abs();
                if s == 0.0 {
                    s = norm;
                }
                if a[l][l - 1].abs() + s == s {
                    a[l][l - 1] = 0.0;
                    break;
                }
                l -= 1;
            }
            let mut x = a[nn][nn];
            if l == nn {
                wr[nn] = x + t;
                wi[nn] = 0.0;
                nn -= 1;
            } else {
                let mut y = a[nn - 1][nn - 1];
                let mut w = a[nn][nn - 1] * a[nn - 1][nn];
                if l == nn - 1 {
                    p = 0.5 * (y - x);
                    q = p * p + w;
                    let mut z = q.abs().sqrt();
                    x += t;
                    if q >= 0.0 {
                        z = p + sign(z, p);
                        wr[nn - 1] = x + z;
                        wr[nn] = x + z;
                        if z != 0.0 {
                            wr[nn] = x - w / z;
                        }
                        wi[nn - 1] = 0.0;
                        wi[nn] = 0.0;
                    } else {
                        wr[nn - 1] = x + p;
                        wr[nn] = x + p;
                        wi[nn - 1] = -z;
                        wi[nn] = z;
                    }
                    nn = nn.saturating_sub(2);
                } else {
                    if its == MAX_ITERATIONS {
                        return None;
                    }
                    if its % 10 == 0 && its > 0 {
                        // An exceptional shift.
                        t += x;
                        for i in 1..=nn {
                            a[i][i] -= x;
                        }
                        let s = a[nn][nn - 1].abs() + a[nn - 1][nn - 2].abs();
                        x = 0.75 * s;
                        y = x;
                        w = -0.4375 * s * s;
                    }
                    its += 1;
                    let mut m = nn - 2;
                    let mut z;
                    loop {
                        z = a[m][m];
                        r = x - z;
                        let s = y - z;
                        p = (r * s - w) / a[m + 1][m] + a[m][m + 1];
                        q = a[m + 1][m + 1] - z - r - s;
                        r = a[m + 2][m + 1];
                        let s = p.abs() + q.abs() + r.abs();
                        p /= s;
                        q /= s;
                        r /= s;
                        if m == l {
                            break;
                        }
                        let u = a[m][m - 1].abs() * (q.abs() + r.abs());
                        let v = p.abs() * (a[m - 1][m - 1].abs() + z.abs() + a[m + 1][m + 1].abs());
                        if u + v == v {
                            break;
                        }
                        m -= 1;
                    }
                    for i in (m + 2)..=nn {
                        a[i][i - 2] = 0.0;
                        if i != m + 2 {
                            a[i][i - 3] = 0.0;
                        }
                    }
                    let mut k = m;
                    while k < nn {
                        if k != m {
                            p = a[k][k - 1];
                            q = a[k + 1][k - 1];
                            r = 0.0;
                            if k != nn - 1 {
                                r = a[k + 2][k - 1];
                            }
                            x = p.abs() + q.abs() + r.abs();
                            if x != 0.0 {
                                p /= x;
                                q /= x;
                                r /= x;
                            }
                        }
                        let s = sign((p * p + q * q + r * r).sqrt(), p);
                        if s != 0.0 {
                            if k == m {
                                if l != m {
                                    a[k][k - 1] = -a[k][k - 1];
                                }
                            } else {
                                a[k][k - 1] = -s * x;
                            }
                            p += s;
                            x = p / s;
                            y = q / s;
                            z = r / s;
                            q /= p;
                            r /= p;
                            for j in k..=nn {
                                p = a[k][j] + q * a[k + 1][j];
                                if k != nn - 1 {
                                    p += r * a[k + 2][j];
                                    a[k + 2][j] -= p * z;
                                }
                                a[k + 1][j] -= p * y;
                                a[k][j] -= p * x;
                            }
                            let last = nn.min(k + 3);
                            for i in l..=last {
                                p = x * a[i][k] + y * a[i][k + 1];
                                if k != nn - 1 {
                                    p += z * a[i][k + 2];
                                    a[i][k + 2] -= p * r;
                                }
                                a[i][k + 1] -= p * q;
                                a[i][k] -= p;
                            }
                        }
                        k += 1;
                    }
                }
            }
            if nn < 2 || l + 1 >= nn {
                break;
            }
        }
    }
    Some((1..=n).map(|i| Complex::new(wr[i], wi[i])).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sorted(mut v: Vec<Complex<f64>>) -> Vec<(f64, f64)> {
        v.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
        v.into_iter().map(|c| (c.re, c.im)).collect()
    }

    #[test]
    fn companion_matrix_of_known_roots() {
        // (λ − 1)(λ − 2)(λ² + 2λ + 5): roots 1, 2, −1 ± 2i.
        // λ⁴ − λ³ − λ² − 11λ + 10... expanded: (λ² − 3λ + 2)(λ² + 2λ + 5)
        // = λ⁴ − λ³ + λ² − 11λ + 10.
        let a = DMatrix::from_row_slice(
            4,
            4,
            &[
                1.0, -1.0, 11.0, -10.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0,
            ],
        );
        let v = sorted(eigenvalues(&a).unwrap());
        let expected = [(-1.0, -2.0), (-1.0, 2.0), (1.0, 0.0), (2.0, 0.0)];
        for (got, want) in v.iter().zip(expected) {
            assert!(
                (got.0 - want.0).abs() < 1e-10 && (got.1 - want.1).abs() < 1e-10,
                "{v:?}"
            );
        }
    }

    #[test]
    fn zero_and_nilpotent_blocks() {
        let a = DMatrix::from_row_slice(3, 3, &[0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
        assert_eq!(sorted(eigenvalues(&a).unwrap()), vec![(0.0, 0.0); 3]);
        assert_eq!(eigenvalues(&DMatrix::zeros(0, 0)).unwrap(), vec![]);
        assert_eq!(
            sorted(eigenvalues(&DMatrix::from_element(1, 1, 3.0)).unwrap()),
            vec![(3.0, 0.0)]
        );
    }
}
