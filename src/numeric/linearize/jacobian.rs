//! Small motions about a state: the exact state matrix of the equations of motion.
//!
//! The equations are a linear system `A(s) x = b(s)` in the unknowns `x` (the q'' and any
//! reactions), with `s` the inputs (constants, coordinates, rates, time). The state
//! variables `z` are every coordinate, then every rate; their time derivatives the rates,
//! then the q''. Then
//!
//! ```text
//! ∂x/∂z_j = A⁻¹ (∂b/∂z_j − (∂A/∂z_j) x).
//! ```
//!
//! The partial derivatives of `A` and `b` come from differentiating the compiled program
//! that evaluates them, in forward mode ([`crate::symbolic::forward`]): exact to rounding,
//! at the cost of a few evaluations, with no derivative expression ever built. (Taking
//! them symbolically multiplied the equations by the number of variables: the bicycle's
//! took seconds and hundreds of megabytes.)
//!
//! The mass, damping and stiffness matrices of [`SecondOrder`] are the partial derivatives
//! of equations with no reaction in them (Kane's) with respect to the q'', q' and q, taken
//! the same way.

use crate::equations::LinearSystem;
use crate::numeric::inputs::input_symbols;
use crate::numeric::linear::solve_linear;
use crate::numeric::system::describe_state;
use crate::numeric::SolveError;
use crate::problem::Problem;
use crate::symbolic::{Expr, Program, Symbol};
use nalgebra::{DMatrix, DVector};

/// The compiled system, ready to be differentiated at any state.
#[derive(Clone, Debug)]
pub struct Jacobian {
    /// The state variables' names as printed (`q1`, `q1'`).
    pub variables: Vec<String>,
    unknowns: usize,
    /// Reads the inputs of [`input_symbols`]; gives `A` row by row, then `b`.
    system: Program,
    /// The positions among the inputs of the coordinates, then the rates.
    directions: Vec<usize>,
    /// Each coordinate's q'' among the unknowns (none for a prescribed coordinate).
    accelerations: Vec<Option<usize>>,
}

/// The linearization at one state.
#[derive(Clone, Debug)]
pub struct StateMatrix {
    /// The unknowns `x` at the state (the q'' first).
    pub unknowns: Vec<f64>,
    /// `∂ż/∂z`, rows and columns in the order of the variables.
    pub a: DMatrix<f64>,
}

/// The name of a state variable as the command line writes it.
pub fn variable_name(symbol: &Symbol) -> String {
    match symbol {
        Symbol::Coord(name, order) | Symbol::Speed(name, order) => {
            format!("{name}{}", "'".repeat(*order as usize))
        }
        Symbol::Const(name) => name.to_string(),
        Symbol::Unknown(unknown) => unknown.to_string(),
        Symbol::Time => "t".into(),
        Symbol::UnitVector(frame, axis) => format!("{frame}.{axis}"),
        Symbol::Defined(d) => d.name().to_string(),
    }
}

/// The positions among the inputs of [`input_symbols`] of the coordinates, then the rates.
fn state_directions(problem: &Problem) -> Vec<usize> {
    let first = problem.constants.len();
    (first..first + 2 * problem.coordinates.len()).collect()
}

impl Jacobian {
    /// Compiles `system`, the equations of `problem`, for its state matrix.
    pub fn new(problem: &Problem, system: &LinearSystem) -> Jacobian {
        let n = problem.coordinates.len();
        let mut outputs: Vec<Expr> = system.a.iter().flatten().cloned().collect();
        outputs.extend(system.b.iter().cloned());
        let variables = (0..n)
            .map(|i| problem.coordinate_symbol(i, 0))
            .chain((0..n).map(|i| problem.coordinate_symbol(i, 1)))
            .map(|s| variable_name(&s))
            .collect();
        Jacobian {
            variables,
            unknowns: system.unknowns.len(),
            system: Program::compile(&input_symbols(problem), &outputs),
            directions: state_directions(problem),
            accelerations: (0..n)
                .map(|i| {
                    let symbol = problem.coordinate_symbol(i, 2);
                    system.unknowns.iter().position(|u| *u == symbol)
                })
                .collect(),
        }
    }

    /// The number of operations of one evaluation of the system.
    pub fn operation_count(&self) -> usize {
        self.system.operation_count()
    }

