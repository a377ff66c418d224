//! The tree as the composite rows walk it: which joints each speed moves and how, the joints
//! from the leaves in and from a joint in to the root, and quantities carried from a joint
//! to the next one in, each component a named quantity so that every product is one of
//! names.

use crate::mechanics::{cross3, split, Components, Matrix, Model, Vector};
use crate::problem::BodyId;
use crate::symbolic::{latex_name, time_derivative, Expr};

/// Whether every speed moves the bodies outboard of its joint rigidly: the speeds are the
/// rates, and nothing but the tree's joints constrains the motion (no closure, contact,
/// constraint entry, prescribed or dependent coordinate). A joint's motion depends on its
/// own coordinates alone, whatever its type, so the tree's joints never break it.
pub fn applies(model: &Model) -> bool {
    let problem = model.problem;
    model.speeds.is_none()
        && model.constraints.is_empty()
        && model.constraints.friction.is_empty()
        && problem.closures.is_empty()
        && problem.constraints.is_empty()
        && problem
            .coordinates
            .iter()
            .all(|c| c.motion.is_none() && !c.dependent && !c.dependent_rate)
}

/// The motion one speed gives the child of its joint, per unit of the speed.
pub struct SpeedMotion {
    /// The speed's index among the coordinates.
    pub speed: usize,
    /// The partial angular velocity, in the child's unit vectors.
    pub omega: Components,
    /// The partial velocity of the child's point at the joint, in the parent's unit vectors.
    pub velocity: Vector,
}

impl SpeedMotion {
    /// `ω · angular + u · linear` for this speed's `ω` and `u` at the joint of `body`, the
    /// joint's child: the speed's share of a row, or of a mass matrix entry.
    pub(super) fn dot(
        &self,
        model: &Model,
        body: BodyId,
        (linear, angular): (&Vector, &Vector),
    ) -> Expr {
        let omega = Vector::new(body, self.omega.clone());
        omega.dot(angular, &model.frames) + self.velocity.dot(linear, &model.frames)
    }
}

/// The speeds' motions of every joint, indexed like the problem's joints; `None` where
/// [`applies`] does not hold or a joint's motion is not linear in its own rates alone.
pub fn speed_motions(model: &Model) -> Option<Vec<Vec<SpeedMotion>>> {
    if !applies(model) {
        return None;
    }
    (0..model.problem.joints.len())
        .map(|j| joint_speed_motions(model, j))
        .collect()
}

pub(super) fn joint_speed_motions(model: &Model, j: usize) -> Option<Vec<SpeedMotion>> {
    let problem = model.problem;
    let joint = &problem.joints[j];
    let rates = problem.speed_symbols(1);
    let relative = model.frames.relative_angular_velocity(joint.child).ok()?;
    let (turning, turning_rest) = split(&relative, &rates)?;
    let (sliding, sliding_rest) = split(&derivative(&model.joints[j].motion.translation)?, &rates)?;
    let moved_by_others = (0..rates.len())
        .filter(|r| !joint.coordinates.contains(r))
        .any(|r| !is_zero(&turning[r]) || !is_zero(&sliding[r]));
    if moved_by_others || !is_zero(&turning_rest) || !is_zero(&sliding_rest) {
        return None;
    }
    let motions = joint.coordinates.iter().map(|&speed| SpeedMotion {
        speed,
        omega: turning[speed].clone(),
        velocity: Vector::new(joint.parent, sliding[speed].clone()),
    });
    Some(motions.collect())
}

pub(super) fn is_zero(c: &Components) -> bool {
    c.iter().all(Expr::is_zero)
}

/// d/dt of each component.
pub(super) fn derivative(c: &Components) -> Option<Components> {
    Some([
        time_derivative(&c[0]).ok()?,
        time_derivative(&c[1]).ok()?,
        time_derivative(&c[2]).ok()?,
    ])
}

/// The joints whose parent is `body`.
pub(super) fn carried_by(model: &Model, body: BodyId) -> Vec<usize> {
    let joints = &model.problem.joints;
    (0..joints.len())
        .filter(|&c| joints[c].parent == body)
        .collect()
}

/// The joints from the leaves in: each after every joint its child carries.
pub(super) fn leaves_first(model: &Model) -> Vec<usize> {
    let problem = model.problem;
    let order = model.order.iter().rev();
    order.filter_map(|&body| problem.joint_of(body)).collect()
}

/// The joints from joint `j` in to the root, `j` first.
pub(super) fn path_in(model: &Model, j: usize) -> Vec<usize> {
    let problem = model.problem;
    let mut path = vec![j];
    while let Some(inner) = path
        .last()
        .and_then(|&at| problem.joint_of(problem.joints[at].parent))
    {
        path.push(inner);
    }
    path
}

