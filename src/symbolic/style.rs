//! How the worked solution prints what the canonical form keeps exact: `s₁ = sin q₁` and
//! `c₁₂ = cos(q₁ + q₂)` for the sines and cosines of the coordinates, as Kane & Levinson
//! and MotionGenesis write them, and the decimals a problem wrote as decimals (`0.4`, not
//! `2/5`).
//!
//! A [`Style`] is set for the steps that use it with [`with_style`]; the LaTeX printer
//! reads it and records every abbreviation it prints, so that the step that introduces
//! them can list exactly those (see `Style::used`). Only the display changes: the
//! expressions, their canonical form and the numbers stay as they are. Outside
//! [`with_style`] the printer prints as it always did.

use super::expr::{Expr, Func, Node, Symbol};
use super::number::Number;
use super::tex_name::latex_name;
use std::cell::RefCell;
use std::collections::{BTreeMap, BTreeSet};

/// What the printer abbreviates and how it writes numbers.
#[derive(Clone, Debug, Default)]
pub struct Style {
    /// The index each coordinate is abbreviated by (`q1 → 1`, `theta → \theta`), in the
    /// problem's order; empty: no abbreviations.
    indices: Vec<(String, String)>,
    /// The numbers the problem wrote as decimals, each with its text (`2/5 → 0.4`).
    decimals: BTreeMap<(i64, i64), String>,
    /// The letters of the sine and the cosine (`S`, `C` when the problem names `s` or
    /// `c`); `None`: the letters are `s`, `c`.
    letters: Option<(&'static str, &'static str)>,
    /// No abbreviations at all: the problem names both `s` or `c` and `S` or `C`.
    spelled_out: bool,
}

/// The letters of the sine and the cosine to try, in order: the first pair of which the
/// problem names neither letter is used; when it names a letter of each, `sin` and `cos`
/// are written out.
const LETTERS: [(&str, &str); 2] = [("s", "c"), ("S", "C")];

/// One abbreviation printed: `s_{12} = \sin\left(q_{1} + q_{2}\right)`.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Abbreviation {
    /// How many coordinates the argument adds, their positions in the problem, then sine
    /// (0) or cosine (1): the order of the list (`s₁, c₁, s₂, c₂, s₁₂`).
    order: (usize, Vec<(usize, bool)>, u8),
    /// The abbreviation, e.g. `s_{12}`.
    pub name: String,
    /// What it stands for, e.g. `\sin\left(q_{1} + q_{2}\right)`.
    pub value: String,
}

thread_local! {
    static CURRENT: RefCell<Option<(Style, BTreeSet<Abbreviation>)>> = const { RefCell::new(None) };
}

impl Style {
    /// Abbreviations for the sines and cosines of `coordinates` (names as in the problem).
    /// When all of them are one letter with a number (`q1`, `q2`), the number alone is the
    /// index (`s_{1}`); otherwise the whole name is (`s_{\theta}`).
    pub fn with_coordinates(mut self, coordinates: &[&str]) -> Style {
        let names: Vec<String> = coordinates.iter().map(|c| latex_name(c)).collect();
        let split = |n: &str| -> Option<(String, String)> {
            let (stem, sub) = n.split_once("_{")?;
            let sub = sub.strip_suffix('}')?;
            sub.chars()
                .all(|c| c.is_ascii_digit())
                .then(|| (stem.to_string(), sub.to_string()))
        };
        let parts: Vec<Option<(String, String)>> = names.iter().map(|n| split(n)).collect();
        let one_stem = parts.iter().all(Option::is_some)
            && parts
                .iter()
                .flatten()
                .all(|(s, _)| Some(s) == parts[0].as_ref().map(|(s, _)| s));
        self.indices = coordinates
            .iter()
            .zip(names.iter().zip(&parts))
            .map(|(c, (name, part))| {
                let index = match part {
                    Some((_, digits)) if one_stem => digits.clone(),
                    _ => name.clone(),
                };
                (c.to_string(), index)
            })
            .collect();
        self
    }

    /// Abbreviations that cannot be read as one of `taken` (the problem's names in LaTeX):
    /// a rocker length `c` beside `c_1 = \cos q_1` would read as a cosine, so the letters
    /// become `S`, `C`, or, when those are taken too, the sine and cosine are written out.
    pub fn avoiding(mut self, taken: &[String]) -> Style {
        let free = |(s, c): &(&str, &str)| !taken.iter().any(|t| t == s || t == c);
        match LETTERS.iter().find(|pair| free(pair)) {
            Some(&pair) => self.letters = (pair != LETTERS[0]).then_some(pair),
            None => self.spelled_out = true,
        }
        self
    }

    /// Prints `number` as `text` (a decimal the problem wrote, such as `0.4`).
    pub fn with_decimal(mut self, number: Number, text: &str) -> Style {
        if let Number::Ratio(n, d) = number {
            if d != 1 {
                self.decimals
                    .insert((n.abs(), d), text.trim_start_matches('-').into());
            }
        }
        self
    }
}

