//! The articulated-body algorithm (Featherstone, *Rigid Body Dynamics Algorithms*, table
//! 7.1): velocities outward, articulated inertias inward, accelerations outward; O(n).
//! A joint's `S` has at most six columns, so its projections are small loops over them
//! rather than 6×6 products.

// Index loops over the small matrices read as the formulas they compute.
#![allow(clippy::needless_range_loop)]

use super::joint::{State, MAX_DOF};
use super::spatial::{cross_force, cross_motion};
use super::Recursive;
use nalgebra::{Matrix6, Vector6};

/// A joint's projected articulated inertia, `D = Sᵀ Iᴬ S`, with a Cholesky pivot smaller
/// than this relative to its inertia's scale counts as singular: the dense form then
/// explains why.
const SINGULAR: f64 = 1e-13;

/// A small square matrix, the first dof rows and columns used.
type Small = [[f64; MAX_DOF]; MAX_DOF];

/// What the inward pass leaves for the outward one, per body.
#[derive(Clone, Copy, Debug, Default)]
struct Inward {
    /// The columns of `U = Iᴬ S`.
    u: [Vector6<f64>; MAX_DOF],
    /// `D⁻¹`.
    d_inverse: Small,
    /// `τ − Sᵀ pᴬ`, τ the loads' generalized forces on the joint's coordinates.
    free: [f64; MAX_DOF],
}

/// The per-body buffers of one evaluation, kept between evaluations.
#[derive(Clone, Debug, Default)]
pub(super) struct Scratch {
    /// The joint forces τ of the state, in coordinate order: written before the passes.
    pub tau: Vec<f64>,
    states: Vec<State>,
    velocity: Vec<Vector6<f64>>,
    bias: Vec<Vector6<f64>>,
    inertia: Vec<Matrix6<f64>>,
    force: Vec<Vector6<f64>>,
    inward: Vec<Inward>,
    acceleration: Vec<Vector6<f64>>,
}

/// The q'' at coordinates `q` and rates `rates` with the joint forces `s.tau`, in the
/// problem's coordinate order; `None` where a joint's articulated inertia is singular or a
/// value is not finite.
pub(super) fn accelerations(
    tree: &Recursive,
    s: &mut Scratch,
    q: &[f64],
    rates: &[f64],
) -> Option<Vec<f64>> {
    let n = tree.bodies.len();
    s.states.clear();
    s.velocity.clear();
    s.bias.clear();
    s.inertia.clear();
    s.force.clear();
    for body in &tree.bodies {
        let state = body.joint.state(q, rates);
        let carried = match body.parent {
            Some(p) => state.transform.motion(&s.velocity[p]),
            None => Vector6::zeros(),
        };
        let v = carried + state.velocity;
        s.bias.push(state.bias + cross_motion(&v, &state.velocity));
        s.inertia.push(body.inertia);
        s.force.push(cross_force(&v, &(body.inertia * v)));
        s.velocity.push(v);
        s.states.push(state);
    }
    s.inward.clear();
    s.inward.resize(n, Inward::default());
    for i in (0..n).rev() {
        let body = &tree.bodies[i];
        let (k, state, inertia) = (body.dof, &s.states[i], s.inertia[i]);
        let mut w = Inward::default();
        let mut d: Small = Default::default();
        for (a, c) in body.joint.coordinates().enumerate() {
            w.u[a] = inertia * state.s[a];
            w.free[a] = s.tau[c] - state.s[a].dot(&s.force[i]);
            for b in 0..=a {
                let x = state.s[b].dot(&w.u[a]);
                d[a][b] = x;
                d[b][a] = x;
            }
        }
        let scale = inertia.diagonal().amax().max(f64::MIN_POSITIVE);
        w.d_inverse = inverse(&d, k, SINGULAR * scale)?;
        if let Some(p) = body.parent {
            let mut articulated = inertia;
            let mut passed = s.force[i];
            for a in 0..k {
                // Column a of U D⁻¹.
                let mut ud = Vector6::zeros();
                for b in 0..k {
                    ud += w.u[b] * w.d_inverse[b][a];
                }
                articulated -= ud * w.u[a].transpose();
                passed += ud * w.free[a];
            }
            passed += articulated * s.bias[i];
            let back = state.transform.inertia_back(&articulated);
            let pushed = state.transform.force_back(&passed);
            s.inertia[p] += back;
            s.force[p] += pushed;
        }
        s.inward[i] = w;
    }
    let mut out = vec![0.0; q.len()];
    s.acceleration.clear();
    for (i, body) in tree.bodies.iter().enumerate() {
        let state = &s.states[i];
        let parent = match body.parent {
            Some(p) => s.acceleration[p],
            None => tree.ground,
        };
        let carried = state.transform.motion(&parent) + s.bias[i];
        let w = &s.inward[i];
        let k = body.dof;
        let mut rest = [0.0; MAX_DOF];
        for a in 0..k {
            rest[a] = w.free[a] - w.u[a].dot(&carried);
        }
        let mut a = carried;
        for (j, c) in body.joint.coordinates().enumerate() {
            let qdd: f64 = (0..k).map(|b| w.d_inverse[j][b] * rest[b]).sum();
            out[c] = qdd;
            a += state.s[j] * qdd;
        }
        s.acceleration.push(a);
    }
    out.iter().all(|x| x.is_finite()).then_some(out)
}

/// The inverse of the symmetric `d`'s leading k×k block by Cholesky; `None` when a pivot
/// is not above `smallest`.
fn inverse(d: &Small, k: usize, smallest: f64) -> Option<Small> {
    let mut l: Small = Default::default();
    for j in 0..k {
        let mut pivot = d[j][j];
        for p in 0..j {
            pivot -= l[j][p] * l[j][p];
        }
        if pivot.is_nan() || pivot <= smallest {
            return None;
        }
        l[j][j] = pivot.sqrt();
        for i in j + 1..k {
            let mut x = d[i][j];
            for p in 0..j {
                x -= l[i][p] * l[j][p];
            }
            l[i][j] = x / l[j][j];
        }
    }
    // Column by column: L y = e_c, then Lᵀ x = y.
    let mut out: Small = Default::default();
    for c in 0..k {
        let mut y = [0.0; MAX_DOF];
        for i in 0..k {
            let mut x = if i == c { 1.0 } else { 0.0 };
            for p in 0..i {
                x -= l[i][p] * y[p];
            }
            y[i] = x / l[i][i];
        }
        for i in (0..k).rev() {
            let mut x = y[i];
            for p in i + 1..k {
                x -= l[p][i] * out[p][c];
            }
            out[i][c] = x / l[i][i];
        }
    }
    Some(out)
}
