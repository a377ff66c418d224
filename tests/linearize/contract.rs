//! The linearize command's JSON, sweeps, expression-valued states and the handout's section.

use super::*;

/// The JSON of the contract: keys, the variables' order, A's kinematic rows, the sorting of
/// the eigenvalues, one mode per pair with a positive imaginary part, shapes scaled to 1,
/// `state` and `accelerations` as `solve` gives them.
#[test]
fn json_has_the_shape_and_order_of_the_contract() {
    for (name, state) in [
        ("double-pendulum-rods", "q1=0.2,q2=-0.1,q1'=0.3"),
        ("heavy-symmetric-top", ""),
        ("two-mass-spring-damper", ""),
        ("five-link-chain", "q1=0,q2=0,q3=0,q4=0,q5=0"),
    ] {
        let path = problem(name);
        let path = path.to_str().unwrap();
        let mut args = vec![path];
        if !state.is_empty() {
            args.extend(["--state", state]);
        }
        let l = linearize(&args);
        let mut solve_args = vec!["solve", path, "--format", "json"];
        if !state.is_empty() {
            solve_args.extend(["--state", state]);
        }
        let solved = run_json(&solve_args);
        assert_eq!(l["state"], solved["state"], "{name}");
        let names: Vec<&String> = solved["accelerations"]
            .as_object()
            .unwrap()
            .keys()
            .collect();
        for (key, value) in solved["accelerations"].as_object().unwrap() {
            assert!(
                close(number(&l["accelerations"][key]), number(value), 1e-9),
                "{name} {key}"
            );
        }
        let variables: Vec<String> = names
            .iter()
            .map(|n| n.to_string())
            .chain(names.iter().map(|n| format!("{n}'")))
            .collect();
        assert_eq!(l["variables"], serde_json::json!(variables), "{name}");
        let a = matrix(&l["A"]);
        let n = names.len();
        assert_eq!(a.len(), 2 * n);
        for (i, row) in a.iter().enumerate().take(n) {
            for (j, x) in row.iter().enumerate() {
                assert_eq!(
                    *x,
                    if j == n + i { 1.0 } else { 0.0 },
                    "{name}: A[{i}][{j}]"
                );
            }
        }
        let lambda = eigenvalues(&l);
        assert_eq!(lambda.len(), 2 * n);
        for pair in lambda.windows(2) {
            let ((r0, i0), (r1, i1)) = (pair[0], pair[1]);
            let tied = (r1 - r0).abs() <= 1e-9 * r0.abs().max(r1.abs());
            assert!(
                r0 <= r1 || tied,
                "{name}: not sorted by real part: {lambda:?}"
            );
            assert!(
                !tied || i0 <= i1,
                "{name}: ties not sorted by imaginary part: {lambda:?}"
            );
        }
        let modes = l["modes"].as_array().unwrap();
        let pairs: Vec<_> = lambda.iter().filter(|e| e.1 > 0.0).collect();
        assert_eq!(modes.len(), pairs.len(), "{name}");
        for (mode, (re, im)) in modes.iter().zip(pairs) {
            let magnitude = re.hypot(*im);
            assert!(close(
                number(&mode["natural_frequency_hz"]),
                magnitude / TAU,
                1e-12
            ));
            assert!(close(number(&mode["damped_frequency_hz"]), im / TAU, 1e-12));
            assert!(close(
                number(&mode["damping_ratio"]),
                -re / magnitude,
                1e-12
            ));
            let shape = mode["shape"].as_object().unwrap();
            assert_eq!(shape.len(), n, "{name}");
            let sizes: Vec<f64> = shape
                .values()
                .map(|v| match v {
                    Value::Array(mp) => {
                        assert_eq!(mp.len(), 2, "[magnitude, phase]");
                        number(&mp[0])
                    }
                    other => number(other).abs(),
                })
                .collect();
            let largest = sizes.iter().copied().fold(0.0, f64::max);
            assert!(close(largest, 1.0, 1e-12), "{name}: {shape:?}");
        }
    }
}

