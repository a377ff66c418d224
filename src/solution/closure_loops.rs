//! A closure's vector loop as a textbook writes it before its scalar constraints: from the
//! first joint of one chain of bodies to the point where the loop closes, back down the
//! other chain and home along the ground, `r^{OP} + r^{PR} − r^{QR} − r^{OQ} = 0`, each
//! segment in the unit vectors of the body it lies in; then the same loop differentiated,
//! the velocity constraints, and how the dependent rates follow from them.

use super::tex::vector_tex;
use crate::equations::partials;
use crate::equations::Derivation;
use crate::mechanics::RowOrigin;
use crate::mechanics::SiteKind;
use crate::mechanics::{Model, PointMotion, Vector};
use crate::problem::BodyId;
use crate::symbolic::latex_collected;
use crate::symbolic::linear_split;
use crate::symbolic::simplify;
use crate::symbolic::{latex, latex_name};
use crate::symbolic::{Expr, Symbol};

/// The most characters of LaTeX one side of the loop may take, broken over lines.
const LONGEST: usize = 700;

/// One segment of a loop: from one named point to the next, fixed in one body.
struct Segment {
    from: String,
    to: String,
    body: BodyId,
    position: Vector,
    velocity: Vector,
}

/// The joints from the ground to `body`, ground first: (joint index, its parent).
fn chain(model: &Model, body: BodyId) -> Vec<usize> {
    let joints = &model.problem.joints;
    let mut out = Vec::new();
    let mut at = body;
    while at != BodyId::GROUND {
        let Some(j) = joints.iter().position(|j| j.child == at) else {
            break;
        };
        out.push(j);
        at = joints[j].parent;
        if out.len() > joints.len() {
            break;
        }
    }
    out.reverse();
    out
}

/// The joint's point, on the body it carries: where it is and how it moves (a slider's
/// moves along its track).
fn joint_point(model: &Model, joint: usize) -> Option<PointMotion> {
    let site = model
        .sites
        .iter()
        .find(|s| matches!(s.kind, SiteKind::Joint(j) if j == joint))?;
    Some(model.point_on(site.child, &site.child_offset))
}

/// The segments from the first joint of `body`'s chain to the closing point `end`.
fn segments(model: &Model, body: BodyId, end: (&str, &PointMotion)) -> Option<Vec<Segment>> {
    let joints = chain(model, body);
    let mut out = Vec::new();
    for (k, &j) in joints.iter().enumerate() {
        let joint = &model.problem.joints[j];
        let here = joint_point(model, j)?;
        let (to, there) = match joints.get(k + 1) {
            Some(&next) => (
                model.problem.joints[next].name.clone(),
                joint_point(model, next)?,
            ),
            None => (end.0.to_string(), end.1.clone()),
        };
        out.push(Segment {
            from: joint.name.clone(),
            to,
            body: joint.child,
            position: there.position.minus(&here.position),
            velocity: there.velocity.minus(&here.velocity),
        });
    }
    Some(out)
}

/// `\mathbf{r}^{OP}`.
fn name(segment: &Segment, letter: &str) -> String {
    format!(
        "\\mathbf{{{letter}}}^{{{} {}}}",
        latex_name(&segment.from),
        latex_name(&segment.to)
    )
}

/// A vector in one body's unit vectors, simplified.
fn in_body(model: &Model, v: &Vector, body: BodyId) -> Vector {
    let frame = model.bodies[body.0].frame;
    v.expressed_in(frame, &model.frames).map(simplify)
}

/// Whether a term is a sum at its top level (outside every bracket and brace).
fn is_sum(t: &str) -> bool {
    let mut depth = 0i32;
    let bytes = t.as_bytes();
    for (i, &c) in bytes.iter().enumerate() {
        match c {
            b'(' | b'{' | b'[' => depth += 1,
            b')' | b'}' | b']' => depth -= 1,
            b'+' | b'-' if depth == 0 && i > 0 && bytes[i - 1] == b' ' => return true,
            _ => {}
        }
    }
    false
}

