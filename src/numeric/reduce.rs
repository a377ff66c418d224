//! The state matrix of a constrained system in its independent variables, by the chain
//! rule through the constraints: exact Jacobians of the constraints (compiled from symbolic
//! derivatives) carry the derivatives of every q'' (with respect to every coordinate and
//! rate) over to the independent coordinates and rates.
//!
//! With `q_D(q_I)` from `Φ(q) = 0` and the dependent rates from `B(q) q' + β(q, t) = 0`:
//! `∂q/∂q_I = P` (identity on `I`, `−Φ_D⁻¹ Φ_I` on the dependent ones), `∂q'/∂u = S`
//! (identity on the independent rates, `−B_R⁻¹ B_U` on the dependent ones), and
//! `∂q'/∂q_I = E P` with `E = −B_R⁻¹ ∂(B q' + β)/∂q` on the dependent rates.

use crate::mechanics::{Model, RowOrigin};
use crate::symbolic::{linear_split, partial, time_derivative, Expr, Program, Symbol};
use nalgebra::DMatrix;

/// What the reduction needs of a model's constraints, compiled.
#[derive(Clone, Debug)]
pub struct Reducer {
    n: usize,
    /// Independent coordinates, in joint order.
    pub coordinates: Vec<usize>,
    /// Independent rates, in joint order.
    pub rates: Vec<usize>,
    dependent: Vec<usize>,
    dependent_rates: Vec<usize>,
    holonomic: usize,
    /// `∂Φ/∂q`, row by row.
    position: Program,
    velocity_rows: usize,
    /// `B` row by row, then `∂(B q' + β)/∂q` row by row.
    velocity: Program,
}

