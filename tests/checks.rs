//! The confirmation checks on real derivations: they pass on the equations the methods
//! derive and fail on the same equations with one thing wrong.

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::{
    modes, small_oscillation, Compiled, Evaluation, ReactionColumn, SolveError, System,
};
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::problem::{load_file, Problem};

fn problem(name: &str) -> Problem {
    load_file(&crate::support::problem(name)).expect("a bundled problem")
}

fn initial(problem: &Problem) -> Vec<f64> {
    problem.initial_coordinates()
}

/// The equations of `inner` with their evaluation changed by `change`, which is given the
/// evaluation and the names of its reaction columns.
struct Tampered<'a> {
    inner: &'a dyn System,
    change: &'a dyn Fn(&mut Evaluation, &[ReactionColumn]),
}

impl System for Tampered<'_> {
    fn coordinate_names(&self) -> Vec<String> {
        self.inner.coordinate_names()
    }
    fn reaction_columns(&self) -> Vec<ReactionColumn> {
        self.inner.reaction_columns()
    }
    fn evaluate(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError> {
        let mut e = self.inner.evaluate(t, q, rates)?;
        (self.change)(&mut e, &self.inner.reaction_columns());
        Ok(e)
    }
    fn energies(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<(f64, f64), SolveError> {
        self.inner.energies(t, q, rates)
    }
    fn assemble(&self, t: f64, q: &mut [f64], rates: &mut [f64]) -> Result<(), SolveError> {
        self.inner.assemble(t, q, rates)
    }
    fn is_constrained(&self) -> bool {
        self.inner.is_constrained()
    }
    fn is_conservative(&self) -> bool {
        self.inner.is_conservative()
    }
    fn has_dissipation_only(&self) -> bool {
        self.inner.has_dissipation_only()
    }
}

/// Simple pendulum, L = 0.8 m, bob m = 0.5 kg: M = m L² = 0.32 kg·m² and K = m g L =
/// 3.924 N·m by hand, so ω = √(g/L).
#[test]
fn the_energies_give_the_pendulum_by_hand() {
    let problem = problem("simple-pendulum");
    let compiled =
        Compiled::new(&derive(&problem, Method::MotionLaw, Purpose::Rows).expect("derives"));
    let modes = modes(&compiled, &initial(&problem)).expect("a stable equilibrium");
    let (m, l, g) = (0.5, 0.8, 9.81);
    assert!((modes.mass[(0, 0)] - m * l * l).abs() < 1e-12, "{modes:?}");
    assert!(
        (modes.stiffness[(0, 0)] - m * g * l).abs() < 1e-6,
        "{modes:?}"
    );
    assert!((modes.omegas[0] - (g / l).sqrt()).abs() < 1e-7, "{modes:?}");
}

/// Every method's equations pass; a sign wrong in one q'' fails, for one coordinate and for
/// two (where a sign error in q2'' alone is what a student's slip looks like).
#[test]
fn right_equations_pass_and_a_wrong_sign_fails() {
    for name in [
        "simple-pendulum",
        "compound-pendulum",
        "double-pendulum-rods",
    ] {
        let problem = problem(name);
        let q0 = initial(&problem);
        for method in Method::ALL {
            let compiled =
                Compiled::new(&derive(&problem, method, Purpose::Rows).expect("derives"));
            let check = small_oscillation(&compiled, &q0).expect("applies");
            assert!(check.passed, "{name}, {}: {check:?}", method.name());
            let last = q0.len() - 1;
            for factor in [-1.0, 1.05] {
                let wrong = Tampered {
                    inner: &compiled,
                    change: &|e, _| e.accelerations[last] *= factor,
                };
                let check = small_oscillation(&wrong, &q0).expect("applies");
                assert!(!check.passed, "{name}, × {factor}: {check:?}");
            }
        }
    }
}

/// A body hanging from a ball joint may turn about the vertical through the joint at no cost
/// of energy: that neutral direction is no oscillation. Its eigenvalue, at the level of the
/// finite-difference Hessian's error, once passed for a mode with a period of hours, which
/// the check then failed after integrating it for seconds.
#[test]
fn a_body_free_to_turn_about_the_vertical_has_no_failing_oscillation() {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/checks/body-free-to-turn-about-the-vertical.json");
    let problem = load_file(&path).expect("the problem beside the test");
    let q0 = initial(&problem);
    let compiled = Compiled::new(&derive(&problem, Method::Kane, Purpose::Rows).expect("derives"));
    if let Some(check) = small_oscillation(&compiled, &q0) {
        assert!(check.passed, "{check:?}");
    }
}

/// A crank or a rod turned at a constant rate: the energy is not conserved (no such check
/// is made), it changes by the work of the drive, to 1e-6 of the energy scale; a drive
/// torque 0.1 % off breaks that balance.
#[test]
fn driven_systems_balance_energy_with_the_drives_work_and_a_wrong_drive_fails() {
    use mbd_tutor::numeric::{confirm, drive_energy_check, simulate};
    for name in ["slider-crank-driven", "collar-on-driven-rod"] {
        let problem = problem(name);
        let compiled =
            Compiled::new(&derive(&problem, Method::MotionLaw, Purpose::Rows).expect("derives"));
        let rates: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
        let run =
            simulate(&compiled, &initial(&problem), &rates, &problem.simulate).expect("simulates");
        assert!(run.stopped.is_none(), "{name}: {:?}", run.stopped);
        let checks = confirm(
            &problem,
            ("Motion Law", &compiled),
            &[],
            &run,
            &initial(&problem),
        );
        assert!(
            checks
                .iter()
                .all(|c| c.kind != mbd_tutor::numeric::CheckKind::EnergyConservation),
            "{name}: a driven system's energy is not conserved: {checks:?}"
        );
        let balance = drive_energy_check(&problem, &compiled, &run).expect("applies");
        assert!(balance.passed, "{name}: {balance:?}");
        // Every drive's force or torque 0.1 % off: the motion is unchanged, the drives'
        // reported work is not.
        let scale_drives = |e: &mut Evaluation, columns: &[ReactionColumn]| {
            for (value, column) in e.reactions.iter_mut().zip(columns) {
                if matches!(column, ReactionColumn::Drive { .. }) {
                    *value *= 1.001;
                }
            }
        };
        let wrong = Tampered {
            inner: &compiled,
            change: &scale_drives,
        };
        let balance = drive_energy_check(&problem, &wrong, &run).expect("applies");
        assert!(!balance.passed, "{name}, drive × 1.001: {balance:?}");
    }
}
