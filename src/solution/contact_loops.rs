//! A rolling contact's no-slip condition as a textbook writes it before its scalar rows:
//! the arm from the rolling body's mass centre to the contact point, `r^{D*P}`, then the
//! velocity of the body's point there, `ᴺv^P = ᴺv^{D*} + ᴺω^D × r^{D*P}`, set equal to the
//! velocity of the surface's point (zero on the ground), written out in one frame's unit
//! vectors: its components along the surface are the no-slip rows of the constraint table
//! (and along the normal, the no-penetration row differentiated).

use super::tex::{centre_tex, initial_sign, shortest_tex};
use crate::equations::Derivation;
use crate::mechanics::{Model, RowOrigin, SiteKind, Vector};
use crate::problem::{BodyId, ConstraintKind};
use crate::symbolic::{latex_name, roots_of_squares, simplify, Axis};

/// The most characters of LaTeX the velocity written out may take: a longer one (the
/// bicycle's front wheel) is left to the rows.
const LONGEST: usize = 900;

/// One aligned display per rolling contact that has a no-slip row, in the order of the
/// sites.
pub fn loops(derivation: &Derivation) -> Vec<String> {
    let model = &derivation.model;
    let rolling: Vec<String> = (0..model.sites.len())
        .filter(|&k| matches!(model.sites[k].kind, SiteKind::Contact(_)) && rolls(model, k))
        .filter_map(|k| contact_display(model, k, true))
        .collect();
    if !rolling.is_empty() {
        return rolling;
    }
    // No contact that rolls: a rough one's slip velocity, which decides whether it slides.
    rough_sites(model)
        .into_iter()
        .filter_map(|k| contact_display(model, k, false))
        .collect()
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

/// The sentence before the first display: rolling on a surface, or the teeth of two wheels
/// that mesh, each wheel's point at the mesh moving with the other's.
pub fn lead(derivation: &Derivation) -> String {
    let model = &derivation.model;
    let first = (0..model.sites.len())
        .filter(|&k| matches!(model.sites[k].kind, SiteKind::Contact(_)) && rolls(model, k))
        .find(|&k| contact_display(model, k, true).is_some());
    if first.is_none() {
        if let Some(k) =
            (rough_sites(model).into_iter()).find(|&k| contact_display(model, k, false).is_some())
        {
            let site = &model.sites[k];
            return format!(
                "The slip velocity at {}: the velocity of the point of {} there, relative to \
                 the ground. Friction acts against it while it is not zero; once it is zero, \
                 the contact rolls.",
                super::force_labels::place(&site.name),
                super::joint_words::body_words(model.problem, site.child)
            );
        }
    }
    let gear = first.and_then(|k| match model.sites[k].kind {
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
    });
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

/// Whether contact site `k` has a constraint row along a tangent (it rolls, not only
/// touches) and no friction law (a rough contact may slide, as the bowling ball does at
/// the start, and then its point does not move with the surface).
fn rolls(model: &Model, k: usize) -> bool {
    let rough = model.constraints.friction.iter().any(|f| f.site == k);
    !rough
        && model.constraints.rows.iter().any(|row| match row.origin {
            RowOrigin::Site { site, component } => {
                site == k && model.sites[k].reactions[component].axis != Axis::Normal
            }
            _ => false,
        })
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
