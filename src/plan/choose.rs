//! Choosing the rows of the Motion Law from the candidates: a square set, nonsingular at
//! every sample state, with no unwanted reaction. Where one exists, the plan is
//! block-triangular: each block of rows brings in as many new unknowns as it has rows
//! (one, when it can), so that a student solves the rows in order, a few unknowns at a time.

use super::planner::{adds_rank, sample_states, write_out, Candidate};
use super::rejection::{self, Reason, Rejected, SpecialState};
use super::rows::{Equation, Inertia};
use crate::mechanics::Model;
use crate::plan::forces::Action;
use crate::symbolic::{eval, linear_coefficients, Expr, Symbol, Values};
use std::collections::HashMap;
use std::f64::consts::FRAC_PI_2;

/// The chosen rows and the rejected candidates.
#[derive(Clone, Debug)]
pub struct Choice {
    /// Chosen rows, the constraint rows among them, in the order a student solves them.
    pub rows: Vec<Equation>,
    /// Rejected candidates with their reasons, in the order of the candidates.
    pub rejected: Vec<Rejected>,
}

/// A sample state, and whether it is a special one (`None`: generic).
type Sample = (Values, Option<SpecialState>);

/// Whether a sample state is a special one, and which (`None`: generic).
type Kind = Option<SpecialState>;

/// A row's key: its candidate's (`false`) or constraint row's (`true`) index.
type Key = (bool, usize);

/// A row written out, its coefficients, and their values by sample state (`None`: not
/// evaluated yet): writing out, splitting and evaluating a row is what costs, and the
/// attempts share it.
struct Written {
    equation: Equation,
    /// The arithmetic of the whole row: fewer is preferred.
    operations: usize,
    coefficients: Option<Vec<Expr>>,
    values: Vec<Option<Vec<f64>>>,
}

impl Written {
    fn new(equation: Equation, wanted: &[Symbol]) -> Written {
        let coefficients = linear_coefficients(&equation.expression, wanted).ok();
        Written {
            operations: equation.expression.operation_count(),
            equation,
            coefficients,
            values: Vec::new(),
        }
    }

    /// The coefficients' values at `states[state]` (NaN for a row not linear in them).
    fn at(&mut self, states: &[Sample], state: usize, wanted: usize) -> &[f64] {
        if self.values.len() <= state {
            self.values.resize(state + 1, None);
        }
        let coefficients = &self.coefficients;
        self.values[state].get_or_insert_with(|| match coefficients {
            Some(c) => c.iter().map(|c| eval(c, &states[state].0)).collect(),
            None => vec![f64::NAN; wanted],
        })
    }
}

/// What the attempts share: the sample states met so far (each keeps the values of the
/// definitions it evaluated) and the rows written out.
struct Planner<'a, 'p> {
    model: &'a Model<'p>,
    actions: &'a [Action],
    inertia: &'a Inertia,
    candidates: &'a [Candidate],
    wanted: &'a [Symbol],
    given: &'a [Equation],
    states: Vec<Sample>,
    written: HashMap<Key, Written>,
}

