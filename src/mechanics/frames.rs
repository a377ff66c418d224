//! Frames and their direction cosine matrices.
//!
//! Each body's frame is reached from its parent's by a list of elementary rotations
//! (about an axis by an angle). The matrix between any two frames is built from the
//! rotations along the tree path between them, and rotations about the same axis are
//! merged first, so that a planar chain gives `cos(q2 + q3)` instead of a product.

use super::components::{cross3, dot3, Components};
use crate::problem::BodyId;
use crate::symbolic::{add, cos, latex_name, sin, Expr};
use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

/// Chains of more rotations than this, after merging, are composed from named matrices
/// (see [`Frames::composed`]); shorter ones are multiplied out and simplified.
const MAX_DIRECT_ROTATIONS: usize = 3;

const AXES: [&str; 3] = ["x", "y", "z"];

/// A 3x3 matrix of expressions, row-major.
pub type Matrix = [[Expr; 3]; 3];

/// A rotation by `angle` about `axis`, a unit vector with constant components that are the
/// same before and after the rotation.
#[derive(Clone, Debug, PartialEq)]
pub struct Rotation {
    /// The axis components in the frame being rotated (unit length).
    pub axis: Components,
    /// The angle, positive by the right-hand rule.
    pub angle: Expr,
}

impl Rotation {
    /// The matrix taking components in the rotated frame to components in the frame before
    /// (its columns are the new unit vectors written in the old ones): Rodrigues' formula.
    pub fn matrix(&self) -> Matrix {
        let (c, s) = (cos(self.angle.clone()), sin(self.angle.clone()));
        let a = &self.axis;
        let one_minus_c = Expr::one() - c.clone();
        let skew = [
            [Expr::zero(), -a[2].clone(), a[1].clone()],
            [a[2].clone(), Expr::zero(), -a[0].clone()],
            [-a[1].clone(), a[0].clone(), Expr::zero()],
        ];
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let identity = if i == j { c.clone() } else { Expr::zero() };
                add([identity, &s * &skew[i][j], &one_minus_c * &(&a[i] * &a[j])])
            })
        })
    }
}

/// The frame of one body: its parent and the rotations from the parent's frame to it.
#[derive(Clone, Debug)]
pub struct FrameInfo {
    /// The parent frame; `None` only for `N`.
    pub parent: Option<BodyId>,
    /// Body-fixed rotations, applied in order, from the parent's frame to this one.
    pub rotations: Vec<Rotation>,
}

/// All frames of a system, indexed by body id (`N` first).
#[derive(Debug)]
pub struct Frames {
    frames: Vec<FrameInfo>,
    names: Vec<String>,
    cache: RefCell<HashMap<(BodyId, BodyId), Rc<Matrix>>>,
}

/// Matrix product.
pub fn matmul(a: &Matrix, b: &Matrix) -> Matrix {
    std::array::from_fn(|i| std::array::from_fn(|j| add((0..3).map(|k| &a[i][k] * &b[k][j]))))
}

/// Matrix times components.
pub fn apply(m: &Matrix, v: &Components) -> Components {
    std::array::from_fn(|i| dot3(&m[i], v))
}

/// The transpose.
pub fn transpose(m: &Matrix) -> Matrix {
    std::array::from_fn(|i| std::array::from_fn(|j| m[j][i].clone()))
}

/// The identity matrix.
pub fn identity() -> Matrix {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| if i == j { Expr::one() } else { Expr::zero() })
    })
}

impl Frames {
    /// Frames from their descriptions, `frames[0]` being `N`; `names` for display.
    pub fn new(frames: Vec<FrameInfo>, names: Vec<String>) -> Frames {
        Frames {
            frames,
            names,
            cache: RefCell::new(HashMap::new()),
        }
    }

    /// Adds a frame that is no body's (a frame that does not spin, `mechanics/resal.rs`) and
    /// returns its id.
    pub fn push(&mut self, info: FrameInfo, name: String) -> BodyId {
        self.frames.push(info);
        self.names.push(name);
        BodyId(self.frames.len() - 1)
    }

    /// The number of frames, `N` included.
    pub fn len(&self) -> usize {
        self.frames.len()
    }