/// Runs `f` with `style` in force for the LaTeX printer of this thread, and returns its
/// result with the abbreviations printed meanwhile, in the order of the coordinates.
pub fn with_style<R>(style: Style, f: impl FnOnce() -> R) -> (R, Vec<Abbreviation>) {
    let previous = CURRENT.with(|c| c.replace(Some((style, BTreeSet::new()))));
    let result = f();
    let used = CURRENT.with(|c| c.replace(previous));
    let used = used
        .map(|(_, u)| u.into_iter().collect())
        .unwrap_or_default();
    (result, used)
}

/// The abbreviation of `f(arg)` under the current style, if it has one: `f` is `sin` or
/// `cos` and `arg` a coordinate or a sum of coordinates, each once with coefficient 1 or
/// −1, the first +1 (`c_{12-3} = \cos(q_1 + q_2 - q_3)`).
/// Recorded as used, with its value written by `latex_argument` (the printer's, passed in
/// so that the style stays below the printer).
pub(crate) fn abbreviation(
    f: Func,
    arg: &Expr,
    latex_argument: impl FnOnce(&Expr) -> String,
) -> Option<String> {
    if !matches!(f, Func::Sin | Func::Cos) {
        return None;
    }
    let (name, positions) = CURRENT.with(|c| {
        let current = c.borrow();
        let (style, _) = current.as_ref()?;
        if style.indices.is_empty() || style.spelled_out {
            return None;
        }
        let (sine, cosine) = style.letters.unwrap_or(LETTERS[0]);
        let letter = if f == Func::Sin { sine } else { cosine };
        // Each coordinate's position, and whether it is subtracted.
        let mut positions = Vec::new();
        for term in arg.terms() {
            let (coefficient, rest) = term.split_coefficient();
            let minus = if coefficient.is_one() {
                false
            } else if matches!(coefficient, Number::Ratio(-1, 1)) {
                true
            } else {
                return None;
            };
            let Node::Sym(Symbol::Coord(name, 0)) = rest.node() else {
                return None;
            };
            let at = style.indices.iter().position(|(c, _)| **c == **name)?;
            positions.push((at, minus));
        }
        positions.sort_unstable();
        // sin(−q₁ + q₂) would need a sign outside: written out.
        if positions.first().is_some_and(|&(_, minus)| minus) {
            return None;
        }
        let indices: Vec<String> = positions
            .iter()
            .map(|&(i, minus)| {
                let index = &style.indices[i].1;
                if minus {
                    format!("-{index}")
                } else {
                    index.clone()
                }
            })
            .collect();
        let indices: Vec<&str> = indices.iter().map(String::as_str).collect();
        // Single digits run together (`s_{12}`); anything longer is separated (`s_{1,10}`);
        // a long run of consecutive indices by its ends (`s_{2…10}`), as
        // q̇₂ + ⋯ + q̇₁₀ is written.
        let joined = if let Some((first, last)) = consecutive_run(&indices) {
            format!("{first}\\ldots {last}")
        } else if indices
            .iter()
            .all(|i| i.trim_start_matches('-').chars().count() == 1)
        {
            indices.concat()
        } else {
            indices.join(",")
        };
        Some((format!("{letter}_{{{joined}}}"), positions))
    })?;
    // The argument is a sum of coordinates: printing it abbreviates nothing.
    let value = format!("\\{}{}", f.name(), latex_argument(arg));
    CURRENT.with(|c| {
        if let Some((_, used)) = c.borrow_mut().as_mut() {
            used.insert(Abbreviation {
                order: (positions.len(), positions, u8::from(f == Func::Cos)),
                name: name.clone(),
                value,
            });
        }
    });
    Some(name)
}

/// The ends of `indices` when they are at least five consecutive integers.
fn consecutive_run<'a>(indices: &[&'a str]) -> Option<(&'a str, &'a str)> {
    const SHORTEST: usize = 5;
    let numbers: Vec<u64> = indices
        .iter()
        .map(|i| i.parse().ok())
        .collect::<Option<_>>()?;
    let consecutive = numbers
        .windows(2)
        .all(|w| w[0].checked_add(1) == Some(w[1]));
    (numbers.len() >= SHORTEST && consecutive).then(|| (indices[0], indices[indices.len() - 1]))
}

/// How the current style writes the number `n/d` (`d > 1`), if as a decimal.
pub(crate) fn decimal(n: i64, d: i64) -> Option<String> {
    CURRENT.with(|c| {
        let current = c.borrow();
        let (style, _) = current.as_ref()?;
        style.decimals.get(&(n.abs(), d)).cloned()
    })
}

/// The decimal literals of an expression's text that are not whole numbers, each with
/// its value and its text as a plain decimal (`2.0e-3 → (1/500, "0.002")`).
pub fn decimal_literals(text: &str) -> Vec<(Number, String)> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let starts = chars[i].is_ascii_digit()
            || (chars[i] == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit));
        // Digits that end a name (`q1`, `L_2`) are part of it.
        let in_name = i > 0 && (chars[i - 1].is_ascii_alphanumeric() || chars[i - 1] == '_');
        if !starts || in_name {
            i += 1;
            continue;
        }
        let start = i;
        i = super::parse::number_literal_end(&chars, i);
        let literal: String = chars[start..i].iter().collect();
        if !literal.contains(['.', 'e', 'E']) {
            continue;
        }
        if let Some(Number::Ratio(n, d)) = Number::parse_decimal(&literal) {
            if let Some(text) = plain_decimal(n, d) {
                out.push((Number::Ratio(n, d), text));
            }
        }
    }
    out
}

