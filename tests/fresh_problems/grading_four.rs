//! A swinging bar's derivation graded (its equation, its centre's acceleration, a partial
//! velocity, an answer) right and wrong, each wrong item's diagnosis naming the term; and
//! bad input on Version 4's keys refused with exit 1, the JSON path and a hint.

use super::errors::{names, refused, scratch};
use serde_json::json;

/// The bar (m, L, θ from the downward vertical, centre −L/2 b̂_y): m L²/3 θ̈ +
/// m g (L/2) sin θ = 0; a* = (L/2) θ̈ b̂_x + (L/2) θ̇² b̂_y; ∂v*/∂θ̇ = (L/2) b̂_x.
#[test]
fn grade_names_the_wrong_sign_and_the_missing_centripetal_term() {
    let (l, g, th) = (1.1f64, 9.81, 0.6f64);
    let submission = json!({
        "student": "s2",
        "answers": { "0": -3.0 * g / (2.0 * l) * th.sin() },
        "equations": [
            "m*L^2/3*th'' + m*g*L/2*sin(th) = 0",
            "m*L^2/3*th'' - m*g*L/2*sin(th) = 0"
        ],
        "kinematics": {
            "B*": { "velocity": "L/2*th'*B.x", "acceleration": "L/2*th''*B.x" }
        },
        "partial_velocities": { "B*": ["L/2*B.x"] }
    });
    for method in crate::support::METHODS {
        let g = super::graded("bar-for-grading", &submission, method);
        let items = g["items"].as_array().expect("items");
        let item = |name: &str| {
            items
                .iter()
                .find(|i| i["item"] == name)
                .unwrap_or_else(|| panic!("{method}: no item {name} in {g}"))
        };
        for right in ["answers.0", "equations[0]", "partial_velocities.B*[0]"] {
            assert_eq!(item(right)["verdict"], "right", "{method}: {right}: {g}");
        }
        let wrong = item("equations[1]");
        assert_eq!(wrong["verdict"], "wrong", "{method}: {g}");
        let why = wrong["diagnosis"].as_str().expect("diagnosis");
        assert!(why.contains("sin"), "{method}: names the term: {why}");
        if method != "kane" {
            assert!(
                !why.contains("Kane"),
                "{method}: names its own method: {why}"
            );
        }
        let kin = items
            .iter()
            .find(|i| {
                i["item"]
                    .as_str()
                    .is_some_and(|s| s.contains("acceleration"))
            })
            .unwrap_or_else(|| panic!("{method}: no acceleration item in {g}"));
        assert_eq!(kin["verdict"], "wrong", "{method}: {g}");
        let why = kin["diagnosis"].as_str().expect("diagnosis");
        assert!(why.contains("th'"), "{method}: names the θ̇² term: {why}");
    }
}

#[test]
fn bad_questions_of_version_four_name_their_paths() {
    // A bar's pin is no contact: it cannot tip.
    let p = scratch("rod-pendulum-in-frames", "tips", |p| {
        p["find"]["questions"] = json!([{ "tips": "O" }]);
    });
    names(&refused("check", &p, &[]), "find.questions[0].tips");
    // A smooth pin has no friction to slip against.
    let p = scratch("rod-pendulum-in-frames", "slips", |p| {
        p["find"]["questions"] = json!([{ "slips": "O" }]);
    });
    names(&refused("answer", &p, &[]), "find.questions[0].slips");
    // `impending` finds a constant, not a coordinate.
    let p = scratch("block-pushed-up-rough-slope", "find", |p| {
        p["find"]["questions"] = json!([{ "impending": { "find": "s", "at": "slope" } }]);
    });
    names(
        &refused("check", &p, &[]),
        "find.questions[0].impending.find",
    );
    // A misspelled key of the collision.
    let p = scratch("spinning-disc-drops-on-rough-floor", "key", |p| {
        p["impact"]["collision"]["restitutoin"] = json!(0.5);
    });
    names(&refused("check", &p, &[]), "impact.collision.restitutoin");
    // A `show` that does not parse gives the column.
    let p = scratch("rod-pendulum-in-frames", "show", |p| {
        p["find"]["questions"] = json!([{ "show": "th'' = -3*g/(2*L)*sin(th" }]);
    });
    let err = refused("answer", &p, &[]);
    names(&err, "find.questions[0].show");
    assert!(err.contains("column"), "{err}");
}
