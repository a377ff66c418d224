//! What the constraints of a model are, once built: rows at the position, velocity and
//! acceleration levels, each with the unknown that enforces it, and the friction sites'
//! rows that hold only while they stick. Built in [`super::constraints`].

use super::error::MechanicsError;
use crate::problem::{CoordinateKind, Problem};
use crate::symbolic::{latex_name, time_derivative, Expr, Relation, Symbol, Unknown};

/// What imposes a constraint row.
#[derive(Clone, Debug, PartialEq)]
pub enum RowOrigin {
    /// A reaction component of a closure or contact site.
    Site {
        /// Index into `Model::sites`.
        site: usize,
        /// Index into the site's reactions.
        component: usize,
    },
    /// A `position` entry, by index into `Problem::constraints`.
    Position(usize),
    /// A `velocity` entry.
    Velocity(usize),
    /// A prescribed coordinate, by coordinate index.
    Prescribed(usize),
}

/// One scalar constraint.
#[derive(Clone, Debug)]
pub struct ConstraintRow {
    /// What imposes it.
    pub origin: RowOrigin,
    /// A name for messages, e.g. `R.Fx`, `roll.Fz`, `rod`.
    pub name: String,
    /// The position-level expression of a holonomic row (zero when met).
    pub position: Option<Expr>,
    /// The velocity-level expression, affine in the rates (zero when met).
    pub velocity: Expr,
    /// The unknown that enforces it.
    pub unknown: Symbol,
    /// For a closure that holds its point (revolute, spherical, universal, weld), the
    /// acceleration loop's component, (a^{R_C} − a^{R_B}) · d, as a textbook writes the
    /// row: equal to the derivative of `velocity` wherever the loop is closed, which the
    /// assembly keeps it to 1e-13.
    pub loop_acceleration: Option<Expr>,
}

impl ConstraintRow {
    /// The acceleration-level expression, linear in the q''.
    ///
    /// # Errors
    /// When the expression cannot be differentiated.
    pub fn acceleration(&self) -> Result<Expr, MechanicsError> {
        if let Some(written) = &self.loop_acceleration {
            return Ok(written.clone());
        }
        time_derivative(&self.velocity).map_err(|e| MechanicsError {
            path: "constraints".into(),
            message: format!("{}: {e}", self.name),
            hint: None,
        })
    }
}

/// Every constraint of a model, with the coordinates and rates it makes dependent.
#[derive(Clone, Debug, Default)]
pub struct Constraints {
    /// The rows kept, in order: closures, contacts, entries, prescribed coordinates.
    pub rows: Vec<ConstraintRow>,
    /// Rows left out, each with why.
    pub dropped: Vec<(String, String)>,
    /// Coordinates solved from the position rows.
    pub dependent: Vec<usize>,
    /// Coordinates whose rates are solved from the velocity rows (the dependent ones first).
    pub dependent_rates: Vec<usize>,
    /// Prescribed coordinates.
    pub prescribed: Vec<usize>,
    /// What was chosen and why, for the user.
    pub notes: Vec<String>,
    /// The sites where Coulomb friction acts, each with the rows that hold while it
    /// sticks; those rows are not among `rows`, so the rates they tie stay independent.
    pub friction: Vec<FrictionSite>,
    /// Each rolling contact's name and the sine of the angle between its axle and the
    /// plane's normal, which must not vanish.
    pub tilts: Vec<(String, Expr)>,
    /// Each contact whose rows are written with a relation that holds on the motion (a
    /// gear's unit line of centres has unit length there), with the relation; the
    /// dependent speeds and Kane's rows are written with it too.
    pub relations: Vec<(String, Relation)>,
}

impl Constraints {
    /// Whether there is nothing to enforce.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }
}

/// A site where Coulomb friction acts.
#[derive(Clone, Debug)]
pub struct FrictionSite {
    /// The contact's name, which names the site everywhere (`find.reactions`, the JSON).
    pub name: String,
    /// Index into `Model::sites`.
    pub site: usize,
    /// The coefficient of friction μ, a scalar of constants.
    pub coefficient: Expr,
    /// The rows that hold while the site sticks: the slip velocity along each tangent is
    /// zero (one in 2D, two in 3D; one along a rough slider's axis). Each row's unknown is the friction force's component
    /// along that tangent, and its velocity expression is that slip velocity component.
    pub stick: Vec<ConstraintRow>,
    /// The normal force's unknowns: one along the plane's normal (or the line of centres);
    /// for a rough slider, its force components perpendicular to the axis (one in 2D, two
    /// in 3D, |N| then their root sum of squares).
    pub normal: Vec<Symbol>,
}

/// The symbol of the drive of prescribed coordinate `coordinate` (an index into
/// [`Problem::coordinates`]), written as the statement names it (`drive.symbol`), else as a
/// textbook does: τ for a torque (an angle's drive), F for a force (a distance's), with the
/// coordinate as subscript where several drives, or a constant, would share the letter.
pub fn drive_symbol(problem: &Problem, coordinate: usize) -> Symbol {
    let c = &problem.coordinates[coordinate];
    let letter = |c: &crate::problem::Coordinate| match c.kind {
        CoordinateKind::Angle => "\\tau",
        CoordinateKind::Distance => "F",
    };
    let tex = match &c.drive_symbol {
        Some(symbol) => latex_name(symbol),
        None => {
            let shared = problem
                .coordinates
                .iter()
                .filter(|d| d.motion.is_some() && d.drive_symbol.is_none())
                .filter(|d| letter(d) == letter(c))
                .count()
                > 1
                || problem
                    .constants
                    .iter()
                    .any(|k| latex_name(&k.name) == letter(c));
            match shared {
                true => format!("{}_{{{}}}", letter(c), latex_name(&c.name)),
                false => letter(c).to_string(),
            }
        }
    };
    Symbol::Unknown(Unknown::Drive {
        coordinate: c.name.as_str().into(),
        tex: tex.as_str().into(),
    })
}

/// The symbol of a `position` or `velocity` entry's multiplier.
pub fn multiplier_symbol(name: &str) -> Symbol {
    Symbol::Unknown(Unknown::Multiplier {
        constraint: name.into(),
    })
}
