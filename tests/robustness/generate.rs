//! Strategies for hostile input: expression text, JSON documents and mutations of the
//! bundled problems.

use proptest::prelude::*;
use serde_json::{Map, Number, Value};

/// Pieces of expression text: the grammar's tokens, near misses and junk.
const TOKENS: &[&str] = &[
    "q1",
    "q2",
    "q1'",
    "q2''",
    "q1'''",
    "m",
    "L",
    "g",
    "t",
    "pi",
    "x",
    "unknown",
    "N",
    "N.x",
    "N.y",
    "N.z",
    "A.x",
    "A.z",
    "A.w",
    "B.x",
    "N.",
    ".x",
    "sin",
    "cos",
    "tan",
    "asin",
    "acos",
    "atan",
    "atan2",
    "sqrt",
    "exp",
    "ln",
    "abs",
    "sign",
    "min",
    "max",
    "sinh",
    "log",
    "0",
    "1",
    "2",
    "0.5",
    ".5",
    "5.",
    "1e3",
    "1e",
    "1e-",
    "1e308",
    "1e309",
    "1e-400",
    "2^1e308",
    "99999999",
    "9223372036854775807",
    "9223372036854775808",
    "0.000000000000000000001",
    "007",
    "1.2.3",
    "+",
    "-",
    "*",
    "/",
    "^",
    "(",
    ")",
    ",",
    "'",
    " ",
    "\t",
    "\n",
    "^-",
    "**",
    "//",
    "()",
    "(,)",
    "sin()",
    "min(,)",
    "--",
    "ǫ",
    "∞",
    "\u{0}",
    "\u{202e}",
    "é",
    "$",
    "\\",
    "{",
    "}",
    "[",
    "]",
    "\"",
    "#",
    "%",
    "&",
    "_",
    "__init__",
    "NaN",
    "inf",
    "Infinity",
];

/// Names that the small resolver of the parser suites knows, with their kinds.
pub const CONSTANTS: &[&str] = &["m", "L", "g", "pi"];
/// Coordinates known to the parser suites.
pub const COORDINATES: &[&str] = &["q1", "q2"];
/// Frames known to the parser suites.
pub const FRAMES: &[&str] = &["N", "A"];

/// Text made of 0 to 40 tokens and random characters.
pub fn token_soup() -> impl Strategy<Value = String> {
    let piece = prop_oneof![
        6 => proptest::sample::select(TOKENS).prop_map(str::to_string),
        1 => any::<char>().prop_map(|c| c.to_string()),
        1 => any::<f64>().prop_map(|x| format!("{x}")),
        1 => any::<i64>().prop_map(|n| n.to_string()),
        1 => any::<i32>().prop_map(|n| format!("1e{n}")),
    ];
    proptest::collection::vec(piece, 0..40).prop_map(|pieces| pieces.concat())
}

/// A well-formed expression over the known names, so that cases get past the tokenizer
/// into building, expansion and exact arithmetic.
pub fn well_formed() -> impl Strategy<Value = String> {
    let atom = prop_oneof![
        proptest::sample::select(
            &["q1", "q2", "q1'", "q2'", "m", "L", "g", "t", "pi", "N.x", "A.y"][..]
        )
        .prop_map(str::to_string),
        (0i64..20).prop_map(|n| n.to_string()),
        proptest::sample::select(
            &[
                "0",
                "0.25",
                "1e308",
                "1e-308",
                "9223372036854775807",
                "99999999",
                "1e20"
            ][..]
        )
        .prop_map(str::to_string),
    ];
    atom.prop_recursive(8, 64, 4, |inner| {
        let op = proptest::sample::select(&["+", "-", "*", "/", "^"][..]);
        let function = proptest::sample::select(
            &[
                "sin", "cos", "tan", "asin", "acos", "atan", "sqrt", "exp", "ln", "abs", "sign",
            ][..],
        );
        let binary = proptest::sample::select(&["atan2", "min", "max"][..]);
        prop_oneof![
            (inner.clone(), op.clone(), inner.clone())
                .prop_map(|(a, o, b)| format!("({a}){o}({b})")),
            (inner.clone(), op, inner.clone()).prop_map(|(a, o, b)| format!("{a}{o}{b}")),
            (function, inner.clone()).prop_map(|(f, a)| format!("{f}({a})")),
            (binary, inner.clone(), inner.clone()).prop_map(|(f, a, b)| format!("{f}({a}, {b})")),
            inner.clone().prop_map(|a| format!("-({a})")),
            (
                inner,
                proptest::sample::select(
                    &["2", "3", "8", "9", "-1", "-9", "0.5", "99999999", "1e308", "(-1)"][..]
                )
            )
                .prop_map(|(a, k)| format!("({a})^{k}")),
        ]
    })
}

/// Keys of the problem format, at every level, and a few near misses.
const KEYS: &[&str] = &[
    "format",
    "title",
    "statement",
    "dimension",
    "constants",
    "coordinates",
    "gravity",
    "bodies",
    "joints",
    "points",
    "loads",
    "find",
    "simulate",
    "mass",
    "center",
    "inertia",
    "xx",
    "yy",
    "zz",
    "xy",
    "yz",
    "zx",
    "description",
    "name",
    "type",
    "parent",
    "child",
    "axis",
    "at",
    "child_at",
    "sequence",
    "on",
    "vector",
    "reaction_on",
    "between",
    "stiffness",
    "free_length",
    "coefficient",
    "joint",
    "coordinate",
    "rest",
    "value",
    "unit",
    "initial",
    "rate",
    "reactions",
    "duration",
    "output_step",
    "tolerance",
    "A",
    "B",
    "N",
    "q1",
    "q2",
    "O",
    "P",
    "m",
    "L",
    "g",
    "Mass",
    "bodys",
    "",
];

