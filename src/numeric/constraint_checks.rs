//! Confirmation checks for constrained systems: the constraints still hold along the
//! simulated motion, and the energy changes by exactly the work the drives do.

use super::check::{Check, CheckKind, ENERGY_TOLERANCE};
use super::simulate::Trajectory;
use super::system::{ReactionColumn, System};
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
    let rows = &trajectory.rows;
    let total = trajectory.column("total")?;
    let kinetic = trajectory.column("kinetic")?;
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
    let power = |t: f64, mut q: Vec<f64>, mut rates: Vec<f64>| -> Option<f64> {
        system.assemble(t, &mut q, &mut rates).ok()?;
        let evaluation = system.evaluate(t, &q, &rates).ok()?;
        Some(
            drives
                .iter()
                .map(|&(r, c)| evaluation.reactions[r] * rates[c])
                .sum(),
        )
    };
    let n = trajectory.coordinates;
    let mut work = vec![0.0; rows.len()];
    for i in 1..rows.len() {
        let (before, after) = (&rows[i - 1], &rows[i]);
        let h = after[0] - before[0];
        let mut interval = 0.0;
        for (s, weight) in GAUSS_LEGENDRE_3 {
            let (q, rates): (Vec<f64>, Vec<f64>) = (0..n)
                .map(|k| {
                    let at = |row: &[f64]| [row[1 + k], row[1 + n + k], row[1 + 2 * n + k]];
                    hermite(at(before), at(after), h, s)
                })
                .unzip();
            interval += weight * power(before[0] + s * h, q, rates)?;
        }
        work[i] = work[i - 1] + h * interval;
    }
    let scale = rows
        .iter()
        .map(|r| r[kinetic].abs())
        .chain(work.iter().map(|w| w.abs()))
        .fold(0.0f64, f64::max)
        .max(f64::MIN_POSITIVE);
    let first = rows.first()?[total];
    let (mut worst, mut at) = (0.0f64, 0.0);
    for (row, w) in rows.iter().zip(&work) {
        let error = (row[total] - first - w).abs();
        if error > worst {
            (worst, at) = (error, row[0]);
        }
    }
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

/// Three-point Gauss–Legendre on [0, 1]: (node, weight), exact for polynomials of degree 5.
pub(super) const GAUSS_LEGENDRE_3: [(f64, f64); 3] = [
    (0.112_701_665_379_258_3, 5.0 / 18.0),
    (0.5, 8.0 / 18.0),
    (0.887_298_334_620_741_7, 5.0 / 18.0),
];

/// The quintic through a coordinate's `[q, q', q'']` at both ends of a step of `h` seconds,
/// at the fraction `s` of the step: its value and its rate.
pub(super) fn hermite(start: [f64; 3], end: [f64; 3], h: f64, s: f64) -> (f64, f64) {
    let (s2, s3, s4, s5) = (s * s, s * s * s, s.powi(4), s.powi(5));
    let value = [
        1.0 - 10.0 * s3 + 15.0 * s4 - 6.0 * s5,
        s - 6.0 * s3 + 8.0 * s4 - 3.0 * s5,
        0.5 * (s2 - 3.0 * s3 + 3.0 * s4 - s5),
        10.0 * s3 - 15.0 * s4 + 6.0 * s5,
        -4.0 * s3 + 7.0 * s4 - 3.0 * s5,
        0.5 * (s3 - 2.0 * s4 + s5),
    ];
    let slope = [
        -30.0 * s2 + 60.0 * s3 - 30.0 * s4,
        1.0 - 18.0 * s2 + 32.0 * s3 - 15.0 * s4,
        0.5 * (2.0 * s - 9.0 * s2 + 12.0 * s3 - 5.0 * s4),
        30.0 * s2 - 60.0 * s3 + 30.0 * s4,
        -12.0 * s2 + 28.0 * s3 - 15.0 * s4,
        0.5 * (3.0 * s2 - 8.0 * s3 + 5.0 * s4),
    ];
    let data = [
        start[0],
        h * start[1],
        h * h * start[2],
        end[0],
        h * end[1],
        h * h * end[2],
    ];
    let dot = |basis: [f64; 6]| basis.iter().zip(&data).map(|(b, d)| b * d).sum::<f64>();
    (dot(value), dot(slope) / h)
}

#[cfg(test)]
mod tests {
    use super::{hermite, GAUSS_LEGENDRE_3};

    #[test]
    fn the_quintic_through_the_ends_is_exact_for_a_quintic() {
        // p(t) = t^5 - 2 t^2 + 1 on [0.3, 0.8]
        let p = |t: f64| {
            [
                t.powi(5) - 2.0 * t * t + 1.0,
                5.0 * t.powi(4) - 4.0 * t,
                20.0 * t.powi(3) - 4.0,
            ]
        };
        let (t0, t1) = (0.3, 0.8);
        for s in [0.0, 0.25, 0.6, 1.0] {
            let t = t0 + s * (t1 - t0);
            let (value, rate) = hermite(p(t0), p(t1), t1 - t0, s);
            assert!((value - p(t)[0]).abs() < 1e-13, "value at {t}");
            assert!((rate - p(t)[1]).abs() < 1e-12, "rate at {t}");
        }
    }

    #[test]
    fn gauss_legendre_integrates_a_quintic_exactly() {
        // ∫₀¹ (6 s^5 + s^2) ds = 1 + 1/3
        let integral: f64 = GAUSS_LEGENDRE_3
            .iter()
            .map(|(s, w)| w * (6.0 * s.powi(5) + s * s))
            .sum();
        assert!((integral - 4.0 / 3.0).abs() < 1e-14);
    }
}
