//! The Motion Law's planner: groups of bodies as free bodies, plans solved one block of
//! unknowns at a time, and the rejected candidates the worked solution shows.

use crate::support::{problem, run};
use mbd_tutor::equations::{Derivation, Method};
use mbd_tutor::mechanics::reaction_unknowns;
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::plan::{blocks, Equation, Reason, Sum, SHOWN};
use mbd_tutor::problem::load_file;
use mbd_tutor::solution::plan_view as plan;

/// `(free body, equation, unknowns)` of each row, as the plan's table names them.
fn rows(derivation: &Derivation) -> Vec<(String, String, Vec<String>)> {
    let problem = derivation.model.problem;
    derivation
        .rows
        .iter()
        .map(|row: &Equation| {
            let bodies: Vec<&str> = row
                .free_body
                .iter()
                .map(|&b| problem.body_name(b))
                .collect();
            let equation = match &row.sum {
                Sum::Moment { point, .. } => format!("M about {point}"),
                Sum::Force => "F".into(),
                Sum::Constraint { name } => format!("constraint {name}"),
                Sum::Generalized { speed } => format!("generalized {speed}"),
            };
            let unknowns = row.unknowns.iter().map(|u| u.to_string()).collect();
            (bodies.join(" + "), equation, unknowns)
        })
        .collect()
}

