//! Simulating with Coulomb friction: each friction site is held sticking or sliding over a
//! stretch of the motion, and the stretch ends where that stops being true (a slip velocity
//! falls to zero, or the friction that sticking needs reaches μ|N|), located on the
//! integrator's dense output. There the site is decided again as a textbook does (assume
//! sticking, check, else slide) and the integration goes on from that instant.

use super::super::friction::{Held, Mode};
use super::super::integrate::{integrate_until, Options, Solution, Stats};
use super::super::system::System;
use super::super::SolveError;

/// The most switches one run may make: more means the sites chatter between sticking and
/// sliding, which a Coulomb model cannot resolve.
const MOST_SWITCHES: usize = 10_000;

/// A change of a friction site's mode during a simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct Switch {
    /// The instant (s).
    pub t: f64,
    /// The site's name.
    pub site: String,
    /// The mode before.
    pub from: Mode,
    /// The mode after.
    pub to: Mode,
}

impl Switch {
    /// A friction site's switch in words: `t = 0.2912 s: contact lane stops slipping (rolls)`,
    /// `slider slope` for a rough prismatic joint or closure.
    pub fn describe(&self, problem: &crate::problem::Problem) -> String {
        let rolls = problem.constraints.iter().any(|c| {
            c.name == self.site
                && matches!(
                    c.kind,
                    crate::problem::ConstraintKind::Rolling { .. }
                        | crate::problem::ConstraintKind::Gear { .. }
                )
        });
        let what = match (self.from, self.to) {
            (Mode::Slip, Mode::Stick) if rolls => "stops slipping (rolls)",
            (Mode::Slip, Mode::Stick) => "stops slipping (sticks)",
            (Mode::Stick, Mode::Slip) => "starts to slip",
            (Mode::Slip, Mode::Slip) => "stops, and slips the other way",
            (Mode::Stick, Mode::Stick) => "sticks again",
        };
        // A rough prismatic joint or closure is a slider, the rest contacts.
        let slider = problem
            .joints
            .iter()
            .chain(&problem.closures)
            .any(|j| j.name == self.site && j.friction.is_some());
        let kind = if slider { "slider" } else { "contact" };
        // Ten significant digits: the instant is located to the integration tolerance.
        let t: f64 = format!("{:.9e}", self.t).parse().unwrap_or(self.t);
        format!("t = {t} s: {kind} {} {what}", self.site)
    }
}

/// The derivative `dy` at `(t, y)`, each friction site held as `held`.
pub type HeldDerivative<'a> =
    dyn FnMut(f64, &[f64], &mut [f64], &[Held]) -> Result<(), SolveError> + 'a;

/// A state made to meet the constraints at `t` (the dependent coordinates and rates
/// assembled from the others).
pub type Settle<'a> = dyn Fn(f64, &[f64]) -> Result<Vec<f64>, SolveError> + 'a;

/// Integrates from `(0, y0)` through `times` as [`integrate_until`] does, stretch by
/// stretch between the instants a friction site of `system` switches; `settle` makes a
/// state meet the constraints (it assembles the dependent coordinates and rates).
pub fn integrate(
    system: &dyn System,
    derivative: &mut HeldDerivative,
    settle: &Settle,
    y0: &[f64],
    times: &[f64],
    options: &Options,
) -> (Solution<SolveError>, Vec<Switch>) {
    let n = y0.len() / 2;
    let sites = system.friction_sites();
    let mut whole = Solution {
        times: Vec::new(),
        states: Vec::new(),
        event: None,
        stop: None,
        stats: Stats::default(),
    };
    let mut switches = Vec::new();
    let friction_at = |t: f64, y: &[f64], held: Option<&[Held]>| {
        let y = settle(t, y)?;
        system.friction_at(t, &y[..n], &y[n..], held)
    };
    let (mut t, mut y) = (0.0, y0.to_vec());
    let mut held: Vec<Held> = match friction_at(t, &y, None) {
        Ok((states, _)) => states.iter().map(|s| s.held()).collect(),
        Err(e) => {
            whole.stop = Some(super::super::integrate::Stop::Derivative(e));
            return (whole, switches);
        }
    };
    loop {
        let outputs: Vec<f64> = times
            .iter()
            .copied()
            .filter(|&at| at > t || (at == t && whole.times.is_empty()))
            .collect();
        if outputs.is_empty() {
            return (whole, switches);
        }
        let current = held.clone();
        let stretch = integrate_until(
            |t, y: &[f64], dy: &mut [f64]| derivative(t, y, dy, &current),
            |t, y: &[f64]| friction_at(t, y, Some(&current)).map_or_else(|_| Vec::new(), |r| r.1),
            t,
            &y,
            &outputs,
            options,
        );
        whole.times.extend(stretch.times);
        whole.states.extend(stretch.states);
        whole.stats.accepted += stretch.stats.accepted;
        whole.stats.rejected += stretch.stats.rejected;
        whole.stats.evaluations += stretch.stats.evaluations;
        if stretch.stop.is_some() {
            whole.stop = stretch.stop;
            return (whole, switches);
        }
        let Some(event) = stretch.event else {
            return (whole, switches);
        };
        if switches.len() >= MOST_SWITCHES {
            whole.stop = Some(super::super::integrate::Stop::Derivative(
                SolveError::BadSimulation {
                    what: format!(
                        "friction switched between sticking and sliding {MOST_SWITCHES} times by t = {}: the sites chatter",
                        event.t
                    ),
                },
            ));
            return (whole, switches);
        }
        (t, y) = (event.t, event.y);
        for &i in &event.which {
            let mut trial = held.clone();
            let from = match held[i] {
                Held::Slip(_) => Mode::Slip,
                _ => Mode::Stick,
            };
            // A slip that stops is decided by the check; a stick whose friction reached
            // μ|N| slides along the force it needed.
            if from == Mode::Slip {
                trial[i] = Held::Decide;
            }
            let decided = match friction_at(t, &y, Some(&trial)) {
                Ok((states, _)) => match (from, &states[i]) {
                    (Mode::Stick, state) => {
                        let force = state.friction();
                        Held::Slip(
                            state
                                .tangential
                                .iter()
                                .map(|f| f / force.max(f64::MIN_POSITIVE))
                                .collect(),
                        )
                    }
                    (Mode::Slip, state) => state.held(),
                },
                Err(e) => {
                    whole.stop = Some(super::super::integrate::Stop::Derivative(e));
                    return (whole, switches);
                }
            };
            let to = match decided {
                Held::Slip(_) => Mode::Slip,
                _ => Mode::Stick,
            };
            held[i] = decided;
            switches.push(Switch {
                t,
                site: sites.get(i).cloned().unwrap_or_default(),
                from,
                to,
            });
        }
    }
}
