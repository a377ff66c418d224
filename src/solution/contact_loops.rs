//! A rolling contact's no-slip condition as a textbook writes it before its scalar rows:
//! the arm from the rolling body's mass centre to the contact point, `r^{D*P}`, then the
//! velocity of the body's point there, `ᴺv^P = ᴺv^{D*} + ᴺω^D × r^{D*P}`, set equal to the
//! velocity of the surface's point (zero on the ground), written out in one frame's unit
//! vectors: its components along the surface are the no-slip rows of the constraint table
//! (and along the normal, the no-penetration row differentiated). A smooth contact that
//! only touches (a ladder's top on a smooth wall) holds the normal component alone: its
//! point slides along the surface, so only `ᴺv^P · n̂ = 0` is written.

use super::tex::{centre_tex, initial_sign, shortest_tex};
use crate::equations::Derivation;
use crate::mechanics::{Model, RowOrigin, SiteKind, Vector};
use crate::problem::{BodyId, ConstraintKind};
use crate::symbolic::{latex_name, roots_of_squares, simplify, Axis};

/// The most characters of LaTeX the velocity written out may take: a longer one (the
/// bicycle's front wheel) is left to the rows.
const LONGEST: usize = 900;

/// One aligned display per rolling contact that has a no-slip row, and per smooth contact
/// that only touches, in the order of the sites, each with the words that open it; where
/// no contact rolls, a rough contact's slip velocity, which decides whether it slides.
pub fn loops(derivation: &Derivation) -> Vec<(String, String)> {
    let model = &derivation.model;
    let contacts: Vec<usize> = (0..model.sites.len())
        .filter(|&k| matches!(model.sites[k].kind, SiteKind::Contact(_)))
        .collect();
    let any_rolls = contacts.iter().any(|&k| rolls(model, k));
    let rough = rough_sites(model);
    let mut shown = 0;
    let mut out = Vec::new();
    for k in contacts {
        let next = |lead: String, shown: usize| match shown {
            0 => lead,
            _ => "Likewise at the next contact:".to_string(),
        };
        if rolls(model, k) {
            if let Some(display) = contact_display(model, k, true) {
                out.push((next(rolling_lead(model, k), shown), display));
                shown += 1;
            }
        } else if let Some(normal) = smooth_normal(model, k) {
            if let Some(display) = touching_display(model, k, &normal) {
                out.push((touching_lead(model, k), display));
            }
        } else if !any_rolls && rough.contains(&k) {
            if let Some(display) = contact_display(model, k, false) {
                out.push((next(slip_lead(model, k), shown), display));
                shown += 1;
            }
        }
    }
    out
}

/// The rough contacts (a friction law at the site) on the ground.
fn rough_sites(model: &Model) -> Vec<usize> {
    (0..model.sites.len())
        .filter(|&k| {
            matches!(model.sites[k].kind, SiteKind::Contact(_))
                && model.sites[k].parent == BodyId::GROUND
                && model.constraints.friction.iter().any(|f| f.site == k)
        })
        .collect()
}

/// The sentence before a rough contact's slip velocity: while it stays zero, a disc rolls
/// and a point that touches a plane (a ladder's foot) sticks, which friction must allow.
fn slip_lead(model: &Model, k: usize) -> String {
    let site = &model.sites[k];
    let disc = match site.kind {
        SiteKind::Contact(c) => matches!(
            model.problem.constraints.get(c).map(|c| &c.kind),
            Some(ConstraintKind::Rolling { .. })
        ),
        _ => false,
    };
    format!(
        "The slip velocity at {}: the velocity of the point of {} there, relative to \
         the ground. Friction acts against it while it is not zero; it stays zero, and \
         the contact {}, only while friction can hold it.",
        super::force_labels::place(&site.name),
        super::joint_words::body_words(model.problem, site.child),
        if disc { "rolls" } else { "sticks" }
    )
}

