//! Kane's method said once, where step 5 first uses it, and only what applies to the
//! problem: the generalized active and inertia forces, with a body's inertia torque only
//! where some body has rotational inertia.

use crate::equations::{Derivation, Method};
use crate::mechanics::is_particle;
use crate::render::context::KaneTheory;
use crate::render::text::{MarkupLine, Math};

/// The letters the formula's point may take, in order of preference.
const POINT_LETTERS: [&str; 4] = ["P", "Q", "K", "X"];

/// The definitions of `F_r` and `F^*_r` for Kane's handout (`None` for the other methods):
/// a problem of particles alone has no couples on bodies and no inertia torques, so their
/// terms are left out.
pub fn theory(derivation: &Derivation) -> Option<KaneTheory> {
    if derivation.method != Method::Kane {
        return None;
    }
    let model = &derivation.model;
    let rigid = model.order.iter().any(|&body| !is_particle(model, body));
    // The point's letter is one the problem does not use (a double pendulum's pin is P),
    // nor a letter the handout prints for a point named by a word (a contact's P).
    let shown = super::shown_names::shown_names(model);
    let letters: Vec<&str> = (POINT_LETTERS.iter().copied())
        .filter(|l| shown.iter().all(|(_, letter)| letter != l))
        .collect();
    let x = crate::problem::free_letter(model.problem, &letters);
    let (forces_tex, note) = if rigid {
        (
            format!("F_r = \\sum_{{{x}}} \\mathbf{{v}}^{{{x}}}_r \\cdot \\mathbf{{R}}_{{{x}}} + \\sum_{{B}} \\boldsymbol{{\\omega}}^{{B}}_r \\cdot \\mathbf{{T}}_{{B}}, \\qquad F^{{*}}_r = \\sum_{{B}} \\left(\\mathbf{{v}}^{{B^*}}_r \\cdot \\mathbf{{R}}^{{*}}_{{B}} + \\boldsymbol{{\\omega}}^{{B}}_r \\cdot \\mathbf{{T}}^{{*}}_{{B}}\\right),"),
            format!("with $\\mathbf{{R}}_{x}$ a force applied at the point ${x}$, $\\mathbf{{T}}_B$ a couple on body $B$, $\\mathbf{{R}}^{{*}}_{{B}} = -m_B\\,\\mathbf{{a}}^{{B^*}}$ and $\\mathbf{{T}}^{{*}}_{{B}} = -\\boldsymbol{{\\alpha}}^{{B}} \\cdot \\mathbf{{I}}^{{B}} - \\boldsymbol{{\\omega}}^{{B}} \\times \\mathbf{{I}}^{{B}} \\cdot \\boldsymbol{{\\omega}}^{{B}}$."),
        )
    } else {
        (
            format!("F_r = \\sum_{{{x}}} \\mathbf{{v}}^{{{x}}}_r \\cdot \\mathbf{{R}}_{{{x}}}, \\qquad F^{{*}}_r = \\sum_{{B}} \\mathbf{{v}}^{{B^*}}_r \\cdot \\mathbf{{R}}^{{*}}_{{B}},"),
            format!("with $\\mathbf{{R}}_{x}$ a force applied at the point ${x}$ and $\\mathbf{{R}}^{{*}}_{{B}} = -m_B\\,\\mathbf{{a}}^{{B^*}}$ the inertia force of particle $B$ (a particle has no inertia torque)."),
        )
    };
    Some(KaneTheory {
        forces_tex: Math::from(forces_tex),
        note: MarkupLine::from(note),
    })
}
