//! Confirmation checks on a solution (step 6): energy, agreement between methods, and the
//! period of small oscillations against the one the energies give.

mod oscillation;

pub use super::check::{Check, CheckKind, Phrase, AGREEMENT_TOLERANCE, ENERGY_TOLERANCE};
#[cfg(test)]
pub use oscillation::downward_crossings;
pub use oscillation::{modes, small_oscillation};

use super::simulate::Trajectory;
use super::system::System;
use crate::problem::Problem;
use crate::symbolic::fixed;

/// Every confirmation check that applies to a run of `primary` (its method's name and its
/// equations) on `problem`: energy, agreement with `others` (the other three methods, each with
/// its equations or why they could not be had) at 10 rows, the small-oscillation period,
/// and with constraints their drift and the drives' energy balance. Checks that do not
/// apply (energy with actuators, the period without a stable equilibrium) are left out; a
/// method whose equations cannot be had is a failed agreement, never left out.
pub fn confirm(
    problem: &Problem,
    primary: (&str, &dyn System),
    others: &[(&str, Derived)],
    trajectory: &Trajectory,
    q0: &[f64],
) -> Vec<Check> {
    let mut checks = confirm_systems(primary, others, trajectory, q0);
    checks.extend(super::constraint_checks::drive_energy_check(
        problem, primary.1, trajectory,
    ));
    checks.extend(super::load_work::load_work_check(problem, trajectory));
    checks.extend(super::constraint_checks::drift_check(primary.1, trajectory));
    checks.extend(super::constraint_checks::contact_check(
        problem, primary.1, trajectory,
    ));
    checks
}

/// Another method's equations for the checks, or why they could not be derived (the
/// derivation's own error, written into the agreement check as it reads).
pub type Derived<'a> = Result<&'a dyn System, &'a dyn std::fmt::Display>;

/// [`confirm`] on systems already at hand: `primary` is the one that was simulated, `others`
/// the other methods, each with its equations or why they could not be had. A method in
/// `others` that is an `Err` makes the agreement check fail, with its reason.
pub fn confirm_systems(
    primary: (&str, &dyn System),
    others: &[(&str, Derived)],
    trajectory: &Trajectory,
    q0: &[f64],
) -> Vec<Check> {
    let mut systems = vec![primary];
    let mut missing = Vec::new();
    for (name, system) in others {
        match system {
            Ok(system) => systems.push((name, *system)),
            Err(reason) => missing.push(format!(
                "the equations of {name} could not be derived: {reason}"
            )),
        }
    }
    let mut agreement = method_agreement(&systems, trajectory, 10);
    if !missing.is_empty() {
        let mut phrases = vec![Phrase::text(missing.join("; "))];
        if let Some(check) = &agreement {
            phrases.push(Phrase::text("; among the others, "));
            phrases.extend(check.phrases.iter().cloned());
        }
        agreement = Some(Check::phrased(
            CheckKind::MethodAgreement,
            f64::INFINITY,
            AGREEMENT_TOLERANCE,
            phrases,
        ));
    }
    [
        energy_check(primary.1, trajectory),
        agreement,
        // Linearizing about the rest state ignores constraints: open chains only.
        if primary.1.is_constrained() {
            None
        } else {
            small_oscillation(primary.1, q0)
        },
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// Energy over the run: conserved when `system` is conservative (max |E(t) − E(0)| over the
/// energy scale), never rising when it only dissipates (the largest rise above the lowest
/// energy so far, over the scale). The scale is the larger of max |kinetic| and the range
/// of the potential.
///
/// `None` when the system can gain energy (actuators, loads in time) or there are no rows.
pub fn energy_check(system: &dyn System, trajectory: &Trajectory) -> Option<Check> {
    let conservative = system.is_conservative();
    if !conservative && !system.has_dissipation_only() {
        return None;
    }
    let kinetic = trajectory.column("kinetic")?;
    let potential = trajectory.column("potential")?;
    let total = trajectory.column("total")?;
    let rows = &trajectory.rows;
    let first = rows.first()?;
    let largest_kinetic = rows.iter().map(|r| r[kinetic].abs()).fold(0.0, f64::max);
    let (low, high) = rows
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), r| {
            (lo.min(r[potential]), hi.max(r[potential]))
        });
    let scale = largest_kinetic.max(high - low).max(f64::MIN_POSITIVE);
    if conservative {
        let (worst, at) = rows
            .iter()
            .map(|r| ((r[total] - first[total]).abs(), r[0]))
            .fold((0.0, 0.0), |best, x| if x.0 > best.0 { x } else { best });
        let value = worst / scale;
        let detail = format!(
            "the total energy changes by at most {} J (at t = {} s) on an energy scale of {} J (the larger of the largest kinetic energy and the range of the potential energy)",
            fixed(worst),
            fixed(at),
            fixed(scale)
        );
        Some(Check::new(
            CheckKind::EnergyConservation,
            value,
            ENERGY_TOLERANCE,
            detail,
        ))
    } else {
        let mut lowest = first[total];
        let (mut worst, mut at) = (0.0, 0.0);
        for row in rows {
            lowest = lowest.min(row[total]);
            if row[total] - lowest > worst {
                (worst, at) = (row[total] - lowest, row[0]);
            }
        }
        // Coulomb friction, like a damper, only takes energy away. Without friction the
        // only elements that are not conservative are dampers; with it, dampers may or may
        // not be there, so only friction is named.
        let who = if system.friction_sites().is_empty() {
            "the dampers only remove"
        } else {
            "sliding friction only removes"
        };
        let detail = format!(
            "{who} energy: it rises by at most {} J (at t = {} s) on an energy scale of {} J",
            fixed(worst),
            fixed(at),
            fixed(scale)
        );
        Some(Check::new(
            CheckKind::EnergyNeverRises,
            worst / scale,
            ENERGY_TOLERANCE,
            detail,
        ))
    }
}

