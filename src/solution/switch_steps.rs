//! The closed form of a motion that slides until it rolls (a bowling ball released
//! skidding): while a friction site slides, the sliding law `F = −μ N` (against the slip)
//! in place of its no-slip row of step 5; the equations solved in symbols; where they give
//! accelerations free of the coordinates, rates and time, the rates grow linearly, the
//! slip velocity too, and the instant it vanishes and the rates then follow in symbols.
//! Written in the Answers of the questions asked at that switch, and only where the
//! numbers agree with the simulation's to 1e-6.

use crate::equations::Derivation;
use crate::mechanics::FrictionSite;
use crate::numeric::Answer;
use crate::plan::Sum;
use crate::problem::{Problem, QuestionKind};
use crate::render::{AnswerStep, AnswerView};
use crate::symbolic::{eval, latex, partial, simplify, Expr, Symbol, Values};

/// The most unknowns the symbolic elimination takes on.
const LARGEST: usize = 8;

/// A pivot this small beside the matrix's largest entry is taken as zero.
const SINGULAR: f64 = 1e-10;

/// The motion until the switch, in symbols.
struct Closed {
    /// Each coordinate's q'' while the site slides.
    accelerations: Vec<Expr>,
    /// Each coordinate's rate at the start, in symbols.
    start: Vec<Expr>,
    /// The slip velocity as step 5's no-slip row writes it, and at time t.
    slip: (Expr, Expr),
    /// The instant the slip velocity vanishes.
    instant: Expr,
    /// Every unknown of step 5 while the site slides, in the system's order.
    solution: Vec<Expr>,
}

/// Adds the closed-form working to every question asked at the switch of a site that
/// slides from the start with constant accelerations; gives step 5's unknowns in symbols
/// while it slides, where it does.
pub fn attach(
    problem: &Problem,
    derivation: &Derivation,
    answers: &[Answer],
    views: &mut [AnswerView],
) -> Option<Vec<Expr>> {
    let angles: Vec<&str> = (problem.coordinates.iter())
        .filter(|c| c.kind == crate::problem::CoordinateKind::Angle)
        .map(|c| c.name.as_str())
        .collect();
    let style = super::tex::style_of(problem).with_coordinates(&angles);
    crate::symbolic::with_style(style, || {
        let mut done: Vec<usize> = Vec::new();
        let mut sliding: Option<(String, Closed)> = None;
        for (i, question) in problem.questions.iter().enumerate() {
            let Some(site) = question.at.switch else {
                continue;
            };
            if question.at.state.is_some() || question.about.is_some() {
                continue;
            }
            let name = problem.site_name(site);
            let Some(friction) = (derivation.model.constraints.friction.iter())
                .find(|f| f.name == name && f.stick.len() == 1 && f.normal.len() == 1)
            else {
                continue;
            };
            let Some(closed) = closed_form(problem, derivation, friction) else {
                continue;
            };
            let Some(answer) = answers.get(i) else {
                continue;
            };
            let first = !done.contains(&site);
            let steps = steps_for(problem, question, answer, &closed, first, name);
            if !steps.is_empty() {
                views[i].steps = steps;
                views[i].at_note = super::answer_leads::stops_slipping(problem, site);
                done.push(site);
                sliding.get_or_insert((name.to_string(), closed));
            }
        }
        let (site, closed) = sliding?;
        constant_at_start(problem, answers, views, &site, &closed);
        slips_at_start(problem, answers, views, &site, &closed);
        Some(closed.solution)
    })
    .0
}

