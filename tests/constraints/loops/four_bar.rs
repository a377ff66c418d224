//! The four-bar linkage against Lagrange multipliers in absolute angles.

use super::*;

#[test]
fn four_bar_from_rest_matches_lagrange_multipliers() {
    check_four_bar(1.2, 0.0, &[]);
}

#[test]
fn four_bar_in_motion_matches_lagrange_multipliers() {
    // q2 and q3 are dependent: --state sets q1 and q1' only, the tool closes the loop.
    check_four_bar(0.9, 2.5, &["--state", &state(&[("q1", 0.9), ("q1'", 2.5)])]);
}
