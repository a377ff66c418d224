//! Sliding friction in the free bodies: a site that slips at the drawn state has its
//! friction drawn as the unknown of the rows it is (red, as the plan and the table of forces
//! have it), against the slip, signed as it points.

use super::{angle_between, line, Read};
use mbd_tutor::equations::Derivation;
use mbd_tutor::symbolic::{eval, Values};

/// The slip velocity along reaction component `c` of `site`, when it is the friction of a
/// site that slips at this state (none while it sticks or has no friction).
pub(super) fn slip_along(
    d: &Derivation,
    site: &mbd_tutor::mechanics::Site,
    c: &mbd_tutor::mechanics::ReactionComponent,
    values: &Values,
) -> Option<f64> {
    let friction = d
        .model
        .constraints
        .friction
        .iter()
        .find(|f| f.name == site.name)?;
    let row = friction
        .stick
        .iter()
        .find(|r| r.unknown == c.unknown(&site.name))?;
    let slip = eval(&row.velocity, values);
    (slip.abs() > 1e-9).then_some(slip)
}

/// A sliding friction arrow at `at`: an unknown (a reaction) drawn along `against`
/// (against the slip), labelled by the rows' `unknown` signed as the arrow points (`-F^P_x`
/// where the slip is along the unknown's + axis, `slip` > 0) and nothing else: the sliding
/// law is a row of the rows, not a known value of the picture.
pub(super) fn check_sliding(r: &Read, at: &str, against: [f64; 3], (unknown, slip): (&str, f64)) {
    let sign = if slip > 0.0 { "-" } else { "" };
    let want = format!("{sign}{unknown}");
    let found = r.arrows.iter().find(|(g, _)| {
        g.attr("data-kind") == Some("reaction")
            && g.attr("data-at") == Some(at)
            && g.attr("data-label") == Some(want.as_str())
    });
    let (g, m) =
        found.unwrap_or_else(|| panic!("{}: no sliding friction {want:?} at {at}", r.name));
    let (tail, head) = line(g, *m).expect("a straight arrow");
    let got = [head[0] - tail[0], head[1] - tail[1]];
    let want = r.project_direction(against);
    assert!(
        angle_between(got, want) < 1e-3,
        "{}: friction at {at} drawn along {got:?}, not against the slip {want:?}",
        r.name
    );
}