/// Signed terms `± written` joined into a sum.
fn signed_sum(terms: &[(bool, String)]) -> String {
    let mut out = String::new();
    for (plus, t) in terms {
        let wrapped = if is_sum(t) || t.starts_with('-') {
            format!("\\left( {t} \\right)")
        } else {
            t.clone()
        };
        match (out.is_empty(), plus) {
            (true, true) => out.push_str(&wrapped),
            (true, false) => out.push_str(&format!("-{wrapped}")),
            (false, true) => out.push_str(&format!(" + {wrapped}")),
            (false, false) => out.push_str(&format!(" - {wrapped}")),
        }
    }
    out
}

/// One display per closure: the loop by its segments' names, the loop in unit vectors,
/// and its derivative, the velocity constraints. Empty where the loop is too long.
pub fn loops(derivation: &Derivation) -> Vec<String> {
    let model = &derivation.model;
    let mut sites: Vec<usize> = Vec::new();
    for row in &model.constraints.rows {
        if let RowOrigin::Site { site, .. } = &row.origin {
            if matches!(model.sites[*site].kind, SiteKind::Closure(_)) && !sites.contains(site) {
                sites.push(*site);
            }
        }
    }
    sites
        .into_iter()
        .filter_map(|index| loop_display(model, index))
        .collect()
}

/// The loop of closure site `index`, as an aligned display.
fn loop_display(model: &Model, index: usize) -> Option<String> {
    let site = &model.sites[index];
    let on_parent = model.point_on(site.parent, &site.parent_offset);
    let point = site.name.as_str();
    let out = segments(model, site.parent, (point, &on_parent))?;
    let back = segments(model, site.child, (point, &site.point))?;
    let (first_out, first_back) = (out.first()?, back.first()?);
    // Home along the ground: from the first joint of the one chain to the other's.
    let start_out = joint_point(
        model,
        model
            .problem
            .joints
            .iter()
            .position(|j| j.name == first_out.from)?,
    )?;
    let start_back = joint_point(
        model,
        model
            .problem
            .joints
            .iter()
            .position(|j| j.name == first_back.from)?,
    )?;
    let ground = Segment {
        from: first_out.from.clone(),
        to: first_back.from.clone(),
        body: BodyId::GROUND,
        position: start_back.position.minus(&start_out.position),
        velocity: start_back.velocity.minus(&start_out.velocity),
    };
    let mut signed: Vec<(bool, &Segment)> = out.iter().map(|s| (true, s)).collect();
    signed.extend(back.iter().rev().map(|s| (false, s)));
    signed.push((false, &ground));
    // A segment of no length (a slider's pin on its block) is left out.
    let zero = |v: &Vector| {
        v.expressed_in(BodyId::GROUND, &model.frames)
            .map(simplify)
            .is_zero()
    };
    signed.retain(|(_, s)| !zero(&s.position));
    let names: Vec<(bool, String)> = signed.iter().map(|(p, s)| (*p, name(s, "r"))).collect();
    let positions: Vec<(bool, String)> = signed
        .iter()
        .map(|(p, s)| (*p, vector_tex(model, &in_body(model, &s.position, s.body))))
        .collect();
    let moving: Vec<&(bool, &Segment)> =
        signed.iter().filter(|(_, s)| !zero(&s.velocity)).collect();
    let velocity_names: Vec<(bool, String)> = moving
        .iter()
        .map(|(p, s)| (*p, format!("{{}}^{{N}}\\tfrac{{d}}{{dt}} {}", name(s, "r"))))
        .collect();
    let velocities: Vec<(bool, String)> = moving
        .iter()
        .map(|(p, s)| (*p, vector_tex(model, &in_body(model, &s.velocity, s.body))))
        .collect();
    let loop_tex = signed_sum(&positions);
    let velocity_tex = signed_sum(&velocities);
    if loop_tex.len() > LONGEST || velocity_tex.len() > LONGEST {
        return None;
    }
    let mut lines = vec![
        super::aligned::line(
            &signed_sum(&names),
            "=",
            &format!("{loop_tex} = \\mathbf{{0}}"),
        ),
        super::aligned::line(
            &signed_sum(&velocity_names),
            "=",
            &format!("{velocity_tex} = \\mathbf{{0}}"),
        ),
    ];
    let derivative = Vector::sum(moving.iter().map(|(p, s)| {
        if *p {
            s.velocity.clone()
        } else {
            s.velocity.scaled(&Expr::int(-1))
        }
    }));
    lines.extend(dependent_rates(model, &derivative));
    Some(super::aligned::display(&lines))
}

