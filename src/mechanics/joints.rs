//! What each joint type does: the rotations and translation it allows, the directions its
//! joint loads act along, and the directions that carry a reaction.

use super::error::MechanicsError;
use super::frames::{dual_basis, Frames, Rotation};
use super::vector::{cross3, zero3, Components, Vector};
use crate::problem::{BodyId, Dimension, Joint, JointKind, Problem};
use crate::symbolic::{eval, pow, Expr, Values};

/// The motion a joint allows, in the parent's frame.
#[derive(Clone, Debug)]
pub struct JointMotion {
    /// Rotations from the parent's frame to the child's.
    pub rotations: Vec<Rotation>,
    /// The translation of the child's joint point from the parent's, in the parent's frame.
    pub translation: Components,
    /// The unit axis of `revolute`, `prismatic`, `cylindrical`, in the parent's frame, with its
    /// sign made canonical (see [`joint_axis`]).
    pub axis: Option<Components>,
    /// The same axis with the sign as written: the direction its coordinate increases along.
    pub written_axis: Option<Components>,
}

pub use crate::symbolic::{Axis, Component, ComponentKind};
use crate::symbolic::{Symbol, Unknown};

/// A reaction component: its kind and axis (`Fx`, `M1`) and its direction.
#[derive(Clone, Debug)]
pub struct ReactionComponent {
    /// Force or moment.
    pub kind: ComponentKind,
    /// Which way it acts, as its name tells it: the axis letter (`x`, `y`, `z`) or a number.
    pub axis: Axis,
    /// The unit direction.
    pub direction: Vector,
}

impl ReactionComponent {
    /// Its kind and axis, e.g. `Fx`.
    pub fn component(&self) -> Component {
        Component {
            kind: self.kind,
            axis: self.axis,
        }
    }

    /// The unknown of this component at the site named `site`.
    pub fn unknown(&self, site: &str) -> Symbol {
        Symbol::Unknown(Unknown::Reaction {
            site: site.into(),
            component: self.component(),
        })
    }
}

/// Where a joint load on one coordinate acts: a force along `force`, a couple about `torque`.
#[derive(Clone, Debug)]
pub struct LoadAxis {
    /// The direction of the force on the child (zero for an angle), in the parent's frame.
    pub force: Vector,
    /// The direction of the couple on the child (zero for a distance).
    pub torque: Vector,
}

fn unit(axis: usize) -> Components {
    let mut c = zero3();
    c[axis] = Expr::one();
    c
}

/// The axis of a joint in the parent's frame, normalized, with its sign made canonical
/// (first nonzero component positive) so that rotations about one axis merge.
///
/// # Errors
/// When the axis is missing, zero, or not fixed in the parent.
pub fn joint_axis(
    problem: &Problem,
    joint: &Joint,
    frames: &Frames,
    values: &Values,
) -> Result<(Components, bool), MechanicsError> {
    let error = |message: String, hint: &str| MechanicsError {
        path: format!("{}.axis", joint.path),
        message: format!("joint `{}`: {message}", joint.name),
        hint: Some(hint.to_string()),
    };
    let Some(written) = &joint.axis else {
        if problem.dimension == Dimension::Two {
            return Ok((unit(2), false));
        }
        return Err(error(
            "this joint type needs an axis".into(),
            "for example \"axis\": \"N.z\"",
        ));
    };
    let vector = super::vector::vector_of(written);
    let components = vector.components_in(joint.parent, frames);
    if components.iter().any(|c| !c.is_constant()) {
        return Err(error(
            format!("the axis is not fixed in the parent `{}`", problem.body_name(joint.parent)),
            "write the axis with the parent's unit vectors, or with ones that do not move relative to it",
        ));
    }
    let numbers: Vec<f64> = components.iter().map(|c| eval(c, values)).collect();
    let length = numbers.iter().map(|x| x * x).sum::<f64>().sqrt();
    if length.is_nan() || length <= 1e-12 {
        return Err(error(
            "the axis is zero".into(),
            "give a nonzero direction such as N.z",
        ));
    }
    let flip = numbers
        .iter()
        .find(|x| x.abs() > 1e-12 * length)
        .is_some_and(|x| *x < 0.0);
    let sign = if flip { Expr::int(-1) } else { Expr::one() };
    let norm2 = crate::symbolic::add(components.iter().map(|c| c * c));
    let scale = &sign * &pow(norm2, Expr::ratio(-1, 2));
    Ok((std::array::from_fn(|i| &components[i] * &scale), flip))
}

