//! Coulomb friction against closed forms worked by hand: a block on a rough incline
//! (sticks for tan α ≤ μ, else slides with a = g(sin α − μ cos α)), a ladder against a
//! smooth wall on a rough floor (holds at rest iff tan θ ≤ 2μ), and a bowling ball that
//! skids before it rolls (a solid sphere rolls after t = 2v₀/(7μg), a disc after v₀/(3μg)).

use crate::support::{
    assert_close, column, friction_site, number, problem, run, solve_all, table, METHODS,
};
use serde_json::Value;

const G: f64 = 9.81;

// ---- a block on a rough incline (`problems/block-on-rough-incline.json`) ----

const BLOCK_MASS: f64 = 2.0;
const SLOPE: f64 = std::f64::consts::PI / 6.0;

#[test]
fn a_block_on_a_rough_incline_slides_with_a_equal_to_g_sin_minus_mu_cos() {
    let mu = 0.4_f64;
    assert!(SLOPE.tan() > mu, "the case slides");
    let a = G * (SLOPE.sin() - mu * SLOPE.cos());
    let normal = BLOCK_MASS * G * SLOPE.cos();
    for s in solve_all("block-on-rough-incline", &[]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("x"), a, 1e-9, 1.0, &what("x''"));
        let site = friction_site(&s.json, "plane");
        assert_eq!(site["mode"], "slip", "{}", what("mode"));
        assert_close(number(site, "normal"), normal, 1e-9, 1.0, &what("N"));
        assert_close(
            number(site, "tangential"),
            mu * normal,
            1e-9,
            1.0,
            &what("|F|"),
        );
        assert_close(number(site, "ratio"), mu, 1e-9, 1.0, &what("|F|/|N|"));
        // Friction acts up the slope, against the motion that starts.
        assert_close(
            s.force("plane")[0],
            -mu * normal,
            1e-9,
            1.0,
            &what("F along N.x"),
        );
    }
}

#[test]
fn a_block_on_a_rough_incline_sticks_while_tan_alpha_is_at_most_mu() {
    let mu = 0.6_f64;
    assert!(SLOPE.tan() <= mu, "the case sticks");
    for s in solve_all("block-on-rough-incline", &["--set", "mu=0.6"]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("x"), 0.0, 1e-9, 1.0, &what("x''"));
        let site = friction_site(&s.json, "plane");
        assert_eq!(site["mode"], "stick", "{}", what("mode"));
        assert_close(
            number(site, "tangential"),
            BLOCK_MASS * G * SLOPE.sin(),
            1e-9,
            1.0,
            &what("|F|"),
        );
        assert_close(
            number(site, "ratio"),
            SLOPE.tan(),
            1e-9,
            1.0,
            &what("ratio"),
        );
    }
}

#[test]
fn the_block_changes_from_sticking_to_sliding_at_tan_alpha_equal_to_mu() {
    let critical = SLOPE.tan();
    for (mu, mode) in [(critical + 1e-6, "stick"), (critical - 1e-6, "slip")] {
        let set = format!("mu={mu}");
        for s in solve_all("block-on-rough-incline", &["--set", &set]) {
            assert_eq!(
                friction_site(&s.json, "plane")["mode"],
                mode,
                "{} at μ = {mu}",
                s.method
            );
            let a = if mode == "slip" {
                G * (SLOPE.sin() - mu * SLOPE.cos())
            } else {
                0.0
            };
            assert_close(s.acc("x"), a, 1e-9, 1.0, &format!("{}: x''", s.method));
        }
    }
}

