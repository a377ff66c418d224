//! The questions of a validated problem: what each asks for and at which state.

use super::model::BodyId;
use crate::symbolic::Expr;

/// A coordinate's value (`order` 0) or rate (`order` 1), by index into
/// [`Problem::coordinates`](super::Problem::coordinates).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateEntry {
    /// The coordinate, by index.
    pub coordinate: usize,
    /// 0 for the value, 1 for the rate.
    pub order: u8,
}

/// What a question asks for.
#[derive(Clone, Debug, PartialEq)]
pub enum QuestionKind {
    /// A scalar expression, with its text as written.
    Value {
        /// The expression.
        expression: Expr,
        /// Its text as written.
        text: String,
    },
    /// A vector: the position, velocity or acceleration of a point, or the angular velocity
    /// or acceleration of a body, in `N` (`v(P)`, `w(B)`), with its text as written.
    VectorValue {
        /// What it is, and of which point or body.
        quantity: super::vector_value::VectorQuantity,
        /// Its text as written.
        text: String,
    },
    /// A reaction, as a site index (see [`Problem::site_name`](super::Problem::site_name)).
    Reaction {
        /// The site.
        site: usize,
    },
    /// The generalized force that drives a prescribed coordinate, by index into
    /// [`Problem::coordinates`](super::Problem::coordinates). Whether the coordinate is
    /// prescribed is checked when the question is answered.
    Drive {
        /// The coordinate.
        coordinate: usize,
    },
    /// The `unknowns` that make the `zero` expressions vanish (default: every q''), each
    /// with its text.
    Steady {
        /// The values and rates solved for.
        unknowns: Vec<StateEntry>,
        /// The expressions that vanish, each with its text.
        zero: Vec<(Expr, String)>,
    },
    /// Whether friction at a site (a site index) fails to hold the question's state at
    /// rest: the ratio |F|/(μ|N|) decides.
    Slips {
        /// The site.
        site: usize,
    },
    /// Whether a contact (a site index) loses contact at the question's state at rest: its
    /// normal force decides.
    Tips {
        /// The site.
        site: usize,
    },
    /// The value of a constant (an index into [`Problem::constants`](super::Problem::constants)) at which, at rest,
    /// slip impends at a site (|F| = μ|N|), or with `tips` its normal force falls to zero;
    /// `guess` starts Newton's method (default: the constant's value).
    Impending {
        /// The constant solved for, by index.
        constant: usize,
        /// The site.
        site: usize,
        /// Contact lost (the normal force zero) rather than slip.
        tips: bool,
        /// Where Newton's method starts, if given.
        guess: Option<f64>,
    },
    /// The period of small oscillations about the question's state, from the
    /// linearization; `coordinate` (by index) picks the mode it moves most, else the
    /// slowest oscillation.
    Period {
        /// The coordinate whose mode is meant, if given.
        coordinate: Option<usize>,
    },
    /// An identity `lhs = rhs` to derive from the equations of motion and check at the
    /// question's state, with its text as written.
    Show {
        /// The left-hand side.
        lhs: Expr,
        /// The right-hand side.
        rhs: Expr,
        /// The identity as written.
        text: String,
        /// The statement's names for quantities of the identity (`where`), each with what
        /// it stands for: `Omega` for `psi'`, `I1` for `It + m*h^2`.
        names: Vec<(String, Expr)>,
        /// The conditions of the motion the identity is asked of (`assuming`), each a
        /// coordinate, rate or second rate and the value put in for it: `theta' = 0`.
        /// Empty: the conditions are read from the question's state.
        assuming: Vec<(Expr, Expr)>,
    },
    /// A coordinate's motion over a simulated run (from the initial state up to `at.time`,
    /// default `simulate.duration`): its least, greatest and mean value, amplitude and
    /// period, with the range of the rates of `rates` (coordinates by index).
    Describe {
        /// The coordinate described, by index.
        coordinate: usize,
        /// The coordinates whose rates' ranges are given too, by index.
        rates: Vec<usize>,
    },
    /// The values of a constant (an index into `Problem::constants`) between `from` and
    /// `to` where the question's state changes stability (a bicycle's weave and capsize
    /// speeds), from the linearization at `count` values and bisection between them.
    Stability {
        /// The constant varied.
        constant: usize,
        /// The lowest value tried.
        from: f64,
        /// The highest value tried.
        to: f64,
        /// How many values are tried before bisection.
        count: usize,
    },
}

impl QuestionKind {
    /// Whether statics answers it (`slips`, `tips`, `impending`).
    pub fn is_static(&self) -> bool {
        matches!(
            self,
            QuestionKind::Slips { .. } | QuestionKind::Tips { .. } | QuestionKind::Impending { .. }
        )
    }
}

/// Where a question is asked.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct QuestionAt {
    /// Seconds; `None` is t = 0.
    pub time: Option<f64>,
    /// Values given; the others are the initial ones. `None`: no `state` key, so a `time`
    /// is reached by simulating from the initial state.
    pub state: Option<Vec<(StateEntry, f64)>>,
    /// A site with friction (its index as `find.reactions` counts sites): the question is
    /// asked at the first instant, simulating from the initial state, that the site
    /// switches between sticking and slipping (a skidding ball starts to roll).
    pub switch: Option<usize>,
    /// Asked at the state just after the problem's impact (`after_impact`).
    pub after_impact: bool,
}

/// One entry of `find.questions`.
#[derive(Clone, Debug, PartialEq)]
pub struct Question {
    /// The question as worded for the student (user text), if given.
    pub text: Option<String>,
    /// What it asks for.
    pub kind: QuestionKind,
    /// Where it is asked.
    pub at: QuestionAt,
    /// The unit of a `value` (user text), if given.
    pub unit: Option<String>,
    /// The symbol a `value` is answered by (LaTeX math), if given.
    pub symbol: Option<String>,
    /// `in`: the frame a reaction's or a vector value's components are given in, when the
    /// question chooses one (otherwise its site's parent's, or `N`).
    pub frame: Option<BodyId>,
    /// The JSON path, e.g. `find.questions[0]`.
    pub path: String,
    /// `about`: the index of an earlier `steady` question whose state this one is asked
    /// at (a period about a steady precession).
    pub about: Option<usize>,
    /// `item`: the number of the statement's item this question answers; `None` follows
    /// the question before (the first: item 1, or its place when no question has one).
    pub item: Option<u32>,
}