fn motion_law(name: &str) -> mbd_tutor::problem::Problem {
    load_file(&problem(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn q_dd(problem: &mbd_tutor::problem::Problem, i: usize) -> String {
    problem.coordinate_symbol(i, 2).to_string()
}

/// The reaction components of the joint named `name`.
fn reactions_at(derivation: &Derivation, name: &str) -> Vec<String> {
    let model = &derivation.model;
    let site = (0..model.sites.len())
        .find(|&j| model.sites[j].name == name)
        .expect("the joint");
    reaction_unknowns(model, &[site])
        .iter()
        .map(|s| s.to_string())
        .collect()
}

#[test]
fn the_double_pendulum_takes_both_rods_about_o_free_of_every_reaction() {
    let problem = motion_law("double-pendulum-rods");
    let derivation = derive(&problem, Method::MotionLaw, Purpose::Rows).expect("derives");
    let rows = rows(&derivation);
    // Moments of A + B about O: the pin force at O has no moment there and the one at P
    // is internal, so only q1'' and q2'' remain.
    let about_o = rows
        .iter()
        .find(|(body, equation, _)| body == "A + B" && equation == "M about O")
        .unwrap_or_else(|| panic!("no A + B about O in {rows:?}"));
    assert_eq!(about_o.2, vec![q_dd(&problem, 0), q_dd(&problem, 1)]);
    // Then B about P for the second q'', and one new pin force per row.
    assert_eq!(
        rows.iter()
            .map(|(b, e, _)| format!("{b}: {e}"))
            .collect::<Vec<_>>(),
        ["A + B: M about O", "B: M about P", "A + B: F", "A + B: F"]
    );
    assert_eq!(
        blocks(&derivation.rows, &derivation.system.unknowns),
        Some(vec![2, 1, 1])
    );
}

#[test]
fn the_four_bar_takes_crank_and_coupler_about_o() {
    let problem = motion_law("four-bar");
    let derivation = derive(&problem, Method::MotionLaw, Purpose::Rows).expect("derives");
    let rows = rows(&derivation);
    let about_o = rows
        .iter()
        .find(|(body, equation, _)| body == "A + B" && equation == "M about O")
        .unwrap_or_else(|| panic!("no A + B about O in {rows:?}"));
    // The pin force at O has no moment about O; the one at P is internal.
    let at_o = reactions_at(&derivation, "O");
    let at_p = reactions_at(&derivation, "P");
    assert!(
        about_o
            .2
            .iter()
            .all(|u| !at_o.contains(u) && !at_p.contains(u)),
        "{about_o:?}"
    );
    // No group holds both ends of the closure R (B and C): its rows would hold on the
    // closed loop alone, not at every state the other methods are compared at.
    assert!(
        rows.iter()
            .all(|(body, _, _)| !(body.contains('B') && body.contains('C'))),
        "{rows:?}"
    );
    let sizes = blocks(&derivation.rows, &derivation.system.unknowns).expect("a square plan");
    assert_eq!(sizes.iter().sum::<usize>(), derivation.rows.len());
    assert!(sizes.len() > 1, "solved in order: {sizes:?}");
}

#[test]
fn the_spatial_arm_is_solved_one_unknown_per_row() {
    let problem = motion_law("arm-3d-rrp");
    let derivation = derive(&problem, Method::MotionLaw, Purpose::Rows).expect("derives");
    let n = derivation.rows.len();
    assert_eq!(
        blocks(&derivation.rows, &derivation.system.unknowns),
        Some(vec![1; n]),
        "{:?}",
        rows(&derivation)
    );
    let shown = plan(&derivation);
    assert!(
        shown
            .note
            .contains("Each equation introduces one new unknown"),
        "{}",
        shown.note
    );
}

/// Internal names of reaction components, like `P.Fx` or `U.M1`.
fn internal_name(text: &str) -> Option<&str> {
    let bytes = text.as_bytes();
    (1..bytes.len().saturating_sub(1)).find_map(|i| {
        let named = bytes[i] == b'.'
            && bytes[i - 1].is_ascii_alphanumeric()
            && matches!(bytes[i + 1], b'F' | b'M');
        named.then(|| &text[i.saturating_sub(3)..(i + 4).min(text.len())])
    })
}

#[test]
fn the_handout_shows_a_few_rejected_candidates_in_a_students_notation() {
    for path in crate::support::all_problems() {
        let problem = load_file(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let derivation = derive(&problem, Method::MotionLaw, Purpose::Rows).expect("derives");
        let shown = plan(&derivation);
        assert!(
            shown.rejected.len() <= SHOWN,
            "{}: {} shown",
            path.display(),
            shown.rejected.len()
        );
        // Less only a candidate about the very point of a chosen row (said once, by it).
        assert_eq!(shown.rejected_total, shown.rejected_all.len());
        assert!(shown.rejected_all.len() <= derivation.rejected.len());
        for r in &shown.rejected {
            for text in [
                r.free_body_tex.as_str(),
                r.equation_tex.as_str(),
                r.reason.as_str(),
                r.reason_after.as_str(),
            ] {
                assert_eq!(internal_name(text), None, "{}: {text}", path.display());
            }
        }
        // A reason that names reactions names them in math, and the sites by name.
        for r in &derivation.rejected {
            if let Reason::UnwantedReactions { sites, reactions } = &r.reason {
                assert!(
                    !sites.is_empty() && !reactions.is_empty(),
                    "{}",
                    path.display()
                );
            }
        }
    }
}

#[test]
fn the_rejected_reason_names_the_reaction_at_the_next_joint() {
    let problem = motion_law("double-pendulum-rods");
    let derivation = derive(&problem, Method::MotionLaw, Purpose::Rows).expect("derives");
    let shown = plan(&derivation);
    let a_about_o = shown
        .rejected
        .iter()
        .find(|r| r.free_body_tex == "A" && r.equation_tex == "\\sum \\mathbf{M}_{O}")
        .unwrap_or_else(|| panic!("{:?}", shown.rejected));
    assert_eq!(a_about_o.reason, "brings in the reaction at P");
    assert!(a_about_o.reason_tex.contains("F^{P}"), "{a_about_o:?}");
}

fn candidates_section(page: &str) -> Vec<String> {
    let start = page
        .find("Equations one could also write")
        .expect("the list");
    page[start..]
        .lines()
        .skip(1)
        .skip_while(|l| l.trim().is_empty())
        .take_while(|l| l.starts_with("- "))
        .map(str::to_string)
        .collect()
}

#[test]
fn explain_lists_the_rejected_candidates_only_when_verbose() {
    let p = problem("double-pendulum-rods");
    let default = run(&["explain".as_ref(), p.as_os_str()]);
    let verbose = run(&["explain".as_ref(), p.as_os_str(), "--verbose".as_ref()]);
    assert!(default.status.success() && verbose.status.success());
    let (default, verbose) = (
        String::from_utf8_lossy(&default.stdout).into_owned(),
        String::from_utf8_lossy(&verbose.stdout).into_owned(),
    );
    let problem = load_file(&p).expect("loads");
    let total = derive(&problem, Method::MotionLaw, Purpose::Rows)
        .expect("derives")
        .rejected
        .len();
    // The handout a class reads leaves the unused rows out: the plan's note says why its
    // rows were chosen, and --verbose lists every candidate.
    assert!(
        !default.contains("Equations one could also write"),
        "the unused rows only with --verbose"
    );
    assert!(
        !default.contains(&format!("of {total},")),
        "no count of the program's candidates in a handout"
    );
    assert!(
        !default.contains("explain --verbose"),
        "no command in a handout"
    );
    assert_eq!(candidates_section(&verbose).len(), total);
    assert!(!verbose.contains("Candidates not used"));
}

/// Step 5 heads each equation in math, `A + B: ΣM_O · n̂_z`, never with a frame's
/// internal axis name such as `N.z` or a reaction's `O.Fx`.
#[test]
fn step_5_heads_each_equation_in_math() {
    use mbd_tutor::solution::equation_view;
    for path in crate::support::all_problems() {
        let problem = load_file(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        for method in Method::ALL {
            let derivation = derive(&problem, method, Purpose::Rows).expect("derives");
            for row in &derivation.rows {
                let view = equation_view(&derivation, row);
                assert!(!view.label_tex.is_empty(), "{}: {view:?}", path.display());
                for text in [view.label_tex.as_str(), view.label.as_str()] {
                    let axis = text.as_bytes().windows(3).any(|w| {
                        w[0].is_ascii_alphanumeric() && w[1] == b'.' && b"xyzFM".contains(&w[2])
                    });
                    assert!(!axis, "{}, {}: {text}", path.display(), method.name());
                }
            }
        }
    }
}

/// The disc in the cylinder: its planar joint J is at the mass centre D*, so ΣM about D*
/// is the chosen row ΣM_J again. The planner finds it a duplicate; the handout does not
/// list it as a second equation that "says the same".
#[test]
fn a_moment_about_the_same_point_is_said_once() {
    let problem = load_file(&problem("disc-in-cylinder")).expect("loads");
    let derivation = derive(&problem, Method::MotionLaw, Purpose::Rows).expect("derives");
    let about = |sum: &Sum, name: &str| matches!(sum, Sum::Moment { point, .. } if point == name);
    let found = derivation.rejected.iter().any(|r| match r.reason {
        Reason::Duplicate { row } => {
            about(&r.candidate.sum, "D*") && about(&derivation.rows[row].sum, "J")
        }
        _ => false,
    });
    assert!(found, "the planner finds ΣM_D* a duplicate of ΣM_J");
    let shown = plan(&derivation);
    for r in shown.rejected.iter().chain(&shown.rejected_all) {
        let twice = r.equation_tex.as_str().contains("D^{*}")
            && r.reason_tex.as_str().contains("\\mathbf{M}_{J}");
        assert!(!twice, "{} {}", r.equation_tex.as_str(), r.reason);
    }
}
