//! The Motion Law planner (step 3): enumerate candidate rows (free body, one body or a
//! connected group of them; sum of forces or of moments about a point; direction) and find
//! the reactions each brings in. [`choose`](super::choose) then picks a square, nonsingular
//! set with no unwanted reaction, solvable in order when it can be, and every rejected
//! candidate keeps its typed [`Reason`], so that the worked solution can show why a choice
//! was made.

use super::rows::{
    action_terms, resultant, unit_direction, unknowns_in, Direction, Equation, Inertia, Sum,
};
use crate::mechanics::{Model, Vector};
use crate::plan::forces::{Action, Source};
use crate::problem::{BodyId, JointKind};
use crate::symbolic::{eval, linear_coefficients, Symbol, Values};

/// Above this many bodies, connected groups other than subtrees are not tried.
const MAX_BODIES_FOR_GROUPS: usize = 4;

/// A candidate row: free body, sum and direction, before its terms are written out.
#[derive(Clone, Debug)]
pub struct Candidate {
    /// The bodies of the free body.
    pub free_body: Vec<BodyId>,
    /// Forces, or moments about a point.
    pub sum: Sum,
    /// The direction of the dot product.
    pub direction: Direction,
    /// The reaction components it brings in.
    pub reactions: Vec<Symbol>,
}

pub use super::choose::{choose, Choice};

/// The free bodies worth trying: every outboard subtree, every single body, and (while the
/// system is small) every connected group of bodies.
pub fn free_bodies(model: &Model) -> Vec<Vec<BodyId>> {
    let mut out: Vec<Vec<BodyId>> = Vec::new();
    let mut push = |mut set: Vec<BodyId>| {
        set.sort();
        if !set.is_empty() && !out.contains(&set) && !closes_a_loop(model, &set) {
            out.push(set);
        }
    };
    for &body in &model.order {
        if let Some(j) = model.problem.joint_of(body) {
            push(model.subtree(j));
        }
    }
    for &body in &model.order {
        push(vec![body]);
    }
    let n = model.order.len();
    if n <= MAX_BODIES_FOR_GROUPS {
        for mask in 1u32..(1 << n) {
            let set: Vec<BodyId> = (0..n)
                .filter(|i| mask & (1 << i) != 0)
                .map(|i| model.order[i])
                .collect();
            if is_connected(model, &set) {
                push(set);
            }
        }
    }
    out
}

/// Whether a closure joins two bodies of `set`. Its two sides then cancel only where the
/// loop is closed, so the group's rows would hold on the constraint alone, not at every
/// state the other methods are evaluated at.
fn closes_a_loop(model: &Model, set: &[BodyId]) -> bool {
    model.sites[model.problem.joints.len()..]
        .iter()
        .any(|site| set.contains(&site.parent) && set.contains(&site.child))
}

fn is_connected(model: &Model, set: &[BodyId]) -> bool {
    let mut reached = vec![set[0]];
    let mut grew = true;
    while grew {
        grew = false;
        for site in &model.sites {
            let (p, c) = (site.parent, site.child);
            for (a, b) in [(p, c), (c, p)] {
                if reached.contains(&a) && set.contains(&b) && !reached.contains(&b) {
                    reached.push(b);
                    grew = true;
                }
            }
        }
    }
    reached.len() == set.len()
}

/// The sites (joints, closures, contacts) with exactly one side inside the free body.
pub fn boundary_joints(model: &Model, free_body: &[BodyId]) -> Vec<usize> {
    (0..model.sites.len())
        .filter(|&j| {
            let site = &model.sites[j];
            free_body.contains(&site.parent) != free_body.contains(&site.child)
        })
        .collect()
}

fn push_direction(out: &mut Vec<Direction>, d: Direction) {
    if !out.iter().any(|e| e.vector == d.vector) {
        out.push(d);
    }
}

/// Directions for force rows and for moment rows: the joint axes in play and the unit
/// vectors of the frames involved.
fn directions(
    model: &Model,
    free_body: &[BodyId],
    boundary: &[usize],
) -> (Vec<Direction>, Vec<Direction>) {
    let problem = model.problem;
    let planar = model.is_planar();
    let (mut forces, mut moments) = (Vec::new(), Vec::new());
    for &j in boundary.iter().filter(|&&j| j < problem.joints.len()) {
        let joint = &problem.joints[j];
        let motion = &model.joints[j].motion;
        if let Some(axis) = &motion.written_axis {
            // An axis along a unit vector of its frame is written as that unit vector.
            let along = (0..3)
                .find(|&k| axis[k].is_one())
                .filter(|&k| (0..3).all(|i| i == k || axis[i].is_zero()));
            let d = Direction {
                name: format!("axis of {}", joint.name),
                latex: match along {
                    Some(k) => unit_direction(model, joint.parent, k).latex,
                    None => format!(
                        "\\hat{{\\mathbf{{e}}}}_{{{}}}",
                        crate::symbolic::latex_name(&joint.name)
                    ),
                },
                vector: Vector::new(joint.parent, axis.clone()),
            };
            if matches!(joint.kind, JointKind::Prismatic | JointKind::Cylindrical) {
                push_direction(&mut forces, d.clone());
            }
            if matches!(joint.kind, JointKind::Revolute | JointKind::Cylindrical) && !planar {
                push_direction(&mut moments, d);
            }
        }
        if joint.kind == JointKind::Universal {
            push_direction(
                &mut moments,
                unit_direction(model, joint.parent, joint.sequence[0] as usize),
            );
            push_direction(
                &mut moments,
                unit_direction(model, joint.child, joint.sequence[1] as usize),
            );
        }
    }
    let mut frames = vec![BodyId::GROUND];
    // A body spinning about its symmetry axis offers the unit vectors that do not spin.
    for &j in boundary {
        for body in [model.sites[j].parent, model.sites[j].child] {
            frames.push(model.bodies[body.0].frame);
        }
    }
    frames.sort();
    frames.dedup();
    let _ = free_body;
    for frame in frames {
        let axes: &[usize] = if planar { &[0, 1] } else { &[0, 1, 2] };
        for &axis in axes {
            push_direction(&mut forces, unit_direction(model, frame, axis));
        }
        if !planar {
            for axis in 0..3 {
                push_direction(&mut moments, unit_direction(model, frame, axis));
            }
        }
    }
    if planar {
        push_direction(&mut moments, unit_direction(model, BodyId::GROUND, 2));
    }
    (forces, moments)
}

