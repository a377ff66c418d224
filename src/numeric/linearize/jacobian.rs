//! Small motions about a state: the exact state matrix of the equations of motion.
//!
//! The equations are a linear system `A(s) x = b(s)` in the unknowns `x` (the q'' and any
//! reactions), with `s` the inputs (constants, coordinates, rates, time). The state
//! variables `z` are some of the inputs, and each one's time derivative is an expression
//! `f(s, x)`. Then
//!
//! ```text
//! ∂x/∂z_j = A⁻¹ (∂b/∂z_j − (∂A/∂z_j) x),     ∂ż_i/∂z_j = ∂f_i/∂z_j + Σ_k ∂f_i/∂x_k ∂x_k/∂z_j.
//! ```
//!
//! Every partial derivative is taken symbolically, compiled once and evaluated at any
//! state: no finite differences. For a system without constraints `z` is every coordinate,
//! then every rate, and `f` is the rates, then the q''; a constrained system brings its own
//! list of independent variables and their derivatives ([`LinearModel`]).
//!
//! The mass, damping and stiffness matrices of [`SecondOrder`] are the partial derivatives
//! of equations with no reaction in them (Kane's) with respect to the q'', q' and q.

use crate::equations::LinearSystem;
use crate::mechanics::MechanicsError;
use crate::numeric::evaluate::{input_symbols, solve_linear};
use crate::numeric::system::describe_state;
use crate::numeric::SolveError;
use crate::problem::Problem;
use crate::symbolic::compile::Program;
use crate::symbolic::diff::{partial, DiffError};
use crate::symbolic::linear::linear_split;
use crate::symbolic::{add, Expr, Symbol};
use nalgebra::{DMatrix, DVector};

/// What to linearize: a linear system in some unknowns, the state variables among its
/// inputs, and the time derivative of each state variable.
#[derive(Clone, Debug)]
pub struct LinearModel {
    /// The inputs of `a`, `b` and `derivatives`, in the order values are given.
    pub inputs: Vec<Symbol>,
    /// The unknowns `x`.
    pub unknowns: Vec<Symbol>,
    /// Row-major coefficients of `A x = b`.
    pub a: Vec<Vec<Expr>>,
    /// The right-hand sides.
    pub b: Vec<Expr>,
    /// The state variables `z`, each one of `inputs`.
    pub variables: Vec<Symbol>,
    /// `dz/dt`, one per variable, in the inputs and the unknowns.
    pub derivatives: Vec<Expr>,
}

impl LinearModel {
    /// A system without constraints: the variables are every coordinate, then every rate,
    /// in the order the joints name them; their derivatives the rates, then the q''.
    pub fn unconstrained(problem: &Problem, system: &LinearSystem) -> LinearModel {
        let n = problem.coordinates.len();
        let symbol = |order: u8| (0..n).map(move |i| problem.coordinate_symbol(i, order));
        LinearModel {
            inputs: input_symbols(problem),
            unknowns: system.unknowns.clone(),
            a: system.a.clone(),
            b: system.b.clone(),
            variables: symbol(0).chain(symbol(1)).collect(),
            derivatives: symbol(1).chain(symbol(2)).map(Expr::sym).collect(),
        }
    }
}

/// A partial derivative that is not identically zero: which variable, which entry, and
/// where its value is among the outputs of the compiled program.
#[derive(Clone, Copy, Debug)]
struct Entry {
    variable: usize,
    row: usize,
    column: usize,
    output: usize,
}

/// The compiled system and its partial derivatives.
#[derive(Clone, Debug)]
pub struct Jacobian {
    /// The state variables' names as printed (`q1`, `q1'`).
    pub variables: Vec<String>,
    unknowns: usize,
    system: Program,
    /// Reads the inputs, then the unknowns; gives the entries below, each at its `output`.
    partials: Program,
    d_a: Vec<Entry>,
    d_b: Vec<Entry>,
    d_f_by_z: Vec<Entry>,
    d_f_by_x: Vec<Entry>,
}

