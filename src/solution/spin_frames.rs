//! Step 1's frames that do not spin: one per body spinning about its symmetry axis
//! (`mechanics/resal.rs`), a row of the frames' table and the sentence that says why.

use crate::problem::CoordinateKind;
use crate::render::context::{Frame, SpinFrame};
use crate::render::text::Math;
use crate::symbolic::{latex, latex_unit_vector};

/// The frames that do not spin (see [`crate::mechanics::resal`]), with what the handout
/// says of each in step 1.
pub(super) fn spin_frames(derivation: &crate::equations::Derivation) -> Vec<SpinFrame> {
    let model = &derivation.model;
    let problem = model.problem;
    let triad = |name: &str| {
        (0..3)
            .map(|axis| latex_unit_vector(name, axis))
            .collect::<Vec<_>>()
            .join(", ")
    };
    model
        .spin_frames
        .iter()
        .map(|spin| {
            let body = problem.body_name(spin.body);
            let name = model.frames.name(spin.frame);
            let joint = problem.joint_of(spin.body).map(|j| &problem.joints[j]);
            // The added frame is oriented by the joint's angles but the spin.
            let orientation_tex = joint
                .map(|j| {
                    let angles: Vec<String> = j
                        .coordinates
                        .iter()
                        .filter(|&&c| c != spin.spin)
                        .filter(|&&c| problem.coordinates[c].kind == CoordinateKind::Angle)
                        .map(|&c| latex(&problem.coordinate_expr(c, 0)))
                        .collect();
                    super::frames::body_fixed_rotations_tex(&angles, &j.sequence)
                })
                .unwrap_or_default();
            SpinFrame {
                frame: Frame {
                    name: name.to_string(),
                    frame_tex: Math::from(triad(name)),
                    fixed_in: String::new(),
                    parent: joint
                        .map(|j| problem.body_name(j.parent).to_string())
                        .unwrap_or_default(),
                    orientation_tex: Math::from(orientation_tex),
                },
                body: body.to_string(),
                axis_tex: Math::from(latex_unit_vector(body, spin.axis as u8)),
                spin_tex: Math::from(latex(&problem.coordinate_expr(spin.spin, 0))),
                parents: !spin.added,
            }
        })
        .collect()
}
