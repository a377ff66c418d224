//! The statement's own names in the Answers: a `show` whose statement names quantities
//! (`where`: Ω = ψ̇, ω₃ = φ̇ + ψ̇ cos θ, I₁ = I_t + m h²) is finished in those names, and a
//! steady motion the identity governs is solved from it in closed form (the heavy top's
//! precession rates, the roots of I₁ cos θ Ω² − I₃ ω₃ Ω + m g h = 0).

use crate::numeric::{coordinate_unit, Answer};
use crate::problem::{Problem, QuestionKind};
use crate::render::AnswerStep;
use crate::symbolic::latex;
use crate::symbolic::partial;
use crate::symbolic::substitute;
use crate::symbolic::{eval, Values};
use crate::symbolic::{latex_collected, latex_factored};
use crate::symbolic::{simplify, Expr, Symbol};

/// How the problem's symbols are written in the statement's names: each replaced symbol
/// with what it is in them (ψ̇ → Ω, φ̇ → ω₃ − Ω cos θ, I_t → I₁ − m h²).
pub struct Renaming {
    /// The symbol replaced and its expression in the names.
    pub replaced: Vec<(Symbol, Expr)>,
    /// The names and what each stands for, as the question gives them.
    pub names: Vec<(Symbol, Expr)>,
}

fn name_symbol(name: &str) -> Symbol {
    Symbol::Const(name.into())
}

fn is_rate(s: &Symbol) -> bool {
    matches!(s, Symbol::Coord(_, 1))
}

/// The first symbol of `e` that `pick` accepts and in which `e` is linear with a
/// coefficient free of it: the symbol and `e` solved for it given `e = name`.
fn solve_linear(e: &Expr, name: &Expr, pick: &dyn Fn(&Symbol) -> bool) -> Option<(Symbol, Expr)> {
    let mut symbols: Vec<Symbol> = Vec::new();
    e.for_each_symbol(&mut |s| {
        if pick(s) && !symbols.contains(s) {
            symbols.push(s.clone());
        }
    });
    symbols.into_iter().find_map(|s| {
        let slope = simplify(&partial(e, &s).ok()?);
        if slope.is_zero() || slope.contains(&s) || has_any_rate(&slope) {
            return None;
        }
        let rest = simplify(&(e - &(&slope * &Expr::sym(s.clone()))));
        if rest.contains(&s) {
            return None;
        }
        Some((s, simplify(&(&(name - &rest) / &slope))))
    })
}

fn has_any_rate(e: &Expr) -> bool {
    e.any_symbol(&is_rate)
}

impl Renaming {
    /// The renaming of a `show`'s `where` names: a name that is one rate replaces it; a
    /// name of rates replaces the one rate it is linear in that is not yet replaced; a
    /// name of constants replaces a constant it holds with a number as coefficient.
    /// `None` where a name fits none of these.
    pub fn of(names: &[(String, Expr)]) -> Option<Renaming> {
        let mut replaced: Vec<(Symbol, Expr)> = Vec::new();
        let named: Vec<(Symbol, Expr)> = (names.iter())
            .map(|(n, e)| (name_symbol(n), e.clone()))
            .collect();
        // Single rates first, then names of rates, then of constants.
        let mut order: Vec<&(Symbol, Expr)> = named.iter().collect();
        order.sort_by_key(|(_, e)| match e.as_symbol() {
            Some(s) if is_rate(s) => 0,
            _ if has_any_rate(e) => 1,
            _ => 2,
        });
        for (name, definition) in order {
            let n = Expr::sym(name.clone());
            if let Some(s) = definition.as_symbol().filter(|s| is_rate(s)) {
                replaced.push((s.clone(), n));
                continue;
            }
            let written = rewrite(definition, &replaced);
            let taken: Vec<Symbol> = replaced.iter().map(|(s, _)| s.clone()).collect();
            let found = match has_any_rate(&written) {
                true => solve_linear(&written, &n, &|s| is_rate(s) && !taken.contains(s)),
                false => solve_linear(&written, &n, &|s| matches!(s, Symbol::Const(_))),
            }?;
            replaced.push(found);
        }
        Some(Renaming {
            replaced,
            names: named,
        })
    }

    /// `e` in the names.
    pub fn apply(&self, e: &Expr) -> Expr {
        simplify(&rewrite(e, &self.replaced))
    }