#[test]
fn a_block_thrown_up_the_incline_stops_and_sticks_when_mu_holds_it() {
    // Up the slope at 2 m/s with μ = 0.7 > tan α: it slows at g(sin α + μ cos α) and stops
    // for good at t = v/(g(sin α + μ cos α)).
    let mu = 0.7_f64;
    let v = 2.0;
    let stop = v / (G * (SLOPE.sin() + mu * SLOPE.cos()));
    let out = run(&[
        "simulate".as_ref(),
        problem("block-on-rough-incline").as_os_str(),
        "--set".as_ref(),
        "mu=0.7,v=2".as_ref(),
        "--no-checks".as_ref(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let t = switch_time(
        &String::from_utf8_lossy(&out.stderr),
        "plane stops slipping (sticks)",
    );
    assert_close(t, stop, 1e-8, 1.0, "the instant the block stops");
}

// ---- a ladder against a smooth wall on a rough floor ----

const LADDER_MASS: f64 = 10.0;
const HALF: f64 = 1.5;
const LADDER_MU: f64 = 0.3;

/// By hand, sliding from rest at angle θ from the vertical (mid-point at (ℓ sin θ, ℓ cos θ),
/// I = mℓ²/3, floor normal N, friction μN toward the wall, wall push P):
/// m x'' = P − μN, m y'' = N − mg, I θ'' = ℓN(sin θ − μ cos θ) − ℓP cos θ; with θ' = 0,
/// x'' = ℓ cos θ θ'', y'' = −ℓ sin θ θ'', so
/// θ'' = g (sin θ − 2μ cos θ) / (ℓ (4/3 − 2μ sin θ cos θ)).
fn ladder_sliding(theta: f64) -> (f64, f64, f64) {
    let (s, c) = theta.sin_cos();
    let alpha = G * (s - 2.0 * LADDER_MU * c) / (HALF * (4.0 / 3.0 - 2.0 * LADDER_MU * s * c));
    let normal = LADDER_MASS * (G - HALF * s * alpha);
    let wall = LADDER_MASS * HALF * c * alpha + LADDER_MU * normal;
    (alpha, normal, wall)
}

#[test]
fn a_ladder_at_rest_holds_while_tan_theta_is_at_most_two_mu() {
    let theta = 0.5_f64;
    assert!(theta.tan() <= 2.0 * LADDER_MU);
    for s in solve_all("ladder-about-to-slip", &["--state", "theta=0.5"]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("theta"), 0.0, 1e-9, 1.0, &what("theta''"));
        let floor = friction_site(&s.json, "floor");
        assert_eq!(floor["mode"], "stick", "{}", what("mode"));
        // Moments about the foot: the wall pushes mg tan θ / 2, which friction balances.
        let push = LADDER_MASS * G * theta.tan() / 2.0;
        assert_close(
            number(floor, "tangential"),
            push,
            1e-9,
            1.0,
            &what("friction"),
        );
        assert_close(
            number(floor, "normal"),
            LADDER_MASS * G,
            1e-9,
            1.0,
            &what("N"),
        );
        assert_close(s.force("wall")[0], push, 1e-9, 1.0, &what("wall"));
    }
}

#[test]
fn a_ladder_just_past_the_angle_slides_as_worked_by_hand() {
    let theta = 0.5410520681182421_f64;
    assert!(theta.tan() > 2.0 * LADDER_MU, "past tan θ = 2μ");
    let (alpha, normal, wall) = ladder_sliding(theta);
    for s in solve_all("ladder-about-to-slip", &[]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("theta"), alpha, 1e-9, 1.0, &what("theta''"));
        assert_close(
            s.acc("x"),
            HALF * theta.cos() * alpha,
            1e-9,
            1.0,
            &what("x''"),
        );
        assert_close(
            s.acc("y"),
            -HALF * theta.sin() * alpha,
            1e-9,
            1.0,
            &what("y''"),
        );
        let floor = friction_site(&s.json, "floor");
        assert_eq!(floor["mode"], "slip", "{}", what("mode"));
        assert_close(number(floor, "normal"), normal, 1e-9, 1.0, &what("N"));
        assert_close(number(floor, "ratio"), LADDER_MU, 1e-9, 1.0, &what("ratio"));
        assert_close(s.force("wall")[0], wall, 1e-9, 1.0, &what("wall"));
    }
}

#[test]
fn the_ladder_starts_to_slip_at_tan_theta_equal_to_two_mu() {
    let critical = (2.0 * LADDER_MU).atan();
    for (theta, mode) in [(critical - 1e-4, "stick"), (critical + 1e-4, "slip")] {
        let state = format!("theta={theta}");
        for s in solve_all("ladder-about-to-slip", &["--state", &state]) {
            assert_eq!(
                friction_site(&s.json, "floor")["mode"],
                mode,
                "{} at θ = {theta}",
                s.method
            );
            let want = if mode == "slip" {
                ladder_sliding(theta).0
            } else {
                0.0
            };
            assert_close(
                s.acc("theta"),
                want,
                1e-9,
                1.0,
                &format!("{}: theta''", s.method),
            );
        }
    }
}

// ---- a bowling ball that skids before it rolls ----

const BALL_MASS: f64 = 7.0;
const RADIUS: f64 = 0.11;
const BALL_MU: f64 = 0.2;
const V0: f64 = 8.0;

/// The time of the first switch line naming `what` on standard error.
fn switch_time(stderr: &str, what: &str) -> f64 {
    let line = stderr
        .lines()
        .find(|l| l.contains(what))
        .unwrap_or_else(|| panic!("no switch `{what}` in:\n{stderr}"));
    line.trim_start_matches("t = ")
        .split(" s:")
        .next()
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("no time in `{line}`"))
}

