//! `explain --statics`: the worked solution of a problem at rest, by every method. Each
//! bundled statics problem's handout is written without an inertia term; its numbers are
//! those of `statics --format json` and of closed forms worked in the tests (the ladder's
//! reactions and the angle at which it slips, the torsion pendulum's k θ = m g d sin θ);
//! the Motion Law's planner takes moments about the ladder's foot and the four-bar's pins;
//! the LaTeX compiles, the student's version leaves the answers blank.

use crate::support::handouts::two_at_a_time;
use crate::support::{
    explain, pdflatex, pdflatex_present, problem, run, run_afresh, run_json, METHODS,
};
use serde_json::Value;

const G: f64 = 9.81;

/// The bundled statics problems, as `problem` names them.
const PROBLEMS: [&str; 7] = [
    "statics-block-on-incline",
    "statics-crank-held",
    "statics-four-bar-held",
    "statics-ladder",
    "statics-torsion-pendulum",
    "statics-two-link-arm",
    "validation/statics-tall-block",
];

/// What a handout at rest must not write: an inertia force or torque, an acceleration, a
/// second derivative, a rate of angular momentum, a kinetic diagram.
const MOTION: [&str; 10] = [
    "a^*",
    "a^{*}",
    "\\ddot",
    "\\mathbf{a}^{",
    "Ḣ",
    "\\dot{\\mathbf{H}}",
    "inertia force of",
    "inertia torque of",
    "kinetic diagram",
    "Equations of motion",
];

fn statics_json(name: &str, method: &str) -> Value {
    let path = problem(name);
    run_json(&[
        "statics",
        path.to_str().unwrap(),
        "--format",
        "json",
        "--method",
        method,
    ])
}

/// Every number written in `text` (digits with a point, a sign dropped).
fn numbers(text: &str) -> Vec<f64> {
    let mut out = Vec::new();
    let mut run = String::new();
    for c in text.chars().chain(std::iter::once(' ')) {
        if c.is_ascii_digit() || (c == '.' && !run.is_empty()) {
            run.push(c);
        } else if !run.is_empty() {
            if let Ok(x) = run.trim_end_matches('.').parse::<f64>() {
                out.push(x);
            }
            run.clear();
        }
    }
    out
}

/// Asserts `text` writes |want| to the six significant digits a handout prints.
fn writes(text: &str, want: f64, what: &str) {
    let want = want.abs();
    let found = numbers(text)
        .iter()
        .any(|x| (x - want).abs() <= 1e-5 * want.max(1e-3));
    assert!(found, "{what}: {want} is not written in the handout");
}

#[test]
fn no_statics_handout_writes_an_inertia_term() {
    for name in PROBLEMS {
        for method in METHODS {
            let text = explain(name, &["--statics", "--method", method]);
            for word in MOTION {
                assert!(
                    !text.contains(word),
                    "{name} by {method}: the statics handout writes `{word}`"
                );
            }
            assert!(
                text.contains("## Step 5. Equilibrium equations"),
                "{name} {method}"
            );
            assert!(text.contains("## Step 6. At rest"), "{name} {method}");
        }
    }
}

#[test]
fn the_statics_handout_writes_the_numbers_of_statics() {
    for name in PROBLEMS {
        for method in METHODS {
            let text = explain(name, &["--statics", "--method", method]);
            let json = statics_json(name, method);
            let e = &json["equilibria"][0];
            for (coordinate, q) in e["state"].as_object().unwrap() {
                writes(
                    &text,
                    q.as_f64().unwrap(),
                    &format!("{name} {method} {coordinate}"),
                );
            }
            for (site, r) in e["reactions"].as_object().unwrap() {
                for x in r["force"].as_array().unwrap() {
                    writes(
                        &text,
                        x.as_f64().unwrap(),
                        &format!("{name} {method} {site}"),
                    );
                }
            }
            for (held, x) in e["held"].as_object().unwrap() {
                writes(
                    &text,
                    x.as_f64().unwrap(),
                    &format!("{name} {method} {held}"),
                );
            }
            if let Some(friction) = e["friction"].as_object() {
                for (site, f) in friction {
                    let what = format!("{name} {method} {site}");
                    writes(&text, f["normal"].as_f64().unwrap(), &what);
                    writes(&text, f["ratio"].as_f64().unwrap(), &what);
                }
            }
            if let Some(kind) = e["stability"].as_str() {
                // Neutral where friction locks the configuration: said so in words.
                let locked = kind == "neutral" && text.contains("no coordinate can move");
                assert!(
                    locked || text.contains(&format!("The equilibrium is {kind}")),
                    "{name} {method}: stability {kind}"
                );
            }
        }
    }
}

