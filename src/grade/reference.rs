//! What a submission is graded against, derived once per problem (once per variant in a
//! batch): the worked solution's equations, the answers, and the motion at a few random
//! states (the q'' and every reaction component there), at which every expression of a
//! submission is compared.

use crate::equations::{Derivation, Method};
use crate::numeric::{Answer, System};
use crate::pipeline::Solver;
use crate::problem::Problem;
use crate::symbolic::{eval, simplify, substitute, time_derivative, Expr, Symbol, Values};
use crate::Error;
use nalgebra::{DMatrix, DVector};
use std::cell::OnceCell;

/// How many random states an expression is compared at.
const SAMPLES: usize = 4;

/// One random state of the motion.
#[derive(Clone, Debug)]
pub struct Sample {
    /// Time, coordinates and rates.
    pub t: f64,
    /// The coordinates.
    pub q: Vec<f64>,
    /// Their rates.
    pub rates: Vec<f64>,
    /// The constants, the state, the q'' of the equations of motion and every reaction
    /// component of every site there.
    pub motion: Values,
    /// The constants and the state with the q'' drawn at random: kinematics and the
    /// generalized inertia forces hold for any q''.
    pub free: Values,
}

/// The worked solution of one problem, as the grader reads it.
pub struct Reference<'p> {
    /// The problem.
    pub problem: &'p Problem,
    /// The equations of the chosen method, as the worked solution writes them.
    pub derivation: Derivation<'p>,
    /// Newton–Euler's rows (every reaction an unknown), for matching a student's row.
    pub newton_euler: Option<Derivation<'p>>,
    /// Kane's rows, for the generalized forces; derived when first asked for.
    kane: OnceCell<Option<Derivation<'p>>>,
    /// The answers of `find.questions`, one per question (`None` for a question no
    /// submission answers, which is not worked out), or why they could not be found.
    pub answers: Result<Vec<Option<Answer>>, String>,
    /// The random states.
    pub samples: Vec<Sample>,
    /// Every reaction component of every site.
    pub reactions: Vec<Symbol>,
    /// The q'' of every coordinate.
    pub accelerations: Vec<Symbol>,
    /// The rates of every coordinate.
    pub rates: Vec<Symbol>,
    /// Each coordinate of a prescribed motion, its rate and its second rate, with what
    /// the motion makes them (`phi' = W` for `phi = W*t`); a held coordinate's rates only.
    prescribed: Vec<(Symbol, Expr)>,
}

impl<'p> Reference<'p> {
    /// Derives the worked solution of `problem` by `method`, answers every question and
    /// samples its motion.
    ///
    /// # Errors
    /// When the equations cannot be derived or solved at any random state.
    pub fn new(problem: &'p Problem, method: Method) -> Result<Reference<'p>, Error> {
        let every: Vec<usize> = (0..problem.questions.len()).collect();
        Reference::answering(problem, method, &every)
    }

    /// As [`Reference::new`], answering only the questions `asked` (by their index in
    /// `find.questions`), those the submissions answer: a question at a later time is
    /// answered by integrating the motion to it, which no one then reads.
    ///
    /// # Errors
    /// As for [`Reference::new`].
    pub fn answering(
        problem: &'p Problem,
        method: Method,
        asked: &[usize],
    ) -> Result<Reference<'p>, Error> {
        let derivation =
            crate::pipeline::derive(problem, method, crate::pipeline::Purpose::Handout)?;
        let newton_euler = match method {
            Method::NewtonEuler => None,
            _ => crate::pipeline::derive(
                problem,
                Method::NewtonEuler,
                crate::pipeline::Purpose::Handout,
            )
            .ok(),
        };
        let solver = Solver::new(problem, &derivation);
        let answers = answers_of(problem, method, asked);
        let model = &derivation.model;
        let sites: Vec<usize> = (0..model.sites.len()).collect();
        let reactions = crate::mechanics::reaction_unknowns(model, &sites);
        let full = newton_euler.as_ref().unwrap_or(&derivation);
        let samples = sample(problem, &solver, full, &derivation)?;
        let count = problem.coordinates.len();
        Ok(Reference {
            problem,
            accelerations: (0..count)
                .map(|i| problem.coordinate_symbol(i, 2))
                .collect(),
            rates: (0..count)
                .map(|i| problem.coordinate_symbol(i, 1))
                .collect(),
            derivation,
            newton_euler,
            kane: OnceCell::new(),
            answers,
            samples,
            reactions,
            prescribed: prescribed(problem),
        })
    }

