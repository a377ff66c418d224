//! The starting speeds a problem names (`"rate": "v0"`): the configuration draws each as a
//! short arrow at the moving body's mass centre along its distance's line, the way the
//! speed points, labelled with its symbol (the bowling ball's v₀).

use super::numbers::{scale, Numbers};
use crate::problem::PointRef;
use crate::render::draw::{Gauge, Label, Shape};
use crate::symbolic::{latex, simplify};

/// One arrow for each distance coordinate whose starting rate is written as a symbol (or
/// minus one) and is not zero at the state drawn; `size` is the system's length.
pub fn velocities(n: &Numbers, size: f64) -> Vec<Shape> {
    let model = n.model;
    let problem = model.problem;
    let mut out = Vec::new();
    for gauge in super::gauges::gauges(n, size) {
        let Some(Gauge::Distance { along, .. }) = gauge.at else {
            continue;
        };
        let coordinate = &problem.coordinates[gauge.coordinate];
        let Some(rate) = &coordinate.rate_expr else {
            continue;
        };
        let Some(symbol) = [rate.clone(), simplify(&-rate.clone())]
            .into_iter()
            .find(|e| e.as_symbol().is_some())
        else {
            continue;
        };
        let value = n
            .values
            .get(&problem.coordinate_symbol(gauge.coordinate, 1));
        if value == 0.0 || !value.is_finite() {
            continue;
        }
        let child = problem.joints[coordinate.joint].child;
        out.push(Shape::Velocity {
            at: n.vector(&model.position(PointRef::MassCenter(child))),
            direction: scale(along, value.signum()),
            label: Label::from_tex(&latex(&symbol)),
        });
    }
    out
}
