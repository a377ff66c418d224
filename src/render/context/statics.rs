//! The worked solution of a problem at rest (`explain --statics`): what steps 4 to 6 say
//! in place of the kinematics, the equations of motion and the simulation.

use crate::render::text::{MarkupLine, Math};
use serde::Serialize;

/// The statics of a worked solution: the equilibrium, what holds it there and whether it
/// is stable.
#[derive(Clone, Debug, Default, Serialize)]
pub struct StaticsView {
    /// Step 1: the configuration sought, in words (markup).
    pub sought: MarkupLine,
    /// Step 4: why only positions are needed (markup).
    pub kinematics_note: MarkupLine,
    /// Step 5: how the equilibrium configuration was found (markup).
    pub found: MarkupLine,
    /// Step 5: the equilibrium configuration, one coordinate each, e.g. `\theta = 0.4363\ \mathrm{rad}`.
    pub state_tex: Vec<Math>,
    /// Step 5: the generalized force each held coordinate's support supplies, e.g.
    /// `Q_{\phi} = 12.3\ \mathrm{N\,m}`.
    pub held_tex: Vec<Math>,
    /// Step 5: each friction site at rest.
    pub friction: Vec<StaticFriction>,
    /// Step 5: the stability of the equilibrium, in words (markup; empty when every
    /// coordinate is held or prescribed).
    pub stability: MarkupLine,
    /// Step 5: the eigenvalues of the linearization it is judged by, e.g. `\pm 3.1\,i`.
    pub eigenvalues_tex: Vec<Math>,
    /// Step 6: the system stays at rest (markup).
    pub rest_note: MarkupLine,
}

/// One friction site at rest: the forces friction and the normal carry, and whether
/// friction can supply what rest needs.
#[derive(Clone, Debug, Default, Serialize)]
pub struct StaticFriction {
    /// The site's name.
    pub site: String,
    /// The normal force |N|, formatted.
    pub normal: String,
    /// The friction force |F|, formatted.
    pub tangential: String,
    /// |F|/(μ|N|), formatted, or `—` where μ|N| is zero.
    pub ratio: String,
    /// What the ratio decides, in words: `holds` or `slips`.
    pub verdict: String,
}