/// Chooses the rows: wanted unknowns only; a block-triangular set when there is one, else
/// sparse rows first and the fewest terms, each adding rank. `given` (the constraint rows)
/// are always among the rows. `required` are states the caller will solve at.
pub fn choose(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    candidates: Vec<Candidate>,
    wanted: &[Symbol],
    given: &[Equation],
    required: &[Values],
) -> Choice {
    let mut planner = Planner {
        model,
        actions,
        inertia,
        candidates: &candidates,
        wanted,
        given,
        states: Vec::new(),
        written: HashMap::new(),
    };
    let states: Vec<usize> = sample_states(model)
        .into_iter()
        .enumerate()
        .map(|(i, v)| planner.add_state(v, (i == 0).then_some(SpecialState::Initial)))
        .collect();
    let complete = |choice: &Choice| choice.rows.len() == wanted.len();
    if !required.is_empty() {
        // States the caller will solve at: plan for them too if a plan can be; otherwise
        // (the system itself is singular there) plan as usual.
        let mut more = states.clone();
        for v in required {
            more.push(planner.add_state(v.clone(), Some(SpecialState::Requested)));
        }
        let (choice, _) = planner.attempt(&more);
        if complete(&choice) {
            return choice;
        }
    }
    let (choice, keys) = planner.attempt(&states);
    if complete(&choice) {
        // Rows that are independent at generic states can still fail together at special
        // ones: all q = 0 (often the equilibrium a student linearizes about) or a quarter
        // turn. A pendulum's `M about bob*` with `F along N.x` loses the vertical pin force
        // at q = 0. Plan again with those states too (both, else the first), and keep the
        // new plan if there is one: some systems are singular there whatever the rows.
        let special: Vec<usize> = [
            (0.0, SpecialState::AllZero),
            (FRAC_PI_2, SpecialState::QuarterTurn),
        ]
        .into_iter()
        .map(|(q, kind)| planner.add_state(uniform_state(model, q), Some(kind)))
        .collect();
        // The cheap test first: the kinematics are looked at only for a plan that fails.
        let full: Vec<bool> = special
            .iter()
            .map(|&state| planner.full_rank_at(&keys, state))
            .collect();
        if full.iter().all(|&full| full) {
            return choice;
        }
        let columns = rate_columns(model);
        let independent: Vec<bool> = special
            .iter()
            .map(|&state| rates_are_independent(&columns, &planner.states[state].0))
            .collect();
        if full
            .iter()
            .zip(&independent)
            .any(|(full, independent)| !full && *independent)
        {
            let special: Vec<usize> = special
                .into_iter()
                .zip(&independent)
                .filter_map(|(state, independent)| independent.then_some(state))
                .collect();
            for count in (1..=special.len()).rev() {
                let mut more = states.clone();
                more.extend(&special[..count]);
                let (again, _) = planner.attempt(&more);
                if complete(&again) {
                    return again;
                }
            }
        }
        return choice;
    }
    // The initial state itself may be singular (gimbal lock, say): plan on generic states.
    planner.attempt(&states[1..]).0
}

/// The coefficients of the rates in each body's velocity and angular velocity, by rate
/// (`None`: not linear in the rates, no verdict). They do not depend on the state.
fn rate_columns(model: &Model) -> Option<Vec<Vec<Expr>>> {
    let rates: Vec<Symbol> = model.problem.speed_symbols(1);
    let mut columns = vec![Vec::new(); rates.len()];
    for &body in &model.order {
        let b = &model.bodies[body.0];
        let velocity = b.center.velocity.components_in(b.frame, &model.frames);
        let omega = b.omega.components_in(b.frame, &model.frames);
        for component in velocity.iter().chain(&omega) {
            let coefficients = linear_coefficients(component, &rates).ok()?;
            for (column, c) in columns.iter_mut().zip(coefficients) {
                column.push(c);
            }
        }
    }
    Some(columns)
}

/// Whether no combination of the rates leaves every body still at `state`: the columns of
/// the map from the rates to the bodies' velocities and angular velocities (`columns`, see
/// [`rate_columns`]) are independent. Euler angles in gimbal lock fail this, and then no
/// choice of rows can be nonsingular.
fn rates_are_independent(columns: &Option<Vec<Vec<Expr>>>, state: &Values) -> bool {
    let Some(columns) = columns else {
        return true;
    };
    let mut basis = Vec::new();
    columns.iter().all(|column| {
        let column: Vec<f64> = column.iter().map(|c| eval(c, state)).collect();
        adds_rank(&mut basis, &column)
    })
}

/// Every coordinate at `q`, the rates as given initially.
fn uniform_state(model: &Model, q: f64) -> Values {
    let coordinates = &model.problem.coordinates;
    let rates: Vec<f64> = coordinates.iter().map(|c| c.rate).collect();
    model.values_at(0.0, &vec![q; coordinates.len()], &rates)
}

/// A row the planner may use: a candidate's or a constraint row.
struct Row {
    key: Key,
    /// The unknowns it contains, as indices of `wanted`.
    unknowns: Vec<usize>,
    /// Its coefficients of the unknowns at each state.
    coefficients: Vec<Vec<f64>>,
    /// Preference: constraint rows first (they are always in), then fewest unknowns, then
    /// fewest terms, then the candidates' order.
    preference: (bool, usize, usize, usize),
}

impl Row {
    /// The candidate's index, or `None` for a constraint row.
    fn candidate(&self) -> Option<usize> {
        match self.key {
            (false, index) => Some(index),
            (true, _) => None,
        }
    }
}