/// The sentence before a rolling contact's display: rolling on a surface, or the teeth of
/// two wheels that mesh, each wheel's point at the mesh moving with the other's.
fn rolling_lead(model: &Model, k: usize) -> String {
    let gear = match model.sites[k].kind {
        SiteKind::Contact(c) => match &model.problem.constraints[c].kind {
            // Two wheels on their axles; a disc rolling in a fixed cylinder has no teeth.
            ConstraintKind::Gear { body, on, .. }
                if *body != BodyId::GROUND && *on != BodyId::GROUND =>
            {
                Some((*body, *on))
            }
            _ => None,
        },
        _ => None,
    };
    match gear {
        Some((body, on)) => {
            let words = |b| super::joint_words::body_words(model.problem, b);
            format!(
                "The teeth do not slip at the mesh: the point of {} there has the velocity of \
                 the point of {} there; the components of this equation are the constraint \
                 rows below.",
                words(body),
                words(on)
            )
        }
        None => "Rolling without slipping: the rolling body's point at the contact has the \
                 velocity of the surface's point there; the components of this equation are \
                 the constraint rows below."
            .into(),
    }
}

/// The rows of contact site `k`, by their reaction components.
fn site_rows(model: &Model, k: usize) -> Vec<usize> {
    model
        .constraints
        .rows
        .iter()
        .filter_map(|row| match row.origin {
            RowOrigin::Site { site, component } if site == k => Some(component),
            _ => None,
        })
        .collect()
}

/// Whether contact site `k` has a constraint row along a tangent (it rolls, not only
/// touches) and no friction law (a rough contact may slide, as the bowling ball does at
/// the start, and then its point does not move with the surface), and is not a point that
/// only touches, whose one row is along the normal whatever its reaction's axis is called.
fn rolls(model: &Model, k: usize) -> bool {
    let rough = model.constraints.friction.iter().any(|f| f.site == k);
    !rough
        && !touches(model, k)
        && site_rows(model, k)
            .iter()
            .any(|&component| model.sites[k].reactions[component].axis != Axis::Normal)
}

/// Whether contact site `k` is a point that stays on a surface and may slide on it (a
/// ladder's top on a wall), not a disc or a gear, whose point moves with the surface.
fn touches(model: &Model, k: usize) -> bool {
    match model.sites[k].kind {
        SiteKind::Contact(c) => matches!(
            model.problem.constraints.get(c).map(|c| &c.kind),
            Some(ConstraintKind::Contact { .. })
        ),
        _ => false,
    }
}

/// The normal of a smooth contact `k` that only touches: one row, no friction law.
fn smooth_normal(model: &Model, k: usize) -> Option<Vector> {
    let rough = model.constraints.friction.iter().any(|f| f.site == k);
    match site_rows(model, k).as_slice() {
        [component] if !rough && touches(model, k) => {
            Some(model.sites[k].reactions[*component].direction.clone())
        }
        _ => None,
    }
}

/// The words before a smooth contact's display: what it holds, and what it does not.
fn touching_lead(model: &Model, k: usize) -> String {
    let site = &model.sites[k];
    let surface = site.name.replace('_', " ");
    format!(
        "No penetration at the {surface}: the {surface} is smooth and the body's point of contact slides along it, so the contact holds only the component of that point's velocity along the normal, which is zero (the whole velocity is not). It is the derivative of the constraint row below."
    )
}

