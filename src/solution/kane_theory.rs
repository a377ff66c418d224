//! Kane's method said once, where step 5 first uses it, and only what applies to the
//! problem: the generalized active and inertia forces, with a body's inertia torque only
//! where some body has rotational inertia.

use crate::equations::{Derivation, Method};
use crate::mechanics::is_particle;
use crate::render::context::KaneTheory;
use crate::render::text::{MarkupLine, Math};

/// The definitions of `F_r` and `F^*_r` for Kane's handout (`None` for the other methods):
/// a problem of particles alone has no couples on bodies and no inertia torques, so their
/// terms are left out.
pub fn theory(derivation: &Derivation) -> Option<KaneTheory> {
    if derivation.method != Method::Kane {
        return None;
    }
    let model = &derivation.model;
    let rigid = model.order.iter().any(|&body| !is_particle(model, body));
    let (forces_tex, note) = if rigid {
        (
            "F_r = \\sum_{P} \\mathbf{v}^{P}_r \\cdot \\mathbf{R}_{P} + \\sum_{B} \\boldsymbol{\\omega}^{B}_r \\cdot \\mathbf{T}_{B}, \\qquad F^{*}_r = \\sum_{B} \\left(\\mathbf{v}^{B^*}_r \\cdot \\mathbf{R}^{*}_{B} + \\boldsymbol{\\omega}^{B}_r \\cdot \\mathbf{T}^{*}_{B}\\right),",
            "with $\\mathbf{R}_P$ a force applied at the point $P$, $\\mathbf{T}_B$ a couple on body $B$, $\\mathbf{R}^{*}_{B} = -m_B\\,\\mathbf{a}^{B^*}$ and $\\mathbf{T}^{*}_{B} = -\\boldsymbol{\\alpha}^{B} \\cdot \\mathbf{I}^{B} - \\boldsymbol{\\omega}^{B} \\times \\mathbf{I}^{B} \\cdot \\boldsymbol{\\omega}^{B}$.",
        )
    } else {
        (
            "F_r = \\sum_{P} \\mathbf{v}^{P}_r \\cdot \\mathbf{R}_{P}, \\qquad F^{*}_r = \\sum_{B} \\mathbf{v}^{B^*}_r \\cdot \\mathbf{R}^{*}_{B},",
            "with $\\mathbf{R}_P$ a force applied at the point $P$ and $\\mathbf{R}^{*}_{B} = -m_B\\,\\mathbf{a}^{B^*}$ the inertia force of particle $B$ (a particle has no inertia torque).",
        )
    };
    Some(KaneTheory {
        forces_tex: Math::from(forces_tex.to_string()),
        note: MarkupLine::from(note.to_string()),
    })
}