/// A `slips` asked of the site at the start: the quantity that decides it, the slip
/// velocity of the contact point (the velocity rolling makes zero), in symbols and its
/// number, where that agrees with the answer.
fn slips_at_start(
    problem: &Problem,
    answers: &[Answer],
    views: &mut [AnswerView],
    site: &str,
    closed: &Closed,
) {
    let v = initial_values(problem);
    let at_start = simplify(&crate::symbolic::substitute(&closed.slip.1, &|s| {
        (*s == Symbol::Time).then(Expr::zero)
    }));
    let speed = eval(&at_start, &v);
    for (i, question) in problem.questions.iter().enumerate() {
        let QuestionKind::Slips { site: k } = question.kind else {
            continue;
        };
        let fresh =
            question.at == crate::problem::QuestionAt::default() && question.about.is_none();
        let slides = answers
            .get(i)
            .and_then(|a| crate::numeric::slip_speed(&a.values));
        if problem.site_name(k) != site || !fresh || !slides.is_some_and(|s| agrees(s, speed.abs()))
        {
            continue;
        }
        views[i].steps.push(step(
            "What decides it is the slip velocity of the contact point, the velocity that rolling makes zero, at the start:",
            format!(
                "v_{{\\mathrm{{slip}}}} = {} = {} = {}\\ \\mathrm{{m/s}} \\neq 0",
                latex(&closed.slip.0),
                latex(&at_start),
                super::answer_numbers::number_tex(speed)
            ),
        ));
        // The verdict above says the rest: the slip velocity is not listed twice.
        (views[i].values_tex).retain(|v| !v.as_str().starts_with("v_{\\mathrm{slip}}"));
    }
}

/// A second rate asked at the start, while the site slides: constant until it rolls, in
/// closed form, where that agrees with the answer.
fn constant_at_start(
    problem: &Problem,
    answers: &[Answer],
    views: &mut [AnswerView],
    site: &str,
    closed: &Closed,
) {
    let v = initial_values(problem);
    let mut said = false;
    for (i, question) in problem.questions.iter().enumerate() {
        let QuestionKind::Value { expression, .. } = &question.kind else {
            continue;
        };
        if question.at != crate::problem::QuestionAt::default() {
            continue;
        }
        let Some(k) =
            (0..problem.coordinates.len()).find(|&k| *expression == problem.coordinate_expr(k, 2))
        else {
            continue;
        };
        let asked = answers
            .get(i)
            .and_then(|a| a.values.first())
            .map_or(f64::NAN, |x| x.1);
        if !agrees(eval(&closed.accelerations[k], &v), asked) {
            continue;
        }
        let unit = crate::numeric::coordinate_unit(problem, k, 2);
        let why = match std::mem::replace(&mut said, true) {
            false => format!(
                "While the contact at {} slides it stays constant: the rows of step 5 with the sliding law give",
                super::force_labels::place(site).replace('_', "\\_")
            ),
            true => "Constant too while it slides:".to_string(),
        };
        views[i].steps.push(step(
            why,
            format!(
                "{} = {} = {}{}",
                latex(&problem.coordinate_expr(k, 2)),
                latex(&closed.accelerations[k]),
                super::answer_numbers::number_tex(asked),
                super::answer_numbers::unit_tex(&unit)
            ),
        ));
    }
}

fn step(text: impl Into<String>, math: impl Into<String>) -> AnswerStep {
    AnswerStep {
        text: text.into().into(),
        math: math.into().into(),
    }
}

/// The constants, the initial coordinates and rates.
pub(super) fn initial_values(problem: &Problem) -> Values {
    let mut v = Values::new();
    for c in &problem.constants {
        v.set(Symbol::Const(c.name.as_str().into()), c.value);
    }
    for c in &problem.coordinates {
        v.set(Symbol::Coord(c.name.as_str().into(), 0), c.initial);
        v.set(Symbol::Coord(c.name.as_str().into(), 1), c.rate);
    }
    v.set(Symbol::Time, 0.0);
    v
}

/// Whether `e` holds a coordinate, a rate, a second rate or the time.
pub(super) fn moves(e: &Expr) -> bool {
    e.any_symbol(&|s| matches!(s, Symbol::Coord(..) | Symbol::Time))
}