/// The chosen rows of which `row` is a combination, read at the first generic state.
fn follows_from(chosen: &[&Row], row: &Row, kinds: &[Kind]) -> Vec<usize> {
    let Some(state) = kinds.iter().position(Option::is_none) else {
        return Vec::new();
    };
    let chosen: Vec<&[Vec<f64>]> = chosen.iter().map(|c| c.coefficients.as_slice()).collect();
    super::span::combination_of(&chosen, &row.coefficients, state)
}

/// Why a row could not join a set of rows.
enum Fails {
    /// At a generic state: it follows from them.
    Everywhere,
    /// Only at a special state.
    At(SpecialState),
}

/// Whether the row `coefficients` (restricted to `columns` when given) adds rank at every
/// state; the bases grow only when it does.
fn try_add(
    bases: &mut [Vec<Vec<f64>>],
    coefficients: &[Vec<f64>],
    columns: Option<&[usize]>,
    kinds: &[Kind],
) -> Result<(), Fails> {
    let mut trial: Vec<Vec<Vec<f64>>> = bases.to_vec();
    let mut special = None;
    for ((basis, row), kind) in trial.iter_mut().zip(coefficients).zip(kinds) {
        let restricted: Vec<f64> = match columns {
            Some(columns) => {
                let part: Vec<f64> = columns.iter().map(|&c| row[c]).collect();
                // A part that is round-off beside the whole row is no pivot.
                let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
                if norm(&part) <= 1e-10 * norm(row) {
                    vec![0.0; part.len()]
                } else {
                    part
                }
            }
            None => row.clone(),
        };
        if !adds_rank(basis, &restricted) {
            match kind {
                None => return Err(Fails::Everywhere),
                Some(kind) => special = special.or(Some(*kind)),
            }
        }
    }
    if let Some(kind) = special {
        return Err(Fails::At(kind));
    }
    bases.clone_from_slice(&trial);
    Ok(())
}

impl Planner<'_, '_> {
    /// Adds a sample state; returns its index.
    fn add_state(&mut self, values: Values, kind: Kind) -> usize {
        self.states.push((values, kind));
        self.states.len() - 1
    }

    /// The row of `key`, written out (once) and split into its coefficients.
    fn written(&mut self, key: Key) -> &mut Written {
        let Planner {
            model,
            actions,
            inertia,
            candidates,
            wanted,
            given,
            ..
        } = *self;
        self.written.entry(key).or_insert_with(|| {
            let equation = match key {
                (true, i) => given[i].clone(),
                (false, i) => write_out(model, actions, inertia, &candidates[i], wanted),
            };
            Written::new(equation, wanted)
        })
    }

    /// Whether the rows of `keys` determine every wanted unknown at `states[state]`.
    fn full_rank_at(&mut self, keys: &[Key], state: usize) -> bool {
        let mut basis = Vec::new();
        keys.iter().all(|&key| {
            self.written(key);
            let row = self.written.get_mut(&key).expect("written above");
            adds_rank(&mut basis, row.at(&self.states, state, self.wanted.len()))
        })
    }

