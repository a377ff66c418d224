//! The bundled problems' answers, each against a reference written here: a closed form, a
//! hand derivation (Lagrange's equations or Newton–Euler, worked in the comments), or
//! conservation of energy or momentum. None is a number copied from the program.

use super::{bundled_answers, close};
use mbd_tutor::numeric::Answer;
use nalgebra::{Matrix2, Matrix3, Rotation3, Vector2, Vector3};
use std::f64::consts::PI;

/// The first value of answer `i`.
fn v(a: &[Answer], i: usize) -> f64 {
    a[i].values[0].1
}

/// The component `name` (`O.force.x`) of a reaction answer.
fn part(a: &Answer, name: &str) -> f64 {
    a.values
        .iter()
        .find(|(n, _)| n.to_string() == name)
        .map(|(_, x)| *x)
        .unwrap_or_else(|| panic!("no {name} in {:?}", a.values))
}

/// z of the planar cross product.
fn cross2(a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    a.x * b.y - a.y * b.x
}

fn perp(angle: f64) -> Vector2<f64> {
    Vector2::new(-angle.sin(), angle.cos())
}

fn along(angle: f64) -> Vector2<f64> {
    Vector2::new(angle.cos(), angle.sin())
}

/// Simulated answers: the problems integrate with a tolerance of 1e-10 per step, so over a
/// few seconds the state and the conserved quantities drift by far less than this.
const SIMULATED: f64 = 1e-7;

mod planar;
mod spatial;
