//! Declared generalized speeds (step 1): the kinematic differential equations
//! `u = W(q) q'`, their inverse `q' = W⁻¹(q) u`, and the rewriting of the rates in an
//! expression as speeds, so that the kinematics (step 4) are written with `u` and `u'`.
//!
//! `W⁻¹` is found symbolically block by block (the speeds that share coordinates): by the
//! adjugate up to 3×3 (Euler-angle kinematics), by elimination beyond.

use super::error::MechanicsError;
use crate::problem::Problem;
use crate::symbolic::{add, linear_split, simplify, time_derivative, Expr, Symbol};

/// The kinematic differential equations of a problem with declared speeds.
#[derive(Clone, Debug)]
pub struct Speeds {
    /// The speeds `u`, in declaration order.
    pub speeds: Vec<Symbol>,
    /// The coordinates' rates `q'`.
    pub rates: Vec<Symbol>,
    /// `W` of `u = W(q) q'`, row `r` for speed `r`.
    pub w: Vec<Vec<Expr>>,
    /// `W⁻¹`, row `s` for rate `s`: `q'_s = Σ_r W⁻¹[s][r] u_r`.
    pub inverse: Vec<Vec<Expr>>,
}

impl Speeds {
    /// The speeds of `problem`, or `None` when its speeds are its rates.
    ///
    /// # Errors
    /// When a speed is not linear in the rates (validation rules that out).
    pub fn of(problem: &Problem) -> Result<Option<Speeds>, MechanicsError> {
        if !problem.has_speeds() {
            return Ok(None);
        }
        let n = problem.coordinates.len();
        let rates: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
        let speeds = problem.speed_symbols(1);
        let mut w = Vec::with_capacity(n);
        for speed in &problem.speeds {
            let (row, _) = linear_split(&speed.equals, &rates).map_err(|e| MechanicsError {
                path: format!("{}.equals", speed.path),
                message: e.to_string(),
                hint: Some("a speed is linear in the rates".into()),
            })?;
            w.push(row.iter().map(simplify).collect::<Vec<_>>());
        }
        let inverse = inverse(&w);
        Ok(Some(Speeds {
            speeds,
            rates,
            w,
            inverse,
        }))
    }

    /// `q'_s` written with the speeds: `Σ_r W⁻¹[s][r] u_r`, for every `s`.
    pub fn rates_as_speeds(&self) -> Vec<Expr> {
        self.inverse
            .iter()
            .map(|row| {
                add(row
                    .iter()
                    .zip(&self.speeds)
                    .map(|(c, u)| c * &Expr::sym(u.clone())))
            })
            .collect()
    }

    /// `e` with its rates written as speeds. An expression linear in the rates whose
    /// coefficients are a multiple of a row of `W` becomes that multiple of the speed
    /// directly (`ω·b₁` becomes `u₁` without a trigonometric identity); otherwise each rate
    /// is replaced by its row of `W⁻¹ u` and the result simplified.
    pub fn to_speeds(&self, e: &Expr) -> Expr {
        if !self.rates.iter().any(|r| e.contains(r)) {
            return e.clone();
        }
        // Not linear in the rates: every rate replaced by its expression in the speeds.
        let substituted = || {
            let replaced = self.rates_as_speeds();
            simplify(&crate::symbolic::substitute(e, &|s| {
                self.rates
                    .iter()
                    .position(|r| r == s)
                    .map(|i| replaced[i].clone())
            }))
        };
        let Ok((c, rest)) = linear_split(e, &self.rates) else {
            return substituted();
        };
        if c.iter().any(|c| self.rates.iter().any(|r| c.contains(r))) {
            return substituted();
        }
        let c: Vec<Expr> = c.iter().map(simplify).collect();
        if let Some((r, factor)) = self.multiple_of_row(&c) {
            return simplify(&(&rest + &(&factor * &Expr::sym(self.speeds[r].clone()))));
        }
        let terms = (0..self.speeds.len()).map(|r| {
            let coefficient = simplify(&add(c
                .iter()
                .zip(&self.inverse)
                .map(|(cs, row)| cs * &row[r])));
            &coefficient * &Expr::sym(self.speeds[r].clone())
        });
        simplify(&(&rest + &add(terms)))
    }

