//! What one confirmation check reports, and the tolerances the checks hold to; shared by
//! the trajectory checks and the constraint checks.

/// Largest energy error allowed, relative to the energy scale of the motion.
pub const ENERGY_TOLERANCE: f64 = 1e-6;
/// Largest difference allowed between two methods' q'', relative to max(1, |q''|).
pub const AGREEMENT_TOLERANCE: f64 = 1e-8;
/// Largest relative error allowed between the period the equations of motion give and the
/// one the energies give.
pub const PERIOD_TOLERANCE: f64 = 1e-4;

/// What a check compares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CheckKind {
    /// The total energy of a conservative system stays what it was.
    EnergyConservation,
    /// With dampers or friction, the total energy never rises.
    EnergyNeverRises,
    /// Every method's q'' along the trajectory are the same.
    MethodAgreement,
    /// The period of small oscillations from the equations equals the energies' one.
    SmallOscillationPeriod,
    /// The constraints still hold along the trajectory.
    ConstraintDrift,
    /// With prescribed motion, the energy changes by the drives' work.
    EnergyBalanceWithDrives,
    /// With applied forces and couples, the energy changes by their work.
    EnergyBalanceWithLoads,
    /// Every rough contact's normal force presses (a contact is two-sided in the model,
    /// where a real one would separate).
    ContactsPress,
}

impl CheckKind {
    /// Its name in reports, e.g. `energy conservation`.
    pub fn name(self) -> &'static str {
        match self {
            CheckKind::EnergyConservation => "energy conservation",
            CheckKind::EnergyNeverRises => "energy never rises",
            CheckKind::MethodAgreement => "agreement between methods",
            CheckKind::SmallOscillationPeriod => "small-oscillation period",
            CheckKind::ConstraintDrift => "constraint drift",
            CheckKind::EnergyBalanceWithDrives => "energy balance with the drives' work",
            CheckKind::EnergyBalanceWithLoads => "energy balance with the applied loads' work",
            CheckKind::ContactsPress => "contacts press",
        }
    }
}

/// The outcome of one check.
#[derive(Clone, Debug, PartialEq)]
pub struct Check {
    /// What was checked.
    pub kind: CheckKind,
    /// The measured error (dimensionless).
    pub value: f64,
    /// The largest error that passes.
    pub tolerance: f64,
    /// `value < tolerance`.
    pub passed: bool,
    /// One sentence with the numbers behind `value`, in pieces: the worked solution writes
    /// the coordinates it names in its notation ([`Check::detail`] is the plain text).
    pub phrases: Vec<Phrase>,
}

/// A piece of a check's sentence.
#[derive(Clone, Debug, PartialEq)]
pub enum Phrase {
    /// Words and numbers.
    Text(String),
    /// A coordinate by its name, differentiated `order` times (`q1''` in plain text).
    Coordinate {
        /// The coordinate's name.
        name: String,
        /// How many times it is differentiated.
        order: usize,
    },
}

impl Phrase {
    /// Words.
    pub fn text(text: impl Into<String>) -> Phrase {
        Phrase::Text(text.into())
    }

    /// Coordinate `name` differentiated `order` times.
    pub fn coordinate(name: &str, order: usize) -> Phrase {
        Phrase::Coordinate {
            name: name.to_string(),
            order,
        }
    }

    /// As plain text: a coordinate as its name with a prime per derivative.
    pub fn plain(phrases: &[Phrase]) -> String {
        (phrases.iter())
            .map(|p| match p {
                Phrase::Text(text) => text.clone(),
                Phrase::Coordinate { name, order } => format!("{name}{}", "'".repeat(*order)),
            })
            .collect()
    }
}

impl Check {
    /// A check of `value` against `tolerance`: passed when below it.
    pub(crate) fn new(kind: CheckKind, value: f64, tolerance: f64, detail: String) -> Self {
        Check::phrased(kind, value, tolerance, vec![Phrase::Text(detail)])
    }

    /// As [`Check::new`], with a sentence that names coordinates.
    pub(crate) fn phrased(
        kind: CheckKind,
        value: f64,
        tolerance: f64,
        phrases: Vec<Phrase>,
    ) -> Self {
        Check {
            kind,
            value,
            tolerance,
            passed: value < tolerance,
            phrases,
        }
    }

    /// The sentence with the numbers behind `value`, as plain text (`q1''`).
    pub fn detail(&self) -> String {
        Phrase::plain(&self.phrases)
    }

    /// What was checked, e.g. `energy conservation`.
    pub fn name(&self) -> &'static str {
        self.kind.name()
    }
}
