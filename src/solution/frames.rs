//! Step 1's frames: `N` and one per body, each oriented by its joint, and the problem's
//! vectors as it writes them (a joint's axis).

use crate::problem::{Joint, JointKind, Problem, VectorExpr};
use crate::render::context::Frame;
use crate::render::text::Math;
use crate::symbolic::{latex, latex_unit_vector};

/// `N`, then one frame per body in file order, oriented by the joint whose child it is.
pub(super) fn frames(problem: &Problem) -> Vec<Frame> {
    let triad = |name: &str| {
        (0..3)
            .map(|axis| latex_unit_vector(name, axis))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let mut frames = vec![Frame {
        name: "N".into(),
        frame_tex: Math::from(triad("N")),
        fixed_in: "N".into(),
        parent: String::new(),
        orientation_tex: Math::from(String::new()),
    }];
    for id in problem.body_ids() {
        let name = problem.body_name(id);
        let joint = problem.joint_of(id).map(|j| &problem.joints[j]);
        frames.push(Frame {
            name: name.to_string(),
            frame_tex: Math::from(triad(name)),
            fixed_in: name.to_string(),
            parent: joint
                .map(|j| {
                    problem
                        .body_name(j.angle_from.unwrap_or(j.parent))
                        .to_string()
                })
                .unwrap_or_default(),
            orientation_tex: Math::from(
                joint
                    .map(|j| orientation_tex(problem, j))
                    .unwrap_or_default(),
            ),
        });
    }
    frames
}

/// How a joint orients its child's frame relative to its parent's, in words and math.
fn orientation_tex(problem: &Problem, joint: &Joint) -> String {
    let coordinate = |k: usize| {
        joint
            .coordinates
            .get(k)
            .map(|&i| latex(&problem.coordinate_expr(i, 0)))
            .unwrap_or_else(|| "0".into())
    };
    let axis = || match (&joint.axis, joint.angle_from) {
        // An absolute angle turns about N's normal to the plane, as the parent's does.
        (Some(axis), Some(from)) => {
            let terms = axis.terms.iter().map(|(_, k, c)| (from, *k, c.clone()));
            vector_tex(
                problem,
                &VectorExpr {
                    terms: terms.collect(),
                },
            )
        }
        (Some(axis), None) => vector_tex(problem, axis),
        (None, from) => latex_unit_vector(problem.body_name(from.unwrap_or(joint.parent)), 2),
    };
    let rotated = |angle: String, about: String| {
        format!("\\text{{rotated by }} {angle} \\text{{ about }} {about}")
    };
    match joint.kind {
        JointKind::Revolute => rotated(coordinate(0), axis()),
        JointKind::Cylindrical => rotated(coordinate(1), axis()),
        JointKind::Planar => rotated(
            coordinate(2),
            latex_unit_vector(problem.body_name(joint.parent), 2),
        ),
        JointKind::Prismatic | JointKind::Weld => "\\text{aligned}".into(),
        JointKind::Universal | JointKind::Spherical | JointKind::Free => {
            let first_angle = if joint.kind == JointKind::Free { 3 } else { 0 };
            let angles: Vec<String> = (0..joint.sequence.len())
                .map(|k| coordinate(first_angle + k))
                .collect();
            body_fixed_rotations_tex(&angles, &joint.sequence)
        }
    }
}

/// `\text{body-fixed rotations by } ψ, θ \text{ about } z, x`: the angles in order, each
/// about the axis of `sequence` at its place.
pub(super) fn body_fixed_rotations_tex(angles: &[String], sequence: &[u8]) -> String {
    let axes: Vec<&str> = sequence
        .iter()
        .take(angles.len())
        .map(|&a| ["x", "y", "z"].get(a as usize).copied().unwrap_or("?"))
        .collect();
    format!(
        "\\text{{body-fixed rotations by }} {} \\text{{ about }} {}",
        angles.join(", "),
        axes.join(", ")
    )
}

/// A vector expression as textbook LaTeX: `\frac{L}{2} \hat{\mathbf{a}}_{x} - \hat{\mathbf{n}}_{y}`.
pub(super) fn vector_tex(problem: &Problem, vector: &VectorExpr) -> String {
    let mut out = String::new();
    for (frame, axis, coefficient) in &vector.terms {
        let unit = latex_unit_vector(problem.body_name(*frame), *axis);
        let text = if coefficient.is_one() {
            unit
        } else if coefficient.terms().len() > 1 {
            format!("\\left({}\\right) {unit}", latex(coefficient))
        } else {
            let c = latex(coefficient);
            if c == "-1" {
                format!("-{unit}")
            } else {
                format!("{c} {unit}")
            }
        };
        match (out.is_empty(), text.strip_prefix('-')) {
            (true, _) => out.push_str(&text),
            (false, Some(rest)) => {
                out.push_str(" - ");
                out.push_str(rest);
            }
            (false, None) => {
                out.push_str(" + ");
                out.push_str(&text);
            }
        }
    }
    if out.is_empty() {
        "\\mathbf{0}".into()
    } else {
        out
    }
}
