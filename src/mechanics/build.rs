//! Building the kinematic model of a problem: frames from the joints (step 1), then the
//! angular velocity and acceleration of every body and the motion of every point (step 4),
//! then the closures, contacts and constraints on them.

use super::angular::Angular;
use super::error::MechanicsError;
use super::frames::{FrameInfo, Frames, Matrix};
use super::joints::{joint_motion, load_axes, reaction_components, JointMotion};
use super::model::{dt_components, rigid_point, tree_order, BodyState, JointModel, Model};
use super::point::PointMotion;
use super::speeds::Speeds;
use super::vector::{own_components, zero3, Components, Vector};
use crate::problem::{BodyId, Dimension, Inertia, Problem};
use crate::symbolic::{eval, Expr, Symbol, Values};

impl<'p> Model<'p> {
    /// Builds the frames and the kinematics of every body of `problem`.
    ///
    /// # Errors
    /// When a joint axis is zero or not fixed in its parent, or a point is given in the
    /// unit vectors of a frame it is not fixed in.
    pub fn build(problem: &'p Problem) -> Result<Model<'p>, MechanicsError> {
        Model::build_for(problem, super::model::Form::Handout)
    }

    /// As [`Model::build`], the kinematics named as `form` reads them.
    ///
    /// # Errors
    /// As [`Model::build`].
    pub fn build_for(
        problem: &'p Problem,
        form: super::model::Form,
    ) -> Result<Model<'p>, MechanicsError> {
        let values = constant_values(problem);
        let speeds = Speeds::of(problem)?;
        let count = problem.bodies.len() + 1;
        let names = std::iter::once("N".to_string())
            .chain(problem.bodies.iter().map(|b| b.name.clone()))
            .collect();
        let mut frame_infos = vec![
            FrameInfo {
                parent: None,
                rotations: vec![]
            };
            count
        ];
        let order = tree_order(problem);
        let mut motions: Vec<Option<JointMotion>> = vec![None; problem.joints.len()];
        // In a plane, each body's angle from N about N.z: an absolute joint angle turns the
        // child by itself less its parent's.
        let mut absolute = vec![Expr::zero(); count];
        // Frames first, parents before children: an axis is read in its parent's frame.
        for &body in &order {
            let Some(j) = problem.joint_of(body) else {
                continue;
            };
            let joint = &problem.joints[j];
            let partial = Frames::new(frame_infos.clone(), Vec::new());
            let mut motion = joint_motion(problem, joint, &partial, &values)?;
            if joint.angle_from == Some(BodyId::GROUND) {
                if let Some(turn) = motion.rotations.first_mut() {
                    turn.angle = &turn.angle - &(&absolute[joint.parent.0] * &turn.axis[2]);
                }
            }
            if problem.dimension == Dimension::Two {
                absolute[body.0] = motion
                    .rotations
                    .iter()
                    .fold(absolute[joint.parent.0].clone(), |angle, turn| {
                        &angle + &(&turn.angle * &turn.axis[2])
                    });
            }
            frame_infos[body.0] = FrameInfo {
                parent: Some(joint.parent),
                rotations: motion.rotations.clone(),
            };
            motions[j] = Some(motion);
        }
        let frames = Frames::new(frame_infos, names);
        let ground = BodyState {
            frame: BodyId::GROUND,
            omega: Vector::zero(),
            omega_named: Vector::zero(),
            alpha: Vector::zero(),
            origin: PointMotion::default(),
            center: PointMotion::default(),
            center_offset: zero3(),
            mass: Expr::zero(),
            inertia: std::array::from_fn(|_| zero3()),
        };
        let mut bodies = vec![ground; count];
        let mut joints: Vec<Option<JointModel>> = vec![None; problem.joints.len()];
        for &body in &order {
            let Some(j) = problem.joint_of(body) else {
                continue;
            };
            let joint = &problem.joints[j];
            let Some(motion) = motions[j].take() else {
                continue;
            };
            let (state, joint_model) = body_kinematics(
                problem,
                &frames,
                &values,
                &bodies[joint.parent.0],
                (body, j),
                motion,
                (speeds.as_ref(), form),
            )?;
            bodies[body.0] = state;
            joints[j] = Some(joint_model);
        }
        let joints = joints.into_iter().flatten().collect();
        let mut model = Model {
            problem,
            frames,
            values,
            bodies,
            joints,
            order,
            sites: Vec::new(),
            constraints: Default::default(),
            speeds,
            spin_frames: Vec::new(),
        };
        let (sites, constraints) = super::constraints::build(&model)?;
        model.sites = sites;
        model.constraints = constraints;
        super::resal::write_without_spin(&mut model, form);
        super::massless::check(&model)?;
        Ok(model)
    }
}

