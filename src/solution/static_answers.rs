//! The answers of the questions of statics (`slips`, `tips`, `impending`): their JSON for
//! `answer`, and their lines and notes in the handout's Answers, which say in words what
//! the numbers decide and, of several impending motions, which happens first.

use crate::numeric::Answer;
use crate::problem::{Problem, Question, QuestionKind};
use crate::symbolic::fixed;
use serde_json::{Map, Value};

/// The one value of a statics answer (the ratio, the normal force, the constant).
fn value(answer: &Answer) -> f64 {
    answer.values.first().map_or(f64::NAN, |(_, x)| *x)
}

/// Whether a `slips` answer slips: in motion, a slip speed that is not zero; else (and
/// at rest) |F| > μ|N|, or a normal force that would have to pull (the contact is lost,
/// and friction cannot hold it).
pub fn slips(answer: &Answer) -> bool {
    slip_speed(answer).is_some_and(|s| s > 0.0) || value(answer) > 1.0 || lost(answer)
}

/// Whether a `slips` answer's contact is lost: its normal force would have to pull.
pub fn lost(answer: &Answer) -> bool {
    crate::numeric::contact_lost(&answer.values)
}

/// A `slips` answer's normal force, where it has one.
fn normal(answer: &Answer) -> Option<f64> {
    (answer.values.iter())
        .find(|(q, _)| q.to_string() == "normal")
        .map(|(_, x)| *x)
}

/// The slip speed of a `slips` answer asked in motion; `None` at rest.
pub fn slip_speed(answer: &Answer) -> Option<f64> {
    crate::numeric::slip_speed(&answer.values)
}

/// Whether a `tips` answer tips: the normal force would have to pull.
pub fn tips(answer: &Answer) -> bool {
    value(answer) < 0.0
}

/// The yes or no of a `slips` or `tips` answer and what decides it, in words, for
/// `answer`'s text; `None` for any other question.
pub fn verdict_words(question: &Question, answer: &Answer) -> Option<&'static str> {
    Some(match &question.kind {
        QuestionKind::Slips { .. } if lost(answer) => {
            "yes: the normal force would have to pull, so the contact is lost and no friction can hold it"
        }
        QuestionKind::Slips { .. } if slip_speed(answer).is_some_and(|s| s > 0.0) => {
            "yes: the contact point slides, and friction is mu times the normal force, against the slip"
        }
        QuestionKind::Slips { .. } if slips(answer) => "yes: holding it needs |F| > mu |N|",
        QuestionKind::Slips { .. } => "no: friction can hold it, |F| <= mu |N|",
        QuestionKind::Tips { .. } if tips(answer) => {
            "yes: the contact is lost, as its normal force would have to pull, N < 0"
        }
        QuestionKind::Tips { .. } => "no: the contact holds, as its normal force pushes, N >= 0",
        _ => return None,
    })
}

/// `answer --format json`'s fields of a statics answer, added to `out`.
pub fn record(
    problem: &Problem,
    question: &Question,
    answer: &Answer,
    out: &mut Map<String, Value>,
) {
    let number = super::answer_numbers::number;
    match &question.kind {
        QuestionKind::Slips { site } => {
            out.insert("value".into(), slips(answer).into());
            out.insert("ratio".into(), number(value(answer)));
            if let Some(speed) = slip_speed(answer) {
                out.insert("slip_speed".into(), number(speed));
            }
            if let Some(n) = normal(answer) {
                out.insert("normal".into(), number(n));
                out.insert("contact_lost".into(), lost(answer).into());
            }
            out.insert("site".into(), problem.site_name(*site).into());
        }
        QuestionKind::Tips { site } => {
            out.insert("value".into(), tips(answer).into());
            out.insert("normal".into(), number(value(answer)));
            out.insert("unit".into(), "N".into());
            out.insert("site".into(), problem.site_name(*site).into());
        }
        QuestionKind::Impending {
            site,
            tips,
            constant,
            ..
        } => {
            out.insert("value".into(), number(value(answer)));
            let unit = problem.constants[*constant]
                .unit
                .clone()
                .unwrap_or_default();
            out.insert("unit".into(), unit.into());
            out.insert(
                "constant".into(),
                problem.constants[*constant].name.clone().into(),
            );
            out.insert("site".into(), problem.site_name(*site).into());
            out.insert("impends".into(), if *tips { "tip" } else { "slip" }.into());
        }
        _ => {}
    }
}

