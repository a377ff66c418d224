//! One problem file's cost: the time to derive and plan, the size of the compiled program,
//! and the time of one evaluation of q'' (the compiled A and b plus the LU solve), for each
//! method. Times are the fastest of 5 tries. The problem's initial state is the one timed,
//! so the same chain can be timed in Pinocchio side by side (tools/bench/chains.py).
//!
//! Run: `cargo bench --bench evaluate -- PROBLEM.json [METHOD]`

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::evaluate::Compiled;
use mbd_tutor::pipeline::derive;
use std::path::Path;
use std::time::Instant;

const TRIES: usize = 5;

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    let Some(path) = args.first() else {
        eprintln!("usage: cargo bench --bench evaluate -- PROBLEM.json [METHOD]");
        std::process::exit(2);
    };
    let problem = match mbd_tutor::problem::load_file(Path::new(path)) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let methods: Vec<Method> = match args.get(1) {
        Some(name) => Method::ALL
            .into_iter()
            .filter(|m| m.name() == name)
            .collect(),
        None => Method::ALL.to_vec(),
    };
    let q: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
    let rates: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    println!("| method | derive and plan (ms) | operations | evaluate and solve (µs) | q'' |");
    println!("|---|---|---|---|---|");
    for method in methods {
        let start = Instant::now();
        let derivation = match derive(&problem, method) {
            Ok(d) => d,
            Err(e) => {
                println!("| {} | failed: {e} | | | |", method.name());
                continue;
            }
        };
        let derive_ms = start.elapsed().as_secs_f64() * 1e3;
        let compiled = Compiled::fastest(&derivation);
        let repeats = 20_000;
        let mut solve_us = f64::INFINITY;
        let mut last = None;
        for _ in 0..TRIES {
            let start = Instant::now();
            for _ in 0..repeats {
                last = Some(std::hint::black_box(compiled.motion(0.0, &q, &rates)));
            }
            solve_us = solve_us.min(start.elapsed().as_secs_f64() * 1e6 / repeats as f64);
        }
        let accelerations = match last {
            Some(Ok(motion)) => motion
                .accelerations
                .iter()
                .map(|x| format!("{x:.12}"))
                .collect::<Vec<_>>()
                .join(" "),
            _ => "singular".into(),
        };
        println!(
            "| {} | {derive_ms:.1} | {} | {solve_us:.2} | {accelerations} |",
            method.name(),
            compiled.operation_count()
        );
    }
}
