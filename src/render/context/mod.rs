//! The worked solution as plain data: the Tera context of the templates.
//!
//! Everything is already a string, so the templates hold layout only. Each string is of a
//! kind of [`super::text`], and the renderer treats it by its kind:
//!
//! | type | holds | Markdown | LaTeX | HTML |
//! |---|---|---|---|---|
//! | [`Math`] | LaTeX math, without `$` | verbatim, inside `$…$` | verbatim | converted to MathML (use `\| safe`) |
//! | [`LatexCode`] | LaTeX code (a pgfplots or TikZ picture) | removed | verbatim | removed |
//! | [`SvgDocument`] | an SVG document | removed | removed | a `data:` URI for `<img src>` (use `\| safe`) |
//! | [`InlineSvg`] | an SVG element to inline | verbatim | removed | verbatim (use `\| safe`) |
//! | [`Markup`], [`MarkupLine`] | the problem's markup: paragraphs, lists, emphasis, `$…$` math (see `super::markup`) | Markdown, text escaped, math checked | LaTeX, the same | escaped HTML with MathML (use `\| safe`) |
//! | [`FileName`] | a file the Markdown links to | percent-encoded | as is | as is |
//! | `String` | plain text: user text, names, numbers | escaped | escaped | escaped by Tera |
//!
//! The fields keep the names the templates know them by (`…_tex` for math, `…_latex`,
//! `…_svg`), but the type, not the name, decides.
//!
//! So user text (titles, descriptions, the statement) is only ever a value in the context,
//! never part of a template's source, and can never be evaluated by Tera or by TeX.
//! Numbers are formatted before they get here, with [`crate::symbolic::fixed`].

use super::text::{FileName, InlineSvg, LatexCode, Markup, MarkupLine, Math, SvgDocument};
use serde::Serialize;

mod equations;
mod lagrange;
mod named;
mod statics;

pub use super::figure::Figure;
pub use super::sample::sample;
pub use equations::{
    DependentSpeeds, Equation, FrictionStep, FrictionView, InNumbers, InitialValue, KaneTheory,
    MatrixEntry, MatrixForm, PartialVelocity, Reaction, WholeMatrix,
};
pub use lagrange::{GeneralizedForceRow, LagrangeView};
pub use named::{Named, WhereEntry};
pub use statics::{StaticFriction, StaticsView};

