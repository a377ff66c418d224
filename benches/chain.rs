//! The speed benchmark: planar chains of n = 1 … 20 rods joined by revolute joints, with
//! joint (relative) angles as coordinates. For each n: the time to derive and plan, the time
//! to compile A and b, the size of A and b (terms multiplied out, and operations once
//! compiled), and the time of one evaluate-and-solve. Times are the fastest of 5 tries.
//!
//! Run: `cargo bench --bench chain` (add `-- 10` for one size).

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::Compiled;
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::problem::{
    Body, BodyId, Constant, Coordinate, CoordinateKind, Dimension, Inertia, Joint, JointKind,
    Problem, SimulateSettings, VectorExpr,
};
use mbd_tutor::symbolic::Expr;
use std::time::Instant;

/// A planar chain of `n` uniform rods hanging from N, each joined to the previous by a pin.
pub fn planar_chain(n: usize) -> Problem {
    let constant = |name: &str, value: f64| Constant {
        name: name.into(),
        value,
        unit: None,
        description: None,
        vary: None,
    };
    let down = |scale: Expr, frame: usize| VectorExpr {
        terms: vec![(BodyId(frame), 1, -scale)],
    };
    let (m, l) = (Expr::constant("m"), Expr::constant("L"));
    let bodies = (1..=n)
        .map(|i| Body {
            name: format!("B{i}"),
            mass: m.clone(),
            center: down(&l / &Expr::int(2), i),
            inertia: Inertia::Planar(&(&m * &(&l * &l)) / &Expr::int(12)),
            description: None,
            shape: None,
            path: format!("bodies.B{i}"),
        })
        .collect();
    let joints = (1..=n)
        .map(|i| Joint {
            name: format!("J{i}"),
            kind: JointKind::Revolute,
            parent: BodyId(i - 1),
            child: BodyId(i),
            coordinates: vec![i - 1],
            axis: Some(VectorExpr {
                terms: vec![(BodyId(i - 1), 2, Expr::one())],
            }),
            sequence: vec![],
            at: if i == 1 {
                VectorExpr::default()
            } else {
                down(l.clone(), i - 1)
            },
            child_at: VectorExpr::default(),
            friction: None,
            angle_from: None,
            path: format!("joints[{}]", i - 1),
        })
        .collect();
    let coordinates = (1..=n)
        .map(|i| Coordinate {
            name: format!("q{i}"),
            initial: 0.1 * i as f64,
            rate: 0.0,
            initial_expr: None,
            rate_expr: None,
            unit: None,
            description: None,
            joint: i - 1,
            index_in_joint: 0,
            kind: CoordinateKind::Angle,
            dependent: false,
            dependent_rate: false,
            motion: None,
            drive_symbol: None,
            held: false,
        })
        .collect();
    Problem {
        title: format!("{n}-link chain"),
        statement: None,
        dimension: Dimension::Two,
        constants: vec![constant("m", 1.0), constant("L", 0.5), constant("g", 9.81)],
        coordinates,
        gravity: Some(VectorExpr {
            terms: vec![(BodyId::GROUND, 1, -Expr::constant("g"))],
        }),
        bodies,
        joints,
        points: vec![],
        closures: vec![],
        constraints: vec![],
        loads: vec![],
        find_reactions: vec![],
        questions: Vec::new(),
        simulate: SimulateSettings::default(),
        speeds: vec![],
        decimals: vec![],
        impact: None,
    }
}

/// How many times each measurement is repeated; the table shows the fastest, since on a
/// shared machine the slower runs measure the neighbours, not the program.
const TRIES: usize = 5;

fn main() {
    let sizes: Vec<usize> = match std::env::args().nth(1).and_then(|a| a.parse().ok()) {
        Some(n) => vec![n],
        None => (1..=20).collect(),
    };
    println!(
        "| n | method | derive and plan (ms) | compile (ms) | terms in A and b | operations in A and b | evaluate and solve (µs) |"
    );
    println!("|---|---|---|---|---|---|---|");
    for n in sizes {
        let problem = planar_chain(n);
        for method in [Method::Kane, Method::MotionLaw] {
            let (mut derive_ms, mut compile_ms) = (f64::INFINITY, f64::INFINITY);
            let mut last = None;
            for _ in 0..TRIES {
                let start = Instant::now();
                let derivation =
                    derive(&problem, method, Purpose::Numbers).expect("the chain derives");
                derive_ms = derive_ms.min(start.elapsed().as_secs_f64() * 1e3);
                let start = Instant::now();
                let compiled = Compiled::new(&derivation);
                compile_ms = compile_ms.min(start.elapsed().as_secs_f64() * 1e3);
                last = Some((derivation, compiled));
            }
            let Some((derivation, compiled)) = last else {
                continue;
            };
            // The size of the equations themselves: the terms of every entry, multiplied out.
            let system = &derivation.system;
            let terms: usize = system
                .a
                .iter()
                .flatten()
                .chain(&system.b)
                .map(|e| if e.is_zero() { 0 } else { e.terms().len() })
                .sum();
            let q: Vec<f64> = (0..n).map(|i| 0.1 * i as f64).collect();
            let rates = vec![0.3; n];
            let repeats = 2000;
            let mut solve_us = f64::INFINITY;
            for _ in 0..TRIES {
                let start = Instant::now();
                for _ in 0..repeats {
                    std::hint::black_box(compiled.motion(0.0, &q, &rates).expect("solves"));
                }
                solve_us = solve_us.min(start.elapsed().as_secs_f64() * 1e6 / repeats as f64);
            }
            println!(
                "| {n} | {} | {derive_ms:.1} | {compile_ms:.1} | {terms} | {} | {solve_us:.2} |",
                method.name(),
                compiled.operation_count()
            );
        }
    }
}