    /// `\dot{\psi} = \Omega,\ I_{t} = I_{1} - h^{2} m`: each replacement as the step says it.
    fn replacements_tex(&self) -> String {
        (self.replaced.iter())
            .map(|(s, e)| format!("{} = {}", latex(&Expr::sym(s.clone())), latex(e)))
            .collect::<Vec<_>>()
            .join(",\\ ")
    }

    /// `\Omega = \dot{\psi}`: the names as the statement defines them.
    fn names_tex(&self) -> String {
        (self.names.iter())
            .map(|(s, e)| format!("{} = {}", latex(&Expr::sym(s.clone())), latex(e)))
            .collect::<Vec<_>>()
            .join(",\\ ")
    }

    /// `values` with each name set to what it stands for there.
    pub fn with_names(&self, values: &Values) -> Values {
        let mut v = values.clone();
        for (s, e) in &self.names {
            v.set(s.clone(), eval(e, values));
        }
        v
    }
}

fn rewrite(e: &Expr, replaced: &[(Symbol, Expr)]) -> Expr {
    substitute(e, &|s| {
        (replaced.iter())
            .find(|(r, _)| r == s)
            .map(|(_, e)| e.clone())
    })
}

fn step(text: String, math: String) -> AnswerStep {
    AnswerStep {
        text: text.into(),
        math: math.into(),
    }
}

/// The steps from `rest = 0` (the equation the identity comes from, reduced) to the
/// identity in the statement's names, or `None` where the equation in the names is not a
/// multiple of LHS − RHS in them (checked at `values` with the names set three ways).
pub fn identity_steps(
    renaming: &Renaming,
    rest: &Expr,
    (lhs, rhs): (&Expr, &Expr),
    values: &Values,
) -> Option<Vec<AnswerStep>> {
    let named = renaming.apply(rest);
    let (left, right) = (renaming.apply(lhs), renaming.apply(rhs));
    let difference = simplify(&(&left - &right));
    let mut ratios = Vec::new();
    for k in 0..3 {
        let mut v = renaming.with_names(values);
        for (i, (s, _)) in renaming.names.iter().enumerate() {
            let base = eval(&Expr::sym(s.clone()), &v);
            v.set(s.clone(), base * (1.0 + 0.37 * (k + i) as f64));
        }
        let (a, b) = (eval(&named, &v), eval(&difference, &v));
        if !(a.is_finite() && b.is_finite()) || b.abs() < 1e-14 {
            return None;
        }
        ratios.push(a / b);
    }
    let first = ratios[0];
    let proportional =
        first.abs() > 1e-12 && (ratios.iter()).all(|r| (r - first).abs() <= 1e-8 * first.abs());
    if !proportional || has_any_rate(&named) && !named_has_names(&named, renaming) {
        return None;
    }
    Some(vec![
        step(
            format!(
                "In the statement's names, ${}$: so ${}$. Put in, the equation becomes",
                renaming.names_tex(),
                renaming.replacements_tex()
            ),
            format!("{} = 0", latex_collected(&named)),
        ),
        step(
            "and, rearranged, it is the relation asked:".into(),
            format!("{} = {}", latex(&left), factored_tex(&right)),
        ),
    ])
}

/// `\Omega \left(I_{3} \omega_{3} - I_{1} \Omega c_{\theta}\right)`: the common factor
/// out, the terms inside with a positive one first.
fn factored_tex(e: &Expr) -> String {
    let (common, inner) = crate::symbolic::pull_common_factor(e);
    if common.is_one() || inner.terms().len() < 2 {
        return latex_factored(e);
    }
    let mut terms: Vec<String> = inner.terms().iter().map(latex).collect();
    terms.sort_by_key(|t| t.starts_with('-'));
    let mut sum = terms[0].clone();
    for t in &terms[1..] {
        match t.strip_prefix('-') {
            Some(rest) => sum.push_str(&format!(" - {rest}")),
            None => sum.push_str(&format!(" + {t}")),
        }
    }
    format!("{} \\left({sum}\\right)", latex(&common))
}

fn named_has_names(e: &Expr, renaming: &Renaming) -> bool {
    (renaming.names.iter()).any(|(s, _)| e.contains(s))
}