/// `n/d` as a plain decimal when `d > 1` is a divisor of a power of ten (`1/500 → 0.002`).
fn plain_decimal(n: i64, d: i64) -> Option<String> {
    if d <= 1 {
        return None;
    }
    let mut places = 0usize;
    let mut scale: i128 = 1;
    while scale % d as i128 != 0 {
        scale *= 10;
        places += 1;
        if places > 18 {
            return None;
        }
    }
    let digits = (n.unsigned_abs() as i128 * (scale / d as i128)).to_string();
    let digits = format!("{digits:0>width$}", width = places + 1);
    let (whole, fraction) = digits.split_at(digits.len() - places);
    Some(format!("{whole}.{fraction}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::build::{cos, sin};
    use crate::symbolic::print::latex;

    fn q(i: usize) -> Expr {
        Expr::coord(&format!("q{i}"), 0)
    }

    #[test]
    fn sines_and_cosines_of_coordinates_are_abbreviated_and_listed() {
        let style = Style::default().with_coordinates(&["q1", "q2", "q10"]);
        let e = &(&sin(q(1)) * &cos(&q(1) + &q(2))) + &cos(&q(2) + &q(10));
        let (text, used) = with_style(style, || latex(&e));
        assert_eq!(text, "c_{2,10} + s_{1} c_{12}");
        let listed: Vec<String> = used
            .iter()
            .map(|a| format!("{} = {}", a.name, a.value))
            .collect();
        assert_eq!(
            listed,
            [
                "s_{1} = \\sin(q_{1})",
                "c_{12} = \\cos\\left(q_{1} + q_{2}\\right)",
                "c_{2,10} = \\cos\\left(q_{2} + q_{10}\\right)"
            ]
        );
        // Outside the style nothing changes.
        assert_eq!(latex(&sin(q(1))), "\\sin(q_{1})");
    }

    #[test]
    fn a_difference_is_abbreviated_and_a_named_c_changes_the_letters() {
        let diff = &(&q(1) + &q(2)) - &q(3);
        let style = Style::default().with_coordinates(&["q1", "q2", "q3"]);
        let (text, used) = with_style(style.clone(), || latex(&cos(diff.clone())));
        assert_eq!(text, "c_{12-3}");
        assert_eq!(used[0].value, "\\cos\\left(q_{1} + q_{2} - q_{3}\\right)");
        // sin(q₂ − q₁) = −sin(q₁ − q₂): the sign comes out in front of s₁₋₂.
        let back = &q(2) - &q(1);
        let (text, _) = with_style(style.clone(), || latex(&sin(back.clone())));
        assert_eq!(text, "-s_{1-2}");
        // A rocker length c: the letters are S and C.
        let taken = ["c".to_string(), "m".to_string()];
        let (text, _) = with_style(style.clone().avoiding(&taken), || latex(&cos(q(1))));
        assert_eq!(text, "C_{1}");
        // c and C both named: written out.
        let taken = ["c".to_string(), "C".to_string()];
        let (text, _) = with_style(style.avoiding(&taken), || latex(&cos(q(1))));
        assert_eq!(text, "\\cos(q_{1})");
    }

    #[test]
    fn names_with_other_stems_are_indexed_by_the_whole_name() {
        let style = Style::default().with_coordinates(&["psi", "theta", "x1"]);
        let theta = Expr::coord("theta", 0);
        let e = &(&sin(theta.clone()) * &sin(theta.clone())) * &Expr::constant("m");
        let twice = &Expr::int(2) * &theta;
        let (text, _) = with_style(style, || {
            [
                latex(&e),
                latex(&cos(Expr::coord("x1", 0))),
                latex(&sin(twice)),
            ]
        });
        assert_eq!(
            text,
            [
                "m s_{\\theta}^{2}",
                "c_{x_{1}}",
                "\\sin\\left(2 \\theta\\right)"
            ]
        );
    }

    #[test]
    fn decimal_literals_are_found_in_an_expression() {
        let found: Vec<String> = decimal_literals("-0.4*N.x + 1.0*N.y + q1*2.0e-3 + x2/4 + .25")
            .into_iter()
            .map(|(n, t)| format!("{n} {t}"))
            .collect();
        assert_eq!(found, ["2/5 0.4", "1/500 0.002", "1/4 0.25"]);
    }

    #[test]
    fn decimals_the_problem_wrote_print_as_written() {
        let style = Style::default().with_decimal(Number::ratio(2, 5), "0.4");
        let e = &Expr::ratio(-2, 5) + &Expr::constant("x");
        let half = &Expr::ratio(1, 2) * &Expr::constant("x");
        let (text, _) = with_style(style, || [latex(&e), latex(&half)]);
        assert_eq!(text, ["-0.4 + x", "\\frac{x}{2}"]);
    }
}
