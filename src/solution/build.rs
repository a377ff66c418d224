//! Building the [`Solution`] from a problem and what the pipeline derives from it.
//!
//! What the problem alone gives (title, statement, step 1) is filled here; the steps that
//! come from the equations and the simulation start empty, and the templates leave out
//! what is empty.

use super::tex::style_of;
use crate::equations::Method;
use crate::problem::{CoordinateKind, Dimension, Joint, JointKind, Problem, VectorExpr};
use crate::render::context::{Constant, Coordinate, Frame, Named, Plan, Simulation, Solution};
use crate::render::text::{Markup, MarkupLine, Math};
use crate::symbolic::format::fixed;
use crate::symbolic::print::{latex, latex_name, latex_unit_vector};

/// The whole worked solution from what the stages gave (`pipeline::work`): step 1 from
/// the problem, steps 2 to 6 from the derivation, the solution at the initial state and
/// the simulation.
pub fn solution(worked: &crate::pipeline::Worked) -> Solution {
    let derivation = &worked.derivation;
    let problem = derivation.model.problem;
    let mut solution = setup(problem, derivation.method);
    crate::symbolic::style::with_style(style_of(problem), || {
        super::derived::fill(&mut solution, worked)
    });
    solution
}

/// What the problem alone gives: title, statement and step 1 (also the student's handout).
pub fn setup(problem: &Problem, method: Method) -> Solution {
    crate::symbolic::style::with_style(style_of(problem), || setup_styled(problem, method)).0
}

fn setup_styled(problem: &Problem, method: Method) -> Solution {
    Solution {
        title: problem.title.clone(),
        statement: problem.statement.clone().map(Markup::from),
        dimension: match problem.dimension {
            Dimension::Two => "planar",
            Dimension::Three => "spatial",
        }
        .to_string(),
        method: method.title().to_string(),
        student: false,
        frames: frames(problem),
        coordinates: coordinates(problem),
        axes: axes(problem),
        constants: constants(problem),
        plan: Plan::default(),
        simulation: Simulation {
            settings: format!(
                "{} s, output every {} s, tolerance {}",
                fixed(problem.simulate.duration),
                fixed(problem.simulate.output_step),
                fixed(problem.simulate.tolerance)
            ),
            ..Simulation::default()
        },
        ..Solution::default()
    }
}

/// The unit vector along each joint axis that a sum may be taken along (a prismatic or
/// cylindrical joint's; a revolute joint's in 3D), as step 3 names it: `ê_slide`.
fn axes(problem: &Problem) -> Vec<Named> {
    problem
        .joints
        .iter()
        .filter(|j| match j.kind {
            JointKind::Prismatic | JointKind::Cylindrical => true,
            JointKind::Revolute => problem.dimension == Dimension::Three,
            _ => false,
        })
        .filter_map(|j| {
            let axis = j.axis.as_ref()?;
            let unit = format!("\\hat{{\\mathbf{{e}}}}_{{{}}}", latex_name(&j.name));
            // A unit vector as written is the axis; any other vector gives its direction.
            let plain = axis.terms.len() == 1 && axis.terms[0].2.is_one();
            let relation = if plain { "=" } else { "\\parallel" };
            // The subscript names the joint: no note.
            Some(Named::new(
                format!("{unit} {relation} {}", vector_tex(problem, axis)),
                "",
            ))
        })
        .collect()
}

/// `N`, then one frame per body in file order, oriented by the joint whose child it is.
fn frames(problem: &Problem) -> Vec<Frame> {
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
                .map(|j| problem.body_name(j.parent).to_string())
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
    let axis = || match &joint.axis {
        Some(axis) => vector_tex(problem, axis),
        None => latex_unit_vector(problem.body_name(joint.parent), 2),
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
pub fn vector_tex(problem: &Problem, vector: &VectorExpr) -> String {
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

fn coordinates(problem: &Problem) -> Vec<Coordinate> {
    problem
        .coordinates
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let joint = &problem.joints[c.joint];
            let unit = match (&c.unit, c.kind) {
                (Some(unit), _) => unit.clone(),
                (None, CoordinateKind::Angle) => "rad".into(),
                (None, CoordinateKind::Distance) => String::new(),
            };
            Coordinate {
                name_tex: Math::from(latex(&problem.coordinate_expr(i, 0))),
                rate_tex: Math::from(latex(&problem.coordinate_expr(i, 1))),
                description: MarkupLine::from(c.description.clone().unwrap_or_default()),
                joint: format!("{} ({})", joint.name, joint.kind.name()),
                unit_tex: Math::from(crate::render::units::unit_tex(&unit)),
                initial: fixed(c.initial),
                initial_rate: fixed(c.rate),
            }
        })
        .collect()
}

fn constants(problem: &Problem) -> Vec<Constant> {
    problem
        .constants
        .iter()
        .map(|c| Constant {
            name_tex: Math::from(latex_name(&c.name)),
            value: fixed(c.value),
            unit_tex: Math::from(crate::render::units::unit_tex(
                c.unit.as_deref().unwrap_or_default(),
            )),
            description: MarkupLine::from(c.description.clone().unwrap_or_default()),
        })
        .collect()
}
