//! The frame an answer's components are in: a reaction's are along its site's parent's
//! unit vectors (a joint's or a closure's parent; for a gear, a rolling contact or a
//! contact, the body its `on` names), unless the question asks for them in another frame
//! (`"in": "N"`), when they are rotated into that frame at the answer's state.

use super::system::ReactionColumn;
use crate::mechanics::{Frames, Model};
use crate::problem::{BodyId, ConstraintKind, Problem};
use crate::symbolic::{eval, ComponentKind, Values};

/// A rotation matrix of numbers, row-major.
pub type Rotation = [[f64; 3]; 3];

/// The body whose unit vectors reaction site `site`'s components are written in.
pub fn reaction_frame(problem: &Problem, site: usize) -> BodyId {
    let (j, c) = (problem.joints.len(), problem.closures.len());
    if site < j {
        return problem.joints[site].parent;
    }
    if site < j + c {
        return problem.closures[site - j].parent;
    }
    match problem.constraints.get(site - j - c).map(|k| &k.kind) {
        Some(
            ConstraintKind::Rolling { on, .. }
            | ConstraintKind::Gear { on, .. }
            | ConstraintKind::Contact { on, .. },
        ) => *on,
        _ => BodyId::GROUND,
    }
}

/// The name of the frame of site `name`'s reaction (`N` for a name that is no site).
pub fn reaction_frame_named<'p>(problem: &'p Problem, name: &str) -> &'p str {
    let sites = problem.joints.len() + problem.closures.len() + problem.constraints.len();
    (0..sites)
        .find(|&s| problem.site_name(s) == name)
        .map_or("N", |s| problem.body_name(reaction_frame(problem, s)))
}

/// The matrix taking components in `frame` to components in `N` at `values`: the product
/// of the elementary rotations from `N` down to `frame`, each evaluated.
fn orientation(frames: &Frames, frame: BodyId, values: &Values) -> Rotation {
    let mut m = identity();
    for body in frames.path_from_ground(frame) {
        for rotation in &frames.info(body).rotations {
            let r = rotation.matrix().map(|row| row.map(|e| eval(&e, values)));
            m = multiply(&m, &r);
        }
    }
    m
}

fn identity() -> Rotation {
    std::array::from_fn(|i| std::array::from_fn(|j| f64::from(u8::from(i == j))))
}

fn multiply(a: &Rotation, b: &Rotation) -> Rotation {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

/// The matrix taking components in `from` to components in `to` at time `t`, coordinates
/// `q` and `rates`.
///
/// # Errors
/// When the problem's kinematics cannot be built (an invalid joint axis), in words.
pub fn rotation_between(
    problem: &Problem,
    (to, from): (BodyId, BodyId),
    t: f64,
    q: &[f64],
    rates: &[f64],
) -> Result<Rotation, String> {
    let model = Model::build(problem).map_err(|e| e.to_string())?;
    let values = model.values_at(t, q, rates);
    let n_to = orientation(&model.frames, to, &values);
    let n_from = orientation(&model.frames, from, &values);
    // to <- from = (N <- to)ᵀ (N <- from).
    Ok(std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..3).map(|k| n_to[k][i] * n_from[k][j]).sum())
    }))
}

/// Components `v` rewritten by `m`.
pub fn rotate(m: &Rotation, v: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| (0..3).map(|k| m[i][k] * v[k]).sum())
}

/// A site's reaction components (force and moment along x, y, z, any of them absent as
/// zero) rewritten by `m`, each in place.
pub fn rotate_columns(m: &Rotation, found: &mut [(ReactionColumn, f64)]) {
    for kind in [ComponentKind::Force, ComponentKind::Moment] {
        let mut v = [0.0; 3];
        for (column, x) in found.iter() {
            if let ReactionColumn::Component { kind: k, axis, .. } = column {
                if *k == kind && *axis < 3 {
                    v[*axis] = *x;
                }
            }
        }
        let turned = rotate(m, v);
        for (column, x) in found.iter_mut() {
            if let ReactionColumn::Component { kind: k, axis, .. } = column {
                if *k == kind && *axis < 3 {
                    *x = turned[*axis];
                }
            }
        }
    }
}
