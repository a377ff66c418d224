//! The model at one state, as numbers: positions, directions and rotations in `N`.

use crate::mechanics::{Components, Model, Vector};
use crate::problem::BodyId;
use crate::symbolic::{eval, Expr, Values};
use std::cell::RefCell;

// The vector arithmetic of the scenes, which the pictures' files take from here with
// `Numbers`.
pub(super) use crate::render::draw::numbers::{
    add, circle, cross, dot, norm, rotate, scale, sub, unit, P3,
};

/// Evaluates the model's vectors at one state.
pub struct Numbers<'m, 'p> {
    /// The model.
    pub model: &'m Model<'p>,
    /// Constants, coordinates, rates, time (and the q'' once known).
    pub values: Values,
    rotations: RefCell<Vec<Option<[[f64; 3]; 3]>>>,
}

impl<'m, 'p> Numbers<'m, 'p> {
    /// The model at time `t`, coordinates `q` and rates `rates`.
    pub fn new(model: &'m Model<'p>, t: f64, q: &[f64], rates: &[f64]) -> Self {
        Numbers {
            model,
            values: model.values_at(t, q, rates),
            rotations: RefCell::new(vec![None; model.frames.len()]),
        }
    }

    /// Sets the second derivatives of the coordinates.
    pub fn set_accelerations(&mut self, accelerations: &[f64]) {
        for (i, a) in accelerations.iter().enumerate() {
            let symbol = self.model.problem.coordinate_symbol(i, 2);
            self.values.set(symbol, *a);
        }
    }

    /// The value of a scalar.
    pub fn scalar(&self, e: &Expr) -> f64 {
        eval(e, &self.values)
    }

    /// The rotation taking a frame's components to `N`'s (columns: the frame's unit vectors).
    pub fn rotation(&self, frame: BodyId) -> [[f64; 3]; 3] {
        if let Some(r) = self.rotations.borrow()[frame.0] {
            return r;
        }
        let m = self.model.frames.dcm(BodyId::GROUND, frame);
        let r: [[f64; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| eval(&m[i][j], &self.values)));
        self.rotations.borrow_mut()[frame.0] = Some(r);
        r
    }

    /// Components in `frame` turned into `N`'s.
    pub fn in_ground(&self, frame: BodyId, local: &P3) -> P3 {
        let r = self.rotation(frame);
        std::array::from_fn(|i| (0..3).map(|j| r[i][j] * local[j]).sum())
    }

    /// Components as numbers, in their own frame.
    pub fn local(&self, c: &Components) -> P3 {
        std::array::from_fn(|i| self.scalar(&c[i]))
    }

    /// A vector in `N`'s unit vectors.
    pub fn vector(&self, v: &Vector) -> P3 {
        let mut out = [0.0; 3];
        for (frame, components) in v.parts() {
            let part = self.in_ground(*frame, &self.local(components));
            for i in 0..3 {
                out[i] += part[i];
            }
        }
        out
    }

    /// Where a point fixed on `body` at `offset` (body's unit vectors) is.
    pub fn point_on(&self, body: BodyId, offset: &P3) -> P3 {
        let origin = self.vector(&self.model.bodies[body.0].origin.position);
        add(origin, self.in_ground(body, offset))
    }
}
