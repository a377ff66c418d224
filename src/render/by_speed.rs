//! Definitions that differ only in the speed they belong to, listed once: as Kane and
//! Levinson write `ω^{B3}_r = ᴮ³C^{B2} ω^{B2}_r (r = q_1, …, q_6)` rather than six times.

use super::context::Named;
use super::text::Math;

/// `list` with the definitions that read the same but for their speed (`_{q_{1},x}` in a
/// name's index, wherever it stands) merged into one, written with `r` and the speeds it
/// holds for. `speeds` are the speeds as a name's index writes them (`q_{1}`, `\phi`), and
/// `plain` the same as a note writes them (`q1`, `phi`).
pub fn merged(list: Vec<Named>, speeds: &[String], plain: &[String]) -> Vec<Named> {
    let mut groups: Vec<(Named, Vec<usize>)> = Vec::new();
    for named in list {
        let name = named.definition_tex.split(" = ").next().unwrap_or_default();
        let speed = speeds
            .iter()
            .position(|s| name.contains(&format!("_{{{s},")));
        let Some(r) = speed else {
            groups.push((named, Vec::new()));
            continue;
        };
        let key = Named {
            definition_tex: Math::from(
                named
                    .definition_tex
                    .replace(&format!("_{{{},", speeds[r]), "_{r,"),
            ),
            note: named.note.replace(&format!(" {}'", plain[r]), " r"),
        };
        match groups
            .iter_mut()
            .find(|(k, rs)| !rs.is_empty() && *k == key)
        {
            Some((_, rs)) => rs.push(r),
            None => groups.push((key, vec![r])),
        }
    }
    groups
        .into_iter()
        .map(|(key, rs)| match rs.as_slice() {
            // Alone: as it was, its own speed written back.
            [r] => Named {
                definition_tex: Math::from(
                    key.definition_tex
                        .replace("_{r,", &format!("_{{{},", speeds[*r])),
                ),
                note: key.note.replace(" r,", &format!(" {}',", plain[*r])),
            },
            [] => key,
            _ => {
                let list: Vec<&str> = rs.iter().map(|&r| speeds[r].as_str()).collect();
                Named {
                    definition_tex: Math::from(format!(
                        "{} \\quad (r = {})",
                        key.definition_tex,
                        list.join(", ")
                    )),
                    note: key.note,
                }
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_rule_for_several_speeds_is_written_once() {
        let speeds = ["q_{1}", "q_{2}", "q_{3}"].map(String::from);
        let plain = ["q1", "q2", "q3"].map(String::from);
        let list = vec![
            Named::new(
                "w_{q_{1},x} = c w'_{q_{1},x}",
                "partial of B for q1', along x",
            ),
            Named::new("w_{q_{1},y} = s", "partial of B for q1', along y"),
            Named::new(
                "w_{q_{2},x} = c w'_{q_{2},x}",
                "partial of B for q2', along x",
            ),
            Named::new("w_{q_{3},x} = s_{3}", "partial of B for q3', along x"),
            Named::new("a = b", "something else"),
        ];
        let merged = merged(list, &speeds, &plain);
        let texts: Vec<&str> = merged.iter().map(|n| n.definition_tex.as_str()).collect();
        assert_eq!(
            texts,
            [
                "w_{r,x} = c w'_{r,x} \\quad (r = q_{1}, q_{2})",
                "w_{q_{1},y} = s",
                "w_{q_{3},x} = s_{3}",
                "a = b"
            ]
        );
        assert_eq!(merged[0].note, "partial of B for r, along x");
        assert_eq!(merged[1].note, "partial of B for q1', along y");
    }
}
