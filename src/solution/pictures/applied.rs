//! What the configuration shows beyond the bodies: the forces and couples the problem
//! applies, and the bodies each marked point belongs to.

use super::build::Setting;
use crate::plan::Source;
use crate::problem::{BodyId, LoadKind};
use crate::render::draw::{Arrow, Marker};

impl Setting<'_, '_, '_> {
    /// The forces the problem applies (a pull), as the statement's figure shows them: each
    /// once, on the body it acts on, the way it acts (a drive's couple is left to the free
    /// body, where it does not crowd the axle's names).
    pub(super) fn applied(&self, markers: &mut Vec<Marker>) -> Vec<Arrow> {
        let problem = self.problem();
        let mut seen = Vec::new();
        let mut out = Vec::new();
        for action in &self.derivation.actions {
            let Source::Load(i) = action.source else {
                continue;
            };
            let applied = matches!(problem.loads[i].kind, LoadKind::Force { .. });
            if applied && !seen.contains(&i) {
                seen.push(i);
                out.extend(self.action_arrows(action, markers));
            }
        }
        out
    }

    /// The names of `bodies`, `N` left out (it has no shape to keep out of).
    pub(super) fn names(&self, bodies: &[BodyId]) -> Vec<String> {
        (bodies.iter())
            .filter(|b| **b != BodyId::GROUND)
            .map(|b| self.problem().body_name(*b).to_string())
            .collect()
    }
}
