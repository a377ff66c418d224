//! A reaction answered in a moving body's unit vectors (a pin's force in the wheel's ŵ_x,
//! ŵ_y) says how those unit vectors lie at that instant, so that its components can be
//! read in the ground's directions: "At this instant ŵ_x = n̂_x and ŵ_y = n̂_y."

use crate::mechanics::Vector;
use crate::problem::{BodyId, QuestionKind};
use crate::render::{AnswerStep, AnswerView};
use crate::symbolic::{eval, fixed, latex_unit_vector, Expr, Symbol};
use crate::Worked;

/// Under each planar reaction's answer at the start given in a moving frame's unit vectors,
/// that frame's x and y unit vectors in the ground's at the initial state.
pub fn attach(worked: &Worked, views: &mut [AnswerView]) {
    let model = &worked.derivation.model;
    let problem = model.problem;
    if !model.is_planar() {
        return;
    }
    let values = model.values_at(0.0, &worked.q0, &worked.rates0);
    let ground = model.frames.name(BodyId::GROUND).to_string();
    for (question, view) in problem.questions.iter().zip(views.iter_mut()) {
        let QuestionKind::Reaction { site } = question.kind else {
            continue;
        };
        let at_start = question.at.state.is_none()
            && question.at.time.is_none_or(|t| t == 0.0)
            && question.at.switch.is_none()
            && !question.at.after_impact;
        let Some(frame) = model.sites.get(site).map(|s| s.parent) else {
            continue;
        };
        let name = model.frames.name(frame).to_string();
        let unit = |axis: u8| latex_unit_vector(&name, axis);
        let in_it = (view.values_tex.iter()).any(|v| v.as_str().contains(&unit(0)));
        if !at_start || frame == BodyId::GROUND || !in_it {
            continue;
        }
        // The frame's x and y unit vectors in the ground's components, converted once.
        let columns: [[Expr; 3]; 2] = std::array::from_fn(|axis| {
            let mut c = [Expr::zero(), Expr::zero(), Expr::zero()];
            c[axis] = Expr::one();
            Vector::new(frame, c).components_in(BodyId::GROUND, &model.frames)
        });
        let along = |axis: usize| {
            let c = &columns[axis];
            [eval(&c[0], &values), eval(&c[1], &values)]
        };
        // A frame that only translates lies so at every instant, not at this one alone.
        let turns =
            (columns.iter().flatten()).any(|e| e.any_symbol(&|s| matches!(s, Symbol::Coord(..))));
        let sums: Vec<String> = (0..2)
            .map(|axis| {
                let written = in_ground(along(axis), &ground);
                format!("{} = {written}", unit(axis as u8))
            })
            .collect();
        view.steps.push(AnswerStep {
            text: match turns {
                true => format!("At this instant ${}$ and ${}$.", sums[0], sums[1]),
                false => format!("${}$ and ${}$: {name} does not turn.", sums[0], sums[1]),
            }
            .into(),
            math: String::new().into(),
        });
    }
}

/// `c n̂x + s n̂y` with the numbers as the answers print them, a zero term left out and a
/// unit coefficient written as its sign.
fn in_ground(c: [f64; 2], ground: &str) -> String {
    let mut out = String::new();
    for (axis, &value) in c.iter().enumerate() {
        if value.abs() < 1e-12 {
            continue;
        }
        let unit = latex_unit_vector(ground, axis as u8);
        let size = match (value.abs() - 1.0).abs() < 1e-12 {
            true => String::new(),
            false => format!("{} ", fixed(value.abs())),
        };
        let sign = match (value < 0.0, out.is_empty()) {
            (true, true) => "-",
            (true, false) => " - ",
            (false, true) => "",
            (false, false) => " + ",
        };
        out.push_str(&format!("{sign}{size}{unit}"));
    }
    if out.is_empty() {
        out.push('0');
    }
    out
}
