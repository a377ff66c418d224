//! What a student need not read twice: the handout says each value once. Step 5 prints no
//! table of reactions at the initial state of a motion (the Answers give those asked; at rest
//! those the answers leave), the table of initial values is left out where the answers give
//! every value in it, and step 3's candidate rows that the plan does not use are left out
//! unless every one is asked for (`--verbose`).

use crate::render::Solution;

/// Leaves out of `solution` what its Answers already say and, unless `every_rejected`, the
/// rows step 3 does not use; the answers do not restate a question the statement words
/// (`numbered`: the statement numbers its items) or one that only names what it asks.
pub fn without_repeats(solution: &mut Solution, every_rejected: bool, numbered: bool) {
    if !every_rejected {
        solution.plan.rejected.clear();
    }
    let said = said_at_start(solution);
    // The table of initial values whole or not at all: a part of it would read as if the
    // values left out were not found.
    let whole = solution.initial_values.clone();
    (solution.initial_values).retain(|v| !said.iter().any(|s| gives(s, v.name_tex.as_str())));
    if !solution.initial_values.is_empty() {
        solution.initial_values = whole;
    }
    // In motion, reactions nobody asked for: a table of them at the initial state repeats
    // the answers where they are asked, and beside a motion's answers reads as if it were
    // theirs (the top's tip force at the simulated start, one page before its steady
    // precession's). At rest they are what statics finds: those the answers leave.
    match solution.statics {
        Some(_) => {
            (solution.reactions).retain(|r| !said.iter().any(|s| gives_reaction(s, &r.joint)))
        }
        None => solution.reactions.clear(),
    }
    said_at_the_head(&mut solution.answers);
    super::answer_leads::mark_repeated_states(&mut solution.answers);
    super::answer_lines::tighten(&mut solution.answers, numbered);
}

/// An answer states each value once, at its head (`ẍ = −1.962 m/s²`), where a reader looks
/// for it: a working that ends with the same quantity and number (`ẍ = −g μ = −1.962 m/s²`)
/// ends with its closed form instead (`ẍ = −g μ`). A working's step that is the value alone,
/// with no closed form before it, is left as it is.
fn said_at_the_head(views: &mut [crate::render::AnswerView]) {
    for view in views {
        let values: Vec<String> = (view.values_tex.iter())
            .map(|v| v.as_str().to_string())
            .collect();
        for step in &mut view.steps {
            if let Some(closed) = without_value(step.math.as_str(), &values) {
                step.math = closed.into();
            }
        }
    }
}

/// `math` (`a = f = n`) without its last side where `a = n` is one of `values` and a closed
/// form `f` stays; `None` otherwise.
fn without_value(math: &str, values: &[String]) -> Option<String> {
    let (name, _) = math.split_once(" = ")?;
    let (closed, number) = math.rsplit_once(" = ")?;
    let value = format!("{} = {}", name.trim(), number.trim());
    (closed.contains(" = ") && values.iter().any(|v| v.trim() == value))
        .then(|| closed.trim_end().to_string())
}

/// Whether an answer's value is a component of the reaction at `joint`, its force or moment.
fn gives_reaction(value: &str, joint: &str) -> bool {
    let name = crate::symbolic::latex_name(joint);
    ["\\mathbf{F}^{", "\\mathbf{M}^{"]
        .iter()
        .any(|vector| value.starts_with(&format!("{vector}{name}}}")))
}

/// The values the Answers give at the initial state: those of an answer said to be at it,
/// and of every answer at the same state.
fn said_at_start(solution: &Solution) -> Vec<String> {
    let key = |a: &crate::render::AnswerView| format!("{}§{}", a.at_tex.as_str(), a.at_note);
    let starts: Vec<String> = (solution.answers.iter())
        .filter(|a| a.at_note.contains("initial state"))
        .map(key)
        .collect();
    (solution.answers.iter())
        .filter(|a| starts.contains(&key(a)))
        .flat_map(|a| a.values_tex.iter().map(|v| v.as_str().to_string()))
        .collect()
}

/// Whether the answer's value `value` (`\ddot{x} = 0.72\ \mathrm{m/s^{2}}`) gives `name`.
fn gives(value: &str, name: &str) -> bool {
    !name.is_empty()
        && value
            .strip_prefix(name)
            .is_some_and(|rest| rest.trim_start().starts_with('='))
}

#[cfg(test)]
mod tests {
    use super::gives;

    #[test]
    fn a_value_gives_the_name_it_opens_with() {
        assert!(gives("\\ddot{x} = 0.72\\ \\mathrm{m/s^{2}}", "\\ddot{x}"));
        assert!(!gives("\\ddot{x}_{2} = 0.72", "\\ddot{x}"));
        assert!(!gives("\\ddot{\\theta} = 1", "\\ddot{x}"));
        assert!(!gives("x = 1", ""));
    }

    #[test]
    fn a_working_ends_with_its_closed_form_where_the_head_states_the_value() {
        let values = ["\\ddot{x} = -1.962\\ \\mathrm{m/s^{2}}".to_string()];
        let worked = "\\ddot{x} = -g \\mu = -1.962\\ \\mathrm{m/s^{2}}";
        assert_eq!(
            super::without_value(worked, &values).as_deref(),
            Some("\\ddot{x} = -g \\mu")
        );
        // The value alone, another number, or another quantity: left as it is.
        assert_eq!(super::without_value(&values[0], &values), None);
        let other = "\\ddot{x} = -g \\mu = -1.963\\ \\mathrm{m/s^{2}}";
        assert_eq!(super::without_value(other, &values), None);
        let theta = "\\ddot{\\theta} = -g \\mu = -1.962\\ \\mathrm{m/s^{2}}";
        assert_eq!(super::without_value(theta, &values), None);
    }

    #[test]
    fn a_reaction_is_given_by_its_components() {
        let f = "\\mathbf{F}^{\\mathrm{floor}} \\cdot \\hat{\\mathbf{n}}_{y} = 56\\ \\mathrm{N}";
        assert!(super::gives_reaction(f, "floor"));
        assert!(!super::gives_reaction(f, "incline"));
        assert!(super::gives_reaction(
            "\\mathbf{M}^{O} \\cdot \\hat{\\mathbf{n}}_{z} = 1",
            "O"
        ));
    }
}