#[test]
fn the_ladder_handout_gives_the_reactions_and_the_angle_of_impending_slip() {
    // m = 10 kg, μ = 0.3, at α = 25°: the floor carries m g, the wall m g tan α / 2, which
    // friction balances; slip impends at tan α = 2μ.
    let (m, mu, alpha) = (10.0, 0.3, 25f64.to_radians());
    let wall = m * G * alpha.tan() / 2.0;
    for method in METHODS {
        let text = explain("statics-ladder", &["--statics", "--method", method]);
        writes(&text, m * G, "floor's normal force");
        writes(&text, wall, "wall's normal force");
        writes(&text, alpha.tan() / (2.0 * mu), "|F|/(μ|N|)");
        writes(&text, (2.0 * mu).atan(), "the angle of impending slip");
        assert!(text.contains("friction holds it"), "{method}");
    }
}

/// The root of k θ = m g d sin θ in (0.1, π), by bisection.
fn torsion_root(k: f64, mgd: f64) -> f64 {
    let f = |t: f64| k * t - mgd * t.sin();
    let (mut lo, mut hi) = (0.1, std::f64::consts::PI);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(lo) * f(mid) <= 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn the_torsion_pendulum_rests_where_k_theta_equals_m_g_d_sin_theta() {
    // m = 2 kg, L = 1 m (d = L/2), k = 7 N m/rad: found by Newton's method from θ = 1.
    let (m, d, k) = (2.0, 0.5, 7.0);
    let theta = torsion_root(k, m * G * d);
    // Stable: the stiffness k − m g d cos θ is positive there.
    assert!(k - m * G * d * theta.cos() > 0.0);
    for method in METHODS {
        let text = explain(
            "statics-torsion-pendulum",
            &["--statics", "--method", method],
        );
        writes(&text, theta, "θ");
        assert!(text.contains("Newton's method"), "{method}");
        assert!(text.contains("The equilibrium is stable"), "{method}");
        // The pin carries the weight alone.
        writes(&text, m * G, "the pin's vertical force");
    }
}

/// The plan table's rows of the Motion Law's handout: (free body, equation) cells.
fn plan_rows(text: &str) -> Vec<(String, String)> {
    let start = text.find("## Step 3. The plan").expect("step 3");
    let end = text[start..]
        .find("## Step 4")
        .map_or(text.len(), |e| start + e);
    text[start..end]
        .lines()
        .filter(|l| l.starts_with("| $"))
        .map(|l| {
            let cells: Vec<&str> = l.split('|').map(str::trim).collect();
            (cells[1].to_string(), cells[2].to_string())
        })
        .collect()
}

#[test]
fn the_planner_takes_moments_about_the_ladder_foot_and_the_four_bar_pins() {
    let ladder = explain("statics-ladder", &["--statics"]);
    let rows = plan_rows(&ladder);
    assert!(
        rows.iter()
            // The foot's contact with the floor, printed by its letter P.
            .any(|(_, e)| e.contains("\\mathbf{M}_{P}")),
        "the ladder's moments about its foot: {rows:?}"
    );
    let four_bar = explain("statics-four-bar-held", &["--statics"]);
    let rows = plan_rows(&four_bar);
    // Each link about a pin: the coupler about one of its pins, the rocker about Q.
    let about = |pin: &str| {
        rows.iter()
            .any(|(_, e)| e.contains(&format!("\\mathbf{{M}}_{{{pin}}}")))
    };
    assert!(
        about("Q") || about("R"),
        "the four-bar's moments about its pins: {rows:?}"
    );
}

#[test]
fn the_student_statics_handout_leaves_the_work_blank() {
    for name in ["statics-ladder", "statics-torsion-pendulum"] {
        for method in METHODS {
            let text = explain(name, &["--statics", "--student", "--method", method]);
            for word in MOTION {
                assert!(!text.contains(word), "{name} {method}: writes `{word}`");
            }
            assert!(text.contains("## Step 6. At rest"));
            assert!(
                !text.contains("Newton's method"),
                "{name} {method}: the solution is given"
            );
        }
    }
    // The torsion pendulum's equilibrium is the answer: the student's page does not give it.
    let theta = torsion_root(7.0, 2.0 * G * 0.5);
    let text = explain("statics-torsion-pendulum", &["--statics", "--student"]);
    assert!(!numbers(&text).iter().any(|x| (x - theta).abs() < 1e-5));
}

#[test]
fn every_statics_handout_compiles_in_latex() {
    if !pdflatex_present("the statics handouts") {
        return;
    }
    let dir = std::env::temp_dir().join(format!("mbd-statics-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch");
    let jobs: Vec<(&str, &str)> = PROBLEMS
        .iter()
        .flat_map(|name| METHODS.iter().map(move |method| (*name, *method)))
        .collect();
    // Both versions of a handout from one run, set two handouts at a time.
    let failed = two_at_a_time(&jobs, |&(name, method)| {
        let stem = format!("{}-{method}", name.replace('/', "-"));
        let file = dir.join(format!("{stem}.tex"));
        let path = problem(name);
        let out = run(&[
            "explain".as_ref(),
            path.as_os_str(),
            "--statics".as_ref(),
            "--both".as_ref(),
            "--method".as_ref(),
            method.as_ref(),
            "--format".as_ref(),
            "latex".as_ref(),
            "-o".as_ref(),
            file.as_os_str(),
        ]);
        if !out.status.success() {
            return vec![format!("{stem}: {}", String::from_utf8_lossy(&out.stderr))];
        }
        [file.clone(), dir.join(format!("{stem}-student.tex"))]
            .iter()
            .map(|tex| (tex, pdflatex(tex)))
            .filter(|(_, typeset)| !typeset.compiled())
            .map(|(tex, typeset)| {
                format!("{} does not compile: {}", tex.display(), typeset.faults())
            })
            .collect()
    });
    assert!(failed.is_empty(), "{}", failed.join("\n"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_statics_handout_is_the_same_twice() {
    for format in ["markdown", "latex", "html"] {
        let path = problem("statics-four-bar-held");
        let args = [
            "explain".as_ref(),
            path.as_os_str(),
            "--statics".as_ref(),
            "--format".as_ref(),
            format.as_ref(),
        ];
        let (first, second) = (run_afresh(&args), run_afresh(&args));
        assert!(first.status.success(), "{format}: explain failed");
        assert!(first.stdout == second.stdout, "{format}: two runs differ");
    }
}

/// The speeds `v = …` a handout writes for the weave and the capsize speeds.
fn critical_speeds(text: &str) -> Vec<f64> {
    text.lines()
        .filter(|line| line.contains("\\mathrm{m/s} \\quad \\text{(stable"))
        .flat_map(|line| line.split("v = ").skip(1))
        .filter_map(|after| after.split('\\').next()?.parse().ok())
        .collect()
}

/// The eigenvalues of the stability paragraph (`\lambda_{1} = -5.53094`, …), in the order
/// written.
fn eigenvalues(text: &str) -> Vec<f64> {
    let line = text
        .lines()
        .find(|line| line.starts_with("**Stability.**"))
        .expect("a stability paragraph");
    let listed = line.split("Eigenvalues:").nth(1).unwrap_or_default();
    listed
        .split(" = ")
        .skip(1)
        .filter_map(|value| value.split('$').next()?.trim().parse().ok())
        .collect()
}

/// The Whipple bicycle at rest by Kane's and Lagrange's equations: the equilibrium
/// equations of a problem this large are brought to rest in seconds, and the handout
/// gives the paper's weave and capsize speeds (Meijaard et al. 2007: 4.29 and 6.02 m/s)
/// and the eigenvalues the Motion Law's handout gives.
#[test]
fn the_bicycle_at_rest_by_kane_and_lagrange_agrees_with_the_paper_and_the_motion_law() {
    let name = "validation/whipple-bicycle";
    let motion_law = eigenvalues(&explain(name, &["--statics", "--method", "motion-law"]));
    assert_eq!(motion_law.len(), 10, "{motion_law:?}");
    for method in ["kane", "lagrange"] {
        let text = explain(name, &["--statics", "--method", method]);
        let speeds = critical_speeds(&text);
        assert_eq!(speeds.len(), 2, "{method}: {speeds:?}");
        assert!(
            (speeds[0] - 4.29).abs() < 0.005,
            "{method}: weave {}",
            speeds[0]
        );
        assert!(
            (speeds[1] - 6.02).abs() < 0.005,
            "{method}: capsize {}",
            speeds[1]
        );
        let found = eigenvalues(&text);
        assert_eq!(found.len(), motion_law.len(), "{method}: {found:?}");
        for (x, y) in found.iter().zip(&motion_law) {
            assert!(
                (x - y).abs() <= 1e-5 * y.abs().max(1.0),
                "{method}: {x} against {y}"
            );
        }
    }
}
