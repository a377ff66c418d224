//! Tests of the simulation against closed forms.

use super::test_systems::{MassSpringDamper, Pendulum, SingularPast};
use super::*;

fn settings(duration: f64, output_step: f64, tolerance: f64) -> SimulateSettings {
    SimulateSettings {
        duration,
        output_step,
        tolerance,
    }
}

/// The complete elliptic integral of the first kind K(k), by the arithmetic-geometric
/// mean: K(k) = pi / (2 agm(1, sqrt(1 - k^2))).
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    while (a - b).abs() > 1e-16 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

#[test]
fn columns_and_rows_follow_the_contract() {
    let system = MassSpringDamper {
        m: 1.0,
        c: 0.0,
        k: 1.0,
    };
    let run = simulate(&system, &[1.0], &[0.0], &SimulateSettings::default()).unwrap();
    assert_eq!(
        run.columns,
        [
            "t",
            "x",
            "x'",
            "x''",
            "kinetic",
            "potential",
            "total",
            "W.force.x"
        ]
        .map(String::from)
    );
    assert_eq!(run.rows.len(), 501);
    assert!(run.stopped.is_none());
    assert_eq!(run.rows[0][0], 0.0);
    assert_eq!(run.rows[500][0], 5.0);
    assert_eq!(run.rows[37][0], 37.0 * 0.01);
    // Potential relative to the start: 0 there, total = kinetic + potential.
    assert_eq!(run.rows[0][5], 0.0);
    for row in &run.rows {
        assert_eq!(row.len(), run.columns.len());
        assert_eq!(row[6], row[4] + row[5]);
    }
}

#[test]
fn damped_oscillator_matches_closed_form() {
    let (m, c, k) = (2.0, 0.8, 50.0);
    let system = MassSpringDamper { m, c, k };
    let (x0, v0) = (0.1, -0.5);
    let run = simulate(&system, &[x0], &[v0], &settings(4.0, 0.01, 1e-10)).unwrap();
    // x = e^(-s t) (A cos(w t) + B sin(w t)), s = c / 2m, w^2 = k/m - s^2.
    let s = c / (2.0 * m);
    let w = (k / m - s * s).sqrt();
    let (a, b) = (x0, (v0 + s * x0) / w);
    for row in &run.rows {
        let t = row[0];
        let (e, cos, sin) = ((-s * t).exp(), (w * t).cos(), (w * t).sin());
        let x = e * (a * cos + b * sin);
        let v = e * ((b * w - s * a) * cos - (a * w + s * b) * sin);
        let acceleration = -(c * v + k * x) / m;
        assert!((row[1] - x).abs() < 1e-8, "x at t = {t}: {} vs {x}", row[1]);
        assert!(
            (row[2] - v).abs() < 1e-7,
            "x' at t = {t}: {} vs {v}",
            row[2]
        );
        assert!((row[3] - acceleration).abs() < 1e-6, "x'' at t = {t}");
        assert!(
            (row[7] - m * acceleration).abs() < 1e-5,
            "wall force at t = {t}"
        );
    }
}

/// T = 4 sqrt(l/g) K(sin(theta0/2)) for a release from rest at theta0.
#[test]
fn large_swing_pendulum_period_matches_elliptic_integral() {
    let (l, g, theta0): (f64, f64, f64) = (0.75, 9.81, 2.5);
    let exact = 4.0 * (l / g).sqrt() * elliptic_k((theta0 / 2.0).sin());
    let run = simulate(
        &Pendulum::new(l, g),
        &[theta0],
        &[0.0],
        &settings(3.0 * exact, 0.005, 1e-11),
    )
    .unwrap();
    let times: Vec<f64> = run.rows.iter().map(|r| r[0]).collect();
    let theta: Vec<f64> = run.rows.iter().map(|r| r[1]).collect();
    let rate: Vec<f64> = run.rows.iter().map(|r| r[2]).collect();
    let crossings = crate::numeric::checks::downward_crossings(&times, &theta, &rate);
    assert_eq!(crossings.len(), 3);
    let measured = (crossings[2] - crossings[0]) / 2.0;
    assert!(
        (measured - exact).abs() / exact < 1e-7,
        "{measured} vs {exact}"
    );
    // The rod's pull along it, from the radial equation with w^2 from energy:
    // T = m g cos(theta) + m l w^2, so O.force = T (-sin(theta), cos(theta)).
    for row in &run.rows {
        let theta = row[1];
        let w2 = 2.0 * g / l * (theta.cos() - theta0.cos());
        let pull = 2.0 * (g * theta.cos() + l * w2);
        assert!(
            (row[7] + pull * theta.sin()).abs() < 1e-6,
            "O.force.x at t = {}",
            row[0]
        );
        assert!(
            (row[8] - pull * theta.cos()).abs() < 1e-6,
            "O.force.y at t = {}",
            row[0]
        );
    }
}

