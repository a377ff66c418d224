//! The order of step 5's solve while a contact slides. Its no-slip row does not hold then,
//! and the sliding law takes its place, so the rows without a reaction no longer give the
//! second derivatives alone: the sentence says which rows, with the law, give them.

use crate::equations::Derivation;
use crate::numeric::{FrictionMode as Mode, SiteState};
use crate::plan::Sum;
use crate::render::text::MarkupLine;
use crate::symbolic::{latex, Expr, Symbol};

/// `(1), (2) and (4)`.
fn row_list(rows: &[usize]) -> String {
    let names: Vec<String> = rows.iter().map(|i| format!("({})", i + 1)).collect();
    listed(&names)
}

fn listed(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {last}", init.join(", ")),
    }
}

/// `$\ddot{x}$, $\ddot{y}$`, or with `and` before the last where `and_last`.
fn math_list(symbols: &[&Symbol], and_last: bool) -> String {
    let items: Vec<String> = (symbols.iter())
        .map(|u| format!("${}$", latex(&Expr::sym((*u).clone()))))
        .collect();
    match and_last {
        true => listed(&items),
        false => items.join(", "),
    }
}

/// The sentence for the sites that slide at the initial state; `None` where none does.
pub fn sliding_order(derivation: &Derivation, friction: &[SiteState]) -> Option<String> {
    let sites = &derivation.model.constraints.friction;
    let sliding: Vec<_> = (sites.iter().zip(friction))
        .filter(|(_, state)| state.mode == Mode::Slip)
        .map(|(site, _)| site)
        .collect();
    if sliding.is_empty() {
        return None;
    }
    let no_slip: Vec<usize> = (0..derivation.rows.len())
        .filter(|&i| {
            let Sum::Constraint { name } = &derivation.rows[i].sum else {
                return false;
            };
            (sliding.iter()).any(|site| site.stick.iter().any(|r| r.name == *name))
        })
        .collect();
    if no_slip.is_empty() {
        return None;
    }
    let kept: Vec<usize> = (0..derivation.rows.len())
        .filter(|i| !no_slip.contains(i))
        .collect();
    let unknowns = &derivation.system.unknowns;
    let accelerations: Vec<&Symbol> = (unknowns.iter())
        .filter(|u| !matches!(u, Symbol::Unknown(_)))
        .collect();
    let reactions: Vec<&Symbol> = (unknowns.iter())
        .filter(|u| matches!(u, Symbol::Unknown(_)))
        .collect();
    let names: Vec<String> = (sliding.iter())
        .map(|s| super::force_labels::place(&s.name))
        .collect();
    let (row, does, law) = match (no_slip.len(), sliding.len()) {
        (1, 1) => ("condition", "does", "law"),
        (_, 1) => ("conditions", "do", "law"),
        _ => ("conditions", "do", "laws"),
    };
    let reaction_words = if reactions.len() == 1 {
        "reaction"
    } else {
        "reactions"
    };
    let rows = super::sliding_rows::sliding_rows(derivation, friction);
    if !rows.is_empty() {
        // Step 5 prints the sliding law as the row itself and says so beside it; the
        // order of the solve is step 3's, said there once.
        let how = match super::sliding_rows::start_in_turn(derivation, &rows) {
            true => "taken one at a time in step 3's order",
            false => "solved together, as step 3 says",
        };
        return Some(format!("The rows, {how}, give the values below."));
    }
    Some(format!(
        "While the contact at {} slides, the no-slip {row} {} {does} not hold. Rows {} with the sliding {law} above give {} and the {reaction_words} {} together.",
        listed(&names),
        row_list(&no_slip),
        row_list(&kept),
        math_list(&accelerations, false),
        math_list(&reactions, true),
    ))
}

/// Puts the sliding order in place of the order of the solve while every contact sticks
/// (see `solve_words`), which holds only then.
pub fn replace_order(notes: &mut Vec<MarkupLine>, derivation: &Derivation, friction: &[SiteState]) {
    let Some(order) = sliding_order(derivation, friction) else {
        return;
    };
    let sticking = super::solve_words::order(derivation);
    notes.retain(|n| Some(n.as_str()) != sticking.as_deref());
    notes.insert(0, MarkupLine::from(order));
}
