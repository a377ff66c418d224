//! Accelerations in closed form where a course derives them: a problem with one degree of
//! freedom whose equation of motion free of the reactions is `a q̈ = b`, with `a` and `b`
//! free of the coordinates and rates (a gear pair driven by a torque, a rack and pinion),
//! answers a question for q̈ with `q̈ = b/a` in symbols before its number,
//! q̈_A = T/(I_A + I_B r_A²/r_B²); a coordinate tied to it by a velocity constraint with
//! constant coefficients (ẋ = r θ̇) gets its acceleration from that one.

use crate::equations::{LinearSystem, Method};
use crate::numeric::{coordinate_unit, Answer};
use crate::problem::{Problem, Question, QuestionKind};
use crate::render::AnswerStep;
use crate::symbolic::latex;
use crate::symbolic::partial;
use crate::symbolic::{eval, Values};
use crate::symbolic::{simplify, Expr, Symbol};
use crate::Worked;

fn step(text: String, math: String) -> AnswerStep {
    AnswerStep {
        text: text.into(),
        math: math.into(),
    }
}

/// `e` in parentheses where it is a sum, to multiply an acceleration.
fn grouped(e: &Expr) -> String {
    match e.terms().len() > 1 {
        true => format!("\\left({}\\right)", latex(e)),
        false => latex(e),
    }
}

/// Whether `e` holds a coordinate, a rate or the time.
fn varies(e: &Expr) -> bool {
    e.any_symbol(&|s| {
        matches!(
            s,
            Symbol::Coord(_, 0 | 1) | Symbol::Time | Symbol::Speed(..)
        )
    })
}

/// The one row of a system with one degree of freedom, `a q̈_k = b`, with `a` positive at
/// `v`: k, a, b; `None` where there are more rows, or `a` or `b` varies.
fn single_row(problem: &Problem, system: &LinearSystem, v: &Values) -> Option<(usize, Expr, Expr)> {
    let free = (problem.coordinates.iter())
        .filter(|c| !c.dependent && !c.dependent_rate && c.motion.is_none())
        .count();
    if free != 1 {
        return None;
    }
    // The row in one second rate alone: the equation of motion free of the reactions.
    let (i, j) = (0..system.a.len()).find_map(|i| {
        let row = &system.a[i];
        let nonzero: Vec<usize> = (0..row.len()).filter(|&j| !row[j].is_zero()).collect();
        match nonzero[..] {
            [j] if matches!(system.unknowns[j], Symbol::Coord(_, 2)) => Some((i, j)),
            _ => None,
        }
    })?;
    let Symbol::Coord(name, 2) = &system.unknowns[j] else {
        return None;
    };
    let k = problem
        .coordinates
        .iter()
        .position(|c| c.name.as_str() == &**name)?;
    let (a, b) = (system.a[i][j].clone(), system.b[i].clone());
    if varies(&a) || varies(&b) {
        return None;
    }
    Some(match eval(&a, v) < 0.0 {
        true => (k, simplify(&-&a), simplify(&-&b)),
        false => (k, a, b),
    })
}

/// `q̇_j = c q̇_k` from a velocity constraint with only those two rates and constant
/// coefficients: c, and the constraint as written.
fn tied(worked: &Worked, j: usize, k: usize) -> Option<(Expr, String)> {
    let problem = worked.derivation.model.problem;
    let (dj, dk) = (
        problem.coordinate_symbol(j, 1),
        problem.coordinate_symbol(k, 1),
    );
    worked
        .derivation
        .model
        .constraints
        .rows
        .iter()
        .find_map(|row| {
            let e = &row.velocity;
            let others = e.any_symbol(&|s| {
                matches!(
                    s,
                    Symbol::Coord(_, 0 | 1) | Symbol::Speed(..) | Symbol::Time
                ) && *s != dj
                    && *s != dk
            });
            let cj = simplify(&partial(e, &dj).ok()?);
            let ck = simplify(&partial(e, &dk).ok()?);
            if others || cj.is_zero() || ck.is_zero() || varies(&cj) || varies(&ck) {
                return None;
            }
            Some((simplify(&(&-&ck / &cj)), format!("{} = 0", latex(e))))
        })
}

