//! The working of a `period` and of a `show` in the Answers.
//!
//! - A period with one degree of freedom left: the equation of motion of that coordinate
//!   free of the reactions (Kane's equation for its speed), `M q'' = f`, linearized about
//!   the state: M the coefficient of q'' there, K = −∂f/∂q there, ω² = K/M in symbols,
//!   then its number; written only when it agrees with the linearization's eigenvalue.
//!   Every period ends with ω and T = 2π/ω.
//! - A show: the equation of step 5 that the identity comes from, the conditions of the
//!   state substituted (the second rates that vanish there, the rates that are zero), the
//!   factor free of rates taken out, and the identity as stated. The equation is found by
//!   sampling: with the coordinates and constants held, the equation with the conditions
//!   substituted is a rate-free multiple of LHS − RHS at every set of rates tried.

use super::show_conditions::{put_in, Condition};
use crate::equations::{Derivation, LinearSystem};
use crate::numeric::Answer;
use crate::problem::{Problem, QuestionKind};
use crate::render::{AnswerStep, AnswerView};
use crate::symbolic::{
    eval, latex, latex_collected, latex_factored as factored, partial, pull_common_factor,
    simplify, substitute, Expr, Node, Symbol, Values,
};
use crate::Worked;

/// Adds the working of every `period` and `show` question to its view, from the run of
/// the stages: a `show` refers to step 5 of the handout's derivation.
pub fn attach(worked: &Worked, answers: &[Answer], views: &mut [AnswerView]) {
    let derivation = &worked.derivation;
    let problem = derivation.model.problem;
    // Written as step 5 writes: s_θ for sin θ, the problem's decimals.
    let angles: Vec<&str> = (problem.coordinates.iter())
        .filter(|c| c.kind == crate::problem::CoordinateKind::Angle)
        .map(|c| c.name.as_str())
        .collect();
    let style = super::tex::style_of(problem).with_coordinates(&angles);
    let solved = |i: usize| worked.show_accelerations.get(i).and_then(Option::as_deref);
    crate::symbolic::with_style(style, || {
        let questions = problem.questions.iter().zip(answers).zip(views.iter_mut());
        // A steady motion solved from a `show`'s identity only where that identity was
        // derived, not merely checked at the steady motion itself.
        let mut shown_derived = true;
        // The closed form of a support's force is derived once, then referred to.
        let mut force_said = false;
        for (i, ((question, answer), view)) in questions.enumerate() {
            view.steps = match &question.kind {
                QuestionKind::Period { .. } => {
                    let states = super::reduced::on_motion(answer, answers);
                    let kane = worked.period_system.as_ref();
                    let steps = period_steps(derivation, kane, answer, &states);
                    // The period is said where the steps end with it, not also above them.
                    if !steps.is_empty() && said_in(answer, &steps) {
                        view.values_tex.clear();
                    }
                    steps
                }
                QuestionKind::Show {
                    lhs, rhs, names, ..
                } => {
                    let shown = (lhs, rhs, names.as_slice());
                    let assumed = super::show_conditions::assumed(question);
                    let steps =
                        show_steps(problem, derivation, (solved(i), &assumed), answer, shown);
                    // The steps put the conditions in and say them: no lead says them first.
                    if !assumed.is_empty() && derived(&steps) {
                        view.at_tex = super::show_conditions::conditions_tex(&assumed).into();
                        view.at_note = "the conditions of the motion asked, put in below".into();
                        view.same_state = true;
                    }
                    shown_derived &= derived(&steps);
                    check_last(view, steps)
                }
                QuestionKind::Steady { .. } => {
                    let v = values(problem, answer, &[]);
                    let mut steps = (shown_derived)
                        .then(|| super::named_identity::steady_steps(problem, i, answer, &v))
                        .flatten()
                        .unwrap_or_default();
                    // Each value derived in the steps is said there, not also above them.
                    let derived_all = (answer.values.iter()).all(|(_, x)| {
                        let number = super::answer_numbers::number_tex(*x);
                        steps.iter().any(|s| s.math.as_str().contains(&number))
                    });
                    if !steps.is_empty() && derived_all {
                        view.values_tex.clear();
                    }
                    // The check that the motion is steady ends the answer, shown by the rows.
                    if view.note.starts_with("Check:") {
                        let shown = super::steady_check::sentence(derivation, problem, i);
                        view.note = shown.unwrap_or(std::mem::take(&mut view.note));
                    }
                    if !view.note.is_empty() {
                        steps.push(step(std::mem::take(&mut view.note), String::new()));
                    }
                    steps
                }
                QuestionKind::Value { .. } => {
                    super::closed_form::value_steps(worked, question, answer).unwrap_or_default()
                }
                QuestionKind::Describe { .. } => {
                    super::describe_words::fill(problem, question, answer, view)
                }
                QuestionKind::Reaction { .. } => {
                    let steps = super::steady_force::steps(worked, question, answer, !force_said)
                        .unwrap_or_default();
                    force_said |= !steps.is_empty();
                    // After the force said in words by the answers.
                    let mut said = std::mem::take(&mut view.steps);
                    said.extend(steps);
                    said
                }
                _ => Vec::new(),
            };
        }
    });
    super::constancy::attach(worked, answers, views);
    super::period_contrast::attach(worked, answers, views);
}

