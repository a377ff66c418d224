//! The rows a student's equation is matched against, each with the contributions of the
//! worked solution it is the sum of: the moment of A's weight about O, the inertia force
//! of B, the inertia torque of B.

use super::reference::Reference;
use crate::equations::Method;
use crate::mechanics::{Model, Vector};
use crate::plan::{action_terms, inertia_terms, Action, Equation, Inertia, Source, Sum};
use crate::problem::BodyId;
use crate::symbolic::{add, Expr};

/// What a contribution is.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Kind {
    /// A force or couple on the free body: a weight, a load, a reaction.
    Load,
    /// The inertia force `-m a*` of a body (its moment, in a moment equation).
    InertiaForce(String),
    /// The inertia torque of a body.
    InertiaTorque(String),
}

/// One contribution to a row.
#[derive(Clone, Debug)]
pub(super) struct Contribution {
    /// As a course names it: "the moment of the weight of A about O".
    pub label: String,
    /// What it is.
    pub kind: Kind,
    /// Its terms.
    pub expr: Expr,
}

/// A row of the worked solution.
#[derive(Clone, Debug)]
pub(super) struct Row {
    /// "the moment equation of A + B about O along N.z".
    pub label: String,
    /// `expr = 0`.
    pub expr: Expr,
    /// What it sums (empty for Kane's rows and the constraint rows).
    pub contributions: Vec<Contribution>,
    /// The point moments are taken about, in a moment equation.
    pub point: Option<String>,
}

/// Where a row sums: its free body, the point its moments are about, its direction.
struct Spec<'a> {
    free_body: Vec<BodyId>,
    about: Option<(String, Vector)>,
    direction: (&'a str, &'a Vector),
}

/// Every row a student's equation may be: the worked solution's, Newton–Euler's, and the
/// sums of forces and of moments about each joint of the bodies outboard of it.
pub(super) fn rows(reference: &Reference) -> Vec<Row> {
    let derivation = &reference.derivation;
    let model = &derivation.model;
    let inertia = derivation.inertia();
    let actions = &derivation.actions;
    let mut out: Vec<Row> = Vec::new();
    let push = |row: Row, out: &mut Vec<Row>| {
        if !out.iter().any(|r| r.label == row.label) {
            out.push(row);
        }
    };
    let theirs = derivation
        .rows
        .iter()
        .chain(reference.newton_euler.iter().flat_map(|d| d.rows.iter()));
    for equation in theirs {
        let row = of_equation(model, actions, inertia, equation, derivation.method);
        push(row, &mut out);
    }
    for row in subtree_rows(model, actions, inertia) {
        push(row, &mut out);
    }
    out
}

fn of_equation(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    eq: &Equation,
    method: Method,
) -> Row {
    let free_body = eq.free_body.clone();
    let (label, about) = match (&eq.sum, &eq.direction) {
        (Sum::Moment { point, position }, Some(d)) => (
            format!(
                "the moment equation of {} about {point} along {}",
                names(model, &free_body),
                d.name
            ),
            Some((point.clone(), position.clone())),
        ),
        (Sum::Force, Some(d)) => (
            format!(
                "the force equation of {} along {}",
                names(model, &free_body),
                d.name
            ),
            None,
        ),
        (Sum::Generalized { speed }, _) => (generalized_row_name(method, speed), None),
        (Sum::Constraint { name }, _) => (format!("the constraint row {name}"), None),
        _ => ("a row of the worked solution".into(), None),
    };
    let contributions = match (&eq.sum, &eq.direction) {
        (Sum::Moment { .. } | Sum::Force, Some(d)) => {
            let spec = Spec {
                free_body,
                about: about.clone(),
                direction: (&d.name, &d.vector),
            };
            contributions(model, actions, inertia, &spec)
        }
        _ => Vec::new(),
    };
    Row {
        label,
        expr: eq.expression.clone(),
        contributions,
        point: about.map(|(p, _)| p),
    }
}

