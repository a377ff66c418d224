//! The Answers point a reaction asked for to the free body of step 2 that draws it on the
//! body it acts on: where step 2 draws more than one free body, "free body D" tells the
//! student which picture shows the force found, its arrows along the positive senses.

use crate::problem::{Problem, QuestionKind};
use crate::render::context::FreeBody;
use crate::render::AnswerView;

/// The smallest free body that holds `body` and draws the reaction at the site whose name
/// in LaTeX is `site_tex` as a force of its own.
fn smallest_drawing<'f>(
    free_bodies: &'f [FreeBody],
    site_tex: &str,
    body: &str,
) -> Option<&'f FreeBody> {
    let mark = format!("^{{{site_tex}}}_");
    (free_bodies.iter())
        .filter(|b| b.bodies.split(" + ").any(|name| name == body))
        .filter(|b| {
            b.contact
                .iter()
                .any(|f| f.vector_tex.as_str().contains(&mark))
        })
        .min_by_key(|b| b.bodies.split(" + ").count())
}

/// Before each reaction's answer, the free body that shows it on the body it acts on,
/// where step 2 draws more than one.
pub fn point_to_free_bodies(
    problem: &Problem,
    free_bodies: &[FreeBody],
    shown: &[(String, String)],
    views: &mut [AnswerView],
) {
    if free_bodies.len() < 2 {
        return;
    }
    for (question, view) in problem.questions.iter().zip(views.iter_mut()) {
        let QuestionKind::Reaction { site } = question.kind else {
            continue;
        };
        let Some(body) = super::sense_words::carried_body(problem, site) else {
            continue;
        };
        let site_name = problem.site_name(site);
        let site_tex = crate::symbolic::latex_name(site_name);
        let Some(drawing) = smallest_drawing(free_bodies, &site_tex, problem.body_name(body))
        else {
            continue;
        };
        let on = super::force_labels::shown_name(problem.body_name(body), shown);
        // The note is plain text: names as the pictures print them.
        let point = super::force_labels::place(&super::force_labels::shown_name(site_name, shown));
        let bodies: Vec<String> = (drawing.bodies.split(" + "))
            .map(|b| super::force_labels::shown_name(b, shown))
            .collect();
        let text = format!(
            "Free body {} of step 2 shows this force on {on}, at {point}.",
            bodies.join(" + ")
        );
        view.note = match view.note.is_empty() {
            true => text,
            false => format!("{} {text}", view.note.trim_end()),
        };
    }
}
