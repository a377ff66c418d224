//! The derivation of a method's own rows (`pipeline::derive` for `Purpose::Own`), for timing one method
//! against another, or against SymPy, as whole processes side by side.
//!
//! Run: `cargo bench --bench derive_own -- PROBLEM.json METHOD [TRIES]`: derives the rows
//! TRIES times (1 unless given) and prints the fastest time in ms and the q'' at the
//! problem's initial state.

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::Compiled;
use mbd_tutor::pipeline::{derive, Purpose};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| a != "--bench")
        .collect();
    let (Some(path), Some(name)) = (args.first(), args.get(1)) else {
        eprintln!("usage: derive_own PROBLEM.json METHOD [TRIES]");
        std::process::exit(2);
    };
    let Some(method) = Method::ALL.into_iter().find(|m| m.name() == name) else {
        eprintln!("derive_own: no method `{name}`");
        std::process::exit(2);
    };
    let tries: usize = args.get(2).and_then(|t| t.parse().ok()).unwrap_or(1);
    let problem = mbd_tutor::problem::load_file(std::path::Path::new(path)).unwrap_or_else(|e| {
        eprintln!("{e}");
        std::process::exit(1)
    });
    let mut fastest = f64::INFINITY;
    let mut last = None;
    for _ in 0..tries.max(1) {
        let start = Instant::now();
        let derivation = derive(&problem, method, Purpose::Own).unwrap_or_else(|e| {
            eprintln!("{e}");
            std::process::exit(1)
        });
        fastest = fastest.min(start.elapsed().as_secs_f64() * 1e3);
        last = Some(derivation);
    }
    let Some(derivation) = last else {
        return;
    };
    let q: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
    let rates: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    let accelerations = Compiled::new(&derivation)
        .solve(0.0, &q, &rates)
        .map(|s| s.accelerations)
        .unwrap_or_default();
    let shown: Vec<String> = accelerations.iter().map(|a| format!("{a:.6}")).collect();
    println!("{fastest:.1} ms {}", shown.join(" "));
}
