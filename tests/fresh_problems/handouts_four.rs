//! What the worked solutions say on bundled problems where they said it wrong: a held
//! arm's handout by any method is the one of statics, Lagrange's constraint rows are
//! written as constraint rows, and a spring along a line has the signed stretch in V.

use crate::support::{explain, METHODS};

/// Every coordinate held: `explain` writes the statics handout, with or without `--statics`.
#[test]
fn a_held_arm_reads_as_statics_by_every_method() {
    for method in METHODS {
        let plain = explain("statics-two-link-arm", &["--method", method]);
        let statics = explain("statics-two-link-arm", &["--method", method, "--statics"]);
        assert_eq!(
            plain, statics,
            "{method}: the held arm's handout is the statics one"
        );
    }
}

/// The wheel's no-slip and no-penetration rows are not "relaxed along" nothing.
#[test]
fn lagranges_constraint_rows_are_headed_by_what_they_constrain() {
    let text = explain("wheel-pendulum", &["--method", "lagrange"]);
    assert!(
        !text.contains("\\text{relaxed along }$"),
        "a relaxed row names its component"
    );
    let step5 = text.split("## Step 5").nth(1).expect("step 5");
    assert!(
        step5.contains("no slip at the ground"),
        "the no-slip row is named"
    );
}

/// The carts' springs lie along N.x: their lengths are a₁ + x₁ and a₂ + x₂ − x₁ while the
/// carts keep their order, so V = ½k₁x₁² + ½k₂(x₂ − x₁)², with no root.
#[test]
fn a_spring_along_a_line_has_its_signed_stretch_in_lagranges_energy() {
    let text = explain("two-mass-spring-damper", &["--method", "lagrange"]);
    let v = (text.lines())
        .find(|l| l.starts_with("V = "))
        .expect("the line of V");
    assert!(!v.contains("sqrt"), "no root of a square in {v}");
    let step5 = text.split("## Step 5").nth(1).expect("step 5");
    let rows = step5.split("## Step 6").next().expect("step 5's rows");
    assert!(!rows.contains("\\sqrt"), "no root in the rows of step 5");
}