#[test]
fn sweep_gives_an_array_with_both_ends_and_a_plot() {
    let path = problem("simple-pendulum");
    let path = path.to_str().unwrap();
    let plot = std::env::temp_dir().join(format!("mbd-tutor-sweep-{}.svg", std::process::id()));
    let args = [
        "--state",
        "theta=0,theta'=0",
        "--sweep",
        "L=0.5:2:4",
        "--plot",
        plot.to_str().unwrap(),
    ];
    let mut all = vec![path];
    all.extend(args);
    let results = linearize(&all);
    let results = results.as_array().unwrap();
    let lengths: Vec<f64> = results.iter().map(|r| number(&r["sweep"]["L"])).collect();
    assert_eq!(lengths, vec![0.5, 1.0, 1.5, 2.0]);
    for (r, length) in results.iter().zip(lengths) {
        let omega = (9.81f64 / length).sqrt();
        assert!(close(natural_frequencies(r)[0], omega / TAU, 1e-12));
    }
    let svg = std::fs::read_to_string(&plot).expect("the plot is written");
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(
        svg.contains("<circle"),
        "the eigenvalues are drawn as points"
    );
    // -o FILE.svg writes the plot there and the report to standard output; both are the
    // same bytes every run.
    let svg_output = plot.with_extension("o.svg");
    let all = [
        "linearize",
        path,
        "--sweep",
        "L=0.5:2:4",
        "-o",
        svg_output.to_str().unwrap(),
    ];
    let first = run(&all);
    assert!(
        first.status.success(),
        "{}",
        String::from_utf8_lossy(&first.stderr)
    );
    assert!(String::from_utf8_lossy(&first.stdout)
        .contains("stable (every Re λ ≤ 0) for L from 0.5 to 2"));
    let again = std::fs::read_to_string(&svg_output).expect("-o FILE.svg is the plot");
    let second = run(&all);
    assert_eq!(first.stdout, second.stdout);
    assert_eq!(std::fs::read_to_string(&svg_output).unwrap(), again);
    let _ = std::fs::remove_file(&svg_output);
    // A plot without a sweep, or an unknown constant, is refused with a message.
    let out = run(&["linearize", path, "--plot", plot.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let out = run(&["linearize", path, "--sweep", "Lx=1:2:3"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("did you mean `L`?"));
}

#[test]
fn expression_valued_initial_and_rate_follow_set_and_report_errors() {
    let text = TOP.replace(
        r#""a3": { "rate": "w" }"#,
        r#""a3": { "rate": "w", "initial": "pi/w" }, "a1": { "initial": "0.001*m" }"#,
    );
    let path = temporary_problem("expressions", &text);
    let solved = run_json(&[
        "solve",
        path.to_str().unwrap(),
        "--format",
        "json",
        "--set",
        "w=50",
    ]);
    assert_eq!(number(&solved["state"]["a3'"]), 50.0);
    assert!(close(
        number(&solved["state"]["a3"]),
        std::f64::consts::PI / 50.0,
        1e-15
    ));
    assert!(close(number(&solved["state"]["a1"]), 0.0005, 1e-15));
    // Errors name the JSON path and the column.
    let bad = TOP.replace(r#""rate": "w""#, r#""rate": "w*a1 + 1""#);
    let path = temporary_problem("bad-expression", &bad);
    let out = run(&["check", path.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("coordinates.a3.rate, column 3"), "{stderr}");
    let out = run(&["solve", path.to_str().unwrap(), "--set", "w=0"]);
    assert_eq!(out.status.code(), Some(1));
    let zero = TOP.replace(r#""rate": "w""#, r#""rate": "1/w""#);
    let path = temporary_problem("division", &zero);
    let out = run(&["solve", path.to_str().unwrap(), "--set", "w=0"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("coordinates.a3.rate"), "{stderr}");
}

/// At any state, every method's state matrix has the lower rows −M⁻¹ [K C] of Kane's
/// equations, which are formed without reactions: two derivations agree.
#[test]
fn state_matrix_agrees_with_m_c_k_of_kanes_equations_for_every_problem() {
    let mut checked = 0;
    for path in crate::support::all_problems() {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        for method in crate::support::METHODS {
            let l = linearize(&[path.to_str().unwrap(), "--method", method]);
            if l["M"].is_null() {
                // A constrained problem: its q'' are not those of M, C, K alone.
                continue;
            }
            checked += 1;
            let a = matrix(&l["A"]);
            let (m, c, k) = (matrix(&l["M"]), matrix(&l["C"]), matrix(&l["K"]));
            let n = m.len();
            let scale = a.iter().flatten().fold(1.0f64, |s, x| s.max(x.abs()));
            // M times the lower rows of A must be −[K C].
            for i in 0..n {
                for j in 0..2 * n {
                    let product: f64 = (0..n).map(|r| m[i][r] * a[n + r][j]).sum();
                    let expected = if j < n { -k[i][j] } else { -c[i][j - n] };
                    let size = m[i].iter().fold(0.0f64, |s, x| s.max(x.abs())) * scale;
                    assert!(
                        (product - expected).abs() <= 1e-8 * size.max(1e-300),
                        "{name} by {method}: row {i}, column {j}: {product} against {expected}"
                    );
                }
            }
        }
    }
    assert!(
        checked >= 3 * 17,
        "only {checked} problems and methods without constraints"
    );
}

/// `--linearize` before the problem's path leaves the path to the problem: the state, if
/// any, follows an `=`.
#[test]
fn explain_linearize_before_the_path_keeps_the_path() {
    let path = problem("simple-pendulum");
    let out = run(&["explain", "--linearize", path.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // About the initial state, θ = 0.6: K = m g L cos θ = 0.5 · 9.81 · 0.8 · cos 0.6.
    let k = 0.5 * 9.81 * 0.8 * 0.6f64.cos();
    assert!((k - 3.23862).abs() < 5e-6);
    assert!(String::from_utf8_lossy(&out.stdout).contains("\\mathbf{K} = \\begin{bmatrix} 3.23862"));
}

/// `explain --linearize`: the section in Markdown with the pendulum's frequency, and
/// LaTeX that pdflatex compiles (a spinning top: complex shapes; a five-link chain:
/// matrices of five columns).
#[test]
fn explain_adds_a_section_that_compiles() {
    let path = problem("simple-pendulum");
    let out = run(&[
        "explain",
        path.to_str().unwrap(),
        "--linearize=theta=0,theta'=0",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let section = &text[text
        .find("## Small motions about a state")
        .expect("the section")..];
    // ω = √(g/L) = 3.50179 rad/s, 0.557326 Hz; M = m L² = 0.32, K = m g L = 3.924.
    for expected in [
        "0.557326",
        "\\mathbf{M} = \\begin{bmatrix} 0.32 \\end{bmatrix}",
        "3.924",
        "-3.50179 i",
    ] {
        assert!(
            section.contains(expected),
            "missing {expected} in\n{section}"
        );
    }
    if !crate::support::pdflatex_present("the small motions' LaTeX") {
        return;
    }
    let dir = std::env::temp_dir().join(format!("mbd-tutor-linearize-tex-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for name in ["heavy-symmetric-top", "five-link-chain"] {
        let tex = dir.join(format!("{name}.tex"));
        let out = run(&[
            "explain",
            problem(name).to_str().unwrap(),
            "--format",
            "latex",
            "--linearize",
            "-o",
            tex.to_str().unwrap(),
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let source = std::fs::read_to_string(&tex).unwrap();
        assert!(source.contains("\\section*{Small motions about a state}"));
        let typeset = crate::support::pdflatex(&tex);
        assert!(
            typeset.compiled() && typeset.pages() > 0,
            "{name}.tex does not compile: {}",
            typeset.faults()
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}
