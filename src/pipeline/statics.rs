//! Statics: the equilibria of a problem's free coordinates with every rate zero, and what
//! holds it there.
//!
//! The equations are those of the dynamics with the rates zero, solved with every friction
//! site sticking (friction then supplies whatever tangential force rest needs, and the
//! ratio |F|/(μ|N|) says whether it can). An equilibrium is a root of the free coordinates'
//! q'' (Newton's method, [`crate::numeric::newton`]), the dependent coordinates assembled
//! from the constraints at each step and the prescribed and held ones at their values.
//! Its stability comes from the linearization of the same equations
//! ([`super::Linearizer`]): unstable when an eigenvalue has a positive real part, neutral
//! when one is zero (the linearization decides nothing), stable otherwise.

use super::{derive, Linearizer, Purpose, Solver};
use crate::equations::Method;
use crate::error::Error;
use crate::numeric::{newton_solve, Held, Motion, NewtonFailure, SolveError, System};
use crate::problem::{Problem, ProblemError, ProblemErrors};
use nalgebra::{Complex, DMatrix, DVector};

/// How an equilibrium responds to a small disturbance, from its linearization.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StabilityKind {
    /// Every eigenvalue has a negative real part, or is imaginary and not zero.
    Stable,
    /// An eigenvalue has a positive real part.
    Unstable,
    /// An eigenvalue is zero: the linearization does not decide.
    Neutral,
}

impl StabilityKind {
    /// `stable`, `unstable` or `neutral`, as the JSON writes it.
    pub fn name(self) -> &'static str {
        match self {
            StabilityKind::Stable => "stable",
            StabilityKind::Unstable => "unstable",
            StabilityKind::Neutral => "neutral",
        }
    }
}

/// The stability of an equilibrium and the eigenvalues it is judged by.
#[derive(Clone, Debug, PartialEq)]
pub struct Stability {
    /// Stable, unstable, or neutral (the linearization does not decide).
    pub kind: StabilityKind,
    /// The eigenvalues of the state matrix, (re, im), sorted as `linearize` sorts them.
    pub eigenvalues: Vec<(f64, f64)>,
}

/// One equilibrium.
#[derive(Clone, Debug, PartialEq)]
pub struct Equilibrium {
    /// Every coordinate there, assembled.
    pub q: Vec<f64>,
    /// Every rate (zero but for a prescribed motion's).
    pub rates: Vec<f64>,
    /// The reactions, the drives of held and prescribed coordinates, and the friction
    /// sites, sticking.
    pub motion: Motion,
    /// `None` when no coordinate is free: a structure with only reactions to find.
    pub stability: Option<Stability>,
    /// Newton iterations taken.
    pub iterations: usize,
}

impl Solver<'_> {
    /// The q'', reactions, drives and friction forces at a state with every friction site
    /// sticking (the state must meet the constraints).
    ///
    /// # Errors
    /// As for [`Solver::solve`].
    pub fn at_rest(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Motion, SolveError> {
        let stick = vec![Held::Stick; self.friction_sites().len()];
        self.with_plan(t, q, rates, |c| c.motion_held(t, q, rates, Some(&stick)))
    }
}

impl Solver<'_> {
    /// The same equations for `problem`: the problem derived from, with other values of its
    /// constants.
    fn with_problem<'q>(&self, problem: &'q Problem) -> Solver<'q> {
        let constants: Vec<f64> = problem.constants.iter().map(|c| c.value).collect();
        let plans = (self.plans.plans.borrow().iter())
            .map(|c| c.with_constants(&constants))
            .collect();
        Solver {
            problem,
            plans: super::Plans {
                method: self.plans.method,
                replans: self.plans.replans,
                own: self.plans.own,
                plans: std::cell::RefCell::new(plans),
            },
        }
    }
}

/// The equations of a problem at rest, ready to find equilibria.
pub struct Statics<'p> {
    problem: &'p Problem,
    solver: Solver<'p>,
    /// `None` for the same equations with other values of the constants, whose equilibria
    /// are found without their stability.
    linearizer: Option<Linearizer>,
    /// The coordinates Newton's method moves: neither dependent nor prescribed nor held.
    free: Vec<usize>,
}