/// The methods' q'' compared at `samples` rows spread evenly over `trajectory`: the largest
/// |a − b| / max(1, |a|) between the first system and each of the others.
///
/// `None` with fewer than two systems or no rows.
pub fn method_agreement(
    systems: &[(&str, &dyn System)],
    trajectory: &Trajectory,
    samples: usize,
) -> Option<Check> {
    let ((reference_name, reference), others) = systems.split_first()?;
    let rows = &trajectory.rows;
    if others.is_empty() || rows.is_empty() {
        return None;
    }
    let names = reference.coordinate_names();
    let n = names.len();
    let fail = |detail: String| {
        Some(Check::new(
            CheckKind::MethodAgreement,
            f64::INFINITY,
            AGREEMENT_TOLERANCE,
            detail,
        ))
    };
    if let Some((other, _)) = others.iter().find(|(_, s)| s.coordinate_names() != names) {
        return fail(format!(
            "the equations of {other} use other coordinates than those of {reference_name}"
        ));
    }
    let count = samples.clamp(1, rows.len());
    let mut indices: Vec<usize> = (0..count)
        .map(|i| i * (rows.len() - 1) / (count - 1).max(1))
        .collect();
    indices.dedup();
    let mut worst: (f64, Vec<Phrase>) = (0.0, Vec::new());
    for &index in &indices {
        let row = &rows[index];
        let (t, q, rates) = (row[0], &row[1..=n], &row[n + 1..=2 * n]);
        let expected = match reference.evaluate(t, q, rates) {
            Ok(e) => e.accelerations,
            Err(e) => return fail(format!("the equations of {reference_name} failed: {e}")),
        };
        for (other_name, other) in others {
            let got = match other.evaluate(t, q, rates) {
                Ok(e) => e.accelerations,
                Err(e) => return fail(format!("the equations of {other_name} failed: {e}")),
            };
            for ((name, a), b) in names.iter().zip(&expected).zip(&got) {
                let difference = (a - b).abs() / a.abs().max(1.0);
                if difference > worst.0 || difference.is_nan() {
                    let where_ = vec![
                        Phrase::coordinate(name, 2),
                        Phrase::text(format!(
                            " from {other_name} ({}) and {reference_name} ({}) at t = {} s",
                            fixed(*b),
                            fixed(*a),
                            fixed(t)
                        )),
                    ];
                    worst = (difference, where_);
                }
            }
        }
    }
    let phrases = match worst.1.is_empty() {
        true => vec![Phrase::text(format!(
            "the second derivatives of every method are identical at {} states along the run",
            indices.len()
        ))],
        false => std::iter::once(Phrase::text(format!(
            "the other methods' equations (derived as well, not shown here) evaluated at {} states along the run; the largest difference is in ",
            indices.len(),
        )))
        .chain(worst.1)
        .collect(),
    };
    Some(Check::phrased(
        CheckKind::MethodAgreement,
        worst.0,
        AGREEMENT_TOLERANCE,
        phrases,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numeric::simulate::test_systems::{MassSpringDamper, Pendulum, TwoOscillators};
    use crate::numeric::simulate::{simulate, Trajectory};
    use crate::problem::SimulateSettings;

    fn run(system: &dyn System, q0: f64, rate0: f64) -> Trajectory {
        let settings = SimulateSettings {
            duration: 5.0,
            output_step: 0.01,
            tolerance: 1e-9,
        };
        let trajectory = simulate(system, &[q0], &[rate0], &settings).unwrap();
        assert!(trajectory.stopped.is_none());
        trajectory
    }

    #[test]
    fn energy_is_conserved_by_a_correct_pendulum() {
        let pendulum = Pendulum::new(0.5, 9.81);
        let check = energy_check(&pendulum, &run(&pendulum, 1.2, 0.0)).unwrap();
        assert_eq!(check.kind, CheckKind::EnergyConservation);
        assert!(check.passed, "{check:?}");
        assert!(check.value < 1e-7, "{check:?}");
    }

    /// Kinetic energy m l² θ'² instead of half that: the check must notice.
    #[test]
    fn energy_check_catches_a_wrong_kinetic_energy() {
        let wrong = Pendulum {
            kinetic_factor: 1.0,
            ..Pendulum::new(0.5, 9.81)
        };
        let check = energy_check(&wrong, &run(&wrong, 1.2, 0.0)).unwrap();
        assert!(!check.passed, "{check:?}");
        assert!(check.value > 0.1, "{check:?}");
    }

    #[test]
    fn damped_energy_never_rises() {
        let damped = MassSpringDamper {
            m: 1.0,
            c: 0.3,
            k: 20.0,
        };
        let trajectory = run(&damped, 0.2, 0.0);
        let check = energy_check(&damped, &trajectory).unwrap();
        assert_eq!(check.kind, CheckKind::EnergyNeverRises);
        assert!(check.passed, "{check:?}");
        // The same rows with energy added halfway: a damped system cannot do that.
        let mut pumped = trajectory.clone();
        let total = pumped.column("total").unwrap();
        for row in pumped.rows.iter_mut().skip(250) {
            row[total] += 0.05;
        }
        assert!(!energy_check(&damped, &pumped).unwrap().passed);
        // Gaining energy is allowed for neither kind of check to apply.
        let pumping = MassSpringDamper {
            m: 1.0,
            c: -0.3,
            k: 20.0,
        };
        assert!(energy_check(&pumping, &trajectory).is_none());
    }

    #[test]
    fn methods_agree_or_the_difference_is_named() {
        let a = Pendulum::new(0.5, 9.81);
        let b = Pendulum::new(0.5, 9.81);
        let off = Pendulum::new(0.5, 9.80);
        let trajectory = run(&a, 1.0, 0.5);
        let same = method_agreement(&[("motion-law", &a), ("kane", &b)], &trajectory, 10).unwrap();
        assert!(same.passed && same.value == 0.0, "{same:?}");
        let different =
            method_agreement(&[("motion-law", &a), ("kane", &off)], &trajectory, 10).unwrap();
        assert!(!different.passed, "{different:?}");
        // |Δθ''| = 0.01/0.5 |sin θ| at most 0.02 |sin θ| over max(1, |θ''|).
        assert!(
            different.value > 1e-3 && different.value < 0.02,
            "{different:?}"
        );
        assert!(
            different.detail().contains("theta''"),
            "{}",
            different.detail()
        );
        let other = method_agreement(
            &[("motion-law", &a), ("kane", &TwoOscillators)],
            &trajectory,
            10,
        )
        .unwrap();
        assert!(!other.passed);
        assert!(method_agreement(&[("motion-law", &a)], &trajectory, 10).is_none());
    }

    /// A method whose equations cannot be derived is a failed agreement with its reason,
    /// not a check quietly left out.
    #[test]
    fn a_method_that_fails_is_reported_not_dropped() {
        let a = Pendulum::new(0.5, 9.81);
        let b = Pendulum::new(0.5, 9.81);
        let trajectory = run(&a, 1.0, 0.5);
        let reason = "the planner found 1 independent equations for 2 unknowns".to_string();
        let checks = confirm_systems(
            ("motion-law", &a),
            &[("newton-euler", Ok(&b)), ("kane", Err(&reason))],
            &trajectory,
            &[1.0],
        );
        let names: Vec<&str> = checks.iter().map(|c| c.name()).collect();
        assert_eq!(
            names,
            [
                "energy conservation",
                "agreement between methods",
                "small-oscillation period"
            ]
        );
        let agreement = &checks[1];
        assert!(!agreement.passed, "{agreement:?}");
        assert!(
            agreement.detail().starts_with(&format!(
                "the equations of kane could not be derived: {reason}"
            )),
            "{}",
            agreement.detail()
        );
        assert!(
            agreement.detail().contains("identical"),
            "{}",
            agreement.detail()
        );
        // Every other method failing: still reported.
        let alone = confirm_systems(
            ("motion-law", &a),
            &[("kane", Err(&reason))],
            &trajectory,
            &[1.0],
        );
        assert!(alone
            .iter()
            .any(|c| c.kind == CheckKind::MethodAgreement && !c.passed));
        // And when they all derive, the agreement passes.
        let all = confirm_systems(
            ("motion-law", &a),
            &[("newton-euler", Ok(&b)), ("kane", Ok(&b))],
            &trajectory,
            &[1.0],
        );
        assert!(all.iter().all(|c| c.passed), "{all:?}");
    }
}
