//! The equation of motion of the one coordinate left, derived from the energies: the
//! velocity constraints give every other rate through the independent one
//! (`ẏ = −x ẋ/y`, `θ̇ = (R − r) ẋ/(r y)`), so that `T = ½ M(x) ẋ²` and `V(x)`; along
//! the motion the dependent coordinates follow `x` (`dy/dx = ẏ/ẋ`), and Lagrange's
//! equation for `x` alone, `M ẍ + ½ (dM/dx) ẋ² + dV/dx = 0`, is the equation free of the
//! reactions. Written only where it equals Kane's equation for the independent speed at
//! the states given: the constraint forces then do no work and no load lacks a potential.

use crate::equations::{Derivation, LinearSystem};
use crate::mechanics::DependentSpeeds;
use crate::numeric::Answer;
use crate::render::AnswerStep;
use crate::symbolic::{
    add, eval, latex, latex_collected, latex_factored as factored, partial, roots_of_squares,
    simplify, substitute, Expr, Node, Number, Symbol, Values,
};

fn step(text: impl Into<String>, math: impl Into<String>) -> AnswerStep {
    AnswerStep {
        text: text.into().into(),
        math: math.into().into(),
    }
}

/// The rates of the dependent coordinates through the independent one: for each, its
/// index and `ẏ/ẋ`.
fn ratios(derivation: &Derivation, k: usize) -> Option<Vec<(usize, Expr)>> {
    let speeds = DependentSpeeds::written(&derivation.model).ok()??;
    let plain = speeds.independent == [k]
        && speeds.prescribed.is_empty()
        && !speeds.at_each_state
        && speeds.rest.iter().all(|r| simplify(r).is_zero());
    if !plain {
        return None;
    }
    let relations = &derivation.model.constraints.relations;
    let on_motion = |e: &Expr| {
        relations
            .iter()
            .fold(simplify(e), |e, (_, relation)| relation.reduce(&e))
    };
    Some(
        (speeds.dependent.iter().zip(&speeds.c))
            .map(|(&i, row)| (i, on_motion(&row[0])))
            .collect(),
    )
}

/// `de/dx` along the motion: `∂e/∂x + Σ ∂e/∂q_s · (q̇_s/ẋ)`.
fn along(derivation: &Derivation, k: usize, ratios: &[(usize, Expr)], e: &Expr) -> Option<Expr> {
    let problem = derivation.model.problem;
    let mut terms = vec![partial(e, &problem.coordinate_symbol(k, 0)).ok()?];
    for (i, c) in ratios {
        let d = partial(e, &problem.coordinate_symbol(*i, 0)).ok()?;
        if !d.is_zero() {
            terms.push(&d * c);
        }
    }
    let relations = &derivation.model.constraints.relations;
    Some(
        relations
            .iter()
            .fold(simplify(&add(terms)), |e, (_, relation)| {
                relation.reduce(&e)
            }),
    )
}

/// `de/dx` written as the chain rule: `∂e/∂x + (∂e/∂y)(dy/dx)`, each part that is not zero.
fn along_tex(
    derivation: &Derivation,
    k: usize,
    ratios: &[(usize, Expr)],
    e: &Expr,
) -> Option<String> {
    let problem = derivation.model.problem;
    let wrap = |e: &Expr| match e.terms().len() > 1 || latex(e).starts_with('-') {
        true => format!("\\left({}\\right)", latex_collected(e)),
        false => latex_collected(e),
    };
    let mut parts = Vec::new();
    let own = simplify(&partial(e, &problem.coordinate_symbol(k, 0)).ok()?);
    if !own.is_zero() {
        parts.push(latex_collected(&own));
    }
    for (i, c) in ratios {
        let d = simplify(&partial(e, &problem.coordinate_symbol(*i, 0)).ok()?);
        if !d.is_zero() {
            parts.push(format!("{} {}", wrap(&d), wrap(c)));
        }
    }
    Some(parts.join(" + ").replace("+ -", "- "))
}

