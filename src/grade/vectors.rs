//! The kinematics items (positions, velocities and accelerations of points, angular
//! velocities and accelerations of bodies) and the partial velocities: vectors compared in
//! N whatever frame the student wrote them in, and diagnosed component by component in
//! the student's frame.

use super::equations::parse_message;
use super::names::Names;
use super::numbers::close;
use super::parts::values;
use super::reference::Reference;
use super::report::Item;
use super::scalars::differ;
use super::submission::Named;
use crate::mechanics::{Model, Vector};
use crate::problem::{BodyId, PointRef, Problem};
use crate::symbolic::{linear_split, Expr, Symbol};
use serde_json::Value;

/// What a kinematics entry names.
enum Target {
    Point(PointRef),
    Body(BodyId),
}

fn body(problem: &Problem, name: &str) -> Option<BodyId> {
    if name == "N" {
        return Some(BodyId::GROUND);
    }
    let i = problem.bodies.iter().position(|b| b.name == name)?;
    Some(BodyId(i + 1))
}

fn target(problem: &Problem, name: &str) -> Option<Target> {
    if let Some(b) = name.strip_suffix('*') {
        return body(problem, b).map(|b| Target::Point(PointRef::MassCenter(b)));
    }
    if let Some(b) = name.strip_suffix(".o") {
        return body(problem, b).map(|b| Target::Point(PointRef::Origin(b)));
    }
    if let Some(j) = problem.joints.iter().position(|j| j.name == name) {
        return Some(Target::Point(PointRef::Joint(j)));
    }
    if let Some(p) = problem.points.iter().position(|p| p.name == name) {
        return Some(Target::Point(PointRef::Named(p)));
    }
    body(problem, name).map(Target::Body)
}

/// The worked solution's vector `quantity` of `target`, or the quantities there are.
fn quantity(model: &Model, target: &Target, quantity: &str) -> Result<Vector, &'static str> {
    match target {
        Target::Point(p) => {
            let motion = model.point(*p);
            match quantity {
                "position" => Ok(motion.position),
                "velocity" => Ok(motion.velocity),
                "acceleration" => Ok(motion.acceleration),
                _ => Err("a point has a position, a velocity and an acceleration"),
            }
        }
        Target::Body(b) => {
            let state = &model.bodies[b.0];
            match quantity {
                "angular_velocity" => Ok(state.omega.clone()),
                "angular_acceleration" => Ok(state.alpha.clone()),
                _ => Err("a body has an angular_velocity and an angular_acceleration"),
            }
        }
    }
}

/// A student's vector: its parts by frame, in the order the frames are first used.
fn read_vector(reference: &Reference, value: &Value) -> Result<Vector, String> {
    let Value::String(text) = value else {
        return Err("expected a vector expression as a string, e.g. \"L/2*theta'*B.x\"".into());
    };
    let names = Names::new(reference.problem, &reference.reactions, true);
    let expr = names.parse(text).map_err(|e| parse_message(&e))?;
    let mut units: Vec<Symbol> = Vec::new();
    expr.for_each_symbol(&mut |s| {
        if matches!(s, Symbol::UnitVector(..)) && !units.contains(s) {
            units.push(s.clone());
        }
    });
    let (coefficients, rest) =
        linear_split(&expr, &units).map_err(|e| format!("not a vector: {e}"))?;
    if !rest.is_zero() {
        return Err(format!(
            "`{rest}` has no unit vector: write each term times a unit vector such as N.x"
        ));
    }
    let mut parts = Vec::new();
    for (unit, c) in units.iter().zip(coefficients) {
        let Symbol::UnitVector(frame, axis) = unit else {
            continue;
        };
        let id = body(reference.problem, frame).unwrap_or(BodyId::GROUND);
        let mut components: [Expr; 3] = std::array::from_fn(|_| Expr::zero());
        components[*axis as usize] = c;
        parts.push(Vector::new(id, components));
    }
    Ok(Vector::sum(parts))
}