/// Every candidate row of the Motion Law, in a fixed order, with the reactions each brings
/// in. Only the reaction terms are written out here, which is cheap; the full row is written
/// only for candidates that survive.
pub fn candidates(model: &Model, actions: &[Action], reactions: &[Symbol]) -> Vec<Candidate> {
    let problem = model.problem;
    let reaction_actions: Vec<Action> = actions
        .iter()
        .filter(|a| matches!(a.source, Source::Reaction(_)))
        .cloned()
        .collect();
    let mut out = Vec::new();
    for free_body in free_bodies(model) {
        let boundary = boundary_joints(model, &free_body);
        let (force_directions, moment_directions) = directions(model, &free_body, &boundary);
        let mut points: Vec<(String, Vector)> = boundary
            .iter()
            .map(|&j| {
                (
                    model.sites[j].name.clone(),
                    model.sites[j].point.position.clone(),
                )
            })
            .collect();
        // A group is taken about a point where a reaction acts, to remove it; its bodies'
        // mass centers are special only for a free body of one body (and writing out a
        // group's rows is what costs).
        for &body in free_body.iter().filter(|_| free_body.len() == 1) {
            points.push((
                format!("{}*", problem.body_name(body)),
                model.bodies[body.0].center.position.clone(),
            ));
        }
        let mut rows: Vec<(Sum, Direction)> = force_directions
            .into_iter()
            .map(|d| (Sum::Force, d))
            .collect();
        for (point, position) in points {
            for direction in &moment_directions {
                rows.push((
                    Sum::Moment {
                        point: point.clone(),
                        position: position.clone(),
                    },
                    direction.clone(),
                ));
            }
        }
        for (sum, direction) in rows {
            let about = match &sum {
                Sum::Moment { position, .. } => Some(position),
                _ => None,
            };
            let (terms, _) = action_terms(
                model,
                &reaction_actions,
                &free_body,
                about,
                &direction.vector,
            );
            let reactions = unknowns_in(&terms, reactions);
            out.push(Candidate {
                free_body: free_body.clone(),
                sum,
                direction,
                reactions,
            });
        }
    }
    out
}

/// Writes out the whole row of a candidate.
pub fn write_out(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    candidate: &Candidate,
    unknowns: &[Symbol],
) -> Equation {
    let about = match &candidate.sum {
        Sum::Moment { position, .. } => Some(position),
        _ => None,
    };
    let groups = resultant(
        model,
        actions,
        inertia,
        &candidate.free_body,
        about,
        &candidate.direction.vector,
    );
    let expression = groups.total();
    Equation {
        free_body: candidate.free_body.clone(),
        sum: candidate.sum.clone(),
        direction: Some(candidate.direction.clone()),
        unknowns: unknowns_in(&expression, unknowns),
        groups,
        expression,
    }
}

pub use crate::mechanics::sample_states;

/// The coefficients of the unknowns in a row, at each of `states`.
pub fn coefficient_rows(
    equation: &Equation,
    unknowns: &[Symbol],
    states: &[Values],
) -> Vec<Vec<f64>> {
    match linear_coefficients(&equation.expression, unknowns) {
        Ok(coefficients) => states
            .iter()
            .map(|values| coefficients.iter().map(|c| eval(c, values)).collect())
            .collect(),
        Err(_) => vec![vec![f64::NAN; unknowns.len()]; states.len()],
    }
}

/// Incremental Gram–Schmidt: whether `row` adds a new direction to `basis` (and adds it).
pub fn adds_rank(basis: &mut Vec<Vec<f64>>, row: &[f64]) -> bool {
    let norm = row.iter().map(|x| x * x).sum::<f64>().sqrt();
    if !norm.is_finite() || norm <= 0.0 {
        return false;
    }
    let mut residual: Vec<f64> = row.iter().map(|x| x / norm).collect();
    for _ in 0..2 {
        for b in basis.iter() {
            let projection: f64 = residual.iter().zip(b).map(|(r, b)| r * b).sum();
            residual
                .iter_mut()
                .zip(b)
                .for_each(|(r, b)| *r -= projection * b);
        }
    }
    let left = residual.iter().map(|x| x * x).sum::<f64>().sqrt();
    if left < 1e-8 {
        return false;
    }
    basis.push(residual.iter().map(|x| x / left).collect());
    true
}