/// The motion until `friction` rolls, when the equations give constant accelerations.
fn closed_form(
    problem: &Problem,
    derivation: &Derivation,
    friction: &FrictionSite,
) -> Option<Closed> {
    let stick = &friction.stick[0];
    let system = &derivation.system;
    let n = system.b.len();
    if n > LARGEST || derivation.rows.len() != n {
        return None;
    }
    let row = (derivation.rows.iter())
        .position(|r| matches!(&r.sum, Sum::Constraint { name } if *name == stick.name))?;
    let column = |s: &Symbol| system.unknowns.iter().position(|u| u == s);
    let (f, normal) = (column(&stick.unknown)?, column(&friction.normal[0])?);
    let v = initial_values(problem);
    let slip0 = eval(&stick.velocity, &v);
    if slip0.is_nan() || slip0.abs() <= 1e-9 {
        return None;
    }
    // The sliding law, F = −σ μ N, σ the sign that opposes the slip with N pressing.
    let solve_with = |sigma: f64| {
        let mut a = system.a.clone();
        let mut b = system.b.clone();
        a[row] = vec![Expr::zero(); n];
        a[row][f] = Expr::one();
        a[row][normal] = Expr::real(sigma) * friction.coefficient.clone();
        b[row] = Expr::zero();
        eliminate(a, b, &v)
    };
    let sigma = slip0.signum();
    let mut x = solve_with(sigma)?;
    if eval(&x[normal], &v) < 0.0 {
        x = solve_with(-sigma)?;
    }
    let coordinates = problem.coordinates.len();
    let accelerations: Vec<Expr> = (0..coordinates)
        .map(|k| {
            let s = problem.coordinate_symbol(k, 2);
            column(&s).map(|j| x[j].clone())
        })
        .collect::<Option<_>>()?;
    if accelerations.iter().any(moves) {
        return None;
    }
    // The slip velocity, affine in the rates with coefficients free of the motion.
    let rates: Vec<Symbol> = (0..coordinates)
        .map(|k| problem.coordinate_symbol(k, 1))
        .collect();
    let mut growth = Vec::new();
    for (k, rate) in rates.iter().enumerate() {
        let c = simplify(&partial(&stick.velocity, rate).ok()?);
        if moves(&c) {
            return None;
        }
        growth.push(c * accelerations[k].clone());
    }
    let start: Vec<Expr> = (problem.coordinates.iter())
        .map(|c| c.rate_expr.clone().unwrap_or_else(|| Expr::real(c.rate)))
        .collect();
    let at_start = crate::symbolic::substitute(&stick.velocity, &|s| {
        rates.iter().position(|r| r == s).map(|k| start[k].clone())
    });
    let (s0, s1) = (simplify(&at_start), simplify(&crate::symbolic::add(growth)));
    if moves(&s0) || s1.is_zero() {
        return None;
    }
    let instant = simplify(&(-(&s0 / &s1)));
    let slip_t = simplify(&(&s0 + &(&s1 * &Expr::time())));
    Some(Closed {
        accelerations,
        start,
        slip: (simplify(&stick.velocity), slip_t),
        instant,
        solution: x,
    })
}

/// Gauss–Jordan elimination in symbols, each pivot the entry largest in size at the
/// values `v`; `None` where a column has no pivot there or the system is large.
pub(super) fn eliminate(mut a: Vec<Vec<Expr>>, mut b: Vec<Expr>, v: &Values) -> Option<Vec<Expr>> {
    let n = b.len();
    if n > LARGEST || a.len() != n || singular_at(&a, v) {
        return None;
    }
    let mut used = vec![false; n];
    let mut pivots = Vec::new();
    for col in 0..n {
        let (row, size) = (0..n)
            .filter(|&r| !used[r])
            .map(|r| (r, eval(&a[r][col], v).abs()))
            .max_by(|x, y| x.1.total_cmp(&y.1))?;
        if size.is_nan() || size <= 1e-12 {
            return None;
        }
        used[row] = true;
        for r in 0..n {
            if r == row || a[r][col].is_zero() {
                continue;
            }
            let factor = simplify(&(&a[r][col] / &a[row][col]));
            let pivot_row = a[row].clone();
            for (entry, p) in a[r].iter_mut().zip(&pivot_row) {
                if !p.is_zero() {
                    *entry = simplify(&(&*entry - &(&factor * p)));
                }
            }
            b[r] = simplify(&(&b[r] - &(&factor * &b[row])));
        }
        pivots.push((row, col));
    }
    let mut x = vec![Expr::zero(); n];
    for (row, col) in pivots {
        x[col] = simplify(&(&b[row] / &a[row][col]));
    }
    Some(x)
}

