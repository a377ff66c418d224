//! A "where" list grouped by what its entries are: the nine direction cosines, or the
//! partial velocities of one mass centre, are one entry written one after another, as a
//! textbook lists them, instead of one line each with the same note repeated.

use super::context::{Named, WhereEntry};

/// `list` grouped by `kind`, each group where its first member stood; a group of one
/// keeps its own note.
pub fn grouped(list: Vec<Named>) -> Vec<WhereEntry> {
    let list = each_value_once(list);
    let mut groups: Vec<(String, Vec<Named>)> = Vec::new();
    for named in list {
        let key = kind(&named.note);
        match groups.iter_mut().find(|(k, _)| *k == key) {
            Some((_, members)) => members.push(named),
            None => groups.push((key, vec![named])),
        }
    }
    groups
        .into_iter()
        .map(|(key, mut members)| {
            if members.len() == 1 {
                let Named {
                    definition_tex,
                    note,
                } = members.remove(0);
                return WhereEntry {
                    definitions_tex: vec![definition_tex],
                    note,
                    grouped: false,
                };
            }
            WhereEntry {
                definitions_tex: members.into_iter().map(|m| m.definition_tex).collect(),
                note: key,
                grouped: true,
            }
        })
        .collect()
}

/// `list` with a value that two names stand for written out once: the second name is
/// defined as the first (`{}^{B}C^{H}_{31} = {}^{B}C^{H}_{13}`), a direction cosine being
/// the first wherever one has the value (a body's partial velocity along `x` is a
/// direction cosine). A value no longer than its name is left as it is.
fn each_value_once(list: Vec<Named>) -> Vec<Named> {
    let split = |n: &Named| {
        n.definition_tex
            .split_once(" = ")
            .map(|(name, value)| (name.to_string(), value.to_string()))
    };
    let cosine = |n: &Named| n.note.starts_with("the direction cosine ");
    let mut first: Vec<(String, String)> = Vec::new();
    for n in list
        .iter()
        .filter(|n| cosine(n))
        .chain(list.iter().filter(|n| !cosine(n)))
    {
        if let Some((name, value)) = split(n) {
            if value.len() > name.len() && !first.iter().any(|(_, v)| *v == value) {
                first.push((name, value));
            }
        }
    }
    list.into_iter()
        .map(|n| {
            let Some((name, value)) = split(&n) else {
                return n;
            };
            match first.iter().find(|(_, v)| *v == value) {
                Some((earlier, _)) if *earlier != name => Named {
                    definition_tex: format!("{name} = {earlier}").into(),
                    note: n.note,
                },
                _ => n,
            }
        })
        .collect()
}

/// What a definition is, without which component or speed it is for: the note a group of
/// them shares. `partial velocity of B1* for q1', along B1.x` is one of the `partial
/// velocities of B1*`; a note of no known form is its own kind.
fn kind(note: &str) -> String {
    if note.starts_with("the direction cosine ") {
        return "direction cosines".into();
    }
    for (one, many) in [
        (
            "partial angular velocity of ",
            "partial angular velocities of ",
        ),
        ("partial velocity of ", "partial velocities of "),
    ] {
        if let Some(rest) = note.strip_prefix(one) {
            let whose = rest.split(" for ").next().unwrap_or(rest);
            return format!("{many}{whose}");
        }
    }
    // `the x component, in frame N, of the vector from A to B`
    if let Some(rest) = note.strip_prefix("the ") {
        if let Some((_, of)) = rest.split_once(" component, in frame ") {
            if let Some((frame, what)) = of.split_once(", of the ") {
                return format!("components in frame {frame} of the {what}");
            }
        }
    }
    // `acceleration of B1* along B1.x without the q''`, `angular velocity of B along B.x`
    if let Some((what, after)) = note.split_once(" along ") {
        let rest = after.split_once(' ').map_or("", |(_, rest)| rest);
        let rest = if rest.is_empty() {
            String::new()
        } else {
            format!(" {rest}")
        };
        return format!("components of the {what}{rest}");
    }
    note.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_value_two_names_share_is_written_once() {
        let named = |d: &str, note: &str| Named::new(d.to_string(), note);
        let list = each_value_once(vec![
            named(
                "v_{x} = c_{1} c_{2} - s_{1}",
                "partial velocity of B* for x, along B.x",
            ),
            named("C_{13} = s_{1} c_{2}", "the direction cosine A.x · B.z"),
            named(
                "C_{11} = c_{1} c_{2} - s_{1}",
                "the direction cosine A.x · B.x",
            ),
            named("C_{31} = s_{1} c_{2}", "the direction cosine A.z · B.x"),
            named("w_{1} = a", "short"),
            named("w_{2} = a", "short"),
        ]);
        let texts: Vec<&str> = list.iter().map(|n| n.definition_tex.as_str()).collect();
        assert_eq!(
            texts,
            [
                "v_{x} = C_{11}",
                "C_{13} = s_{1} c_{2}",
                "C_{11} = c_{1} c_{2} - s_{1}",
                "C_{31} = C_{13}",
                "w_{1} = a",
                "w_{2} = a"
            ]
        );
    }

    #[test]
    fn a_kind_drops_the_component_and_the_speed() {
        assert_eq!(
            kind("partial velocity of B1* for q1', along B1.x"),
            "partial velocities of B1*"
        );
        assert_eq!(
            kind("partial angular velocity of E for r, along E.x"),
            "partial angular velocities of E"
        );
        assert_eq!(kind("the direction cosine A.x · D.x"), "direction cosines");
        assert_eq!(
            kind("acceleration of B1* along B1.x without the q''"),
            "components of the acceleration of B1* without the q''"
        );
        assert_eq!(
            kind("angular velocity of B along B.z"),
            "components of the angular velocity of B"
        );
        assert_eq!(
            kind("the y component, in frame N, of the unit vector from rim toward F*"),
            "components in frame N of the unit vector from rim toward F*"
        );
        assert_eq!(kind("distance from rim to F*"), "distance from rim to F*");
    }

    #[test]
    fn entries_of_one_kind_are_one_entry_where_the_first_stood() {
        let list = vec![
            Named::new("a = 1", "the direction cosine A.x · B.x"),
            Named::new("l = 2", "distance from A to B"),
            Named::new("b = 3", "the direction cosine A.y · B.x"),
        ];
        let entries = grouped(list);
        assert_eq!(entries.len(), 2);
        assert_eq!(entries[0].definitions_tex, ["a = 1", "b = 3"]);
        assert_eq!(entries[0].note, "direction cosines");
        assert!(entries[0].grouped);
        assert_eq!(entries[1].definitions_tex, ["l = 2"]);
        assert_eq!(entries[1].note, "distance from A to B");
        assert!(!entries[1].grouped);
    }
}
