//! Step 3's candidates not used: the sentence for each typed reason, in the notation the
//! plan's table uses, and the sentence on the order in which the rows are solved.

use super::context::Rejected as RejectedView;
use crate::equations::Derivation;
use crate::plan::planner::{Reason, Rejected};
use crate::plan::rejection::SpecialState;
use crate::symbolic::print::latex;
use crate::symbolic::Expr;

/// The rejected candidate as the worked solution prints it.
pub fn view(derivation: &Derivation, rejected: &Rejected) -> RejectedView {
    let model = &derivation.model;
    let candidate = &rejected.candidate;
    let (reason, reason_tex, reason_after) = match &rejected.reason {
        Reason::UnwantedReactions { sites, reactions } => {
            let names: Vec<&str> = sites
                .iter()
                .map(|&j| model.sites[j].name.as_str())
                .collect();
            let place = match names.as_slice() {
                [one] => format!("the reaction at {one}"),
                [first @ .., last] => format!("the reactions at {} and {last}", first.join(", ")),
                [] => "reactions".to_string(),
            };
            let tex: Vec<String> = reactions
                .iter()
                .map(|r| latex(&Expr::sym(r.clone())))
                .collect();
            (
                format!("brings in {place}"),
                tex.join(", "),
                ", which is not asked for".to_string(),
            )
        }
        Reason::NoUnknown => plain("contains none of the unknowns"),
        Reason::Duplicate { row } if *row < derivation.rows.len() => (
            format!("says the same as row {} of the plan", row + 1),
            super::matrix::row_heading_tex(derivation, *row),
            String::new(),
        ),
        Reason::Duplicate { row } => {
            plain(&format!("says the same as row {} of the plan", row + 1))
        }
        Reason::Redundant => plain("adds nothing new: it follows from the rows chosen"),
        Reason::SingularAt(state) => plain(&format!(
            "would make the plan singular {}, though it is independent at most states",
            match state {
                SpecialState::Initial => "at the initial state",
                SpecialState::Requested => "at the state asked for",
                SpecialState::AllZero => "where every coordinate is 0",
                SpecialState::QuarterTurn => "where every coordinate is π/2",
            }
        )),
        Reason::NotNeeded => plain("not needed: the rows chosen already determine every unknown"),
    };
    RejectedView {
        free_body_tex: super::derived::bodies_tex(derivation, &candidate.free_body),
        equation_tex: super::matrix::sum_tex(derivation, &candidate.sum),
        direction_tex: candidate.direction.latex.clone(),
        reason,
        reason_tex,
        reason_after,
    }
}

fn plain(text: &str) -> (String, String, String) {
    (text.to_string(), String::new(), String::new())
}

/// The sentence on the order in which the plan's rows are solved; empty when they must be
/// solved all together.
pub fn order_note(derivation: &Derivation) -> String {
    let blocks = crate::plan::choose::blocks(&derivation.rows, &derivation.system.unknowns);
    let Some(blocks) = blocks.filter(|b| b.len() > 1) else {
        return String::new();
    };
    if blocks.iter().all(|&b| b == 1) {
        return "Each equation introduces one new unknown, so they can be solved one after another."
            .into();
    }
    let mut parts = Vec::new();
    let (mut first, mut i) = (1, 0);
    while i < blocks.len() {
        if blocks[i] > 1 {
            let last = first + blocks[i] - 1;
            parts.push(format!("rows {first} to {last} together"));
            first = last + 1;
            i += 1;
            continue;
        }
        let run = blocks[i..].iter().take_while(|&&b| b == 1).count();
        let last = first + run - 1;
        parts.push(if run == 1 {
            format!("row {first}, which brings in one new unknown")
        } else {
            format!("rows {first} to {last}, each bringing in one new unknown")
        });
        first = last + 1;
        i += run;
    }
    format!(
        "The equations can be solved in order, a few unknowns at a time: {}.",
        parts.join(", then ")
    )
}