/// The worked solution of one problem by one method: the six steps.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Solution {
    /// The problem's title (user text, one line).
    pub title: String,
    /// The letter printed in math for each body and point named by a word,
    /// `(\mathrm{top}, B)`; applied to every string at rendering.
    #[serde(skip)]
    pub shown_names: Vec<(String, String)>,
    /// The problem as given to the student (user text in the small Markdown of
    /// `super::markup`: paragraphs, lists, emphasis, `$…$` math).
    pub statement: Option<Markup>,
    /// `planar` or `spatial`.
    pub dimension: String,
    /// The method's name as a sentence uses it, e.g. `the Motion Law`.
    pub method: String,
    /// True for the student handout (statement and blank tables); set by
    /// [`render`](super::render), not by the pipeline.
    pub student: bool,
    /// Step 1: one frame per body, `N` first.
    pub frames: Vec<Frame>,
    /// Step 1: the frames that do not spin, one per body spinning about its symmetry axis
    /// (Resal's frames), in which that body's kinematics and moments are written.
    pub spin_frames: Vec<SpinFrame>,
    /// Step 1: the generalized coordinates, in the order the joints name them.
    pub coordinates: Vec<Coordinate>,
    /// Step 1: the unit vectors along the joints' axes that step 3 sums along, e.g.
    /// `\hat{\mathbf{e}}_{\mathrm{slide}} = \hat{\mathbf{x}}_{\mathrm{rod}}`.
    pub axes: Vec<Named>,
    /// Step 1: the constants, in file order.
    pub constants: Vec<Constant>,
    /// Step 1: the declared generalized speeds and their kinematic differential equations
    /// (`None` when the speeds are the coordinates' rates).
    pub speeds: Option<SpeedsView>,
    /// Step 1: the constraints beyond the joints (loop closures, rolling, entries,
    /// prescribed motion), each as an equation.
    pub constraints: Vec<ConstraintView>,
    /// Step 1: which coordinates and rates the constraints solve for and why, and which
    /// constraints were left out.
    pub constraint_notes: Vec<MarkupLine>,
    /// Step 1: each closure's vector loop, segment by segment, and its time derivative, the
    /// velocity constraints (aligned displays).
    pub closure_loops: Vec<Math>,
    /// Step 1: each rolling contact's no-slip condition as a vector equation, the arm from
    /// the mass centre and the velocity of the body's point there (aligned displays).
    pub contact_loops: Vec<Math>,
    /// The words opening each of `contact_loops`: rolling without slipping, or a smooth
    /// contact that holds only the normal component (plain text).
    pub contact_leads: Vec<String>,
    /// Step 5: the solve said in words after the matrix form: what is solved first, and
    /// where the constraint rows' block is singular.
    pub solve_notes: Vec<MarkupLine>,
    /// The names of the system matrix, its right-hand side and the dependent rates' matrix,
    /// free of the problem's own names.
    pub matrix_names: MatrixLetters,
    /// Step 1: the picture of the system at the initial state (empty when not drawn).
    pub configuration: Figure,
    /// Step 2: the free bodies the planner uses.
    pub free_bodies: Vec<FreeBody>,
    /// Step 2: how the free-body pictures are drawn, said once where the pictures leave it
    /// out (LaTeX); empty when nothing is drawn.
    pub free_body_legend: String,
    /// Step 2: the quantities the forces are written with (a spring's length `ℓ₁`, its
    /// unit vector `û₁`, its rate `ℓ̇₁`), each defined once; the later steps use them too.
    pub force_definitions: Vec<WhereEntry>,
    /// Step 4: the abbreviations of sines and cosines that steps 4 and 5 use
    /// (`s_{1} = \sin(q_{1})`), each defined once.
    pub abbreviations: Vec<Named>,
    /// When the abbreviations are many, the letters of their sines and cosines (`s`, `c`, or
    /// `S`, `C` where the problem names a constant s or c), so that the handout states their
    /// rule and lists only `abbreviations`' few examples of it; else empty.
    pub abbreviations_by_rule: Vec<String>,
    /// Step 4: the named kinematic quantities that steps 4 and 5 use (the direction cosines
    /// of long chains, partial velocities, accelerations without the q''), each defined once.
    pub kinematic_definitions: Vec<WhereEntry>,
    /// Step 2 by Lagrange's equations: the energies, the generalized forces and the
    /// multipliers (`None` for the other methods).
    pub lagrange: Option<LagrangeView>,
    /// Step 3: the planner's table.
    pub plan: Plan,
    /// Step 4: angular velocity and acceleration of each body, velocity and acceleration of
    /// its mass center, all in N.
    pub kinematics: Vec<Kinematics>,
    /// Step 5 by Kane's method: the partial velocities of the mass centres and the partial
    /// angular velocities of the bodies, for each generalized speed (empty for the other
    /// methods).
    pub partial_velocities: Vec<PartialVelocity>,
    /// Step 5 by Kane's method: the generalized forces defined once (`None` for the other
    /// methods).
    pub kane_theory: Option<KaneTheory>,
    /// Step 5: each equation, as formed and as simplified.
    pub equations: Vec<Equation>,
    /// Step 5: how the dependent rates follow from the independent ones (constrained
    /// systems with velocity constraints only).
    pub dependent_speeds: Option<DependentSpeeds>,
    /// Step 5: the system in matrix form.
    pub matrix: MatrixForm,
    /// Step 5: the system with its numbers at the initial state and its solution, for a
    /// system of at most six unknowns (empty otherwise).
    pub in_numbers: InNumbers,
    /// Step 5: the second derivatives at the initial state.
    pub initial_values: Vec<InitialValue>,
    /// Step 5: the requested reactions at the initial state.
    pub reactions: Vec<Reaction>,
    /// Step 5: each friction site at the initial state, sticking or sliding, and why.
    pub friction: Vec<FrictionView>,
    /// The impact at the initial state, after step 5 (problems with `impact`).
    pub impact: Option<super::impact::ImpactSection>,
    /// Step 6: the simulation and its checks.
    pub simulation: Simulation,
    /// Small motions about a state (`explain --linearize`).
    pub linearization: Option<super::sections::LinearizationSection>,
    /// The answers to the problem's `find.questions` (blank in the student's handout).
    pub answers: Vec<super::sections::AnswerView>,
    /// The problem at rest (`explain --statics`): steps 4 to 6 say this in place of the
    /// kinematics, the equations of motion and the simulation.
    pub statics: Option<StaticsView>,
}

