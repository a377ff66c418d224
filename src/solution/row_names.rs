//! How step 5 and the matrix name a row: the free body and the sum (`B\colon \sum
//! \mathbf{M}_{P} \cdot \hat{\mathbf{a}}_{z}`), Kane's `F_{r} + F^{*}_{r}`, Lagrange's
//! equation of a coordinate, or what a constraint row constrains and along which direction.

use super::direction::simplest_tex;
use super::force_labels::place;
use super::tex::{bodies_tex_short, point_tex};
use crate::equations::Derivation;
use crate::mechanics::{Model, RowOrigin};
use crate::plan::Sum;
use crate::symbolic::latex;

/// Row `i`'s equation as step 5 heads it: `B\colon \sum \mathbf{M}_{P} \cdot
/// \hat{\mathbf{a}}_{z}`, `F_{1} + F^{*}_{1}`, or what a constraint row constrains.
pub fn row_heading_tex(derivation: &Derivation, i: usize) -> String {
    let row = &derivation.rows[i];
    let direction = row
        .direction
        .as_ref()
        .map(|d| format!(" \\cdot {}", d.latex))
        .unwrap_or_default();
    match &row.sum {
        Sum::Constraint { name } => constraint_label_tex(&derivation.model, name),
        Sum::Generalized { .. } => sum_tex(derivation, &row.sum),
        _ => format!(
            "{}\\colon {}{direction}",
            bodies_tex_short(derivation, &row.free_body),
            sum_tex(derivation, &row.sum)
        ),
    }
}

/// The number `r` of Kane's row among the rows of the speeds and auxiliary speeds (1-based).
fn kane_index(derivation: &Derivation, sum: &Sum) -> String {
    derivation
        .rows
        .iter()
        .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
        .position(|x| x.sum == *sum)
        .map_or("r".to_string(), |i| (i + 1).to_string())
}

/// What Kane's row `r` dots the forces with, as the plan's Direction column names it: the
/// partial velocities of its speed, `\mathbf{v}_{r}, \boldsymbol{\omega}_{r}` (with a
/// tilde where formed with the constrained partial velocities; no `ω` for particles alone).
pub fn kane_direction_tex(derivation: &Derivation, row: &crate::plan::Equation) -> String {
    let r = kane_index(derivation, &row.sum);
    let tilde = |t: &str| match derivation.dependent_speeds {
        Some(_) => format!("\\tilde{{{t}}}_{{{r}}}"),
        None => format!("{t}_{{{r}}}"),
    };
    let model = &derivation.model;
    let rigid = (row.free_body.iter()).any(|&b| !crate::mechanics::is_particle(model, b));
    match rigid {
        true => format!(
            "{},\\ {}",
            tilde("\\mathbf{v}"),
            tilde("\\boldsymbol{\\omega}")
        ),
        false => tilde("\\mathbf{v}"),
    }
}

/// A sum as an equation's column names it: `\sum \mathbf{F}`, `\sum \mathbf{M}_{O}`,
/// `F_{r} + F^{*}_{r}` (r among Kane's rows), or what a constraint constrains.
pub fn sum_tex(derivation: &Derivation, sum: &Sum) -> String {
    match sum {
        Sum::Force => "\\sum \\mathbf{F}".into(),
        Sum::Moment { point, position } => format!(
            "\\sum \\mathbf{{M}}_{{{}}}",
            point_tex(&super::moment_point::shown_point(
                &derivation.model,
                point,
                position
            ))
        ),
        Sum::Generalized { .. } if derivation.method == crate::equations::Method::Lagrange => {
            super::lagrange::equation_tex(derivation, sum).unwrap_or_default()
        }
        Sum::Generalized { .. } => {
            let r = kane_index(derivation, sum);
            if derivation.dependent_speeds.is_some() {
                format!("\\tilde{{F}}_{{{r}}} + \\tilde{{F}}^{{*}}_{{{r}}}")
            } else {
                format!("F_{{{r}}} + F^{{*}}_{{{r}}}")
            }
        }
        Sum::Constraint { name } => constraint_what_tex(&derivation.model, name),
    }
}

/// A constraint row's label in the matrix form: what it constrains and, for a site's row,
/// the direction of its reaction, e.g. `\text{loop closure at C}\text{, along } \hat{\mathbf{a}}_{x}`.
pub(super) fn constraint_label_tex(model: &Model, name: &str) -> String {
    let what = constraint_what_tex(model, name);
    match constraint_direction_tex(model, name) {
        Some(direction) => format!("{what}\\text{{, along }} {direction}"),
        None => what,
    }
}