fn constant_values(problem: &Problem) -> Values {
    let mut values = Values::new();
    for c in &problem.constants {
        values.set(Symbol::Const(c.name.as_str().into()), c.value);
    }
    values
}

fn body_kinematics(
    problem: &Problem,
    frames: &Frames,
    values: &Values,
    parent_state: &BodyState,
    (body, j): (BodyId, usize),
    motion: JointMotion,
    (speeds, form): (Option<&Speeds>, super::model::Form),
) -> Result<(BodyState, JointModel), MechanicsError> {
    let joint = &problem.joints[j];
    let parent = joint.parent;
    let path = &joint.path;
    let fail = |message: String| MechanicsError {
        path: path.clone(),
        message: format!("joint `{}`: {message}", joint.name),
        hint: None,
    };
    let relative = frames
        .relative_angular_velocity(body)
        .map_err(|e| fail(e.to_string()))?;
    let planar = problem.dimension == crate::problem::Dimension::Two;
    let Angular {
        omega,
        omega_named,
        alpha,
    } = if planar || speeds.is_some() {
        super::angular::multiplied_out(
            problem,
            frames,
            parent_state,
            (body, path),
            &relative,
            speeds,
        )?
    } else {
        super::angular::built(
            problem,
            frames,
            parent_state,
            (body, parent, form),
            &relative,
        )
        .map_err(fail)?
    };

    // The joint point on the parent, then the sliding along the joint, then back to the origin.
    let at = own_components(&joint.at, parent);
    let child_at = own_components(&joint.child_at, body);
    let d = motion.translation.clone();
    let d_rate = dt_components(&d, path, speeds)?;
    let d_accel = dt_components(&d_rate, path, speeds)?;
    let carried: Components = std::array::from_fn(|i| &at[i] + &d[i]);
    let carried_point = rigid_point(frames, parent_state, parent, &carried);
    let slide_rate = Vector::new(parent, d_rate);
    let joint_point = PointMotion {
        position: carried_point.position,
        velocity: carried_point.velocity.plus(&slide_rate),
        acceleration: Vector::sum([
            carried_point.acceleration,
            Vector::new(parent, d_accel),
            parent_state
                .omega_named
                .cross(&slide_rate, frames)
                .scaled(&Expr::int(2)),
        ]),
    };
    let back: Components = std::array::from_fn(|i| -child_at[i].clone());
    let partial_state = BodyState {
        frame: body,
        omega: omega.clone(),
        omega_named: omega_named.clone(),
        alpha: alpha.clone(),
        origin: joint_point.clone(),
        center: PointMotion::default(),
        center_offset: zero3(),
        mass: Expr::zero(),
        inertia: std::array::from_fn(|_| zero3()),
    };
    // The joint point moves with the child, so the origin follows by the rigid-body formulas.
    let origin = rigid_point(frames, &partial_state, body, &back);

    let declared = problem.body(body);
    let center_offset = own_components(&declared.center, body);
    let inertia = match &declared.inertia {
        Inertia::Planar(izz) => {
            let mut m: Matrix = std::array::from_fn(|_| zero3());
            m[2][2] = izz.clone();
            m
        }
        Inertia::Spatial(m) => m.clone(),
    };
    let massless = eval(&declared.mass, values) == 0.0;
    let mut state = BodyState {
        frame: body,
        omega,
        omega_named,
        alpha,
        origin,
        center: PointMotion::default(),
        center_offset: center_offset.clone(),
        // A massless body (mass 0, validated with no inertia) carries no weight and no
        // inertia force: written 0, its terms leave the equations and the diagrams.
        mass: if massless {
            Expr::zero()
        } else {
            declared.mass.clone()
        },
        inertia: if massless {
            std::array::from_fn(|_| zero3())
        } else {
            inertia
        },
    };
    state.center = rigid_point(frames, &state, body, &center_offset);
    let reactions = reaction_components(problem, joint, &motion, values);
    let axes = load_axes(joint, &motion, frames);
    let joint_model = JointModel {
        motion,
        at,
        child_at,
        reactions,
        load_axes: axes,
        point: joint_point,
    };
    Ok((state, joint_model))
}