/// The working of a question for a second rate `q''` in closed form, or `None` where the
/// problem is not of that kind or the numbers disagree with the answer.
pub fn value_steps(
    worked: &Worked,
    question: &Question,
    answer: &Answer,
) -> Option<Vec<AnswerStep>> {
    let QuestionKind::Value { expression, .. } = &question.kind else {
        return None;
    };
    let Some(Symbol::Coord(name, 2)) = expression.as_symbol() else {
        return None;
    };
    let problem = worked.derivation.model.problem;
    let j = problem
        .coordinates
        .iter()
        .position(|c| c.name.as_str() == &**name)?;
    let mut v = Values::new();
    for c in &problem.constants {
        v.set(Symbol::Const(c.name.as_str().into()), c.value);
    }
    let (k, a, b) = single_row(problem, worked.period_system.as_ref()?, &v)?;
    let found = answer.values.first()?.1;
    let unit = super::answer_numbers::unit_tex(&coordinate_unit(problem, j, 2));
    let (an, bn) = (eval(&a, &v), eval(&b, &v));
    let qk = problem.coordinate_expr(k, 2);
    let words = match worked.derivation.method {
        Method::Kane => "Kane's equation for its speed",
        _ => "the equations of step 5 with the reactions and the other accelerations eliminated",
    };
    let close = |x: f64| (x - found).abs() <= 1e-6 * found.abs().max(1e-9);
    let equation = format!("{} \\, {} = {}", grouped(&a), latex(&qk), latex(&b));
    let kept = (worked.derivation.system.unknowns.iter()).position(
        |u| matches!(u, Symbol::Coord(c, 2) if &**c == problem.coordinates[k].name.as_str()),
    );
    let eliminated =
        kept.and_then(|keep| super::elimination::steps(&worked.derivation, keep, &v, bn / an));
    let mut steps = match eliminated {
        // The elimination written out, row by row, then what is left.
        Some((mut steps, last)) => {
            steps.insert(0, step(format!("One degree of freedom, ${}$. The reactions and the other accelerations are eliminated from the equations of step 5, one row at a time:", latex(&problem.coordinate_expr(k, 0))), String::new()));
            steps.push(step(format!("Put into row ({}), these leave one equation of motion, free of the reactions, whose coefficients are free of the coordinates and rates:", last + 1), equation));
            steps
        }
        None => vec![step(
            format!("One degree of freedom, ${}$. Its equation of motion free of the reactions ({words}) has coefficients free of the coordinates and rates,", latex(&problem.coordinate_expr(k, 0))),
            equation,
        )],
    };
    // b/a as written, or simplified where that is shorter (T r/(I + M r²)).
    let quotient = [
        format!("\\frac{{{}}}{{{}}}", latex(&b), latex(&a)),
        latex(&simplify(&(&b / &a))),
    ]
    .into_iter()
    .min_by_key(String::len)
    .unwrap_or_default();
    let numbers = format!(
        "\\frac{{{}}}{{{}}}",
        super::answer_numbers::number_tex(bn),
        super::answer_numbers::number_tex(an)
    );
    if j == k {
        if !close(bn / an) {
            return None;
        }
        steps.push(step(
            "so that the acceleration is constant:".into(),
            format!(
                "{} = {quotient} = {numbers} = {}{unit}",
                latex(&qk),
                super::answer_numbers::number_tex(found)
            ),
        ));
        return Some(steps);
    }
    let (c, constraint) = tied(worked, j, k)?;
    let cn = eval(&c, &v);
    if !close(cn * bn / an) {
        return None;
    }
    let qj = problem.coordinate_expr(j, 2);
    // Where q̈_k is asked too, its answer has the equation already.
    let asked = (problem.questions.iter())
        .any(|q| matches!(&q.kind, QuestionKind::Value { expression, .. } if *expression == qk));
    let lead = match asked {
        true => {
            steps.clear();
            "The constraint"
        }
        false => "and the constraint",
    };
    steps.push(step(
        format!(
            "{lead} ${constraint}$ gives ${} = {} \\, {}$ at every instant, so that",
            latex(&problem.coordinate_expr(j, 1)),
            latex(&c),
            latex(&problem.coordinate_expr(k, 1))
        ),
        format!(
            "{} = {} \\, {} = {} \\, {quotient} = {}{unit}",
            latex(&qj),
            latex(&c),
            latex(&qk),
            latex(&c),
            super::answer_numbers::number_tex(found)
        ),
    ));
    Some(steps)
}
