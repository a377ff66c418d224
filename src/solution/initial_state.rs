//! Step 1's coordinate table at the assembled initial state: a dependent coordinate's
//! value and a dependent rate as solved from the constraints, a prescribed coordinate's
//! from its motion, each with its unit and a short mark (`0 m/s†`) that a note under the
//! table explains, so that the narrow value columns do not wrap around words.

use super::pictures::numbers::Numbers;
use crate::mechanics::Model;
use crate::numeric::coordinate_unit;
use crate::problem::{Coordinate, Dimension, JointKind, Problem};
use crate::render::context::Coordinate as CoordinateView;
use crate::render::draw::numbers::P3;
use crate::symbolic::fixed;

/// A value smaller than this is round-off of zero in a teaching problem's SI units.
const ROUND_OFF: f64 = 1e-12;

/// The mark of a value solved from the constraints (or the loop's closure).
pub const SOLVED_MARK: char = '†';
/// The mark of a value that follows from a prescribed motion.
pub const MOTION_MARK: char = '‡';

/// Where a value of step 1's table comes from when not from the problem.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Source {
    /// Solved from the constraints at the start.
    Solved,
    /// From the coordinate's prescribed motion.
    Motion,
}

/// Rewrites the initial values and rates of `rows` (one per coordinate of `problem`) with
/// the assembled state `q0`, `rates0`, each with its unit and mark; returns the note that
/// says what the marks mean, when any value is marked. A rate among `dependent_rates` is
/// solved from the constraints, and marked so, even where it comes out as the problem gave
/// it (a rolling coin's ẏ = 0 as its ẋ).
pub fn assembled(
    rows: &mut [CoordinateView],
    problem: &Problem,
    (q0, rates0): (&[f64], &[f64]),
    dependent_rates: &[usize],
) -> Option<String> {
    let mut marks = Vec::new();
    for (i, (row, c)) in rows.iter_mut().zip(&problem.coordinates).enumerate() {
        if let Some(&q) = q0.get(i) {
            let unit = coordinate_unit(problem, i, 0);
            row.initial = value_cell(q, c.initial, solved(c, c.dependent), &unit, &mut marks);
        }
        if let Some(&rate) = rates0.get(i) {
            let unit = coordinate_unit(problem, i, 1);
            let how = solved(
                c,
                c.dependent || c.dependent_rate || dependent_rates.contains(&i),
            );
            row.initial_rate = value_cell(rate, c.rate, how, &unit, &mut marks);
        }
    }
    marks_note(problem, &marks)
}

/// The note under the table: what each mark used means.
fn marks_note(problem: &Problem, marks: &[Source]) -> Option<String> {
    // What a dependent value satisfies: the loop's closure when the constraints are
    // closures only, else the constraints.
    // A closure that joins a body straight to its joint's parent (a collar on a fixed
    // rod) is a guide, and closes no loop.
    let guide = |c: &crate::problem::Joint| {
        (problem.joints.iter()).any(|j| j.child == c.child && j.parent == c.parent)
    };
    let loops = problem.closures.iter().any(|c| !guide(c));
    let satisfied = if problem.constraints.is_empty() && loops {
        "the loop's closure"
    } else {
        "the constraints"
    };
    let mut parts = Vec::new();
    if marks.contains(&Source::Solved) {
        parts.push(format!(
            "{SOLVED_MARK}: solved from {satisfied} at the start"
        ));
    }
    if marks.contains(&Source::Motion) {
        parts.push(format!("{MOTION_MARK}: from the prescribed motion"));
    }
    (!parts.is_empty()).then(|| format!("In the table of coordinates, {}.", parts.join("; ")))
}

/// Where a value comes from when not from the problem: a prescribed coordinate's motion,
/// or what it satisfies (a coordinate or rate marked dependent, or one the assembly moved).
fn solved(c: &Coordinate, dependent: bool) -> Option<Source> {
    if c.motion.is_some() {
        Some(Source::Motion)
    } else if dependent {
        Some(Source::Solved)
    } else {
        None
    }
}

/// `-0.65053 rad†`, or the value and its unit alone when the problem's value stands. A
/// value the assembly moved is solved from the constraints even when unmarked.
fn value_cell(
    value: f64,
    given: f64,
    how: Option<Source>,
    unit: &str,
    marks: &mut Vec<Source>,
) -> String {
    // Round-off of a zero (1e-16 m/s) is the zero it is.
    let shown = with_unit(
        &fixed(if value.abs() < ROUND_OFF { 0.0 } else { value }),
        unit,
    );
    let how = match how {
        Some(how) => how,
        None if fixed(given) == fixed(value) || (value.abs() < ROUND_OFF && given == 0.0) => {
            return shown
        }
        None => Source::Solved,
    };
    marks.push(how);
    let mark = match how {
        Source::Solved => SOLVED_MARK,
        Source::Motion => MOTION_MARK,
    };
    format!("{shown}{mark}")
}

/// `0.7 rad`, `1 rad/s`: a value and its unit as step 1's tables print them.
pub fn with_unit(value: &str, unit: &str) -> String {
    if unit.is_empty() {
        value.to_string()
    } else {
        format!("{value} {}", unit.replace("^2", "²"))
    }
}

/// For each revolute closure of a plane loop whose two bodies hang from revolute joints
/// (a four-bar's coupler and rocker): which of the loop's two assemblies the initial state
/// took, named by the side of the line between those joints that the closure's point is
/// on. The constraints hold for its mirror image across that line as well; the solution
/// follows the one nearest the problem's starting values.
pub fn branches(model: &Model, q0: &[f64], rates0: &[f64]) -> Vec<String> {
    let problem = model.problem;
    if problem.dimension != Dimension::Two || !problem.coordinates.iter().any(|c| c.dependent) {
        return Vec::new();
    }
    let numbers = Numbers::new(model, 0.0, q0, rates0);
    let n = problem.joints.len();
    let revolute_joint = |body| {
        problem
            .joint_of(body)
            .filter(|&j| problem.joints[j].kind == JointKind::Revolute)
    };
    (problem.closures.iter().enumerate())
        .filter(|(_, closure)| closure.kind == JointKind::Revolute)
        .filter_map(|(k, closure)| {
            let (p, q) = (revolute_joint(closure.parent)?, revolute_joint(closure.child)?);
            let at = |j: usize| numbers.vector(&model.joints[j].point.position);
            let r = numbers.vector(&model.sites.get(n + k)?.point.position);
            let side = side_of(at(p), at(q), r)?;
            Some(format!(
                "The loop closes at {} {side} the line from {} to {}: the assembly drawn in the figure (its mirror image across that line closes the loop too).",
                closure.name, problem.joints[p].name, problem.joints[q].name
            ))
        })
        .collect()
}

/// Where `r` lies from the line through `p` and `q`: above or below it when the line is
/// nearer the horizontal, to its right or left when nearer the vertical; `None` on it.
fn side_of(p: P3, q: P3, r: P3) -> Option<&'static str> {
    let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
    if dx.abs() >= dy.abs() {
        let on_line = p[1] + (r[0] - p[0]) * dy / dx;
        let gap = r[1] - on_line;
        (gap.abs() > 1e-9).then_some(if gap > 0.0 { "above" } else { "below" })
    } else {
        let on_line = p[0] + (r[1] - p[1]) * dx / dy;
        let gap = r[0] - on_line;
        (gap.abs() > 1e-9).then_some(if gap > 0.0 {
            "to the right of"
        } else {
            "to the left of"
        })
    }
}