/// A derived `show` ends with its derivation: the values of its two sides at a state, and
/// whether they agree, are dropped (they are left only where the working is not derived).
fn check_last(view: &mut AnswerView, steps: Vec<AnswerStep>) -> Vec<AnswerStep> {
    if !derived(&steps) || view.values_tex.is_empty() {
        return steps;
    }
    // Derived to the form asked, a "show" needs no numbers: the sides evaluated add nothing.
    view.values_tex.clear();
    view.note.clear();
    steps
}

/// Whether every value of `answer` is written in the math of `steps`.
fn said_in(answer: &Answer, steps: &[AnswerStep]) -> bool {
    (answer.values.iter()).all(|(_, x)| {
        let number = super::answer_numbers::number_tex(*x);
        steps.iter().any(|s| s.math.as_str().contains(&number))
    })
}

/// Whether the working of a `show` derives it (it starts from an equation of step 5).
fn derived(steps: &[AnswerStep]) -> bool {
    (steps.first()).is_some_and(|s| s.text.as_str().starts_with("Equation"))
}

fn step(text: impl Into<String>, math: impl Into<String>) -> AnswerStep {
    AnswerStep {
        text: text.into().into(),
        math: math.into().into(),
    }
}

/// The constants, and the coordinates, rates and second rates of the state.
fn values(problem: &Problem, answer: &Answer, accelerations: &[f64]) -> Values {
    let mut v = Values::new();
    for c in &problem.constants {
        v.set(Symbol::Const(c.name.as_str().into()), c.value);
    }
    for (i, c) in problem.coordinates.iter().enumerate() {
        let s = |order| Symbol::Coord(c.name.as_str().into(), order);
        v.set(s(0), answer.q[i]);
        v.set(s(1), answer.rates[i]);
        v.set(s(2), accelerations.get(i).copied().unwrap_or(0.0));
    }
    v.set(Symbol::Time, answer.time);
    v
}

/// `e` with the symbols of `zero` set to 0.
fn zeroed(e: &Expr, zero: &[Symbol]) -> Expr {
    simplify(&substitute(e, &|s| zero.contains(s).then(Expr::zero)))
}

fn number(x: f64) -> String {
    super::answer_numbers::number_tex(x)
}

/// The conditions read from a state: the second rates that vanish there (by the step-5
/// accelerations) and the rates that are zero there, each set to 0.
fn state_conditions(problem: &Problem, accelerations: &[f64], answer: &Answer) -> Vec<Condition> {
    let scale = accelerations.iter().fold(1.0f64, |s, a| s.max(a.abs()));
    let mut zero: Vec<Symbol> = (0..problem.coordinates.len())
        .filter(|&i| accelerations[i].abs() < 1e-9 * scale)
        .map(|i| problem.coordinate_symbol(i, 2))
        .collect();
    zero.extend(zero_at_state(problem, answer, 1));
    zero.into_iter().map(|s| (s, Expr::zero())).collect()
}

