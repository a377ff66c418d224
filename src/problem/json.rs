//! Reading JSON by hand, with paths, so that every error can be reported at once.
//!
//! serde's derive stops at the first error and forgets which key was repeated; here the
//! text is read into a [`Value`] by a visitor that notes duplicate keys, and the value is
//! then walked with helpers that record an error and carry on.

use super::error::ProblemError;
use serde::de::{self, DeserializeSeed, MapAccess, SeqAccess, Visitor};
use serde_json::{Map, Value};
use std::cell::RefCell;
use std::collections::HashMap;
use std::fmt;

/// The errors found so far, in the order found.
#[derive(Debug, Default)]
pub struct Diagnostics {
    /// Every error so far.
    pub errors: Vec<ProblemError>,
}

impl Diagnostics {
    /// Records an error without a hint.
    pub fn error(&mut self, path: &str, message: impl Into<String>) {
        self.push(path, None, message, None::<String>);
    }

    /// Records an error with a hint.
    pub fn hint(&mut self, path: &str, message: impl Into<String>, hint: impl Into<String>) {
        self.push(path, None, message, Some(hint));
    }

    /// Records an error with everything.
    pub fn push(
        &mut self,
        path: &str,
        column: Option<usize>,
        message: impl Into<String>,
        hint: Option<impl Into<String>>,
    ) {
        self.errors.push(ProblemError {
            path: path.to_string(),
            column,
            message: message.into(),
            hint: hint.map(Into::into),
        });
    }

    /// Whether no error was recorded.
    pub fn is_empty(&self) -> bool {
        self.errors.is_empty()
    }
}

/// `path.key`, or `path["key"]` when the key is not a plain name.
pub fn key_path(path: &str, key: &str) -> String {
    let plain = key.chars().next().is_some_and(|c| c.is_ascii_alphabetic())
        && key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    match (plain, path.is_empty()) {
        (true, true) => key.to_string(),
        (true, false) => format!("{path}.{key}"),
        (false, _) => {
            let quoted = serde_json::to_string(key).unwrap_or_else(|_| format!("\"{key}\""));
            format!("{path}[{quoted}]")
        }
    }
}

/// `path[index]`.
pub fn index_path(path: &str, index: usize) -> String {
    format!("{path}[{index}]")
}

/// What kind of JSON value this is, for messages.
pub fn kind(value: &Value) -> &'static str {
    match value {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// The value as an object, or an error.
pub fn object<'a>(
    value: &'a Value,
    path: &str,
    diag: &mut Diagnostics,
) -> Option<&'a Map<String, Value>> {
    match value {
        Value::Object(map) => Some(map),
        other => {
            diag.error(path, format!("expected an object, found {}", kind(other)));
            None
        }
    }
}

/// The value as an array, or an error.
pub fn array<'a>(value: &'a Value, path: &str, diag: &mut Diagnostics) -> Option<&'a [Value]> {
    match value {
        Value::Array(items) => Some(items),
        other => {
            diag.error(path, format!("expected an array, found {}", kind(other)));
            None
        }
    }
}

/// The value as a string, or an error.
pub fn string<'a>(value: &'a Value, path: &str, diag: &mut Diagnostics) -> Option<&'a str> {
    match value {
        Value::String(s) => Some(s),
        other => {
            diag.error(path, format!("expected a string, found {}", kind(other)));
            None
        }
    }
}

/// The value as a finite number, or an error.
pub fn number(value: &Value, path: &str, diag: &mut Diagnostics) -> Option<f64> {
    match value {
        Value::Number(n) => match n.as_f64().filter(|x| x.is_finite()) {
            Some(x) => Some(x),
            None => {
                diag.error(path, format!("`{n}` is not a finite number"));
                None
            }
        },
        Value::String(s) if s.trim().parse::<f64>().is_ok() => {
            diag.hint(
                path,
                format!("expected a number, found the string \"{s}\""),
                "remove the quotes",
            );
            None
        }
        other => {
            diag.error(path, format!("expected a number, found {}", kind(other)));
            None
        }
    }
}