    /// A choice of rows nonsingular at the sample states `picked`, and the keys of its rows.
    fn attempt(&mut self, picked: &[usize]) -> (Choice, Vec<Key>) {
        let (model, candidates, wanted) = (self.model, self.candidates, self.wanted);
        let kinds: Vec<Kind> = picked.iter().map(|&s| self.states[s].1).collect();
        let mut rejected: Vec<(usize, Rejected)> = Vec::new();
        let mut rows: Vec<Row> = Vec::new();
        let mut make_row = |planner: &mut Self, key: Key| {
            let states = &planner.states;
            let written = planner.written.get_mut(&key).expect("written above");
            let unknowns: Vec<usize> = (0..wanted.len())
                .filter(|&i| written.equation.unknowns.contains(&wanted[i]))
                .collect();
            let coefficients = picked
                .iter()
                .map(|&state| written.at(states, state, wanted.len()).to_vec())
                .collect();
            let preference = match key {
                (false, index) => (true, unknowns.len(), written.operations, index),
                (true, i) => (false, 0, 0, i),
            };
            rows.push(Row {
                key,
                unknowns,
                coefficients,
                preference,
            });
        };
        for i in 0..self.given.len() {
            self.written((true, i));
            make_row(self, (true, i));
        }
        for (index, candidate) in candidates.iter().enumerate() {
            let unwanted: Vec<Symbol> = candidate
                .reactions
                .iter()
                .filter(|u| !wanted.contains(u))
                .cloned()
                .collect();
            if !unwanted.is_empty() {
                let reason = rejection::unwanted(model, &unwanted);
                let candidate = candidate.clone();
                rejected.push((index, Rejected { candidate, reason }));
                continue;
            }
            if self.written((false, index)).equation.unknowns.is_empty() {
                let candidate = candidate.clone();
                let reason = Reason::NoUnknown;
                rejected.push((index, Rejected { candidate, reason }));
                continue;
            }
            make_row(self, (false, index));
        }
        rows.sort_by_key(|r| r.preference);
        let mut failed: HashMap<usize, Fails> = HashMap::new();
        let order = triangular(&rows, wanted.len(), &kinds, &mut failed)
            .unwrap_or_else(|| any_square(&rows, wanted.len(), &kinds, &mut failed));
        let mut used = vec![false; rows.len()];
        order.iter().for_each(|&r| used[r] = true);
        let chosen: Vec<&Row> = order.iter().map(|&r| &rows[r]).collect();
        for (r, row) in rows.iter().enumerate().filter(|(r, _)| !used[*r]) {
            let Some(index) = row.candidate() else {
                continue;
            };
            let duplicate = chosen
                .iter()
                .position(|c| super::span::parallel(&c.coefficients, &row.coefficients));
            let reason = match (duplicate, failed.get(&r)) {
                (Some(row), _) => Reason::Duplicate { row },
                (None, Some(Fails::At(kind))) => Reason::SingularAt(*kind),
                (None, Some(Fails::Everywhere)) => Reason::Redundant {
                    rows: follows_from(&chosen, row, &kinds),
                },
                (None, None) => Reason::NotNeeded {
                    rows: follows_from(&chosen, row, &kinds),
                },
            };
            let candidate = candidates[index].clone();
            rejected.push((index, Rejected { candidate, reason }));
        }
        rejected.sort_by_key(|(i, _)| *i);
        let keys: Vec<Key> = chosen.iter().map(|r| r.key).collect();
        let choice = Choice {
            rows: keys
                .iter()
                .map(|key| self.written[key].equation.clone())
                .collect(),
            rejected: rejected.into_iter().map(|(_, r)| r).collect(),
        };
        (choice, keys)
    }
}

/// Whether two rows of coefficients are multiples of each other at every state.
/// The old way, when no block-triangular plan exists: rows in order of preference, each
/// kept when it adds rank at every state; the order of the candidates, the constraint rows
/// last.
fn any_square(
    rows: &[Row],
    n: usize,
    kinds: &[Kind],
    failed: &mut HashMap<usize, Fails>,
) -> Vec<usize> {
    let mut bases: Vec<Vec<Vec<f64>>> = vec![Vec::new(); kinds.len()];
    let mut order = Vec::new();
    for (r, row) in rows.iter().enumerate() {
        if bases.iter().all(|b| b.len() == n) {
            break;
        }
        match try_add(&mut bases, &row.coefficients, None, kinds) {
            Ok(()) => order.push(r),
            Err(fails) => {
                failed.insert(r, fails);
            }
        }
    }
    order.sort_by_key(|&r| (rows[r].candidate().is_none(), rows[r].candidate()));
    order
}

