//! The articulated-body form (`src/numeric/recursive/`) against the dense compiled rows on
//! every bundled and validation problem it takes, and on the bundled problems with loads
//! with their requested reactions taken out (which the recursive form does not give): the
//! q'' to 1e-10 relative to max(1, |x|), and the simulation's first second to 1e-10. The
//! two forms round differently, and the ten-link chain's ten seconds of chaotic motion,
//! integrated to a tolerance of 1e-9, grow that to about 3.5e-9 by its end, so later rows
//! are not compared.

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::{is_faster, simulate, Compiled, System};
use mbd_tutor::pipeline::{derive, Purpose, Solver};
use mbd_tutor::problem::{load, load_file, Problem};

fn close(a: &[f64], b: &[f64], tolerance: f64, what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (x, y) in a.iter().zip(b) {
        assert!(
            (x - y).abs() <= tolerance * y.abs().max(1.0),
            "{what}: {x} against the dense {y}"
        );
    }
}

#[test]
fn bundled_problems_keep_their_numbers_with_the_recursive_form() {
    let mut paths: Vec<_> = ["problems", "problems/validation"]
        .iter()
        .flat_map(|d| std::fs::read_dir(d).expect("problems").flatten())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    let mut taken = 0;
    for path in &paths {
        let problem = load_file(path).expect("valid");
        for method in Method::ALL {
            let Ok(derivation) = derive(&problem, method, Purpose::Numbers) else {
                continue;
            };
            let fastest = Solver::fastest(&problem, &derivation);
            if !fastest.compiled().is_recursive() {
                continue;
            }
            taken += 1;
            assert!(!fastest.is_own(), "the checks must derive their own rows");
            let dense = Solver::new(&problem, &derivation);
            let what = format!("{} by {}", path.display(), method.name());
            let q: Vec<f64> = problem.initial_coordinates();
            let rates: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
            let ours = fastest.solve(0.0, &q, &rates).expect("solves");
            let theirs = dense.solve(0.0, &q, &rates).expect("solves");
            close(&ours.accelerations, &theirs.accelerations, 1e-10, &what);
            first_second_agrees(&problem, &fastest, &dense, &what);
        }
    }
    assert!(taken >= 4, "the recursive form took {taken} runs");
}

/// A bundled problem with its requested reactions and questions taken out.
fn without_find(path: &str) -> Problem {
    let text = std::fs::read_to_string(path).expect("bundled problem");
    let mut value: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    value.as_object_mut().expect("object").remove("find");
    load(&serde_json::to_string(&value).expect("JSON")).expect("valid problem")
}

/// The first second of the simulations of `ours` and `theirs` from the initial state.
fn first_second_agrees(problem: &Problem, ours: &dyn System, theirs: &dyn System, what: &str) {
    let q: Vec<f64> = problem.initial_coordinates();
    let rates: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    let ours = simulate(ours, &q, &rates, &problem.simulate).expect("simulates");
    let theirs = simulate(theirs, &q, &rates, &problem.simulate).expect("simulates");
    assert_eq!(ours.rows.len(), theirs.rows.len(), "{what}");
    for (a, b) in ours
        .rows
        .iter()
        .zip(&theirs.rows)
        .filter(|(_, b)| b[0] <= 1.0)
    {
        close(a, b, 1e-10, what);
    }
}

#[test]
fn bundled_problems_with_loads_keep_their_numbers_with_the_recursive_form() {
    // Springs and dampers between bodies and on joints, forces and torques (the pushes of
    // the two masses and the plate functions of t), joint actuators with rate feedback.
    for path in [
        "problems/two-mass-spring-damper.json",
        "problems/plate-on-two-springs.json",
        "problems/floating-plate-springs.json",
        "problems/two-link-robot-arm.json",
        "problems/five-link-chain.json",
        "problems/arm-3d-rrp.json",
        "problems/collar-on-spinning-shaft.json",
    ] {
        let problem = without_find(path);
        for method in Method::ALL {
            let derivation = derive(&problem, method, Purpose::Numbers).expect("derives");
            let what = format!("{path} by {}", method.name());
            let ours = Compiled::recursive(&derivation);
            assert!(ours.is_recursive(), "{what}");
            let fastest = Solver::fastest(&problem, &derivation);
            let n = problem.coordinates.len();
            let planar = derivation.model.is_planar();
            assert_eq!(
                fastest.compiled().is_recursive(),
                is_faster(n, planar),
                "{what}"
            );
            let theirs = Compiled::new(&derivation);
            // Random states and times, a repeatable stream.
            let mut seed = 0x2545_f491_4f6c_dd1du64;
            let mut next = || {
                seed ^= seed << 13;
                seed ^= seed >> 7;
                seed ^= seed << 17;
                (seed >> 11) as f64 / (1u64 << 52) as f64 - 1.0
            };
            for _ in 0..5 {
                let t = 2.0 + 2.0 * next();
                let q: Vec<f64> = (0..n).map(|_| next()).collect();
                let rates: Vec<f64> = (0..n).map(|_| 2.0 * next()).collect();
                let a = ours.motion(t, &q, &rates).expect("solves").accelerations;
                let b = theirs.motion(t, &q, &rates).expect("solves").accelerations;
                close(&a, &b, 1e-10, &what);
            }
            first_second_agrees(&problem, &ours, &theirs, &what);
        }
    }
}