/// `simulate` of `path` by `method`: the switch time on standard error, the columns and rows.
fn simulate_ball(path: &std::path::Path, method: &str) -> (f64, Vec<String>, Vec<Vec<f64>>) {
    let out = run(&[
        "simulate".as_ref(),
        path.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
        "--method".as_ref(),
        method.as_ref(),
        "--no-checks".as_ref(),
    ]);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(out.status.success(), "{method}: {stderr}");
    let t = switch_time(&stderr, "lane stops slipping (rolls)");
    let json: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let (columns, rows) = table(&json);
    (t, columns, rows)
}

/// Slipping: m x'' = −μmg, I θ'' = −μmgR, so the contact's slip velocity x' + Rθ' falls at
/// μg(1 + mR²/I) from v₀ and reaches 0 at t = v₀/(μg(1 + mR²/I)); the friction's work until
/// then is −μmg v₀ t/2, the energy lost.
fn check_ball(path: &std::path::Path, inertia_factor: f64) {
    let factor = 1.0 + 1.0 / inertia_factor;
    let t_roll = V0 / (BALL_MU * G * factor);
    let work = -BALL_MU * BALL_MASS * G * V0 * t_roll / 2.0;
    let mut times = Vec::new();
    for method in METHODS {
        let (t, columns, rows) = simulate_ball(path, method);
        let what = |q: &str| format!("{method}: {q}");
        assert_close(t, t_roll, 1e-8, 1.0, &what("the instant it rolls"));
        times.push(t);
        let at = |name: &str| column(&columns, name);
        let (time, xd, td, xdd) = (at("t"), at("x'"), at("theta'"), at("x''"));
        let (total, push) = (at("total"), at("lane.force.x"));
        let last = rows.last().expect("rows");
        let lost = last[total] - rows[0][total];
        assert_close(
            lost,
            work,
            1e-7,
            1.0,
            &what("energy lost = friction's work"),
        );
        // The friction's work from the table, trapezoid over the output rows.
        let power = |r: &[f64]| r[push] * (r[xd] + RADIUS * r[td]);
        let by_rows: f64 = rows
            .windows(2)
            .map(|w| (w[1][time] - w[0][time]) * (power(&w[0]) + power(&w[1])) / 2.0)
            .sum();
        assert_close(by_rows, work, 1e-4, 1.0, &what("∫ F·v_slip dt"));
        for r in &rows {
            if r[time] < t_roll - 1e-6 {
                assert_close(r[xdd], -BALL_MU * G, 1e-9, 1.0, &what("x'' while slipping"));
            } else if r[time] > t_roll + 1e-6 {
                assert_close(r[xd] + RADIUS * r[td], 0.0, 1e-8, 1.0, &what("rolls"));
                assert_close(r[xd], V0 - BALL_MU * G * t_roll, 1e-8, 1.0, &what("speed"));
            }
        }
    }
    for t in &times {
        assert_close(
            *t,
            times[0],
            1e-9,
            1.0,
            "every method switches at one instant",
        );
    }
}

#[test]
fn a_skidding_bowling_ball_rolls_after_two_v0_over_seven_mu_g() {
    assert_close(
        V0 / (BALL_MU * G * 3.5),
        2.0 * V0 / (7.0 * BALL_MU * G),
        1e-15,
        1.0,
        "the factor",
    );
    check_ball(&problem("bowling-ball"), 0.4);
    for s in solve_all("bowling-ball", &[]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("x"), -BALL_MU * G, 1e-9, 1.0, &what("x''"));
        assert_close(
            s.acc("theta"),
            -BALL_MU * G / (0.4 * RADIUS),
            1e-9,
            1.0,
            &what("theta''"),
        );
        assert_eq!(
            friction_site(&s.json, "lane")["mode"],
            "slip",
            "{}",
            what("mode")
        );
    }
}

#[test]
fn a_skidding_disc_rolls_after_v0_over_three_mu_g() {
    let text = std::fs::read_to_string(problem("bowling-ball")).expect("the problem");
    let disc = text.replace("\"2*m*R^2/5\"", "\"m*R^2/2\"");
    assert_ne!(disc, text, "the inertia was replaced");
    let path = std::env::temp_dir().join(format!("skidding-disc-{}.json", std::process::id()));
    std::fs::write(&path, disc).expect("a temporary file");
    check_ball(&path, 0.5);
    let _ = std::fs::remove_file(&path);
}

#[test]
fn a_ball_that_already_rolls_keeps_rolling_with_no_friction() {
    let state = format!("theta'={}", -V0 / RADIUS);
    for s in solve_all("bowling-ball", &["--state", &state]) {
        let lane = friction_site(&s.json, "lane");
        assert_eq!(lane["mode"], "stick", "{}", s.method);
        assert_close(
            number(lane, "tangential"),
            0.0,
            1e-9,
            1.0,
            "no friction needed",
        );
        assert_close(s.acc("x"), 0.0, 1e-9, 1.0, "x''");
    }
}

