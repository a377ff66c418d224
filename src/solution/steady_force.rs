//! The force of a support on a single body in a steady motion, in closed form: with the
//! steady motion's conditions put in, the mass centre's acceleration of step 3, then
//! Newton's second law, the weight and the support's force being the body's only forces
//! (a heavy top's tip: F = m g n̂_z + m h sin θ Ω², toward the vertical axis). Written only
//! where its value at the answer's state agrees with the answer's components.

use crate::numeric::{Answer, Quantity, ReactionColumn};
use crate::problem::{BodyId, Question, QuestionKind};
use crate::render::text::{MarkupLine, Math};
use crate::render::AnswerStep;
use crate::symbolic::{eval, latex, simplify, substitute, ComponentKind, Expr, Symbol};
use crate::Worked;

fn step(text: String, math: String) -> AnswerStep {
    AnswerStep {
        text: MarkupLine::from(text),
        math: Math::from(math),
    }
}

/// The symbols the steady motion makes zero: every second derivative, and each rate that
/// is zero at the answer's state.
fn zeroed(worked: &Worked, answer: &Answer) -> Vec<Symbol> {
    let problem = worked.derivation.model.problem;
    let n = problem.coordinates.len();
    let rates = (0..n)
        .filter(|&i| answer.rates.get(i) == Some(&0.0))
        .map(|i| problem.coordinate_symbol(i, 1));
    rates
        .chain((0..n).map(|i| problem.coordinate_symbol(i, 2)))
        .collect()
}

/// The components the answer gives in `N`, by axis; `None` unless all three forces are.
fn answered(answer: &Answer) -> Option<[f64; 3]> {
    let mut found = [None; 3];
    for (quantity, value) in &answer.values {
        if let Quantity::Reaction(ReactionColumn::Component { kind, axis, .. }) = quantity {
            if *kind == ComponentKind::Force && *axis < 3 {
                found[*axis] = Some(*value);
            }
        }
    }
    Some([found[0]?, found[1]?, found[2]?])
}

/// The working of a reaction asked about a steady motion of a single body held by one
/// joint, under gravity alone; `None` for any other problem, or where the closed form
/// disagrees with the numbers.
/// Where `first` is false, the closed form was derived at an earlier answer: one short
/// sentence refers to it.
pub fn steps(
    worked: &Worked,
    question: &Question,
    answer: &Answer,
    first: bool,
) -> Option<Vec<AnswerStep>> {
    let model = &worked.derivation.model;
    let problem = model.problem;
    let QuestionKind::Reaction { site } = question.kind else {
        return None;
    };
    let about = problem.questions.get(question.about?)?;
    let alone = problem.bodies.len() == 1
        && problem.joints.len() == 1
        && problem.loads.is_empty()
        && problem.constraints.is_empty()
        && problem.closures.is_empty();
    let in_n = answer.frame.as_deref().is_none_or(|f| f == "N");
    if !matches!(about.kind, QuestionKind::Steady { .. }) || !alone || site != 0 || !in_n {
        return None;
    }
    let body = problem.joints[0].child;
    let state = &model.bodies[body.0];
    let zero = zeroed(worked, answer);
    let steady = |e: &Expr| simplify(&substitute(e, &|s| zero.contains(s).then(Expr::zero)));
    let acceleration = state.center.acceleration.map(steady);
    let weight = crate::mechanics::vector_of(problem.gravity.as_ref()?).scaled(&state.mass);
    let force = acceleration
        .scaled(&state.mass)
        .minus(&weight)
        .map(simplify);
    // Checked against the answer's numbers before it is written.
    let values = model.values_at(answer.time, &answer.q, &answer.rates);
    let found = force.components_in(BodyId::GROUND, &model.frames);
    let expected = answered(answer)?;
    let agrees = (0..3).all(|i| {
        let x = eval(&found[i], &values);
        (x - expected[i]).abs() <= 1e-6 * expected[i].abs().max(1.0)
    });
    if !agrees {
        return None;
    }
    if !first {
        return Some(vec![step(
            "The closed form above, with this motion's values, gives these components.".into(),
            String::new(),
        )]);
    }
    let conditions: Vec<String> = (zero.iter())
        .map(|s| format!("{} = 0", latex(&Expr::sym(s.clone()))))
        .collect();
    let m = latex(&state.mass);
    let name = format!(
        "\\mathbf{{F}}^{{\\mathrm{{{}}}}}",
        problem.site_name(site).replace('_', "\\_")
    );
    let a = "{}^{N}\\mathbf{a}^{*}";
    Some(vec![
        step(
            format!(
                "In the steady motion, ${}$. With these put in, the acceleration of the mass centre (step 4) is",
                conditions.join(",\\ ")
            ),
            format!("{a} = {}", shortest_tex(worked, &acceleration)),
        ),
        step(
            format!("The weight and the force at {} are the only forces on the body, so Newton's second law, ${name} + {m}\\,\\mathbf{{g}} = {m}\\,{a}$, gives", problem.site_name(site).replace('_', " ")),
            format!(
                "{name} = {m}\\,{a} - {m}\\,\\mathbf{{g}} = {}",
                shortest_tex(worked, &force)
            ),
        ),
        step(
            [
                "With the values of this steady motion put in, its components are those above.",
                &parts_words(model, (&force, site), &values, answer).unwrap_or_default(),
            ]
            .join(" ")
            .trim_end()
            .to_string(),
            String::new(),
        ),
    ])
}