/// String values of the problem format and hostile strings.
const STRINGS: &[&str] = &[
    "revolute",
    "prismatic",
    "cylindrical",
    "planar",
    "universal",
    "spherical",
    "free",
    "weld",
    "force",
    "torque",
    "spring",
    "damper",
    "joint_spring",
    "joint_damper",
    "joint_actuator",
    "N",
    "A",
    "B",
    "O",
    "P",
    "q1",
    "q2",
    "N.x",
    "N.z",
    "A.y",
    "m",
    "L",
    "-g*N.y",
    "m*L^2/12",
    "L*A.x",
    "-L/2*A.y",
    "xyz",
    "zxz",
    "xx",
    "m/0",
    "1/(L-L)",
    "2^1e308",
    "q1^99999999",
    "sin(q1)*N.x",
    "A.o",
    "N.o",
    "",
    " ",
    "NaN",
    "Infinity",
    "-inf",
    "1e999",
    "<script>",
    "\\input{/etc/passwd}",
    "{{ x }}",
    "{% raw %}",
    "\u{0}",
    "\u{feff}",
    "é∞",
];

/// A number, often at the edges of what JSON and f64 hold.
pub fn json_number() -> impl Strategy<Value = Value> {
    prop_oneof![
        (-3i64..12).prop_map(Value::from),
        any::<i64>().prop_map(Value::from),
        any::<u64>().prop_map(Value::from),
        any::<f64>().prop_map(|x| Number::from_f64(x).map_or(Value::Null, Value::Number)),
        proptest::sample::select(
            &[
                0.0,
                -0.0,
                1e308,
                -1e308,
                f64::MAX,
                f64::MIN_POSITIVE,
                5e-324,
                std::f64::consts::FRAC_PI_2
            ][..]
        )
        .prop_map(|x| Number::from_f64(x).map_or(Value::Null, Value::Number)),
    ]
}

/// A string value, mostly from the format's vocabulary.
pub fn json_string() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => proptest::sample::select(STRINGS).prop_map(str::to_string),
        2 => well_formed(),
        1 => token_soup(),
        1 => any::<String>(),
    ]
}

/// An arbitrary JSON document whose keys and strings mostly come from the format.
pub fn json_value() -> impl Strategy<Value = Value> {
    let leaf = prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::Bool),
        json_number(),
        json_string().prop_map(Value::String),
    ];
    leaf.prop_recursive(6, 96, 8, |inner| {
        let key = prop_oneof![
            6 => proptest::sample::select(KEYS).prop_map(str::to_string),
            1 => any::<String>(),
        ];
        prop_oneof![
            proptest::collection::vec(inner.clone(), 0..6).prop_map(Value::Array),
            proptest::collection::vec((key, inner), 0..8)
                .prop_map(|entries| Value::Object(entries.into_iter().collect::<Map<_, _>>())),
        ]
    })
}

/// A document shaped like a problem: an object with the top-level keys, each holding
/// an arbitrary value.
pub fn problem_shaped() -> impl Strategy<Value = Value> {
    proptest::collection::vec((proptest::sample::select(&KEYS[..13]), json_value()), 0..13)
        .prop_map(|entries| {
            Value::Object(
                entries
                    .into_iter()
                    .map(|(k, v)| (k.to_string(), v))
                    .collect(),
            )
        })
}

/// One change to a JSON document, applied at the node chosen by `at` (an index into the
/// document's nodes, modulo their count).
#[derive(Clone, Debug)]
pub enum Mutation {
    /// Remove the node from its parent.
    Delete,
    /// Write one key of the object twice (the second time with this value).
    DuplicateKey(Value),
    /// Rename one key of the object.
    RenameKey(String),
    /// Replace the node by another value, usually of another type.
    Replace(Value),
    /// Replace the node by a string or number taken from elsewhere in the same document
    /// (a body's name where a joint's is expected, and so on).
    Borrow(usize),
    /// Replace a string by one with a token inserted, or a number by an extreme one.
    Perturb(String),
    /// Wrap the node in this many arrays.
    Nest(usize),
}

/// A mutation with the node it applies to.
pub fn mutation() -> impl Strategy<Value = (usize, Mutation)> {
    let kind = prop_oneof![
        2 => Just(Mutation::Delete),
        1 => json_value().prop_map(Mutation::DuplicateKey),
        1 => prop_oneof![
            proptest::sample::select(KEYS).prop_map(str::to_string),
            any::<String>(),
        ]
        .prop_map(Mutation::RenameKey),
        2 => json_value().prop_map(Mutation::Replace),
        3 => any::<usize>().prop_map(Mutation::Borrow),
        3 => prop_oneof![
            proptest::sample::select(TOKENS).prop_map(str::to_string),
            proptest::sample::select(STRINGS).prop_map(str::to_string),
        ]
        .prop_map(Mutation::Perturb),
        1 => prop_oneof![1usize..10, 100usize..140].prop_map(Mutation::Nest),
    ];
    (any::<usize>(), kind)
}