/// A block-triangular plan, as indices of `rows` in the order they are solved: blocks
/// taken one after another, each the smallest set of rows that brings in exactly as many
/// new unknowns as it has rows and determines them at every state. `None` when the blocks
/// run out before every unknown is found, or leave a constraint row out.
fn triangular(
    rows: &[Row],
    n: usize,
    kinds: &[Kind],
    failed: &mut HashMap<usize, Fails>,
) -> Option<Vec<usize>> {
    let mut known = vec![false; n];
    let mut used = vec![false; rows.len()];
    let mut order = Vec::new();
    while known.iter().any(|k| !k) {
        let new = |r: usize| -> Vec<usize> {
            rows[r]
                .unknowns
                .iter()
                .copied()
                .filter(|&u| !known[u])
                .collect()
        };
        let open: Vec<(usize, Vec<usize>)> = (0..rows.len())
            .filter(|&r| !used[r])
            .map(|r| (r, new(r)))
            .filter(|(_, new)| !new.is_empty())
            .collect();
        let mut seeds: Vec<&(usize, Vec<usize>)> = open.iter().collect();
        // The smallest blocks first; among them, those that find the earliest unknowns
        // (the q'' before the reactions, as a student goes), then the preferred rows.
        seeds.sort_by_key(|(r, new)| (new.len(), new.iter().min().copied(), *r));
        let mut best: Option<(Vec<usize>, HashMap<usize, Fails>)> = None;
        for (_, seed_new) in seeds {
            if best.as_ref().is_some_and(|b| b.0.len() <= seed_new.len()) {
                break;
            }
            let mut set: Vec<usize> = seed_new.clone();
            loop {
                if best.as_ref().is_some_and(|b| b.0.len() <= set.len()) {
                    break;
                }
                let inside: Vec<usize> = open
                    .iter()
                    .filter(|(_, new)| new.iter().all(|u| set.contains(u)))
                    .map(|(r, _)| *r)
                    .collect();
                if inside.len() >= set.len() {
                    let mut passed_over = HashMap::new();
                    if let Some(block) = block(rows, &inside, &set, kinds, &mut passed_over) {
                        best = Some((block, passed_over));
                        break;
                    }
                }
                // Grow by the row that brings in the fewest unknowns more.
                let next = open
                    .iter()
                    .filter(|(r, _)| !inside.contains(r))
                    .min_by_key(|(r, new)| (new.iter().filter(|u| !set.contains(u)).count(), *r));
                let Some((_, more)) = next else { break };
                set.extend(more.iter().copied());
                set.sort();
                set.dedup();
            }
        }
        let (mut block, passed_over) = best?;
        // Only the rows passed over for the block chosen have a reason to show.
        failed.extend(passed_over);
        // Within a block, the free bodies' rows in the candidates' order, then the
        // constraint rows.
        block.sort_by_key(|&r| (rows[r].candidate().is_none(), rows[r].candidate(), r));
        for &r in &block {
            used[r] = true;
            rows[r].unknowns.iter().for_each(|&u| known[u] = true);
        }
        order.extend(block);
    }
    let every_constraint_row = (0..rows.len()).all(|r| used[r] || rows[r].candidate().is_some());
    every_constraint_row.then_some(order)
}

/// `set.len()` rows of `inside` (in order of preference) that determine the unknowns `set`
/// at every state, once those found before are known.
fn block(
    rows: &[Row],
    inside: &[usize],
    set: &[usize],
    kinds: &[Kind],
    failed: &mut HashMap<usize, Fails>,
) -> Option<Vec<usize>> {
    let mut bases: Vec<Vec<Vec<f64>>> = vec![Vec::new(); kinds.len()];
    let mut taken = Vec::new();
    for &r in inside {
        match try_add(&mut bases, &rows[r].coefficients, Some(set), kinds) {
            Ok(()) => taken.push(r),
            Err(fails) => {
                failed.insert(r, fails);
            }
        }
        if taken.len() == set.len() {
            return Some(taken);
        }
    }
    None
}

/// The blocks of `rows` in the order given, by their sizes: a block ends as soon as its
/// rows bring in as many new unknowns (of `unknowns`) as it has rows. A plan that is not
/// block-triangular is one block; `None` when the rows bring in fewer unknowns than rows.
pub fn blocks(rows: &[Equation], unknowns: &[Symbol]) -> Option<Vec<usize>> {
    let mut known: Vec<&Symbol> = Vec::new();
    let (mut sizes, mut open) = (Vec::new(), 0);
    for row in rows {
        open += 1;
        for u in row.unknowns.iter().filter(|u| unknowns.contains(u)) {
            if !known.contains(&u) {
                known.push(u);
            }
        }
        if known.len() == sizes.iter().sum::<usize>() + open {
            sizes.push(open);
            open = 0;
        } else if known.len() < sizes.iter().sum::<usize>() + open {
            return None;
        }
    }
    (open == 0).then_some(sizes)
}
