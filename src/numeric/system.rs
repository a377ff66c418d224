//! The interface between the equations of motion and the numerics of step 6.
//!
//! Whatever forms the equations (Newton-Euler, the Motion Law, Kane's method) implements
//! [`System`]; the integrator, the simulation and the confirmation checks see only this.

use super::friction::{Held, SiteState};
use super::SolveError;
use crate::symbolic::fixed;
use crate::symbolic::ComponentKind;
use std::fmt;

/// One reported reaction: a component of a site's force or moment along its frame's unit
/// vectors, or the force or torque that drives a prescribed coordinate. Written
/// `O.force.x`, `O.moment.z`, `q1.drive` in simulate's columns and the answers' keys.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ReactionColumn {
    /// The component along unit vector `axis` (0, 1, 2 for x, y, z) of the force or the
    /// moment of the joint or site named `site`.
    Component {
        /// The joint's or site's name.
        site: String,
        /// Force or moment.
        kind: ComponentKind,
        /// The unit vector's index: 0, 1, 2 for x, y, z.
        axis: usize,
    },
    /// The drive of the prescribed coordinate named `coordinate`.
    Drive {
        /// The prescribed coordinate's name.
        coordinate: String,
    },
}

impl ReactionColumn {
    /// The six components of `site`'s reaction: force x, y, z, then moment x, y, z.
    pub fn of_site(site: &str) -> impl Iterator<Item = ReactionColumn> + '_ {
        [ComponentKind::Force, ComponentKind::Moment]
            .into_iter()
            .flat_map(move |kind| {
                (0..3).map(move |axis| ReactionColumn::Component {
                    site: site.to_string(),
                    kind,
                    axis,
                })
            })
    }

    /// The site whose reaction this is, for a component.
    pub fn site(&self) -> Option<&str> {
        match self {
            ReactionColumn::Component { site, .. } => Some(site),
            ReactionColumn::Drive { .. } => None,
        }
    }

    /// Whether this is a moment component.
    pub fn is_moment(&self) -> bool {
        matches!(
            self,
            ReactionColumn::Component {
                kind: ComponentKind::Moment,
                ..
            }
        )
    }
}

impl fmt::Display for ReactionColumn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReactionColumn::Component { site, kind, axis } => {
                let kind = match kind {
                    ComponentKind::Force => "force",
                    ComponentKind::Moment => "moment",
                };
                let axis = ["x", "y", "z"].get(*axis).copied().unwrap_or("?");
                write!(f, "{site}.{kind}.{axis}")
            }
            ReactionColumn::Drive { coordinate } => write!(f, "{coordinate}.drive"),
        }
    }
}

/// One evaluation of the equations of motion at a state.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation {
    /// The second derivatives q'', one per coordinate, in [`System::coordinate_names`] order
    /// (m/s² or rad/s²).
    pub accelerations: Vec<f64>,
    /// The reaction components, one per [`System::reaction_columns`] entry, in that order
    /// (N or N·m).
    pub reactions: Vec<f64>,
    /// The kinetic energy of all bodies (J).
    pub kinetic: f64,
    /// The potential energy (J), with any reference: the simulation reports it relative to
    /// the initial configuration.
    pub potential: f64,
}

/// A system of equations of motion that can be evaluated at any state.
pub trait System {
    /// The coordinate names, in the order the contract uses: as first named by the joints.
    fn coordinate_names(&self) -> Vec<String>;

    /// The names of the reaction components reported by [`System::evaluate`], e.g.
    /// `O.force.x`, `O.force.y`, `O.force.z`, `O.moment.x`, `O.moment.y`, `O.moment.z`.
    fn reaction_columns(&self) -> Vec<ReactionColumn>;

