//! The letters a handout prints in math for a problem's bodies and points named by words
//! (chosen by `solution::shown_names`): `\mathrm{top}` becomes `B` in every string of the
//! context, math and pictures alike, before each format prepares it.

use serde_json::Value;

/// `value` with each `(word, letter)` of `names` replaced in its strings: the word as math
/// sets it, `\mathrm{top}`, and the word as a picture's label (`>tip<` in SVG).
pub fn rename(value: &mut Value, names: &[(String, String)]) {
    if names.is_empty() {
        return;
    }
    match value {
        Value::String(text) => {
            if let Some(renamed) = renamed(text, names) {
                *text = renamed;
            }
        }
        Value::Array(items) => items.iter_mut().for_each(|v| rename(v, names)),
        Value::Object(map) => map.values_mut().for_each(|v| rename(v, names)),
        _ => {}
    }
}

/// `text` renamed, or `None` when it holds none of the words.
fn renamed(text: &str, names: &[(String, String)]) -> Option<String> {
    let mut out: Option<String> = None;
    for (word, letter) in names {
        let current = out.as_deref().unwrap_or(text);
        let bare = word
            .strip_prefix("\\mathrm{")
            .and_then(|w| w.strip_suffix('}'))
            .unwrap_or(word);
        let label = format!(">{bare}<");
        if current.contains(word.as_str()) || current.contains(&label) {
            let next = current
                .replace(word.as_str(), letter)
                .replace(&label, &format!(">{letter}<"));
            out = Some(next);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::rename;
    use serde_json::json;

    #[test]
    fn a_word_in_math_and_in_a_picture_becomes_its_letter() {
        let names = [("\\mathrm{top}".to_string(), "B".to_string())];
        let mut value = json!({"a": ["\\hat{\\mathbf{x}}_{\\mathrm{top}}, \\mathrm{top}^*"], "b": "<text>top</text> the top"});
        rename(&mut value, &names);
        assert_eq!(value["a"][0], "\\hat{\\mathbf{x}}_{B}, B^*");
        assert_eq!(value["b"], "<text>B</text> the top");
    }
}
