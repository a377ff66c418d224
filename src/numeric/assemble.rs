//! Assembly: the dependent coordinates from the position constraints (Newton's method, the
//! independent ones held fixed), then the dependent rates from the velocity constraints,
//! and the prescribed coordinates from their motion. The simulation assembles at every
//! step, so the constraints hold to the Newton tolerance all along (coordinate partitioning).

use super::SolveError;
use crate::mechanics::{Model, RowOrigin};
use crate::symbolic::{linear_split, time_derivative, Expr, Program, Symbol};
use nalgebra::{DMatrix, DVector};

/// Newton stops when every position residual is below this (metres or radians).
const POSITION_TOLERANCE: f64 = 1e-13;
/// And gives up after this many iterations.
const MAX_ITERATIONS: usize = 60;

/// The compiled constraints of a model.
#[derive(Clone, Debug)]
pub struct Assembly {
    coordinates: usize,
    /// Prescribed coordinates with a program of `[f, f', f'']` in `t`.
    prescribed: Vec<usize>,
    motion: Program,
    dependent: Vec<usize>,
    /// The coordinates whose rates may be solved for (not prescribed).
    free: Vec<usize>,
    /// The rates solved for now: the chosen ones at first, others where those become
    /// ill-conditioned along a motion.
    current_rates: std::cell::RefCell<Vec<usize>>,
    /// The holonomic rows' names, for messages.
    position_names: Vec<String>,
    /// `Φ` then the Jacobian `∂Φ/∂q` row by row.
    position: Program,
    /// The velocity rows (prescribed ones excepted): `B` row by row, then `β`.
    velocity: Program,
    velocity_rows: usize,
    /// Each rolling contact's name and a program of its tilt.
    tilt_names: Vec<String>,
    tilts: Program,
}

impl Assembly {
    /// Compiles the constraints of `model`; `None` when it has none.
    pub fn new(model: &Model) -> Option<Assembly> {
        let constraints = &model.constraints;
        if constraints.is_empty() {
            return None;
        }
        let problem = model.problem;
        let n = problem.coordinates.len();
        let inputs = super::inputs::input_symbols(problem);
        let rates: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
        let split = |e: &Expr| -> (Vec<Expr>, Expr) {
            linear_split(e, &rates).unwrap_or_else(|_| (vec![Expr::zero(); n], e.clone()))
        };
        let free_rows: Vec<_> = constraints
            .rows
            .iter()
            .filter(|r| !matches!(r.origin, RowOrigin::Prescribed(_)))
            .collect();
        let mut position_names = Vec::new();
        let (mut phi, mut jacobian) = (Vec::new(), Vec::new());
        for row in free_rows.iter().filter(|r| r.position.is_some()) {
            let position = row.position.clone().unwrap_or_else(Expr::zero);
            let rate = time_derivative(&position).unwrap_or_else(|_| Expr::zero());
            jacobian.extend(split(&rate).0);
            phi.push(position);
            position_names.push(row.name.clone());
        }
        phi.extend(jacobian);
        let (mut b, mut beta) = (Vec::new(), Vec::new());
        for row in &free_rows {
            let (coefficients, rest) = split(&row.velocity);
            b.extend(coefficients);
            beta.push(rest);
        }
        b.extend(beta);
        let mut motion = Vec::new();
        for &p in &constraints.prescribed {
            let f = problem.coordinates[p]
                .motion
                .clone()
                .unwrap_or_else(Expr::zero);
            let df = time_derivative(&f).unwrap_or_else(|_| Expr::zero());
            let ddf = time_derivative(&df).unwrap_or_else(|_| Expr::zero());
            motion.extend([f, df, ddf]);
        }
        Some(Assembly {
            coordinates: n,
            prescribed: constraints.prescribed.clone(),
            motion: Program::compile(&inputs, &motion),
            dependent: constraints.dependent.clone(),
            current_rates: std::cell::RefCell::new(constraints.dependent_rates.clone()),
            free: (0..n)
                .filter(|&i| problem.coordinates[i].motion.is_none())
                .collect(),
            position_names,
            position: Program::compile(&inputs, &phi),
            velocity: Program::compile(&inputs, &b),
            velocity_rows: free_rows.len(),
            tilt_names: constraints.tilts.iter().map(|(n, _)| n.clone()).collect(),
            tilts: Program::compile(
                &inputs,
                &constraints
                    .tilts
                    .iter()
                    .map(|(_, e)| e.clone())
                    .collect::<Vec<_>>(),
            ),
        })
    }

