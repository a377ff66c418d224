//! The abbreviations a handout lists, kept to those it prints: a statics handout leaves out
//! the kinematics and rows that used some, and the concise handout drops repeated rows.

use crate::render::Solution;

/// The abbreviation `s_{1}` of the listed `s_{1} = \sin q_{1}`.
fn name(definition: &str) -> &str {
    definition.split_once(" = ").map_or(definition, |(n, _)| n)
}

/// Leaves out of `solution`'s abbreviations those no other part of it prints; the rule
/// that names the many by their letters goes with the last of its examples.
pub fn keep_printed(solution: &mut Solution) {
    if solution.abbreviations.is_empty() {
        return;
    }
    let listed = std::mem::take(&mut solution.abbreviations);
    let printed = serde_json::to_string(&*solution).unwrap_or_default();
    let in_print = |definition: &str| {
        let quoted = serde_json::to_string(name(definition)).unwrap_or_default();
        printed.contains(quoted.trim_matches('"'))
    };
    solution.abbreviations = listed
        .into_iter()
        .filter(|a| in_print(a.definition_tex.as_str()))
        .collect();
    if solution.abbreviations.is_empty() {
        solution.abbreviations_by_rule.clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::context::Named;
    use crate::render::text::Math;

    fn listed(definition: &str) -> Named {
        Named {
            definition_tex: Math::from(definition.to_string()),
            note: String::new(),
        }
    }

    #[test]
    fn only_the_abbreviations_printed_stay_listed() {
        let mut solution = Solution {
            abbreviations: vec![
                listed("s_{1} = \\sin q_{1}"),
                listed("c_{12} = \\cos\\left(q_{1} + q_{2}\\right)"),
            ],
            abbreviations_by_rule: vec!["s".into(), "c".into()],
            ..Solution::default()
        };
        solution.title = "a pendulum".into();
        solution.solve_notes = vec![crate::render::text::MarkupLine::from(
            "with $s_{1}$ and $c_{1}$".to_string(),
        )];
        keep_printed(&mut solution);
        assert_eq!(solution.abbreviations.len(), 1);
        assert_eq!(
            solution.abbreviations[0].definition_tex.as_str(),
            "s_{1} = \\sin q_{1}"
        );
        assert_eq!(solution.abbreviations_by_rule, ["s", "c"]);
        solution.solve_notes.clear();
        keep_printed(&mut solution);
        assert!(solution.abbreviations.is_empty());
        assert!(solution.abbreviations_by_rule.is_empty());
    }
}
