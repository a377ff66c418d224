//! A constant's `vary` and `step`: the range and grid a randomized variant draws its value
//! from (`"m": { "value": 2, "vary": [1.5, 3], "step": 0.1 }`).
//!
//! Choices, documented in `docs/answer-and-variants.md`:
//! - the grid of an explicit `step` starts at the low end: `low + k step`, k = 0, 1, …;
//! - without `step` the values have 3 significant digits: the multiples of
//!   10^(e - 2), e the decimal exponent of the end larger in size, that lie in the range;
//! - a range must hold its constant's `value` and at least two values of its grid.

use super::json::{self, key_path, number, Diagnostics};
use serde_json::{Map, Value};

/// The range and grid of a constant that varies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Vary {
    /// The least value drawn.
    pub low: f64,
    /// The greatest value drawn.
    pub high: f64,
    /// As written; `None` draws 3 significant digits (see [`Vary::grid`]).
    pub step: Option<f64>,
}

/// The values a draw picks from, uniformly: `origin + k step` for k in `0..=count - 1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// The first value.
    pub origin: f64,
    /// The spacing of the values.
    pub step: f64,
    /// How many values.
    pub count: u64,
    /// Decimals that print every value of the grid exactly as meant (0.1 + 0.2 is 0.3).
    pub decimals: usize,
}

/// Floating room for a grid end: a range [1.5, 3] with step 0.1 holds 3.
const SLACK: f64 = 1e-9;

impl Vary {
    /// The grid of values a draw picks from.
    pub fn grid(&self) -> Grid {
        let (origin, step, last) = match self.step {
            Some(step) => (
                self.low,
                step,
                ((self.high - self.low) / step + SLACK).floor(),
            ),
            None => {
                let largest = self.low.abs().max(self.high.abs());
                let exponent = if largest > 0.0 {
                    largest.log10().floor()
                } else {
                    0.0
                };
                let step = 10f64.powf(exponent - 2.0);
                let first = (self.low / step - SLACK).ceil();
                let last = (self.high / step + SLACK).floor();
                (first * step, step, last - first)
            }
        };
        Grid {
            origin,
            step,
            // Saturating: a range of 1e300 steps is refused by its size (MAX_GRID), not a panic.
            count: if last >= 0.0 {
                (last as u64).saturating_add(1)
            } else {
                0
            },
            decimals: decimals(step).max(decimals(origin)),
        }
    }
}

impl Grid {
    /// The value `k` steps from the origin, rounded to the grid's decimals.
    pub fn value(&self, k: u64) -> f64 {
        let x = self.origin + k as f64 * self.step;
        format!("{x:.*}", self.decimals).parse().unwrap_or(x)
    }
}

/// The fewest decimals (up to 12) that write `x` to within a part in 10⁹ of itself.
fn decimals(x: f64) -> usize {
    (0..=12)
        .find(|&d| {
            let scaled = x * 10f64.powi(d as i32);
            (scaled - scaled.round()).abs() <= 1e-9 * scaled.abs().max(1.0)
        })
        .unwrap_or(12)
}

/// Reads `vary` and `step` of the constant at `path` whose value is `value`; every error
/// names its path and says how to mend it.
pub(super) fn read(
    fields: &Map<String, Value>,
    path: &str,
    value: Option<f64>,
    diag: &mut Diagnostics,
) -> Option<Vary> {
    let step_path = key_path(path, "step");
    let step = fields.get("step").and_then(|v| number(v, &step_path, diag));
    let Some(range) = fields.get("vary") else {
        if fields.contains_key("step") {
            diag.hint(
                &step_path,
                "`step` without `vary`: there is no range to step through",
                "add the range the variants draw from, e.g. \"vary\": [1.5, 3]",
            );
        }
        return None;
    };
    let vary_path = key_path(path, "vary");
    let ends = match range.as_array().map(Vec::as_slice) {
        Some([low, high]) => (
            number(low, &json::index_path(&vary_path, 0), diag),
            number(high, &json::index_path(&vary_path, 1), diag),
        ),
        _ => {
            diag.hint(
                &vary_path,
                format!("expected [low, high], found {}", describe(range)),
                "write the range as two numbers, e.g. \"vary\": [1.5, 3]",
            );
            return None;
        }
    };
    let (Some(low), Some(high)) = ends else {
        return None;
    };
    let mut valid = true;
    if low >= high {
        let message = if low == high {
            format!("the range [{low}, {high}] holds one value only")
        } else {
            format!("the range's low end {low} is above its high end {high}")
        };
        diag.hint(
            &vary_path,
            message,
            format!(
                "write the low end first and make the ends differ, e.g. [{}, {}]",
                low.min(high),
                low.max(high).max(low.min(high) + 1.0)
            ),
        );
        return None;
    }
    if let Some(s) = step {
        if s <= 0.0 {
            diag.hint(
                &step_path,
                format!("the step must be positive, not {s}"),
                "the spacing of the values drawn, e.g. \"step\": 0.1",
            );
            valid = false;
        } else if s > high - low + SLACK * s {
            diag.hint(
                &step_path,
                format!("the step {s} is wider than the range [{low}, {high}]: every variant would draw {low}"),
                format!("a step of at most {}, e.g. {}", high - low, (high - low) / 10.0),
            );
            valid = false;
        }
    } else if fields.contains_key("step") {
        valid = false;
    }
    if let Some(v) = value.filter(|v| *v < low || *v > high) {
        diag.hint(
            &key_path(path, "value"),
            format!("the value {v} lies outside its range [{low}, {high}]"),
            "the value is the problem as written, one of its variants: widen the range or change the value",
        );
        valid = false;
    }
    let vary = Vary { low, high, step };
    if valid && vary.grid().count < 2 {
        diag.hint(
            &vary_path,
            format!(
                "the range [{low}, {high}] holds fewer than two values of 3 significant digits"
            ),
            "widen the range, or give a finer `step`",
        );
        valid = false;
    }
    if valid && vary.grid().count > MAX_GRID {
        diag.hint(
            &step_path,
            format!(
                "the step {} makes more than {MAX_GRID} values in [{low}, {high}]",
                vary.grid().step
            ),
            "a coarser step: a grader reads the values a student was given",
        );
        valid = false;
    }
    valid.then_some(vary)
}

/// The most values a range's grid may hold: a draw's index must be exact in f64.
const MAX_GRID: u64 = 1 << 40;

fn describe(value: &Value) -> String {
    match value.as_array() {
        Some(items) => format!("an array of {} items", items.len()),
        None => json::kind(value).to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(low: f64, high: f64, step: Option<f64>) -> Grid {
        Vary { low, high, step }.grid()
    }

    #[test]
    fn explicit_step_starts_at_the_low_end() {
        let g = grid(1.5, 3.0, Some(0.1));
        assert_eq!((g.count, g.decimals), (16, 1));
        assert_eq!(g.value(7), 2.2);
        assert_eq!(g.value(15), 3.0);
    }

    #[test]
    fn default_step_is_three_significant_digits() {
        let g = grid(1.5, 3.0, None);
        assert_eq!((g.step, g.count), (0.01, 151));
        assert_eq!(g.value(37), 1.87);
        let g = grid(0.0312, 0.05, None);
        assert_eq!(g.value(0), 0.0312);
        assert_eq!(g.value(g.count - 1), 0.05);
        let huge = Vary {
            low: 0.0,
            high: 1e300,
            step: Some(1e-300),
        }
        .grid();
        assert_eq!(huge.count, u64::MAX);
    }
}
