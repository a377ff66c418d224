//! Confirmation checks for constrained systems: the constraints still hold along the
//! simulated motion, and the energy changes by exactly the work the drives do.

use super::check::{Check, CheckKind, ENERGY_TOLERANCE};
use super::simulate::Trajectory;
use super::system::{ReactionColumn, System};
use super::work_along::{work_along, Imbalance};
use crate::problem::{LoadKind, Problem};
use crate::symbolic::fixed;

/// Largest constraint residual allowed along a simulation (metres, radians, m/s, rad/s).
pub const DRIFT_TOLERANCE: f64 = 1e-8;

/// The largest residual of the position and velocity constraints over the output rows.
pub fn drift_check(system: &dyn System, trajectory: &Trajectory) -> Option<Check> {
    if !system.is_constrained() {
        return None;
    }
    let n = trajectory.coordinates;
    let (mut worst, mut at) = (0.0f64, 0.0);
    for row in &trajectory.rows {
        let drift = system.drift(row[0], &row[1..=n], &row[n + 1..=2 * n]);
        if drift.is_nan() || drift > worst {
            (worst, at) = (drift, row[0]);
        }
    }
    Some(Check::new(
        CheckKind::ConstraintDrift,
        worst,
        DRIFT_TOLERANCE,
        format!(
            "the largest residual of the constraints is {} (at t = {} s); the dependent coordinates and rates are solved from the independent ones at every step",
            fixed(worst),
            fixed(at)
        ),
    ))
}

/// The most a rough contact's normal force may pull, over the largest normal force of the
/// run, and still count as pressing: rounding at a contact that carries nothing.
pub const PULL_TOLERANCE: f64 = 1e-9;

/// Whether every rough contact presses on its surface along the run. The model holds a
/// contact on its surface whatever the sign of its normal force (the constraint is
/// two-sided); a real ladder leaves the wall where its normal force would turn to a pull,
/// and the motion after that instant is not the ladder's. `None` without rough contacts
/// (a rough slider may be pushed either way: it is left out).
pub fn contact_check(
    problem: &Problem,
    system: &dyn System,
    trajectory: &Trajectory,
) -> Option<Check> {
    let sites = system.friction_sites();
    let contacts: Vec<usize> = (0..sites.len())
        .filter(|&i| problem.constraints.iter().any(|c| c.name == sites[i]))
        .collect();
    if contacts.is_empty() {
        return None;
    }
    let n = trajectory.coordinates;
    let (mut largest, mut least) = (0.0f64, (f64::INFINITY, 0.0, String::new()));
    // The first instant a contact's force turns to a pull, between two rows.
    let mut previous: Vec<Option<(f64, f64)>> = vec![None; contacts.len()];
    let mut first_pull: Option<(f64, String)> = None;
    for row in &trajectory.rows {
        let (q, rates) = (&row[1..=n], &row[n + 1..=2 * n]);
        let Ok((states, _)) = system.friction_at(row[0], q, rates, None) else {
            continue;
        };
        for (k, &i) in contacts.iter().enumerate() {
            let normal = states[i].normal;
            largest = largest.max(normal.abs());
            if normal < least.0 {
                least = (normal, row[0], states[i].name.clone());
            }
            if let (Some((t0, n0)), None) = (previous[k], &first_pull) {
                if n0 >= 0.0 && normal < 0.0 {
                    let at = t0 + (row[0] - t0) * n0 / (n0 - normal);
                    first_pull = Some((at, states[i].name.clone()));
                }
            }
            previous[k] = Some((row[0], normal));
        }
    }
    let (normal, at, site) = least;
    let value = (-normal / largest.max(f64::MIN_POSITIVE)).max(0.0);
    let detail = if value < PULL_TOLERANCE {
        format!(
            "the least normal force at a rough contact is {} N ({site}, at t = {} s): every contact presses on its surface throughout",
            fixed(normal),
            fixed(at)
        )
    } else {
        let turns = match &first_pull {
            Some((when, site)) => format!(
                "the normal force at {site} turns to a pull at t ≈ {} s (between output rows)",
                fixed(*when)
            ),
            None => format!("the normal force at {site} pulls from the start"),
        };
        format!(
            "{turns}, down to {} N (at {site}, t = {} s): a real contact leaves its surface there, which the model, holding the contact whatever its force, does not; the motion from that instant on is not the real one",
            fixed(normal),
            fixed(at)
        )
    };
    Some(Check::new(
        CheckKind::ContactsPress,
        value,
        PULL_TOLERANCE,
        detail,
    ))
}

/// With prescribed coordinates and otherwise conservative loads: the total energy changes
/// by the work of the drives, `∫ Σ Q q' dt`.
///
/// The work is integrated between output rows by three-point Gauss–Legendre, the state at
/// each node interpolated from the rows' q, q' and q'' (quintic Hermite) and the drives
/// evaluated there: a rule on the output rows alone (Simpson's) is off by parts in 10⁵ when
/// the drive turns fast against the output step, which would fail a correct motion.
pub fn drive_energy_check(
    problem: &Problem,
    system: &dyn System,
    trajectory: &Trajectory,
) -> Option<Check> {
    let prescribed: Vec<&str> = problem
        .coordinates
        .iter()
        .filter(|c| c.motion.is_some())
        .map(|c| c.name.as_str())
        .collect();
    let conservative = problem.loads.iter().all(|l| {
        matches!(
            l.kind,
            LoadKind::Spring { .. } | LoadKind::JointSpring { .. }
        )
    });
    if prescribed.is_empty() || !conservative {
        return None;
    }
    let reactions = system.reaction_columns();
    let names = system.coordinate_names();
    // (the drive's index among the reactions, its coordinate's index)
    let drives: Vec<(usize, usize)> = prescribed
        .iter()
        .map(|name| {
            let drive = ReactionColumn::Drive {
                coordinate: name.to_string(),
            };
            Some((
                reactions.iter().position(|r| *r == drive)?,
                names.iter().position(|q| q == name)?,
            ))
        })
        .collect::<Option<_>>()?;
    let n = trajectory.coordinates;
    let columns: Vec<[usize; 3]> = (0..n).map(|k| [1 + k, 1 + n + k, 1 + 2 * n + k]).collect();
    let work = work_along(&trajectory.rows, &columns, |t, state| {
        let (mut q, mut rates): (Vec<f64>, Vec<f64>) = state.iter().copied().unzip();
        system.assemble(t, &mut q, &mut rates).ok()?;
        let evaluation = system.evaluate(t, &q, &rates).ok()?;
        Some(
            drives
                .iter()
                .map(|&(r, c)| evaluation.reactions[r] * rates[c])
                .sum(),
        )
    })?;
    let Imbalance { worst, at, scale } = Imbalance::of(trajectory, &work)?;
    Some(Check::new(
        CheckKind::EnergyBalanceWithDrives,
        worst / scale,
        ENERGY_TOLERANCE,
        format!(
            "the total energy differs from its initial value plus the drives' work by at most {} J (at t = {} s) on an energy scale of {} J",
            fixed(worst),
            fixed(at),
            fixed(scale)
        ),
    ))
}
