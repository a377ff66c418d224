//! Where the potential energy of an energy answer is zero, said beside the value: an
//! energy without its datum means nothing. Said only where the answer at the start equals
//! the energy the simulation measures from the problem's datum (gravity's from the height
//! of the ground's origin, springs' from their free lengths), so that the datum named is
//! the one the answer uses.

use crate::mechanics::SiteKind;
use crate::problem::{BodyId, LoadKind};
use crate::Worked;

/// The ground's origin as the handout names it: a joint of the ground at its origin (pin
/// O), else the origin of N.
fn origin_name(worked: &Worked) -> String {
    let model = &worked.derivation.model;
    let at_origin = model.sites.iter().find(|s| {
        s.parent == BodyId::GROUND
            && matches!(s.kind, SiteKind::Joint(_))
            && (s
                .point
                .position
                .components_in(BodyId::GROUND, &model.frames)
                .iter())
            .all(|c| crate::symbolic::simplify(c).is_zero())
    });
    match at_origin {
        Some(site) => super::force_labels::place(&site.name),
        None => "the origin of N".into(),
    }
}

/// The sentence for an energy `value` given at the start; `None` where the simulation did
/// not run or measures another energy.
pub fn sentence(worked: &Worked, value: f64) -> Option<String> {
    let Some(Ok((trajectory, _))) = &worked.simulation else {
        return None;
    };
    let total = trajectory.series("total")?.first()?.1 + trajectory.potential_at_start;
    if (total - value).abs() > 1e-9 * value.abs().max(1e-9) {
        return None;
    }
    let problem = worked.derivation.model.problem;
    let springs = (problem.loads.iter()).any(|l| {
        matches!(
            l.kind,
            LoadKind::Spring { .. } | LoadKind::JointSpring { .. }
        )
    });
    let gravity = problem.gravity.is_some();
    let datum = match (gravity, springs) {
        (true, false) => format!("$V$ is zero at the height of {}", origin_name(worked)),
        (true, true) => format!(
            "$V$ is zero at the height of {} with the springs at their free lengths",
            origin_name(worked)
        ),
        (false, true) => "$V$ is zero with the springs at their free lengths".into(),
        (false, false) => return None,
    };
    Some(format!("{datum}."))
}
