//! The one orchestrator of a handout, `pipeline::run`: each stage once, only what the job
//! asks, and the handout written from what it gave.

use mbd_tutor::equations::Method;
use mbd_tutor::pipeline::{run, Job};
use mbd_tutor::problem::load_file;
use mbd_tutor::solution::{handout, student, Handout};

/// The student's version asks for the derivation and the initial state only: no
/// simulation, no checks, no answers. Its blank tables still count what the worked
/// solution writes: as many free bodies and rows of step 5.
#[test]
fn the_student_run_simulates_nothing_and_counts_the_worked_rows() {
    let cases = [
        ("double-pendulum-rods", Method::MotionLaw),
        ("rolling-coin", Method::Kane),
        ("slider-crank-flywheel", Method::NewtonEuler),
    ];
    for (name, method) in cases {
        let problem = load_file(&crate::support::problem(name)).expect("loads");
        let job = Job {
            student: true,
            ..Job::worked(method)
        };
        let asked = run(&problem, &job).expect("runs");
        assert!(asked.simulation.is_none() && asked.answers.is_none() && asked.frames.is_none());
        let worked = run(&problem, &Job::worked(method)).expect("runs");
        assert!(
            matches!(worked.simulation, Some(Ok(_))),
            "{name}: simulates"
        );
        let settings = Handout::default();
        let full = handout(&worked, &settings);
        let blank = student(&problem, method, Some(&asked), &settings);
        assert!(!full.free_bodies.is_empty() && !full.plan.rows.is_empty());
        assert_eq!(blank.free_bodies.len(), full.free_bodies.len(), "{name}");
        assert_eq!(blank.plan.rows.len(), full.plan.rows.len(), "{name}");
        assert!(blank.equations.is_empty() && blank.simulation.checks.is_empty());
    }
}