/// Records an error for every key of `map` not in `allowed`, with a suggestion.
pub fn check_keys(map: &Map<String, Value>, path: &str, allowed: &[&str], diag: &mut Diagnostics) {
    for key in map.keys() {
        if allowed.contains(&key.as_str()) {
            continue;
        }
        let hint = match crate::symbolic::closest(key, allowed.iter().copied()) {
            Some(close) => format!("did you mean `{close}`?"),
            None => format!("the keys here are {}", list(allowed)),
        };
        diag.hint(&key_path(path, key), format!("unknown key `{key}`"), hint);
    }
}

/// The value of a required key, or an error naming it.
pub fn required<'a>(
    map: &'a Map<String, Value>,
    key: &str,
    path: &str,
    diag: &mut Diagnostics,
) -> Option<&'a Value> {
    let value = map.get(key);
    if value.is_none() {
        diag.error(&key_path(path, key), format!("`{key}` is required"));
    }
    value
}

/// An optional string key.
pub fn optional_string(
    map: &Map<String, Value>,
    key: &str,
    path: &str,
    diag: &mut Diagnostics,
) -> Option<String> {
    map.get(key)
        .and_then(|v| string(v, &key_path(path, key), diag))
        .map(str::to_string)
}

/// `a`, `b`, `c` as `` `a`, `b`, `c` ``.
pub fn list(items: &[&str]) -> String {
    items
        .iter()
        .map(|k| format!("`{k}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// Reads JSON text into a value, noting every repeated key of an object.
///
/// # Errors
/// A message with the line and column when the text is not JSON.
pub fn parse(text: &str, diag: &mut Diagnostics) -> Result<Value, String> {
    if text.trim().is_empty() {
        return Err("the file is empty".to_string());
    }
    let duplicates = RefCell::new(Vec::new());
    let mut deserializer = serde_json::Deserializer::from_str(text);
    let value = ValueSeed {
        path: String::new(),
        duplicates: &duplicates,
    }
    .deserialize(&mut deserializer)
    .and_then(|value| deserializer.end().map(|()| value))
    .map_err(|e| describe_syntax_error(&e))?;
    for (path, key) in duplicates.into_inner() {
        diag.hint(
            &path,
            format!("the key `{key}` appears more than once"),
            "keep one; JSON readers keep only the last",
        );
    }
    Ok(value)
}

fn describe_syntax_error(e: &serde_json::Error) -> String {
    // serde_json appends " at line L column C"; say it once, in our words.
    let text = e.to_string();
    let message = text.split(" at line ").next().unwrap_or(&text).to_string();
    if message == "recursion limit exceeded" {
        // serde_json's guard against a stack overflow; say what it means for the file.
        return format!(
            "the file is nested more than 128 levels deep at line {}, column {}",
            e.line(),
            e.column()
        );
    }
    format!(
        "the file is not valid JSON: {message} at line {}, column {}",
        e.line(),
        e.column()
    )
}

/// Builds a [`Value`] like serde_json does, but records `(path, key)` for repeated keys.
struct ValueSeed<'a> {
    path: String,
    duplicates: &'a RefCell<Vec<(String, String)>>,
}

impl<'de> DeserializeSeed<'de> for ValueSeed<'_> {
    type Value = Value;
    fn deserialize<D: de::Deserializer<'de>>(self, deserializer: D) -> Result<Value, D::Error> {
        deserializer.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for ValueSeed<'_> {
    type Value = Value;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E>(self, v: bool) -> Result<Value, E> {
        Ok(Value::Bool(v))
    }
    fn visit_i64<E>(self, v: i64) -> Result<Value, E> {
        Ok(Value::from(v))
    }
    fn visit_u64<E>(self, v: u64) -> Result<Value, E> {
        Ok(Value::from(v))
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Value, E> {
        serde_json::Number::from_f64(v)
            .map(Value::Number)
            .ok_or_else(|| E::custom("number out of range"))
    }
    fn visit_str<E>(self, v: &str) -> Result<Value, E> {
        Ok(Value::String(v.to_string()))
    }
    fn visit_string<E>(self, v: String) -> Result<Value, E> {
        Ok(Value::String(v))
    }
    fn visit_unit<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_none<E>(self) -> Result<Value, E> {
        Ok(Value::Null)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Value, A::Error> {
        let mut items = Vec::new();
        loop {
            let seed = ValueSeed {
                path: index_path(&self.path, items.len()),
                duplicates: self.duplicates,
            };
            match seq.next_element_seed(seed)? {
                Some(item) => items.push(item),
                None => return Ok(Value::Array(items)),
            }
        }
    }
    fn visit_map<A: MapAccess<'de>>(self, mut access: A) -> Result<Value, A::Error> {
        let mut map = Map::new();
        while let Some(key) = access.next_key::<String>()? {
            let path = key_path(&self.path, &key);
            let value = access.next_value_seed(ValueSeed {
                path: path.clone(),
                duplicates: self.duplicates,
            })?;
            if map.insert(key.clone(), value).is_some() {
                self.duplicates.borrow_mut().push((path, key));
            }
        }
        Ok(Value::Object(map))
    }
}

/// The position of every path in the document, so errors can be listed in file order.
pub struct FileOrder(HashMap<String, usize>);

impl FileOrder {
    /// Numbers every value of `root` in document order.
    pub fn new(root: &Value) -> FileOrder {
        fn walk(value: &Value, path: String, order: &mut HashMap<String, usize>) {
            let next = order.len();
            order.entry(path.clone()).or_insert(next);
            match value {
                Value::Object(map) => map
                    .iter()
                    .for_each(|(k, v)| walk(v, key_path(&path, k), order)),
                Value::Array(items) => items
                    .iter()
                    .enumerate()
                    .for_each(|(i, v)| walk(v, index_path(&path, i), order)),
                _ => {}
            }
        }
        let mut order = HashMap::new();
        walk(root, String::new(), &mut order);
        FileOrder(order)
    }

    /// The position of `path`, or of its nearest ancestor that is in the file.
    pub fn position(&self, path: &str) -> usize {
        let mut path = path;
        loop {
            if let Some(position) = self.0.get(path) {
                return *position;
            }
            // Missing keys and `--set` are not in the file: go up one step.
            match path.rfind(['.', '[']) {
                Some(cut) => path = &path[..cut],
                None if !path.is_empty() => path = "",
                None => return usize::MAX,
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn duplicates(text: &str) -> Vec<String> {
        let mut diag = Diagnostics::default();
        parse(text, &mut diag).unwrap();
        diag.errors.into_iter().map(|e| e.path).collect()
    }

    #[test]
    fn repeated_keys_are_found_at_any_depth() {
        assert_eq!(duplicates(r#"{"a": 1, "a": 2}"#), ["a"]);
        assert_eq!(
            duplicates(r#"{"b": [{"x": 1}, {"x": 1, "x": 2}]}"#),
            ["b[1].x"]
        );
        assert!(duplicates(r#"{"a": 1, "b": {"a": 2}}"#).is_empty());
    }

    #[test]
    fn syntax_errors_say_where() {
        let mut diag = Diagnostics::default();
        assert_eq!(parse("", &mut diag).unwrap_err(), "the file is empty");
        assert_eq!(parse("  \n ", &mut diag).unwrap_err(), "the file is empty");
        let e = parse("{\n  \"a\": 1,\n}", &mut diag).unwrap_err();
        assert!(e.contains("line 3, column 1"), "{e}");
        assert!(parse("{} x", &mut diag).is_err());
        assert!(parse("1e999", &mut diag).is_err());
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_crash() {
        let deep = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
        let e = parse(&deep, &mut Diagnostics::default()).unwrap_err();
        assert!(e.contains("nested more than 128 levels deep"), "{e}");
    }

    #[test]
    fn paths() {
        assert_eq!(key_path("", "title"), "title");
        assert_eq!(key_path("bodies", "A"), "bodies.A");
        assert_eq!(key_path("bodies", "my body"), "bodies[\"my body\"]");
        assert_eq!(index_path("joints", 1), "joints[1]");
    }

    #[test]
    fn file_order_falls_back_to_the_parent() {
        let value: Value = serde_json::from_str(r#"{"b": {"x": 1}, "a": [1, 2]}"#).unwrap();
        let order = FileOrder::new(&value);
        assert!(order.position("b.x") < order.position("a[1]"));
        assert_eq!(order.position("b.missing"), order.position("b"));
        assert!(order.position("a[0].nothing") > order.position("b.x"));
    }
}
