//! The JSON Schema (draft 2020-12) of the problem format, written by hand beside it.
//!
//! A schema cannot say everything `check` does (names unique across kinds, the joints a
//! tree, what an expression may use); it serves editors and other tools.

/// The schema text, as `mbd-tutor schema` prints it.
pub const SCHEMA: &str = include_str!("schema.json");

#[cfg(test)]
mod tests {
    use super::SCHEMA;
    use serde_json::Value;
    use std::collections::BTreeSet;

    /// Every property name in the schema, and every string in an `enum` or `const`.
    fn words(value: &Value, out: &mut BTreeSet<String>) {
        match value {
            Value::Object(map) => {
                for (key, inner) in map {
                    if key == "properties" {
                        out.extend(
                            inner
                                .as_object()
                                .into_iter()
                                .flat_map(|m| m.keys().cloned()),
                        );
                    }
                    if key == "enum" || key == "const" {
                        let items = inner
                            .as_array()
                            .cloned()
                            .unwrap_or_else(|| vec![inner.clone()]);
                        out.extend(items.iter().filter_map(|v| v.as_str().map(str::to_string)));
                    }
                    words(inner, out);
                }
            }
            Value::Array(items) => items.iter().for_each(|v| words(v, out)),
            _ => {}
        }
    }

    #[test]
    fn the_schema_is_json_of_draft_2020_12() {
        let schema: Value = serde_json::from_str(SCHEMA).unwrap();
        assert_eq!(
            schema["$schema"],
            "https://json-schema.org/draft/2020-12/schema"
        );
        assert_eq!(schema["additionalProperties"], false);
    }

    #[test]
    fn every_key_and_type_of_the_format_page_is_in_the_schema() {
        // Copied from the format page's tables, not from the reader.
        let format = "format title statement dimension constants coordinates gravity bodies joints points \
            loads find simulate value unit description initial rate mass center inertia xx yy zz xy yz zx \
            name type parent child axis sequence at child_at on vector reaction_on between stiffness \
            free_length coefficient joint coordinate rest reactions duration output_step tolerance \
            revolute prismatic cylindrical planar universal spherical free weld \
            force torque spring damper joint_spring joint_damper joint_actuator";
        let mut found = BTreeSet::new();
        words(&serde_json::from_str(SCHEMA).unwrap(), &mut found);
        let missing: Vec<&str> = format
            .split_whitespace()
            .filter(|k| !found.contains(*k))
            .collect();
        assert!(missing.is_empty(), "missing from the schema: {missing:?}");
    }
}