/// The bases of the negative powers among the factors of `e` that vary: `y` in `−x/y`.
fn vanishing(e: &Expr, into: &mut Vec<Expr>) {
    let factors: Vec<Expr> = match e.node() {
        Node::Mul(_) => e.factors().to_vec(),
        _ => vec![e.clone()],
    };
    for f in factors {
        if let Node::Pow(base, exponent) = f.node() {
            let negative = match exponent.as_number() {
                Some(Number::Ratio(n, _)) => n < 0,
                Some(Number::Real(x)) => x < 0.0,
                None => false,
            };
            if negative && !base.is_constant() && !into.contains(base) {
                into.push(base.clone());
            }
        }
    }
}

/// The steps from the energies to `M q̈ = f` for the one coordinate `k` left, `m` and `f`
/// Kane's mass and right side for its speed; `None` where the reduction does not apply or
/// does not give Kane's equation at every one of `states` (time and coordinates, each on
/// the constraints, the state of the oscillations first), with the rates the constraints
/// allow.
pub fn steps(
    derivation: &Derivation,
    k: usize,
    (m, f): (&Expr, &Expr),
    states: &[(f64, &[f64])],
    lead: &str,
) -> Option<Vec<AnswerStep>> {
    let model = &derivation.model;
    let problem = model.problem;
    let ratios = ratios(derivation, k)?;
    let states = at_states(derivation, k, &ratios, states);
    let states = states.as_slice();
    let (q, qd) = (
        problem.coordinate_symbol(k, 0),
        problem.coordinate_symbol(k, 1),
    );
    let rate = Expr::sym(qd.clone());
    let bodies = crate::equations::energy_terms(model);
    let kinetic = simplify(&add(bodies.iter().map(|b| b.kinetic())));
    let v = simplify(&crate::equations::potential(model));
    let reduced = rates_put_in(derivation, &ratios, &kinetic, &rate);
    let mass = partial(&partial(&reduced, &qd).ok()?, &qd).ok()?;
    let dm = along(derivation, k, &ratios, m)?;
    let dv = along(derivation, k, &ratios, &v)?;
    let half = Expr::ratio(1, 2);
    let rhs = simplify(&(-(&(&(&half * &dm) * &(&rate * &rate)) + &dv)));
    let same = |a: &Expr, b: &Expr| crate::mechanics::same_at(a, b, states);
    let t_half = &(&half * m) * &(&rate * &rate);
    if states.is_empty() || !same(&mass, m) || !same(&reduced, &t_half) || !same(&rhs, f) {
        return None;
    }
    let sign = super::tex::initial_sign(model);
    let tex = |e: &Expr| latex_collected(&roots_of_squares(&simplify(e), &sign));
    let (q_tex, qd_tex, qdd_tex) = (
        latex(&Expr::sym(q.clone())),
        latex(&rate),
        latex(&problem.coordinate_expr(k, 2)),
    );
    let rates_tex: Vec<String> = (ratios.iter())
        .map(|(i, c)| {
            format!(
                "{} = {}",
                latex(&problem.coordinate_expr(*i, 1)),
                latex_collected(&simplify(&(c * &rate)))
            )
        })
        .collect();
    // The coordinates that follow x in M or V, with dq/dx.
    let follows: Vec<String> = (ratios.iter())
        .filter(|(i, _)| {
            let s = problem.coordinate_symbol(*i, 0);
            m.contains(&s) || v.contains(&s)
        })
        .map(|(i, c)| {
            let name = latex(&problem.coordinate_expr(*i, 0));
            format!(
                "$\\mathrm{{d}}{name}/\\mathrm{{d}}{q_tex} = {}/{qd_tex} = {}$",
                latex(&problem.coordinate_expr(*i, 1)),
                latex_collected(c)
            )
        })
        .collect();
    let relations: Vec<String> = (model.constraints.relations.iter())
        .map(|(_, relation)| format!("${}$", relation.latex()))
        .collect();
    let on_relations = match relations.is_empty() {
        true => String::new(),
        false => format!(" with {} on the motion", relations.join(" and ")),
    };
    let d = |e: &str| format!("\\frac{{\\mathrm{{d}} {e}}}{{\\mathrm{{d}} {q_tex}}}");
    let mut out = vec![
        step(
            format!("{lead} The velocity constraints of step 1 give the other rates through ${qd_tex}$:"),
            rates_tex.join(", \\qquad "),
        ),
        step(
            format!("Put into the kinetic energy{on_relations}, $T = \\frac{{1}}{{2}} M \\, {qd_tex}^{{2}}$ with $M$ free of the rates; the potential energy is $V$:"),
            format!(
                "T = {} = {} \\, {qd_tex}^{{2}}, \\qquad V = {}",
                tex(&kinetic),
                factored(&simplify(&(&half * m))),
                tex(&v)
            ),
        ),
    ];
    let chain = |e: &Expr, de: &Expr| -> Option<String> {
        let written = along_tex(derivation, k, &ratios, e)?;
        let done = tex(de);
        Some(match written == done {
            true => done,
            false => format!("{written} = {done}"),
        })
    };
    let dm_dv = format!(
        "{} = {}, \\qquad {} = {}",
        d("M"),
        chain(m, &dm)?,
        d("V"),
        chain(&v, &dv)?
    );
    out.push(match follows.is_empty() {
        true => step("Their derivatives with respect to the coordinate:", dm_dv),
        false => step(
            format!(
                "Along the motion the other coordinates follow ${q_tex}$, {}; by the chain rule",
                follows.join(", ")
            ),
            dm_dv,
        ),
    });
    out.push(step(
        format!(
            "Lagrange's equation for ${q_tex}$ alone, with $\\partial T/\\partial {qd_tex} = M {qd_tex}$, whose rate is $M {qdd_tex} + {} \\, {qd_tex}^{{2}}$, and $\\partial T/\\partial {q_tex} = \\frac{{1}}{{2}} {} \\, {qd_tex}^{{2}}$:",
            d("M"),
            d("M")
        ),
        format!(
            "M {qdd_tex} + \\frac{{1}}{{2}} {} \\, {qd_tex}^{{2}} + {} = 0",
            d("M"),
            d("V")
        ),
    ));
    out.push(step(
        "that is, the equation of motion free of the reactions:",
        format!("{} \\, {qdd_tex} = {}", factored(m), latex_collected(f)),
    ));
    out.extend(singular_note(&ratios, m, states, &q_tex));
    Some(out)
}