impl<'p> Statics<'p> {
    /// Derives the equations of `problem` by `method`.
    ///
    /// # Errors
    /// As for [`derive()`].
    pub fn new(problem: &'p Problem, method: Method) -> Result<Statics<'p>, Error> {
        let derivation = derive(problem, method, Purpose::Numbers)?;
        let dependent = &derivation.model.constraints.dependent;
        let free = (0..problem.coordinates.len())
            .filter(|i| !dependent.contains(i) && problem.coordinates[*i].motion.is_none())
            .collect();
        Ok(Statics {
            problem,
            solver: Solver::new(problem, &derivation),
            linearizer: Some(Linearizer::new(&derivation)),
            free,
        })
    }

    /// The same equations for `problem`, the problem derived from with other values of its
    /// constants; its equilibria come without their stability.
    pub fn with_problem<'q>(&self, problem: &'q Problem) -> Statics<'q> {
        Statics {
            problem,
            solver: self.solver.with_problem(problem),
            linearizer: None,
            free: self.free.clone(),
        }
    }

    /// The coordinates that are free to find, by index.
    pub fn free(&self) -> &[usize] {
        &self.free
    }

    /// The names of the sites with friction.
    pub fn friction_sites(&self) -> Vec<String> {
        self.solver.friction_sites()
    }

    /// The solver of the equations (with every friction site sticking at rest).
    pub fn solver(&self) -> &Solver<'p> {
        &self.solver
    }

    /// The state at configuration `q` with every rate zero, assembled.
    fn at(&self, q: &[f64]) -> Result<(Vec<f64>, Vec<f64>), SolveError> {
        let (mut q, mut rates) = (q.to_vec(), vec![0.0; q.len()]);
        self.solver.assemble(0.0, &mut q, &mut rates)?;
        Ok((q, rates))
    }

    /// The free coordinates' q'' at rest at configuration `q`.
    fn residual(&self, q: &[f64]) -> Option<DVector<f64>> {
        let (q, rates) = self.at(q).ok()?;
        let a = self.solver.at_rest(0.0, &q, &rates).ok()?.accelerations;
        let r = DVector::from_iterator(self.free.len(), self.free.iter().map(|&i| a[i]));
        r.iter().all(|x| x.is_finite()).then_some(r)
    }

    /// The equilibrium nearest (by Newton's method) the configuration `guess`, every
    /// coordinate given; `from` says where the guess came from, for the error.
    ///
    /// # Errors
    /// No equilibrium found (exit 1, with a hint), or the equations cannot be solved there.
    pub fn equilibrium(&self, guess: &[f64], from: &str) -> Result<Equilibrium, Error> {
        let set = |u: &DVector<f64>| {
            let mut q = guess.to_vec();
            for (&i, &x) in self.free.iter().zip(u.iter()) {
                q[i] = x;
            }
            q
        };
        let u0 = DVector::from_iterator(self.free.len(), self.free.iter().map(|&i| guess[i]));
        let root = newton_solve(|u| self.residual(&set(u)), u0)
            .map_err(|failure| self.not_found(failure, from))?;
        let (q, rates) = self.at(&set(&root.u))?;
        let motion = self.solver.at_rest(0.0, &q, &rates)?;
        let stability = match (&self.linearizer, self.free.is_empty()) {
            (Some(linearizer), false) => Some(self.stability(linearizer, &q, &rates)?),
            _ => None,
        };
        Ok(Equilibrium {
            q,
            rates,
            motion,
            stability,
            iterations: root.iterations,
        })
    }

    fn not_found(&self, failure: NewtonFailure, from: &str) -> Error {
        let message = match failure {
            NewtonFailure::NotSolvable => {
                format!("the equations of equilibrium cannot be solved at {from}")
            }
            NewtonFailure::NoRoot { left, iterations } => format!(
                "no equilibrium found near {from}: after {iterations} Newton iterations the largest second derivative of a free coordinate is still {}",
                crate::symbolic::fixed(left)
            ),
        };
        let error = ProblemError {
            path: "coordinates".into(),
            column: None,
            message,
            hint: Some(
                "start nearer an equilibrium with --near q=V (one guess per --near), or check the loads: without a restoring load there may be none"
                    .into(),
            ),
        };
        Error::Problem(ProblemErrors(vec![error]))
    }

    /// The stability of the equilibrium at `q`, `rates`: from the exact linearization, or,
    /// where its equations are singular (rough contacts whose forces statics does not
    /// split), from central differences of the free coordinates' q'' at rest.
    fn stability(
        &self,
        linearizer: &Linearizer,
        q: &[f64],
        rates: &[f64],
    ) -> Result<Stability, Error> {
        let values: Vec<Complex<f64>> = match linearizer.at(self.problem, 0.0, q, rates) {
            Ok(linear) => linear.eigen.iter().map(|e| e.value).collect(),
            Err(error) => {
                let a = self.state_matrix(q).ok_or(error)?;
                let mut values = crate::numeric::eigenvalues(&a).unwrap_or_default();
                crate::numeric::sort_modes(&mut values);
                values
            }
        };
        // Parts within the tolerance of zero are zero: round-off, not motion.
        let tolerance = zero_tolerance(values.iter().map(|v| v.norm()).fold(0.0, f64::max));
        let snap = |x: f64| if x.abs() <= tolerance { 0.0 } else { x };
        let eigenvalues: Vec<(f64, f64)> =
            values.iter().map(|v| (snap(v.re), snap(v.im))).collect();
        Ok(Stability {
            kind: classify(&eigenvalues),
            eigenvalues,
        })
    }

    /// The state matrix of the free coordinates and their rates at rest at `q`, by central
    /// differences of [`Solver::at_rest`] (the dependent coordinates and rates assembled).
    fn state_matrix(&self, q: &[f64]) -> Option<DMatrix<f64>> {
        let n = self.free.len();
        let accelerations = |z: &[f64]| -> Option<Vec<f64>> {
            let (mut q, mut rates) = (q.to_vec(), vec![0.0; q.len()]);
            for (k, &i) in self.free.iter().enumerate() {
                q[i] = z[k];
                rates[i] = z[n + k];
            }
            self.solver.assemble(0.0, &mut q, &mut rates).ok()?;
            let a = self.solver.at_rest(0.0, &q, &rates).ok()?.accelerations;
            Some(self.free.iter().map(|&i| a[i]).collect())
        };
        let z0: Vec<f64> = self
            .free
            .iter()
            .map(|&i| q[i])
            .chain(vec![0.0; n])
            .collect();
        let mut a = DMatrix::zeros(2 * n, 2 * n);
        for k in 0..n {
            a[(k, n + k)] = 1.0;
        }
        for j in 0..2 * n {
            let h = 1e-6 * z0[j].abs().max(1.0);
            let (mut up, mut down) = (z0.clone(), z0.clone());
            up[j] += h;
            down[j] -= h;
            let (plus, minus) = (accelerations(&up)?, accelerations(&down)?);
            for k in 0..n {
                a[(n + k, j)] = (plus[k] - minus[k]) / (2.0 * h);
            }
        }
        Some(a)
    }
}

