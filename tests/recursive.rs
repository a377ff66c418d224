//! The articulated-body form (`src/numeric/recursive/`) against the dense compiled rows on
//! every bundled and validation problem it takes: the q'' at the initial state to 1e-10
//! relative to max(1, |x|), and the simulation's first second to 1e-10. The two forms
//! round differently, and the ten-link chain's ten seconds of chaotic motion, integrated
//! to a tolerance of 1e-9, grow that to about 3.5e-9 by its end, so later rows are not
//! compared.

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::simulate::simulate;
use mbd_tutor::pipeline::{derive, Solver};
use mbd_tutor::problem::load_file;

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
            let Ok(derivation) = derive(&problem, method) else {
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
            let q: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
            let rates: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
            let ours = fastest.solve(0.0, &q, &rates).expect("solves");
            let theirs = dense.solve(0.0, &q, &rates).expect("solves");
            close(&ours.accelerations, &theirs.accelerations, 1e-10, &what);
            let ours = simulate(&fastest, &q, &rates, &problem.simulate).expect("simulates");
            let theirs = simulate(&dense, &q, &rates, &problem.simulate).expect("simulates");
            assert_eq!(ours.rows.len(), theirs.rows.len(), "{what}");
            for (a, b) in ours
                .rows
                .iter()
                .zip(&theirs.rows)
                .filter(|(_, b)| b[0] <= 1.0)
            {
                close(a, b, 1e-10, &what);
            }
        }
    }
    assert!(taken >= 4, "the recursive form took {taken} runs");
}