/// The point of joint `c` (on its parent) from the point `from` of the same body, in that
/// body's unit vectors: where the joint is fixed, plus how far it slides.
pub(super) fn joint_offset(model: &Model, c: usize, from: &Components) -> Components {
    let joint = &model.joints[c];
    std::array::from_fn(|i| &(&joint.at[i] + &joint.motion.translation[i]) - &from[i])
}

/// A resultant at joint `c` (`linear`, and `angular` its moment about the joint's point)
/// carried to the point `to` of the joint's parent, in the parent's unit vectors:
/// `linear` and `angular + (O_c − to) × linear`.
pub(super) fn carried_in(
    model: &Model,
    c: usize,
    to: &Components,
    (linear, angular): (&Vector, &Vector),
) -> (Components, Components) {
    let parent = model.problem.joints[c].parent;
    let linear = in_frame(model, linear, parent);
    let offset = joint_offset(model, c, to);
    let angular = sum(&in_frame(model, angular, parent), &cross3(&offset, &linear));
    (linear, angular)
}

/// The components of `v` in `frame`'s unit vectors, a part in the frame of a body `frame`
/// carries by one joint through that joint's named direction cosines.
pub(super) fn in_frame(model: &Model, v: &Vector, frame: BodyId) -> Components {
    let parts = v.parts().iter().map(|(from, c)| {
        if *from == frame {
            c.clone()
        } else if model.frames.info(*from).parent == Some(frame) {
            apply(&named_dcm(model, frame, *from), c)
        } else {
            model.frames.express(c, *from, frame)
        }
    });
    parts.fold(crate::mechanics::zero3(), |total, c| sum(&total, &c))
}

/// The direction cosines `to <- from` of one joint, each entry of more than one term named,
/// so that the products taken with it are products of names.
pub(super) fn named_dcm(model: &Model, to: BodyId, from: BodyId) -> Matrix {
    let matrix = model.frames.dcm(to, from);
    let (to_name, from_name) = (model.frames.name(to), model.frames.name(from));
    std::array::from_fn(|i| {
        std::array::from_fn(|k| {
            named(
                format!("{to_name}.crb.C.{from_name}.{}{}", i + 1, k + 1),
                format!(
                    "{{}}^{{{}}}C^{{{}}}_{{{}{}}}",
                    latex_name(to_name),
                    latex_name(from_name),
                    i + 1,
                    k + 1
                ),
                format!(
                    "the direction cosine {to_name}.{} · {from_name}.{}",
                    AXES[i], AXES[k]
                ),
                matrix[i][k].clone(),
            )
        })
    })
}

/// What a named vector is: the name's middle part, its LaTeX symbol and a description.
pub(super) type Label<'a> = (&'a str, &'a str, &'a str);

/// Three components, each of more than one term named `{body}.crb.{prefix}.{axis}`.
pub(super) fn named_components(
    model: &Model,
    body: BodyId,
    label: Label,
    value: Components,
) -> Components {
    named_in(model, body, body, label, value)
}

/// As [`named_components`] for each part of `value`, a part in another frame than `body`'s
/// named `{body}.crb.{prefix}.in.{frame}.{axis}`.
pub(super) fn named_vector(model: &Model, body: BodyId, label: Label, value: &Vector) -> Vector {
    let parts = value
        .parts()
        .iter()
        .map(|(frame, c)| Vector::new(*frame, named_in(model, body, *frame, label, c.clone())));
    Vector::sum(parts)
}

pub(super) fn named_in(
    model: &Model,
    body: BodyId,
    frame: BodyId,
    (prefix, symbol, what): Label,
    value: Components,
) -> Components {
    let name = model.frames.name(body);
    let (place, frame_name) = match frame == body {
        true => (String::new(), name),
        false => {
            let other = model.frames.name(frame);
            (format!(".in.{other}"), other)
        }
    };
    std::array::from_fn(|axis| {
        let axis_name = AXES[axis];
        named(
            format!("{name}.crb.{prefix}{place}.{axis_name}"),
            format!("{symbol}^{{{}}}_{{{axis_name}}}", latex_name(name)),
            format!("{what}, along {frame_name}.{axis_name}"),
            value[axis].clone(),
        )
    })
}

pub(super) fn apply(m: &Matrix, v: &Components) -> Components {
    crate::mechanics::apply(m, v)
}

pub(super) fn sum(a: &Components, b: &Components) -> Components {
    std::array::from_fn(|i| &a[i] + &b[i])
}

pub(super) const AXES: [&str; 3] = ["x", "y", "z"];

/// `value` under `label` when it has more than one term (a single term the compiler
/// computes once as it is).
pub(super) fn named(label: String, latex: String, note: String, value: Expr) -> Expr {
    if value.terms().len() < 2 {
        return value;
    }
    Expr::named(&label, &latex, &note, value)
}
