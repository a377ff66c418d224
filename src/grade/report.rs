//! The grade of a submission: one item per thing asked, each with its verdict, score and
//! diagnosis, as JSON or as text.

use serde_json::{json, Value};
use std::fmt::Write;

/// How an item was judged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Equal to the worked solution's.
    Right,
    /// Different; the diagnosis says how.
    Wrong,
    /// Asked for and not given.
    Missing,
    /// Not readable: the diagnosis gives the parser's message and column.
    Invalid,
}

impl Verdict {
    /// The word of the JSON output.
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Right => "right",
            Verdict::Wrong => "wrong",
            Verdict::Missing => "missing",
            Verdict::Invalid => "invalid",
        }
    }
}

/// One graded item.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    /// Where it is in the submission: `equations[0]`, `answers.1`, `kinematics.B*.velocity`.
    pub item: String,
    /// The verdict.
    pub verdict: Verdict,
    /// 1 when right, 0 otherwise.
    pub score: f64,
    /// What is wrong, in the problem's notation (empty when right).
    pub diagnosis: String,
}

impl Item {
    fn new(item: String, verdict: Verdict, diagnosis: String) -> Item {
        let score = if verdict == Verdict::Right { 1.0 } else { 0.0 };
        Item {
            item,
            verdict,
            score,
            diagnosis,
        }
    }

    /// A right item.
    pub fn right(item: String, diagnosis: &str) -> Item {
        Item::new(item, Verdict::Right, diagnosis.to_string())
    }

    /// A wrong item and why.
    pub fn wrong(item: String, diagnosis: String) -> Item {
        Item::new(item, Verdict::Wrong, diagnosis)
    }

    /// An item not given.
    pub fn missing(item: String, diagnosis: String) -> Item {
        Item::new(item, Verdict::Missing, diagnosis)
    }

    /// An item that cannot be read.
    pub fn invalid(item: String, diagnosis: String) -> Item {
        Item::new(item, Verdict::Invalid, diagnosis)
    }

    /// The same item under another name.
    pub fn named(mut self, item: String) -> Item {
        self.item = item;
        self
    }
}

/// A submission graded.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// The student, as the submission names them.
    pub student: Option<String>,
    /// Every item, in the order of the submission's sections.
    pub items: Vec<Item>,
}

impl Report {
    /// The sum of the items' scores.
    pub fn score(&self) -> f64 {
        self.items.iter().map(|i| i.score).sum()
    }

    /// The number of items.
    pub fn out_of(&self) -> usize {
        self.items.len()
    }

    /// `{ "student", "items": [ { "item", "verdict", "score", "diagnosis" } ], "score", "out_of" }`.
    pub fn json(&self) -> Value {
        let items: Vec<Value> = self
            .items
            .iter()
            .map(|i| {
                json!({
                    "item": i.item,
                    "verdict": i.verdict.name(),
                    "score": i.score,
                    "diagnosis": i.diagnosis,
                })
            })
            .collect();
        json!({
            "student": self.student,
            "items": items,
            "score": self.score(),
            "out_of": self.out_of(),
        })
    }

    /// One line per item, then the total.
    pub fn text(&self) -> String {
        let mut out = String::new();
        let who = self.student.as_deref().unwrap_or("(no name)");
        let _ = writeln!(out, "{who}: {} of {}", self.score(), self.out_of());
        for item in &self.items {
            let _ = write!(out, "  {:<8} {}", item.verdict.name(), item.item);
            if !item.diagnosis.is_empty() {
                let _ = write!(out, ": {}", item.diagnosis);
            }
            out.push('\n');
        }
        out
    }
}
