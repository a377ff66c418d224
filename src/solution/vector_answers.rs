//! The answer to a vector `value` question (`v(P)`, `w(B)`): its components along the unit
//! vectors of the frame asked for (`N` unless `in` names another), in `answer`'s JSON, in
//! key.csv's columns and in the handout's Answers, each written as the dot product of the
//! vector with a unit vector of that frame.

use crate::numeric::{answer_unit, Answer, Quantity};
use crate::problem::{PointRef, Problem, Question, QuestionKind, VectorQuantity};
use crate::symbolic::{latex_name, latex_unit_vector};
use serde_json::{Map, Value};

/// The axis (`x`, `y`, `z`) of one component of a vector answer, named `v(P).x`.
pub(super) fn axis_of(found: &Quantity) -> &str {
    match found {
        Quantity::Named(name) => name.rsplit('.').next().unwrap_or("x"),
        Quantity::Reaction(_) => "x",
    }
}

/// `components`, `unit` and `frame` of `answer --format json`.
pub(super) fn record(
    problem: &Problem,
    question: &Question,
    answer: &Answer,
    out: &mut Map<String, Value>,
) {
    let mut components = Map::new();
    for (found, x) in &answer.values {
        components.insert(axis_of(found).into(), super::answer_numbers::number(*x));
    }
    if let Some((found, _)) = answer.values.first() {
        out.insert("unit".into(), answer_unit(problem, question, found).into());
    }
    out.insert("components".into(), Value::Object(components));
    if let Some(frame) = &answer.frame {
        out.insert("frame".into(), frame.as_str().into());
    }
}

/// A point as the handout names it: `P`, `B^{*}`, `B_{o}`.
fn point_tex(problem: &Problem, point: PointRef) -> String {
    match point {
        PointRef::Named(i) => super::tex::point_tex(&problem.points[i].name),
        PointRef::MassCenter(b) => super::tex::point_tex(&format!("{}*", problem.body_name(b))),
        PointRef::Origin(b) => format!("{}_{{o}}", latex_name(problem.body_name(b))),
        PointRef::Joint(j) => super::tex::point_tex(problem.site_name(j)),
    }
}

/// The vector as the handout writes it: `{}^{N}\mathbf{v}^{P}`, `{}^{N}\boldsymbol{\omega}^{B}`,
/// `\mathbf{r}^{P}` (from `N`'s origin).
pub(super) fn symbol_tex(problem: &Problem, quantity: VectorQuantity) -> String {
    let body = |b| latex_name(problem.body_name(b));
    match quantity {
        VectorQuantity::Position(p) => format!("\\mathbf{{r}}^{{{}}}", point_tex(problem, p)),
        VectorQuantity::Velocity(p) => {
            format!("{{}}^{{N}}\\mathbf{{v}}^{{{}}}", point_tex(problem, p))
        }
        VectorQuantity::Acceleration(p) => {
            format!("{{}}^{{N}}\\mathbf{{a}}^{{{}}}", point_tex(problem, p))
        }
        VectorQuantity::AngularVelocity(b) => {
            format!("{{}}^{{N}}\\boldsymbol{{\\omega}}^{{{}}}", body(b))
        }
        VectorQuantity::AngularAcceleration(b) => {
            format!("{{}}^{{N}}\\boldsymbol{{\\alpha}}^{{{}}}", body(b))
        }
    }
}

/// What a point or body is called in the question's words: `$P$`, the mass centre `$B^{*}$`,
/// body `$B$`.
fn of_what(problem: &Problem, quantity: VectorQuantity) -> String {
    match quantity {
        VectorQuantity::Position(p)
        | VectorQuantity::Velocity(p)
        | VectorQuantity::Acceleration(p) => match p {
            PointRef::MassCenter(_) => format!("the mass centre ${}$", point_tex(problem, p)),
            PointRef::Origin(b) if b == crate::problem::BodyId::GROUND => {
                format!("the fixed point ${}$", point_tex(problem, p))
            }
            _ => format!("point ${}$", point_tex(problem, p)),
        },
        VectorQuantity::AngularVelocity(b) | VectorQuantity::AngularAcceleration(b) => {
            format!("body ${}$", latex_name(problem.body_name(b)))
        }
    }
}

/// The question made from what it asks, when it has no `text`: "Find the velocity of point
/// $P$ in $N$, ${}^{N}\mathbf{v}^{P}$, along the unit vectors of $N$."
pub(super) fn asked(problem: &Problem, question: &Question) -> String {
    let QuestionKind::VectorValue { quantity, .. } = question.kind else {
        return String::new();
    };
    let frame = question
        .frame
        .map_or("N", |b| problem.body_name(b))
        .to_string();
    let place = match quantity {
        VectorQuantity::Position(_) => " from the fixed origin".to_string(),
        _ => " in $N$".to_string(),
    };
    format!(
        "Find {} of {}{place}, ${}$, along the unit vectors of ${}$.",
        quantity.noun(),
        of_what(problem, quantity),
        symbol_tex(problem, quantity),
        latex_name(&frame)
    )
}

/// The component `found` of the answer as the Answers write it: `{}^{N}\mathbf{v}^{P}
/// \cdot \hat{\mathbf{n}}_{x}`.
pub(super) fn component_tex(
    problem: &Problem,
    quantity: VectorQuantity,
    answer: &Answer,
    found: &Quantity,
) -> String {
    let frame = answer.frame.as_deref().unwrap_or("N");
    let axis = match axis_of(found) {
        "y" => 1,
        "z" => 2,
        _ => 0,
    };
    format!(
        "{} \\cdot {}",
        symbol_tex(problem, quantity),
        latex_unit_vector(frame, axis)
    )
}