/// The `show` question with `where` names whose identity holds at a steady motion with
/// the same conditions as question `k`: its renaming and its two sides.
fn governing_identity(problem: &Problem, k: usize) -> Option<(Renaming, Expr, Expr, usize)> {
    let QuestionKind::Steady { zero, .. } = &problem.questions.get(k)?.kind else {
        return None;
    };
    problem.questions.iter().enumerate().find_map(|(index, q)| {
        let QuestionKind::Show {
            lhs, rhs, names, ..
        } = &q.kind
        else {
            return None;
        };
        let about = problem.questions.get(q.about?)?;
        let same = matches!(&about.kind, QuestionKind::Steady { zero: z, .. } if z == zero);
        if !same || names.is_empty() {
            return None;
        }
        Some((Renaming::of(names)?, lhs.clone(), rhs.clone(), index))
    })
}

/// A steady motion in closed form: where a `show` of the statement governs it and its
/// identity, in the statement's names, is a quadratic in the name of one unknown rate,
/// the quadratic, its roots in symbols, the root that is this answer, and each other
/// unknown from the names. `None` where that is not so or the numbers disagree.
pub fn steady_steps(
    problem: &Problem,
    k: usize,
    answer: &Answer,
    values: &Values,
) -> Option<Vec<AnswerStep>> {
    let (renaming, lhs, rhs, shown) = governing_identity(problem, k)?;
    let labels = super::answer_numbers::labels(problem);
    let item = labels[..=shown]
        .iter()
        .rev()
        .find(|l| !l.is_empty())
        .cloned();
    let item = item.unwrap_or_else(|| "above".into());
    let QuestionKind::Steady { unknowns, .. } = &problem.questions[k].kind else {
        return None;
    };
    let difference = renaming.apply(&(&lhs - &rhs));
    // The name of an unknown rate, with the index of its coordinate.
    let (name, i) = renaming.names.iter().find_map(|(s, e)| {
        let rate = e.as_symbol().filter(|s| is_rate(s))?;
        let entry = unknowns
            .iter()
            .find(|u| u.order == 1 && problem.coordinate_symbol(u.coordinate, 1) == *rate)?;
        Some((s.clone(), entry.coordinate))
    })?;
    let n = Expr::sym(name.clone());
    let at_zero = |e: &Expr| simplify(&substitute(e, &|s| (s == &name).then(Expr::zero)));
    let first = simplify(&partial(&difference, &name).ok()?);
    let second = simplify(&partial(&first, &name).ok()?);
    let third = simplify(&partial(&second, &name).ok()?);
    if !third.is_zero() || second.contains(&name) || second.is_zero() {
        return None;
    }
    let a = simplify(&(&second / &Expr::int(2)));
    let (b, c) = (at_zero(&first), at_zero(&difference));
    let v = renaming.with_names(values);
    let (an, bn, cn) = (eval(&a, &v), eval(&b, &v), eval(&c, &v));
    let discriminant = bn * bn - 4.0 * an * cn;
    if discriminant < 0.0 || an == 0.0 {
        return None;
    }
    let found = answer.rates[i];
    let roots = [-1.0, 1.0].map(|sign| (-bn + sign * discriminant.sqrt()) / (2.0 * an));
    let which = roots
        .iter()
        .position(|r| (r - found).abs() <= 1e-6 * found.abs().max(1e-9))?;
    let quadratic = crate::symbolic::add(vec![&a * &(&n * &n), &b * &n, c.clone()]);
    let disc = simplify(&(&(&b * &b) - &(&(&Expr::int(4) * &a) * &c)));
    let name_tex = latex(&n);
    let unit = crate::render::unit_tex(&coordinate_unit(problem, i, 1));
    let sign = ["-", "+"][which];
    // A second root of the same quadratic: the quadratic is said once, above.
    let same = |q: &crate::problem::Question| {
        matches!((&q.kind, &problem.questions[k].kind),
            (QuestionKind::Steady { zero: a, .. }, QuestionKind::Steady { zero: b, .. }) if a == b)
    };
    if problem.questions[..k].iter().any(same) {
        let mut steps = vec![step(
            format!(
                "The other root of the quadratic above: with {}, the sign ${sign}$ gives",
                known_tex(problem, &renaming, &(&a * &(&b * &c)), &v, &name)
            ),
            format!(
                "{name_tex} = {}\\ {unit}",
                super::answer_numbers::number_tex(roots[which])
            ),
        )];
        steps.extend(other_rates(problem, &renaming, unknowns, i, answer));
        return Some(steps);
    }
    let mut steps = vec![
        step(
            format!("The relation of answer {item}, in the statement's names, is a quadratic in ${name_tex}$:"),
            format!("{} = 0", latex_collected(&quadratic)),
        ),
        step(
            "Its roots are".into(),
            format!(
                "{name_tex} = \\frac{{{} \\mp \\sqrt{{{}}}}}{{{}}}",
                latex(&simplify(&-&b)),
                latex(&disc),
                latex(&simplify(&(&Expr::int(2) * &a)))
            ),
        ),
        step(
            format!(
                "With {}, the sign ${sign}$ gives this one (the other gives ${name_tex} = {}\\ {unit}$):",
                known_tex(problem, &renaming, &(&a * &(&b * &c)), &v, &name),
                super::answer_numbers::number_tex(roots[1 - which])
            ),
            format!("{name_tex} = {}\\ {unit}", super::answer_numbers::number_tex(roots[which])),
        ),
    ];
    steps.extend(other_rates(problem, &renaming, unknowns, i, answer));
    Some(steps)
}