    /// Whether there are no frames (never: `N` is always there).
    pub fn is_empty(&self) -> bool {
        self.frames.is_empty()
    }

    /// The description of a frame.
    pub fn info(&self, frame: BodyId) -> &FrameInfo {
        &self.frames[frame.0]
    }

    /// The frame's name.
    pub fn name(&self, frame: BodyId) -> &str {
        &self.names[frame.0]
    }

    /// The frames from `N` down to `frame`, both included.
    pub fn path_from_ground(&self, frame: BodyId) -> Vec<BodyId> {
        let mut path = vec![frame];
        let mut current = frame;
        while let Some(parent) = self.frames[current.0].parent {
            path.push(parent);
            current = parent;
        }
        path.reverse();
        path
    }

    /// The rotations that take frame `from` to frame `to` (so that the matrix
    /// `to <- from` is their product), merged where consecutive axes agree.
    pub fn rotations_between(&self, to: BodyId, from: BodyId) -> Vec<Rotation> {
        let to_path = self.path_from_ground(to);
        let from_path = self.path_from_ground(from);
        let common = to_path
            .iter()
            .zip(&from_path)
            .take_while(|(a, b)| a == b)
            .count();
        let mut chain: Vec<Rotation> = Vec::new();
        // Up from `to` to the common ancestor: each rotation reversed, in reverse order.
        for frame in to_path[common..].iter().rev() {
            for r in self.frames[frame.0].rotations.iter().rev() {
                chain.push(Rotation {
                    axis: r.axis.clone(),
                    angle: -r.angle.clone(),
                });
            }
        }
        // Down from the common ancestor to `from`.
        for frame in &from_path[common..] {
            chain.extend(self.frames[frame.0].rotations.iter().cloned());
        }
        let mut merged: Vec<Rotation> = Vec::with_capacity(chain.len());
        for r in chain {
            match merged.last_mut() {
                Some(last) if last.axis == r.axis => last.angle = &last.angle + &r.angle,
                _ => merged.push(r),
            }
            if merged.last().is_some_and(|last| last.angle.is_zero()) {
                merged.pop();
            }
        }
        merged
    }

    /// The direction cosine matrix taking components in `from` to components in `to`.
    pub fn dcm(&self, to: BodyId, from: BodyId) -> Rc<Matrix> {
        // A frame that does not turn against its parent (a slider's) is the parent's
        // orientation: one matrix and one set of names, ᴬC^E, not ᴮC^E as well.
        let (to, from) = (self.oriented_as(to), self.oriented_as(from));
        if let Some(m) = self.cache.borrow().get(&(to, from)) {
            return m.clone();
        }
        let rotations = self.rotations_between(to, from);
        if rotations.len() > MAX_DIRECT_ROTATIONS {
            let matrix = Rc::new(self.composed(to, from));
            self.cache.borrow_mut().insert((to, from), matrix.clone());
            return matrix;
        }
        let matrix = rotations
            .iter()
            .fold(identity(), |acc, r| matmul(&acc, &r.matrix()));
        // Products of rotations about different axes leave sums of trig products that the
        // angle-sum identities shorten; everything built on the matrix is then smaller.
        let matrix: Matrix = if rotations.len() > 1 {
            std::array::from_fn(|i| {
                std::array::from_fn(|j| crate::symbolic::simplify(&matrix[i][j]))
            })
        } else {
            matrix
        };
        let matrix = Rc::new(matrix);
        self.cache.borrow_mut().insert((to, from), matrix.clone());
        matrix
    }

    /// The nearest of `frame` and its ancestors that turns against its own parent (or `N`):
    /// the frames between have the same orientation.
    fn oriented_as(&self, frame: BodyId) -> BodyId {
        let mut frame = frame;
        while let (true, Some(parent)) = (
            self.frames[frame.0].rotations.is_empty(),
            self.frames[frame.0].parent,
        ) {
            frame = parent;
        }
        frame
    }