/// What is zero among eigenvalues whose largest |λ| is `scale`.
fn zero_tolerance(scale: f64) -> f64 {
    (1e-7 * scale).max(1e-6)
}

/// Unstable when an eigenvalue's real part is positive, neutral when an eigenvalue is zero,
/// stable otherwise; "positive" and "zero" beyond 1e-7 of the largest |λ| and beyond
/// 1e-6 /s (a period of some seventy days), since the eigenvalues of a conservative
/// system's centre, and the zero ones of a system held by friction, come out with a
/// rounding's real part.
pub fn classify(eigenvalues: &[(f64, f64)]) -> StabilityKind {
    let scale = eigenvalues
        .iter()
        .map(|(re, im)| re.hypot(*im))
        .fold(0.0, f64::max);
    let tolerance = zero_tolerance(scale);
    if eigenvalues.iter().any(|(re, _)| *re > tolerance) {
        StabilityKind::Unstable
    } else if eigenvalues
        .iter()
        .any(|(re, im)| re.hypot(*im) <= tolerance)
    {
        StabilityKind::Neutral
    } else {
        StabilityKind::Stable
    }
}

#[cfg(test)]
mod tests {
    use super::{classify, StabilityKind};

    #[test]
    fn stability_from_eigenvalues() {
        assert_eq!(classify(&[(0.0, 3.1), (0.0, -3.1)]), StabilityKind::Stable);
        assert_eq!(
            classify(&[(-0.2, 3.1), (-0.2, -3.1)]),
            StabilityKind::Stable
        );
        assert_eq!(
            classify(&[(-3.1, 0.0), (3.1, 0.0)]),
            StabilityKind::Unstable
        );
        assert_eq!(classify(&[(0.0, 0.0), (0.0, 0.0)]), StabilityKind::Neutral);
        assert_eq!(classify(&[(0.0, 0.0), (-1.0, 0.0)]), StabilityKind::Neutral);
        assert_eq!(
            classify(&[(-3.6e-8, 0.0), (3.6e-8, 0.0)]),
            StabilityKind::Neutral
        );
    }
}
