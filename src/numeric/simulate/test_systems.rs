//! Small systems with hand-written equations, for the tests here and in `checks`.

use super::super::system::{describe_state, Evaluation, ReactionColumn, System};
use super::super::SolveError;

/// m x'' + c x' + k x = 0; the wall's force on the mass is the reaction `W.force.x`.
pub struct MassSpringDamper {
    pub m: f64,
    pub c: f64,
    pub k: f64,
}

impl System for MassSpringDamper {
    fn coordinate_names(&self) -> Vec<String> {
        vec!["x".into()]
    }
    fn reaction_columns(&self) -> Vec<ReactionColumn> {
        ReactionColumn::of_site("W").take(1).collect()
    }
    fn evaluate(&self, _: f64, q: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError> {
        let (x, v) = (q[0], rates[0]);
        Ok(Evaluation {
            accelerations: vec![-(self.c * v + self.k * x) / self.m],
            reactions: vec![-(self.c * v + self.k * x)],
            kinetic: 0.5 * self.m * v * v,
            potential: 0.5 * self.k * x * x,
        })
    }
    fn is_conservative(&self) -> bool {
        self.c == 0.0
    }
    fn has_dissipation_only(&self) -> bool {
        self.c > 0.0
    }
}

/// A point mass m on a massless rod of length l from the pivot O; `theta` from the
/// downward vertical; N's x to the right and y up. `kinetic_factor` is 0.5 for the true
/// kinetic energy and anything else for a deliberately wrong one.
pub struct Pendulum {
    pub m: f64,
    pub l: f64,
    pub g: f64,
    pub kinetic_factor: f64,
}

impl Pendulum {
    pub fn new(l: f64, g: f64) -> Self {
        Pendulum {
            m: 2.0,
            l,
            g,
            kinetic_factor: 0.5,
        }
    }
}

impl System for Pendulum {
    fn coordinate_names(&self) -> Vec<String> {
        vec!["theta".into()]
    }
    fn reaction_columns(&self) -> Vec<ReactionColumn> {
        ReactionColumn::of_site("O").take(2).collect()
    }
    fn evaluate(&self, _: f64, q: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError> {
        let (theta, w) = (q[0], rates[0]);
        let (m, l, g) = (self.m, self.l, self.g);
        let alpha = -(g / l) * theta.sin();
        // r = l (sin, -cos): the rod force is m a - m g, with g pointing down.
        let ax = l * (alpha * theta.cos() - w * w * theta.sin());
        let ay = l * (alpha * theta.sin() + w * w * theta.cos());
        Ok(Evaluation {
            accelerations: vec![alpha],
            reactions: vec![m * ax, m * ay + m * g],
            kinetic: self.kinetic_factor * m * l * l * w * w,
            potential: -m * g * l * theta.cos(),
        })
    }
    fn is_conservative(&self) -> bool {
        true
    }
    fn has_dissipation_only(&self) -> bool {
        false
    }
}

/// Two uncoupled oscillators (for checks that need more than one coordinate).
pub struct TwoOscillators;

impl System for TwoOscillators {
    fn coordinate_names(&self) -> Vec<String> {
        vec!["a".into(), "b".into()]
    }
    fn reaction_columns(&self) -> Vec<ReactionColumn> {
        Vec::new()
    }
    fn evaluate(&self, _: f64, q: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError> {
        Ok(Evaluation {
            accelerations: vec![-q[0], -4.0 * q[1]],
            reactions: Vec::new(),
            kinetic: 0.5 * (rates[0] * rates[0] + rates[1] * rates[1]),
            potential: 0.5 * (q[0] * q[0] + 4.0 * q[1] * q[1]),
        })
    }
    fn is_conservative(&self) -> bool {
        true
    }
    fn has_dissipation_only(&self) -> bool {
        false
    }
}

/// x'' = 0, but the equations are singular once x passes `wall`.
pub struct SingularPast {
    pub wall: f64,
}

impl System for SingularPast {
    fn coordinate_names(&self) -> Vec<String> {
        vec!["x".into()]
    }
    fn reaction_columns(&self) -> Vec<ReactionColumn> {
        Vec::new()
    }
    fn evaluate(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError> {
        if q[0] > self.wall {
            let state = describe_state(t, &self.coordinate_names(), q, rates);
            return Err(SolveError::SingularSystem {
                state,
                detail: "x'' is undetermined".into(),
            });
        }
        Ok(Evaluation {
            accelerations: vec![0.0],
            reactions: Vec::new(),
            kinetic: 0.0,
            potential: 0.0,
        })
    }
    fn is_conservative(&self) -> bool {
        true
    }
    fn has_dissipation_only(&self) -> bool {
        false
    }
}
