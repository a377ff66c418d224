//! The inverse of a block of velocity-constraint coefficients too large to write out in
//! symbols (the Whipple bicycle's two contacts couple six dependent rates), as an
//! expression the numbers evaluate at each state: every entry is built from named minors,
//! each computed once, so the program stays a few hundred operations where the entries
//! multiplied out would run to pages.
//!
//! The columns with a number to pivot on (a rate with a unit coefficient, as an axle's
//! velocity has in a contact's rows) are eliminated first, exactly; what is left, the
//! Schur complement `S`, is inverted by its adjugate over its determinant, both expanded by
//! minors. No symbolic pivot is chosen, so no entry divides by something that vanishes at
//! some state unless `A_D` itself is singular there.

use crate::symbolic::{add, Expr, FastMap};

/// The most columns left after the numeric pivots that the minors may expand: `2ⁿ` row
/// sets by `2ⁿ` column sets at worst.
const LARGEST_REMAINDER: usize = 8;

/// `A⁻¹[s][k]` of the square matrix `a` (rows `k`, columns `s`), each entry a named
/// quantity (`prefix` keeps the names apart from any other), or `None` when the block left
/// after the numeric pivots is larger than `LARGEST_REMAINDER`.
pub fn inverse_by_minors(a: &[Vec<Expr>], prefix: &str) -> Option<Vec<Vec<Expr>>> {
    let n = a.len();
    let mut m: Vec<Vec<Expr>> = a.to_vec();
    // The row operations applied so far, as a matrix: `e · a = m`.
    let mut e: Vec<Vec<Expr>> = (0..n)
        .map(|i| (0..n).map(|j| Expr::int(i64::from(i == j))).collect())
        .collect();
    let mut pivot_row: Vec<Option<usize>> = vec![None; n];
    let mut used = vec![false; n];
    for col in 0..n {
        let is_pivot =
            |r: &usize| !used[*r] && m[*r][col].as_number().is_some_and(|x| !x.is_zero());
        let Some(p) = (0..n).find(is_pivot) else {
            continue;
        };
        used[p] = true;
        pivot_row[col] = Some(p);
        super::speeds::pivot_on(&mut m, &mut e, (p, col), &|_| false);
    }
    let rest_rows: Vec<usize> = (0..n).filter(|&r| !used[r]).collect();
    let rest_columns: Vec<usize> = (0..n).filter(|&c| pivot_row[c].is_none()).collect();
    if rest_rows.len() != rest_columns.len() || rest_rows.len() > LARGEST_REMAINDER {
        return None;
    }
    let name = |what: &str, value: Expr| Expr::defined(&format!("{prefix}.{what}"), value);
    let s: Vec<Vec<Expr>> = (rest_rows.iter().enumerate())
        .map(|(i, &r)| {
            (rest_columns.iter().enumerate())
                .map(|(j, &c)| name(&format!("S{i},{j}"), m[r][c].clone()))
                .collect()
        })
        .collect();
    let mut minors = Minors {
        s: &s,
        prefix,
        known: FastMap::default(),
    };
    let size = s.len();
    let all = (1u64 << size) - 1;
    let det = minors.det(all, all);
    // S⁻¹[j][i] = (−1)^(i+j) M_ij / det S.
    let s_inverse: Vec<Vec<Expr>> = (0..size)
        .map(|j| {
            (0..size)
                .map(|i| {
                    let minor = minors.det(all & !(1 << i), all & !(1 << j));
                    let signed = if (i + j) % 2 == 0 { minor } else { -minor };
                    name(&format!("Sinv{j},{i}"), &signed / &det)
                })
                .collect()
        })
        .collect();
    let mut inverse = vec![vec![Expr::zero(); n]; n];
    // x_C' = S⁻¹ (e b)_R': the columns without a numeric pivot.
    for (j, &c) in rest_columns.iter().enumerate() {
        for (k, slot) in inverse[c].iter_mut().enumerate() {
            let terms = (rest_rows.iter().enumerate()).map(|(i, &r)| &s_inverse[j][i] * &e[r][k]);
            *slot = name(&format!("inv{c},{k}"), add(terms));
        }
    }
    // x_c = (e b)_p − Σ_j m[p][j] x_j for a column pivoted on row p.
    for c in 0..n {
        let Some(p) = pivot_row[c] else { continue };
        for k in 0..n {
            let coupled = rest_columns
                .iter()
                .filter(|&&j| !m[p][j].is_zero())
                .map(|&j| -(&m[p][j] * &inverse[j][k]));
            let value = add(std::iter::once(e[p][k].clone()).chain(coupled));
            inverse[c][k] = name(&format!("inv{c},{k}"), value);
        }
    }
    Some(inverse)
}

/// The minors of `s`, each named once, by the sets of its rows and columns kept.
struct Minors<'a> {
    s: &'a [Vec<Expr>],
    prefix: &'a str,
    known: FastMap<(u64, u64), Expr>,
}

impl Minors<'_> {
    /// The determinant of the rows and columns of `s` in the bit sets `rows`, `columns`,
    /// expanded along its first row.
    fn det(&mut self, rows: u64, columns: u64) -> Expr {
        if rows == 0 {
            return Expr::one();
        }
        if let Some(known) = self.known.get(&(rows, columns)) {
            return known.clone();
        }
        let first = rows.trailing_zeros() as usize;
        let mut terms = Vec::new();
        let mut sign = 1;
        for j in (0..self.s.len()).filter(|j| columns & (1 << j) != 0) {
            let entry = &self.s[first][j];
            if !entry.is_zero() {
                let minor = self.det(rows & !(1 << first), columns & !(1 << j));
                let term = entry * &minor;
                terms.push(if sign > 0 { term } else { -term });
            }
            sign = -sign;
        }
        let value = Expr::defined(
            &format!("{}.M{rows:x},{columns:x}", self.prefix),
            add(terms),
        );
        self.known.insert((rows, columns), value.clone());
        value
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::{cos, eval, sin, Symbol, Values};

    #[test]
    fn matches_the_inverse_of_a_coupled_block_at_a_state() {
        // Two unit pivots, then a 2×2 remainder of trigonometric entries.
        let q = Expr::coord("q", 0);
        let (s, c) = (sin(q.clone()), cos(q.clone()));
        let a = vec![
            vec![Expr::one(), Expr::zero(), s.clone(), Expr::zero()],
            vec![Expr::zero(), Expr::one(), c.clone(), s.clone()],
            vec![Expr::one(), c.clone(), Expr::int(2), Expr::one()],
            vec![s.clone(), Expr::one(), c.clone(), Expr::int(3)],
        ];
        let inverse = inverse_by_minors(&a, "test").unwrap();
        let mut values = Values::new();
        values.set(Symbol::Coord("q".into(), 0), 0.7);
        let number = |x: &Expr| eval(x, &values);
        for (k, row) in inverse.iter().enumerate() {
            for l in 0..4 {
                // (A⁻¹ A)[k][l] = Σ_i A⁻¹[k][i] A[i][l] = δ_kl.
                let product: f64 = (row.iter().zip(&a))
                    .map(|(x, a_row)| number(x) * number(&a_row[l]))
                    .sum();
                let identity = if k == l { 1.0 } else { 0.0 };
                assert!((product - identity).abs() < 1e-12, "{k},{l}: {product}");
            }
        }
    }
}
