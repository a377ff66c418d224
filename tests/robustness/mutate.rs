//! Applies [`Mutation`]s to a JSON document and writes it out, repeated keys included.

use super::generate::Mutation;
use serde_json::{Map, Value};

/// A key written with this prefix comes out as the key without it, so that one object
/// can hold the same key twice in the written text.
const REPEAT: &str = "\u{1}repeat\u{1}";

#[derive(Clone, Debug)]
enum Step {
    Key(String),
    Index(usize),
}

fn paths(value: &Value, prefix: &mut Vec<Step>, out: &mut Vec<Vec<Step>>) {
    out.push(prefix.clone());
    match value {
        Value::Object(map) => {
            for (k, v) in map {
                prefix.push(Step::Key(k.clone()));
                paths(v, prefix, out);
                prefix.pop();
            }
        }
        Value::Array(items) => {
            for (i, v) in items.iter().enumerate() {
                prefix.push(Step::Index(i));
                paths(v, prefix, out);
                prefix.pop();
            }
        }
        _ => {}
    }
}

fn node<'a>(root: &'a mut Value, path: &[Step]) -> Option<&'a mut Value> {
    let mut v = root;
    for step in path {
        v = match (step, v) {
            (Step::Key(k), Value::Object(map)) => map.get_mut(k)?,
            (Step::Index(i), Value::Array(items)) => items.get_mut(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

fn leaves(value: &Value, out: &mut Vec<Value>) {
    match value {
        Value::Object(map) => map.values().for_each(|v| leaves(v, out)),
        Value::Array(items) => items.iter().for_each(|v| leaves(v, out)),
        Value::String(_) | Value::Number(_) => out.push(value.clone()),
        _ => {}
    }
}

/// Applies `mutation` at the node numbered `at` (modulo the number of nodes).
pub fn apply(root: &mut Value, at: usize, mutation: &Mutation) {
    let mut all = Vec::new();
    paths(root, &mut Vec::new(), &mut all);
    let path = all[at % all.len()].clone();
    let mut borrowed = Vec::new();
    if let Mutation::Borrow(_) = mutation {
        leaves(root, &mut borrowed);
    }
    match mutation {
        Mutation::Delete => match path.split_last() {
            None => *root = Value::Object(Map::new()),
            Some((last, parent)) => match (last, node(root, parent)) {
                (Step::Key(k), Some(Value::Object(map))) => {
                    map.shift_remove(k);
                }
                (Step::Index(i), Some(Value::Array(items))) => {
                    items.remove(*i);
                }
                _ => {}
            },
        },
        Mutation::DuplicateKey(value) => {
            if let Some(Value::Object(map)) = nearest_object(root, &path) {
                if let Some(key) = map.keys().nth(at % map.len().max(1)).cloned() {
                    map.insert(format!("{REPEAT}{key}"), value.clone());
                }
            }
        }
        Mutation::RenameKey(new) => {
            if let Some(Value::Object(map)) = nearest_object(root, &path) {
                let index = at % map.len().max(1);
                let renamed: Map<String, Value> = std::mem::take(map)
                    .into_iter()
                    .enumerate()
                    .map(|(i, (k, v))| if i == index { (new.clone(), v) } else { (k, v) })
                    .collect();
                *map = renamed;
            }
        }
        Mutation::Replace(value) => {
            if let Some(v) = node(root, &path) {
                *v = value.clone();
            }
        }
        Mutation::Borrow(index) => {
            if let (Some(v), false) = (node(root, &path), borrowed.is_empty()) {
                *v = borrowed[index % borrowed.len()].clone();
            }
        }
        Mutation::Perturb(token) => match node(root, &path) {
            Some(Value::String(s)) => {
                let cut = s
                    .char_indices()
                    .map(|(i, _)| i)
                    .chain([s.len()])
                    .nth(at % (s.chars().count() + 1))
                    .unwrap_or(s.len());
                s.insert_str(cut, token);
            }
            Some(v @ Value::Number(_)) => {
                let x = v.as_f64().unwrap_or(0.0);
                let extreme = match token.len() % 4 {
                    0 => x * 1e300,
                    1 => -x,
                    2 => x * 1e-300,
                    _ => x + 1e16,
                };
                *v = serde_json::Number::from_f64(extreme).map_or(Value::Null, Value::Number);
            }
            _ => {}
        },
        Mutation::Nest(depth) => {
            if let Some(v) = node(root, &path) {
                let mut wrapped = std::mem::take(v);
                for _ in 0..*depth {
                    wrapped = Value::Array(vec![wrapped]);
                }
                *v = wrapped;
            }
        }
    }
}

/// The node at `path` if it is an object, else its nearest ancestor that is.
fn nearest_object<'a>(root: &'a mut Value, path: &[Step]) -> Option<&'a mut Value> {
    let depth = (0..=path.len())
        .rev()
        .find(|&n| matches!(node_ref(root, &path[..n]), Some(Value::Object(m)) if !m.is_empty()))?;
    node(root, &path[..depth])
}

fn node_ref<'a>(root: &'a Value, path: &[Step]) -> Option<&'a Value> {
    let mut v = root;
    for step in path {
        v = match (step, v) {
            (Step::Key(k), Value::Object(map)) => map.get(k)?,
            (Step::Index(i), Value::Array(items)) => items.get(*i)?,
            _ => return None,
        };
    }
    Some(v)
}

/// The JSON text of `value`; keys marked by [`apply`] as repeated are written twice.
pub fn write(value: &Value) -> String {
    let mut out = String::new();
    write_into(value, &mut out);
    out
}

fn write_into(value: &Value, out: &mut String) {
    let quoted = |s: &str| serde_json::to_string(s).unwrap_or_else(|_| "\"\"".into());
    match value {
        Value::Object(map) => {
            out.push('{');
            for (i, (k, v)) in map.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                out.push_str(&quoted(k.strip_prefix(REPEAT).unwrap_or(k)));
                out.push(':');
                write_into(v, out);
            }
            out.push('}');
        }
        Value::Array(items) => {
            out.push('[');
            for (i, v) in items.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                write_into(v, out);
            }
            out.push(']');
        }
        Value::String(s) => out.push_str(&quoted(s)),
        other => out.push_str(&other.to_string()),
    }
}
