//! Where the potential energy of an energy answer is zero, said beside the value: an
//! energy without its datum means nothing. Said only where the answer at the start equals
//! the kinetic energy plus gravity's potential measured from the height of the ground's
//! origin, so that the datum named is the one the answer uses.

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

/// The potential energy of gravity at the start, zero at the height of N's origin:
/// −Σ m g · r*, each mass centre from the origin.
fn gravity_potential(worked: &Worked) -> Option<f64> {
    let model = &worked.derivation.model;
    let g = crate::mechanics::vector_of(model.problem.gravity.as_ref()?);
    let values = model.values_at(0.0, &worked.q0, &worked.rates0);
    let v: f64 = (model.problem.body_ids())
        .map(|b| {
            let body = &model.bodies[b.0];
            let height = body.center.position.dot(&g, &model.frames);
            -crate::symbolic::eval(&body.mass, &values) * crate::symbolic::eval(&height, &values)
        })
        .sum();
    Some(v)
}

/// The sentence for an energy `value` given at the start; `None` where the simulation did
/// not run, the problem has springs, or the value is not T + V with V zero at the height of
/// the ground's origin.
pub fn sentence(worked: &Worked, value: f64) -> Option<String> {
    let Some(Ok((trajectory, _))) = &worked.simulation else {
        return None;
    };
    let problem = worked.derivation.model.problem;
    let springs = (problem.loads.iter()).any(|l| {
        matches!(
            l.kind,
            LoadKind::Spring { .. } | LoadKind::JointSpring { .. }
        )
    });
    if springs {
        return None;
    }
    let kinetic = trajectory.series("kinetic")?.first()?.1;
    let total = kinetic + gravity_potential(worked)?;
    if (total - value).abs() > 1e-9 * value.abs().max(1e-9) {
        return None;
    }
    Some(format!(
        "$V$ is zero at the height of {}.",
        origin_name(worked)
    ))
}
