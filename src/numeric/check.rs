//! What one confirmation check reports, and the tolerances the checks hold to; shared by
//! the trajectory checks and the constraint checks.

/// Largest energy error allowed, relative to the energy scale of the motion.
pub const ENERGY_TOLERANCE: f64 = 1e-6;
/// Largest difference allowed between two methods' q'', relative to max(1, |q''|).
pub const AGREEMENT_TOLERANCE: f64 = 1e-8;
/// Largest relative error allowed between the period the equations of motion give and the
/// one the energies give.
pub const PERIOD_TOLERANCE: f64 = 1e-4;

/// The outcome of one check.
#[derive(Clone, Debug, PartialEq)]
pub struct Check {
    /// What was checked, e.g. `energy conservation`.
    pub name: String,
    /// The measured error (dimensionless).
    pub value: f64,
    /// The largest error that passes.
    pub tolerance: f64,
    /// `value < tolerance`.
    pub passed: bool,
    /// One sentence with the numbers behind `value`, for the worked solution.
    pub detail: String,
}

impl Check {
    /// A check of `value` against `tolerance`: passed when below it.
    pub(crate) fn new(name: &str, value: f64, tolerance: f64, detail: String) -> Self {
        Check {
            name: name.into(),
            value,
            tolerance,
            passed: value < tolerance,
            detail,
        }
    }
}