    /// `e` in the problem's own symbols, as a student writes it: every named quantity
    /// replaced by what it stands for, and a prescribed motion's coordinate and rates by
    /// its expression (`phi'` by `W` where `phi = W*t`).
    pub fn own_symbols(&self, e: &Expr) -> Expr {
        let e = unfold(e);
        match self.prescribed.is_empty() {
            true => e,
            false => simplify(&substitute(&e, &|s| {
                (self.prescribed.iter())
                    .find(|(symbol, _)| symbol == s)
                    .map(|(_, by)| by.clone())
            })),
        }
    }

    /// Kane's rows, derived on first use (`None` when they cannot be).
    pub fn kane(&self) -> Option<&Derivation<'p>> {
        self.kane
            .get_or_init(|| match self.derivation.method {
                Method::Kane => None,
                _ => crate::pipeline::derive(
                    self.problem,
                    Method::Kane,
                    crate::pipeline::Purpose::Handout,
                )
                .ok(),
            })
            .as_ref()
            .or((self.derivation.method == Method::Kane).then_some(&self.derivation))
    }

    /// The number of coordinates whose q'' the equations must determine.
    pub fn degrees_of_freedom(&self) -> usize {
        let constraints = &self.derivation.model.constraints;
        self.problem
            .coordinates
            .iter()
            .enumerate()
            .filter(|(i, c)| c.motion.is_none() && !constraints.dependent.contains(i))
            .count()
    }
}

/// The answers of the questions `asked`, as `answer` gives them (statics, impacts and
/// periods included), `None` for the others; every question's where one is asked about
/// a steady motion another finds (`about`), which the answers must keep in their places.
fn answers_of(
    problem: &Problem,
    method: Method,
    asked: &[usize],
) -> Result<Vec<Option<Answer>>, String> {
    let questions = &problem.questions;
    let about = questions.iter().any(|q| q.about.is_some());
    let wanted: Vec<bool> = (0..questions.len())
        .map(|i| about || asked.contains(&i))
        .collect();
    if !wanted.contains(&true) {
        return Ok(vec![None; questions.len()]);
    }
    let found = match wanted.contains(&false) {
        false => crate::pipeline::answers(problem, method),
        // The others left out: each question is answered on its own (its path, which an
        // error names, kept), so those asked come out the same.
        true => crate::pipeline::answers(
            &Problem {
                questions: (questions.iter().zip(&wanted))
                    .filter(|(_, &w)| w)
                    .map(|(q, _)| q.clone())
                    .collect(),
                ..problem.clone()
            },
            method,
        ),
    };
    let mut found = found.map_err(|e| e.to_string())?.into_iter();
    Ok(wanted
        .iter()
        .map(|&w| if w { found.next() } else { None })
        .collect())
}

/// `e` with every named quantity replaced by what it stands for.
pub(super) fn unfold(e: &Expr) -> Expr {
    substitute(e, &|s| match s {
        Symbol::Defined(d) => Some(unfold(d.value())),
        _ => None,
    })
}

/// Each prescribed coordinate (but a held one, whose name stands for its value), its rate
/// and its second rate, with their expressions of time; a rate whose derivative cannot be
/// taken is left as it is.
fn prescribed(problem: &Problem) -> Vec<(Symbol, Expr)> {
    let mut out = Vec::new();
    for (i, c) in problem.coordinates.iter().enumerate() {
        let Some(motion) = &c.motion else {
            continue;
        };
        let Ok(rate) = time_derivative(motion) else {
            continue;
        };
        if !c.held {
            out.push((problem.coordinate_symbol(i, 0), motion.clone()));
        }
        out.push((problem.coordinate_symbol(i, 1), simplify(&rate)));
        if let Ok(second) = time_derivative(&rate) {
            out.push((problem.coordinate_symbol(i, 2), simplify(&second)));
        }
    }
    out
}