/// The rates (and coordinates) that are zero at the state, as symbols.
fn zero_at_state(problem: &Problem, answer: &Answer, order: u8) -> Vec<Symbol> {
    let list = if order == 0 { &answer.q } else { &answer.rates };
    (0..problem.coordinates.len())
        .filter(|&i| list[i].abs() < 1e-12)
        .map(|i| problem.coordinate_symbol(i, order))
        .collect()
}

fn period_steps(
    derivation: &Derivation,
    kane: Option<&LinearSystem>,
    answer: &Answer,
    states: &[(f64, &[f64])],
) -> Vec<AnswerStep> {
    let Some(found) = &answer.period else {
        return Vec::new();
    };
    let mut steps = match found.coordinates.as_slice() {
        [one] => kane
            .and_then(|system| {
                one_freedom(derivation, system, (answer, states), one, found.natural)
            })
            .unwrap_or_default(),
        _ => Vec::new(),
    };
    let (which, omega) = match (found.mode.1, found.damping_ratio > 0.0) {
        (1, false) => ("The oscillation", "\\omega"),
        (1, true) => ("The damped oscillation", "\\omega_d"),
        (_, false) => (
            "Of the oscillations of the linearization, the one asked",
            "\\omega",
        ),
        (_, true) => (
            "Of the damped oscillations of the linearization, the one asked",
            "\\omega_d",
        ),
    };
    // Without the one-coordinate working above, where the period comes from is said: the
    // equations linearized about the state, valid for oscillations that stay small.
    let derived = !steps.is_empty();
    let mut text = format!("{which} has the angular frequency ${omega}$ and the period is");
    if !derived && found.mode.1 == 1 {
        text = format!(
            "Linearized about this state, the equations of motion give small oscillations \
             about it. {text}"
        );
    }
    if found.damping_ratio > 0.0 {
        text = format!(
            "{text} that of the damped motion (damping ratio {}):",
            crate::symbolic::fixed(found.damping_ratio)
        );
    } else {
        text.push(':');
    }
    steps.push(step(
        text,
        format!(
            "{omega} = {}\\ \\mathrm{{rad/s}}, \\qquad \\tau = \\frac{{2\\pi}}{{{omega}}} = {}\\ \\mathrm{{s}}",
            number(found.damped),
            number(found.period)
        ),
    ));
    if !derived && found.mode.1 == 1 {
        steps.push(step(
            "Oscillations that stay small about this state have this period; a motion that \
             starts away from it need not."
                .to_string(),
            String::new(),
        ));
    }
    steps
}

