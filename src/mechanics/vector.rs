//! Vectors as sums over the unit vectors of any frames, with dot and cross products
//! across frames and re-expression in a frame.

use super::frames::Frames;
use crate::problem::BodyId;
use crate::symbolic::{add, Expr};

/// Three components in one frame's unit vectors.
pub type Components = [Expr; 3];

/// The zero triple.
pub fn zero3() -> Components {
    [Expr::zero(), Expr::zero(), Expr::zero()]
}

/// `a × b` of two triples in the same frame.
pub fn cross3(a: &Components, b: &Components) -> Components {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

/// `a · b` of two triples in the same frame.
pub fn dot3(a: &Components, b: &Components) -> Expr {
    add([&a[0] * &b[0], &a[1] * &b[1], &a[2] * &b[2]])
}

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
        for (frame, c) in self.parts {
            match merged.last_mut() {
                Some((last, acc)) if *last == frame => {
                    *acc = [&acc[0] + &c[0], &acc[1] + &c[1], &acc[2] + &c[2]];
                }
                _ => merged.push((frame, c)),
            }
        }
        merged.retain(|(_, c)| c.iter().any(|e| !e.is_zero()));
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
        let mut total = zero3();
        for (from, c) in &self.parts {
            let expressed = frames.express(c, *from, frame);
            total = [
                &total[0] + &expressed[0],
                &total[1] + &expressed[1],
                &total[2] + &expressed[2],
            ];
        }
        total
    }

    /// The same vector written in `frame`'s unit vectors only.
    pub fn expressed_in(&self, frame: BodyId, frames: &Frames) -> Vector {
        Vector::new(frame, self.components_in(frame, frames))
    }

    /// `self · other`, each part of `other` expressed in the frame of each part of `self`.
    pub fn dot(&self, other: &Vector, frames: &Frames) -> Expr {
        let mut terms = Vec::new();
        for (frame, a) in &self.parts {
            for (other_frame, b) in &other.parts {
                terms.push(dot3(a, &frames.express(b, *other_frame, *frame)));
            }
        }
        add(terms)
    }

    /// `self × other`, each part of `other` expressed in the frame of each part of `self`.
    pub fn cross(&self, other: &Vector, frames: &Frames) -> Vector {
        let mut parts = Vec::new();
        for (frame, a) in &self.parts {
            for (other_frame, b) in &other.parts {
                parts.push((*frame, cross3(a, &frames.express(b, *other_frame, *frame))));
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
