//! The units and names an answer's values are reported with: what the handout prints
//! after a number and `mbd-tutor answer` reports.

use super::quantity::Quantity;
use crate::problem::{CoordinateKind, Problem, Question, QuestionKind, StateEntry};

/// The unit of the value `name` of `answer`'s question: what the handout prints after the
/// number and `mbd-tutor answer` reports. A `value`'s is its `unit`, else the unit of the
/// coordinate or rate it is, else none; a reaction's force is in N and its moment in N m;
/// a drive is a torque (an angle's) or a force (a distance's); a steady motion's unknown
/// has its coordinate's unit, per second for a rate.
pub fn unit(problem: &Problem, question: &Question, found: &Quantity) -> String {
    match &question.kind {
        QuestionKind::Value { expression, .. } => question
            .unit
            .clone()
            .or_else(|| {
                (0..problem.coordinates.len()).find_map(|i| {
                    (0..3u8).find_map(|order| {
                        (*expression == problem.coordinate_expr(i, order))
                            .then(|| coordinate_unit(problem, i, order))
                    })
                })
            })
            .unwrap_or_default(),
        QuestionKind::VectorValue { quantity, .. } => question
            .unit
            .clone()
            .unwrap_or_else(|| quantity.unit().into()),
        QuestionKind::Reaction { .. } => {
            if matches!(found, Quantity::Reaction(column) if column.is_moment()) {
                "N m".into()
            } else {
                "N".into()
            }
        }
        QuestionKind::Drive { coordinate } => match problem.coordinates[*coordinate].kind {
            CoordinateKind::Angle => "N m".into(),
            CoordinateKind::Distance => "N".into(),
        },
        QuestionKind::Period { .. } => "s".into(),
        QuestionKind::Show { .. } => question.unit.clone().unwrap_or_default(),
        QuestionKind::Steady { unknowns, .. } => {
            let entry = unknowns
                .iter()
                .find(|e| matches!(found, Quantity::Named(name) if entry_name(problem, e) == *name))
                .copied()
                .unwrap_or(StateEntry {
                    coordinate: 0,
                    order: 0,
                });
            coordinate_unit(problem, entry.coordinate, entry.order)
        }
        QuestionKind::Describe { coordinate, .. } => match found {
            Quantity::Named(name) => super::describe_answer::unit(problem, *coordinate, name),
            _ => String::new(),
        },
        QuestionKind::Slips { .. } => String::new(),
        QuestionKind::Tips { .. } => "N".into(),
        QuestionKind::Impending { constant, .. } | QuestionKind::Stability { constant, .. } => {
            problem.constants[*constant]
                .unit
                .clone()
                .unwrap_or_default()
        }
    }
}

/// `theta` or `theta'`: a steady motion's unknown as [`Answer::values`](super::answers::Answer::values) names it.
pub fn entry_name(problem: &Problem, e: &StateEntry) -> String {
    let name = &problem.coordinates[e.coordinate].name;
    if e.order == 0 {
        name.clone()
    } else {
        format!("{name}'")
    }
}

/// The unit of coordinate `i` differentiated `order` times: its `unit`, else rad or m.
pub fn coordinate_unit(problem: &Problem, i: usize, order: u8) -> String {
    let c = &problem.coordinates[i];
    let base = match (&c.unit, c.kind) {
        (Some(unit), _) => unit.clone(),
        (None, CoordinateKind::Angle) => "rad".into(),
        (None, CoordinateKind::Distance) => "m".into(),
    };
    match order {
        0 => base,
        1 => format!("{base}/s"),
        _ => format!("{base}/s^2"),
    }
}

/// Whether `name` is a reaction's moment about a free axis: no unknown at all, exactly 0,
/// so that neither the handout nor `answer` reports it.
pub fn is_free_moment(question: &Question, found: &Quantity, value: f64) -> bool {
    matches!(question.kind, QuestionKind::Reaction { .. })
        && value == 0.0
        && matches!(found, Quantity::Reaction(column) if column.is_moment())
}