/// The display of smooth contact site `k`: the arm, the velocity of the body's point there
/// and its component along `normal`, zero.
fn touching_display(model: &Model, k: usize, normal: &Vector) -> Option<String> {
    let site = &model.sites[k];
    if site.parent != BodyId::GROUND {
        return None;
    }
    let body = site.child;
    let sign = initial_sign(model);
    let tidy = |v: &Vector| v.map(|e| roots_of_squares(&simplify(e), &sign));
    let centre = &model.bodies[body.0].center;
    let arm = tidy(&site.point.position.minus(&centre.position));
    let velocity = tidy(&site.point.velocity);
    let along = roots_of_squares(&simplify(&velocity.dot(normal, &model.frames)), &sign);
    let point = latex_name(&site.name);
    let name = latex_name(model.problem.body_name(body));
    let star = centre_tex(model, body);
    let arm_name = format!("\\mathbf{{r}}^{{{star} {point}}}");
    let arm_tex = shortest_tex(model, &arm, body);
    let velocity_tex = shortest_tex(model, &velocity, site.parent);
    let normal_tex = shortest_tex(model, normal, site.parent);
    if velocity_tex.len() > LONGEST || arm_tex.len() > LONGEST {
        return None;
    }
    let own = format!("{{}}^{{N}}\\mathbf{{v}}^{{{point}}}");
    let lines = vec![
        super::aligned::line(&arm_name, "=", &arm_tex),
        format!(
            "{own} &= {{}}^{{N}}\\mathbf{{v}}^{{{star}}} + {{}}^{{N}}\\boldsymbol{{\\omega}}^{{{name}}} \\times {arm_name}"
        ),
        super::aligned::line("", "=", &velocity_tex),
        super::aligned::line(
            &format!("{own} \\cdot {normal_tex}"),
            "=",
            &format!("{} = 0", crate::symbolic::latex(&along)),
        ),
    ];
    Some(super::aligned::display(&lines))
}

/// The display of contact site `k`: its point's velocity set to the surface's (`rolls`), or
/// written as the slip it is.
fn contact_display(model: &Model, k: usize, rolls: bool) -> Option<String> {
    let site = &model.sites[k];
    let body = site.child;
    let sign = initial_sign(model);
    let tidy = |v: &Vector| v.map(|e| roots_of_squares(&simplify(e), &sign));
    let centre = &model.bodies[body.0].center;
    let arm = tidy(&site.point.position.minus(&centre.position));
    let on_parent = model.point_on(site.parent, &site.parent_offset);
    let slip = tidy(&site.point.velocity.minus(&on_parent.velocity));
    let point = latex_name(&site.name);
    let name = latex_name(model.problem.body_name(body));
    let star = centre_tex(model, body);
    let arm_name = format!("\\mathbf{{r}}^{{{star} {point}}}");
    let arm_tex = shortest_tex(model, &arm, body);
    // In the surface's unit vectors, along which the constraint rows take its components.
    let slip_tex = shortest_tex(model, &slip, site.parent);
    if slip_tex.len() > LONGEST || arm_tex.len() > LONGEST {
        return None;
    }
    let moving = site.parent != BodyId::GROUND;
    // On a moving body the point of the body rolled on has its own velocity there.
    let (own, surface) = if moving {
        let on = latex_name(model.problem.body_name(site.parent));
        (
            format!("{point}_{{{name}}}"),
            format!("{{}}^{{N}}\\mathbf{{v}}^{{{point}_{{{on}}}}}"),
        )
    } else {
        (point.clone(), "\\mathbf{0}".to_string())
    };
    let velocity = format!(
        "{{}}^{{N}}\\mathbf{{v}}^{{{star}}} + {{}}^{{N}}\\boldsymbol{{\\omega}}^{{{name}}} \\times {arm_name}"
    );
    let own_velocity = format!("{{}}^{{N}}\\mathbf{{v}}^{{{own}}}");
    let mut lines = vec![super::aligned::line(&arm_name, "=", &arm_tex)];
    if moving {
        // The difference of the two points' velocities, written out, is the slip.
        lines.push(format!("{own_velocity} &= {velocity} = {surface}"));
        lines.push(super::aligned::line(
            &format!("{own_velocity} - {surface}"),
            "=",
            &format!("{slip_tex} = \\mathbf{{0}}"),
        ));
    } else {
        // On the ground the velocity itself is the slip.
        lines.push(format!("{own_velocity} &= {velocity}"));
        let zero = if rolls { " = \\mathbf{0}" } else { "" };
        lines.push(super::aligned::line("", "=", &format!("{slip_tex}{zero}")));
    }
    Some(super::aligned::display(&lines))
}
