//! Step 5 of the worked solution as plain data: each equation as formed and simplified,
//! Kane's partial velocities and dependent speeds, the matrix form, the values at the start,
//! friction and the reactions.

use super::named::Named;
use crate::render::text::{MarkupLine, Math};
use serde::Serialize;

/// One scalar equation of motion (or of a reaction).
#[derive(Clone, Debug, Default, Serialize)]
pub struct Equation {
    /// Where it comes from: the free body, the sum and its direction, e.g.
    /// `A + B\colon \sum \mathbf{M}_{O} \cdot \hat{\mathbf{n}}_{z}`, or Kane's `r` and speed.
    pub label_tex: Math,
    /// Plain words after it, e.g. `(an auxiliary speed, as in row 3)`; may be empty.
    pub label: String,
    /// Kane's row of an auxiliary speed: its augmented velocities, their partial
    /// velocities and which forces drop out; Lagrange's row of a joint let give way: its
    /// auxiliary coordinate; in markup (empty otherwise).
    pub augmented_note: MarkupLine,
    /// The equation as formed, forces grouped, e.g. `\hat{\mathbf{n}}_{z} \cdot (…) = 0`.
    pub grouped_tex: Math,
    /// The Motion Law's inertia terms written out before the simplified form: each body's
    /// cross product and inertia torque, or `m a*` dotted term by term (an `aligned`
    /// display; empty otherwise).
    pub written_tex: Math,
    /// The same equation simplified, `… = 0`; when that is too long to read, the same
    /// with the coefficients of the matrix form by name, `A_{1,1} \ddot{q}_{1} + … = b_{1}`.
    pub simplified_tex: Math,
    /// What introduces the simplified equation when it is not `Simplified:` (plain text;
    /// may be empty).
    pub simplified_note: String,
    /// The row as formed is already in its simplest form: written once, with no words
    /// before it (neither `Simplified:` nor a note).
    pub bare: bool,
    /// The simplified equation is written with the names of A's and b's entries, which the
    /// matrix form then lists.
    pub by_name: bool,
    /// Kane's rows: the generalized active force, e.g. `F_{1} = -m g L \sin(q_{1})`
    /// (empty for the other methods; then `grouped_tex` shows the row as formed).
    pub active_tex: Math,
    /// Kane's rows: the generalized inertia force, e.g. `F^{*}_{1} = -m L^{2} \ddot{q}_{1}`.
    pub inertia_tex: Math,
    /// Lagrange's row of a coordinate: ∂L/∂q̇_r, its time derivative, ∂L/∂q_r and Q_r, one
    /// equation each, before the collected equation (empty for the other methods).
    pub lagrange_tex: Vec<Math>,
    /// Kane's row of an auxiliary speed that holds one reaction: solved for it,
    /// `T^{O} = …` (empty otherwise).
    pub solved_tex: Math,
}

/// One line of Kane's table of partial velocities: a generalized speed and a body.
#[derive(Clone, Debug, Default, Serialize)]
pub struct PartialVelocity {
    /// The speed's index `r`, 1-based.
    pub r: usize,
    /// The speed, e.g. `u_{1} = \dot{q}_{1}`, on the first line of each speed; empty on
    /// the others.
    pub speed_tex: Math,
    /// The body's name.
    pub body: String,
    /// The partial velocity of its mass centre, e.g.
    /// `{}^{N}\mathbf{v}^{A^*}_{1} = \frac{L}{2} \hat{\mathbf{a}}_{y}`.
    pub velocity_tex: Math,
    /// Its partial angular velocity, e.g. `{}^{N}\boldsymbol{\omega}^{A}_{1} = \hat{\mathbf{n}}_{z}`.
    pub omega_tex: Math,
    /// A point's line (a rough contact point), which has no angular velocity to give.
    pub point: bool,
}