/// The force's parts as a course states them, true at every instant of the steady
/// motion: its vertical part, and its horizontal part's size and sense (toward the
/// vertical through the support, where it points there); `None` where gravity is not
/// along a unit vector of `N` or the horizontal size has no short form.
fn parts_words(
    model: &crate::mechanics::Model,
    (force, site): (&crate::mechanics::Vector, usize),
    values: &crate::symbolic::Values,
    answer: &Answer,
) -> Option<String> {
    let problem = model.problem;
    let [(frame, axis, g)] = problem.gravity.as_ref()?.terms.as_slice() else {
        return None;
    };
    if *frame != BodyId::GROUND {
        return None;
    }
    let (axis, up) = (*axis as usize, -eval(g, values).signum());
    let c = force
        .components_in(BodyId::GROUND, &model.frames)
        .map(|e| simplify(&e));
    let others: Vec<usize> = (0..3).filter(|&k| k != axis).collect();
    let square = simplify(&crate::symbolic::add(others.iter().map(|&k| &c[k] * &c[k])));
    let sign = |e: &Expr| eval(e, values).signum();
    let horizontal =
        crate::symbolic::roots_of_squares(&simplify(&crate::symbolic::sqrt(square)), &sign);
    let written = latex(&horizontal);
    let size = others
        .iter()
        .map(|&k| eval(&c[k], values).powi(2))
        .sum::<f64>()
        .sqrt();
    let agrees = (eval(&horizontal, values) - size).abs() <= 1e-9 * size.max(1.0);
    if written.contains("sqrt") || !agrees || size < 1e-12 {
        return None;
    }
    // Toward the vertical through the support: against the mass centre's horizontal
    // offset from it.
    let place = model.sites.get(site)?;
    let centre = model.bodies[place.child.0]
        .center
        .position
        .minus(&place.point.position)
        .components_in(BodyId::GROUND, &model.frames)
        .map(|e| eval(&e, values));
    let offset = others
        .iter()
        .map(|&k| centre[k].powi(2))
        .sum::<f64>()
        .sqrt();
    let along: f64 = others
        .iter()
        .map(|&k| centre[k] * eval(&c[k], values))
        .sum();
    let toward = match offset > 1e-12 && along < -(1.0 - 1e-9) * offset * size {
        true => format!(
            ", toward the vertical through {}",
            super::force_labels::place(problem.site_name(site))
        ),
        false => String::new(),
    };
    // The same at every instant where it holds no coordinate that moves.
    let moving = (0..problem.coordinates.len())
        .filter(|&i| answer.rates.get(i).is_some_and(|r| *r != 0.0))
        .any(|i| horizontal.contains(&problem.coordinate_symbol(i, 0)));
    let always = if moving {
        ""
    } else {
        " at every instant of this motion"
    };
    let vertical = simplify(&(&c[axis] * &Expr::int(up as i64)));
    Some(format!(
        "That is, a vertical force ${}$ up and a horizontal force ${written}${toward}{always}.",
        latex(&vertical)
    ))
}

/// The vector in the one frame that writes it shortest.
fn shortest_tex(worked: &Worked, v: &crate::mechanics::Vector) -> String {
    let model = &worked.derivation.model;
    let written = (0..model.frames.len())
        .map(|k| v.expressed_in(BodyId(k), &model.frames).map(simplify))
        .min_by_key(|w| {
            w.parts()
                .iter()
                .flat_map(|(_, c)| c.iter().map(Expr::operation_count))
                .sum::<usize>()
        })
        .unwrap_or_else(|| v.clone());
    super::tex::vector_tex(model, &written)
}
