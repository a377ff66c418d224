//! The light rods whose closure carries the rod's tension alone, said as a textbook says
//! it (the Motion Law's plan and Kane's step 5 both write the tension as the unknown).

use crate::equations::Derivation;
use crate::symbolic::{latex_name, Expr};

/// Each light rod whose closure carries its tension alone, and why (see
/// [`crate::mechanics::light_rod`]).
pub(super) fn notes(derivation: &Derivation) -> Vec<String> {
    let model = &derivation.model;
    let problem = model.problem;
    let closures = model.sites.iter().skip(problem.joints.len());
    closures
        .filter_map(|site| {
            let member = (site.reactions.iter()).find(|c| c.axis == crate::symbolic::Axis::Member)?;
            let rod = latex_name(problem.body_name(site.parent));
            let pin = model.sites.iter().find(|other| other.child == site.parent)?;
            let (at, from) = (latex_name(&site.name), latex_name(&pin.name));
            let unknown = Expr::sym(member.unknown(&site.name));
            let force = super::tex::vector_tex(model, &member.direction.scaled(&unknown));
            Some(format!(
                "The light rod ${rod}$, pinned at ${from}$ and ${at}$ with no mass and no load, is a two-force member: its moment balance about ${from}$ leaves no force across it, so the force at ${at}$ lies along the rod, $\\mathbf{{F}}^{{{at}}} = {force}$: one unknown, the rod's tension (positive when the rod pulls), instead of two components."
            ))
        })
        .collect()
}
