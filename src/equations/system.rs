//! What a derivation is and is asked for: the [`Method`], the [`Request`] ([`Rows`],
//! [`State`]s), and the [`Derivation`] with its symbolic linear system `A x = b`.

use super::method::Method;
use crate::mechanics::Form;
use crate::mechanics::{DependentSpeeds, KeptForces, Model};
use crate::plan::{Action, Rejected};
use crate::plan::{Equation, Inertia, LazyInertia};
use crate::problem::State;
use crate::symbolic::{Expr, Symbol};

/// The symbolic linear system `A x = b`.
#[derive(Clone, Debug)]
pub struct LinearSystem {
    /// The unknowns `x`: every q'', then reaction components.
    pub unknowns: Vec<Symbol>,
    /// Row-major coefficients.
    pub a: Vec<Vec<Expr>>,
    /// Right-hand sides.
    pub b: Vec<Expr>,
}

/// Everything one method derives for one problem.
#[derive(Debug)]
pub struct Derivation<'p> {
    /// The kinematics.
    pub model: Model<'p>,
    /// The method.
    pub method: Method,
    /// Every force and couple, reactions included.
    pub actions: Vec<Action>,
    /// The inertia forces and torques ([`Self::inertia`]), written when first read.
    pub(super) lazy_inertia: LazyInertia,
    /// The chosen rows; none where only the numbers were asked for and Kane's system was
    /// built by composite bodies alone ([`Rows::Compiled`], [`Rows::Fastest`]).
    pub rows: Vec<Equation>,
    /// The candidates rejected, with reasons (the Motion Law only).
    pub rejected: Vec<Rejected>,
    /// The assembled system.
    pub system: LinearSystem,
    /// The method whose equations `system` holds: `method`, or Kane's where Kane's system
    /// by composite bodies stands in for the numbers of another method ([`Rows::Fastest`]).
    pub system_method: Method,
    /// The same system with Kane's rows rebuilt by composite bodies, for evaluation (see
    /// `super::composite`): equal numbers, the mass matrix for n² work where `system`'s
    /// rows take n³, the rest for n where they take n². Only for Kane's method in
    /// [`Form::Numeric`], where it applies. Derivatives are taken of `system`: these rows
    /// nest named quantities through the whole tree, and a derivative multiplies a named
    /// quantity out.
    pub composite_system: Option<LinearSystem>,
    /// Joints whose reactions are unknowns of the system.
    pub reaction_joints: Vec<usize>,
    /// Kane's method on a constrained system: the independent speeds and `u_D = C u_I`
    /// its rows are formed with. `None` for the other methods, an unconstrained system, or
    /// one whose dependent speeds are too long to write (its rows then keep the
    /// constraint forces as unknowns).
    pub dependent_speeds: Option<DependentSpeeds>,
    /// Kane's method on a constrained system whose rows keep the constraint forces as
    /// unknowns: why the independent speeds are not taken alone.
    pub kept_forces: Option<KeptForces>,
    /// Lagrange's equations in the worked solution's form: each coordinate's derivatives
    /// of the energies as the rows were formed from them, for step 5 to show without
    /// differentiating again. Empty for the other methods and for the numbers.
    pub lagrange_terms: Vec<super::lagrange::CoordinateTerms>,
}

impl Derivation<'_> {
    /// The inertia forces and torques of step 2.
    pub fn inertia(&self) -> &Inertia {
        self.lazy_inertia.get(&self.model)
    }
}

/// What a derivation is for: the form its expressions take, which rows it forms, and the
/// states where the Motion Law's plan must be nonsingular where a plan can be (the other
/// methods have no choice to make).
#[derive(Clone, Copy, Debug)]
pub struct Request<'s> {
    /// For numbers or for the worked solution.
    pub form: Form,
    /// Which rows to form.
    pub rows: Rows,
    /// The states the plan must be nonsingular at.
    pub states: &'s [State],
}

/// Which rows a derivation forms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rows {
    /// Every row the method writes, for the worked solution and for comparisons.
    Formed,
    /// Only what is compiled for numbers: where Kane's system by composite bodies is the
    /// one compiled (a tree large enough, see [`super::composite::SMALL_PROGRAM`]), it is
    /// built directly and Kane's rows are never formed; the derivation's `rows` are then
    /// empty and its `system` is the composite one.
    Compiled,
    /// As `Compiled`, with Kane's system by composite bodies standing in for the rows of
    /// any method where it is built alone: an unconstrained tree large enough (see
    /// `super::composite::system_alone`). The q'' and the reactions are the method's own
    /// to rounding, and the composite system costs n² where the Motion Law's and
    /// Newton–Euler's rows cost n³ or more. The derivation keeps `method`; its
    /// `system_method` says whose equations its system holds.
    Fastest,
}
