//! Building the kinematic model of a problem: frames from the joints (step 1), then the
//! angular velocity and acceleration of every body and the motion of every point (step 4).

use super::angular::Angular;
use super::frames::{FrameInfo, Frames, Matrix};
use super::joints::{
    joint_motion, load_axes, reaction_components, JointMotion, LoadAxis, ReactionComponent,
};
use super::speeds::Speeds;
use super::vector::{zero3, Components, Vector};
use super::MechanicsError;
use crate::problem::{BodyId, Dimension, Inertia, PointRef, Problem, VectorExpr};
use crate::symbolic::diff::time_derivative;
use crate::symbolic::eval::{eval, Values};
use crate::symbolic::{Expr, Symbol};

/// Position, velocity and acceleration of a point in `N`.
#[derive(Clone, Debug, Default)]
pub struct PointMotion {
    /// From `N.o`.
    pub position: Vector,
    /// The velocity in `N`.
    pub velocity: Vector,
    /// The acceleration in `N`.
    pub acceleration: Vector,
}

/// The kinematics of one body.
#[derive(Clone, Debug)]
pub struct BodyState {
    /// Angular velocity in `N`, in the body's own unit vectors.
    pub omega: Vector,
    /// The same with components kept whole as named symbols, for the velocity products
    /// `ω×(ω×r)` and `ω×I·ω`: multiplied out, `(q1' + … + qk')^2` alone would be k² terms.
    /// Planar problems name every sum; spatial ones only the long components.
    pub omega_named: Vector,
    /// Angular acceleration in `N`, in the body's own unit vectors.
    pub alpha: Vector,
    /// The body's origin.
    pub origin: PointMotion,
    /// The mass center `B*`.
    pub center: PointMotion,
    /// The mass center from the origin, in the body's unit vectors.
    pub center_offset: Components,
    /// The mass (zero for `N`).
    pub mass: Expr,
    /// The central inertia matrix in the body's unit vectors (2D: only `zz` is set).
    pub inertia: Matrix,
}

/// A joint with what it allows and what it transmits.
#[derive(Clone, Debug)]
pub struct JointModel {
    /// Its rotations and translation.
    pub motion: JointMotion,
    /// The joint point on the parent, from the parent's origin, parent's unit vectors.
    pub at: Components,
    /// The joint point on the child, from the child's origin, child's unit vectors.
    pub child_at: Components,
    /// The reaction components, each an unknown of the joint (`O.Fx`).
    pub reactions: Vec<ReactionComponent>,
    /// Where a joint load on each coordinate acts.
    pub load_axes: Vec<LoadAxis>,
    /// The motion of the joint's point on the child.
    pub point: PointMotion,
}

/// The kinematic model of a problem.
#[derive(Debug)]
pub struct Model<'p> {
    /// The problem it was built from.
    pub problem: &'p Problem,
    /// Every body's frame, `N` first.
    pub frames: Frames,
    /// The constants' values, for decisions that need numbers (never baked into equations).
    pub values: Values,
    /// Indexed by body id, `N` first.
    pub bodies: Vec<BodyState>,
    /// Indexed like [`Problem::joints`].
    pub joints: Vec<JointModel>,
    /// Bodies with parents before children (`N` excluded).
    pub order: Vec<BodyId>,
    /// Where reactions act: the joints (indexed like [`Problem::joints`]), then the
    /// closures, then one per entry of `constraints` (only rolling contacts carry reactions).
    pub sites: Vec<super::sites::Site>,
    /// Closures, contacts, constraint entries and prescribed coordinates as rows.
    pub constraints: super::constraints::Constraints,
    /// The declared speeds' kinematic differential equations; `None` when the speeds are
    /// the rates. With them the kinematics are written with `u` and `u'`.
    pub speeds: Option<super::speeds::Speeds>,
}

/// The vector a [`VectorExpr`] describes.
pub fn vector_of(written: &VectorExpr) -> Vector {
    Vector::sum(
        written.terms.iter().map(|(frame, axis, coefficient)| {
            Vector::unit(*frame, *axis as usize).scaled(coefficient)
        }),
    )
}