    fn inputs(constants: &[f64], t: f64, q: &[f64], rates: &[f64]) -> Vec<f64> {
        let mut inputs = constants.to_vec();
        inputs.extend_from_slice(q);
        inputs.extend_from_slice(rates);
        inputs.push(t);
        inputs
    }

    /// Sets the prescribed coordinates and rates at `t`, solves the dependent coordinates
    /// (starting from the values in `q`) and then the dependent rates.
    ///
    /// # Errors
    /// [`SolveError::Assembly`] naming the constraint with the largest residual when
    /// Newton's method does not converge, or when the dependent rates are undetermined.
    pub fn assemble(
        &self,
        constants: &[f64],
        t: f64,
        q: &mut [f64],
        rates: &mut [f64],
    ) -> Result<(), SolveError> {
        let n = self.coordinates;
        let values = self.motion.eval(&Self::inputs(constants, t, q, rates));
        for (k, &p) in self.prescribed.iter().enumerate() {
            q[p] = values[3 * k];
            rates[p] = values[3 * k + 1];
        }
        let h = self.position_names.len();
        let mut worst = (0.0f64, 0usize);
        for _ in 0..=MAX_ITERATIONS {
            let out = self.position.eval(&Self::inputs(constants, t, q, rates));
            worst = (0.0, 0);
            for (i, r) in out[..h].iter().enumerate() {
                if r.is_nan() || r.abs() > worst.0 {
                    worst = (r.abs(), i);
                }
            }
            if worst.0 <= POSITION_TOLERANCE || h == 0 {
                break;
            }
            let jacobian = DMatrix::from_fn(h, self.dependent.len(), |r, c| {
                out[h + r * n + self.dependent[c]]
            });
            let residual = DVector::from_iterator(h, out[..h].iter().map(|r| -r));
            let Some(step) = least_squares(&jacobian, &residual) else {
                break;
            };
            for (c, &d) in self.dependent.iter().enumerate() {
                q[d] += step[c];
            }
        }
        if worst.0.is_nan() || worst.0 > POSITION_TOLERANCE * 1e3 {
            return Err(SolveError::Assembly {
                constraint: self
                    .position_names
                    .get(worst.1)
                    .cloned()
                    .unwrap_or_default(),
                residual: worst.0,
            });
        }
        let tilts = self.tilts.eval(&Self::inputs(constants, t, q, rates));
        if let Some(k) = tilts.iter().position(|s| s.is_nan() || s.abs() <= 1e-9) {
            return Err(SolveError::FlatDisc {
                constraint: self.tilt_names[k].clone(),
            });
        }
        let m = self.velocity_rows;
        if m == 0 {
            return Ok(());
        }
        let out = self.velocity.eval(&Self::inputs(constants, t, q, rates));
        let columns = self.rate_columns(&out, m, rates);
        let columns = &columns;
        let matrix = DMatrix::from_fn(m, columns.len(), |r, c| out[r * n + columns[c]]);
        let rhs = DVector::from_fn(m, |r, _| {
            let known: f64 = (0..n)
                .filter(|i| !columns.contains(i))
                .map(|i| out[r * n + i] * rates[i])
                .sum();
            -(known + out[m * n + r])
        });
        let Some(x) = least_squares(&matrix, &rhs) else {
            return Err(SolveError::Assembly {
                constraint: "the velocity constraints".into(),
                residual: f64::NAN,
            });
        };
        for (c, &d) in columns.iter().enumerate() {
            rates[d] = x[c];
        }
        Ok(())
    }