/// What is wrong with `given` against `expected`, or `None` when they are equal.
fn compare(reference: &Reference, given: &Vector, expected: &Vector) -> Option<String> {
    let model = &reference.derivation.model;
    let samples = &reference.samples;
    let in_n = |v: &Vector| v.components_in(BodyId::GROUND, &model.frames);
    let (g, e) = (in_n(given), in_n(expected));
    let flat =
        |c: &[Expr; 3]| -> Vec<f64> { c.iter().flat_map(|x| values(x, samples, true)).collect() };
    if close(&flat(&g), &flat(&e), 0.0) {
        return None;
    }
    // Component by component in the frame the student wrote, or in N for several.
    let frame = match given.parts() {
        [(f, _)] => *f,
        _ => BodyId::GROUND,
    };
    let name = model.frames.name(frame);
    let (g, e) = (
        given.components_in(frame, &model.frames),
        expected.components_in(frame, &model.frames),
    );
    let texts: Vec<String> = (0..3)
        .filter_map(|a| {
            differ(reference, &g[a], &e[a], true)
                .map(|why| format!("along {name}.{}: {why}", ["x", "y", "z"][a]))
        })
        .collect();
    Some(texts.join("; "))
}

/// Grades `kinematics`: each point's or body's quantities given.
pub(super) fn kinematics(reference: &Reference, given: &Named<Named<Value>>) -> Vec<Item> {
    let model = &reference.derivation.model;
    let mut items = Vec::new();
    for (name, quantities) in given {
        let found = target(reference.problem, name);
        for (what, value) in quantities {
            let item = format!("kinematics.{name}.{what}");
            let Some(found) = &found else {
                items.push(Item::invalid(item, format!("`{name}` is not a point or a body: write B* for a mass centre, B.o for an origin, a joint's or a point's name, or a body's name")));
                continue;
            };
            let expected = match quantity(model, found, what) {
                Ok(v) => v,
                Err(why) => {
                    items.push(Item::invalid(item, format!("`{what}`: {why}")));
                    continue;
                }
            };
            items.push(match read_vector(reference, value) {
                Err(why) => Item::invalid(item, why),
                Ok(v) => match compare(reference, &v, &expected) {
                    None => Item::right(item, ""),
                    Some(why) => Item::wrong(item, why),
                },
            });
        }
    }
    items
}

/// The partial velocities of `target`: of a point's velocity, or of a body's angular
/// velocity, one per generalized speed.
fn partials(reference: &Reference, target: &Target) -> Option<Vec<Vector>> {
    let model = &reference.derivation.model;
    let v = match target {
        Target::Point(p) => model.point(*p).velocity,
        Target::Body(b) => model.bodies[b.0].omega.clone(),
    };
    let components = v.components_in(BodyId::GROUND, &model.frames);
    let speeds = reference.problem.speed_symbols(1);
    let split: Vec<Vec<Expr>> = components
        .iter()
        .map(|c| {
            linear_split(&super::reference::unfold(c), &speeds)
                .ok()
                .map(|(cs, _)| cs)
        })
        .collect::<Option<_>>()?;
    Some(
        (0..speeds.len())
            .map(|r| Vector::new(BodyId::GROUND, std::array::from_fn(|a| split[a][r].clone())))
            .collect(),
    )
}

/// Grades `partial_velocities`: each point's or body's list, one vector per speed.
pub(super) fn partial_velocities(reference: &Reference, given: &Named<Vec<Value>>) -> Vec<Item> {
    let mut items = Vec::new();
    for (name, list) in given {
        let Some(expected) = target(reference.problem, name).and_then(|t| partials(reference, &t))
        else {
            items.push(Item::invalid(
                format!("partial_velocities.{name}"),
                format!("`{name}` is not a point or a body of the problem"),
            ));
            continue;
        };
        for (r, e) in expected.iter().enumerate() {
            let item = format!("partial_velocities.{name}[{r}]");
            let Some(value) = list.get(r) else {
                items.push(Item::missing(
                    item,
                    format!("the partial velocity for speed {} is not given", r + 1),
                ));
                continue;
            };
            items.push(match read_vector(reference, value) {
                Err(why) => Item::invalid(item, why),
                Ok(v) => match compare(reference, &v, e) {
                    None => Item::right(item, ""),
                    Some(why) => Item::wrong(item, why),
                },
            });
        }
        for extra in expected.len()..list.len() {
            items.push(Item::wrong(
                format!("partial_velocities.{name}[{extra}]"),
                format!("the problem has {} generalized speeds", expected.len()),
            ));
        }
    }
    items
}