/// Components of a vector written in the body's own unit vectors (as `at`, `center` are).
pub fn own_components(written: &VectorExpr, frame: BodyId) -> Components {
    let mut c = zero3();
    for (f, axis, coefficient) in &written.terms {
        if *f == frame {
            c[*axis as usize] = &c[*axis as usize] + coefficient;
        }
    }
    c
}

fn constant_values(problem: &Problem) -> Values {
    let mut values = Values::new();
    for c in &problem.constants {
        values.set(Symbol::Const(c.name.as_str().into()), c.value);
    }
    values
}

pub(super) fn dt_components(
    c: &Components,
    path: &str,
    speeds: Option<&Speeds>,
) -> Result<Components, MechanicsError> {
    let d = |e: &Expr| {
        match speeds {
            Some(s) => s.dt(e),
            None => time_derivative(e),
        }
        .map_err(|e| MechanicsError {
            path: path.to_string(),
            message: e.to_string(),
            hint: None,
        })
    };
    Ok([d(&c[0])?, d(&c[1])?, d(&c[2])?])
}

impl<'p> Model<'p> {
    /// Builds the frames and the kinematics of every body of `problem`.
    ///
    /// # Errors
    /// When a joint axis is zero or not fixed in its parent, or a point is given in the
    /// unit vectors of a frame it is not fixed in.
    pub fn build(problem: &'p Problem) -> Result<Model<'p>, MechanicsError> {
        Model::build_for(problem, super::Form::Handout)
    }

    /// As [`Model::build`], the kinematics named as `form` reads them.
    ///
    /// # Errors
    /// As [`Model::build`].
    pub fn build_for(problem: &'p Problem, form: super::Form) -> Result<Model<'p>, MechanicsError> {
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
        // Frames first, parents before children: an axis is read in its parent's frame.
        for &body in &order {
            let Some(j) = problem.joint_of(body) else {
                continue;
            };
            let joint = &problem.joints[j];
            let partial = Frames::new(frame_infos.clone(), Vec::new());
            let motion = joint_motion(problem, joint, &partial, &values)?;
            frame_infos[body.0] = FrameInfo {
                parent: Some(joint.parent),
                rotations: motion.rotations.clone(),
            };
            motions[j] = Some(motion);
        }
        let frames = Frames::new(frame_infos, names);
        let ground = BodyState {
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
        };
        let (sites, constraints) = super::constraints::build(&model)?;
        model.sites = sites;
        model.constraints = constraints;
        super::massless::check(&model)?;
        Ok(model)
    }

    /// The motion of a point fixed on `body` at `offset` (body's unit vectors) from its origin.
    pub fn point_on(&self, body: BodyId, offset: &Components) -> PointMotion {
        rigid_point(&self.frames, &self.bodies[body.0], body, offset)
    }

    /// The position alone of a point fixed on `body` at `offset`: a moment arm needs no
    /// velocity or acceleration, whose cross products are most of [`Model::point_on`]'s work.
    pub fn position_on(&self, body: BodyId, offset: &Components) -> Vector {
        self.bodies[body.0]
            .origin
            .position
            .plus(&Vector::new(body, offset.clone()))
    }

    /// The position of a named point.
    pub fn position(&self, point: PointRef) -> Vector {
        let (body, offset) = self.locate(point);
        self.position_on(body, &offset)
    }

    /// The body a point belongs to and its offset from that body's origin.
    pub fn locate(&self, point: PointRef) -> (BodyId, Components) {
        match point {
            PointRef::Named(i) => {
                let p = &self.problem.points[i];
                (p.on, own_components(&p.at, p.on))
            }
            PointRef::MassCenter(b) => (b, self.bodies[b.0].center_offset.clone()),
            PointRef::Origin(b) => (b, zero3()),
            PointRef::Joint(j) => (
                self.problem.joints[j].child,
                self.joints[j].child_at.clone(),
            ),
        }
    }

    /// The motion of a named point.
    pub fn point(&self, point: PointRef) -> PointMotion {
        let (body, offset) = self.locate(point);
        self.point_on(body, &offset)
    }

    /// The ancestors of `body` up to `N` excluded, `body` included.
    pub fn is_in_subtree(&self, body: BodyId, root: BodyId) -> bool {
        let mut current = Some(body);
        while let Some(b) = current {
            if b == root {
                return true;
            }
            current = self.frames.info(b).parent;
        }
        false
    }

    /// The bodies outboard of joint `j`: its child and everything carried by it.
    pub fn subtree(&self, j: usize) -> Vec<BodyId> {
        let root = self.problem.joints[j].child;
        self.order
            .iter()
            .copied()
            .filter(|&b| self.is_in_subtree(b, root))
            .collect()
    }

    /// Components in own frame made a vector of that frame.
    pub fn own(frame: BodyId, c: &Components) -> Vector {
        Vector::new(frame, c.clone())
    }

    /// The constants' values with the coordinates `q`, their `rates` and time `t`.
    pub fn values_at(&self, t: f64, q: &[f64], rates: &[f64]) -> Values {
        let problem = self.problem;
        let mut values = self.values.clone();
        for (i, (q, rate)) in q.iter().zip(rates).enumerate() {
            values.set(problem.coordinate_symbol(i, 0), *q);
            values.set(problem.coordinate_symbol(i, 1), *rate);
        }
        values.set(Symbol::Time, t);
        for (r, speed) in problem.speeds.iter().enumerate() {
            let u = crate::symbolic::eval::eval(&speed.equals, &values);
            values.set(problem.speed_symbol(r, 1), u);
        }
        values
    }

    /// Whether the problem is planar.
    pub fn is_planar(&self) -> bool {
        self.problem.dimension == Dimension::Two
    }
}

/// The declared bodies, parents before children, siblings in file order.
pub fn tree_order(problem: &Problem) -> Vec<BodyId> {
    let mut order = Vec::new();
    let mut frontier = vec![BodyId::GROUND];
    while let Some(parent) = frontier.pop() {
        let children: Vec<BodyId> = problem
            .joints
            .iter()
            .filter(|j| j.parent == parent)
            .map(|j| j.child)
            .collect();
        for child in children.iter().rev() {
            frontier.push(*child);
        }
        if parent != BodyId::GROUND {
            order.push(parent);
        }
        if order.len() > problem.bodies.len() {
            break;
        }
    }
    order
}

fn rigid_point(
    frames: &Frames,
    state: &BodyState,
    body: BodyId,
    offset: &Components,
) -> PointMotion {
    let r = Vector::new(body, offset.clone());
    let w_x_r = state.omega.cross(&r, frames);
    PointMotion {
        position: state.origin.position.plus(&r),
        velocity: state.origin.velocity.plus(&w_x_r),
        acceleration: Vector::sum([
            state.origin.acceleration.clone(),
            state.alpha.cross(&r, frames),
            state
                .omega_named
                .cross(&state.omega_named.cross(&r, frames), frames),
        ]),
    }
}

fn body_kinematics(
    problem: &Problem,
    frames: &Frames,
    values: &Values,
    parent_state: &BodyState,
    (body, j): (BodyId, usize),
    motion: JointMotion,
    (speeds, form): (Option<&Speeds>, super::Form),
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

/// Whether `a` and `b` have the same value at every one of `states` (to 1e-9, relative): an
/// identity holds there, and a slip in a name would not.
pub fn same_at(a: &Expr, b: &Expr, states: &[Values]) -> bool {
    states.iter().all(|state| {
        let (x, y) = (
            crate::symbolic::eval::eval(a, state),
            crate::symbolic::eval::eval(b, state),
        );
        (x - y).abs() <= 1e-9 * (1.0 + y.abs())
    })
}

/// States at which a choice of rows must be nonsingular: the initial state and a few generic
/// ones (seeded, so the choice is the same every run). Requiring rank at all of them keeps the
/// planner away from rows that only look independent at one state.
pub fn sample_states(model: &Model) -> Vec<Values> {
    let problem = model.problem;
    let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    };
    let mut states = Vec::new();
    for sample in 0..4 {
        let (mut q, mut rates) = (Vec::new(), Vec::new());
        for c in &problem.coordinates {
            let (value, rate) = if sample == 0 {
                (c.initial, c.rate)
            } else {
                (c.initial + next(), c.rate + next())
            };
            q.push(value);
            rates.push(rate);
        }
        states.push(model.values_at(0.37 * sample as f64, &q, &rates));
    }
    states
}
