//! The diagnosis of a wrong expression, part by part: which term differs, its value
//! expected and given, and the kind of slip (a sign, a missing or extra term, a factor, a
//! sine for a cosine).

use super::numbers::{close, factor_text, is_zero, ratio};
use super::parts::{first_trig, swap_sine_cosine, terms, values, Key, Part};
use super::reference::Sample;
use crate::symbolic::Expr;

/// One part that differs, with what the student wrote short of the worked solution.
#[derive(Clone, Debug)]
pub(super) struct Finding {
    /// Which part.
    pub key: Key,
    /// The sentence.
    pub text: String,
    /// Expected minus given, at the sampled states.
    pub shortfall: Vec<f64>,
}

/// The slip that turns `expected` into `given`, if it is a simple one.
pub(super) fn slip(
    given: (&Expr, &[f64]),
    expected: (&Expr, &[f64]),
    samples: &[Sample],
) -> Option<String> {
    if let Some(k) = ratio(given.1, expected.1).filter(|k| k.abs() > 1e-9) {
        if (k + 1.0).abs() < 1e-9 {
            return Some("has the wrong sign".into());
        }
        if (k - 1.0).abs() > 1e-9 {
            return Some(format!("is off by the factor {}", factor_text(k)));
        }
    }
    let swapped = swap_sine_cosine(given.0);
    let swapped_values = values(&swapped, samples, true);
    if swapped != *given.0 && close(&swapped_values, expected.1, 0.0) {
        return Some(match first_trig(given.0) {
            Some(true) => "has a sine where a cosine was expected".into(),
            _ => "has a cosine where a sine was expected".into(),
        });
    }
    None
}

/// Every part of `given` that differs from the same part of `expected`.
pub(super) fn compare(
    given: &[Part],
    expected: &[Part],
    scale: f64,
    samples: &[Sample],
) -> Vec<Finding> {
    given
        .iter()
        .zip(expected)
        .filter(|(g, e)| !close(&g.values, &e.values, scale))
        .map(|(g, e)| Finding {
            key: g.key.clone(),
            text: describe(g, e, scale, samples),
            shortfall: e.values.iter().zip(&g.values).map(|(x, y)| x - y).collect(),
        })
        .collect()
}

/// One sentence on how the part `given` differs from `expected`.
fn describe(given: &Part, expected: &Part, scale: f64, samples: &[Sample]) -> String {
    let (g, e) = (&given.expr, &expected.expr);
    if let Key::Unknown(symbol) = &given.key {
        let name = Expr::sym(symbol.clone());
        if is_zero(&given.values, scale) {
            return format!(
                "the term in {name} is missing ({} was expected)",
                e.clone() * name.clone()
            );
        }
        if is_zero(&expected.values, scale) {
            return format!(
                "{name} does not belong in this equation (the extra term {})",
                g.clone() * name.clone()
            );
        }
        let what = given.key.phrase();
        return match slip((g, &given.values), (e, &expected.values), samples) {
            Some(kind) => format!("{what} {kind}: {g} where {e} was expected"),
            None => format!("{what} is {g} where {e} was expected"),
        };
    }
    if let Some(kind) = slip((g, &given.values), (e, &expected.values), samples) {
        if e.terms().len() == 1 {
            return format!("the term {e} {kind} (written {g})");
        }
        return format!("{} {kind}: {g} where {e} was expected", given.key.phrase());
    }
    by_terms(given, expected, scale, samples)
}

/// The terms of two parts paired off, and what is left of each described.
fn by_terms(given: &Part, expected: &Part, scale: f64, samples: &[Sample]) -> String {
    let mut left = nonzero_terms(&given.expr, samples, scale);
    let mut wanted = nonzero_terms(&expected.expr, samples, scale);
    wanted.retain(
        |(_, w)| match left.iter().position(|(_, g)| close(g, w, scale)) {
            Some(i) => {
                left.remove(i);
                false
            }
            None => true,
        },
    );
    let mut sentences = Vec::new();
    if left.len() == 1 && wanted.len() == 1 {
        let ((g, gv), (e, ev)) = (&left[0], &wanted[0]);
        return match slip((g, gv), (e, ev), samples) {
            Some(kind) => format!("the term {e} {kind} (written {g})"),
            None => format!("the term {g} is written where {e} was expected"),
        };
    }
    for (e, _) in &wanted {
        sentences.push(format!("the term {e} is missing"));
    }
    for (g, _) in &left {
        sentences.push(format!("the term {g} is not in the worked solution"));
    }
    if sentences.is_empty() {
        let (g, e) = (&given.expr, &expected.expr);
        return format!("{} are {g} where {e} was expected", given.key.phrase());
    }
    sentences.join("; ")
}

fn nonzero_terms(e: &Expr, samples: &[Sample], scale: f64) -> Vec<(Expr, Vec<f64>)> {
    if e.is_zero() {
        return Vec::new();
    }
    terms(e, samples)
        .into_iter()
        .filter(|(_, v)| !is_zero(v, scale))
        .collect()
}

/// The whole of `given` against `expected` when every part is off by one factor: the
/// sentence for it (`every term is off by the factor 2`), if so.
pub(super) fn whole(given: &[f64], expected: &[f64]) -> Option<String> {
    let k = ratio(given, expected).filter(|k| k.abs() > 1e-9)?;
    if (k + 1.0).abs() < 1e-9 {
        Some("every term has the wrong sign".into())
    } else if (k - 1.0).abs() > 1e-9 {
        Some(format!(
            "every term is off by the factor {}",
            factor_text(k)
        ))
    } else {
        None
    }
}
