//! Frames that do not spin (Resal's): a body symmetric about the axis of its last joint
//! angle (a top, a rotor, a wheel on its axle) has the same inertia in every frame turned
//! about that axis. Its angular velocity, angular acceleration and moments are then written
//! in the frame after the joint's other angles — the parent's frame for a revolute joint —
//! where the spin angle never appears: ω = ω^A + φ̇ â_z, α = ᴬd ω/dt + ω^A × ω. A textbook
//! derives the heavy top's gyroscopic equations so, in three lines.
//!
//! Only for the worked solution (the numbers are the same either way), only without
//! declared speeds (those stay as given), and only for a body whose spin changes nothing
//! else: mass centre and joint point on the axis, no children, no contacts or closures but
//! a rolling contact about that axis (a wheel, a coin), no forces, springs or dampers
//! attached to it (torques and joint loads are fine).

use super::angular::omega_component_named;
use super::components::{cross3, Components};
use super::frames::{FrameInfo, Frames};
use super::model::{rigid_point, Form, Model, SpinFrame};
use super::vector::Vector;
use crate::problem::{BodyId, Dimension, ForcePoint, LoadKind, PointRef, Problem};
use crate::symbolic::{simplify, time_derivative, Expr};

/// Writes every body that qualifies in its frame that does not spin (see the module).
pub(super) fn write_without_spin(model: &mut Model, form: Form) {
    let problem = model.problem;
    if form != Form::Handout || problem.dimension != Dimension::Three || model.speeds.is_some() {
        return;
    }
    for body in problem.body_ids() {
        let Some(j) = problem.joint_of(body) else {
            continue;
        };
        let Some((spin, axis)) = spin_of(model, body, j) else {
            continue;
        };
        let rotations = &model.frames.info(body).rotations;
        let parent = problem.joints[j].parent;
        let (frame, added) = if rotations.len() == 1 {
            (parent, false)
        } else {
            let info = FrameInfo {
                parent: Some(parent),
                rotations: rotations[..rotations.len() - 1].to_vec(),
            };
            let name = free_letter(problem, &model.frames);
            (model.frames.push(info, name), true)
        };
        let spin_frame = SpinFrame {
            body,
            frame,
            added,
            spin,
            axis,
        };
        rewrite(model, &spin_frame);
        model.spin_frames.push(spin_frame);
    }
}

/// The spin coordinate and the symmetry axis when `body` qualifies.
fn spin_of(model: &Model, body: BodyId, j: usize) -> Option<(usize, usize)> {
    let problem = model.problem;
    let last = model.frames.info(body).rotations.last()?;
    let spin = (0..problem.coordinates.len())
        .find(|&c| last.angle.as_symbol() == Some(&problem.coordinate_symbol(c, 0)))?;
    let axis = (0..3).find(|&k| last.axis[k].is_one())?;
    let others = [(axis + 1) % 3, (axis + 2) % 3];
    if others.iter().any(|&k| !last.axis[k].is_zero()) {
        return None;
    }
    let state = &model.bodies[body.0];
    let i = &state.inertia;
    let symmetric = simplify(&(&i[others[0]][others[0]] - &i[others[1]][others[1]])).is_zero()
        && (0..3).all(|a| (0..3).all(|b| a == b || i[a][b].is_zero()));
    let on_axis = |c: &Components| others.iter().all(|&k| c[k].is_zero());
    // A wheel's rolling contact about the same axis is the same in every frame turned
    // about it: the contact point is below the centre whatever the spin. Only where the
    // frame is added after the joint's other angles (the coin's lean frame): a wheel on an
    // axle would be written in the axle's frame, which turns with the carrier's pitch.
    let added = model.frames.info(body).rotations.len() > 1;
    let alone = !problem.joints.iter().any(|joint| joint.parent == body)
        && model
            .sites
            .iter()
            .filter(|s| s.parent == body || s.child == body)
            .filter(|s| !(added && rolls_about(model, s, body, axis)))
            .count()
            == 1
        && !problem.loads.iter().any(|l| pulls_on(model, &l.kind, body));
    (symmetric
        && on_axis(&state.center_offset)
        && on_axis(&model.joints[j].child_at)
        && alone
        && !state.mass.is_zero())
    .then_some((spin, axis))
}