/// The rotations and translation of a joint, given its coordinates' expressions.
///
/// # Errors
/// When the axis is invalid (see [`joint_axis`]).
pub fn joint_motion(
    problem: &Problem,
    joint: &Joint,
    frames: &Frames,
    values: &Values,
) -> Result<JointMotion, MechanicsError> {
    let q: Vec<Expr> = joint
        .coordinates
        .iter()
        .map(|&c| problem.coordinate_expr(c, 0))
        .collect();
    let sequence_rotations = |angles: &[Expr]| -> Vec<Rotation> {
        joint
            .sequence
            .iter()
            .zip(angles)
            .map(|(&a, angle)| Rotation {
                axis: unit(a as usize),
                angle: angle.clone(),
            })
            .collect()
    };
    let along = |axis: &Components, distance: &Expr| -> Components {
        std::array::from_fn(|i| &axis[i] * distance)
    };
    let motion = match joint.kind {
        JointKind::Revolute | JointKind::Prismatic | JointKind::Cylindrical => {
            let (axis, flipped) = joint_axis(problem, joint, frames, values)?;
            let signed = |e: &Expr| if flipped { -e.clone() } else { e.clone() };
            let (rotations, translation) = match joint.kind {
                JointKind::Revolute => (
                    vec![Rotation {
                        axis: axis.clone(),
                        angle: signed(&q[0]),
                    }],
                    zero3(),
                ),
                JointKind::Prismatic => (vec![], along(&axis, &signed(&q[0]))),
                _ => (
                    vec![Rotation {
                        axis: axis.clone(),
                        angle: signed(&q[1]),
                    }],
                    along(&axis, &signed(&q[0])),
                ),
            };
            let written: Components = std::array::from_fn(|i| signed(&axis[i]));
            JointMotion {
                rotations,
                translation,
                axis: Some(axis),
                written_axis: Some(written),
            }
        }
        JointKind::Planar => JointMotion {
            rotations: vec![Rotation {
                axis: unit(2),
                angle: q[2].clone(),
            }],
            translation: [q[0].clone(), q[1].clone(), Expr::zero()],
            axis: None,
            written_axis: None,
        },
        JointKind::Universal | JointKind::Spherical => JointMotion {
            rotations: sequence_rotations(&q),
            translation: zero3(),
            axis: None,
            written_axis: None,
        },
        JointKind::Free => JointMotion {
            rotations: sequence_rotations(&q[3..]),
            translation: [q[0].clone(), q[1].clone(), q[2].clone()],
            axis: None,
            written_axis: None,
        },
        JointKind::Weld => JointMotion {
            rotations: vec![],
            translation: zero3(),
            axis: None,
            written_axis: None,
        },
    };
    Ok(motion)
}

/// For each of the joint's coordinates, where a joint load on it acts.
pub fn load_axes(joint: &Joint, motion: &JointMotion, frames: &Frames) -> Vec<LoadAxis> {
    let (parent, child) = (joint.parent, joint.child);
    let force = |c: Components| LoadAxis {
        force: Vector::new(parent, c),
        torque: Vector::zero(),
    };
    let torque = |frame: BodyId, c: Components| LoadAxis {
        force: Vector::zero(),
        torque: Vector::new(frame, c),
    };
    // A coordinate increases along the axis as written, so its load acts along that.
    let signed_axis = || motion.written_axis.clone().unwrap_or_else(|| unit(2));
    match joint.kind {
        JointKind::Revolute => vec![torque(parent, signed_axis())],
        JointKind::Prismatic => vec![force(signed_axis())],
        JointKind::Cylindrical => {
            let axis = signed_axis();
            vec![force(axis.clone()), torque(parent, axis)]
        }
        JointKind::Planar => vec![force(unit(0)), force(unit(1)), torque(parent, unit(2))],
        JointKind::Universal => frames
            .rotation_axes_in_frame(child)
            .into_iter()
            .map(|a| torque(child, a))
            .collect(),
        JointKind::Spherical | JointKind::Free => {
            let axes = frames.rotation_axes_in_frame(child);
            let axes: [Components; 3] = std::array::from_fn(|i| axes[i].clone());
            let duals = dual_basis(&axes).into_iter().map(|b| torque(child, b));
            let translations = (0..3).map(|i| force(unit(i)));
            if joint.kind == JointKind::Free {
                translations.chain(duals).collect()
            } else {
                duals.collect()
            }
        }
        JointKind::Weld => vec![],
    }
}

