//! Step 3's candidates not used: the sentence for each typed reason, in the notation the
//! plan's table uses, and the sentence on the order in which the rows are solved.

use crate::equations::Derivation;
use crate::plan::{Reason, Rejected, SpecialState, Sum};
use crate::render::context::Rejected as RejectedView;
use crate::render::text::Math;
use crate::symbolic::{latex, Expr};

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
                if names.len() > 1 {
                    ", which are not asked for"
                } else {
                    ", which is not asked for"
                }
                .to_string(),
            )
        }
        Reason::NoUnknown => plain("contains none of the unknowns"),
        Reason::Duplicate { row } if *row < derivation.rows.len() => (
            format!("says the same as row {} of the plan", row + 1),
            super::row_names::row_heading_tex(derivation, *row),
            String::new(),
        ),
        Reason::Duplicate { row } => {
            plain(&format!("says the same as row {} of the plan", row + 1))
        }
        Reason::Redundant { rows } | Reason::NotNeeded { rows } => plain(&match rows.as_slice() {
            [] if matches!(rejected.reason, Reason::NotNeeded { .. }) => {
                "not needed: the rows chosen already determine every unknown".to_string()
            }
            [] => "adds nothing new: it follows from the rows chosen".to_string(),
            [one] => format!("adds nothing that row {} does not already say", one + 1),
            _ => format!(
                "adds nothing that rows {} do not already say",
                row_list(rows)
            ),
        }),
        Reason::SingularAt(state) => plain(&format!(
            "not needed: the rows chosen determine every unknown, {}",
            match state {
                SpecialState::Initial => "at the initial state too",
                SpecialState::Requested => "at the state asked for too",
                SpecialState::AllZero => "also where every coordinate is 0",
                SpecialState::QuarterTurn => "also where every coordinate is π/2",
            }
        )),
    };
    RejectedView {
        free_body_tex: Math::from(super::tex::bodies_tex(derivation, &candidate.free_body)),
        equation_tex: Math::from(super::row_names::sum_tex(derivation, &candidate.sum)),
        direction_tex: Math::from(candidate.direction.latex.clone()),
        reason,
        reason_tex: Math::from(reason_tex),
        reason_after,
    }
}

/// Whether a candidate not used is a chosen row again, about the very same point: a joint
/// at a body's mass centre makes ΣM_J and ΣM_{D*} one equation, said once, by the row.
pub fn repeats_the_same_point(derivation: &Derivation, rejected: &Rejected) -> bool {
    let Reason::Duplicate { row } = rejected.reason else {
        return false;
    };
    let Some(chosen) = derivation.rows.get(row) else {
        return false;
    };
    let (Sum::Moment { position: a, .. }, Sum::Moment { position: b, .. }) =
        (&rejected.candidate.sum, &chosen.sum)
    else {
        return false;
    };
    if chosen.free_body != rejected.candidate.free_body {
        return false;
    }
    let model = &derivation.model;
    let apart = a
        .minus(b)
        .components_in(crate::problem::BodyId::GROUND, &model.frames);
    crate::mechanics::sample_states(model).iter().all(|state| {
        apart
            .iter()
            .all(|c| crate::symbolic::eval(c, state).abs() <= 1e-12)
    })
}

/// Plan rows (indices from 0) as a sentence names them, from 1, a run of three or more by
/// its ends: `1, 2 and 4`, `1 to 6`.
pub(super) fn row_list(rows: &[usize]) -> String {
    let mut parts: Vec<String> = Vec::new();
    let mut i = 0;
    while i < rows.len() {
        let run = rows[i..]
            .windows(2)
            .take_while(|w| w[1] == w[0] + 1)
            .count()
            + 1;
        if run >= 3 {
            parts.push(format!("{} to {}", rows[i] + 1, rows[i + run - 1] + 1));
            i += run;
        } else {
            parts.push((rows[i] + 1).to_string());
            i += 1;
        }
    }
    match parts.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => parts.concat(),
    }
}

fn plain(text: &str) -> (String, String, String) {
    (text.to_string(), String::new(), String::new())
}

/// The sentence on the order in which the plan's rows are solved; empty when they must be
/// solved all together.
pub fn order_note(derivation: &Derivation) -> String {
    let blocks = crate::plan::blocks(&derivation.rows, &derivation.system.unknowns);
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

/// What this plan's moment rows leave out, said of its own points: "Taking moments about
/// O and P leaves out the reactions at those points." Empty where no moment row is about a
/// point where a reaction on its free body acts.
pub fn moment_note(derivation: &Derivation) -> String {
    let mut points: Vec<&str> = Vec::new();
    let mut names: Vec<String> = Vec::new();
    for row in &derivation.rows {
        let Sum::Moment { point, position } = &row.sum else {
            continue;
        };
        let acts = derivation.model.sites.iter().any(|site| {
            site.name == *point
                && !site.reactions.is_empty()
                && row.free_body.contains(&site.child) != row.free_body.contains(&site.parent)
        });
        let kept = (row.unknowns.iter()).any(|u| match u {
            crate::symbolic::Symbol::Unknown(unknown) => unknown.site() == Some(point.as_str()),
            _ => false,
        });
        if acts && !kept && !points.contains(&point.as_str()) {
            points.push(point);
            let shown = super::moment_point::shown_point(&derivation.model, point, position);
            names.push(format!("${}$", super::tex::point_tex(&shown)));
        }
    }
    match names.as_slice() {
        [] => String::new(),
        [one] => format!("Taking moments about {one} leaves out the reaction at {one}."),
        [rest @ .., last] => format!(
            "Taking moments about {} and {last} leaves out the reactions at those points.",
            rest.join(", ")
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::row_list;

    #[test]
    fn rows_are_named_from_one_with_runs_by_their_ends() {
        assert_eq!(row_list(&[2]), "3");
        assert_eq!(row_list(&[2, 3]), "3 and 4");
        assert_eq!(row_list(&[0, 1, 5, 6]), "1, 2, 6 and 7");
        assert_eq!(row_list(&[0, 1, 2, 3, 4, 5]), "1 to 6");
        assert_eq!(row_list(&[0, 2, 3, 4, 7]), "1, 3 to 5 and 8");
    }
}
