//! The work of the applied forces and torques along a run, against closed forms: a constant
//! torque T on an angle θ does W = T (θ − θ₀), a constant force P along x does
//! W = P (x − x₀); with that work the total energy balances, and with a load 0.1 % off it
//! does not. Sliding friction's work is included: μ times the normal force against the
//! slip, times the distance slid.

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::{load_work, load_work_check, simulate, Compiled, Trajectory};
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::problem::{load_file, Problem};

fn problem(name: &str) -> Problem {
    load_file(&crate::support::problem(name)).expect("a bundled problem")
}

fn run(problem: &Problem) -> Trajectory {
    let compiled =
        Compiled::new(&derive(problem, Method::MotionLaw, Purpose::Rows).expect("derives"));
    let rates: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    let q0 = problem.initial_coordinates();
    let run = simulate(&compiled, &q0, &rates, &problem.simulate).expect("simulates");
    assert!(run.stopped.is_none(), "{:?}", run.stopped);
    run
}

fn constant(problem: &Problem, name: &str) -> f64 {
    (problem.constants.iter().find(|c| c.name == name))
        .expect("the constant")
        .value
}

/// (problem, its load's constant, the coordinate it works on): a torque `T·n̂_z` on the
/// angle of the body it turns, a force `P·n̂_x` on the cart's `x`.
const CLOSED_FORMS: [(&str, &str, &str); 3] = [
    ("rack-and-pinion", "T", "theta"),
    ("gear-pair-torque", "T", "qA"),
    ("disc-on-cart", "P", "x"),
];

#[test]
fn the_work_of_a_constant_load_is_the_load_times_its_displacement() {
    for (name, load, coordinate) in CLOSED_FORMS {
        let problem = problem(name);
        let trajectory = run(&problem);
        let work = load_work(&problem, &trajectory).expect("a load does work");
        let column = trajectory.column(coordinate).expect("the coordinate");
        let first = trajectory.rows[0][column];
        let value = constant(&problem, load);
        let largest = work.iter().fold(0.0f64, |m, w| m.max(w.abs()));
        assert!(largest > 1.0, "{name}: the load does work ({largest} J)");
        for (row, w) in trajectory.rows.iter().zip(&work) {
            let closed = value * (row[column] - first);
            assert!(
                (w - closed).abs() <= 1e-9 * largest,
                "{name} at t = {}: W = {w}, {load}·Δ{coordinate} = {closed}",
                row[0]
            );
        }
        assert!(
            load_work_check(&problem, &trajectory)
                .expect("applies")
                .passed
        );
    }
}

/// The rack and pinion by hand: (M + I/r²) ẍ = T/r from ẋ₀ = 0.1 m/s, and x = r θ, so
/// W(1 s) = T θ(1) = (T/r)(ẋ₀ + ẍ/2): 31.0119 J, as the handout prints.
#[test]
fn the_rack_and_pinion_torque_does_the_work_of_the_hand_result() {
    let problem = problem("rack-and-pinion");
    let trajectory = run(&problem);
    let work = load_work(&problem, &trajectory).expect("applies");
    let (r, i, m, t) = (0.04, 0.001, 2.0, 0.5);
    let acceleration = (t / r) / (m + i / (r * r));
    let by_hand = (t / r) * (0.1 + acceleration / 2.0);
    let end = *work.last().expect("rows");
    assert!(
        (end - by_hand).abs() < 1e-9 * by_hand,
        "{end} against {by_hand}"
    );
    assert!((by_hand - 31.0119).abs() < 1e-4, "{by_hand}");
}

#[test]
fn a_load_off_by_a_thousandth_breaks_the_energy_balance() {
    for (name, load, _) in CLOSED_FORMS {
        let mut problem = problem(name);
        let trajectory = run(&problem);
        let constant = (problem.constants.iter_mut().find(|c| c.name == load)).expect("load");
        constant.value *= 1.001;
        let check = load_work_check(&problem, &trajectory).expect("applies");
        assert!(!check.passed, "{name}: {check:?}");
    }
}

/// A force pushing along a rough rod or floor, sliding from rest: the friction is μ N
/// against the slip, N by hand from the forces across the slide (the block: N = m g; the
/// collar pulled up at β: N = |m g − P sin β|), so the work of the push and of friction
/// together is W = (P cos β − μ N)(x − x₀), and the energy balances with it.
#[test]
fn sliding_frictions_work_is_mu_n_times_the_distance_slid() {
    for (name, beta) in [
        ("block-pushed-on-rough-floor", None),
        ("collar-on-rough-rod", Some("beta")),
    ] {
        let problem = problem(name);
        let trajectory = run(&problem);
        let work = load_work(&problem, &trajectory).expect("the push and friction do work");
        let (m, g, p, mu) = (
            constant(&problem, "m"),
            constant(&problem, "g"),
            constant(&problem, "P"),
            constant(&problem, "mu"),
        );
        let beta = beta.map_or(0.0, |b| constant(&problem, b));
        let normal = (m * g - p * beta.sin()).abs();
        let net = p * beta.cos() - mu * normal;
        assert!(
            net > 0.0 && mu * normal > 0.1,
            "{name}: it slides, against friction"
        );
        let column = trajectory.column("x").expect("x");
        let first = trajectory.rows[0][column];
        let largest = work.iter().fold(0.0f64, |m, w| m.max(w.abs()));
        for (row, w) in trajectory.rows.iter().zip(&work) {
            let closed = net * (row[column] - first);
            assert!(
                (w - closed).abs() <= 1e-9 * largest,
                "{name} at t = {}: W = {w}, (P cos β − μN)·Δx = {closed}",
                row[0]
            );
        }
        // Friction's share is no rounding: over the run it takes more than a joule.
        let slid = trajectory.rows.last().expect("rows")[column] - first;
        assert!(
            mu * normal * slid > 1.0,
            "{name}: friction's work {}",
            mu * normal * slid
        );
        assert!(
            load_work_check(&problem, &trajectory)
                .expect("applies")
                .passed,
            "{name}"
        );
    }
}

/// Where a damper also takes energy, or nothing is applied, or friction holds the body at
/// rest all along (no work, no motion), the balance with the applied loads is not claimed.
#[test]
fn no_balance_is_claimed_where_other_forces_do_work_without_a_potential() {
    for name in [
        "two-mass-spring-damper",
        "simple-pendulum",
        "statics-block-on-incline",
    ] {
        let problem = problem(name);
        let trajectory = run(&problem);
        assert!(load_work(&problem, &trajectory).is_none(), "{name}");
    }
}
