//! Coulomb friction in the equations: every method solves for the friction and normal
//! forces of each friction site, and is formed with the site sticking (rolling). The rows
//! that say so are named after the site's tangential components, so that the numbers can
//! exchange them for the sliding law where the site slips ([`crate::numeric::friction`]).

use crate::mechanics::{MechanicsError, Model};
use crate::plan::{Equation, Sum};
use crate::symbolic::{linear_split, Expr, Symbol};

/// Adds every friction site to the sites whose reactions are unknowns: friction is
/// proportional to the normal force, so neither Newton–Euler nor the Motion Law may leave
/// it out (Kane's rows keep the friction and normal forces alone, [`kept_forces`]).
pub fn require_sites(model: &Model, reaction_sites: &mut Vec<usize>) {
    for f in &model.constraints.friction {
        if !reaction_sites.contains(&f.site) {
            reaction_sites.push(f.site);
        }
    }
}

/// The rows that hold while each friction site sticks, at the acceleration level.
///
/// # Errors
/// When a row cannot be differentiated.
pub fn stick_equations(
    model: &Model,
    unknowns: &[Symbol],
) -> Result<Vec<Equation>, MechanicsError> {
    let rows = model.constraints.friction.iter().flat_map(|f| &f.stick);
    super::constraint_rows::constraint_equations(rows, unknowns)
}

/// `given` with each friction site's stick rows written as the sliding law writes them,
/// `F_k − c N = 0` (generic c): rows for the Motion Law's planner to judge a plan by where
/// sticking leaves the forces undetermined but sliding does not. Two rough contacts of one
/// body (a box on two edges, a ladder on a rough floor and wall) share one no-slip motion,
/// so their sticking rows say the same thing; sliding, each has its own law. The chosen
/// rows are the stick rows again ([`stick_rows_back`]): the numbers exchange them where a
/// site slips.
pub fn sliding_stand_ins(model: &Model, given: &[Equation], unknowns: &[Symbol]) -> Vec<Equation> {
    let mut stand_ins = given.to_vec();
    for (k, f) in model.constraints.friction.iter().enumerate() {
        for (t, row) in f.stick.iter().enumerate() {
            let Some(at) = given
                .iter()
                .position(|e| matches!(&e.sum, Sum::Constraint { name } if *name == row.name))
            else {
                continue;
            };
            // Coefficients no two sites share, so that no choice of rows is singular by
            // coincidence.
            let mut expression = Expr::sym(row.unknown.clone());
            for (n, normal) in f.normal.iter().enumerate() {
                let c = Expr::ratio(7 + 3 * (k + t + n) as i64, 11 + 5 * k as i64 + 2 * t as i64);
                expression = &expression - &(&c * &Expr::sym(normal.clone()));
            }
            let equation = &mut stand_ins[at];
            equation.unknowns = crate::plan::unknowns_in(&expression, unknowns);
            equation.groups.contact = expression.clone();
            equation.expression = expression;
        }
    }
    stand_ins
}

/// The chosen rows with each stand-in of [`sliding_stand_ins`] exchanged for the stick row
/// of the same name in `given`.
pub fn stick_rows_back(rows: Vec<Equation>, given: &[Equation]) -> Vec<Equation> {
    rows.into_iter()
        .map(|row| match &row.sum {
            Sum::Constraint { name } => given
                .iter()
                .find(|e| matches!(&e.sum, Sum::Constraint { name: n } if n == name))
                .cloned()
                .unwrap_or(row),
            _ => row,
        })
        .collect()
}

/// Adds to `q`, one generalized force per coordinate, the friction force of each site (of
/// each rough prismatic joint of the tree alone, when `tree_only`): a component `F` whose
/// stick row is the slip velocity `v_t` gives `F ∂v_t/∂q'` (a rough slider's `F ∂(±q')/∂q'`).
/// Kane's rows leave the rest of a reaction out, as it does no work; with the
/// coordinates' rates as speeds the reactions at closures and contacts are taken whole
/// instead (`tree_only`).
pub fn add_friction_forces(model: &Model, q: &mut [Expr], tree_only: bool) {
    let problem = model.problem;
    let rates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|i| problem.coordinate_symbol(i, 1))
        .collect();
    for f in &model.constraints.friction {
        if tree_only && f.site >= problem.joints.len() {
            continue;
        }
        for row in &f.stick {
            let Ok((coefficients, _)) = linear_split(&row.velocity, &rates) else {
                continue;
            };
            for (c, coefficient) in coefficients.iter().enumerate() {
                if !coefficient.is_zero() {
                    q[c] = &q[c] + &(coefficient * &Expr::sym(row.unknown.clone()));
                }
            }
        }
    }
}

/// Whether `unknown` is the friction force of a rough prismatic joint `j` of the tree.
pub fn is_slider_friction(model: &Model, j: usize, unknown: &Symbol) -> bool {
    j < model.problem.joints.len()
        && model
            .constraints
            .friction
            .iter()
            .any(|f| f.site == j && f.stick.iter().any(|r| r.unknown == *unknown))
}

/// The friction and normal forces of every site, but those among `asked` (the unknowns of
/// requested reactions): the unknowns Kane's rows keep though no reaction is asked for.
/// The friction force does work while the site slips; the normal force gets an auxiliary
/// speed along it.
pub fn kept_forces(model: &Model, asked: &[Symbol]) -> Vec<Symbol> {
    let mut kept: Vec<Symbol> = Vec::new();
    for unknown in friction_forces(model)
        .into_iter()
        .chain(normal_forces(model))
    {
        if !asked.contains(&unknown) && !kept.contains(&unknown) {
            kept.push(unknown);
        }
    }
    kept
}

/// The friction forces' unknowns of every site: the stick rows' unknowns.
pub fn friction_forces(model: &Model) -> Vec<Symbol> {
    let sites = model.constraints.friction.iter();
    sites
        .flat_map(|f| f.stick.iter().map(|r| r.unknown.clone()))
        .collect()
}

/// The normal forces' unknowns of every friction site.
pub fn normal_forces(model: &Model) -> Vec<Symbol> {
    let sites = model.constraints.friction.iter();
    sites.flat_map(|f| f.normal.iter().cloned()).collect()
}
