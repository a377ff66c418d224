//! The declared speeds' kinematic differential equations, compiled: how the q'' follow
//! from the speeds' rates.

use super::inputs::state_symbols;
use super::linear::solve_linear;
use crate::problem::Problem;
use crate::symbolic::{Expr, Program, Symbol};
use nalgebra::{DMatrix, DVector};

/// The kinematic differential equations compiled: from the state, the speeds `u = W q'`,
/// the entries of `W` and `Ẇ q'`, so that `q'' = W⁻¹ (u' − Ẇ q')`.
#[derive(Clone, Debug)]
pub struct SpeedProgram {
    /// The number of coordinates (and of speeds).
    pub n: usize,
    names: Vec<String>,
    program: Program,
}

impl SpeedProgram {
    /// The speeds' program, `None` when the problem declares no speeds.
    pub fn new(problem: &Problem) -> Option<SpeedProgram> {
        if !problem.has_speeds() {
            return None;
        }
        let n = problem.coordinates.len();
        let rates: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
        let mut outputs: Vec<Expr> = problem.speeds.iter().map(|s| s.equals.clone()).collect();
        let mut derivatives = Vec::with_capacity(n);
        for speed in &problem.speeds {
            let (row, _) = crate::symbolic::linear_split(&speed.equals, &rates).ok()?;
            outputs.extend(row);
            let d = crate::symbolic::time_derivative(&speed.equals).ok()?;
            derivatives.push(crate::symbolic::substitute(&d, &|s| {
                matches!(s, Symbol::Coord(_, 2)).then(Expr::zero)
            }));
        }
        outputs.extend(derivatives);
        Some(SpeedProgram {
            n,
            names: problem.speeds.iter().map(|s| s.name.clone()).collect(),
            program: Program::compile(&state_symbols(problem), &outputs),
        })
    }

    /// `[u, W row-major, Ẇ q']` at the state of `inputs`.
    pub fn run(&self, inputs: &[f64]) -> Vec<f64> {
        let mut scratch = Vec::new();
        let mut out = vec![0.0; self.n * (self.n + 2)];
        self.program.run(inputs, &mut scratch, &mut out);
        out
    }

    /// Each speed's name, `u` and `u' = W q'' + Ẇ q'`, at the state whose `run` gave `values`.
    pub fn rates_of_speeds(
        &self,
        values: &[f64],
        accelerations: &[f64],
    ) -> Vec<(String, f64, f64)> {
        let n = self.n;
        (0..n)
            .map(|r| {
                let w_row = &values[n + r * n..n + (r + 1) * n];
                let du = w_row
                    .iter()
                    .zip(accelerations)
                    .map(|(w, a)| w * a)
                    .sum::<f64>()
                    + values[n + n * n + r];
                (self.names[r].clone(), values[r], du)
            })
            .collect()
    }

    /// The q'' from the speeds' rates `du` at the state whose `run` gave `values`.
    pub fn accelerations(&self, values: &[f64], du: &[f64]) -> Option<Vec<f64>> {
        let n = self.n;
        let w = DMatrix::from_row_slice(n, n, &values[n..n + n * n]);
        let rhs = DVector::from_iterator(n, (0..n).map(|r| du[r] - values[n + n * n + r]));
        solve_linear(&w, &rhs).map(|x| x.iter().copied().collect())
    }
}
