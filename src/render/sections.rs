//! Two sections of the worked solution's content that stand apart from the six steps: the
//! Answers and the linearization (`explain --linearize`). The solution stage fills them;
//! strings are of the kinds of [`super::text`].

use super::text::{MarkupLine, Math};
use serde::Serialize;

/// One question and its answer, as the templates show it.
#[derive(Clone, Debug, Default, Serialize)]
pub struct AnswerView {
    /// The question as worded (user text in the markup of `super::markup`, one line), or
    /// one made from what it asks, its expressions as `$…$` math.
    pub question: MarkupLine,
    /// Where it is asked: `t = 2 \text{ s}, ...` (LaTeX math).
    pub at_tex: Math,
    /// How the state was reached, in words: "the initial state", "simulated from the initial state".
    pub at_note: String,
    /// Each value found, `name = value unit` (LaTeX math); empty in the student's handout.
    pub values_tex: Vec<Math>,
    /// A steady motion: the second derivatives left and the iterations (plain text).
    pub note: String,
    /// The number of the statement's item the question answers (`2`), or empty where it
    /// goes on the item of the question before.
    pub label: String,
    /// The working that leads to the answer: a derivation of a `show`, ω² = K/M of a
    /// `period`; empty in the student's handout.
    pub steps: Vec<AnswerStep>,
    /// The student's handout: how many lines the answer takes (a value one, a reaction one
    /// per component, a steady motion one per unknown), or 0 for a box to work in (a `show`).
    pub blank_lines: usize,
    /// Asked at the same state as the answer before it: the state is not said again.
    pub same_state: bool,
}

/// One step of an answer's working: a sentence, then a displayed equation (either may be
/// empty).
#[derive(Clone, Debug, Default, Serialize)]
pub struct AnswerStep {
    /// The sentence (the problem's markup, one line: `$…$` for inline math).
    pub text: MarkupLine,
    /// The equation displayed after it (LaTeX math).
    pub math: Math,
}

/// Small motions about a state.
#[derive(Clone, Debug, Default, Serialize)]
pub struct LinearizationSection {
    /// The state, e.g. `q_{1} = 0, \dot{q}_{1} = 0`.
    pub state_tex: Math,
    /// A sentence when the state is not steady (plain text; may be empty).
    pub steady_note: String,
    /// `\mathbf{M}\,\delta\ddot{\mathbf{q}} + … = \mathbf{0}`.
    pub equation_tex: Math,
    /// `\delta\mathbf{q} = [δq_1 … ]`.
    pub q_tex: Math,
    /// `\mathbf{M} = [...]`, and likewise `C` and `K`; empty when too large to print.
    pub m_tex: Math,
    /// The damping (and gyroscopic) matrix.
    pub c_tex: Math,
    /// The stiffness matrix.
    pub k_tex: Math,
    /// `\mathbf{A} = [...]` with the state `\mathbf{z}`; empty when too large.
    pub a_tex: Math,
    /// The state variables, e.g. `\mathbf{z} = [q_1, \dot q_1]^T`.
    pub z_tex: Math,
    /// `M`, `C`, `K` and `A` entry by entry (`M_{1,2} = 0.5`, the nonzero ones), for a page
    /// too narrow for the whole matrix; each empty when its matrix is.
    pub entries: MatrixEntries,
    /// The eigenvalues, sorted.
    pub eigenvalues: Vec<EigenvalueRow>,
    /// One row per mode.
    pub modes: Vec<ModeRow>,
    /// Stable or not, as a sentence (plain text).
    pub stability: String,
}

/// The nonzero entries of the matrices of [`LinearizationSection`], each as
/// `M_{i,j} = value` (LaTeX math).
#[derive(Clone, Debug, Default, Serialize)]
pub struct MatrixEntries {
    /// Of the mass matrix.
    pub m_tex: Vec<Math>,
    /// Of the damping matrix.
    pub c_tex: Vec<Math>,
    /// Of the stiffness matrix.
    pub k_tex: Vec<Math>,
    /// Of the state matrix.
    pub a_tex: Vec<Math>,
}

/// One eigenvalue.
#[derive(Clone, Debug, Default, Serialize)]
pub struct EigenvalueRow {
    /// E.g. `\lambda_{1} = -0.5 + 3.1 i`.
    pub value_tex: Math,
}

/// One mode in the table.
#[derive(Clone, Debug, Default, Serialize)]
pub struct ModeRow {
    /// 1, 2, …
    pub index: usize,
    /// |λ|/2π in Hz, formatted.
    pub natural_frequency: String,
    /// Im λ/2π in Hz, formatted.
    pub damped_frequency: String,
    /// −Re λ/|λ|, formatted.
    pub damping_ratio: String,
    /// The shape as a column, scaled so that its largest component is 1.
    pub shape_tex: Math,
    /// The shape drawn as bars, one per coordinate.
    pub figure: super::figure::Figure,
}