/// A generator of numbers in [-1, 1), seeded so that a grade is the same every run.
struct Draw(u64);

impl Draw {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
}

/// The random states, each with the q'' of `solver` and the reactions of `full` (a
/// derivation in which every reaction is an unknown).
fn sample(
    problem: &Problem,
    solver: &Solver,
    full: &Derivation,
    derivation: &Derivation,
) -> Result<Vec<Sample>, Error> {
    let mut draw = Draw(0x2545_F491_4F6C_DD1D);
    let mut samples = Vec::new();
    let mut last_error = None;
    for _ in 0..SAMPLES * 5 {
        if samples.len() == SAMPLES {
            break;
        }
        let t = 0.5 + 0.5 * draw.next();
        let mut q: Vec<f64> = problem
            .coordinates
            .iter()
            .map(|c| c.initial + spread(c) * draw.next())
            .collect();
        let mut rates: Vec<f64> = problem
            .coordinates
            .iter()
            .map(|c| c.rate + 1.5 * draw.next())
            .collect();
        let random: Vec<f64> = problem
            .coordinates
            .iter()
            .map(|_| 3.0 * draw.next())
            .collect();
        if let Err(e) = solver.assemble(t, &mut q, &mut rates) {
            last_error = Some(e);
            continue;
        }
        let solution = match solver.solve(t, &q, &rates) {
            Ok(s) => s,
            Err(e) => {
                last_error = Some(e);
                continue;
            }
        };
        let base = derivation.model.values_at(t, &q, &rates);
        let mut motion = base.clone();
        let mut free = base;
        for (i, (a, r)) in solution.accelerations.iter().zip(&random).enumerate() {
            motion.set(problem.coordinate_symbol(i, 2), *a);
            free.set(problem.coordinate_symbol(i, 2), *r);
        }
        for (symbol, value) in reactions_at(full, &motion) {
            motion.set(symbol, value);
        }
        samples.push(Sample {
            t,
            q,
            rates,
            motion,
            free,
        });
    }
    match (samples.is_empty(), last_error) {
        (true, Some(e)) => Err(Error::Solve(e)),
        _ => Ok(samples),
    }
}

/// How far a sampled coordinate strays either side of its initial value: 1.2, but a
/// length not zero at the start keeps its sign, as the distance r of a particle on a
/// spring from its pivot does (its spring's length |r| is r only for r > 0, and a student
/// writes k (r − l₀)).
fn spread(coordinate: &crate::problem::Coordinate) -> f64 {
    let angle = matches!(coordinate.unit.as_deref(), Some("rad" | "deg" | "degree"));
    match (angle, coordinate.initial) {
        (false, x) if x != 0.0 => (0.8 * x.abs()).min(1.2),
        _ => 1.2,
    }
}

/// Every reaction unknown of `full` at the state of `values` (with its q'' set): its
/// linear system solved there. Empty when the system is not square or is singular.
fn reactions_at(full: &Derivation, values: &Values) -> Vec<(Symbol, f64)> {
    let system = &full.system;
    let n = system.unknowns.len();
    if system.a.len() != n || system.b.len() != n {
        return Vec::new();
    }
    let a = DMatrix::from_fn(n, n, |i, j| eval(&system.a[i][j], values));
    let b = DVector::from_fn(n, |i, _| eval(&system.b[i], values));
    let Some(x) = crate::numeric::solve_linear(&a, &b) else {
        return Vec::new();
    };
    system
        .unknowns
        .iter()
        .zip(x.iter())
        .filter(|(s, _)| matches!(s, Symbol::Unknown(_)))
        .map(|(s, v)| (s.clone(), *v))
        .collect()
}
