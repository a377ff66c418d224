//! Six more problems the bundled set does not hold, each against a closed form worked
//! here, by every method: a block on a wedge tied to a wall by a spring (two coordinates,
//! a spring in V), a particle swinging on a spring (the elastic pendulum, its acceleration
//! along the swinging line's unit vectors, and a student's row with the centripetal term
//! left out), a ladder on a rough floor climbed by a person (`slips`, `impending` on the
//! person's distance, no coordinate marked dependent), a hanging rod swinging into a stop
//! (`impact`, the centre of percussion), a bead on a hoop spun about its vertical diameter
//! (a student's row without the spin named), and a toggle held at an angle against a
//! load on its slider (`held`, the closure's coordinates solved unmarked).

use super::{at, close, command, fixture, graded, solve_each, triple};
use crate::support::METHODS;
use serde_json::json;

const G: f64 = 9.81;

/// `explain` of tests/fresh_problems/NAME.json with `args`: its standard output.
fn explained(name: &str, args: &[&str]) -> String {
    let path = fixture(name);
    let mut all = vec![std::ffi::OsStr::new("explain"), path.as_os_str()];
    all.extend(args.iter().map(std::ffi::OsStr::new));
    let out = crate::support::run(&all);
    assert!(
        out.status.success(),
        "{name}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// The wedge (M, X along N.x, tied to the wall by k: V = ½ k X²) and the block (m, s down
/// the smooth incline of angle α): (M + m) Ẍ + m cos α s̈ = −k X and
/// cos α Ẍ + s̈ = g sin α, so Ẍ = −(k X + m g sin α cos α)/(M + m sin²α) and
/// s̈ = g sin α − cos α Ẍ. The incline pushes the block along its normal (sin α, cos α)
/// with N = m g cos α + m Ẍ sin α (the block's acceleration along that normal is Ẍ sin α).
#[test]
fn a_block_on_a_sprung_wedge_by_every_method() {
    let (mm, m, al, k, x) = (5.0, 2.0, 0.5f64, 60.0, 0.1);
    let (s, c) = al.sin_cos();
    let xdd = -(k * x + m * G * s * c) / (mm + m * s * s);
    let sdd = G * s - c * xdd;
    let normal = m * G * c + m * xdd * s;
    for sol in solve_each("block-on-sprung-wedge", &[]) {
        let what = format!("{}: sprung wedge", sol["method"]);
        close(at(&sol, &["accelerations", "X"]), xdd, &what);
        close(at(&sol, &["accelerations", "s"]), sdd, &what);
        let f = triple(&sol["reactions"]["incline"]["force"]);
        close(f[0], normal * s, &what);
        close(f[1], normal * c, &what);
    }
    for method in METHODS {
        let a = command("answer", "block-on-sprung-wedge", method, &[]);
        let what = format!("{method}: sprung wedge's answers");
        close(at(&a["answers"][0], &["value"]), xdd, &what);
        close(at(&a["answers"][1], &["value"]), sdd, &what);
        let push = &a["answers"][2];
        assert_eq!(push["frame"], "W", "{what}: {push}");
        close(at(push, &["components", "x"]), normal * s, &what);
        close(at(push, &["components", "y"]), normal * c, &what);
    }
}

/// Lagrange's V of the wedge is ½ k X², the spring's stretch squared, not multiplied out.
#[test]
fn a_springs_potential_is_half_k_times_its_stretch_squared() {
    let text = explained("block-on-sprung-wedge", &["--method", "lagrange"]);
    let v = (text.lines().map(str::trim))
        .find(|l| l.starts_with("V = "))
        .unwrap_or_else(|| panic!("no line of V in {text}"));
    assert!(v.contains("\\frac{1}{2} k X^{2}"), "½ k X² in {v}");
    let text = explained("elastic-pendulum", &["--method", "lagrange"]);
    let v = (text.lines().map(str::trim))
        .find(|l| l.starts_with("V = "))
        .unwrap_or_else(|| panic!("no line of V in {text}"));
    assert!(
        v.contains("\\frac{1}{2} k (r - l_{0})^{2}"),
        "½ k (r − l₀)² in {v}"
    );
    let text = crate::support::explain("two-mass-spring-damper", &["--method", "lagrange"]);
    let v = (text.lines().map(str::trim))
        .find(|l| l.starts_with("V = "))
        .unwrap_or_else(|| panic!("no line of V in {text}"));
    assert!(
        v.contains("\\frac{1}{2} k_{1} x_{1}^{2} + \\frac{1}{2} k_{2} (x_{2} - x_{1})^{2}"),
        "½ k₁ x₁² + ½ k₂ (x₂ − x₁)² in {v}"
    );
}

/// The particle (m) at distance r from the pivot, θ from the downward vertical, on a
/// spring k of free length l₀: r̈ = r θ̇² + g cos θ − (k/m)(r − l₀) and
/// θ̈ = −(g sin θ + 2 ṙ θ̇)/r. Its acceleration along the line's unit vectors (â_x across
/// the line, â_y from the particle to the pivot) is (r θ̈ + 2 ṙ θ̇, −(r̈ − r θ̇²)); its
/// small swings and bounces about the hanging equilibrium have the periods of a pendulum
/// of length r₀ and of a mass on a spring.
#[test]
fn an_elastic_pendulum_by_every_method_with_its_acceleration_along_the_line() {
    let (m, k, l0, th, w, r, v) = (0.5, 40.0, 0.8, 0.4f64, 1.5, 0.9, -0.3);
    let rdd = r * w * w + G * th.cos() - k / m * (r - l0);
    let thdd = -(G * th.sin() + 2.0 * v * w) / r;
    for sol in solve_each("elastic-pendulum", &[]) {
        let what = format!("{}: elastic pendulum", sol["method"]);
        close(at(&sol, &["accelerations", "r"]), rdd, &what);
        close(at(&sol, &["accelerations", "theta"]), thdd, &what);
    }
    for method in METHODS {
        let a = command("answer", "elastic-pendulum", method, &[]);
        let what = format!("{method}: elastic pendulum's answers");
        close(at(&a["answers"][0], &["value"]), thdd, &what);
        close(at(&a["answers"][1], &["value"]), rdd, &what);
        let acc = &a["answers"][2];
        assert_eq!(acc["frame"], "A", "{what}: {acc}");
        close(at(acc, &["components", "x"]), r * thdd + 2.0 * v * w, &what);
        close(at(acc, &["components", "y"]), -(rdd - r * w * w), &what);
        // Hanging at r₀ = l₀ + m g/k: it swings at √(g/r₀) and bounces at √(k/m).
        let r0 = l0 + m * G / k;
        close(r0, 0.922625, "the equilibrium the questions give");
        let swing = 2.0 * std::f64::consts::PI / (G / r0).sqrt();
        let bounce = 2.0 * std::f64::consts::PI / (k / m).sqrt();
        assert_eq!(a["answers"][3]["kind"], "period", "{what}");
        close(at(&a["answers"][3], &["value"]), swing, &what);
        close(at(&a["answers"][4], &["value"]), bounce, &what);
    }
}

/// A student's pair of equations for the elastic pendulum, both right, with the spring's
/// force k (r − l₀) as a course writes it for r > 0; then the stretch's without the
/// centripetal term m r θ̇², which the diagnosis names.
#[test]
fn grade_names_the_centripetal_term_a_student_left_out() {
    let submission = json!({
        "student": "s9",
        "equations": [
            "r*theta'' + 2*r'*theta' + g*sin(theta) = 0",
            "m*r'' - m*g*cos(theta) + k*(r - l0) = 0"
        ]
    });
    let right = json!({
        "student": "s1",
        "equations": [
            "r*theta'' + 2*r'*theta' + g*sin(theta) = 0",
            "m*r'' - m*r*theta'^2 - m*g*cos(theta) + k*(r - l0) = 0"
        ]
    });
    for method in METHODS {
        let g = graded("elastic-pendulum", &right, method);
        for item in g["items"].as_array().expect("items") {
            assert_eq!(item["verdict"], "right", "{method}: {g}");
        }
        let g = graded("elastic-pendulum", &submission, method);
        let items = g["items"].as_array().expect("items");
        let item = |name: &str| {
            (items.iter())
                .find(|i| i["item"] == name)
                .unwrap_or_else(|| panic!("{method}: no item {name} in {g}"))
        };
        assert_eq!(item("equations[0]")["verdict"], "right", "{method}: {g}");
        let wrong = item("equations[1]");
        assert_eq!(wrong["verdict"], "wrong", "{method}: {g}");
        let why = wrong["diagnosis"].as_str().expect("diagnosis");
        assert!(
            why.contains("theta'^2") && why.contains("missing"),
            "{method}: names the θ̇² term as missing: {why}"
        );
        // Its spring term k (r − l₀) is right while r > 0, as a distance is.
        assert!(!why.contains("sign(r)"), "{method}: {why}");
        assert!(!why.contains("sqrt"), "{method}: {why}");
    }
}

/// The ladder (m, L, at angle b to the floor, rough floor μ, smooth wall) with a person
/// (M) at distance d from its foot. About the foot: the wall pushes
/// N_w = (m L/2 + M d) g cos b/(L sin b); the floor holds the foot back by F = N_w and
/// pushes (m + M) g. Slip impends when N_w = μ (m + M) g:
/// d* = (μ (m + M) L tan b − m L/2)/M.
#[test]
fn a_ladder_climbed_by_a_person_slips_past_a_distance_up_it() {
    let (m, mm, l, b, mu) = (10.0, 70.0, 4.0, 1.1f64, 0.4);
    let wall = |d: f64| (m * l / 2.0 + mm * d) * G * b.cos() / (l * b.sin());
    let ratio = |d: f64| wall(d) / (mu * (m + mm) * G);
    let far = (mu * (m + mm) * l * b.tan() - m * l / 2.0) / mm;
    for method in METHODS {
        let what = format!("{method}: ladder");
        let s = command("statics", "ladder-climbed-on-rough-floor", method, &[]);
        let eq = &s["equilibria"][0];
        close(at(eq, &["state", "theta"]), std::f64::consts::PI - b, &what);
        close(at(eq, &["state", "x"]), l / 2.0 * b.cos(), &what);
        let foot = triple(&eq["reactions"]["foot"]["force"]);
        close(foot[0], -wall(1.5), &what);
        close(foot[1], (m + mm) * G, &what);
        close(
            triple(&eq["reactions"]["top"]["force"])[0],
            wall(1.5),
            &what,
        );
        close(at(&eq["friction"]["foot"], &["ratio"]), ratio(1.5), &what);
        for d in [1.5, 3.6] {
            let set = format!("d={d}");
            let a = command(
                "answer",
                "ladder-climbed-on-rough-floor",
                method,
                &["--set", &set],
            );
            let slips = &a["answers"][0];
            assert_eq!(slips["kind"], "slips", "{what}: {slips}");
            assert_eq!(slips["value"], ratio(d) > 1.0, "{what}, {set}: {slips}");
            close(at(slips, &["ratio"]), ratio(d), &format!("{what}, {set}"));
            close(at(&a["answers"][1], &["value"]), far, &what);
        }
    }
    // Nothing marked dependent: the handout is written all the same.
    let text = explained("ladder-climbed-on-rough-floor", &["--method", "lagrange"]);
    assert!(
        text.contains("## Answers"),
        "the ladder's handout has answers"
    );
}

/// The rod (m, L, pinned at its top O, I_O = m L²/3) swings through the vertical at ω₀
/// into a stop at distance p below O (restitution e). About O: I_O (ω⁺ − ω₀) = −p P with
/// ω⁺ = −e ω₀, so P = I_O (1 + e) ω₀/p; the pin's impulse along N.x is
/// m (L/2)(ω⁺ − ω₀) + P, zero at the centre of percussion p = 2L/3.
#[test]
fn a_rod_swinging_into_a_stop_and_its_centre_of_percussion() {
    let (m, l, e, w0) = (2.0, 1.5, 0.4, 3.0);
    let io = m * l * l / 3.0;
    for p in [1.2, 1.0] {
        let blow = io * (1.0 + e) * w0 / p;
        let pin = m * l / 2.0 * (-e * w0 - w0) + blow;
        let set = format!("p={p}");
        for method in METHODS {
            let what = format!("{method}: rod into the stop, {set}");
            let s = command("impact", "rod-swings-into-stop", method, &["--set", &set]);
            close(at(&s, &["before", "theta'"]), w0, &what);
            close(at(&s, &["after", "theta'"]), -e * w0, &what);
            let stop = triple(&s["impulses"]["stop"]);
            close(stop[0], -blow, &what);
            close(stop[1], 0.0, &what);
            let o = triple(&s["impulses"]["O"]["force"]);
            close(o[0], pin, &what);
            close(o[1], 0.0, &what);
            close(at(&s, &["energy", "before"]), io * w0 * w0 / 2.0, &what);
            close(
                at(&s, &["energy", "after"]),
                io * (e * w0) * (e * w0) / 2.0,
                &what,
            );
        }
    }
    close(
        2.0 * l / 3.0,
        1.0,
        "the centre of percussion is the second stop",
    );
}

/// The bead on the hoop (radius R) spun at W about its vertical diameter:
/// θ̈ = sin θ (W² cos θ − g/R). A student who leaves out the spin writes
/// R θ̈ + g sin θ = 0, and the diagnosis names the missing term in the student's own
/// symbols, W² (φ̇ = W for φ = W t), and the factor between the rows in the constants:
/// the row −m R² θ̈ − m g R sin θ + m R² W² sin θ cos θ = 0 (the moments of the weight
/// and of the inertia force about C) times −1/(m R) is R θ̈ + g sin θ − R W² sin θ cos θ,
/// so the term −R W² sin θ cos θ is missing.
#[test]
fn a_bead_on_a_spinning_hoop_and_a_student_who_forgot_the_spin() {
    let (r, w, th) = (0.5, 6.0, 0.7f64);
    let thdd = th.sin() * (w * w * th.cos() - G / r);
    for sol in solve_each("bead-on-spinning-hoop", &[]) {
        let what = format!("{}: bead on the hoop", sol["method"]);
        close(at(&sol, &["accelerations", "theta"]), thdd, &what);
        close(at(&sol, &["accelerations", "phi"]), 0.0, &what);
    }
    let submission = json!({
        "student": "s4",
        "equations": [ "R*theta'' + g*sin(theta) = 0" ]
    });
    let right = json!({
        "student": "s5",
        "equations": [ "R*theta'' + g*sin(theta) - R*W^2*sin(theta)*cos(theta) = 0" ]
    });
    for method in METHODS {
        let g = graded("bead-on-spinning-hoop", &submission, method);
        let item = &g["items"][0];
        assert_eq!(item["verdict"], "wrong", "{method}: {g}");
        let why = item["diagnosis"].as_str().expect("diagnosis");
        assert!(
            why.contains("the term -R*W^2*sin(theta)*cos(theta) is missing"),
            "{method}: names the spin's term as missing, in W: {why}"
        );
        assert!(
            !why.contains("phi"),
            "{method}: phi is the student's W*t: {why}"
        );
        // The factor that matches m R² θ̈ with R θ̈, as the problem's constants write it.
        let factor = match method {
            "newton-euler" => "(multiplied by -1/m)",
            _ => "(multiplied by -1/(R*m))",
        };
        assert!(why.contains(factor), "{method}: {factor} in {why}");
        let g = graded("bead-on-spinning-hoop", &right, method);
        assert_eq!(g["items"][0]["verdict"], "right", "{method}: {g}");
    }
}

/// The toggle: bars OK and KC (m, L each) with the slider C on N.x, the bar OK held at
/// θ = b against a push P on the slider towards O. x = 2 L cos θ, the bar KC at −2θ
/// from OK; by virtual work the holding torque is m g L cos b − 2 P L sin b.
#[test]
fn a_toggle_held_against_a_load_with_its_closure_unmarked() {
    let (m, l, p, b) = (1.5, 0.4, 120.0, 0.6f64);
    let torque = m * G * l * b.cos() - 2.0 * p * l * b.sin();
    for method in METHODS {
        let what = format!("{method}: toggle");
        let s = command("statics", "toggle-held-against-load", method, &[]);
        let eq = &s["equilibria"][0];
        close(at(eq, &["state", "x"]), 2.0 * l * b.cos(), &what);
        close(at(eq, &["state", "phi"]), -2.0 * b, &what);
        close(at(eq, &["held", "theta"]), torque, &what);
        let a = command("answer", "toggle-held-against-load", method, &[]);
        close(at(&a["answers"][0], &["value"]), torque, &what);
    }
    // Every coordinate held or fixed by the closure: the handout is the statics one.
    let plain = explained("toggle-held-against-load", &["--method", "kane"]);
    let statics = explained(
        "toggle-held-against-load",
        &["--method", "kane", "--statics"],
    );
    assert_eq!(
        plain, statics,
        "the held toggle's handout is the statics one"
    );
}