    /// `(r, k)` when `c = k W_r` for one row `r`.
    fn multiple_of_row(&self, c: &[Expr]) -> Option<(usize, Expr)> {
        for (r, row) in self.w.iter().enumerate() {
            let Some(s) = row.iter().position(|x| !x.is_zero()) else {
                continue;
            };
            if c[s].is_zero() {
                continue;
            }
            let proportional = (0..c.len())
                .all(|j| simplify(&(&(&c[j] * &row[s]) - &(&c[s] * &row[j]))).is_zero());
            if proportional {
                return Some((r, simplify(&(&c[s] / &row[s]))));
            }
        }
        None
    }

    /// d/dt of `e`, its rates then written as speeds.
    ///
    /// # Errors
    /// As for [`time_derivative`].
    pub fn dt(&self, e: &Expr) -> Result<Expr, crate::symbolic::DiffError> {
        Ok(self.to_speeds(&time_derivative(e)?))
    }
}

/// `W⁻¹`, block by block: for a square matrix of rows `r` and columns `s`, the
/// inverse indexed `[s][r]`.
pub(crate) fn inverse(w: &[Vec<Expr>]) -> Vec<Vec<Expr>> {
    inverse_within(w, None).unwrap_or_default()
}

/// As [`inverse`], or `None` once an entry formed on the way has more than `largest`
/// operations: the elimination of a large block of trigonometric entries grows without
/// bound, and is given up early rather than simplified for minutes.
pub(crate) fn inverse_within(w: &[Vec<Expr>], largest: Option<usize>) -> Option<Vec<Vec<Expr>>> {
    let n = w.len();
    let mut out = vec![vec![Expr::zero(); n]; n];
    for (rows, columns) in blocks(w) {
        let block: Vec<Vec<Expr>> = rows
            .iter()
            .map(|&r| columns.iter().map(|&s| w[r][s].clone()).collect())
            .collect();
        let inv = if block.len() <= 3 {
            adjugate_inverse(&block)
        } else {
            eliminate(&block, largest)?
        };
        // W⁻¹ maps speeds (rows of W) to rates (columns of W).
        for (i, &s) in columns.iter().enumerate() {
            for (k, &r) in rows.iter().enumerate() {
                out[s][r] = inv[i][k].clone();
            }
        }
    }
    Some(out)
}

/// The size of the largest block [`inverse`] solves together.
pub(crate) fn largest_block(w: &[Vec<Expr>]) -> usize {
    blocks(w)
        .iter()
        .map(|(rows, _)| rows.len())
        .max()
        .unwrap_or(0)
}

/// The square blocks of `w`: rows and columns connected through nonzero entries.
fn blocks(w: &[Vec<Expr>]) -> Vec<(Vec<usize>, Vec<usize>)> {
    let n = w.len();
    let mut row_seen = vec![false; n];
    let mut out = Vec::new();
    for start in 0..n {
        if row_seen[start] {
            continue;
        }
        let (mut rows, mut columns) = (vec![start], Vec::new());
        row_seen[start] = true;
        let mut k = 0;
        while k < rows.len() {
            let r = rows[k];
            for (s, entry) in w[r].iter().enumerate() {
                if !entry.is_zero() && !columns.contains(&s) {
                    columns.push(s);
                    for (r2, seen) in row_seen.iter_mut().enumerate() {
                        if !*seen && !w[r2][s].is_zero() {
                            *seen = true;
                            rows.push(r2);
                        }
                    }
                }
            }
            k += 1;
        }
        rows.sort_unstable();
        columns.sort_unstable();
        if rows.len() != columns.len() {
            // Singular (validation rules it out at the initial state): elimination over all.
            return vec![((0..n).collect(), (0..n).collect())];
        }
        out.push((rows, columns));
    }
    out
}

