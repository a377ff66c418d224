//! Why the planner left a candidate row out, as a type: the worked solution prints its
//! sentences from it, and picks the few rejections worth showing a student.

use super::planner::Candidate;
use super::rows::Sum;
use crate::mechanics::{reaction_unknowns, Model};
use crate::symbolic::Symbol;

/// A state at which rows that are independent at generic states may fail together.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpecialState {
    /// The problem's initial state.
    Initial,
    /// A state the caller will solve at.
    Requested,
    /// Every coordinate zero (often the equilibrium a student linearizes about).
    AllZero,
    /// Every coordinate a quarter turn, π/2.
    QuarterTurn,
}

/// Why a candidate row was not used.
#[derive(Clone, Debug, PartialEq)]
pub enum Reason {
    /// It brings in reaction components that are not asked for.
    UnwantedReactions {
        /// The sites (joints, closures, contacts) of those reactions, as indices of
        /// `Model::sites`.
        sites: Vec<usize>,
        /// The reaction components themselves.
        reactions: Vec<Symbol>,
    },
    /// It contains none of the unknowns.
    NoUnknown,
    /// Its coefficients are a multiple of those of a chosen row: it says the same thing.
    Duplicate {
        /// The chosen row, as an index of the plan's rows.
        row: usize,
    },
    /// It adds no new equation: it follows from the rows chosen.
    Redundant {
        /// The chosen rows it is a combination of, as indices of the plan's rows; empty
        /// when it follows from them only on the unknowns of a block.
        rows: Vec<usize>,
    },
    /// It would add a new equation at generic states, but not at a special one, where the
    /// plan would become singular.
    SingularAt(SpecialState),
    /// The rows chosen already determine every unknown.
    NotNeeded {
        /// The chosen rows it is a combination of, as indices of the plan's rows.
        rows: Vec<usize>,
    },
}

/// A candidate the planner did not use, and why.
#[derive(Clone, Debug)]
pub struct Rejected {
    /// The candidate row.
    pub candidate: Candidate,
    /// Why it was not chosen.
    pub reason: Reason,
}

/// The reason for a candidate whose reactions include `unwanted`: the sites they belong to.
pub fn unwanted(model: &Model, unwanted: &[Symbol]) -> Reason {
    let sites = (0..model.sites.len())
        .filter(|&j| {
            reaction_unknowns(model, &[j])
                .iter()
                .any(|r| unwanted.contains(r))
        })
        .collect();
    Reason::UnwantedReactions {
        sites,
        reactions: unwanted.to_vec(),
    }
}

/// How many rejected candidates the worked solution shows at most (`explain --verbose`
/// shows them all).
pub const SHOWN: usize = 4;

/// The few rejected candidates worth showing a student, as indices of `rejected`, in its
/// order: the natural first choices that fail (moments of one body about its own joint,
/// which bring in a reaction not asked for) and, when that leaves fewer than two, a row
/// that adds nothing new, one that says the same as a chosen row, and one that the rows
/// chosen make unnecessary. A row left out only
/// because the plan would fail at a special state (every coordinate 0) teaches nothing
/// about choosing equations, so it is listed only by `explain --verbose`.
pub fn highlights(model: &Model, rejected: &[Rejected]) -> Vec<usize> {
    let mut shown: Vec<usize> = Vec::new();
    // The natural first choice for each body: moments about the joint that holds it, along
    // that joint's axis when it has one (else the first direction tried).
    for &body in &model.order {
        let Some(site) = model.sites.iter().find(|s| s.child == body) else {
            continue;
        };
        let natural = |r: &Rejected| {
            r.candidate.free_body == [body]
                && matches!(&r.candidate.sum, Sum::Moment { point, .. } if *point == site.name)
        };
        let about_joint: Vec<usize> = (0..rejected.len())
            .filter(|&i| natural(&rejected[i]))
            .collect();
        let pick = about_joint
            .iter()
            .copied()
            .find(|&i| rejected[i].candidate.direction.name.starts_with("axis of"))
            .or(about_joint.first().copied());
        if let Some(i) = pick.filter(|&i| {
            matches!(rejected[i].reason, Reason::UnwantedReactions { .. }) && !shown.contains(&i)
        }) {
            shown.push(i);
        }
    }
    shown.truncate(SHOWN - 1);
    // With nothing else to show, a row that adds nothing new, and one that says the same
    // as a chosen row: the first of each, in candidate order.
    if shown.len() < 2 {
        for wanted in [
            Reason::Redundant { rows: Vec::new() },
            Reason::Duplicate { row: 0 },
            Reason::NotNeeded { rows: Vec::new() },
        ] {
            let same = |r: &Reason| std::mem::discriminant(r) == std::mem::discriminant(&wanted);
            if let Some(i) = (0..rejected.len()).find(|&i| same(&rejected[i].reason)) {
                if shown.len() < SHOWN && !shown.contains(&i) {
                    shown.push(i);
                }
            }
        }
    }
    shown.sort();
    shown
}
