//! The impact's section of the worked solution, as the templates read it.

use super::text::Math;
use serde::Serialize;

/// The impact, after step 5: its sentences, each with its math.
#[derive(Clone, Debug, Default, Serialize)]
pub struct ImpactSection {
    /// In order: what the method's rows become, the rows, the collision's law, the rates,
    /// the impulses, the energy.
    pub steps: Vec<ImpactStep>,
}

/// One sentence of the impact's section.
#[derive(Clone, Debug, Default, Serialize)]
pub struct ImpactStep {
    /// Plain text.
    pub text: String,
    /// LaTeX math without `$`, inline after the text (a row's heading); empty for none.
    pub heading_tex: Math,
    /// LaTeX math without `$`, shown on its own line; empty for none.
    pub math_tex: Math,
}
