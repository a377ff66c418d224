//! Kane's linear system for the numbers by composite bodies: the mass matrix as the
//! composite-rigid-body algorithm builds it ([`mass`]), and what the rows hold besides the
//! q'' from the bodies' forces carried in from the leaves ([`forces`]), as the recursive
//! Newton–Euler algorithm does, on each body's motion built on its parent's
//! ([`kinematics`]); the rows of requested reactions likewise ([`reactions`]). Kane's rows
//! sum over the bodies for every entry, n³ work for the mass matrix and n² for the rest;
//! these are n² and n.
//!
//! Both rest on one fact. With the rates as the speeds and nothing but the tree's joints
//! constraining the motion, each speed `r` of joint `i` moves the bodies outboard of `i`
//! as one rigid body: with `ω_r` the partial angular velocity of the joint's child and
//! `u_r` the partial velocity of the child's point at the joint `O_i`, a point `P` of a
//! body outboard of `i` has the partial velocity `u_r + ω_r × (P − O_i)` and the body the
//! partial angular velocity `ω_r`; every other body, none. Kane's `Σ F · v_r + T · ω_r`
//! over those bodies is then `u_r · F + ω_r · M(O_i)`, with `F` the resultant of the forces
//! on the bodies outboard of `i` and `M(O_i)` their moment about `O_i` with the couples.
//!
//! A quantity taken at a joint is written in the unit vectors of the joint's child, each
//! component a named quantity, so that carrying it to the next joint in is a rotation by
//! that joint's direction cosines and a cross product of names. A joint's own sliding stays
//! in its parent's unit vectors, where its axes are fixed: a free body's three translations
//! then meet its mass as `m`, not as products of direction cosines that make up `m`.

pub(super) mod forces;
pub(super) mod kinematics;
pub(super) mod mass;
pub(super) mod reactions;
mod tree;

pub use tree::{applies, speed_motions};

use crate::equations::LinearSystem;
use crate::mechanics::Model;
use crate::plan::Action;
use crate::symbolic::{Expr, Program, Symbol};

/// Below this many operations Kane's rows as formed may compile shorter than by composite
/// bodies, and both are built to keep the shorter: a planar chain of two links writes its
/// rows whole in a few dozen operations (the angle sums keep `cos(q1 + q2)` one factor), a
/// handful fewer than by composite bodies. Past a few hundred the composite rows are the
/// shorter (five links in the plane: 359 operations against 506), and forming the rows
/// only to drop them would cost time and memory, n³ of each.
pub const SMALL_PROGRAM: usize = 400;

/// Kane's linear system in `unknowns` (the q'', then the reactions of `reaction_joints`)
/// built by composite bodies alone, without forming Kane's rows, for the numbers of a
/// system large enough that the rows as formed would not be compiled (see
/// [`SMALL_PROGRAM`]). `None` where [`applies`] does not hold or the system is small.
pub fn system_alone(
    model: &Model,
    actions: &[Action],
    unknowns: &[Symbol],
    reaction_joints: &[usize],
) -> Option<LinearSystem> {
    if !applies(model) {
        return None;
    }
    // Every row of the outline is replaced: `system` checks the count.
    let k = unknowns.len();
    let outline = LinearSystem {
        unknowns: unknowns.to_vec(),
        a: vec![vec![Expr::zero(); k]; k],
        b: vec![Expr::zero(); k],
    };
    let built = system(model, actions, &outline, reaction_joints)?;
    let mut outputs: Vec<Expr> = built.a.iter().flatten().cloned().collect();
    outputs.extend(built.b.iter().cloned());
    let inputs = state_symbols(model);
    (Program::compile(&inputs, &outputs).operation_count() >= SMALL_PROGRAM).then_some(built)
}

/// Constants, coordinates, rates and time: what a compiled system reads.
fn state_symbols(model: &Model) -> Vec<Symbol> {
    let problem = model.problem;
    let n = problem.coordinates.len();
    let mut inputs: Vec<Symbol> = problem
        .constants
        .iter()
        .map(|c| Symbol::Const(c.name.as_str().into()))
        .collect();
    inputs.extend((0..n).map(|i| problem.coordinate_symbol(i, 0)));
    inputs.extend((0..n).map(|i| problem.coordinate_symbol(i, 1)));
    inputs.push(Symbol::Time);
    inputs
}

/// Kane's linear system as `formed` from the rows, with the reactions of `reaction_joints`
/// (tree joints, in the order of their rows), every row rebuilt by composite bodies. `None`
/// where [`applies`] does not hold.
pub fn system(
    model: &Model,
    actions: &[Action],
    formed: &LinearSystem,
    reaction_joints: &[usize],
) -> Option<LinearSystem> {
    let speeds = speed_motions(model)?;
    let bodies = kinematics::body_motions(model)?;
    let resultants = forces::resultants(model, actions, &bodies)?;
    let momenta = mass::momenta(model, &speeds)?;
    let mut rebuilt = formed.clone();
    let mass = mass::mass_matrix(model, &speeds, &momenta);
    let rests = forces::rests(model, &resultants, &speeds);
    let rows = rebuilt.a.iter_mut().zip(&mut rebuilt.b);
    for ((row, b), (entries, rest)) in rows.zip(mass.into_iter().zip(rests)) {
        for (entry, m) in row.iter_mut().zip(entries) {
            *entry = -m;
        }
        *b = -rest;
    }
    let reaction_rows = reactions::rows(
        model,
        actions,
        (&speeds, &momenta, &resultants),
        reaction_joints,
        &formed.unknowns,
    )?;
    let n = speeds.iter().map(Vec::len).sum::<usize>();
    if n + reaction_rows.len() != formed.a.len() {
        // A row of another kind (a constraint's, which `applies` rules out).
        return None;
    }
    for (index, (a, b)) in reaction_rows.into_iter().enumerate() {
        rebuilt.a[n + index] = a;
        rebuilt.b[n + index] = b;
    }
    Some(rebuilt)
}