/// Whether the matrix `a` is singular at the values `v`, by the same elimination in
/// numbers: a pivot at most [`SINGULAR`] times the largest entry. Found before the
/// elimination in symbols, whose entries grow at each step (from sums of products to
/// quotients of them) so that a pivot that is zero at `v` evaluates there only to
/// rounding, and would be taken, all the columns after it eliminated in vain.
fn singular_at(a: &[Vec<Expr>], v: &Values) -> bool {
    let mut m: Vec<Vec<f64>> = (a.iter())
        .map(|row| row.iter().map(|e| eval(e, v)).collect())
        .collect();
    let largest = (m.iter().flatten()).fold(0.0_f64, |x, y| x.max(y.abs()));
    if !largest.is_finite() || largest == 0.0 {
        return true;
    }
    let n = m.len();
    let mut used = vec![false; n];
    for col in 0..n {
        let Some((row, size)) = (0..n)
            .filter(|&r| !used[r])
            .map(|r| (r, m[r][col].abs()))
            .max_by(|x, y| x.1.total_cmp(&y.1))
        else {
            return true;
        };
        if size.is_nan() || size <= SINGULAR * largest {
            return true;
        }
        used[row] = true;
        let pivot_row = m[row].clone();
        for (r, entries) in m.iter_mut().enumerate() {
            let factor = entries[col] / pivot_row[col];
            if r == row || factor == 0.0 {
                continue;
            }
            for (entry, p) in entries.iter_mut().zip(&pivot_row) {
                *entry -= factor * p;
            }
        }
    }
    false
}

/// Whether `found` is `expected` to 1e-6, relative.
fn agrees(found: f64, expected: f64) -> bool {
    (found - expected).abs() <= 1e-6 * expected.abs().max(1e-12)
}