/// One constraint row as step 1 shows it.
#[derive(Clone, Debug, Default, Serialize)]
pub struct ConstraintView {
    /// What the row constrains, e.g. `\text{loop closure at R} \text{, along } \hat{\mathbf{b}}_{x}`
    /// (the direction of the reaction that enforces it) or `\text{prescribed motion of } q_{1}`.
    pub name_tex: Math,
    /// `position` (holonomic) or `velocity` (nonholonomic).
    pub level: String,
    /// The equation, `… = 0`.
    pub equation_tex: Math,
    /// Too long for the table's column: displayed below it at full width, the table
    /// pointing to it by number.
    pub below: bool,
}

/// A reference frame and its unit vectors.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Frame {
    /// The frame's name, e.g. `A`.
    pub name: String,
    /// Its unit vectors, e.g. `\hat{\mathbf{a}}_{x}, \hat{\mathbf{a}}_{y}, \hat{\mathbf{a}}_{z}`.
    pub frame_tex: Math,
    /// The body it is fixed in, e.g. `A` (`N` for the ground).
    pub fixed_in: String,
    /// The frame it is oriented relative to (empty for `N`).
    pub parent: String,
    /// Its orientation relative to `parent`, e.g. `\text{rotated by } q_{1} \text{ about } \hat{\mathbf{n}}_{z}`.
    pub orientation_tex: Math,
}

/// A frame that turns with a body but does not spin with it, and why it is used.
#[derive(Clone, Debug, Default, Serialize)]
pub struct SpinFrame {
    /// The frame, as a row of the frames' table (`parent` and `orientation_tex` as for a
    /// body's; `fixed_in` empty: it is fixed in no body).
    pub frame: Frame,
    /// The spinning body's name.
    pub body: String,
    /// Its symmetry axis, e.g. `\hat{\mathbf{z}}_{\mathrm{top}}`.
    pub axis_tex: Math,
    /// The spin angle, e.g. `\phi`.
    pub spin_tex: Math,
    /// Whether the frame is the parent's own (a revolute joint) rather than one added.
    pub parents: bool,
}

/// A generalized coordinate.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Coordinate {
    /// The coordinate as a symbol, e.g. `q_{1}`.
    pub name_tex: Math,
    /// Its rate, e.g. `\dot{q}_{1}`.
    pub rate_tex: Math,
    /// What it measures (user text; may be empty).
    pub description: MarkupLine,
    /// The joint that owns it in words, e.g. `the pinion turns on the ground at pin $O_{A}$`.
    pub joint: MarkupLine,
    /// Its unit in LaTeX, e.g. `\\mathrm{rad}` (see `units`).
    pub unit_tex: Math,
    /// Its initial value, formatted.
    pub initial: String,
    /// Its initial rate, formatted.
    pub initial_rate: String,
}

/// The declared generalized speeds.
#[derive(Clone, Debug, Default, Serialize)]
pub struct SpeedsView {
    /// One row per speed.
    pub rows: Vec<SpeedRow>,
    /// The kinematic differential equations `u = W(q) q'` as one matrix equation.
    pub matrix_tex: Math,
    /// Their inverse, one rate per line: `\dot{q}_s = Σ_r W⁻¹_{sr} u_r`.
    pub inverse_tex: Vec<Math>,
}

/// A declared generalized speed.
#[derive(Clone, Debug, Default, Serialize)]
pub struct SpeedRow {
    /// The speed as a symbol, e.g. `u_{1}`.
    pub name_tex: Math,
    /// Its definition, e.g. `u_{2} = \dot{q}_{1} + \dot{q}_{2}`.
    pub definition_tex: Math,
    /// Its unit in LaTeX (may be empty).
    pub unit_tex: Math,
    /// What it is (user text; may be empty).
    pub description: MarkupLine,
}

/// A constant of the problem.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Constant {
    /// The constant as a symbol, e.g. `L`.
    pub name_tex: Math,
    /// Its value (after `--set`), formatted.
    pub value: String,
    /// Its unit in LaTeX (may be empty).
    pub unit_tex: Math,
    /// What it is (user text; may be empty).
    pub description: MarkupLine,
}