fn det(m: &[Vec<Expr>]) -> Expr {
    match m.len() {
        1 => m[0][0].clone(),
        2 => &(&m[0][0] * &m[1][1]) - &(&m[0][1] * &m[1][0]),
        _ => add((0..3).map(|j| {
            let minor = &(&m[1][(j + 1) % 3] * &m[2][(j + 2) % 3])
                - &(&m[1][(j + 2) % 3] * &m[2][(j + 1) % 3]);
            &m[0][j] * &minor
        })),
    }
}

/// The inverse of a 1×1, 2×2 or 3×3 matrix: the adjugate over the determinant.
fn adjugate_inverse(m: &[Vec<Expr>]) -> Vec<Vec<Expr>> {
    let n = m.len();
    let d = simplify(&det(m));
    let cofactor = |i: usize, j: usize| -> Expr {
        match n {
            1 => Expr::one(),
            2 => {
                let e = m[1 - i][1 - j].clone();
                if (i + j).is_multiple_of(2) {
                    e
                } else {
                    -e
                }
            }
            _ => {
                let (r1, r2) = ((i + 1) % 3, (i + 2) % 3);
                let (c1, c2) = ((j + 1) % 3, (j + 2) % 3);
                &(&m[r1][c1] * &m[r2][c2]) - &(&m[r1][c2] * &m[r2][c1])
            }
        }
    };
    (0..n)
        .map(|i| (0..n).map(|j| simplify(&(&cofactor(j, i) / &d))).collect())
        .collect()
}

/// The inverse by Gauss–Jordan elimination, preferring numeric pivots, then short ones.
/// `None` once an entry passes `largest` operations.
fn eliminate(m: &[Vec<Expr>], largest: Option<usize>) -> Option<Vec<Vec<Expr>>> {
    let too_long = |e: &Expr| largest.is_some_and(|cap| e.operation_count_capped(cap) > cap);
    let n = m.len();
    let mut a: Vec<Vec<Expr>> = m.to_vec();
    let mut inv: Vec<Vec<Expr>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| if i == j { Expr::one() } else { Expr::zero() })
                .collect()
        })
        .collect();
    for col in 0..n {
        let pivot = (col..n)
            .filter(|&r| !a[r][col].is_zero())
            .min_by_key(|&r| (a[r][col].as_number().is_none(), a[r][col].terms().len()));
        let Some(p) = pivot else { continue };
        a.swap(col, p);
        inv.swap(col, p);
        if !pivot_on(&mut a, &mut inv, (col, col), &too_long) {
            return None;
        }
    }
    Some(inv)
}

/// One Gauss–Jordan step on `a` and the row operations `e` applied alongside: row `p`
/// scaled to a unit at `col`, then `col` cleared from every other row. `false`, the step
/// left unfinished, as soon as an entry is `too_long`.
pub(crate) fn pivot_on(
    a: &mut [Vec<Expr>],
    e: &mut [Vec<Expr>],
    (p, col): (usize, usize),
    too_long: &dyn Fn(&Expr) -> bool,
) -> bool {
    let n = a.len();
    let lead = a[p][col].clone();
    for j in 0..n {
        a[p][j] = simplify(&(&a[p][j] / &lead));
        e[p][j] = simplify(&(&e[p][j] / &lead));
    }
    for r in 0..n {
        if r == p || a[r][col].is_zero() {
            continue;
        }
        let factor = a[r][col].clone();
        for j in 0..n {
            a[r][j] = simplify(&(&a[r][j] - &(&factor * &a[p][j])));
            e[r][j] = simplify(&(&e[r][j] - &(&factor * &e[p][j])));
            if too_long(&a[r][j]) || too_long(&e[r][j]) {
                return false;
            }
        }
    }
    true
}
