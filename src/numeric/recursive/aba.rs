//! The articulated-body algorithm (Featherstone, *Rigid Body Dynamics Algorithms*, table
//! 7.1): velocities outward, articulated inertias inward, accelerations outward; O(n).

use super::joint::{State, MAX_DOF};
use super::spatial::{cross_force, cross_motion};
use super::Recursive;
use nalgebra::{Matrix6, Vector6};

/// A joint's projected articulated inertia, `D = Sᵀ Iᴬ S`, smaller than this relative to
/// its inertia's scale counts as zero: the dense form then explains the singularity.
const SINGULAR: f64 = 1e-13;

/// What the inward pass leaves for the outward one, per body.
#[derive(Clone, Copy)]
struct Inward {
    /// `U = Iᴬ S`, the first dof columns used.
    u: Matrix6<f64>,
    /// `D⁻¹`, padded with the identity past the dof.
    d_inverse: Matrix6<f64>,
    /// `τ − Sᵀ pᴬ` (τ = 0: no loads).
    free: Vector6<f64>,
}

/// The q'' at coordinates `q` and rates `rates`, in the problem's coordinate order; `None`
/// where a joint's articulated inertia is singular or a value is not finite.
pub(super) fn accelerations(tree: &Recursive, q: &[f64], rates: &[f64]) -> Option<Vec<f64>> {
    let n = tree.bodies.len();
    let mut states: Vec<State> = Vec::with_capacity(n);
    let mut velocity = vec![Vector6::zeros(); n];
    let mut bias = vec![Vector6::zeros(); n];
    let mut inertia = vec![Matrix6::zeros(); n];
    let mut force = vec![Vector6::zeros(); n];
    for (i, body) in tree.bodies.iter().enumerate() {
        let state = body.joint.state(q, rates);
        let carried = match body.parent {
            Some(p) => state.transform.motion(&velocity[p]),
            None => Vector6::zeros(),
        };
        velocity[i] = carried + state.velocity;
        bias[i] = state.bias + cross_motion(&velocity[i], &state.velocity);
        inertia[i] = body.inertia;
        force[i] = cross_force(&velocity[i], &(body.inertia * velocity[i]));
        states.push(state);
    }
    let mut inward = vec![
        Inward {
            u: Matrix6::zeros(),
            d_inverse: Matrix6::identity(),
            free: Vector6::zeros(),
        };
        n
    ];
    for i in (0..n).rev() {
        let dof = tree.bodies[i].dof;
        let state = &states[i];
        let mut s = Matrix6::zeros();
        for k in 0..dof {
            s.set_column(k, &state.s[k]);
        }
        let u = inertia[i] * s;
        let mut d = s.transpose() * u;
        let scale = inertia[i].diagonal().amax().max(f64::MIN_POSITIVE);
        for k in dof..MAX_DOF {
            d[(k, k)] = 1.0;
        }
        let d_inverse = match dof {
            0 => Matrix6::identity(),
            1 => {
                if !(d[(0, 0)] > SINGULAR * scale) {
                    return None;
                }
                let mut m = Matrix6::identity();
                m[(0, 0)] = 1.0 / d[(0, 0)];
                m
            }
            _ => {
                let cholesky = d.cholesky()?;
                let l = cholesky.l_dirty();
                if (0..dof).any(|k| !(l[(k, k)] * l[(k, k)] > SINGULAR * scale)) {
                    return None;
                }
                cholesky.inverse()
            }
        };
        let free = -(s.transpose() * force[i]);
        inward[i] = Inward { u, d_inverse, free };
        if let Some(p) = tree.bodies[i].parent {
            let ud = u * d_inverse;
            let articulated = inertia[i] - ud * u.transpose();
            let passed = force[i] + articulated * bias[i] + ud * free;
            inertia[p] += state.transform.inertia_back(&articulated);
            force[p] += state.transform.force_back(&passed);
        }
    }
    let mut out = vec![0.0; q.len()];
    let mut acceleration = vec![Vector6::zeros(); n];
    for (i, body) in tree.bodies.iter().enumerate() {
        let state = &states[i];
        let parent = match body.parent {
            Some(p) => acceleration[p],
            None => tree.ground,
        };
        let carried = state.transform.motion(&parent) + bias[i];
        let Inward { u, d_inverse, free } = inward[i];
        let qdd = d_inverse * (free - u.transpose() * carried);
        let mut a = carried;
        for (k, c) in body.joint.coordinates().enumerate() {
            out[c] = qdd[k];
            a += state.s[k] * qdd[k];
        }
        acceleration[i] = a;
    }
    out.iter().all(|x| x.is_finite()).then_some(out)
}
