//! A reaction answered at the initial state in closed form beside its number, where step 5
//! gives it in symbols: the system's coefficients free of the coordinates, rates and time
//! (a gear pair, a ball sliding on a lane), solved by elimination in symbols, or the
//! solution while a contact slides. `F^P·n̂x = −μ m g = −13.734 N`. A component is matched
//! to the unknown whose form gives its number (or its negative) to the printed digits.

use crate::equations::Derivation;
use crate::numeric::Answer;
use crate::problem::{Problem, QuestionAt, QuestionKind};
use crate::render::text::Math;
use crate::render::AnswerView;
use crate::symbolic::{eval, latex, simplify, substitute, Expr, Symbol};

/// The longest closed form written beside a number, in LaTeX characters.
const LONGEST_FORM: usize = 80;

/// Writes the closed forms into the reaction answers at the initial state. `sliding` is
/// step 5's solution while a contact slides from the start, where one does.
pub fn attach(
    problem: &Problem,
    derivation: &Derivation,
    answers: &[Answer],
    views: &mut [AnswerView],
    sliding: Option<Vec<Expr>>,
) {
    let asked: Vec<usize> = (problem.questions.iter().enumerate())
        .filter(|(_, q)| {
            matches!(
                q.kind,
                QuestionKind::Reaction { .. } | QuestionKind::Slips { .. }
            )
        })
        .filter(|(_, q)| q.at == QuestionAt::default() && q.about.is_none())
        .map(|(i, _)| i)
        .collect();
    if asked.is_empty() {
        return;
    }
    let angles: Vec<&str> = (problem.coordinates.iter())
        .filter(|c| c.kind == crate::problem::CoordinateKind::Angle)
        .map(|c| c.name.as_str())
        .collect();
    let style = super::tex::style_of(problem).with_coordinates(&angles);
    let v = super::switch_steps::initial_values(problem);
    crate::symbolic::with_style(style, || {
        let Some(x) = sliding.or_else(|| fixed_solution(derivation, &v)) else {
            return;
        };
        let forms: Vec<(Expr, f64)> = (x.iter())
            .filter(|e| !e.is_constant() && !super::switch_steps::moves(e))
            .map(|e| (e.clone(), eval(e, &v)))
            .filter(|(_, n)| n.is_finite() && n.abs() > 1e-12)
            .collect();
        for i in asked {
            if answers.get(i).is_none() {
                continue;
            }
            for value in &mut views[i].values_tex {
                if let Some(with_form) = with_form(value.as_str(), &forms) {
                    *value = Math::from(with_form);
                }
            }
        }
    });
}

/// Step 5 solved in symbols where its coefficients and right-hand side are free of the
/// motion (then so is every unknown).
fn fixed_solution(derivation: &Derivation, v: &crate::symbolic::Values) -> Option<Vec<Expr>> {
    let system = &derivation.system;
    // At the initial state: the coordinates and rates by their values (a gear's cos q_A
    // is 1 there); a form that keeps a decimal number is not written.
    let at = |e: &Expr| {
        simplify(&substitute(e, &|s| match s {
            Symbol::Coord(_, 0 | 1) => Some(Expr::real(eval(&Expr::sym(s.clone()), v))),
            _ => None,
        }))
    };
    let a: Vec<Vec<Expr>> = (system.a.iter())
        .map(|row| row.iter().map(at).collect())
        .collect();
    let b: Vec<Expr> = system.b.iter().map(at).collect();
    let still = |e: &Expr| !super::switch_steps::moves(e);
    let free = a.iter().flatten().all(still) && b.iter().all(still);
    free.then(|| super::switch_steps::eliminate(a, b, v))?
}

/// `name = number unit` as `name = form = number unit`, with the form whose number is the
/// printed one (or its negative, then negated); `None` where none is, or it is long.
fn with_form(value: &str, forms: &[(Expr, f64)]) -> Option<String> {
    let (name, rest) = value.rsplit_once(" = ")?;
    let printed: f64 = rest.split("\\ ").next()?.trim().parse().ok()?;
    let close = |n: f64| (n - printed).abs() <= 1e-5 * (1.0 + printed.abs());
    let form = forms
        .iter()
        .find_map(|(e, n)| match (close(*n), close(-n)) {
            (true, _) => Some(e.clone()),
            (false, true) => Some(simplify(&-e)),
            _ => None,
        })?;
    let form_tex = latex(&form);
    (form_tex.len() <= LONGEST_FORM && !form_tex.contains('.'))
        .then(|| format!("{name} = {form_tex} = {rest}"))
}