/// The working for one question at the switch: the derivation of the instant (on the
/// first), and the rate asked (on a question asking for one).
fn steps_for(
    problem: &Problem,
    question: &crate::problem::Question,
    answer: &Answer,
    closed: &Closed,
    first: bool,
    site: &str,
) -> Vec<AnswerStep> {
    let v = initial_values(problem);
    let instant = eval(&closed.instant, &v);
    if !agrees(instant, answer.time) {
        return Vec::new();
    }
    let number = super::answer_numbers::number_tex;
    let mut steps = Vec::new();
    if first {
        let moving: Vec<String> = (0..problem.coordinates.len())
            .filter(|&k| !closed.accelerations[k].is_zero())
            .map(|k| {
                format!(
                    "{} = {}",
                    latex(&problem.coordinate_expr(k, 2)),
                    latex(&closed.accelerations[k])
                )
            })
            .collect();
        let site = super::force_labels::place(site).replace('_', "\\_");
        steps.push(step(
            format!("While the contact at {site} slides, friction is $\\mu$ times the normal force, against the slip: with the sliding law in place of the no-slip condition, the equations of step 5 give accelerations that stay constant until it rolls,"),
            moving.join(", \\qquad "),
        ));
        steps.push(step(
            "so each rate changes linearly in time from its start, and so does the slip velocity of the contact point, the velocity that the no-slip condition makes zero:",
            format!(
                "v_{{\\mathrm{{slip}}}} = {} = {}",
                latex(&closed.slip.0),
                latex(&closed.slip.1)
            ),
        ));
        steps.push(step(
            "It vanishes, and the contact rolls from then on, at",
            format!(
                "t = {} = {}\\ \\mathrm{{s}}",
                latex(&closed.instant),
                number(instant)
            ),
        ));
        steps.push(step(
            "The simulation from the initial state reaches the same instant.",
            String::new(),
        ));
    }
    if let QuestionKind::Value { expression, .. } = &question.kind {
        let Some(k) =
            (0..problem.coordinates.len()).find(|&k| *expression == problem.coordinate_expr(k, 1))
        else {
            return steps;
        };
        let grown = |t: &Expr| simplify(&(&closed.start[k] + &(&closed.accelerations[k] * t)));
        let then = grown(&closed.instant);
        let value = eval(&then, &v);
        let asked = answer.values.first().map_or(f64::NAN, |(_, x)| *x);
        if !agrees(value, asked) {
            return steps;
        }
        let rate = latex(&problem.coordinate_expr(k, 1));
        let unit = crate::numeric::answer_unit(
            problem,
            question,
            &crate::numeric::Quantity::Named(String::new()),
        );
        let unit = crate::render::unit_tex(&unit);
        let unit = if unit.is_empty() {
            unit
        } else {
            format!("\\ {unit}")
        };
        steps.push(step(
            "At that instant the rate has changed from its start by the constant acceleration times the time:",
            format!(
                "{rate} = {} = {} = {}{unit}",
                latex(&grown(&Expr::time())),
                latex(&then),
                number(value)
            ),
        ));
        steps.push(step(
            "The simulation from the initial state gives the same rate at that instant.",
            String::new(),
        ));
    }
    steps
}

#[cfg(test)]
mod tests {
    use super::eliminate;
    use crate::symbolic::{eval, Expr, Symbol, Values};

    fn at(pairs: &[(&str, f64)]) -> Values {
        let mut v = Values::new();
        for (name, value) in pairs {
            v.set(Symbol::Const((*name).into()), *value);
        }
        v
    }

    /// `[1, x y; 1, z]` at x = 1.1, y = 1.1e5, z = 1.21e5 is singular, but its second
    /// pivot `z − x y` evaluates there to 1.46e-11, rounding alone, which is past an
    /// absolute 1e-12: refused beside the largest entry, 1.21e5.
    #[test]
    fn a_pivot_that_is_rounding_is_refused() {
        let (x, y, z) = (
            Expr::constant("x"),
            Expr::constant("y"),
            Expr::constant("z"),
        );
        let v = at(&[("x", 1.1), ("y", 1.1e5), ("z", 1.21e5)]);
        let pivot = eval(&z, &v) - eval(&x, &v) * eval(&y, &v);
        assert!(pivot.abs() > 1e-12 && pivot.abs() < 1e-10, "{pivot}");
        let a = vec![vec![Expr::one(), &x * &y], vec![Expr::one(), z]];
        assert!(eliminate(a, vec![Expr::one(), Expr::int(2)], &v).is_none());
    }

    /// `[m, 1; k, 0] [p; q] = [0; f]`: by hand p = f/k, q = −m f/k, checked at numbers.
    #[test]
    fn a_regular_system_is_solved() {
        let (m, k, f) = (
            Expr::constant("m"),
            Expr::constant("k"),
            Expr::constant("f"),
        );
        let v = at(&[("m", 2.0), ("k", 4.0), ("f", 3.0)]);
        let a = vec![vec![m, Expr::one()], vec![k, Expr::zero()]];
        let x = eliminate(a, vec![Expr::zero(), f], &v).expect("regular");
        assert!((eval(&x[0], &v) - 0.75).abs() < 1e-12);
        assert!((eval(&x[1], &v) + 1.5).abs() < 1e-12);
    }
}