/// The directions that carry a reaction at a joint, in the parent's frame unless they move.
pub fn reaction_components(
    problem: &Problem,
    joint: &Joint,
    motion: &JointMotion,
    values: &Values,
) -> Vec<ReactionComponent> {
    let planar = problem.dimension == Dimension::Two;
    let parent = joint.parent;
    let component = |kind: ComponentKind, c: Components, index: usize| -> ReactionComponent {
        let axis = match unit_axis_of(&c) {
            Some(axis) => Axis::Unit(axis as u8),
            None => Axis::Numbered(index as u8),
        };
        ReactionComponent {
            kind,
            axis,
            direction: Vector::new(parent, c),
        }
    };
    let all = |kind: ComponentKind, axes: &[usize]| -> Vec<ReactionComponent> {
        axes.iter()
            .map(|&a| component(kind, unit(a), a + 1))
            .collect()
    };
    let in_plane: &[usize] = &[0, 1];
    let out_of_plane: &[usize] = &[2];
    let every: &[usize] = &[0, 1, 2];
    let perpendicular = |kind: ComponentKind, axis: &Components| -> Vec<ReactionComponent> {
        perpendicular_pair(axis, values)
            .into_iter()
            .enumerate()
            .map(|(i, c)| component(kind, c, i + 1))
            .collect()
    };
    let axis = motion.axis.clone().unwrap_or_else(|| unit(2));
    let mut out = match (joint.kind, planar) {
        (JointKind::Revolute, true) => all(ComponentKind::Force, in_plane),
        (JointKind::Prismatic, true) => {
            vec![component(ComponentKind::Force, cross3(&unit(2), &axis), 1)]
                .into_iter()
                .chain(all(ComponentKind::Moment, out_of_plane))
                .collect()
        }
        (JointKind::Planar, true) => vec![],
        (JointKind::Weld, true) => all(ComponentKind::Force, in_plane)
            .into_iter()
            .chain(all(ComponentKind::Moment, out_of_plane))
            .collect(),
        (JointKind::Revolute, false) => all(ComponentKind::Force, every)
            .into_iter()
            .chain(perpendicular(ComponentKind::Moment, &axis))
            .collect(),
        (JointKind::Prismatic, false) => perpendicular(ComponentKind::Force, &axis)
            .into_iter()
            .chain(all(ComponentKind::Moment, every))
            .collect(),
        (JointKind::Cylindrical, _) => perpendicular(ComponentKind::Force, &axis)
            .into_iter()
            .chain(perpendicular(ComponentKind::Moment, &axis))
            .collect(),
        (JointKind::Planar, false) => all(ComponentKind::Force, out_of_plane)
            .into_iter()
            .chain(all(ComponentKind::Moment, in_plane))
            .collect(),
        (JointKind::Universal, _) => {
            // The constraint couple is along (first axis) × (second axis), turned with the first angle.
            let first = &motion.rotations[0];
            let second = &motion.rotations[1];
            let normal = cross3(&first.axis, &second.axis);
            let turned = super::frames::apply(&first.matrix(), &normal);
            let mut out = all(ComponentKind::Force, every);
            out.push(ReactionComponent {
                kind: ComponentKind::Moment,
                axis: Axis::Numbered(1),
                direction: Vector::new(parent, turned),
            });
            out
        }
        (JointKind::Spherical, _) => all(ComponentKind::Force, every),
        (JointKind::Free, _) => vec![],
        (JointKind::Weld, false) => all(ComponentKind::Force, every)
            .into_iter()
            .chain(all(ComponentKind::Moment, every))
            .collect(),
    };
    if joint.kind == JointKind::Prismatic && joint.friction.is_some() {
        out.insert(0, friction_component(parent, axis));
    }
    out
}

/// A rough slider's friction force along its (canonical) axis, first among its reactions:
/// named by the axis letter when the axis is a unit vector (`Fx`), `Ft1` (printed
/// `F_t`) otherwise.
fn friction_component(parent: BodyId, axis: Components) -> ReactionComponent {
    ReactionComponent {
        kind: ComponentKind::Force,
        axis: match unit_axis_of(&axis) {
            Some(a) => Axis::Unit(a as u8),
            None => Axis::SoleTangent,
        },
        direction: Vector::new(parent, axis),
    }
}

/// Which unit axis `c` is exactly, if any.
fn unit_axis_of(c: &Components) -> Option<usize> {
    let ones: Vec<usize> = (0..3).filter(|&i| c[i].is_one()).collect();
    let zeros = c.iter().filter(|e| e.is_zero()).count();
    (ones.len() == 1 && zeros == 2).then(|| ones[0])
}

/// Two unit vectors perpendicular to the unit `axis` and to each other: the other two unit
/// axes when `axis` is one, otherwise built from the unit axis least aligned with it.
fn perpendicular_pair(axis: &Components, values: &Values) -> [Components; 2] {
    if let Some(a) = unit_axis_of(axis) {
        return [unit((a + 1) % 3), unit((a + 2) % 3)];
    }
    let magnitudes: Vec<f64> = axis.iter().map(|c| eval(c, values).abs()).collect();
    let least = (0..3)
        .min_by(|&i, &j| magnitudes[i].total_cmp(&magnitudes[j]))
        .unwrap_or(0);
    let raw = cross3(axis, &unit(least));
    let norm2 = crate::symbolic::add(raw.iter().map(|c| c * c));
    let scale = pow(norm2, Expr::ratio(-1, 2));
    let first: Components = std::array::from_fn(|i| &raw[i] * &scale);
    let second = cross3(axis, &first);
    [first, second]
}