/// The question made from what it asks, when it has no `text`.
pub fn asked(problem: &Problem, question: &Question) -> String {
    match &question.kind {
        QuestionKind::Slips { site } => format!(
            "Can friction at {} hold the system at rest?",
            super::force_labels::place(problem.site_name(*site))
        ),
        QuestionKind::Tips { site } => format!(
            "Does the contact at {} hold at rest, or does the body tip off it?",
            super::force_labels::place(problem.site_name(*site))
        ),
        QuestionKind::Impending {
            constant,
            site,
            tips,
            ..
        } => format!(
            "Find the value of ${}$ at which {} impends at {}.",
            constant_tex(problem, *constant),
            if *tips { "tipping" } else { "slip" },
            super::force_labels::place(problem.site_name(*site))
        ),
        _ => String::new(),
    }
}

fn constant_tex(problem: &Problem, constant: usize) -> String {
    crate::symbolic::latex(&crate::symbolic::Expr::constant(
        &problem.constants[constant].name,
    ))
}

/// The answer's line of math.
pub fn value_tex(problem: &Problem, question: &Question, answer: &Answer) -> String {
    let x = value(answer);
    let number = |x: f64| {
        if x.is_finite() {
            fixed(x)
        } else {
            "\\infty".into()
        }
    };
    match &question.kind {
        QuestionKind::Slips { .. } if lost(answer) => format!(
            "F_{{n}} = {}\\ \\mathrm{{N}} < 0",
            number(normal(answer).unwrap_or(f64::NAN))
        ),
        QuestionKind::Slips { .. } if slip_speed(answer).is_some_and(|s| s > 0.0) => format!(
            "v_{{\\mathrm{{slip}}}} = {}\\ \\mathrm{{m/s}} \\neq 0",
            number(slip_speed(answer).unwrap_or(0.0))
        ),
        QuestionKind::Slips { .. } => format!(
            "\\frac{{|F_{{t}}|}}{{\\mu |F_{{n}}|}} = {} {} 1",
            number(x),
            if slips(answer) { ">" } else { "\\le" }
        ),
        QuestionKind::Tips { .. } => format!(
            "F_{{n}} = {}\\ \\mathrm{{N}} {} 0",
            number(x),
            if tips(answer) { "<" } else { "\\ge" }
        ),
        QuestionKind::Impending { constant, .. } => {
            let unit = problem.constants[*constant]
                .unit
                .clone()
                .unwrap_or_default();
            let unit = crate::render::unit_tex(&unit);
            let unit = if unit.is_empty() {
                unit
            } else {
                format!("\\ {unit}")
            };
            format!("{} = {}{unit}", constant_tex(problem, *constant), number(x))
        }
        _ => String::new(),
    }
}

/// What the number decides, as a line of math in words: "it does not slip".
pub fn verdict_tex(problem: &Problem, question: &Question, answer: &Answer) -> String {
    let site = |i: usize| super::force_labels::place(problem.site_name(i)).replace('_', "\\_");
    match &question.kind {
        QuestionKind::Slips { site: i } if lost(answer) => format!(
            "\\text{{the contact at {} would have to pull: contact is lost, and no friction can hold it}}",
            site(*i)
        ),
        QuestionKind::Slips { site: i } if slip_speed(answer).is_some() => {
            moving_verdict(&site(*i), answer)
        }
        QuestionKind::Slips { site: i } => match slips(answer) {
            false => format!(
                "\\text{{friction at {} can hold it: it does not slip}}",
                site(*i)
            ),
            true => format!(
                "\\text{{rest needs more friction at {} than }} \\mu |F_{{n}}| \\text{{: it slips}}",
                site(*i)
            ),
        },
        QuestionKind::Tips { site: i } => tips_verdict(&site(*i), answer),
        QuestionKind::Impending {
            site: i,
            tips: true,
            ..
        } => {
            format!(
                "\\text{{the normal force at {} falls to zero: tipping impends}}",
                site(*i)
            )
        }
        QuestionKind::Impending { site: i, .. } => {
            format!("|F_{{t}}| = \\mu |F_{{n}}| \\text{{ at {}: slip impends}}", site(*i))
        }
        _ => String::new(),
    }
}