/// The states on the constraints the answers are at, the period's own first: where the
/// equation from the energies is checked against Kane's.
pub fn on_motion<'a>(answer: &'a Answer, answers: &'a [Answer]) -> Vec<(f64, &'a [f64])> {
    let mut states = vec![(answer.time, answer.q.as_slice())];
    states.extend(answers.iter().map(|a| (a.time, a.q.as_slice())));
    states
}

/// The equation `M q̈ = f` of the one coordinate `k` left (Kane's row `row` of `system`),
/// derived: from the energies in that coordinate alone, or, by Kane's method, said to be
/// the row of step 5 for its speed.
pub fn equation_steps(
    derivation: &Derivation,
    system: &LinearSystem,
    (row, k): (usize, usize),
    (m, f): (&Expr, &Expr),
    states: &[(f64, &[f64])],
) -> (Vec<AnswerStep>, bool) {
    let problem = derivation.model.problem;
    let q_tex = latex(&problem.coordinate_expr(k, 0));
    let equation = format!(
        "{} \\, {} = {}",
        factored(m),
        latex(&problem.coordinate_expr(k, 2)),
        latex_collected(f)
    );
    if derivation.method == crate::equations::Method::Kane {
        // Kane's row for the independent speed holds no constraint force, and its
        // dependent accelerations are put in from the differentiated relations there.
        let own = std::ptr::eq(system, &derivation.system) || system.a == derivation.system.a;
        let which = match own && derivation.rows.len() == system.a.len() {
            true => format!("row ({}) of step 5", row + 1),
            false => "Kane's equation for its speed".to_string(),
        };
        let why = match derivation.dependent_speeds.is_some() {
            true => ": the constraint forces do no work with its partial velocities, and the other accelerations were put in there from the relations of the dependent rates differentiated. It reads",
            false => ", which holds no reaction:",
        };
        let text = format!("One degree of freedom is left, ${q_tex}$. Its equation of motion free of the reactions is already {which}{why}");
        return (vec![step(text, equation)], false);
    }
    let lead = match derivation.method {
        crate::equations::Method::Lagrange => format!("One degree of freedom is left, ${q_tex}$. The multipliers and the other accelerations drop out when $T$ and $V$ are written in ${q_tex}$ and Lagrange's equation is taken for ${q_tex}$ alone."),
        _ => format!("One degree of freedom is left, ${q_tex}$. Eliminating the reactions and the other accelerations from the rows of step 5 gives the equation that the energies written in ${q_tex}$ give, more shortly: the constraint forces do no work in the motions the constraints allow."),
    };
    match steps(derivation, k, (m, f), states, &lead) {
        Some(steps) => (steps, true),
        None => (vec![step(
            format!("One degree of freedom is left, ${q_tex}$. Its equation of motion free of the reactions (the equations of step 5 with the reactions and the other accelerations eliminated) is"),
            equation,
        )], false),
    }
}