/// Kane's method as step 5 states it once: the generalized active and inertia forces, with
/// only the terms that apply to the problem.
#[derive(Clone, Debug, Default, Serialize)]
pub struct KaneTheory {
    /// `F_r = …, F^*_r = …`, display math.
    pub forces_tex: Math,
    /// What each symbol of `forces_tex` is, in markup.
    pub note: MarkupLine,
    /// A mass centre's partial velocity defined, `v^{B*}_r = ∂v^{B*}/∂u_r`, with the
    /// formula's body letter.
    pub velocity_partial_tex: Math,
    /// A body's partial angular velocity defined likewise.
    pub omega_partial_tex: Math,
    /// `F_r = …` alone, for a system at rest (inline math, ending in a comma).
    pub active_tex: Math,
    /// What its symbols are, in markup, without a closing full stop.
    pub active_note: MarkupLine,
}

/// The dependent rates as a linear map of the independent ones at the initial state, and
/// Kane's equations with dependent speeds.
#[derive(Clone, Debug, Default, Serialize)]
pub struct DependentSpeeds {
    /// `q'_D = C q'_U (+ …)` at the initial state, with `C` in numbers.
    pub relation_tex: Math,
    /// The same, one equation per dependent rate, `\dot{x} = -0.3 \dot{\theta}_{R}`.
    pub relations_tex: Vec<Math>,
    /// Kane's equations for the independent speeds, the constraint forces eliminated.
    pub kane_tex: Math,
    /// The reduced partial velocities of the mass centres at the initial state, one per
    /// body and independent speed, in `N`'s unit vectors.
    pub reduced_tex: Vec<Math>,
    /// Kane's method with independent speeds (empty otherwise): what the speeds are and
    /// why, before `relation_tex`, in markup.
    pub kane_speeds_notes: Vec<MarkupLine>,
    /// After the rows: which forces dropped out and why, the auxiliary speeds, and the
    /// order of the solve, in markup.
    pub kane_solve_notes: Vec<MarkupLine>,
    /// Kane's rows with the constraint forces kept: why, in markup (empty otherwise).
    pub kane_kept_note: MarkupLine,
    /// Some motion is prescribed (a driven coordinate, or a constraint written with `t`):
    /// the dependent rates then have terms in time besides the map.
    pub time_terms: bool,
    /// Where `relations_tex` hold in general (written in symbols): each dependent rate's
    /// value at the initial state, `\dot{y} = 0`; empty where they are numbers at it.
    pub start_tex: Vec<Math>,
}

/// The equations as `A x = b`.
#[derive(Clone, Debug, Default, Serialize)]
pub struct MatrixForm {
    /// The whole matrices, when there are at most four unknowns.
    pub whole: Option<WholeMatrix>,
    /// The nonzero entries one by one, when there are more.
    pub entries: Vec<MatrixEntry>,
    /// For a system too large to print every entry as a formula, `A` and `b` at the initial
    /// state as tables of numbers (`array`s), in blocks of columns when the system is wide,
    /// `b` in the last; empty otherwise.
    pub value_tables_tex: Vec<Math>,
    /// With the tables of values, what each kind of entry is, so that every value can be
    /// traced.
    pub rules: Vec<Named>,
    /// For a large system whose rows step 5 writes out, all or most: where `A` and `b` are
    /// not zero, as tables of dots (`array`s) in blocks; the entries are read off step 5,
    /// but for the few rows it writes by their coefficients' names (too long to print),
    /// whose values at the initial state are in `entries`. Empty otherwise.
    pub pattern_tex: Vec<Math>,
    /// The unknowns by column, where the entries name them `x_{j}`: `x_{1} = \ddot{q}_{1}`.
    pub columns_tex: Vec<Math>,
    /// The rows listed entry by entry leave out those step 5 writes out in full, to be
    /// read off there: their numbers, `(1)--(9), (24)` (empty when none is left out).
    pub read_off_tex: Math,
}