/// What decides a `tips`: at rest, or (where no equilibrium is near) as the motion
/// starts, whether the contact's normal force pushes (it holds) or would have to pull
/// (the contact is lost, and the body tips off it).
fn tips_verdict(site: &str, answer: &Answer) -> String {
    let when = match slip_speed(answer) {
        Some(_) => "as the motion starts",
        None => "at rest",
    };
    match tips(answer) {
        false => format!(
            "\\text{{no: {when} the contact at {site} pushes, so it holds: the body does not tip}}"
        ),
        true => format!(
            "\\text{{yes: {when} the contact at {site} would have to pull, so it is lost: the body tips}}"
        ),
    }
}

/// What decides a `slips` asked in motion: the contact point slides (yes), or it does not
/// and friction can hold it (no), or sticking would need more than μ|N| (yes).
fn moving_verdict(site: &str, answer: &Answer) -> String {
    match (slip_speed(answer).is_some_and(|s| s > 0.0), slips(answer)) {
        (true, _) => format!(
            "\\text{{yes: the contact point at {site} slides, so friction is }} \\mu \\text{{ times the normal force, against the slip}}"
        ),
        (false, false) => format!(
            "\\text{{no: the contact point at {site} does not slide, and }} |F_{{t}}| \\le \\mu |F_{{n}}|"
        ),
        (false, true) => format!(
            "\\text{{yes: rolling at {site} would need }} |F_{{t}}| > \\mu |F_{{n}}|"
        ),
    }
}

/// The note under a statics answer: for an impending motion, of those found for the same
/// constant on the same side of its value, which comes first (empty otherwise).
pub fn note(problem: &Problem, index: usize, answers: &[Answer]) -> String {
    match &problem.questions[index].kind {
        QuestionKind::Impending { constant, .. } => first(problem, index, *constant, answers),
        _ => String::new(),
    }
}

/// "As P grows from 10 N, tipping at back impends first (P = 19.62 N), before slip at
/// front (P = 39.24 N)."; empty when this is the only impending motion on its side.
fn first(problem: &Problem, index: usize, constant: usize, answers: &[Answer]) -> String {
    let c = &problem.constants[constant];
    let given = c.value;
    let mine = value(&answers[index]);
    let rising = mine >= given;
    let mut found: Vec<(f64, String)> = (problem.questions.iter().zip(answers))
        .filter_map(|(q, a)| match q.kind {
            QuestionKind::Impending {
                constant: k,
                site,
                tips,
                ..
            } if k == constant => {
                let x = value(a);
                let what = if tips { "tipping" } else { "slip" };
                (x.is_finite() && (x >= given) == rising)
                    .then(|| (x, format!("{what} at {}", problem.site_name(site))))
            }
            _ => None,
        })
        .collect();
    if found.len() < 2 {
        return String::new();
    }
    found.sort_by(|a, b| match rising {
        true => a.0.total_cmp(&b.0),
        false => b.0.total_cmp(&a.0),
    });
    let unit = c.unit.clone().map(|u| format!(" {u}")).unwrap_or_default();
    let at = |(x, what): &(f64, String)| format!("{what} ({} = {}{unit})", c.name, fixed(*x));
    let rest: Vec<String> = found[1..].iter().map(at).collect();
    format!(
        "As {} {} from {}{unit}, {} impends first, before {}.",
        c.name,
        if rising { "grows" } else { "falls" },
        fixed(given),
        at(&found[0]),
        rest.join(", ")
    )
}
