//! A closure's vector loop as a textbook writes it before its scalar constraints: the
//! point where the loop closes, reached down each chain of bodies, is one point; and the
//! same loop differentiated, the velocity constraints.

use super::tex::vector_tex;
use crate::equations::Derivation;
use crate::mechanics::RowOrigin;
use crate::symbolic::latex_name_of;

/// The most characters of LaTeX a side of a loop written in the text may take.
const LONGEST_SIDE: usize = 90;

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
        .filter_map(|index| {
            let site = &model.sites[index];
            let on_parent = model.point_on(site.parent, &site.parent_offset);
            // Plain brackets, which TeX can break inside a line of text.
            let plain = |v: &crate::mechanics::Vector| {
                vector_tex(model, v)
                    .replace("\\left(", "(")
                    .replace("\\right)", ")")
            };
            let sides = [
                plain(&site.point.position),
                plain(&on_parent.position),
                plain(&site.point.velocity),
                plain(&on_parent.velocity),
            ];
            // Within a line of text: a longer side, or one in other brackets TeX cannot
            // break, would stick out of the margin.
            if sides.iter().any(|s| s.len() > LONGEST_SIDE || s.contains("\\left")) {
                return None;
            }
            let [r_child, r_parent, v_child, v_parent] = sides;
            let name = |body| latex_name_of(&site.name, model.problem.body_name(body));
            let (child, parent) = (name(site.child), name(site.parent));
            let point = crate::symbolic::latex_name(&site.name);
            Some(format!(
                "The loop closes at ${point}$, reached through each chain of bodies: ${{}}^{{N}}\\mathbf{{r}}^{{{child}}} = {{}}^{{N}}\\mathbf{{r}}^{{{parent}}}$, that is ${} = {}$. Its components along the rows' directions are the position constraints above. Differentiated, ${{}}^{{N}}\\mathbf{{v}}^{{{child}}} = {{}}^{{N}}\\mathbf{{v}}^{{{parent}}}$, that is ${} = {}$: its components are the velocity constraints.",
                r_child, r_parent, v_child, v_parent,
            ))
        })
        .collect()
}