/// `A`, `x` and `b` as `bmatrix` environments.
#[derive(Clone, Debug, Default, Serialize)]
pub struct WholeMatrix {
    /// The coefficient matrix.
    pub a_tex: Math,
    /// The unknowns, a column.
    pub x_tex: Math,
    /// The right-hand side, a column.
    pub b_tex: Math,
    /// `A` and `b` as one table: a column per unknown, headed by it, then `b`; a row per
    /// equation, led by its number in step 5 and what it sums, e.g. `(1)\; A{+}B\colon
    /// \sum \mathbf{M}_{O} \cdot \hat{\mathbf{n}}_{z}`.
    pub table_tex: Math,
}

/// One entry of `A` or `b`.
#[derive(Clone, Debug, Default, Serialize)]
pub struct MatrixEntry {
    /// The row, 1-based.
    pub row: usize,
    /// The column, 1-based; `b` for the right-hand side.
    pub column: String,
    /// The entry, e.g. `A_{12} = \frac{m L^{2}}{2} \cos(q_{2})`.
    pub value_tex: Math,
    /// On the first entry of each row, the row's equation as in [`WholeMatrix::table_tex`];
    /// empty on the others.
    pub row_label_tex: Math,
    /// The column's unknown, e.g. `\ddot{q}_{2}`, or `\mathbf{b}`.
    pub column_tex: Math,
    /// A whole row's entries, printed one after the other (a system too large to print an
    /// entry a line); empty otherwise.
    pub values_tex: Vec<Math>,
}

/// Step 5's system at the initial state with its numbers, and its solution.
#[derive(Clone, Debug, Default, Serialize)]
pub struct InNumbers {
    /// What is solved, in markup (empty when there is no such system).
    pub lead: MarkupLine,
    /// The system `A x = b` with its numbers, beside its solution `x` where both fit the
    /// line.
    pub displays_tex: Vec<Math>,
    /// The solution where it is not beside the system, each unknown a row holds alone in
    /// symbols and then its number, and the reactions the other rows give, in markup.
    pub closed_forms: Vec<MarkupLine>,
    /// Whether the solution gives every coordinate's second derivative (the table of them
    /// at the initial state would repeat it).
    #[serde(skip)]
    pub gives_accelerations: bool,
    /// Whether the rows without a reaction are solved first and the others after them, as
    /// the lead and the sentence after the system say.
    #[serde(skip)]
    pub in_order: bool,
}

/// A number at the initial state.
#[derive(Clone, Debug, Default, Serialize)]
pub struct InitialValue {
    /// What it is, e.g. `\ddot{q}_{1}`.
    pub name_tex: Math,
    /// Its value, formatted.
    pub value: String,
    /// Its unit in LaTeX (may be empty), e.g. `\\mathrm{rad/s^{2}}`.
    pub unit_tex: Math,
}

/// A friction site at the initial state: the textbook's process, step by step.
#[derive(Clone, Debug, Default, Serialize)]
pub struct FrictionView {
    /// The site's name (user text).
    pub site: String,
    /// μ, formatted.
    pub coefficient: String,
    /// The sentences, each with its display math.
    pub steps: Vec<FrictionStep>,
}

/// One sentence of a friction site's process, and the math it leads to (may be empty).
#[derive(Clone, Debug, Default, Serialize)]
pub struct FrictionStep {
    /// Plain text.
    pub text: String,
    /// LaTeX math without `$`, shown on its own line; empty for none.
    pub math_tex: Math,
}

/// The reaction at one joint, at the initial state.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Reaction {
    /// The joint's name.
    pub joint: String,
    /// The force on the child, in the parent's unit vectors, formatted, e.g. `(1.2, 19.6, 0) N`;
    /// shown when `force_tex` is empty.
    pub force: String,
    /// The moment about the joint point, likewise.
    pub moment: String,
    /// The force as a vector with its unit, e.g.
    /// `\left(1.2 \hat{\mathbf{n}}_{x} + 19.6 \hat{\mathbf{n}}_{y}\right) \mathrm{N}`.
    pub force_tex: Math,
    /// The moment as a vector with its unit.
    pub moment_tex: Math,
}
