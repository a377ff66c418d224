//! A randomized variant of a problem: each constant with a `vary` range gets a value drawn
//! on its grid, and the problem's JSON is written again with those values and without
//! `vary` and `step`, otherwise as it was (keys in their order).
//!
//! The draws come from SplitMix64 (Steele, Lea and Flood, "Fast splittable pseudorandom
//! number generators", OOPSLA 2014; the generator of `java.util.SplittableRandom`): a few
//! lines whose output is fixed by the seed alone on every platform and for every version
//! of this program, which a key that must be drawn again identically needs. A crate's
//! generator may change its stream between versions (`rand`'s `StdRng` says so).

use super::validated::Problem;
use super::vary::Grid;
use serde_json::Value;

/// SplitMix64: a 64-bit state advanced by a fixed odd constant, each output a mix of it.
#[derive(Clone, Debug)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// The generator started from `seed`.
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64 { state: seed }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform on `0..n` (n > 0), without the bias of a plain remainder: draws in the
    /// incomplete last block of n are drawn again.
    pub fn below(&mut self, n: u64) -> u64 {
        let n = n.max(1);
        let zone = u64::MAX - (u64::MAX - n + 1) % n;
        loop {
            let x = self.next_u64();
            if x <= zone {
                return x % n;
            }
        }
    }
}

/// The constants that vary, in the order of the problem, with their grids.
pub fn varied(problem: &Problem) -> Vec<(String, Grid)> {
    problem
        .constants
        .iter()
        .filter_map(|c| c.vary.map(|v| (c.name.clone(), v.grid())))
        .collect()
}

/// How many different variants the grids allow (saturating).
pub fn distinct(varied: &[(String, Grid)]) -> u64 {
    varied
        .iter()
        .fold(1u64, |n, (_, grid)| n.saturating_mul(grid.count))
}

/// One value for each varied constant, drawn in their order.
pub fn draw(varied: &[(String, Grid)], random: &mut SplitMix64) -> Vec<(String, f64)> {
    varied
        .iter()
        .map(|(name, grid)| (name.clone(), grid.value(random.below(grid.count))))
        .collect()
}

/// The problem's JSON `raw` with the `values` drawn, `vary` and `step` removed.
pub fn with_values(raw: &Value, values: &[(String, f64)]) -> Value {
    let mut out = raw.clone();
    let Some(constants) = out.get_mut("constants").and_then(Value::as_object_mut) else {
        return out;
    };
    for (name, x) in values {
        let Some(fields) = constants.get_mut(name).and_then(Value::as_object_mut) else {
            continue;
        };
        if let Some(number) = serde_json::Number::from_f64(*x) {
            fields.insert("value".into(), Value::Number(number));
        }
        fields.shift_remove("vary");
        fields.shift_remove("step");
    }
    let originals: Vec<(String, f64, f64)> = values
        .iter()
        .filter_map(|(name, x)| {
            let old = raw.pointer(&format!("/constants/{name}/value"))?.as_f64()?;
            Some((name.clone(), old, *x))
        })
        .collect();
    if let Some(Value::String(text)) = out.get_mut("statement") {
        *text = restated(text, &originals);
    }
    if let Some(questions) = out
        .pointer_mut("/find/questions")
        .and_then(Value::as_array_mut)
    {
        for question in questions {
            if let Some(Value::String(text)) = question.get_mut("text") {
                *text = restated(text, &originals);
            }
        }
    }
    out
}

/// `text` with every `$NAME = VALUE$` that gives a varied constant its original value
/// written with the drawn one, so that a variant's statement ("Given $m = 0.5$ kg") agrees
/// with its constants. NAME as the problem's name (`I3`) or as LaTeX prints it (`I_3`,
/// `I_{3}`); anything else in the text is left as written.
fn restated(text: &str, values: &[(String, f64, f64)]) -> String {
    let mut text = text.to_string();
    for (name, old, new) in values {
        let printed = crate::symbolic::latex_name(name);
        let plain = printed.replace(['{', '}'], "");
        for symbol in [name.as_str(), printed.as_str(), plain.as_str()] {
            text = restate_one(&text, symbol, *old, *new);
        }
    }
    text
}

fn restate_one(text: &str, symbol: &str, old: f64, new: f64) -> String {
    let opening = format!("${symbol} = ");
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(&opening) {
        let after = &rest[at + opening.len()..];
        let number_length = after
            .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
            .unwrap_or(after.len());
        let closes = after[number_length..].starts_with('$');
        let matches = closes
            && after[..number_length]
                .parse::<f64>()
                .is_ok_and(|x| (x - old).abs() <= 1e-12 * old.abs().max(1.0));
        out.push_str(&rest[..at + opening.len()]);
        if matches {
            out.push_str(&new.to_string());
        } else {
            out.push_str(&after[..number_length]);
        }
        rest = &after[number_length..];
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix64_gives_the_published_stream() {
        // The first outputs for seed 1234567, as the reference C code (Vigna,
        // prng.di.unimi.it/splitmix64.c) prints them.
        let mut random = SplitMix64::new(1_234_567);
        assert_eq!(random.next_u64(), 6_457_827_717_110_365_317);
        assert_eq!(random.next_u64(), 3_203_168_211_198_807_973);
    }

    #[test]
    fn a_statement_gives_the_drawn_values() {
        let values = [("m".to_string(), 0.5, 0.43), ("I3".to_string(), 4e-4, 5e-4)];
        assert_eq!(
            restated(
                "Given $m = 0.5$ kg, $m = 2$ and $I_3 = 0.0004$, $mm = 0.5$",
                &values
            ),
            "Given $m = 0.43$ kg, $m = 2$ and $I_3 = 0.0005$, $mm = 0.5$"
        );
    }

    #[test]
    fn below_stays_below() {
        let mut random = SplitMix64::new(7);
        let mut seen = [0u32; 3];
        for _ in 0..3000 {
            seen[random.below(3) as usize] += 1;
        }
        assert!(seen.iter().all(|&n| (900..1100).contains(&n)), "{seen:?}");
    }
}
