//! Vectors as sums over the unit vectors of any frames, with dot and cross products
//! across frames and re-expression in a frame.

pub use super::components::{cross3, dot3, size, zero3, Components};
use super::frames::Frames;
use crate::problem::{BodyId, VectorExpr};
use crate::symbolic::{add, Expr};

/// A vector: a sum of parts, each a triple of components in one frame's unit vectors.
///
/// Parts are kept sorted by frame and never all zero, so equal sums compare equal.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Vector {
    parts: Vec<(BodyId, Components)>,
}

impl Vector {
    /// The zero vector.
    pub fn zero() -> Vector {
        Vector::default()
    }

    /// A vector given by its components in `frame`.
    pub fn new(frame: BodyId, components: Components) -> Vector {
        Vector {
            parts: vec![(frame, components)],
        }
        .normalized()
    }

    /// The unit vector `frame.axis` (axis 0, 1, 2 for x, y, z).
    pub fn unit(frame: BodyId, axis: usize) -> Vector {
        let mut c = zero3();
        c[axis] = Expr::one();
        Vector::new(frame, c)
    }

    /// The parts: frame and components.
    pub fn parts(&self) -> &[(BodyId, Components)] {
        &self.parts
    }

    /// Whether every component is exactly zero.
    pub fn is_zero(&self) -> bool {
        self.parts.is_empty()
    }

    fn normalized(mut self) -> Vector {
        self.parts.sort_by_key(|(f, _)| *f);
        let mut merged: Vec<(BodyId, Components)> = Vec::with_capacity(self.parts.len());
        let mut rest = self.parts.as_slice();
        while let Some((frame, _)) = rest.first() {
            let same = rest.iter().take_while(|(f, _)| f == frame).count();
            let (group, tail) = rest.split_at(same);
            rest = tail;
            // One sum per axis over the whole group: adding the parts one at a time would
            // re-sort a growing sum for every part.
            let components = if group.len() == 1 {
                group[0].1.clone()
            } else {
                std::array::from_fn(|axis| add(group.iter().map(|(_, c)| c[axis].clone())))
            };
            if components.iter().any(|e| !e.is_zero()) {
                merged.push((*frame, components));
            }
        }
        Vector { parts: merged }
    }

    /// The sum.
    pub fn plus(&self, other: &Vector) -> Vector {
        let mut parts = self.parts.clone();
        parts.extend(other.parts.iter().cloned());
        Vector { parts }.normalized()
    }

    /// The difference.
    pub fn minus(&self, other: &Vector) -> Vector {
        self.plus(&other.scaled(&Expr::int(-1)))
    }

    /// The sum of many vectors.
    pub fn sum(vectors: impl IntoIterator<Item = Vector>) -> Vector {
        let parts = vectors.into_iter().flat_map(|v| v.parts).collect();
        Vector { parts }.normalized()
    }

    /// `factor` times the vector.
    pub fn scaled(&self, factor: &Expr) -> Vector {
        self.map(|e| e * factor)
    }

    /// The vector with `f` applied to every component.
    pub fn map(&self, f: impl Fn(&Expr) -> Expr) -> Vector {
        let parts = self
            .parts
            .iter()
            .map(|(frame, c)| (*frame, [f(&c[0]), f(&c[1]), f(&c[2])]))
            .collect();
        Vector { parts }.normalized()
    }

    /// The vector with a fallible `f` applied to every component.
    ///
    /// # Errors
    /// The first error of `f`.
    pub fn try_map<E>(&self, f: impl Fn(&Expr) -> Result<Expr, E>) -> Result<Vector, E> {
        let mut parts = Vec::with_capacity(self.parts.len());
        for (frame, c) in &self.parts {
            parts.push((*frame, [f(&c[0])?, f(&c[1])?, f(&c[2])?]));
        }
        Ok(Vector { parts }.normalized())
    }

    /// The components in `frame`'s unit vectors.
    pub fn components_in(&self, frame: BodyId, frames: &Frames) -> Components {
        let expressed: Vec<Components> = self
            .parts
            .iter()
            .map(|(from, c)| frames.express(c, *from, frame))
            .collect();
        std::array::from_fn(|axis| add(expressed.iter().map(|c| c[axis].clone())))
    }

    /// The same vector written in `frame`'s unit vectors only.
    pub fn expressed_in(&self, frame: BodyId, frames: &Frames) -> Vector {
        Vector::new(frame, self.components_in(frame, frames))
    }

    /// `self · other`, part by part, the shorter part of each pair expressed in the frame
    /// of the longer.
    pub fn dot(&self, other: &Vector, frames: &Frames) -> Expr {
        let mut terms = Vec::new();
        for (frame, a) in &self.parts {
            for (other_frame, b) in &other.parts {
                terms.push(if size(a) >= size(b) {
                    dot3(a, &frames.express(b, *other_frame, *frame))
                } else {
                    dot3(&frames.express(a, *frame, *other_frame), b)
                });
            }
        }
        add(terms)
    }

    /// `self × other`, part by part, the shorter part of each pair expressed in the frame
    /// of the longer (which is cheaper: the long one is multiplied out once, in the cross
    /// product, instead of twice).
    pub fn cross(&self, other: &Vector, frames: &Frames) -> Vector {
        let mut parts = Vec::new();
        for (frame, a) in &self.parts {
            for (other_frame, b) in &other.parts {
                parts.push(if size(a) >= size(b) {
                    (*frame, cross3(a, &frames.express(b, *other_frame, *frame)))
                } else {
                    (
                        *other_frame,
                        cross3(&frames.express(a, *frame, *other_frame), b),
                    )
                });
            }
        }
        Vector { parts }.normalized()
    }

    /// The number of operations to evaluate every component: a measure of length.
    pub fn operation_count(&self) -> usize {
        self.parts
            .iter()
            .flat_map(|(_, c)| c.iter())
            .map(|e| e.operation_count() + 1)
            .sum()
    }
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
