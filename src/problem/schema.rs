//! The JSON Schema (draft 2020-12) of the problem format, written by hand beside it.

/// The schema text, as `mbd-tutor schema` prints it.
pub const SCHEMA: &str = include_str!("schema.json");