/// In a plane, two dependent rates from the loop's derivative `v`, each as a textbook
/// finds it: dotted with the unit vector perpendicular to the one the other rate
/// multiplies, the derivative loses that rate and gives this one,
/// `q̇₂ = … \quad (\cdot\, ĉ_x)`. Empty in space, for other counts, or where a rate does
/// not multiply one unit vector.
fn dependent_rates(model: &Model, v: &Vector) -> Vec<String> {
    let problem = model.problem;
    let Some(found) = rates_from(model, v) else {
        return Vec::new();
    };
    (found.into_iter())
        .map(|(i, value, normal)| {
            format!(
                "{} &= {} \\quad \\text{{(the derivative dotted with }} {}\\text{{)}}",
                latex(&problem.coordinate_expr(i, 1)),
                latex_collected(&value),
                vector_tex(model, &normal)
            )
        })
        .collect()
}

/// Each dependent rate of a plane's one loop, as [`dependent_rates`] finds it from the
/// closure's relative velocity: `(coordinate, value, unit vector dotted with)`; `None`
/// where the loop has no such form (see there) or there is not exactly one closure.
pub(super) fn loop_rates(model: &Model) -> Option<Vec<(usize, Expr)>> {
    let mut closures = (model.sites.iter()).filter(|s| matches!(s.kind, SiteKind::Closure(_)));
    let site = closures.next()?;
    if closures.next().is_some() {
        return None;
    }
    let on_parent = model.point_on(site.parent, &site.parent_offset);
    let v = on_parent.velocity.minus(&site.point.velocity);
    let found = rates_from(model, &v)?;
    Some(found.into_iter().map(|(i, value, _)| (i, value)).collect())
}

/// The two dependent rates' values from the loop's derivative `v`, with the unit vector
/// each is found with.
fn rates_from(model: &Model, v: &Vector) -> Option<Vec<(usize, Expr, Vector)>> {
    let problem = model.problem;
    let dependent = &model.constraints.dependent_rates;
    if !model.is_planar() || dependent.len() != 2 {
        return None;
    }
    let rates: Vec<Symbol> = dependent
        .iter()
        .map(|&i| problem.coordinate_symbol(i, 1))
        .collect();
    let partial = partials(v, &rates);
    let mut out = Vec::new();
    for k in 0..2 {
        let normal = perpendicular(model, &partial[1 - k])?;
        let along = simplify(&v.dot(&normal, &model.frames));
        let (coefficients, rest) = linear_split(&along, std::slice::from_ref(&rates[k])).ok()?;
        if coefficients[0].is_zero() {
            return None;
        }
        let value = simplify(&(-rest / coefficients[0].clone()));
        out.push((dependent[k], value, normal));
    }
    Some(out)
}

/// A unit vector perpendicular to `p` in the plane: the other in-plane unit vector of a
/// frame in which `p` has one in-plane component.
fn perpendicular(model: &Model, p: &Vector) -> Option<Vector> {
    (0..model.frames.len()).map(BodyId).find_map(|frame| {
        let c = p.components_in(frame, &model.frames).map(|e| simplify(&e));
        match (c[0].is_zero(), c[1].is_zero()) {
            (true, false) => Some(Vector::unit(frame, 0)),
            (false, true) => Some(Vector::unit(frame, 1)),
            _ => None,
        }
    })
}
