//! The numbers of a vector `value` question (`v(P)`, `a(B*)`, `w(B)`, `alpha(B)`, `r(P)`):
//! the vector's components along `N`'s unit vectors, found by differentiating, with respect
//! to time, the position of the point (and, for a body's rotation, the matrix of its unit
//! vectors written in `N`'s) as the kinematics of the problem write them, then evaluating at
//! the question's state with the accelerations the equations of motion give there. The
//! components are then rotated into the frame the question asks for.
//!
//! A body's angular velocity is the vector of the skew matrix Ṙ Rᵀ, R the matrix whose
//! columns are the body's unit vectors in `N`'s; its angular acceleration that of the skew
//! part of R̈ Rᵀ (the derivative of Ṙ Rᵀ is R̈ Rᵀ + Ṙ Ṙᵀ, and Ṙ Ṙᵀ is symmetric).

use super::answer_frame::{rotate, rotation_between};
use crate::mechanics::{Matrix, Model};
use crate::problem::{BodyId, Problem, VectorQuantity};
use crate::symbolic::{eval, time_derivative, Expr, Values};

/// The state a vector value is found at: the time, the coordinates, their rates and the
/// second rates the equations of motion give there.
#[derive(Clone, Copy, Debug)]
pub struct At<'a> {
    /// Seconds.
    pub t: f64,
    /// The coordinates.
    pub q: &'a [f64],
    /// Their rates.
    pub rates: &'a [f64],
    /// Their second rates.
    pub accelerations: &'a [f64],
}

/// The components of `quantity` along the unit vectors of `frame`, at `at`.
///
/// # Errors
/// When the kinematics cannot be built or differentiated, in words.
pub fn components(
    problem: &Problem,
    quantity: VectorQuantity,
    frame: BodyId,
    at: At,
) -> Result<[f64; 3], String> {
    let model = Model::build(problem).map_err(|e| e.to_string())?;
    let mut values = model.values_at(at.t, at.q, at.rates);
    for (i, a) in at.accelerations.iter().enumerate() {
        values.set(problem.coordinate_symbol(i, 2), *a);
    }
    let in_n = in_ground(&model, quantity, &values)?;
    if frame == BodyId::GROUND {
        return Ok(in_n);
    }
    let m = rotation_between(problem, (frame, BodyId::GROUND), at.t, at.q, at.rates)?;
    Ok(rotate(&m, in_n))
}

/// The components along `N`'s unit vectors.
fn in_ground(model: &Model, quantity: VectorQuantity, values: &Values) -> Result<[f64; 3], String> {
    let d = |e: &Expr| time_derivative(e).map_err(|e| e.to_string());
    let point = |p| {
        model
            .position(p)
            .components_in(BodyId::GROUND, &model.frames)
    };
    let numbers = |c: &[Expr; 3]| -> [f64; 3] { std::array::from_fn(|i| eval(&c[i], values)) };
    match quantity {
        VectorQuantity::Position(p) => Ok(numbers(&point(p))),
        VectorQuantity::Velocity(p) => {
            let [x, y, z] = point(p);
            Ok(numbers(&[d(&x)?, d(&y)?, d(&z)?]))
        }
        VectorQuantity::Acceleration(p) => {
            let [x, y, z] = point(p);
            Ok(numbers(&[d(&d(&x)?)?, d(&d(&y)?)?, d(&d(&z)?)?]))
        }
        VectorQuantity::AngularVelocity(b) | VectorQuantity::AngularAcceleration(b) => {
            if b == BodyId::GROUND {
                return Ok([0.0; 3]);
            }
            let r = model.frames.dcm(BodyId::GROUND, b);
            let r_dot = derivative(&r, &d)?;
            let second = matches!(quantity, VectorQuantity::AngularAcceleration(_));
            let left = if second {
                derivative(&r_dot, &d)?
            } else {
                r_dot
            };
            Ok(skew_vector(
                &number_matrix(&left, values),
                &number_matrix(&r, values),
            ))
        }
    }
}

/// Every entry of `m` differentiated by `d`.
fn derivative(m: &Matrix, d: &impl Fn(&Expr) -> Result<Expr, String>) -> Result<Matrix, String> {
    let mut out: Matrix = std::array::from_fn(|_| std::array::from_fn(|_| Expr::zero()));
    for (row, entries) in out.iter_mut().zip(m) {
        for (cell, e) in row.iter_mut().zip(entries) {
            *cell = d(e)?;
        }
    }
    Ok(out)
}

fn number_matrix(m: &Matrix, values: &Values) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| eval(&m[i][j], values)))
}

/// The vector of the skew part of `a bᵀ`: (w_x, w_y, w_z) where the skew part is
/// [[0, −w_z, w_y], [w_z, 0, −w_x], [−w_y, w_x, 0]].
fn skew_vector(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [f64; 3] {
    let m = |i: usize, j: usize| (0..3).map(|k| a[i][k] * b[j][k]).sum::<f64>();
    [
        (m(2, 1) - m(1, 2)) / 2.0,
        (m(0, 2) - m(2, 0)) / 2.0,
        (m(1, 0) - m(0, 1)) / 2.0,
    ]
}
