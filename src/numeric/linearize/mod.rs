//! Small motions about a state (an equilibrium, or a steady motion such as a spinning
//! top): the exact state matrix ([`jacobian`]), then its eigenvalues and modes
//! ([`modes`]). For a system without constraints, also the mass, damping and stiffness
//! matrices of `M δq'' + C δq' + K δq = 0`.

pub(super) mod hqr;
pub(super) mod jacobian;
pub(super) mod modes;

use crate::equations::{kane_equations, Derivation, Method};
use crate::numeric::assemble::Assembly;
use crate::numeric::reduce::Reducer;
use crate::numeric::SolveError;
use crate::problem::Problem;
use jacobian::{input_values, state_text, variable_name, Matrices, SecondOrder};
pub use jacobian::{Jacobian, StateMatrix};
use modes::{Eigen, Mode};
use nalgebra::DMatrix;

/// What the linearization of one problem by one method makes of a state matrix, for any
/// state and any values of the constants: a constrained system reduced to its independent
/// variables, the eigenvalues and modes, and M, C, K. The state matrix itself comes from a
/// [`Jacobian`] of the plan that suits the state, which the pipeline chooses
/// (`pipeline::Linearizer`), planning again where the first plan is singular.
#[derive(Clone, Debug)]
pub struct ModalAnalysis {
    method: Method,
    /// The state variables' names as printed (`q1`, `q1'`), whatever the plan.
    variables: Vec<String>,
    /// `None` for a constrained system, whose equations carry constraint forces.
    second_order: Option<SecondOrder>,
    /// A constrained system's assembly and reduction to its independent variables.
    constraints: Option<(Assembly, Reducer)>,
}

/// The equations of `derivation` (its linear system in the q'' and the other unknowns)
/// compiled for their partial derivatives: by composite bodies where the derivation has
/// them, the shorter program for the same unknowns.
pub fn jacobian_of(derivation: &Derivation) -> Jacobian {
    let system = derivation
        .composite_system
        .as_ref()
        .unwrap_or(&derivation.system);
    Jacobian::new(derivation.model.problem, system)
}

impl Jacobian {
    /// The state matrix of these equations at the state `t`, `q`, `rates`, with the
    /// constants of `problem`.
    ///
    /// # Errors
    /// A singular system or a value that is not finite, naming the state.
    pub fn at(
        &self,
        problem: &Problem,
        t: f64,
        q: &[f64],
        rates: &[f64],
    ) -> Result<StateMatrix, SolveError> {
        let inputs = input_values(problem, t, q, rates);
        self.state_matrix(&inputs, &|| state_text(problem, t, q, rates))
    }
}

/// The linearization at one state.
#[derive(Clone, Debug)]
pub struct Linearization {
    /// Time.
    pub t: f64,
    /// The coordinates, in the order the joints name them.
    pub q: Vec<f64>,
    /// Their rates.
    pub rates: Vec<f64>,
    /// The q'' at the state (zero at an equilibrium or a steady motion).
    pub accelerations: Vec<f64>,
    /// The state variables' names: the coordinates, then the rates (`q1'`).
    pub variables: Vec<String>,
    /// The state matrix `∂ż/∂z`.
    pub a: DMatrix<f64>,
    /// Its eigenvalues and eigenvectors, sorted.
    pub eigen: Vec<Eigen>,
    /// One mode per complex-conjugate pair.
    pub modes: Vec<Mode>,
    /// `M`, `C`, `K` (systems without constraints).
    pub matrices: Option<Matrices>,
}

/// Kane's rows without reactions, each `… = 0`: the equations of motion for the q'' alone.
/// A derivation whose system is Kane's (its own, or standing in for another method's) has
/// them as its first rows, `A x − b` with the q'' its first unknowns (by composite bodies
/// where it has those), so they are not formed twice.
fn kane_rows(derivation: &Derivation) -> Vec<crate::symbolic::Expr> {
    let problem = derivation.model.problem;
    let n = problem.coordinates.len();
    let accelerations: Vec<_> = (0..n).map(|i| problem.coordinate_symbol(i, 2)).collect();
    let system = derivation
        .composite_system
        .as_ref()
        .unwrap_or(&derivation.system);
    if derivation.system_method == Method::Kane
        && system.unknowns.get(..n) == Some(&accelerations[..])
    {
        return (0..n)
            .map(|i| {
                let mut terms: Vec<_> = (0..n)
                    .map(|j| {
                        &system.a[i][j] * &crate::symbolic::Expr::sym(accelerations[j].clone())
                    })
                    .collect();
                terms.push(-&system.b[i]);
                crate::symbolic::add(terms)
            })
            .collect();
    }
    kane_equations(
        &derivation.model,
        &derivation.actions,
        derivation.inertia(),
        &accelerations,
        (&[], &[]),
    )
    .into_iter()
    .map(|row| row.expression)
    .collect()
}