/// What `K` is, in the linearization's sentence, defined once: from the energies,
/// `d²V/dx²` at the state (the right side's term in the rate squared vanishes at rest, and
/// the rest of its derivative is this); otherwise minus the derivative of the right side.
pub fn k_words(energies: bool, q_tex: &str) -> String {
    match energies {
        true => format!("$K = \\mathrm{{d}}^{{2}} V/\\mathrm{{d}} {q_tex}^{{2}}$"),
        false => format!("$K$ is minus the derivative of the right side with respect to ${q_tex}$"),
    }
}

/// The states to check at: each of `states` with the independent rate 0.7 and the others
/// as the constraints give them.
fn at_states(
    derivation: &Derivation,
    k: usize,
    ratios: &[(usize, Expr)],
    states: &[(f64, &[f64])],
) -> Vec<Values> {
    let model = &derivation.model;
    (states.iter())
        .map(|&(t, q)| {
            let mut rates = vec![0.0; q.len()];
            rates[k] = 0.7;
            let at = model.values_at(t, q, &rates);
            for (i, c) in ratios {
                rates[*i] = 0.7 * eval(c, &at);
            }
            model.values_at(t, q, &rates)
        })
        .collect()
}

/// `e` with every dependent rate written through the independent one, `rate`.
fn rates_put_in(derivation: &Derivation, ratios: &[(usize, Expr)], e: &Expr, rate: &Expr) -> Expr {
    let problem = derivation.model.problem;
    simplify(&substitute(e, &|s| {
        let Symbol::Coord(name, 1) = s else {
            return None;
        };
        let i = (problem.coordinates.iter()).position(|c| c.name.as_str() == &**name)?;
        let (_, c) = ratios.iter().find(|(j, _)| *j == i)?;
        Some(c * rate)
    }))
}

/// Where the forms of the dependent rates and of `M` are singular, `y ≠ 0`, and whether
/// the state of the oscillations (the first of `states`) is away from there.
fn singular_note(
    ratios: &[(usize, Expr)],
    m: &Expr,
    states: &[Values],
    q_tex: &str,
) -> Option<AnswerStep> {
    let mut singular = Vec::new();
    for (_, c) in ratios {
        vanishing(c, &mut singular);
    }
    vanishing(m, &mut singular);
    if singular.is_empty() {
        return None;
    }
    let at_state = states.first();
    let away = at_state.is_some_and(|s| singular.iter().all(|b| eval(b, s).abs() > 1e-9));
    let list: Vec<String> = singular
        .iter()
        .map(|b| format!("${} \\neq 0$", latex_collected(b)))
        .collect();
    let zero: Vec<String> = singular
        .iter()
        .map(|b| format!("${} = 0$", latex_collected(b)))
        .collect();
    let tail = match away {
        true => " The state of the small oscillations is away from there.",
        false => "",
    };
    Some(step(
        format!(
            "These forms hold wherever {}; where {}, ${q_tex}$ does not fix the other rates.{tail}",
            list.join(" and "),
            zero.join(" or ")
        ),
        String::new(),
    ))
}