impl Reducer {
    /// Compiles the constraint Jacobians of `model` (none for an unconstrained one).
    pub fn new(model: &Model) -> Reducer {
        let problem = model.problem;
        let constraints = &model.constraints;
        let n = problem.coordinates.len();
        let inputs = super::inputs::input_symbols(problem);
        let q: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 0)).collect();
        let rates: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
        let coefficients = |e: &Expr| {
            linear_split(e, &rates)
                .map(|(c, _)| c)
                .unwrap_or_else(|_| vec![Expr::zero(); n])
        };
        let rows: Vec<_> = constraints
            .rows
            .iter()
            .filter(|r| !matches!(r.origin, RowOrigin::Prescribed(_)))
            .collect();
        let mut jacobian = Vec::new();
        let mut holonomic = 0;
        for row in rows.iter().filter(|r| r.position.is_some()) {
            let position = row.position.clone().unwrap_or_else(Expr::zero);
            jacobian.extend(coefficients(
                &time_derivative(&position).unwrap_or_else(|_| Expr::zero()),
            ));
            holonomic += 1;
        }
        let mut velocity = Vec::new();
        for row in &rows {
            velocity.extend(coefficients(&row.velocity));
        }
        for row in &rows {
            velocity.extend(
                q.iter()
                    .map(|s| partial(&row.velocity, s).unwrap_or_else(|_| Expr::zero())),
            );
        }
        let free = |i: &usize| problem.coordinates[*i].motion.is_none();
        Reducer {
            n,
            coordinates: (0..n)
                .filter(free)
                .filter(|i| !constraints.dependent.contains(i))
                .collect(),
            rates: (0..n)
                .filter(free)
                .filter(|i| !constraints.dependent_rates.contains(i))
                .collect(),
            dependent: constraints.dependent.clone(),
            dependent_rates: constraints.dependent_rates.clone(),
            holonomic,
            position: Program::compile(&inputs, &jacobian),
            velocity_rows: rows.len(),
            velocity: Program::compile(&inputs, &velocity),
        }
    }

    /// The dependent rates (in the order solved for) and the matrix `C` of
    /// `q'_D = C q'_U + …` over the independent rates `U`, at the state `inputs`.
    pub fn dependent_rate_map(&self, inputs: &[f64]) -> (Vec<usize>, DMatrix<f64>) {
        let n = self.n;
        let m = self.velocity_rows;
        if m == 0 || self.dependent_rates.is_empty() {
            return (Vec::new(), DMatrix::zeros(0, self.rates.len()));
        }
        let velocity = self.velocity.eval(inputs);
        let b = DMatrix::from_row_slice(m, n, &velocity[..m * n]);
        let b_r = select_columns(&b, &self.dependent_rates);
        let b_u = select_columns(&b, &self.rates);
        let c = pseudo_inverse(&b_r)
            .map(|inverse| -(inverse * b_u))
            .unwrap_or_else(|| DMatrix::zeros(self.dependent_rates.len(), self.rates.len()));
        (self.dependent_rates.clone(), c)
    }

    /// The state matrix in the independent coordinates then the independent rates, from
    /// the derivatives of every q'' with respect to every coordinate (`qdd_q`, n × n) and
    /// every rate (`qdd_v`), at an assembled state `inputs` (constants, q, q', t).
    pub fn state_matrix(
        &self,
        inputs: &[f64],
        qdd_q: &DMatrix<f64>,
        qdd_v: &DMatrix<f64>,
    ) -> DMatrix<f64> {
        let n = self.n;
        let (ni, nu) = (self.coordinates.len(), self.rates.len());
        let jacobian = self.position.eval(inputs);
        let velocity = self.velocity.eval(inputs);
        let (h, m) = (self.holonomic, self.velocity_rows);
        // P = ∂q/∂q_I.
        let mut p = DMatrix::zeros(n, ni);
        for (k, &c) in self.coordinates.iter().enumerate() {
            p[(c, k)] = 1.0;
        }
        if h > 0 && !self.dependent.is_empty() {
            let phi = DMatrix::from_row_slice(h, n, &jacobian);
            let phi_d = select_columns(&phi, &self.dependent);
            let phi_i = select_columns(&phi, &self.coordinates);
            if let Some(inverse) = pseudo_inverse(&phi_d) {
                let block = -(inverse * phi_i);
                for (r, &d) in self.dependent.iter().enumerate() {
                    for k in 0..ni {
                        p[(d, k)] = block[(r, k)];
                    }
                }
            }
        }
        // S = ∂q'/∂u and E = ∂q'/∂q (explicit).
        let mut s = DMatrix::zeros(n, nu);
        for (k, &c) in self.rates.iter().enumerate() {
            s[(c, k)] = 1.0;
        }
        let mut e = DMatrix::zeros(n, n);
        if m > 0 && !self.dependent_rates.is_empty() {
            let b = DMatrix::from_row_slice(m, n, &velocity[..m * n]);
            let psi_q = DMatrix::from_row_slice(m, n, &velocity[m * n..2 * m * n]);
            let b_r = select_columns(&b, &self.dependent_rates);
            let b_u = select_columns(&b, &self.rates);
            if let Some(inverse) = pseudo_inverse(&b_r) {
                let s_block = -(&inverse * b_u);
                let e_block = -(inverse * psi_q);
                for (r, &d) in self.dependent_rates.iter().enumerate() {
                    for k in 0..nu {
                        s[(d, k)] = s_block[(r, k)];
                    }
                    for k in 0..n {
                        e[(d, k)] = e_block[(r, k)];
                    }
                }
            }
        }
        let dv_dq = &e * &p;
        let qdd_qi = qdd_q * &p + qdd_v * &dv_dq;
        let qdd_u = qdd_v * &s;
        let mut a = DMatrix::zeros(ni + nu, ni + nu);
        for (r, &c) in self.coordinates.iter().enumerate() {
            for k in 0..ni {
                a[(r, k)] = dv_dq[(c, k)];
            }
            for k in 0..nu {
                a[(r, ni + k)] = s[(c, k)];
            }
        }
        for (r, &c) in self.rates.iter().enumerate() {
            for k in 0..ni {
                a[(ni + r, k)] = qdd_qi[(c, k)];
            }
            for k in 0..nu {
                a[(ni + r, ni + k)] = qdd_u[(c, k)];
            }
        }
        a
    }
}

fn select_columns(m: &DMatrix<f64>, columns: &[usize]) -> DMatrix<f64> {
    DMatrix::from_fn(m.nrows(), columns.len(), |r, c| m[(r, columns[c])])
}

/// The inverse of a square matrix, or the least-squares pseudo-inverse of any other.
fn pseudo_inverse(m: &DMatrix<f64>) -> Option<DMatrix<f64>> {
    if m.nrows() == m.ncols() {
        if let Some(inverse) = m.clone().try_inverse() {
            return Some(inverse);
        }
    }
    m.clone().pseudo_inverse(1e-12).ok()
}
