//! One problem file's cost: the time to derive and plan, the size of the compiled program,
//! and the time of one evaluation of q'' in the form `solve` uses, for each method; beside
//! it the time of each form alone, the dense one (the compiled A and b plus the LU solve)
//! and the recursive one (the articulated-body algorithm, with the loads' program), where
//! it applies whatever the number of coordinates, and the operations of the loads' program.
//! Times are the fastest of 9 tries, the forms taking turns in each, so that the machine's
//! changing speed falls on each alike. The problem's initial state is the one timed, so
//! the same chain can be timed in Pinocchio side by side (tools/bench/chains.py).
//!
//! Run: `cargo bench --bench evaluate -- PROBLEM.json [METHOD]`

use mbd_tutor::equations::Method;
use mbd_tutor::numeric::Compiled;
use mbd_tutor::pipeline::{derive, Purpose};
use std::path::Path;
use std::time::Instant;

const TRIES: usize = 9;

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
    println!("| method | derive and plan (ms) | operations | evaluate and solve (µs) | dense form (µs) | recursive form (µs) | load operations | q'' |");
    println!("|---|---|---|---|---|---|---|---|");
    for method in methods {
        let start = Instant::now();
        let derivation = match derive(&problem, method, Purpose::Numbers) {
            Ok(d) => d,
            Err(e) => {
                println!("| {} | failed: {e} | | | |", method.name());
                continue;
            }
        };
        let derive_ms = start.elapsed().as_secs_f64() * 1e3;
        let compiled = Compiled::fastest(&derivation);
        let dense = Compiled::new(&derivation);
        let recursive = Compiled::recursive(&derivation);
        let load_operations = recursive.load_operation_count();
        let forms: Vec<&Compiled> = match load_operations {
            Some(_) => vec![&compiled, &dense, &recursive],
            None => vec![&compiled, &dense],
        };
        let (times, last) = time(&forms, &q, &rates);
        let (recursive_us, load_operations) = match load_operations {
            Some(count) => (format!("{:.2}", times[2]), count.to_string()),
            None => ("—".into(), "—".into()),
        };
        let accelerations = match last {
            Ok(accelerations) => accelerations
                .iter()
                .map(|x| format!("{x:.12}"))
                .collect::<Vec<_>>()
                .join(" "),
            _ => "singular".into(),
        };
        println!(
            "| {} | {derive_ms:.1} | {} | {:.2} | {:.2} | {recursive_us} | {load_operations} | {accelerations} |",
            method.name(),
            compiled.operation_count(),
            times[0],
            times[1],
        );
    }
}

/// For each form, the fastest of [`TRIES`] mean times of one evaluation of q'' at the
/// initial state, in µs, the forms taking turns in each try so that the machine's changing
/// speed falls on each alike; and the first form's last q''.
fn time(forms: &[&Compiled], q: &[f64], rates: &[f64]) -> (Vec<f64>, Result<Vec<f64>, String>) {
    let repeats = 20_000;
    let mut best = vec![f64::INFINITY; forms.len()];
    let mut last = Err(String::new());
    for _ in 0..TRIES {
        for (form, best) in forms.iter().zip(&mut best) {
            let start = Instant::now();
            for _ in 0..repeats {
                let motion = std::hint::black_box(form.motion(0.0, q, rates));
                if std::ptr::eq(*form, forms[0]) {
                    last = motion.map(|m| m.accelerations).map_err(|e| e.to_string());
                }
            }
            *best = best.min(start.elapsed().as_secs_f64() * 1e6 / repeats as f64);
        }
    }
    (best, last)
}