// ---- bad input ----

fn check_fails(json: &str, path_fragment: &str) {
    let file = std::env::temp_dir().join(format!(
        "friction-bad-{}-{}.json",
        std::process::id(),
        path_fragment.replace(['[', ']', '.', ':', ' '], "_")
    ));
    std::fs::write(&file, json).expect("a temporary file");
    for command in ["check", "solve"] {
        let out = run(&[command.as_ref(), file.as_os_str()]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{command}: {stderr}");
        assert!(
            stderr.contains(path_fragment),
            "{command}: no `{path_fragment}` in {stderr}"
        );
        assert!(stderr.contains("hint"), "{command}: no hint in {stderr}");
    }
    let _ = std::fs::remove_file(&file);
}

#[test]
fn negative_friction_and_a_zero_normal_are_refused_with_their_paths() {
    let text = std::fs::read_to_string(problem("block-on-rough-incline")).expect("problem");
    check_fails(
        &text.replace("\"friction\": \"mu\"", "\"friction\": \"-mu\""),
        "constraints[0].friction",
    );
    check_fails(
        &text.replace("\"normal\": \"N.y\"", "\"normal\": \"0*N.y\""),
        "constraints[0].normal: the normal is the zero vector",
    );
    check_fails(
        &text.replace(
            "\"body\": \"B\", \"on\"",
            "\"body\": \"B\", \"slope\": 1, \"on\"",
        ),
        "constraints[0].slope",
    );
}

/// The worked solution says when the ball starts to roll, the statement's third question:
/// the Answers give the instant, 2v₀/(7μg), and step 6 does not say it again.
#[test]
fn the_bowling_ball_handout_says_when_it_starts_to_roll() {
    let text = crate::support::explain("bowling-ball", &["--method", "kane"]);
    // Asked in the Answers, the instant is said there once, not again in step 6.
    assert!(!text.contains("Friction changes its mode"), "{text}");
    let answers = &text[text.find("## Answers").expect("answers")..];
    let lead = "stops slipping and starts to roll: $t = ";
    let t: f64 = answers[answers.find(lead).expect("the instant") + lead.len()..]
        .split("\\ ")
        .next()
        .and_then(|t| t.parse().ok())
        .expect("a time");
    // Printed to six figures; `answer --format json` gives it in full (tested below).
    assert_close(
        t,
        2.0 * V0 / (7.0 * BALL_MU * G),
        1e-5,
        1.0,
        "the instant it rolls",
    );
}

/// `"at": { "switch": "lane" }`: the bowling ball's answers at the instant it starts to
/// roll are that instant, 2v₀/(7μg), and the speed then, 5v₀/7 (friction −μmg slows the
/// centre, its moment μmgR spins the ball up, until v = −Rθ̇).
#[test]
fn the_answers_say_when_the_ball_rolls_and_how_fast_it_moves_then() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems/bowling-ball.json");
    let out = run(&[
        "answer".as_ref(),
        path.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let answers = json["answers"].as_array().expect("answers");
    let at_switch: Vec<&Value> = answers.iter().filter(|a| a["switch"] == "lane").collect();
    assert_eq!(at_switch.len(), 2);
    let t_roll = 2.0 * V0 / (7.0 * BALL_MU * G);
    assert_close(
        number(at_switch[0], "value"),
        t_roll,
        1e-7,
        1.0,
        "t at rolling",
    );
    let speed = 5.0 * V0 / 7.0;
    assert_close(
        number(at_switch[1], "value"),
        speed,
        1e-7,
        1.0,
        "v at rolling",
    );
    assert_close(
        number(at_switch[1], "time"),
        t_roll,
        1e-7,
        1.0,
        "its instant",
    );
}

/// A switch asked of a site without friction is refused with the question's path.
#[test]
fn a_switch_of_a_smooth_site_is_refused_with_its_path() {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems/cylinder-on-incline.json");
    let mut json: Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("reads")).expect("JSON");
    let site = json["constraints"][0]["name"].clone();
    json["find"]["questions"] = serde_json::json!([{ "value": "t", "at": { "switch": site } }]);
    let file = std::env::temp_dir().join(format!("smooth-switch-{}.json", std::process::id()));
    std::fs::write(&file, json.to_string()).expect("writes");
    let out = run(&["answer".as_ref(), file.as_os_str()]);
    let _ = std::fs::remove_file(&file);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("find.questions[0].at.switch"), "{stderr}");
    assert!(stderr.contains("hint"), "{stderr}");
}
