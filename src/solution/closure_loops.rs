//! A closure's vector loop as a textbook writes it before its scalar constraints: the
//! point where the loop closes, reached down each chain of bodies, is one point; and the
//! same loop differentiated, the velocity constraints.

use super::tex::vector_tex;
use crate::equations::Derivation;
use crate::mechanics::constraints::RowOrigin;
use crate::symbolic::print::latex_name_of;

/// One sentence per closure written as its loop (see `ConstraintRow::loop_acceleration`):
/// `r^{R_C} = r^{R_B}` and `v^{R_C} = v^{R_B}`, each side written down its chain.
pub fn notes(derivation: &Derivation) -> Vec<String> {
    let model = &derivation.model;
    let mut sites: Vec<usize> = Vec::new();
    for row in &model.constraints.rows {
        if let (RowOrigin::Site { site, .. }, Some(_)) = (&row.origin, &row.loop_acceleration) {
            if !sites.contains(site) {
                sites.push(*site);
            }
        }
    }
    sites
        .into_iter()
        .map(|index| {
            let site = &model.sites[index];
            let on_parent = model.point_on(site.parent, &site.parent_offset);
            let name = |body| latex_name_of(&site.name, model.problem.body_name(body));
            let (child, parent) = (name(site.child), name(site.parent));
            let point = crate::symbolic::print::latex_name(&site.name);
            format!(
                "The loop closes at ${point}$, reached through each chain of bodies: ${{}}^{{N}}\\mathbf{{r}}^{{{child}}} = {{}}^{{N}}\\mathbf{{r}}^{{{parent}}}$, that is ${} = {}$. Its components along the rows' directions are the position constraints above. Differentiated, ${{}}^{{N}}\\mathbf{{v}}^{{{child}}} = {{}}^{{N}}\\mathbf{{v}}^{{{parent}}}$, that is ${} = {}$: its components are the velocity constraints.",
                vector_tex(model, &site.point.position),
                vector_tex(model, &on_parent.position),
                vector_tex(model, &site.point.velocity),
                vector_tex(model, &on_parent.velocity),
            )
        })
        .collect()
}
