//! The Motion Law planner (step 3): enumerate candidate rows (free body, sum of forces or of
//! moments about a point, direction), find each one's unknowns, and choose a square,
//! nonsingular set with no unwanted reaction and the fewest terms. Every rejected candidate
//! keeps its reason, so that the worked solution can show why a choice was made.

use crate::equations::rows::{
    action_terms, resultant, unit_direction, unknowns_in, Direction, Equation, Inertia, Sum,
};
use crate::mechanics::{Model, Vector};
use crate::plan::forces::{Action, Source};
use crate::problem::{BodyId, JointKind};
use crate::symbolic::eval::{eval, Values};
use crate::symbolic::linear::linear_split;
use crate::symbolic::Symbol;
use std::f64::consts::FRAC_PI_2;

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

/// A candidate the planner did not use, and why.
#[derive(Clone, Debug)]
pub struct Rejected {
    /// The candidate row.
    pub candidate: Candidate,
    /// Why it was not chosen.
    pub reason: String,
}

/// The chosen rows and the rejected candidates.
#[derive(Clone, Debug)]
pub struct Choice {
    /// Chosen rows, in the order of the candidates.
    pub rows: Vec<Equation>,
    /// Rejected candidates with their reasons.
    pub rejected: Vec<Rejected>,
}