/// What a constraint row constrains, in LaTeX: `\text{no slip at floor}`, or
/// `\text{prescribed motion of } \theta` with the coordinate as a symbol.
pub(super) fn constraint_what_tex(model: &Model, name: &str) -> String {
    use crate::mechanics::SiteKind;
    let problem = model.problem;
    // A site's name in words: `rear_contact` is the rear contact.
    let text = |words: String| {
        format!(
            "\\text{{{}}}",
            crate::render::escape_latex(&words.replace('_', " "), crate::render::Lines::One)
        )
    };
    let sticking = model
        .constraints
        .friction
        .iter()
        .find(|f| f.stick.iter().any(|r| r.name == name));
    if let Some(site) = sticking {
        // A friction site's no-slip row holds only while it sticks (rolls).
        return text(format!("no slip at {} while it sticks", place(&site.name)));
    }
    let row = model.constraints.rows.iter().find(|r| r.name == name);
    match row.map(|r| &r.origin) {
        Some(RowOrigin::Site { site, .. }) => match model.sites.get(*site) {
            Some(s) if matches!(s.kind, SiteKind::Contact(_)) => {
                let kind = match s.kind {
                    SiteKind::Contact(k) => problem.constraints.get(k).map(|c| &c.kind),
                    _ => None,
                };
                // A position-level row holds the body on the surface (the normal) or,
                // for a gear, the distance between the centres; a velocity-level row is
                // the no-slip condition along the contact's tangent (a gear's meshing).
                let holonomic = row.is_some_and(|r| r.position.is_some());
                match (kind, holonomic) {
                    (Some(crate::problem::ConstraintKind::Gear { .. }), true) => {
                        centres_apart_tex(kind)
                    }
                    (_, true) => text(format!("no penetration at {}", place(&s.name))),
                    (_, false) => text(format!("no slip at {}", place(&s.name))),
                }
            }
            Some(s) if matches!(s.kind, SiteKind::Closure(_)) => match row.map(|r| &r.origin) {
                Some(RowOrigin::Site { component, .. }) if is_guide(model, s) => {
                    text(guide_words(model, s, *component))
                }
                _ => text(format!("loop closure at {}", place(&s.name))),
            },
            Some(s) => text(format!("constraint at {}", place(&s.name))),
            None => text(format!("constraint {name}")),
        },
        Some(RowOrigin::Position(_)) => text(format!("position constraint {name}")),
        Some(RowOrigin::Velocity(_)) => text(format!("velocity constraint {name}")),
        Some(RowOrigin::Prescribed(c)) if *c < problem.coordinates.len() => {
            let symbol = latex(&problem.coordinate_expr(*c, 0));
            if problem.coordinates[*c].held {
                format!("{symbol} \\text{{ held by its support}}")
            } else {
                format!("\\text{{prescribed motion of }} {symbol}")
            }
        }
        Some(RowOrigin::Prescribed(_)) => text(format!("prescribed motion {name}")),
        None => text(format!("constraint {name}")),
    }
}

/// A gear's position row as a course says it: the centres stay `R - r` apart (`R + r`
/// outside the other disc), the radii as the problem names them.
fn centres_apart_tex(kind: Option<&crate::problem::ConstraintKind>) -> String {
    let Some(crate::problem::ConstraintKind::Gear {
        radius,
        on_radius,
        internal,
        ..
    }) = kind
    else {
        return "\\text{the centres stay apart}".to_string();
    };
    let apart = match internal {
        true => on_radius - radius,
        false => crate::symbolic::add(vec![on_radius.clone(), radius.clone()]),
    };
    format!(
        "\\text{{the centres stay }} {} \\text{{ apart}}",
        latex(&apart)
    )
}

/// Whether closure `site` joins a body straight to the body its own joint hangs it from
/// (a collar on a fixed rod): no chain of bodies closes a loop there; it is a guide.
pub(super) fn is_guide(model: &Model, site: &crate::mechanics::Site) -> bool {
    let problem = model.problem;
    let joined = |a, b| {
        (problem.joints.iter())
            .any(|j| (j.child == a && j.parent == b) || (j.child == b && j.parent == a))
    };
    matches!(site.kind, crate::mechanics::SiteKind::Closure(_)) && joined(site.child, site.parent)
}

/// What a guide's row holds, by its reaction component: the rod keeps the collar on its
/// line (a force), stops it turning (a moment).
fn guide_words(model: &Model, site: &crate::mechanics::Site, component: usize) -> String {
    use crate::symbolic::ComponentKind;
    let guide = match place(&site.name) {
        words if words.starts_with("the ") => words,
        letter => format!("the guide at {letter}"),
    };
    let body = super::joint_words::body_words(model.problem, site.child);
    let closure = match site.kind {
        crate::mechanics::SiteKind::Closure(k) => model.problem.closures.get(k),
        _ => None,
    };
    let sliding = closure.is_some_and(|c| {
        matches!(
            c.kind,
            crate::problem::JointKind::Prismatic | crate::problem::JointKind::Cylindrical
        )
    });
    match site.reactions.get(component).map(|c| c.kind) {
        Some(ComponentKind::Moment) => format!("{guide} stops {body} turning"),
        _ if sliding => format!("{guide} keeps {body} on its line"),
        _ => format!("{guide} holds {body} at its pin"),
    }
}

/// The direction of a closure's or a contact's constraint row: that of the reaction
/// component that enforces it (the row is the relative motion along it).
pub(super) fn constraint_direction_tex(model: &Model, name: &str) -> Option<String> {
    // A no-slip row of a friction site: along the tangent its friction component takes.
    for friction in &model.constraints.friction {
        if let Some(row) = friction.stick.iter().find(|r| r.name == name) {
            let site = model.sites.get(friction.site)?;
            let component =
                (site.reactions.iter()).find(|c| c.unknown(&site.name) == row.unknown)?;
            return Some(direction_tex(model, &component.direction));
        }
    }
    let row = model.constraints.rows.iter().find(|r| r.name == name)?;
    let RowOrigin::Site { site, component } = row.origin else {
        return None;
    };
    let direction = model.sites.get(site)?.row_direction(component)?;
    Some(direction_tex(model, direction))
}

/// A row's direction by the name step 1 defines for it (ê_t, −ê_r), else in the frame
/// that writes it shortest.
fn direction_tex(model: &Model, direction: &crate::mechanics::Vector) -> String {
    super::polar_units::named(model, direction).unwrap_or_else(|| simplest_tex(model, direction))
}
