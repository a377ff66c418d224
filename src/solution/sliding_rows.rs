//! A contact that slides at the initial state: its no-slip row does not hold there, and the
//! sliding law, F_t = −μ N along the slip, stands in its place wherever the rows are
//! printed (the plan's table, step 5 and the matrix form). The no-slip row holds only once
//! the contact sticks (rolls).

use super::force_labels::place;
use crate::equations::Derivation;
use crate::numeric::{FrictionMode as Mode, SiteState};
use crate::plan::Sum;
use crate::render::context::{Plan, Solution};
use crate::render::text::{MarkupLine, Math};
use crate::symbolic::{latex, latex_collected, Expr, Symbol};

/// One no-slip row replaced by the sliding law.
#[derive(Clone, Debug)]
pub struct SlidingRow {
    /// The row's index in the derivation's rows (from 0).
    pub index: usize,
    /// The contact's name, as the problem spells it.
    pub contact: String,
    /// The friction component the row gave while it stuck.
    pub friction: Symbol,
    /// The normal force.
    pub normal: Symbol,
    /// The law as a sum equal to zero: F_t − k μ N, k = ±1 in the plane.
    pub law: Expr,
    /// In the plane (one tangent), the signs of the friction component and of the normal
    /// force at the state: what turns |F_t| = μ|N| into the signed law.
    pub signs: Option<(f64, f64)>,
    /// The coefficient of friction.
    pub mu: Expr,
}

/// The no-slip rows of the contacts that slide at the initial state, each with its sliding
/// law; empty where every contact sticks. A contact with two normal components (a rough
/// slider in space, whose |N| is a root) keeps its rows: its law is said in words only.
pub fn sliding_rows(derivation: &Derivation, friction: &[SiteState]) -> Vec<SlidingRow> {
    let sites = &derivation.model.constraints.friction;
    let mut out = Vec::new();
    for (site, state) in sites.iter().zip(friction) {
        if state.mode != Mode::Slip || site.normal.len() != 1 {
            continue;
        }
        let size = state.friction();
        if size <= 0.0 {
            continue;
        }
        // F_t = (F_t / |F|) μ |N|, |N| = ±N by the sign of the normal force.
        let sign = if state.normal < 0.0 { -1.0 } else { 1.0 };
        for (k, stick) in site.stick.iter().enumerate() {
            let Some(index) = derivation.rows.iter().position(
                |row| matches!(&row.sum, Sum::Constraint { name } if *name == stick.name),
            ) else {
                continue;
            };
            let factor = sign * state.tangential.get(k).copied().unwrap_or(0.0) / size;
            let tangent = state.tangential.get(k).copied().unwrap_or(0.0);
            let signs = ((factor.abs() - 1.0).abs() < 1e-12 && site.stick.len() == 1)
                .then(|| (tangent.signum(), sign));
            let factor = match factor {
                f if (f - 1.0).abs() < 1e-12 => Expr::one(),
                f if (f + 1.0).abs() < 1e-12 => Expr::int(-1),
                f => Expr::real(f),
            };
            let (friction, normal) = (stick.unknown.clone(), site.normal[0].clone());
            let law = Expr::sym(friction.clone())
                - factor * site.coefficient.clone() * Expr::sym(normal.clone());
            out.push(SlidingRow {
                index,
                contact: site.name.clone(),
                friction,
                normal,
                law,
                signs,
                mu: site.coefficient.clone(),
            });
        }
    }
    out
}

/// The law as step 5 prints it: `F^{P}_{x} = -\mu F^{P}_{y}`.
pub fn law_tex(row: &SlidingRow) -> String {
    let friction = Expr::sym(row.friction.clone());
    let rest = crate::symbolic::simplify(&(Expr::sym(row.friction.clone()) - row.law.clone()));
    format!("{} = {}", latex(&friction), latex_collected(&rest))
}

/// The law as a textbook gives it, the sizes `|F_t| = μ|N|`, then the signs of the friction
/// component (against the slip) and of the normal force at this state, and the signed law
/// they give: `|F^S_x| = \mu |F^S_y|,\ F^S_x < 0,\ F^S_y < 0 \Rightarrow F^S_x = \mu F^S_y`.
pub fn sized_law_tex(friction: &str, normal: &str, mu: &str, (f, n): (f64, f64)) -> String {
    let sign = |v: f64| if v < 0.0 { "<" } else { ">" };
    let law = if (f < 0.0) == (n < 0.0) {
        format!("{friction} = {mu} {normal}")
    } else {
        format!("{friction} = -{mu} {normal}")
    };
    format!(
        "\\left\\vert {friction} \\right\\vert = {mu} \\left\\vert {normal} \\right\\vert, \\quad {friction} {} 0,\\ {normal} {} 0 \\quad \\Rightarrow \\quad {law}",
        sign(f),
        sign(n)
    )
}

/// The words before the sized law: the rule, then where the signs come from.
pub const SIZED_LAW_NOTE: &str = "Sliding friction is μ times the normal force in size and points against the slip (here, against the slip that starts); with the signs the two forces have at this state, the law reads:";

/// The row's name in the plan and in step 5's heading.
fn heading_tex(row: &SlidingRow) -> String {
    format!("\\text{{sliding friction at {}}}", place(&row.contact))
}