/// ω² = K/M in symbols for the one coordinate `name` left free, from Kane's equation for
/// it (`system`: Kane's equations of the problem in its rates); `None` where that equation
/// is not at hand or does not give the linearization's `natural` frequency.
fn one_freedom(
    derivation: &Derivation,
    system: &LinearSystem,
    (answer, states): (&Answer, &[(f64, &[f64])]),
    name: &str,
    natural: f64,
) -> Option<Vec<AnswerStep>> {
    let problem = derivation.model.problem;
    let k = problem.coordinates.iter().position(|c| c.name == name)?;
    let qdd = problem.coordinate_symbol(k, 2);
    let row = (0..system.b.len()).find(|&i| {
        let nonzero: Vec<usize> = (0..system.unknowns.len())
            .filter(|&j| !system.a[i][j].is_zero())
            .collect();
        nonzero.len() == 1 && system.unknowns[nonzero[0]] == qdd
    })?;
    let j = system.unknowns.iter().position(|u| *u == qdd)?;
    let v = values(problem, answer, &[]);
    // The mass positive: the row's signs changed where it is not.
    let (m, f) = match eval(&system.a[row][j], &v) < 0.0 {
        true => (-&system.a[row][j], -&system.b[row]),
        false => (system.a[row][j].clone(), system.b[row].clone()),
    };
    let (m, f) = (&m, &f);
    let mut zero = zero_at_state(problem, answer, 1);
    zero.extend(zero_at_state(problem, answer, 0));
    zero.retain(|s| m.contains(s) || f.contains(s));
    let q = problem.coordinate_symbol(k, 0);
    let k_full = -partial(f, &q).ok()?;
    // The other coordinates follow q through the constraints; their terms must vanish here.
    for (i, _) in problem
        .coordinates
        .iter()
        .enumerate()
        .filter(|(i, _)| *i != k)
    {
        let d = partial(f, &problem.coordinate_symbol(i, 0)).ok()?;
        if eval(&d, &v).abs() > 1e-9 * eval(&k_full, &v).abs() {
            return None;
        }
    }
    // Damping: no K/M form of the period.
    let c = partial(f, &problem.coordinate_symbol(k, 1)).ok()?;
    if eval(&c, &v).abs() > 1e-12 {
        return None;
    }
    let (m0, k0) = (zeroed(m, &zero), zeroed(&k_full, &zero));
    let omega2 = simplify(&(&k0 / &m0));
    let value = eval(&omega2, &v);
    let agrees = (value - natural * natural).abs() <= 1e-6 * value.abs();
    if !agrees || k0.is_zero() {
        return None;
    }
    let qdd_tex = latex(&Expr::sym(qdd.clone()));
    let q_tex = latex(&Expr::sym(q.clone()));
    let zero_tex: Vec<String> = zero
        .iter()
        .map(|s| format!("{} = 0", latex(&Expr::sym(s.clone()))))
        .collect();
    let settled = super::settled::on_constraints(derivation, answer, &omega2, k, value);
    let (m1, k1) = match &settled {
        Some(s) => (s.apply(&m0), s.apply(&k0)),
        None => (m0.clone(), k0.clone()),
    };
    let others = match &settled {
        Some(s) => format!(", where {}", s.sentence().replace(" giving ", " give ")),
        None => others_tex(problem, answer, &omega2, k),
    };
    let period = simplify(&(&m1 / &k1));
    let (mut steps, energies) =
        super::reduced::equation_steps(derivation, system, (row, k), (m, f), states);
    let k_words = super::reduced::k_words(energies, &q_tex);
    steps.extend([
        step(
            format!(
                "For small motions about this state, $M \\, \\delta {qdd_tex} + K \\, \\delta {q_tex} = 0$, where $M$ is the coefficient of ${qdd_tex}$ and {k_words}, both evaluated at {}{}:",
                if zero_tex.is_empty() { "the state".to_string() } else { format!("${}$", zero_tex.join(",\\ ")) },
                others.trim_end_matches(',')
            ),
            format!("M = {}, \\qquad K = {}", factored(&m1), factored(&k1)),
        ),
        step(
            "so that".to_string(),
            format!(
                "\\omega^{{2}} = \\frac{{K}}{{M}} = {} = {}\\ \\mathrm{{s^{{-2}}}}, \\qquad \\tau = 2\\pi \\sqrt{{\\frac{{M}}{{K}}}} = 2\\pi \\sqrt{{{}}}",
                ratio_tex(&k1, &m1),
                number(value),
                factored(&period)
            ),
        ),
    ]);
    Some(steps)
}

/// K/M written with M's common factor cancelled against K and the sum left in M kept
/// whole, `\frac{-2 g y}{3 (R - r)^{2}}`, where K is one term; else K/M simplified.
fn ratio_tex(k: &Expr, m: &Expr) -> String {
    let (common, inner) = match m.node() {
        Node::Add(_) => pull_common_factor(m),
        _ => (m.clone(), Expr::one()),
    };
    let quotient = simplify(&(k / &common));
    if inner.is_one() || matches!(k.node(), Node::Add(_)) {
        return latex(&simplify(&(k / m)));
    }
    let (coefficient, rest) = quotient.split_coefficient();
    match coefficient {
        crate::symbolic::Number::Ratio(n, d) => {
            let top = latex(&(&Expr::int(n) * &rest));
            let sum = square_tex(&inner).unwrap_or_else(|| factored(&inner));
            let sum = match sum.starts_with('(') || sum.starts_with("\\left(") {
                true => sum,
                false => format!("\\left({sum}\\right)"),
            };
            let bottom = match d {
                1 => sum,
                _ => format!("{d} {sum}"),
            };
            format!("\\frac{{{top}}}{{{bottom}}}")
        }
        _ => latex(&simplify(&(k / m))),
    }
}