/// One free body with its forces, sorted the way the Motion Law sorts them.
#[derive(Clone, Debug, Default, Serialize)]
pub struct FreeBody {
    /// Its name, e.g. `A` or `A+B`.
    pub name: String,
    /// Its name in LaTeX, e.g. `A + B`, `\mathrm{link}_{1}`.
    pub name_tex: Math,
    /// The bodies it contains, e.g. `A, B`.
    pub bodies: String,
    /// Contact forces: reactions, springs, applied loads, joint loads.
    pub contact: Vec<Force>,
    /// Distance forces: gravity.
    pub distance: Vec<Force>,
    /// Inertia forces and couples: `-m a` and `-(I·α + ω×I·ω)`.
    pub inertia: Vec<Force>,
    /// Its free-body diagram with the kinetic diagram (empty when not drawn).
    pub figure: Figure,
}

/// One force or couple on a free body.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Force {
    /// What it is, e.g. `reaction force at $O_{A}$` or the load's name, as markup: a
    /// point's symbol set as math, as the equations set it.
    pub label: MarkupLine,
    /// The vector, e.g. `F^{O}_{x} \hat{\mathbf{n}}_{x} + F^{O}_{y} \hat{\mathbf{n}}_{y}`.
    pub vector_tex: Math,
    /// Where it acts, or for a couple empty, e.g. `A^{*}`.
    pub point_tex: Math,
}

/// Step 3: which equation each free body gives, and what it leaves unknown.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Plan {
    /// The equations used, in order.
    pub rows: Vec<PlanRow>,
    /// Candidate equations considered and not used: the few worth showing, or every one
    /// after [`Plan::show_every_rejected`].
    pub rejected: Vec<Rejected>,
    /// How many candidates were considered and not used in all.
    pub rejected_total: usize,
    /// Every candidate considered and not used (`explain --verbose` shows them).
    #[serde(skip)]
    pub rejected_all: Vec<Rejected>,
    /// How many equations the rows give.
    pub equations_count: usize,
    /// How many unknowns they contain.
    pub unknowns_count: usize,
    /// A sentence about the count, and what the unknowns are (markup; may be empty).
    pub note: MarkupLine,
    /// The widths of the table's columns in LaTeX.
    pub columns: PlanColumns,
    /// Whether some row names a direction: Kane's rows alone name none, and the table
    /// then has no direction column.
    pub directions: bool,
}

/// The widths of step 3's table in centimetres, each column as wide as what it prints and
/// the unknowns the rest, so that a long list of unknowns takes one line where it can.
#[derive(Clone, Debug, Default, Serialize)]
pub struct PlanColumns {
    /// The free-body column.
    pub free_body_cm: f64,
    /// The equation column (the sum).
    pub equation_cm: f64,
    /// The direction column.
    pub direction_cm: f64,
    /// The unknowns' column: what the others leave of the line.
    pub unknowns_cm: f64,
}

/// One equation of the plan.
#[derive(Clone, Debug, Default, Serialize)]
pub struct PlanRow {
    /// The free body in LaTeX, e.g. `A + B` (empty for a constraint row).
    pub free_body_tex: Math,
    /// The equation, e.g. `\sum \mathbf{M}_{O}`.
    pub equation_tex: Math,
    /// Its direction, e.g. `\hat{\mathbf{n}}_{z}`.
    pub direction_tex: Math,
    /// The unknowns it contains, e.g. `\ddot{q}_{1}, \ddot{q}_{2}`.
    pub unknowns_tex: Math,
}

/// A candidate equation the planner rejected.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Rejected {
    /// The free body in LaTeX, e.g. `A + B` (empty for a constraint row).
    pub free_body_tex: Math,
    /// The equation, e.g. `\sum \mathbf{F}`.
    pub equation_tex: Math,
    /// Its direction.
    pub direction_tex: Math,
    /// Why it was not used (plain text), e.g. `brings in the reaction at P`.
    pub reason: String,
    /// The reaction components it names, if any, e.g. `F^{P}_{x}, F^{P}_{y}`.
    pub reason_tex: Math,
    /// Plain text after them, e.g. `, which is not asked for`.
    pub reason_after: String,
}

impl Plan {
    /// Shows every rejected candidate instead of the few worth showing.
    pub fn show_every_rejected(&mut self) {
        self.rejected = self.rejected_all.clone();
    }
}

