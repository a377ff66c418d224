//! The kinematic model of a problem: every body's frame, angular velocity and
//! acceleration, the motion of its points, and the sites and constraints on it; built in
//! [`super::build`].

use super::constraint_rows::Constraints;
use super::error::MechanicsError;
use super::frames::{Frames, Matrix};
use super::joints::{JointMotion, LoadAxis, ReactionComponent};
pub use super::point::PointMotion;
use super::site::Site;
use super::speeds::Speeds;
pub use super::vector::own_components;
use super::vector::{zero3, Components, Vector};
use crate::problem::{BodyId, Dimension, PointRef, Problem};
use crate::symbolic::{time_derivative, Expr, Symbol, Values};

/// Who reads the equations: how much of the kinematics is named depends on it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// A student, in the worked solution: a planar acceleration is written whole, and a
    /// spatial one named where it is long.
    Handout,
    /// The compiled program only: every long acceleration gets named parts, and every
    /// partial angular velocity past the first body, the fewest operations.
    Numeric,
}

/// The kinematics of one body.
#[derive(Clone, Debug)]
pub struct BodyState {
    /// The frame the body's `omega`, `alpha` and `inertia` are written in: its own, or for
    /// a body spinning about its symmetry axis the frame that does not spin (Resal's, see
    /// `mechanics/resal.rs`).
    pub frame: BodyId,
    /// Angular velocity in `N`, in the unit vectors of `frame`.
    pub omega: Vector,
    /// The same with components kept whole as named symbols, for the velocity products
    /// `ω×(ω×r)` and `ω×I·ω`: multiplied out, `(q1' + … + qk')^2` alone would be k² terms.
    /// Planar problems name every sum; spatial ones only the long components.
    pub omega_named: Vector,
    /// Angular acceleration in `N`, in the unit vectors of `frame`.
    pub alpha: Vector,
    /// The body's origin.
    pub origin: PointMotion,
    /// The mass center `B*`.
    pub center: PointMotion,
    /// The mass center from the origin, in the body's unit vectors.
    pub center_offset: Components,
    /// The mass (zero for `N`).
    pub mass: Expr,
    /// The central inertia matrix in the unit vectors of `frame` (2D: only `zz` is set).
    pub inertia: Matrix,
}

/// A body written in a frame that does not spin with it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpinFrame {
    /// The spinning body.
    pub body: BodyId,
    /// The frame its ω, α and inertia are written in: the parent's (one rotation), or a
    /// frame of its own after the joint's other rotations, named like a body.
    pub frame: BodyId,
    /// Whether `frame` was added for it (not a body's frame).
    pub added: bool,
    /// The spin angle: the coordinate of the joint's last rotation.
    pub spin: usize,
    /// The symmetry axis (0, 1, 2: x, y, z of the body).
    pub axis: usize,
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
    pub sites: Vec<Site>,
    /// Closures, contacts, constraint entries and prescribed coordinates as rows.
    pub constraints: Constraints,
    /// The declared speeds' kinematic differential equations; `None` when the speeds are
    /// the rates. With them the kinematics are written with `u` and `u'`.
    pub speeds: Option<Speeds>,
    /// The bodies written in a frame that does not spin with them (the worked solution's).
    pub spin_frames: Vec<SpinFrame>,
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
            let u = crate::symbolic::eval(&speed.equals, &values);
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

pub(super) fn rigid_point(
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

/// Whether `a` and `b` have the same value at every one of `states` (to 1e-9, relative): an
/// identity holds there, and a slip in a name would not.
pub fn same_at(a: &Expr, b: &Expr, states: &[Values]) -> bool {
    states.iter().all(|state| {
        let (x, y) = (
            crate::symbolic::eval(a, state),
            crate::symbolic::eval(b, state),
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