/// A sum `a² + b² ± 2ab` written `(a ± b)²`.
fn square_tex(sum: &Expr) -> Option<String> {
    let squares: Vec<Expr> = (sum.terms().iter())
        .filter_map(|t| match t.node() {
            Node::Pow(base, two)
                if two.as_number() == Some(crate::symbolic::Number::Ratio(2, 1)) =>
            {
                Some(base.clone())
            }
            _ => None,
        })
        .collect();
    let [a, b] = squares.as_slice() else {
        return None;
    };
    [a - b, a + b].into_iter().find_map(|root| {
        let left = simplify(&(sum - &(&root * &root)));
        left.is_zero()
            .then(|| format!("\\left({}\\right)^{{2}}", latex(&root)))
    })
}

/// `, with y = −0.4 m,`: the values of the coordinates other than `k` left in `e`.
fn others_tex(problem: &Problem, answer: &Answer, e: &Expr, k: usize) -> String {
    let parts: Vec<String> = (0..problem.coordinates.len())
        .filter(|&i| i != k && e.contains(&problem.coordinate_symbol(i, 0)))
        .map(|i| {
            let unit = crate::numeric::coordinate_unit(problem, i, 0);
            format!(
                "${} = {}{}$",
                latex(&problem.coordinate_expr(i, 0)),
                number(answer.q[i]),
                super::answer_numbers::unit_tex(&unit)
            )
        })
        .collect();
    match parts.is_empty() {
        true => String::new(),
        false => format!(", with {} at the state,", parts.join(", ")),
    }
}

/// Whether `e` holds a rate (first derivative) of a coordinate.
fn has_rates(e: &Expr) -> bool {
    e.any_symbol(&|s| matches!(s, Symbol::Coord(_, 1) | Symbol::Speed(_, 0)))
}

fn show_steps(
    problem: &Problem,
    derivation: &Derivation,
    (accelerations, assumed): (Option<&[f64]>, &[Condition]),
    answer: &Answer,
    (lhs, rhs, names): (&Expr, &Expr, &[(String, Expr)]),
) -> Vec<AnswerStep> {
    let identity = accelerations.and_then(|a| {
        derive_identity(problem, derivation, (a, assumed), answer, (lhs, rhs, names))
    });
    identity.unwrap_or_else(|| {
        vec![step(
            "No single equation of step 5 reduces to this identity once the conditions of the state are put in; it is checked at the state only.",
            String::new(),
        )]
    })
}

/// The steps from an equation of step 5 to `lhs = rhs`, or `None` when no equation gives
/// it; `accelerations` are the q'' at the answer's state by those equations.
fn derive_identity(
    problem: &Problem,
    derivation: &Derivation,
    (accelerations, assumed): (&[f64], &[Condition]),
    answer: &Answer,
    (lhs, rhs, names): (&Expr, &Expr, &[(String, Expr)]),
) -> Option<Vec<AnswerStep>> {
    let system = &derivation.system;
    let v = values(problem, answer, accelerations);
    let zero = match assumed.is_empty() {
        true => state_conditions(problem, accelerations, answer),
        false => assumed.to_vec(),
    };
    let difference = lhs - rhs;
    for i in 0..system.b.len() {
        let mut terms: Vec<Expr> = (0..system.unknowns.len())
            .map(|j| &system.a[i][j] * &Expr::sym(system.unknowns[j].clone()))
            .collect();
        terms.push(-&system.b[i]);
        let row = crate::symbolic::add(terms);
        // Quoted as step 5 prints it: Kane's and Lagrange's rows with their signs changed.
        let row = match super::kane::sign_changed(derivation, i) {
            true => -&row,
            false => row,
        };
        let reduced = put_in(&row, &zero);
        // Another unknown left (a reaction, a second rate that does not vanish): not this row.
        if system.unknowns.iter().any(|u| reduced.contains(u)) || reduced.is_zero() {
            continue;
        }
        if !proportional(problem, &v, (&reduced, &difference), &zero) {
            continue;
        }
        let assumed = !assumed.is_empty();
        let mut steps = identity_steps(problem, answer, i, (&row, &reduced), (&zero, assumed));
        let (_, rest) = split_factor(&reduced);
        let named = super::named_identity::Renaming::of(names)
            .and_then(|r| super::named_identity::identity_steps(&r, &rest, (lhs, rhs), &v));
        steps.extend(named.unwrap_or_else(|| {
            vec![step(
                "which, the terms rearranged, is the relation asked, its right side multiplied out:",
                format!("{} = {}", latex(lhs), latex(rhs)),
            )]
        }));
        return Some(steps);
    }
    None
}