    /// The rates to solve the velocity rows for: the chosen ones, unless their block of `B`
    /// is nearly singular here (a knife edge whose blade turns through N.y cannot give y'),
    /// and then the best pivots at this state. The other rates keep their values, so
    /// which rates are dependent may change along a motion.
    fn rate_columns(&self, out: &[f64], m: usize, rates: &[f64]) -> Vec<usize> {
        let n = self.coordinates;
        // Rates that do not meet the constraints yet (a state just given, its dependent
        // rates placeholders) are the user's independent ones: keep the chosen set unless
        // it cannot give the rest at all, or the given rates would be overwritten.
        let consistent = (0..m).all(|r| {
            let row = &out[r * n..(r + 1) * n];
            let residual: f64 =
                row.iter().zip(rates).map(|(c, v)| c * v).sum::<f64>() + out[m * n + r];
            let scale = row
                .iter()
                .zip(rates)
                .fold(out[m * n + r].abs(), |a, (c, v)| a.max((c * v).abs()));
            residual.abs() <= 1e-9 * scale.max(1.0)
        });
        let smallest_singular = |columns: &[usize]| -> f64 {
            let block = DMatrix::from_fn(m, columns.len(), |r, c| out[r * n + columns[c]]);
            let singular = block.svd(false, false).singular_values;
            if singular.len() < m {
                return 0.0;
            }
            singular.iter().fold(f64::INFINITY, |a, s| a.min(*s))
        };
        let current = self.current_rates.borrow().clone();
        let best = best_pivots(out, n, m, &self.free);
        if best.len() == m && best != current {
            // Hysteresis: change only when the best block is ten times better conditioned,
            // so that two nearly equal choices do not alternate from step to step.
            let (now, better) = (smallest_singular(&current), smallest_singular(&best));
            if now < 0.1 * better && (consistent || now <= 1e-9 * better) {
                *self.current_rates.borrow_mut() = best.clone();
                return best;
            }
        }
        current
    }

    /// The largest residual of the position and velocity constraints at a state.
    pub fn drift(&self, constants: &[f64], t: f64, q: &[f64], rates: &[f64]) -> f64 {
        let n = self.coordinates;
        let h = self.position_names.len();
        let inputs = Self::inputs(constants, t, q, rates);
        let position = self.position.eval(&inputs);
        let velocity = self.velocity.eval(&inputs);
        let m = self.velocity_rows;
        let worst_velocity = (0..m)
            .map(|r| {
                let s: f64 = (0..n).map(|i| velocity[r * n + i] * rates[i]).sum();
                (s + velocity[m * n + r]).abs()
            })
            .fold(0.0f64, f64::max);
        position[..h]
            .iter()
            .map(|r| r.abs())
            .fold(worst_velocity, f64::max)
    }
}

/// The columns of `B` (m rows of n, row-major in `out`) that Gaussian elimination with
/// complete pivoting over `free` picks, in coordinate order.
fn best_pivots(out: &[f64], n: usize, m: usize, free: &[usize]) -> Vec<usize> {
    let rows: Vec<Vec<f64>> = (0..m).map(|r| out[r * n..(r + 1) * n].to_vec()).collect();
    let mut chosen = crate::mechanics::pick(&rows, &[], free, &vec![1.0; n]).unwrap_or_default();
    chosen.sort_unstable();
    chosen
}

/// The least-squares (or exact) solution of `a x = b` by SVD; `None` when it is not finite.
fn least_squares(a: &DMatrix<f64>, b: &DVector<f64>) -> Option<DVector<f64>> {
    if a.ncols() == 0 {
        return Some(DVector::zeros(0));
    }
    let svd = a.clone().svd(true, true);
    let largest = svd.singular_values.iter().fold(0.0f64, |m, s| m.max(*s));
    let x = svd.solve(b, largest * 1e-12).ok()?;
    x.iter().all(|v| v.is_finite()).then_some(x)
}