impl ModalAnalysis {
    /// Compiles what the linearization needs besides the state matrix: M, C and K (Kane's
    /// rows without reactions), or the reduction of a constrained system.
    pub fn new(derivation: &Derivation) -> ModalAnalysis {
        let problem = derivation.model.problem;
        let mut variables: Vec<String> = (0..problem.coordinates.len())
            .map(|i| variable_name(&problem.coordinate_symbol(i, 0)))
            .collect();
        variables.extend(
            (0..problem.coordinates.len()).map(|i| variable_name(&problem.coordinate_symbol(i, 1))),
        );
        if let Some(assembly) = Assembly::new(&derivation.model) {
            return ModalAnalysis {
                method: derivation.method,
                variables,
                second_order: None,
                constraints: Some((assembly, Reducer::new(&derivation.model))),
            };
        }
        let rows = kane_rows(derivation);
        ModalAnalysis {
            method: derivation.method,
            variables,
            second_order: Some(SecondOrder::new(problem, &rows)),
            constraints: None,
        }
    }

    /// The method the equations come from.
    pub fn method(&self) -> Method {
        self.method
    }

    /// The state to linearize about: `q`, `rates` as given, or for a constrained system
    /// the nearest that meets its constraints (with the constants of `problem`).
    ///
    /// # Errors
    /// When the constraints cannot be met near the state.
    pub fn assemble(
        &self,
        problem: &Problem,
        t: f64,
        q: &[f64],
        rates: &[f64],
    ) -> Result<(Vec<f64>, Vec<f64>), SolveError> {
        let (mut q, mut rates) = (q.to_vec(), rates.to_vec());
        if let Some((assembly, _)) = &self.constraints {
            let constants: Vec<f64> = problem.constants.iter().map(|c| c.value).collect();
            assembly.assemble(&constants, t, &mut q, &mut rates)?;
        }
        Ok((q, rates))
    }

    /// The linearization about the state `t`, `q`, `rates` (assembled, see
    /// [`ModalAnalysis::assemble`]), with the constants of `problem` (the problem this was
    /// built from, up to the values of its constants), given the state matrix of its
    /// equations there.
    ///
    /// # Errors
    /// A value that is not finite, or eigenvalues that do not converge.
    pub fn at(
        &self,
        problem: &Problem,
        t: f64,
        q: &[f64],
        rates: &[f64],
        state: StateMatrix,
    ) -> Result<Linearization, SolveError> {
        let inputs = input_values(problem, t, q, rates);
        let describe = || state_text(problem, t, q, rates);
        let n = problem.coordinates.len();
        let accelerations: Vec<f64> = state.unknowns[..n].to_vec();
        let (a, variables, coordinates) = match &self.constraints {
            None => (state.a, self.variables.clone(), n),
            Some((_, reducer)) => {
                let qdd_q = state.a.view((n, 0), (n, n)).into_owned();
                let qdd_v = state.a.view((n, n), (n, n)).into_owned();
                let names = |list: &[usize], prime: &str| -> Vec<String> {
                    list.iter()
                        .map(|&i| format!("{}{prime}", problem.coordinates[i].name))
                        .collect()
                };
                let mut variables = names(&reducer.coordinates, "");
                variables.extend(names(&reducer.rates, "'"));
                (
                    reducer.state_matrix(&inputs, &qdd_q, &qdd_v),
                    variables,
                    reducer.coordinates.len(),
                )
            }
        };
        let eigen = modes::eigen(&a).ok_or_else(|| SolveError::NotFinite {
            state: describe(),
            what: "the eigenvalues of the state matrix (the iteration did not converge)".into(),
        })?;
        let modes = modes::modes(&eigen, coordinates);
        let matrices = self
            .second_order
            .as_ref()
            .map(|s| s.at(&inputs, &accelerations));
        Ok(Linearization {
            t,
            q: q.to_vec(),
            rates: rates.to_vec(),
            accelerations,
            variables,
            a,
            eigen,
            modes,
            matrices,
        })
    }
}