    /// The accelerations, reactions and energies at time `t` (s), coordinates `q` and
    /// rates `rates` (both in [`System::coordinate_names`] order).
    ///
    /// # Errors
    /// [`SolveError::SingularSystem`] when the equations cannot be solved there, or
    /// [`SolveError::NotFinite`]; the error's `state` should come from `describe_state`.
    fn evaluate(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError>;

    /// Only the accelerations, for the integrator, which calls this six times a step and
    /// needs nothing else. By default the accelerations of [`System::evaluate`]; a system
    /// that can skip the energies and reactions should.
    ///
    /// # Errors
    /// As for [`System::evaluate`].
    fn accelerations(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Vec<f64>, SolveError> {
        self.evaluate(t, q, rates).map(|e| e.accelerations)
    }

    /// Makes a state meet the constraints: prescribed coordinates from their motion at `t`,
    /// dependent coordinates and rates solved from the others. Unconstrained: nothing.
    ///
    /// # Errors
    /// [`SolveError::Assembly`] when the constraints cannot be met.
    fn assemble(&self, _t: f64, _q: &mut [f64], _rates: &mut [f64]) -> Result<(), SolveError> {
        Ok(())
    }

    /// The largest residual of the constraints at a state (0 without constraints).
    fn drift(&self, _t: f64, _q: &[f64], _rates: &[f64]) -> f64 {
        0.0
    }

    /// Whether the system has constraints to assemble.
    fn is_constrained(&self) -> bool {
        false
    }

    /// The kinetic and the potential energy alone (J), without solving the equations of
    /// motion: the small-oscillation check builds its reference from them. By default
    /// those of [`System::evaluate`]; a system that can compute them apart should, so that
    /// they stay independent of the equations.
    ///
    /// # Errors
    /// As for [`System::evaluate`].
    fn energies(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<(f64, f64), SolveError> {
        self.evaluate(t, q, rates).map(|e| (e.kinetic, e.potential))
    }

    /// True when total energy is conserved: no dampers, no actuators, no loads that depend
    /// on time.
    fn is_conservative(&self) -> bool;

    /// True when the only non-conservative elements are dampers, so energy can only fall.
    fn has_dissipation_only(&self) -> bool;

    /// The names of the sites where Coulomb friction acts (none by default).
    fn friction_sites(&self) -> Vec<String> {
        Vec::new()
    }

    /// The accelerations with each friction site held as `held` (sticking, or sliding a
    /// given way), as a simulation holds them between switches. By default
    /// [`System::accelerations`].
    ///
    /// # Errors
    /// As for [`System::evaluate`].
    fn accelerations_held(
        &self,
        t: f64,
        q: &[f64],
        rates: &[f64],
        _held: &[Held],
    ) -> Result<Vec<f64>, SolveError> {
        self.accelerations(t, q, rates)
    }

    /// Each friction site at a state, held as `held` (decided by the check when `None`),
    /// with the values of the functions whose zeros are its switches (positive until then).
    ///
    /// # Errors
    /// As for [`System::evaluate`].
    fn friction_at(
        &self,
        _t: f64,
        _q: &[f64],
        _rates: &[f64],
        _held: Option<&[Held]>,
    ) -> Result<(Vec<SiteState>, Vec<f64>), SolveError> {
        Ok((Vec::new(), Vec::new()))
    }
}

/// A state in words for error messages: `t = 0.5, q1 = 0.3, q1' = -1.2`.
///
/// Numbers use [`fixed`], so messages are the same run to run. Names and values are paired
/// up to the shorter of the lists.
pub fn describe_state(t: f64, names: &[String], q: &[f64], rates: &[f64]) -> String {
    let mut text = format!("t = {}", fixed(t));
    for (name, value) in names.iter().zip(q) {
        text.push_str(&format!(", {name} = {}", fixed(*value)));
    }
    for (name, value) in names.iter().zip(rates) {
        text.push_str(&format!(", {name}' = {}", fixed(*value)));
    }
    text
}

#[cfg(test)]
mod tests {
    use super::describe_state;

    #[test]
    fn state_in_words() {
        let names = vec!["q1".to_string(), "x".to_string()];
        assert_eq!(
            describe_state(0.5, &names, &[0.3, 2.0], &[-1.2, 0.0]),
            "t = 0.5, q1 = 0.3, x = 2, q1' = -1.2, x' = 0"
        );
    }
}