/// Whether `site` is a rolling contact of `body` as a wheel about its own `axis`, its
/// centre on that axis.
fn rolls_about(model: &Model, site: &super::Site, body: BodyId, axis: usize) -> bool {
    let super::SiteKind::Contact(k) = site.kind else {
        return false;
    };
    let crate::problem::ConstraintKind::Rolling {
        axis: wheel_axis,
        center,
        ..
    } = &model.problem.constraints[k].kind
    else {
        return false;
    };
    let along = crate::mechanics::vector_of(wheel_axis).components_in(body, &model.frames);
    let centre = super::sites::offset_on(model, center, body);
    let off_axis = |c: &Components| (0..3).any(|i| i != axis && !simplify(&c[i]).is_zero());
    site.child == body
        && !simplify(&along[axis]).is_zero()
        && !off_axis(&along)
        && !off_axis(&centre)
}

/// Whether a load acts at a point of `body` (a force, or a spring's or damper's end).
fn pulls_on(model: &Model, kind: &LoadKind, body: BodyId) -> bool {
    let on_body = |p: &PointRef| model.locate(*p).0 == body;
    match kind {
        LoadKind::Force { on, at, .. } => {
            *on == body || matches!(at, ForcePoint::Point(p) if on_body(p))
        }
        LoadKind::Spring { between, .. } | LoadKind::Damper { between, .. } => {
            between.iter().any(on_body)
        }
        LoadKind::Torque { .. }
        | LoadKind::JointSpring { .. }
        | LoadKind::JointDamper { .. }
        | LoadKind::JointActuator { .. } => false,
    }
}

/// ω, α, the origin and the mass centre of the body, written in the frame that does not spin.
fn rewrite(model: &mut Model, spin: &SpinFrame) {
    let problem = model.problem;
    let frames = &model.frames;
    let body = spin.body;
    let parent = problem.joints[problem.joint_of(body).unwrap_or_default()].parent;
    let parent_state = &model.bodies[parent.0];
    // ω^A: the parent's carried into A, plus A's own turning in the parent.
    let own = match spin.added {
        true => frames.relative_angular_velocity(spin.frame).ok(),
        false => Some(std::array::from_fn(|_| Expr::zero())),
    };
    let Some(own) = own else {
        return;
    };
    let carried = parent_state.omega.components_in(spin.frame, frames);
    let frame_omega: Components = std::array::from_fn(|k| simplify(&(&carried[k] + &own[k])));
    let rate = problem.coordinate_expr(spin.spin, 1);
    let omega: Components = std::array::from_fn(|k| match k == spin.axis {
        true => simplify(&(&frame_omega[k] + &rate)),
        false => frame_omega[k].clone(),
    });
    // α = ᴬdω/dt + ω^A × ω.
    let Ok(derivative) = omega
        .clone()
        .map(|c| time_derivative(&c))
        .into_iter()
        .collect::<Result<Vec<_>, _>>()
    else {
        return;
    };
    let turning = cross3(&frame_omega, &omega);
    let alpha: Components = std::array::from_fn(|k| simplify(&(&derivative[k] + &turning[k])));
    let name = problem.body_name(body).to_string();
    let named: Components =
        std::array::from_fn(|k| omega_component_named(&name, k, omega[k].terms().len(), &omega[k]));
    let j = problem.joint_of(body).unwrap_or_default();
    let joint_point = model.joints[j].point.clone();
    let back = model.joints[j].child_at.clone().map(|c| -c);
    let state = &mut model.bodies[body.0];
    state.frame = spin.frame;
    state.omega = Vector::new(spin.frame, omega);
    state.omega_named = Vector::new(spin.frame, named);
    state.alpha = Vector::new(spin.frame, alpha);
    // Points on the axis have the same components in A as in the body.
    state.origin = joint_point;
    state.origin = rigid_point(frames, state, spin.frame, &back);
    state.center = rigid_point(frames, state, spin.frame, &state.center_offset.clone());
}

/// The first capital letter that names no body and no frame (`N` is taken).
fn free_letter(problem: &Problem, frames: &Frames) -> String {
    let taken = |name: &str| {
        (0..frames.len()).any(|f| frames.name(BodyId(f)).eq_ignore_ascii_case(name))
            || problem
                .bodies
                .iter()
                .any(|b| b.name.eq_ignore_ascii_case(name))
    };
    ('A'..='Z')
        .map(String::from)
        .find(|l| l != "N" && !taken(l))
        .unwrap_or_else(|| format!("F{}", frames.len()))
}