/// The sums of moments about each joint, and of forces, of the bodies outboard of it,
/// along each axis of N the problem moves in.
/// A generalized row as the course names it: Kane's equation belongs to a speed, Lagrange's
/// to the coordinate whose rate it is.
fn generalized_row_name(method: Method, speed: &str) -> String {
    match method {
        Method::Lagrange => {
            let coordinate = speed.strip_suffix('\'').unwrap_or(speed);
            format!("Lagrange's equation for {coordinate}")
        }
        _ => format!("Kane's equation for {speed}"),
    }
}

fn subtree_rows(model: &Model, actions: &[Action], inertia: &Inertia) -> Vec<Row> {
    let planar = model.is_planar();
    let axes: &[usize] = if planar { &[2] } else { &[0, 1, 2] };
    let forces: &[usize] = if planar { &[0, 1] } else { &[0, 1, 2] };
    let mut out = Vec::new();
    for (j, joint) in model.problem.joints.iter().enumerate() {
        let free_body = model.subtree(j);
        let point = (joint.name.clone(), model.joints[j].point.position.clone());
        for (about, list) in [(Some(point), axes), (None, forces)] {
            for &axis in list {
                let direction = crate::plan::unit_direction(model, BodyId::GROUND, axis);
                let spec = Spec {
                    free_body: free_body.clone(),
                    about: about.clone(),
                    direction: (&direction.name, &direction.vector),
                };
                let contributions = contributions(model, actions, inertia, &spec);
                let expr = add(contributions.iter().map(|c| c.expr.clone()));
                let label = match &about {
                    Some((p, _)) => format!(
                        "the moment equation of {} about {p} along {}",
                        names(model, &free_body),
                        direction.name
                    ),
                    None => format!(
                        "the force equation of {} along {}",
                        names(model, &free_body),
                        direction.name
                    ),
                };
                out.push(Row {
                    label,
                    expr,
                    contributions,
                    point: about.as_ref().map(|(p, _)| p.clone()),
                });
            }
        }
    }
    out
}

fn names(model: &Model, bodies: &[BodyId]) -> String {
    bodies
        .iter()
        .map(|b| model.frames.name(*b).to_string())
        .collect::<Vec<_>>()
        .join(" + ")
}

/// Each external action's term and each body's inertia terms in the row `spec`.
fn contributions(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    spec: &Spec,
) -> Vec<Contribution> {
    let about = spec.about.as_ref().map(|(_, v)| v);
    let point = spec.about.as_ref().map(|(p, _)| p.as_str());
    let (_, direction) = spec.direction;
    let mut out = Vec::new();
    for action in actions {
        if !crate::plan::is_external(action, &spec.free_body) {
            continue;
        }
        let (contact, distance) = action_terms(
            model,
            std::slice::from_ref(action),
            &spec.free_body,
            about,
            direction,
        );
        let expr = contact + distance;
        if expr.is_zero() {
            continue;
        }
        out.push(Contribution {
            label: action_label(model, action, point),
            kind: Kind::Load,
            expr,
        });
    }
    for &body in &spec.free_body {
        let name = model.frames.name(body).to_string();
        let (force, torque) = inertia_terms(model, inertia, &[body], about, direction);
        let force_label = match point {
            Some(p) => format!("the moment of the inertia force of {name} (-m a*) about {p}"),
            None => format!("the inertia force of {name} (-m a*)"),
        };
        for (label, kind, expr) in [
            (force_label, Kind::InertiaForce(name.clone()), force),
            (
                format!("the inertia torque of {name}"),
                Kind::InertiaTorque(name.clone()),
                torque,
            ),
        ] {
            if !expr.is_zero() {
                out.push(Contribution { label, kind, expr });
            }
        }
    }
    out
}

fn action_label(model: &Model, action: &Action, point: Option<&str>) -> String {
    let what = match action.source {
        Source::Gravity => format!("the weight of {}", model.frames.name(action.body)),
        Source::Reaction(site) => format!("the reaction at {}", model.sites[site].name),
        _ => action.label.clone(),
    };
    match point {
        Some(p) => format!("the moment of {what} about {p}"),
        None => what,
    }
}