/// Each other unknown rate from the names: φ̇ = ω₃ − Ω c_θ = … .
fn other_rates(
    problem: &Problem,
    renaming: &Renaming,
    unknowns: &[crate::problem::StateEntry],
    i: usize,
    answer: &Answer,
) -> Vec<AnswerStep> {
    let mut steps = Vec::new();
    for u in unknowns
        .iter()
        .filter(|u| u.coordinate != i && u.order == 1)
    {
        let symbol = problem.coordinate_symbol(u.coordinate, 1);
        if let Some((_, e)) = renaming.replaced.iter().find(|(s, _)| *s == symbol) {
            let unit = crate::render::unit_tex(&coordinate_unit(problem, u.coordinate, 1));
            steps.push(step(
                "and the other rate follows from the definitions in the statement:".into(),
                format!(
                    "{} = {} = {}\\ {unit}",
                    latex(&Expr::sym(symbol)),
                    latex(e),
                    super::answer_numbers::number_tex(answer.rates[u.coordinate])
                ),
            ));
        }
    }
    steps
}

/// `$\theta = 0.5$ rad, $\omega_{3} = 150$`: the values of the coordinates and names in
/// `e` other than `skip`, with the units the problem gives them.
fn known_tex(
    problem: &Problem,
    renaming: &Renaming,
    e: &Expr,
    v: &Values,
    skip: &Symbol,
) -> String {
    let mut parts = Vec::new();
    for i in 0..problem.coordinates.len() {
        let s = problem.coordinate_symbol(i, 0);
        if e.contains(&s) {
            let unit = crate::render::unit_tex(&coordinate_unit(problem, i, 0));
            let x = eval(&Expr::sym(s.clone()), v);
            parts.push(format!(
                "${} = {}\\ {unit}$",
                latex(&Expr::sym(s)),
                super::answer_numbers::number_tex(x)
            ));
        }
    }
    for (s, _) in &renaming.names {
        if s == skip || !e.contains(s) {
            continue;
        }
        let unit = name_unit(problem, renaming, s);
        parts.push(format!(
            "${} = {}{}$",
            latex(&Expr::sym(s.clone())),
            super::answer_numbers::number_tex(eval(&Expr::sym(s.clone()), v)),
            super::answer_numbers::unit_tex(&unit)
        ));
    }
    parts.join(", ")
}

/// A name's unit: that of the symbol it replaces (a rate's, a constant's).
fn name_unit(problem: &Problem, renaming: &Renaming, s: &Symbol) -> String {
    // The replacements are in order, a name's own rate first.
    let Some((replaced, _)) = (renaming.replaced.iter()).find(|(_, e)| e.contains(s)) else {
        return String::new();
    };
    match replaced {
        Symbol::Coord(name, order) => (problem.coordinates.iter())
            .position(|c| c.name.as_str() == &**name)
            .map(|i| coordinate_unit(problem, i, *order))
            .unwrap_or_default(),
        Symbol::Const(name) => (problem.constants.iter())
            .find(|c| c.name.as_str() == &**name)
            .and_then(|c| c.unit.clone())
            .unwrap_or_default(),
        _ => String::new(),
    }
}