#[test]
fn singular_mid_run_keeps_rows_and_names_the_state() {
    let system = SingularPast { wall: 0.5 };
    let run = simulate(&system, &[0.0], &[1.0], &settings(1.0, 0.1, 1e-9)).unwrap();
    // The steps close in on x = 0.5 from below, reaching every output before it.
    assert_eq!(run.rows.len(), 5, "t = 0 ..= 0.4");
    assert!((run.rows[4][1] - 0.4).abs() < 1e-12);
    match &run.stopped {
        Some(SolveError::SingularSystem { state, .. }) => {
            assert!(state.starts_with("t = 0.5"), "{state}")
        }
        other => panic!("expected a singular system, got {other:?}"),
    }
    // Singular at the start: no rows, and the reason.
    let run = simulate(&system, &[1.0], &[0.0], &SimulateSettings::default()).unwrap();
    assert!(run.rows.is_empty());
    assert!(matches!(
        run.stopped,
        Some(SolveError::SingularSystem { .. })
    ));
}

#[test]
fn refuses_runs_that_are_too_long_or_malformed() {
    let system = MassSpringDamper {
        m: 1.0,
        c: 0.0,
        k: 1.0,
    };
    let too_long = simulate(&system, &[1.0], &[0.0], &settings(1e4, 1e-3, 1e-9));
    assert!(
        matches!(
            too_long,
            Err(SolveError::TooManyRows {
                limit: MAX_ROWS,
                ..
            })
        ),
        "{too_long:?}"
    );
    let raised = Limits {
        max_rows: 20_000_000,
        ..Limits::default()
    };
    assert!(output_times(1e4, 1e-3, raised.max_rows).is_ok());
    for bad in [
        settings(-1.0, 0.01, 1e-9),
        settings(1.0, 0.0, 1e-9),
        settings(1.0, 0.01, 0.0),
    ] {
        assert!(matches!(
            simulate(&system, &[1.0], &[0.0], &bad),
            Err(SolveError::BadSimulation { .. })
        ));
    }
    assert!(simulate(&system, &[1.0, 2.0], &[0.0], &SimulateSettings::default()).is_err());
}

#[test]
fn output_times_end_at_the_duration() {
    let times = output_times(1.0, 0.3, MAX_ROWS).unwrap();
    assert_eq!(times, vec![0.0, 0.3, 0.6, 0.8999999999999999, 1.0]);
    let times = output_times(5.0, 0.01, MAX_ROWS).unwrap();
    assert_eq!((times.len(), times[500]), (501, 5.0));
    assert_eq!(output_times(0.0, 0.01, MAX_ROWS).unwrap(), vec![0.0]);
}

#[test]
fn csv_and_json_round_trip_every_digit() {
    let trajectory = Trajectory {
        columns: ["t", "q1", "q1'"].map(String::from).to_vec(),
        rows: vec![vec![0.0, 0.1 + 0.2, -0.0], vec![0.01, 1e-7, 12345678.9]],
        stopped: None,
        coordinates: 1,
        potential_at_start: 0.0,
        switches: Vec::new(),
    };
    assert_eq!(
        trajectory.to_csv(),
        "t,q1,q1'\n0.0,0.30000000000000004,0.0\n0.01,1e-7,12345678.9\n"
    );
    let json: serde_json::Value = serde_json::from_str(&trajectory.to_json()).unwrap();
    assert_eq!(json["columns"], serde_json::json!(["t", "q1", "q1'"]));
    assert_eq!(json["rows"][0][1].as_f64(), Some(0.1 + 0.2));
    assert_eq!(json["rows"][1][1].as_f64(), Some(1e-7));
    let empty = Trajectory {
        rows: Vec::new(),
        ..trajectory
    };
    let json: serde_json::Value = serde_json::from_str(&empty.to_json()).unwrap();
    assert_eq!(json["rows"], serde_json::json!([]));
}
