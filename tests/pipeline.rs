//! The pipeline's recovery: where the Motion Law's plan is singular at a state at which the
//! system is not, the solver plans again, for `solve`, `simulate` and `explain` alike.

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::{simulate, System};
use mbd_tutor::pipeline::{derive, Purpose, Solver};
use mbd_tutor::problem::load_file;

/// The spherical pendulum's Motion Law plan, chosen at its initial state, is singular with
/// the rod horizontal, (q1, q2, q3) = (π/2, 0, 0); the system is not. The solver plans again
/// there and gives Newton–Euler's q''; a simulation started there runs to its end.
#[test]
fn a_plan_singular_at_a_state_is_made_again_there() {
    let problem = load_file(&crate::support::problem("spherical-pendulum")).expect("loads");
    let special = [std::f64::consts::FRAC_PI_2, 0.0, 0.0];
    let rates = [0.2, 1.0, 0.3];
    let motion_law = derive(&problem, Method::MotionLaw, Purpose::Numbers).expect("derives");
    // The plan of the derivation alone fails there: that is what is being recovered from.
    let direct = mbd_tutor::numeric::Compiled::new(&motion_law).solve(0.0, &special, &rates);
    assert!(
        direct.is_err(),
        "the first plan is expected to be singular there"
    );
    let solver = Solver::new(&problem, &motion_law);
    let recovered = solver
        .solve(0.0, &special, &rates)
        .expect("the solver plans again");
    let newton_euler = derive(&problem, Method::NewtonEuler, Purpose::Numbers).expect("derives");
    let reference = Solver::new(&problem, &newton_euler)
        .solve(0.0, &special, &rates)
        .expect("Newton-Euler has no plan to make");
    for (a, b) in recovered.accelerations.iter().zip(&reference.accelerations) {
        assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{a} against {b}");
    }
    // A simulation that starts there, through the same solver.
    let mut settings = problem.simulate.clone();
    settings.duration = 0.2;
    let trajectory = simulate(&solver, &special, &rates, &settings).expect("runs");
    assert!(trajectory.stopped.is_none(), "{:?}", trajectory.stopped);
    assert_eq!(trajectory.rows.len(), 21);
    assert!(solver.coordinate_names().len() == 3);
}

/// `linearize` goes through the same recovery: at the spherical pendulum's special state
/// the Motion Law's first plan gives no state matrix, the pipeline's linearizer plans again
/// and its state matrix, eigenvalues and q'' are Kane's, which has no plan to make.
#[test]
fn a_linearization_where_the_plan_is_singular_is_made_with_a_new_plan() {
    use mbd_tutor::numeric::jacobian_of;
    use mbd_tutor::pipeline::Linearizer;
    let problem = load_file(&crate::support::problem("spherical-pendulum")).expect("loads");
    let special = [std::f64::consts::FRAC_PI_2, 0.0, 0.0];
    let rates = [0.2, 1.0, 0.3];
    let motion_law = derive(&problem, Method::MotionLaw, Purpose::Numbers).expect("derives");
    let direct = jacobian_of(&motion_law).at(&problem, 0.0, &special, &rates);
    assert!(
        matches!(
            direct,
            Err(mbd_tutor::numeric::SolveError::SingularSystem { .. })
        ),
        "the first plan is expected to be singular there: {direct:?}"
    );
    let recovered = Linearizer::new(&motion_law)
        .at(&problem, 0.0, &special, &rates)
        .expect("the linearizer plans again");
    let kane = derive(&problem, Method::Kane, Purpose::Numbers).expect("derives");
    let reference = Linearizer::new(&kane)
        .at(&problem, 0.0, &special, &rates)
        .expect("Kane's method has no plan to make");
    assert_eq!(recovered.a.shape(), (6, 6));
    assert_eq!(recovered.variables, reference.variables);
    let scale = reference.a.amax().max(1.0);
    for (a, b) in recovered.a.iter().zip(reference.a.iter()) {
        assert!((a - b).abs() <= 1e-9 * scale, "{a} against {b}");
    }
    for (a, b) in recovered.accelerations.iter().zip(&reference.accelerations) {
        assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{a} against {b}");
    }
    for (a, b) in recovered.eigen.iter().zip(&reference.eigen) {
        assert!(
            (a.value - b.value).norm() <= 1e-7 * b.value.norm().max(1.0),
            "{:?} against {:?}",
            a.value,
            b.value
        );
    }
}

/// `explain`'s stages (`pipeline::run`) on the spherical pendulum started at the special
/// state: the worked solution's q'' there are Newton–Euler's, and its simulation, which
/// runs through the Motion Law solver with the recovery, ends normally with every check
/// passing.
#[test]
fn the_worked_solution_is_made_at_a_state_where_the_first_plan_is_singular() {
    let mut problem = load_file(&crate::support::problem("spherical-pendulum")).expect("loads");
    for (c, q) in problem
        .coordinates
        .iter_mut()
        .zip([std::f64::consts::FRAC_PI_2, 0.0, 0.0])
    {
        c.initial = q;
    }
    problem.simulate.duration = 0.5;
    let worked = mbd_tutor::pipeline::work(&problem, Method::MotionLaw).expect("works");
    let reference = mbd_tutor::pipeline::work(&problem, Method::NewtonEuler).expect("works");
    for (a, b) in worked
        .initial
        .accelerations
        .iter()
        .zip(&reference.initial.accelerations)
    {
        assert!((a - b).abs() <= 1e-9 * b.abs().max(1.0), "{a} against {b}");
    }
    let simulated = worked
        .simulation
        .as_ref()
        .expect("the worked solution simulates");
    let (trajectory, checks) = simulated.as_ref().expect("the simulation runs");
    assert!(trajectory.stopped.is_none(), "{:?}", trajectory.stopped);
    assert!(!checks.is_empty());
    assert!(checks.iter().all(|c| c.passed), "{checks:?}");
}
