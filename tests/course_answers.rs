//! Questions answered as a course answers them: whether the skidding bowling ball slips,
//! when it rolls and how fast it then moves in closed form; the bicycle's weave and
//! capsize speeds; each against a closed form or a published value written here.

use crate::support::{answers_json, explain, problem};
use serde_json::Value;

const V0: f64 = 8.0;
const MU: f64 = 0.2;
const G: f64 = 9.81;

fn close(found: f64, expected: f64, tolerance: f64, what: &str) {
    assert!(
        (found - expected).abs() <= tolerance * expected.abs().max(1.0),
        "{what}: {found} against {expected}"
    );
}

/// Released with v₀ and no spin, the contact point of the ball slides at v₀ + Rθ̇ = v₀:
/// the ball slips, yes, whatever the forces.
#[test]
fn the_bowling_ball_slips_at_release_and_says_why() {
    for method in ["motion-law", "kane"] {
        let found = answers_json(&problem("bowling-ball"), method);
        let slips = &found[0];
        assert_eq!(slips["kind"], "slips", "{method}");
        assert_eq!(slips["value"], true, "{method}");
        close(
            slips["slip_speed"].as_f64().expect("slip speed"),
            V0,
            1e-9,
            "slip speed",
        );
        // Sliding, friction is μ|N|: the ratio is 1.
        close(slips["ratio"].as_f64().expect("ratio"), 1.0, 1e-9, "ratio");
    }
    let text = explain("bowling-ball", &["--format", "markdown"]);
    let answers = &text[text.find("## Answers").expect("Answers")..];
    assert!(
        answers.contains("yes: the contact point at the lane slides"),
        "{answers}"
    );
    assert!(!answers.contains("at rest, every friction site sticking"));
}

/// Sliding: m ẍ = −μ m g and (2/5) m R² θ̈ = −μ m g R, so ẍ = −μg, θ̈ = −5μg/(2R); the
/// slip velocity ẋ + Rθ̇ = v₀ − (7/2) μ g t vanishes at t = 2v₀/(7μg), when
/// ẋ = v₀ − μg t = 5v₀/7. The handout derives both in symbols, by the Motion Law and by
/// Kane's method, and their numbers are these.
#[test]
fn the_bowling_ball_rolls_at_the_closed_form_instant_and_speed() {
    let t_roll = 2.0 * V0 / (7.0 * MU * G);
    let speed = 5.0 * V0 / 7.0;
    for method in ["motion-law", "kane"] {
        let text = explain(
            "bowling-ball",
            &["--format", "markdown", "--method", method],
        );
        let answers = &text[text.find("## Answers").expect("Answers")..];
        for needed in [
            "with the sliding law in place of the no-slip condition",
            "v_{\\mathrm{slip}}",
            "\\frac{2 v_{0}}{7 g \\mu}",
            "\\frac{5 v_{0}}{7}",
            &format!("{t_roll:.5}"),
            &format!("{speed:.5}"),
        ] {
            assert!(answers.contains(needed), "{method}: {needed}: {answers}");
        }
        let found = answers_of(method);
        close(found.0, t_roll, 1e-6, "t");
        close(found.1, speed, 1e-6, "v");
    }
}

/// The instant and the speed that `answer` gives at the switch.
fn answers_of(method: &str) -> (f64, f64) {
    let found = answers_json(&problem("bowling-ball"), method);
    let at: Vec<&Value> = found.iter().filter(|a| a["switch"] == "lane").collect();
    (
        at[0]["value"].as_f64().expect("t"),
        at[1]["value"].as_f64().expect("v"),
    )
}

/// The benchmark bicycle of Meijaard et al. (2007): the upright straight run is stable
/// between the weave speed 4.29238253634111 m/s, where an oscillation stops growing, and
/// the capsize speed 6.02426201538837 m/s, where a motion without oscillation starts to.
#[test]
fn the_bicycle_answers_its_weave_and_capsize_speeds() {
    let path = problem("validation/whipple-bicycle");
    let found = answers_json(&path, "motion-law");
    let stability = found.last().expect("an answer");
    assert_eq!(stability["kind"], "stability");
    assert_eq!(stability["unit"], "m/s");
    let edges = stability["edges"].as_array().expect("edges");
    assert_eq!(edges.len(), 2, "{edges:?}");
    close(
        edges[0]["value"].as_f64().expect("weave"),
        4.29238253634111,
        1e-6,
        "weave speed",
    );
    assert_eq!(edges[0]["stable_above"], true);
    assert_eq!(edges[0]["oscillates"], true);
    close(
        edges[1]["value"].as_f64().expect("capsize"),
        6.02426201538837,
        1e-6,
        "capsize speed",
    );
    assert_eq!(edges[1]["stable_above"], false);
    assert_eq!(edges[1]["oscillates"], false);
}

/// A problem whose only loss is sliding friction says so, and names no damper.
#[test]
fn friction_without_dampers_names_no_damper() {
    let text = explain("bowling-ball", &["--format", "markdown"]);
    assert!(text.contains("Sliding friction only takes energy away"));
    assert!(!text.contains("dampers"), "a damper is named");
}