/// Step 4 for one body.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Kinematics {
    /// The body's name.
    pub body: String,
    /// Whether it is a particle (mass, no central inertia): headed so, not as a body,
    /// and given no angular velocity or acceleration.
    pub particle: bool,
    /// Whether it is massless (a light link or slider): headed "Light body".
    pub light: bool,
    /// Its mass centre's place from the pin that holds it, e.g.
    /// `\mathbf{r}^{O A^*} = -\frac{L}{2} \hat{\mathbf{a}}_{y}` (empty without one).
    pub position_tex: Math,
    /// Its angular velocity in N, e.g. `{}^{N}\boldsymbol{\omega}^{A} = \dot{q}_{1} \hat{\mathbf{n}}_{z}`.
    pub omega_tex: Math,
    /// Its angular acceleration in N.
    pub alpha_tex: Math,
    /// The velocity of the pin that holds it to a moving parent, in N (empty without one).
    pub pin_velocity_tex: Math,
    /// The acceleration of that pin in N (empty when it shares the velocity's display).
    pub pin_acceleration_tex: Math,
    /// The velocity of its mass center in N.
    pub velocity_tex: Math,
    /// The acceleration of its mass center in N.
    pub acceleration_tex: Math,
}

/// Step 6: the simulation that confirms the equations.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Simulation {
    /// How the equations are integrated: the state, the start, the time, the step (markup).
    pub settings: MarkupLine,
    /// The checks.
    pub checks: Vec<Check>,
    /// The plots.
    pub plots: Vec<Plot>,
    /// How many plots share a row of the page: four when there are four (each narrower),
    /// else three.
    pub plots_in_row: usize,
    /// A sentence about the outcome (plain text; may be empty).
    pub note: String,
    /// The motion as an animated SVG element, for the HTML page (empty otherwise).
    pub motion_svg_inline: InlineSvg,
    /// The motion's length in seconds, and where the plots' time axis runs (fractions of
    /// their width), for the page's slider and the plots' markers.
    pub motion_duration: f64,
    /// See `motion_duration`.
    pub time_axis: [f64; 2],
}

/// One confirmation check.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Check {
    /// What is checked, e.g. `energy drift`.
    pub name: String,
    /// The measured value, formatted.
    pub value: String,
    /// The tolerance it is held to, formatted, e.g. `< 1e-6`.
    pub tolerance: String,
    /// Whether it passed.
    pub passed: bool,
    /// What was compared with what, with the numbers behind the value.
    pub detail: MarkupLine,
}

/// One plot, as an SVG file (Markdown, HTML) and as a pgfplots picture (LaTeX).
#[derive(Clone, Debug, Default, Serialize)]
pub struct Plot {
    /// Which plot, used in file names: `coordinates` or `energy`.
    pub kind: String,
    /// The caption (plain text).
    pub title: String,
    /// The SVG file name the Markdown refers to, relative to the output, e.g.
    /// `pendulum-energy.svg`; empty when no file is written (output to standard output).
    pub svg_file: FileName,
    /// The SVG document, inlined into HTML.
    pub image_svg: SvgDocument,
    /// A `tikzpicture` with a pgfplots `axis`, for LaTeX.
    pub image_latex: LatexCode,
    /// What is plotted, from which the renderer draws [`Plot::image_svg`] and
    /// [`Plot::image_latex`] for the format asked ([`crate::render::plots_drawn::draw`]).
    #[serde(skip)]
    pub data: Option<crate::render::plot::PlotData>,
}

/// The letters the handout names its matrices by: the system matrix `a`, its right-hand
/// side `b` and the dependent rates' matrix `c`, chosen by the solution free of the
/// problem's own names.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct MatrixLetters {
    /// The system matrix.
    pub a: String,
    /// The right-hand side.
    pub b: String,
    /// The matrix of the dependent rates.
    pub c: String,
    /// The column of unknowns of `A x = b`.
    pub x: String,
    /// The state of the small motions, `ż = A z`.
    pub z: String,
}

impl Default for MatrixLetters {
    fn default() -> Self {
        MatrixLetters {
            a: "A".into(),
            b: "b".into(),
            c: "C".into(),
            x: "x".into(),
            z: "z".into(),
        }
    }
}
