//! A moment row's reactions and weights written out as a student writes them: for each
//! reaction or weight on a body of the free body whose line misses the moment point, its
//! moment
//! `(r^{D* P} × F^P) · n̂_z` worked to its value, reduced by what the constraints keep
//! (x² + y² = (R − r)²).

use crate::equations::Derivation;
use crate::mechanics::Vector;
use crate::plan::{is_external, ActionKind, Direction, Source};
use crate::problem::BodyId;
use crate::symbolic::{latex_collected, latex_name, simplify, Expr};

/// One line of the written-out display per reaction and per weight with a moment about
/// the point named `point_tex` at `position`, on the bodies of `free_body`.
pub fn lines(
    derivation: &Derivation,
    free_body: &[BodyId],
    (point_tex, position): (&str, &Vector),
    direction: &Direction,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Vec<String> {
    let model = &derivation.model;
    let frames = &model.frames;
    let mut out = Vec::new();
    for action in (derivation.actions.iter()).filter(|a| is_external(a, free_body)) {
        let ActionKind::Force { offset, force } = &action.kind else {
            continue;
        };
        let (to, f) = match action.source {
            Source::Reaction(site) => {
                let name = latex_name(model.problem.site_name(site));
                (
                    name.clone(),
                    force_tex(derivation, action, site, &name, force),
                )
            }
            // A weight at its body's mass centre, written as the table writes it.
            Source::Gravity => (
                super::tex::centre_tex(model, action.body),
                format!("({})", super::tex::vector_tex(model, force)),
            ),
            _ => continue,
        };
        let at = (model.bodies[action.body.0].origin.position)
            .plus(&Vector::new(action.body, offset.clone()));
        let r = at.minus(position);
        let apart = r.components_in(BodyId::GROUND, frames);
        if apart.iter().all(|c| simplify(c).is_zero()) {
            continue;
        }
        let moment = simplify(&r.cross(force, frames).dot(&direction.vector, frames));
        let moment = reduced(derivation, moment);
        if moment.is_zero() {
            continue;
        }
        out.push(format!(
            "(\\mathbf{{r}}^{{{point_tex} {to}}} \\times {f}) \\cdot {} &= {}",
            direction.latex,
            latex_collected(&shown(&moment))
        ));
    }
    out
}

/// A reaction force as the free body's table names it: along one unit vector, as the
/// table writes it (`−F_t^P n̂_y`); else by the site's name, `F^P` on the child and its
/// opposite on the parent.
fn force_tex(
    derivation: &Derivation,
    action: &crate::plan::Action,
    site: usize,
    name: &str,
    force: &Vector,
) -> String {
    let shown = force.map(crate::symbolic::as_shown);
    let written = super::direction::simplest_tex(&derivation.model, &shown);
    let body = written.strip_prefix('-').unwrap_or(&written);
    if !body.contains(" + ") && !body.contains(" - ") {
        return format!("({written})");
    }
    if action.body == derivation.model.sites[site].child {
        format!("\\mathbf{{F}}^{{{name}}}")
    } else {
        format!("(-\\mathbf{{F}}^{{{name}}})")
    }
}

/// `e` reduced by each relation the constraints keep, where that is shorter.
pub(super) fn reduced(derivation: &Derivation, e: Expr) -> Expr {
    let mut best = e;
    for (_, relation) in &derivation.model.constraints.relations {
        let candidate = simplify(&relation.reduce(&best));
        if candidate.operation_count() < best.operation_count() {
            best = candidate;
        }
    }
    best
}
