//! Step 5's words on a contact's normal force that comes out negative: the free body draws
//! the unknown along its positive unit vector, which at a contact points into the body (a
//! push, `docs/conventions/normal-forces.md`). A normal force whose value is negative acts
//! against that arrow, and the handout says which way it then acts on the body, as a course
//! says it: "a pull of 2.1 N on D" (a body that would leave its surface).

use crate::mechanics::{ComponentKind, Model, Site};
use crate::symbolic::{eval, fixed, latex, Axis, Expr, Values};

/// One sentence for each contact whose normal force at the initial state is negative;
/// `reactions` are the forces at the initial state, each along its site's parent's unit
/// vectors.
pub(super) fn notes(
    model: &Model,
    (q0, rates0): (&[f64], &[f64]),
    reactions: &[(String, [f64; 3], [f64; 3])],
) -> Vec<String> {
    let values = model.values_at(0.0, q0, rates0);
    let mut out = Vec::new();
    for site in &model.sites {
        let Some(normal) = (site.reactions.iter())
            .find(|c| c.kind == ComponentKind::Force && c.axis == Axis::Normal)
        else {
            continue;
        };
        let Some((_, force, _)) = reactions.iter().find(|(name, _, _)| *name == site.name) else {
            continue;
        };
        let along = numbers(
            &normal.direction.components_in(site.parent, &model.frames),
            &values,
        );
        let value: f64 = (0..3).map(|k| force[k] * along[k]).sum();
        if value >= 0.0 || fixed(value) == "0" {
            continue;
        }
        // Positive along a normal into the body is a push, so a negative value pulls.
        let push = !toward_body(model, site, along, &values);
        let name = latex(&Expr::sym(normal.unknown(&site.name)));
        let body = crate::symbolic::latex_name(model.problem.body_name(site.child));
        let kind = if push { "push" } else { "pull" };
        let sense = format!("a {kind} of {} N on ${body}$", fixed(-value));
        out.push(format!(
            "The normal force at {} comes out negative at the initial state, ${name} = {}\\ \\mathrm{{N}}$: it acts against the arrow of the free body, {sense}.",
            site.name.replace('_', "\\_"),
            fixed(value)
        ));
    }
    out
}

fn numbers(c: &[Expr; 3], values: &Values) -> [f64; 3] {
    std::array::from_fn(|k| eval(&c[k], values))
}

/// Whether the normal's positive unit vector `along` (parent's unit vectors) points from
/// the contact point into the body it acts on, toward its mass centre: then a positive
/// normal force pushes.
fn toward_body(model: &Model, site: &Site, along: [f64; 3], values: &Values) -> bool {
    let centre = model.bodies[site.child.0]
        .center
        .position
        .components_in(site.parent, &model.frames);
    let point = site
        .point
        .position
        .components_in(site.parent, &model.frames);
    let (centre, point) = (numbers(&centre, values), numbers(&point, values));
    (0..3)
        .map(|k| along[k] * (centre[k] - point[k]))
        .sum::<f64>()
        > 0.0
}