/// Whether `e` is a multiple of `d` by a factor free of rates: at several sets of rates,
/// the coordinates and constants held, e/d is the same nonzero number.
fn proportional(problem: &Problem, v: &Values, (e, d): (&Expr, &Expr), zero: &[Condition]) -> bool {
    let held = super::show_conditions::held_values(zero, v);
    let mut ratios = Vec::new();
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..4 {
        let mut w = v.clone();
        for i in 0..problem.coordinates.len() {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let x = (seed % 10_000) as f64 / 1000.0 - 5.0;
            let rate = problem.coordinate_symbol(i, 1);
            let value = held.iter().find(|(s, _)| *s == rate).map(|(_, x)| *x);
            w.set(rate, value.unwrap_or(x));
        }
        let (a, b) = (eval(e, &w), eval(d, &w));
        if !(a.is_finite() && b.is_finite()) || b.abs() < 1e-12 {
            return false;
        }
        ratios.push(a / b);
    }
    let first = ratios[0];
    first.abs() > 1e-12
        && ratios
            .iter()
            .all(|r| (r - first).abs() <= 1e-8 * first.abs())
}

/// The factors of `e` free of rates, and the rest.
fn split_factor(e: &Expr) -> (Expr, Expr) {
    let (common, inner) = match e.node() {
        Node::Add(_) => pull_common_factor(e),
        _ => (Expr::one(), e.clone()),
    };
    let mut outer = vec![common];
    let mut rest = Vec::new();
    for f in inner.factors() {
        if has_rates(f) {
            rest.push(f.clone());
        } else {
            outer.push(f.clone());
        }
    }
    (crate::symbolic::mul(outer), crate::symbolic::mul(rest))
}

fn identity_steps(
    problem: &Problem,
    answer: &Answer,
    i: usize,
    (row, reduced): (&Expr, &Expr),
    (zero, assumed): (&[Condition], bool),
) -> Vec<AnswerStep> {
    let mut steps = vec![step(
        format!("Equation ({}) of step 5:", i + 1),
        format!("{} = 0", latex_collected(&simplify(row))),
    )];
    steps.push(step(
        super::show_conditions::put_in_sentence(row, zero, assumed),
        format!("{} = 0", latex_collected(reduced)),
    ));
    let (outer, rest) = split_factor(reduced);
    if assumed && !outer.is_one() && outer.as_number().is_none() {
        steps.push(step(
            format!("Where ${} \\neq 0$, divided by it,", latex(&outer)),
            format!("{} = 0", latex_collected(&rest)),
        ));
    } else if !outer.is_one() && outer.as_number().is_none() {
        let held: Vec<String> = (0..problem.coordinates.len())
            .filter(|&k| outer.contains(&problem.coordinate_symbol(k, 0)))
            .map(|k| {
                format!(
                    "${} = {}$",
                    latex(&problem.coordinate_expr(k, 0)),
                    number(answer.q[k])
                )
            })
            .collect();
        let at = match held.is_empty() {
            true => String::new(),
            false => format!(" at {}", held.join(", ")),
        };
        steps.push(step(
            format!(
                "The factor ${}$ is not zero{at}; divided by it,",
                latex(&outer)
            ),
            format!("{} = 0", latex_collected(&rest)),
        ));
    }
    steps
}
