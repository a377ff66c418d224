//! Kane's rows by composite bodies (`src/equations/composite/`), which the numbers evaluate
//! in place of the rows as formed: the same linear system, entry by entry, at generic
//! states wherever they apply; the rows as formed wherever they do not.

use crate::support::problem;
use mbd_tutor::equations::{Derivation, LinearSystem, Method};
use mbd_tutor::mechanics::Form;
use mbd_tutor::numeric::Compiled;
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::problem::{load_file, Problem};
use mbd_tutor::symbolic::{eval, Values};

fn load(name: &str) -> Problem {
    load_file(&problem(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Kane's equations for the numbers.
fn kane(problem: &Problem) -> Derivation<'_> {
    derive(problem, Method::Kane, Purpose::At(&[], Form::Numeric)).expect("Kane's method derives")
}

/// Three generic states: every coordinate and rate moved off its initial value by a
/// different amount, seeded so that every run takes the same.
fn generic_states(derivation: &Derivation) -> Vec<Values> {
    let problem = derivation.model.problem;
    let mut seed: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    (0..3)
        .map(|k| {
            let q: Vec<f64> = problem
                .coordinates
                .iter()
                .map(|c| c.initial + next())
                .collect();
            let rates: Vec<f64> = problem
                .coordinates
                .iter()
                .map(|c| c.rate + next())
                .collect();
            derivation.model.values_at(0.4 * f64::from(k), &q, &rates)
        })
        .collect()
}

/// Every entry of `A` and `b` of the two systems at `values`, as pairs.
fn entries(a: &LinearSystem, b: &LinearSystem, values: &Values) -> Vec<(f64, f64)> {
    let flat = |s: &LinearSystem| -> Vec<f64> {
        let matrix = s.a.iter().flatten();
        matrix.chain(&s.b).map(|e| eval(e, values)).collect()
    };
    flat(a).into_iter().zip(flat(b)).collect()
}

#[test]
fn kanes_rows_by_composite_bodies_equal_the_rows_as_formed() {
    // A spherical chain; every joint type with reactions, joint loads, springs and a
    // damper; a planar chain; a gimbal and an arm with reactions; a free body.
    for name in [
        "validation/spherical-chain-3",
        "validation/all-joints-3d",
        "validation/ten-link-chain",
        "five-link-chain",
        "gyroscope-gimbal",
        "arm-3d-rrp",
        "torque-free-body",
        "floating-plate-springs",
    ] {
        let problem = load(name);
        let derivation = kane(&problem);
        let formed = &derivation.system;
        let composite = derivation
            .composite_system
            .as_ref()
            .unwrap_or_else(|| panic!("{name}: Kane's rows are not rebuilt by composite bodies"));
        assert_eq!(composite.unknowns, formed.unknowns, "{name}");
        for values in generic_states(&derivation) {
            let pairs = entries(composite, formed, &values);
            let scale = pairs.iter().fold(0.0f64, |m, (_, y)| m.max(y.abs()));
            for (index, (x, y)) in pairs.into_iter().enumerate() {
                assert!(
                    (x - y).abs() <= 1e-10 * scale,
                    "{name}: entry {index} is {x} by composite bodies, {y} as formed"
                );
            }
        }
    }
}

#[test]
fn where_the_composite_rows_do_not_apply_the_rows_stay_as_formed() {
    // A closure, a rolling contact, declared speeds, a prescribed coordinate.
    for name in [
        "four-bar",
        "rolling-coin",
        "torque-free-body-speeds",
        "collar-on-driven-rod",
    ] {
        let problem = load(name);
        assert!(kane(&problem).composite_system.is_none(), "{name}");
    }
    // Nor does any method but Kane's, nor the handout's form.
    let chain = load("validation/spherical-chain-3");
    for method in [Method::MotionLaw, Method::NewtonEuler] {
        let derivation = derive(&chain, method, Purpose::At(&[], Form::Numeric)).expect("derives");
        assert!(derivation.composite_system.is_none(), "{method:?}");
    }
    let handout = derive(&chain, Method::Kane, Purpose::At(&[], Form::Handout)).expect("derives");
    assert!(handout.composite_system.is_none());
}

#[test]
fn a_deep_chain_compiles_by_composite_bodies_and_a_small_system_as_formed() {
    let program = |derivation: &Derivation| Compiled::new(derivation).operation_count();
    // The three-link spherical chain: 3,836 operations as formed, 2,091 by composite bodies.
    let chain = load("validation/spherical-chain-3");
    let mut derivation = kane(&chain);
    let by_composite = program(&derivation);
    derivation.composite_system = None;
    let as_formed = program(&derivation);
    assert!(
        10 * by_composite < 6 * as_formed,
        "{by_composite} operations by composite bodies, {as_formed} as formed"
    );
    // The double pendulum's rows as formed are the shorter (111 against 122): they are kept.
    let pendulum = load("double-pendulum-rods");
    let mut derivation = kane(&pendulum);
    assert!(derivation.composite_system.is_some());
    let chosen = program(&derivation);
    derivation.composite_system = None;
    assert_eq!(chosen, program(&derivation));
}

#[test]
fn every_methods_numbers_of_a_large_tree_are_kanes_composite_system_and_its_own_rows() {
    use mbd_tutor::pipeline::{derive, Purpose, Solver};
    // A spherical chain, and every joint type with the reactions at O and W asked for.
    for name in ["validation/spherical-chain-3", "validation/all-joints-3d"] {
        let problem = load(name);
        let q: Vec<f64> = problem
            .coordinates
            .iter()
            .map(|c| c.initial + 0.3)
            .collect();
        let rates: Vec<f64> = problem.coordinates.iter().map(|c| c.rate - 0.7).collect();
        for method in [Method::MotionLaw, Method::NewtonEuler] {
            let fastest = derive(&problem, method, Purpose::Numbers).expect("derives");
            assert_eq!(fastest.method, method, "{name}");
            assert_eq!(fastest.system_method, Method::Kane, "{name} {method:?}");
            let own = derive(&problem, method, Purpose::Own).expect("derives");
            assert_eq!(own.system_method, method, "{name} {method:?}");
            let stand_in = Solver::new(&problem, &fastest);
            assert!(!stand_in.is_own() && Solver::new(&problem, &own).is_own());
            let got = stand_in.solve(0.0, &q, &rates).expect("solves");
            let expected = Solver::new(&problem, &own)
                .solve(0.0, &q, &rates)
                .expect("solves");
            let close = |x: f64, y: f64| (x - y).abs() <= 1e-10 * y.abs().max(1.0);
            for (x, y) in got.accelerations.iter().zip(&expected.accelerations) {
                assert!(close(*x, *y), "{name} {method:?}: q'' {x} against {y}");
            }
            assert_eq!(got.reactions.len(), expected.reactions.len(), "{name}");
            for (a, b) in got.reactions.iter().zip(&expected.reactions) {
                assert_eq!(a.0, b.0, "{name}");
                for (x, y) in a.1.iter().chain(&a.2).zip(b.1.iter().chain(&b.2)) {
                    assert!(close(*x, *y), "{name} {method:?} {}: {x} against {y}", a.0);
                }
            }
        }
    }
}