/// The free bodies worth trying: every outboard subtree, every single body, and (while the
/// system is small) every connected group of bodies.
pub fn free_bodies(model: &Model) -> Vec<Vec<BodyId>> {
    let mut out: Vec<Vec<BodyId>> = Vec::new();
    let mut push = |mut set: Vec<BodyId>| {
        set.sort();
        if !set.is_empty() && !out.contains(&set) {
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
            let d = Direction {
                name: format!("axis of {}", joint.name),
                latex: format!(
                    "\\hat{{\\mathbf{{e}}}}_{{{}}}",
                    crate::symbolic::print::latex_name(&joint.name)
                ),
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
    for &j in boundary {
        frames.push(model.sites[j].parent);
        frames.push(model.sites[j].child);
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
        for &body in &free_body {
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

/// States at which a choice of rows must be nonsingular: the initial state and a few generic
/// ones (seeded, so the choice is the same every run). Requiring rank at all of them keeps the
/// planner away from rows that only look independent at one state.
pub fn sample_states(model: &Model) -> Vec<Values> {
    let problem = model.problem;
    let mut seed: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut next = || {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    };
    let mut states = Vec::new();
    for sample in 0..4 {
        let (mut q, mut rates) = (Vec::new(), Vec::new());
        for c in &problem.coordinates {
            let (value, rate) = if sample == 0 {
                (c.initial, c.rate)
            } else {
                (c.initial + next(), c.rate + next())
            };
            q.push(value);
            rates.push(rate);
        }
        states.push(model.values_at(0.37 * sample as f64, &q, &rates));
    }
    states
}

/// The coefficients of the unknowns in a row, at each of `states`.
pub fn coefficient_rows(
    equation: &Equation,
    unknowns: &[Symbol],
    states: &[Values],
) -> Vec<Vec<f64>> {
    match linear_split(&equation.expression, unknowns) {
        Ok((coefficients, _)) => states
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

/// Chooses the rows: wanted unknowns only, fewest terms first, each adding rank.
pub fn choose(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    candidates: Vec<Candidate>,
    wanted: &[Symbol],
    given: &[Equation],
    required: &[Values],
) -> Choice {
    let states = sample_states(model);
    let complete = |choice: &Choice| choice.rows.len() + given.len() == wanted.len();
    // Rows written out once serve every attempt below: writing them out is what costs.
    let mut written = std::collections::HashMap::new();
    let mut attempt = |candidates: Vec<Candidate>, states: &[Values]| {
        choose_at(
            model,
            actions,
            inertia,
            candidates,
            wanted,
            given,
            states,
            &mut written,
        )
    };
    if !required.is_empty() {
        // States the caller will solve at: plan for them too if a plan can be; otherwise
        // (the system itself is singular there) plan as usual.
        let mut more = states.clone();
        more.extend(required.iter().cloned());
        let choice = attempt(candidates.clone(), &more);
        if complete(&choice) {
            return choice;
        }
    }
    let choice = attempt(candidates.clone(), &states);
    if complete(&choice) {
        // Rows that are independent at generic states can still fail together at special
        // ones: all q = 0 (often the equilibrium a student linearizes about) or a quarter
        // turn. A pendulum's `M about bob*` with `F along N.x` loses the vertical pin force
        // at q = 0. Plan again with those states too (both, else the first), and keep the
        // new plan if there is one: some systems are singular there whatever the rows.
        let special: Vec<Values> = [0.0, FRAC_PI_2]
            .into_iter()
            .map(|q| uniform_state(model, q))
            .collect();
        // The cheap test first: the kinematics are looked at only for a plan that fails.
        let all_rows: Vec<Equation> = given.iter().chain(&choice.rows).cloned().collect();
        let full = full_rank_at(&all_rows, wanted, &special);
        if special
            .iter()
            .zip(&full)
            .any(|(state, full)| !full && rates_are_independent(model, state))
        {
            let special: Vec<Values> = special
                .into_iter()
                .filter(|state| rates_are_independent(model, state))
                .collect();
            for count in (1..=special.len()).rev() {
                let mut more = states.clone();
                more.extend(special[..count].iter().cloned());
                let again = attempt(candidates.clone(), &more);
                if complete(&again) {
                    return again;
                }
            }
        }
        return choice;
    }
    // The initial state itself may be singular (gimbal lock, say): plan on generic states.
    attempt(candidates, &states[1..])
}

/// Whether no combination of the rates leaves every body still at `state`: the columns of
/// the map from the rates to the bodies' velocities and angular velocities are independent.
/// Euler angles in gimbal lock fail this, and then no choice of rows can be nonsingular.
fn rates_are_independent(model: &Model, state: &Values) -> bool {
    let problem = model.problem;
    let rates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|i| problem.coordinate_symbol(i, 1))
        .collect();
    let mut columns = vec![Vec::new(); rates.len()];
    for &body in &model.order {
        let b = &model.bodies[body.0];
        let velocity = b.center.velocity.components_in(body, &model.frames);
        let omega = b.omega.components_in(body, &model.frames);
        for component in velocity.iter().chain(&omega) {
            let Ok((coefficients, _)) = linear_split(component, &rates) else {
                return true; // not linear in the rates: no verdict
            };
            for (column, c) in columns.iter_mut().zip(&coefficients) {
                column.push(eval(c, state));
            }
        }
    }
    let mut basis = Vec::new();
    columns.iter().all(|column| adds_rank(&mut basis, column))
}

/// Every coordinate at `q`, the rates as given initially.
fn uniform_state(model: &Model, q: f64) -> Values {
    let coordinates = &model.problem.coordinates;
    let rates: Vec<f64> = coordinates.iter().map(|c| c.rate).collect();
    model.values_at(0.0, &vec![q; coordinates.len()], &rates)
}

/// For each of `states`, whether `rows` determine every one of `wanted` there (each row
/// is split into its coefficients once for all the states).
fn full_rank_at(rows: &[Equation], wanted: &[Symbol], states: &[Values]) -> Vec<bool> {
    let mut bases = vec![Vec::new(); states.len()];
    let mut full = vec![true; states.len()];
    for row in rows {
        let coefficients = coefficient_rows(row, wanted, states);
        for ((basis, full), row) in bases.iter_mut().zip(&mut full).zip(&coefficients) {
            *full = *full && adds_rank(basis, row);
        }
    }
    full
}

#[allow(clippy::too_many_arguments)]
fn choose_at(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    candidates: Vec<Candidate>,
    wanted: &[Symbol],
    given: &[Equation],
    states: &[Values],
    written_before: &mut std::collections::HashMap<usize, Equation>,
) -> Choice {
    let mut rejected: Vec<(usize, Rejected)> = Vec::new();
    // Candidates free of unwanted reactions, by tier: free bodies of one body first, then
    // of two, and so on. A tier is written out only while the rows so far are not enough,
    // since writing out a row of a large free body is what costs.
    let mut tiers: std::collections::BTreeMap<usize, Vec<(usize, Candidate)>> = Default::default();
    for (index, candidate) in candidates.into_iter().enumerate() {
        let unwanted: Vec<&Symbol> = candidate
            .reactions
            .iter()
            .filter(|u| !wanted.contains(u))
            .collect();
        if unwanted.is_empty() {
            tiers
                .entry(candidate.free_body.len())
                .or_default()
                .push((index, candidate));
        } else {
            let reason = unwanted_reason(&unwanted);
            rejected.push((index, Rejected { candidate, reason }));
        }
    }
    let mut bases: Vec<Vec<Vec<f64>>> = vec![Vec::new(); states.len()];
    // The constraint rows are always in: the free bodies' rows complete them.
    for row in given {
        adds_rank_everywhere(&mut bases, row, wanted, states);
    }
    let mut chosen: Vec<(usize, Equation)> = Vec::new();
    for (_, tier) in tiers {
        if bases[0].len() == wanted.len() {
            for (index, candidate) in tier {
                let reason =
                    "not needed: the rows chosen already determine every unknown".to_string();
                rejected.push((index, Rejected { candidate, reason }));
            }
            continue;
        }
        let mut written: Vec<(usize, Candidate, Equation)> = tier
            .into_iter()
            .map(|(index, candidate)| {
                let equation = written_before
                    .entry(index)
                    .or_insert_with(|| write_out(model, actions, inertia, &candidate, wanted))
                    .clone();
                (index, candidate, equation)
            })
            .collect();
        // Sparse rows first (fewest unknowns), then the fewest terms.
        written
            .sort_by_cached_key(|(i, _, e)| (e.unknowns.len(), e.expression.operation_count(), *i));
        for (index, candidate, equation) in written {
            let reason = if equation.unknowns.is_empty() {
                Some("contains no unknown".to_string())
            } else if bases[0].len() == wanted.len() {
                Some("not needed: the rows chosen already determine every unknown".to_string())
            } else if !adds_rank_everywhere(&mut bases, &equation, wanted, states) {
                Some("adds nothing new: it follows from the rows already chosen".to_string())
            } else {
                None
            };
            match reason {
                Some(reason) => rejected.push((index, Rejected { candidate, reason })),
                None => chosen.push((index, equation)),
            }
        }
    }
    chosen.sort_by_key(|(i, _)| *i);
    rejected.sort_by_key(|(i, _)| *i);
    Choice {
        rows: chosen.into_iter().map(|(_, e)| e).collect(),
        rejected: rejected.into_iter().map(|(_, r)| r).collect(),
    }
}

/// Whether a row adds rank at every sample state; the bases grow only when it does.
fn adds_rank_everywhere(
    bases: &mut [Vec<Vec<f64>>],
    equation: &Equation,
    wanted: &[Symbol],
    states: &[Values],
) -> bool {
    let mut trial: Vec<Vec<Vec<f64>>> = bases.to_vec();
    let rows = coefficient_rows(equation, wanted, states);
    for (basis, row) in trial.iter_mut().zip(&rows) {
        if !adds_rank(basis, row) {
            return false;
        }
    }
    bases.clone_from_slice(&trial);
    true
}

fn unwanted_reason(unwanted: &[&Symbol]) -> String {
    let mut joints: Vec<String> = Vec::new();
    for u in unwanted {
        if let Symbol::Unknown(unknown) = u {
            // A reaction's place is its site; a drive or a multiplier is its own.
            let joint = unknown
                .site()
                .map_or_else(|| unknown.to_string(), str::to_string);
            if !joints.contains(&joint) {
                joints.push(joint);
            }
        }
    }
    let list: Vec<String> = unwanted.iter().map(|u| u.to_string()).collect();
    let place = if joints.len() == 1 {
        format!("the reaction at {}", joints[0])
    } else {
        format!("the reactions at {}", joints.join(", "))
    };
    format!("brings in {place} ({})", list.join(", "))
}