/// The linearization at one state.
#[derive(Clone, Debug)]
pub struct StateMatrix {
    /// The unknowns `x` at the state (the q'' first).
    pub unknowns: Vec<f64>,
    /// `∂ż/∂z`, rows and columns in the order of the variables.
    pub a: DMatrix<f64>,
}

fn not_differentiable(e: DiffError) -> MechanicsError {
    MechanicsError {
        path: "loads".into(),
        message: format!("the equations cannot be linearized: {e}"),
        hint: Some(
            "linearizing needs loads with a derivative; replace min/max by a smooth expression"
                .into(),
        ),
    }
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

impl Jacobian {
    /// Differentiates the system with respect to every variable and compiles the result.
    ///
    /// # Errors
    /// When an entry has no derivative (`min`, `max` of something that changes).
    pub fn new(model: &LinearModel) -> Result<Jacobian, MechanicsError> {
        let d = |e: &Expr, z: &Symbol| partial(e, z).map_err(not_differentiable);
        let mut outputs: Vec<Expr> = Vec::new();
        let (mut d_a, mut d_b, mut d_f_by_z, mut d_f_by_x) = (vec![], vec![], vec![], vec![]);
        for (variable, z) in model.variables.iter().enumerate() {
            for (row, entries) in model.a.iter().enumerate() {
                for (column, e) in entries.iter().enumerate() {
                    push(&mut outputs, &mut d_a, d(e, z)?, variable, row, column);
                }
            }
            for (row, e) in model.b.iter().enumerate() {
                push(&mut outputs, &mut d_b, d(e, z)?, variable, row, 0);
            }
            for (row, e) in model.derivatives.iter().enumerate() {
                push(&mut outputs, &mut d_f_by_z, d(e, z)?, variable, row, 0);
            }
        }
        for (k, x) in model.unknowns.iter().enumerate() {
            for (row, e) in model.derivatives.iter().enumerate() {
                push(&mut outputs, &mut d_f_by_x, d(e, x)?, k, row, 0);
            }
        }
        let mut system_outputs: Vec<Expr> = model.a.iter().flatten().cloned().collect();
        system_outputs.extend(model.b.iter().cloned());
        let mut extended = model.inputs.clone();
        extended.extend(model.unknowns.iter().cloned());
        Ok(Jacobian {
            variables: model.variables.iter().map(variable_name).collect(),
            unknowns: model.unknowns.len(),
            system: Program::compile(&model.inputs, &system_outputs),
            partials: Program::compile(&extended, &outputs),
            d_a,
            d_b,
            d_f_by_z,
            d_f_by_x,
        })
    }

    /// The number of operations of one evaluation of the partial derivatives.
    pub fn operation_count(&self) -> usize {
        self.system.operation_count() + self.partials.operation_count()
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
        let values = self.system.eval(inputs);
        let a = DMatrix::from_row_slice(n, n, &values[..n * n]);
        let b = DVector::from_column_slice(&values[n * n..]);
        let not_finite = |what: &str| SolveError::NotFinite {
            state: state(),
            what: what.into(),
        };
        if values.iter().any(|x| !x.is_finite()) {
            return Err(not_finite("a coefficient of the equations"));
        }
        let singular = || SolveError::SingularSystem {
            state: state(),
            detail: "the equations do not determine the unknowns here".into(),
        };
        let x = solve_linear(&a, &b).ok_or_else(singular)?;
        let mut extended = inputs.to_vec();
        extended.extend(x.iter());
        let values = self.partials.eval(&extended);
        if values.iter().any(|x| !x.is_finite()) {
            return Err(not_finite("a partial derivative of the equations"));
        }
        let m = self.variables.len();
        // ∂b/∂z_j − (∂A/∂z_j) x for every j, as the columns of one right-hand side.
        let mut rhs = DMatrix::<f64>::zeros(n, m);
        for e in &self.d_a {
            let value = values[e.output];
            rhs[(e.row, e.variable)] -= value * x[e.column];
        }
        for e in &self.d_b {
            rhs[(e.row, e.variable)] += values[e.output];
        }
        let mut jacobian = DMatrix::<f64>::zeros(m, m);
        for e in &self.d_f_by_z {
            jacobian[(e.row, e.variable)] += values[e.output];
        }
        let dx = if n == 0 {
            DMatrix::zeros(0, m)
        } else {
            let lu = a.clone().lu();
            lu.solve(&rhs).ok_or_else(singular)?
        };
        for e in &self.d_f_by_x {
            let value = values[e.output];
            for j in 0..m {
                jacobian[(e.row, j)] += value * dx[(e.variable, j)];
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

fn push(
    outputs: &mut Vec<Expr>,
    entries: &mut Vec<Entry>,
    e: Expr,
    variable: usize,
    row: usize,
    column: usize,
) {
    if !e.is_zero() {
        entries.push(Entry {
            variable,
            row,
            column,
            output: outputs.len(),
        });
        outputs.push(e);
    }
}

/// The mass, damping and stiffness matrices `M δq'' + C δq' + K δq = 0` of equations
/// free of reactions, one per coordinate.
#[derive(Clone, Debug)]
pub struct SecondOrder {
    coordinates: usize,
    inputs: usize,
    program: Program,
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
    /// Compiles the partial derivatives of `rows`, each `… = 0` and linear in the q''
    /// with coefficients `−M` (as Kane's `F_r + F_r* = 0` are: the sign is turned so that
    /// `M` is the mass matrix).
    ///
    /// # Errors
    /// When a row has no derivative.
    pub fn new(problem: &Problem, rows: &[Expr]) -> Result<SecondOrder, MechanicsError> {
        let n = problem.coordinates.len();
        let accelerations: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 2)).collect();
        let (mut m, mut c, mut k) = (Vec::new(), Vec::new(), Vec::new());
        for row in rows {
            // row = Σ coefficients_j q''_j + rest: the mass matrix is read off, and only the
            // (smaller) coefficients and the rest are differentiated.
            let (coefficients, rest) =
                linear_split(row, &accelerations).map_err(|e| MechanicsError {
                    path: "loads".into(),
                    message: e.to_string(),
                    hint: Some("loads may not depend on second rates".into()),
                })?;
            m.extend(coefficients.iter().map(|e| -e));
            for (order, out) in [(1u8, &mut c), (0, &mut k)] {
                for i in 0..n {
                    let z = problem.coordinate_symbol(i, order);
                    let mut terms = vec![partial(&rest, &z).map_err(not_differentiable)?];
                    for (coefficient, x) in coefficients.iter().zip(&accelerations) {
                        let d = partial(coefficient, &z).map_err(not_differentiable)?;
                        if !d.is_zero() {
                            terms.push(d * Expr::sym(x.clone()));
                        }
                    }
                    out.push(-add(terms));
                }
            }
        }
        let outputs: Vec<Expr> = m.into_iter().chain(c).chain(k).collect();
        let mut inputs = input_symbols(problem);
        let count = inputs.len();
        inputs.extend((0..n).map(|i| problem.coordinate_symbol(i, 2)));
        Ok(SecondOrder {
            coordinates: n,
            inputs: count,
            program: Program::compile(&inputs, &outputs),
        })
    }

    /// `M`, `C`, `K` at the inputs' values, with the q'' there.
    pub fn at(&self, inputs: &[f64], accelerations: &[f64]) -> Matrices {
        let n = self.coordinates;
        let mut extended = inputs[..self.inputs].to_vec();
        extended.extend_from_slice(accelerations);
        let values = self.program.eval(&extended);
        let block = |i: usize| DMatrix::from_row_slice(n, n, &values[i * n * n..(i + 1) * n * n]);
        Matrices {
            m: block(0),
            c: block(1),
            k: block(2),
        }
    }
}

/// The values of the inputs of [`input_symbols`]: constants, coordinates, rates, time.
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