    /// The state matrix at the state given by the values of the inputs.
    ///
    /// # Errors
    /// A singular system or a value that is not finite, naming the state as `state`
    /// describes it.
    pub fn state_matrix(
        &self,
        inputs: &[f64],
        state: &dyn Fn() -> String,
    ) -> Result<StateMatrix, SolveError> {
        let n = self.unknowns;
        let m = self.directions.len();
        let d = self.system.run_with_derivatives(inputs, &self.directions);
        let not_finite = |what: &str| SolveError::NotFinite {
            state: state(),
            what: what.into(),
        };
        if d.values.iter().any(|x| !x.is_finite()) {
            return Err(not_finite("a coefficient of the equations"));
        }
        let a = DMatrix::from_row_slice(n, n, &d.values[..n * n]);
        let b = DVector::from_column_slice(&d.values[n * n..]);
        let singular = || SolveError::SingularSystem {
            state: state(),
            detail: "the equations do not determine the unknowns here".into(),
        };
        let x = solve_linear(&a, &b).ok_or_else(singular)?;
        if d.partials.iter().any(|x| !x.is_finite()) {
            return Err(not_finite("a partial derivative of the equations"));
        }
        // ∂b/∂z_j − (∂A/∂z_j) x for every j, as the columns of one right-hand side.
        let mut rhs = DMatrix::<f64>::zeros(n, m);
        for row in 0..n {
            for (j, value) in d.of(n * n + row).iter().enumerate() {
                rhs[(row, j)] = *value;
            }
            for column in 0..n {
                for (j, value) in d.of(row * n + column).iter().enumerate() {
                    rhs[(row, j)] -= value * x[column];
                }
            }
        }
        let dx = if n == 0 {
            DMatrix::zeros(0, m)
        } else {
            a.lu().solve(&rhs).ok_or_else(singular)?
        };
        // ż = (q', q''): the rates' rows pick the rates, the q''s' rows are rows of ∂x/∂z.
        let coordinates = self.accelerations.len();
        let mut jacobian = DMatrix::<f64>::zeros(m, m);
        for i in 0..coordinates {
            jacobian[(i, coordinates + i)] = 1.0;
            if let Some(k) = self.accelerations[i] {
                for j in 0..m {
                    // Added to zero, so that a −0 prints as 0.
                    jacobian[(coordinates + i, j)] += dx[(k, j)];
                }
            }
        }
        if jacobian.iter().any(|x| !x.is_finite()) {
            return Err(not_finite("the state matrix"));
        }
        Ok(StateMatrix {
            unknowns: x.iter().copied().collect(),
            a: jacobian,
        })
    }
}

/// The mass, damping and stiffness matrices `M δq'' + C δq' + K δq = 0` of equations
/// free of reactions, one per coordinate.
#[derive(Clone, Debug)]
pub struct SecondOrder {
    coordinates: usize,
    inputs: usize,
    /// Reads the inputs, then the q''; gives the rows.
    rows: Program,
    /// The positions among its inputs of the q'', the rates, then the coordinates.
    directions: Vec<usize>,
}

/// `M`, `C`, `K` at one state.
#[derive(Clone, Debug, PartialEq)]
pub struct Matrices {
    /// Mass matrix, ∂(equations)/∂q''.
    pub m: DMatrix<f64>,
    /// Damping (and gyroscopic) matrix, ∂/∂q'.
    pub c: DMatrix<f64>,
    /// Stiffness (and circulatory) matrix, ∂/∂q.
    pub k: DMatrix<f64>,
}

impl SecondOrder {
    /// Compiles `rows`, each `… = 0` and linear in the q'' with coefficients `−M` (as
    /// Kane's `F_r + F_r* = 0` are: the sign is turned so that `M` is the mass matrix).
    pub fn new(problem: &Problem, rows: &[Expr]) -> SecondOrder {
        let n = problem.coordinates.len();
        let mut inputs = input_symbols(problem);
        let count = inputs.len();
        inputs.extend((0..n).map(|i| problem.coordinate_symbol(i, 2)));
        let states = state_directions(problem);
        let directions = (count..count + n)
            .chain(states[n..].iter().copied())
            .chain(states[..n].iter().copied())
            .collect();
        SecondOrder {
            coordinates: n,
            inputs: count,
            rows: Program::compile(&inputs, rows),
            directions,
        }
    }

    /// `M`, `C`, `K` at the inputs' values, with the q'' there.
    pub fn at(&self, inputs: &[f64], accelerations: &[f64]) -> Matrices {
        let n = self.coordinates;
        let mut extended = inputs[..self.inputs].to_vec();
        extended.extend_from_slice(accelerations);
        let d = self.rows.run_with_derivatives(&extended, &self.directions);
        // Subtracted from zero, so that a −0 prints as 0.
        let block = |k: usize| DMatrix::from_fn(n, n, |r, c| 0.0 - d.of(r)[k * n + c]);
        Matrices {
            m: block(0),
            c: block(1),
            k: block(2),
        }
    }
}

/// The values of the inputs of `input_symbols`: constants, coordinates, rates, time.
pub fn input_values(problem: &Problem, t: f64, q: &[f64], rates: &[f64]) -> Vec<f64> {
    let mut inputs: Vec<f64> = problem.constants.iter().map(|c| c.value).collect();
    inputs.extend_from_slice(q);
    inputs.extend_from_slice(rates);
    inputs.push(t);
    inputs
}

/// A description of the state for messages.
pub fn state_text(problem: &Problem, t: f64, q: &[f64], rates: &[f64]) -> String {
    let names: Vec<String> = problem.coordinates.iter().map(|c| c.name.clone()).collect();
    describe_state(t, &names, q, rates)
}