    /// The matrix `to <- from` of a long chain of rotations, as the product of the matrices
    /// of a shorter chain and of one joint, each entry named (`ᴺC^{B3}_{12}`). Multiplied
    /// out, a chain of k spherical joints has entries of 3^k-fold trig products, and every
    /// product of vectors across the chain would multiply them out again.
    fn composed(&self, to: BodyId, from: BodyId) -> Matrix {
        if self.path_from_ground(to).contains(&from) {
            // `from` is an ancestor of `to`: the transpose of the named matrix the other way.
            return transpose(&self.dcm(from, to));
        }
        let Some(parent) = self.frames[from.0].parent else {
            return transpose(&self.dcm(from, to));
        };
        // ᴺC^E = ᴺC^D ᴰC^E with both factors by name, as a textbook composes rotations:
        // each entry is then three products of names, not the factors multiplied out.
        let product = matmul(
            &self.named(self.dcm(to, parent).as_ref(), to, parent),
            &self.named(self.dcm(parent, from).as_ref(), parent, from),
        );
        self.named(&product, to, from)
    }

    /// The matrix `to <- from` with every entry of more than one term a named direction
    /// cosine, `ᴺC^{B3}_{12}` (entries already names stay as they are).
    fn named(&self, matrix: &Matrix, to: BodyId, from: BodyId) -> Matrix {
        let (to_name, from_name) = (self.display_name(to), self.display_name(from));
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                let value = &matrix[i][j];
                if value.terms().len() < 2 {
                    return value.clone();
                }
                Expr::named(
                    &format!("C.{to_name}.{from_name}.{}{}", i + 1, j + 1),
                    &format!(
                        "{{}}^{{{}}}C^{{{}}}_{{{}{}}}",
                        latex_name(&to_name),
                        latex_name(&from_name),
                        i + 1,
                        j + 1
                    ),
                    &format!(
                        "the direction cosine {}.{} · {}.{}",
                        to_name, AXES[i], from_name, AXES[j]
                    ),
                    value.clone(),
                )
            })
        })
    }

    fn display_name(&self, frame: BodyId) -> String {
        self.names
            .get(frame.0)
            .cloned()
            .unwrap_or_else(|| format!("F{}", frame.0))
    }

    /// Components given in `from` rewritten in `to`.
    pub fn express(&self, v: &Components, from: BodyId, to: BodyId) -> Components {
        if from == to {
            return v.clone();
        }
        apply(&self.dcm(to, from), v)
    }

    /// The relative angular velocity of a frame in its parent, in its own components:
    /// each rotation's axis times its angle's rate, carried through the later rotations.
    ///
    /// # Errors
    /// When an angle cannot be differentiated.
    pub fn relative_angular_velocity(
        &self,
        frame: BodyId,
    ) -> Result<Components, crate::symbolic::DiffError> {
        let rotations = &self.frames[frame.0].rotations;
        let mut omega: Components = std::array::from_fn(|_| Expr::zero());
        // Walk backwards: the last rotation's axis is already in this frame's components.
        let mut carry = identity();
        for r in rotations.iter().rev() {
            let rate = crate::symbolic::time_derivative(&r.angle)?;
            let axis_here = apply(&carry, &r.axis);
            omega = std::array::from_fn(|i| &omega[i] + &(&rate * &axis_here[i]));
            carry = matmul(&carry, &transpose(&r.matrix()));
        }
        Ok(omega)
    }

    /// The rotation axes of a frame's rotations, each in the frame's own components
    /// (the partial angular velocities of the angles).
    pub fn rotation_axes_in_frame(&self, frame: BodyId) -> Vec<Components> {
        let rotations = &self.frames[frame.0].rotations;
        let mut axes = Vec::with_capacity(rotations.len());
        let mut carry = identity();
        for r in rotations.iter().rev() {
            axes.push(apply(&carry, &r.axis));
            carry = matmul(&carry, &transpose(&r.matrix()));
        }
        axes.reverse();
        axes
    }
}

/// The dual basis of three vectors: `b_i · a_j = δ_ij`. Used to turn a generalized force on
/// one angle of a rotation sequence into the couple that does work on that angle alone.
pub fn dual_basis(a: &[Components; 3]) -> [Components; 3] {
    let volume = dot3(&a[0], &cross3(&a[1], &a[2]));
    let inverse = crate::symbolic::pow(volume, Expr::int(-1));
    std::array::from_fn(|i| {
        let c = cross3(&a[(i + 1) % 3], &a[(i + 2) % 3]);
        std::array::from_fn(|k| &c[k] * &inverse)
    })
}