/// Puts the sliding law in place of each no-slip row in the plan's table and in step 5.
pub fn replace_rows(solution: &mut Solution, derivation: &Derivation, rows: &[SlidingRow]) {
    for row in rows {
        if let Some(plan_row) = solution.plan.rows.get_mut(row.index) {
            plan_row.equation_tex = Math::from(heading_tex(row));
            plan_row.unknowns_tex = Math::from(format!(
                "{}, {}",
                latex(&Expr::sym(row.friction.clone())),
                latex(&Expr::sym(row.normal.clone()))
            ));
        }
        if let Some(view) = solution.equations.get_mut(row.index) {
            view.label_tex = Math::from(heading_tex(row));
            view.label = format!(
                "(while it slides: in place of the no-slip condition, which holds only once the contact at {} sticks)",
                place(&row.contact)
            );
            view.grouped_tex = Math::from(String::new());
            view.written_tex = Math::from(String::new());
            // The law is said before its equation: the no-slip row it replaces was bare.
            view.bare = false;
            if let Some(signs) = row.signs {
                view.simplified_note = SIZED_LAW_NOTE.into();
                view.simplified_tex = Math::from(sized_law_tex(
                    &latex(&Expr::sym(row.friction.clone())),
                    &latex(&Expr::sym(row.normal.clone())),
                    &latex(&row.mu),
                    signs,
                ));
            } else {
                view.simplified_note =
                    "Friction is μ times the normal force, against the slip (its sign from the slip's direction):".into();
                view.simplified_tex = Math::from(law_tex(row));
            }
        }
    }
    if !rows.is_empty() {
        replace_order(&mut solution.plan, &order_sentence(derivation, rows));
    }
}

/// The unknowns of each row once the sliding law stands in for the no-slip rows.
fn row_unknowns(derivation: &Derivation, rows: &[SlidingRow]) -> Vec<Vec<Symbol>> {
    (derivation.rows.iter().enumerate())
        .map(|(i, row)| match rows.iter().find(|r| r.index == i) {
            Some(r) => vec![r.friction.clone(), r.normal.clone()],
            None => row.unknowns.clone(),
        })
        .collect()
}

/// Whether, while the contacts slide, some row gives a single unknown to start the solve
/// from (else the rows are solved together).
pub fn start_in_turn(derivation: &Derivation, rows: &[SlidingRow]) -> bool {
    row_unknowns(derivation, rows).iter().any(|u| u.len() == 1)
}

/// The order in which the rows give the unknowns while the contacts slide: a row with one
/// new unknown at a time, and what is left together.
pub fn order_sentence(derivation: &Derivation, rows: &[SlidingRow]) -> String {
    let unknowns = row_unknowns(derivation, rows);
    let mut known: Vec<Symbol> = Vec::new();
    let mut used = vec![false; unknowns.len()];
    let mut steps: Vec<String> = Vec::new();
    while let Some(i) = (0..unknowns.len())
        .find(|&i| !used[i] && unknowns[i].iter().filter(|u| !known.contains(u)).count() == 1)
    {
        used[i] = true;
        let Some(new) = unknowns[i].iter().find(|u| !known.contains(u)).cloned() else {
            break;
        };
        steps.push(format!("({}) ${}$", i + 1, latex(&Expr::sym(new.clone()))));
        known.push(new);
    }
    let left: Vec<String> = (0..unknowns.len())
        .filter(|&i| !used[i] && unknowns[i].iter().any(|u| !known.contains(u)))
        .map(|i| format!("({})", i + 1))
        .collect();
    let mut contacts: Vec<String> = rows.iter().map(|r| place(&r.contact)).collect();
    contacts.dedup();
    let contacts = contacts.join(" and ");
    let mut sentence = if steps.is_empty() {
        format!(
            "While the contact at {contacts} slides, no row gives a single new unknown: rows {} are solved together",
            left.join(", ")
        )
    } else {
        format!(
            "While the contact at {contacts} slides, the rows give one new unknown each, in the order {}",
            steps.join(", ")
        )
    };
    if !left.is_empty() && !steps.is_empty() {
        sentence.push_str(&format!(
            ", then rows {} give the rest together",
            left.join(", ")
        ));
    }
    sentence.push('.');
    sentence
}

/// The plan's note with its order sentence (written for rows that all hold) replaced by
/// the order with the sliding law.
fn replace_order(plan: &mut Plan, order: &str) {
    let note = plan.note.as_str().to_string();
    let orders = [
        "The equations can be solved in order",
        "Each equation introduces one new unknown",
    ];
    let kept = match orders.iter().filter_map(|o| note.find(o)).min() {
        Some(at) => note[..at].trim_end().to_string(),
        None => note,
    };
    plan.note = MarkupLine::from(format!("{kept} {order}"));
}

/// The matrix's rows with the sliding law in place of each no-slip row: 1 under the
/// friction component, −k μ under the normal force, 0 on the right.
pub fn replace_in_matrix(
    unknowns: &[Symbol],
    a: &mut [Vec<Expr>],
    b: &mut [Expr],
    rows: &[SlidingRow],
) {
    for row in rows {
        let (Some(a_row), Some(b_row)) = (a.get_mut(row.index), b.get_mut(row.index)) else {
            continue;
        };
        let Ok(coefficients) = crate::symbolic::linear_coefficients(&row.law, unknowns) else {
            continue;
        };
        for (entry, c) in a_row.iter_mut().zip(coefficients) {
            *entry = crate::symbolic::simplify(&c);
        }
        *b_row = Expr::zero();
    }
}
