//! One joint as the articulated-body passes see it: its constant geometry, read once from
//! the model, and at each state the change of coordinates across it, its motion subspace
//! `S(q)`, its velocity `S q'` and the bias `S̊ q'` (the rate of `S` in the child's
//! coordinates times q').

use super::spatial::{join, Transform};
use crate::mechanics::JointModel;
use crate::problem::{Joint, JointKind};
use crate::symbolic::{eval, Expr, Values};
use nalgebra::{Matrix3, Vector3, Vector6};

/// The most coordinates one joint has (a free joint).
pub(super) const MAX_DOF: usize = 6;

/// A joint's constant geometry.
#[derive(Clone, Debug)]
pub(super) struct Geometry {
    /// The coordinates of the slides, each with its direction in the parent's unit vectors.
    slides: Vec<(usize, Vector3<f64>)>,
    /// The coordinates of the body-fixed rotations in order, each with its unit axis.
    turns: Vec<(usize, Vector3<f64>)>,
    /// The joint point on the parent, from the parent's origin, parent's unit vectors.
    at: Vector3<f64>,
    /// The joint point on the child, from the child's origin, child's unit vectors.
    child_at: Vector3<f64>,
}

/// A joint at one state.
#[derive(Clone, Copy, Debug)]
pub(super) struct State {
    /// From the parent's coordinates to the child's.
    pub transform: Transform,
    /// The columns of `S`, the first `dof` used, in the joint's coordinate order.
    pub s: [Vector6<f64>; MAX_DOF],
    /// `S q'`, the child's velocity relative to the parent.
    pub velocity: Vector6<f64>,
    /// `S̊ q'`.
    pub bias: Vector6<f64>,
}

/// The numbers of three constant expressions; `None` if one is not constant.
pub(super) fn numbers(c: &[Expr; 3], values: &Values) -> Option<Vector3<f64>> {
    if !c.iter().all(Expr::is_constant) {
        return None;
    }
    let v = Vector3::new(
        eval(&c[0], values),
        eval(&c[1], values),
        eval(&c[2], values),
    );
    v.iter().all(|x| x.is_finite()).then_some(v)
}

fn unit(axis: u8) -> Vector3<f64> {
    let mut v = Vector3::zeros();
    v[axis as usize] = 1.0;
    v
}

impl Geometry {
    /// The geometry of `joint`, as the model built it; `None` where it is not constant.
    pub fn new(joint: &Joint, model: &JointModel, values: &Values) -> Option<Geometry> {
        let c = &joint.coordinates;
        let sequence = |angles: &[usize]| -> Vec<(usize, Vector3<f64>)> {
            joint
                .sequence
                .iter()
                .zip(angles)
                .map(|(&a, &q)| (q, unit(a)))
                .collect()
        };
        // The axis as written: the way its coordinate increases (see `joint_motion`).
        let written = || {
            model
                .motion
                .written_axis
                .as_ref()
                .and_then(|a| numbers(a, values))
        };
        let (slides, turns) = match joint.kind {
            JointKind::Revolute => (vec![], vec![(c[0], written()?)]),
            JointKind::Prismatic => (vec![(c[0], written()?)], vec![]),
            JointKind::Cylindrical => (vec![(c[0], written()?)], vec![(c[1], written()?)]),
            JointKind::Planar => (
                vec![(c[0], unit(0)), (c[1], unit(1))],
                vec![(c[2], unit(2))],
            ),
            JointKind::Universal | JointKind::Spherical => (vec![], sequence(c)),
            JointKind::Free => (
                vec![(c[0], unit(0)), (c[1], unit(1)), (c[2], unit(2))],
                sequence(&c[3..]),
            ),
            JointKind::Weld => (vec![], vec![]),
        };
        if slides.len() + turns.len() != c.len() {
            return None;
        }
        Some(Geometry {
            slides,
            turns,
            at: numbers(&model.at, values)?,
            child_at: numbers(&model.child_at, values)?,
        })
    }

    /// The number of coordinates.
    pub fn dof(&self) -> usize {
        self.slides.len() + self.turns.len()
    }

    /// The joint's coordinates, in its order.
    pub fn coordinates(&self) -> impl Iterator<Item = usize> + '_ {
        self.slides.iter().chain(&self.turns).map(|(c, _)| *c)
    }

    /// The joint at coordinates `q` and rates `rates` (all of the problem's).
    pub fn state(&self, q: &[f64], rates: &[f64]) -> State {
        let mut d = Vector3::zeros();
        let mut d_rate = Vector3::zeros();
        for (c, direction) in &self.slides {
            d += direction * q[*c];
            d_rate += direction * rates[*c];
        }
        // Through the rotations in order: the rotation so far (parent <- current), the
        // relative angular velocity and its rate without q'' (current coordinates), and
        // each axis so far in the current coordinates.
        let mut turned = Matrix3::identity();
        let mut omega = Vector3::zeros();
        let mut omega_bias = Vector3::zeros();
        let mut axes = [Vector3::zeros(); MAX_DOF];
        for (j, (c, a)) in self.turns.iter().enumerate() {
            let back = rotation(a, q[*c]).transpose();
            let carried = back * omega;
            let spin = a * rates[*c];
            omega_bias = back * omega_bias + carried.cross(&spin);
            omega = carried + spin;
            for axis in &mut axes[..j] {
                *axis = back * *axis;
            }
            axes[j] = *a;
            turned *= back.transpose();
        }
        let e = turned.transpose();
        let c = self.child_at;
        let mut s = [Vector6::zeros(); MAX_DOF];
        for (k, (_, direction)) in self.slides.iter().enumerate() {
            s[k] = join(Vector3::zeros(), e * direction);
        }
        let first = self.slides.len();
        for (k, axis) in axes[..self.turns.len()].iter().enumerate() {
            s[first + k] = join(*axis, c.cross(axis));
        }
        let slide = e * d_rate;
        State {
            transform: Transform {
                e,
                r: self.at + d - turned * c,
            },
            s,
            velocity: join(omega, slide - omega.cross(&c)),
            bias: join(omega_bias, -omega.cross(&slide) - omega_bias.cross(&c)),
        }
    }
}

/// The rotation by `angle` about the unit `axis`: components in the turned frame to
/// components in the frame before (Rodrigues' formula, as the model's).
fn rotation(axis: &Vector3<f64>, angle: f64) -> Matrix3<f64> {
    let (s, c) = angle.sin_cos();
    Matrix3::identity() * c + super::spatial::skew(axis) * s + axis * axis.transpose() * (1.0 - c)
}
