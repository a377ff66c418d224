//! The four methods against each other at many random states of every bundled problem,
//! and energy conservation over 10 s: checks that do not rest on any one method.

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::{simulate, Compiled, System};
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::problem::load_file;

use crate::support::Lcg;

fn bundled() -> Vec<std::path::PathBuf> {
    let mut paths: Vec<_> = std::fs::read_dir("problems")
        .expect("problems/")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    paths
}

fn close(a: f64, b: f64, scale: f64) -> bool {
    (a - b).abs() <= 1e-10 * scale.max(1.0)
}

#[test]
fn the_methods_agree_at_random_states_of_every_bundled_problem() {
    for path in bundled() {
        let problem = load_file(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let compiled: Vec<Compiled> = Method::ALL
            .iter()
            .map(|&m| {
                Compiled::new(
                    &derive(&problem, m, Purpose::Rows)
                        .unwrap_or_else(|e| panic!("{}: {e}", path.display())),
                )
            })
            .collect();
        let mut random = Lcg(7);
        let mut checked = 0;
        for _ in 0..12 {
            // Within ±0.5 of the initial state: away from the singular configurations that
            // the problems are written to avoid.
            let (mut q, mut rates) = random.state_near(&problem, 0.5);
            let t = 0.5 * (random.next() + 1.0);
            // Kane's rows with independent speeds hold only where the constraints do: the
            // methods are compared on the constraint manifold.
            if compiled[0].assemble(t, &mut q, &mut rates).is_err() {
                continue;
            }
            let Ok(first) = compiled[0].solve(t, &q, &rates) else {
                continue;
            };
            let scale = first
                .accelerations
                .iter()
                .fold(0.0f64, |m, x| m.max(x.abs()));
            for other in &compiled[1..] {
                let s = other
                    .solve(t, &q, &rates)
                    .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                for (a, b) in first.accelerations.iter().zip(&s.accelerations) {
                    assert!(
                        close(*a, *b, scale),
                        "{}: {} gives {b}, motion-law {a}",
                        path.display(),
                        other.method.name()
                    );
                }
                for ((joint, f1, m1), (_, f2, m2)) in first.reactions.iter().zip(&s.reactions) {
                    let scale = f1.iter().chain(m1).fold(0.0f64, |m, x| m.max(x.abs()));
                    for (a, b) in f1.iter().chain(m1).zip(f2.iter().chain(m2)) {
                        assert!(
                            close(*a, *b, scale),
                            "{}: reaction at {joint}: {} gives {b}, motion-law {a}",
                            path.display(),
                            other.method.name()
                        );
                    }
                }
            }
            checked += 1;
        }
        assert!(checked >= 6, "{}: too few regular states", path.display());
    }
}

/// The largest change of kinetic + potential energy over the run, relative to its scale.
fn energy_drift(name: &str, method: Method) -> f64 {
    let mut problem =
        load_file(std::path::Path::new(&format!("problems/{name}.json"))).expect("valid");
    problem.simulate.duration = 10.0;
    problem.simulate.output_step = 0.05;
    problem.simulate.tolerance = 1e-10;
    let compiled = Compiled::new(&derive(&problem, method, Purpose::Rows).expect("derives"));
    let q0: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
    let r0: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    let run = simulate(&compiled, &q0, &r0, &problem.simulate).expect("runs");
    assert!(run.stopped.is_none(), "{name} stopped: {:?}", run.stopped);
    let kinetic = run.column("kinetic").expect("kinetic");
    let potential = run.column("potential").expect("potential");
    let totals: Vec<f64> = run.rows.iter().map(|r| r[kinetic] + r[potential]).collect();
    let scale = run
        .rows
        .iter()
        .map(|r| r[kinetic].abs().max(r[potential].abs()))
        .fold(1e-12, f64::max);
    totals
        .iter()
        .map(|e| (e - totals[0]).abs())
        .fold(0.0, f64::max)
        / scale
}

#[test]
fn double_pendulum_and_heavy_top_conserve_energy_over_ten_seconds() {
    for name in ["double-pendulum-rods", "heavy-symmetric-top"] {
        for method in [Method::MotionLaw, Method::Kane] {
            let drift = energy_drift(name, method);
            assert!(
                drift < 1e-6,
                "{name} by {}: energy drift {drift}",
                method.name()
            );
        }
    }
}
