//! A sum with the terms that differ only in their constants written as one:
//! c θ̇² + w θ̇² − x_B θ̇² → (c + w − x_B) θ̇², as a textbook writes a definition whose
//! terms share the state they depend on. Display only, like [`super::collect`].

use super::build::{add, mul};
use super::expr::{Expr, Node, Symbol};
use super::factor::{
    gcd, multiple_of, pull_common_factor, push_signed, signed_term, square_root_of_sum, square_tex,
};
use super::fast_hash::FastMap;
use super::number::Number;
use super::print::{latex, latex_term};
use std::ops::Neg as _;

/// Terms that share their varying factors: those factors, and each term whole and as its
/// constant part.
struct Set {
    varying: Expr,
    terms: Vec<Expr>,
    constants: Vec<Expr>,
}

/// `e` (a canonical sum) in LaTeX with each set of terms that share all their varying
/// factors written as the sum of their constant factors times those, in the order each
/// set first appears; sets whose sums are multiples of one share it:
/// −(r + z)(θ̇² + 2 ψ̇ θ̇ s_φ). A sum of constants alone is collected the same way by its
/// functions of constants: (c + w − x_H) cos λ + z_H sin λ. `None` when no two terms share
/// what they are collected by, or when that is no shorter.
fn latex_constants_collected(e: &Expr) -> Option<String> {
    constants_collected_terms(e).map(|terms| {
        let mut out = String::new();
        terms.into_iter().for_each(|t| push_signed(&mut out, t));
        out
    })
}

/// A sum in LaTeX, its terms that differ only in constants written once (see
/// [`latex_constants_collected`]) where that is shorter.
pub(super) fn sum_tex(e: &Expr) -> String {
    latex_constants_collected(e).unwrap_or_else(|| latex(e))
}

/// The terms [`latex_constants_collected`] writes, each with its sign.
pub(super) fn constants_collected_terms(e: &Expr) -> Option<Vec<String>> {
    let mut sets = sets_by(e, Expr::is_constant);
    if sets.iter().all(|s| s.varying.is_one()) {
        sets = sets_by(e, is_plain_constant);
    }
    // Nothing shared, or constants that are all plain (c + w − x_H): left to `latex`.
    if sets.iter().all(|s| s.terms.len() < 2) || sets.iter().all(|s| s.varying.is_one()) {
        return None;
    }
    let groups = shared_sums(&sets);
    // Only the collected groups differ from the sum as `latex` writes it: each is weighed
    // against the terms it replaces, so a long row is printed once, not twice.
    let mut texts = Vec::with_capacity(groups.len());
    let mut gain = 0isize;
    for group in &groups {
        let Shared::Sum {
            constant,
            varying,
            members,
        } = group
        else {
            texts.push(None);
            continue;
        };
        let text = collected_text(constant, varying);
        let before: usize = members.iter().map(|t| shown_length(&latex(t)) + 3).sum();
        gain += before as isize - (shown_length(&text) + 3) as isize;
        texts.push(Some(text));
    }
    if gain <= 0 {
        return None;
    }
    let out = groups
        .iter()
        .zip(texts)
        .map(|(group, text)| match group {
            Shared::AsIs(term) => latex(term),
            Shared::Sum { .. } => text.unwrap_or_default(),
        })
        .collect();
    Some(out)
}

/// A sum of constants times a sum of varying parts: `(c + w − x_H) (ω_y² + ω_z²)`.
fn collected_text(constant: &Expr, varying: &Expr) -> String {
    let (common, sum) = pull_common_factor(constant);
    // A varying part that only divides joins the common factor's fraction, `\frac{g m}{y}
    // (r − R)`, rather than trailing as `(r − R) \frac{1}{y}`.
    let divides = !varying.is_one() && varying.factors().iter().all(is_divisor);
    let common = if divides {
        mul([common, varying.clone()])
    } else {
        common
    };
    let key = if varying.is_one() || divides {
        String::new()
    } else if varying.terms().len() > 1 {
        format!("\\left({}\\right)", latex(varying))
    } else {
        latex(varying)
    };
    if sum.terms().len() > 1 {
        factored(&common, &sum, &key)
    } else {
        signed_term(&mul([common, sum]), &key)
    }
}

/// Whether `factor` is a power with a negative exponent: it only divides.
pub(super) fn is_divisor(factor: &Expr) -> bool {
    matches!(factor.node(), Node::Pow(_, exponent)
        if exponent.as_number().is_some_and(Number::is_negative))
}

/// The length of LaTeX as a reader sees it: `\left(` and `\right)` are one character each.
fn shown_length(tex: &str) -> usize {
    tex.len() - 5 * tex.matches("\\left").count() - 6 * tex.matches("\\right").count()
}

/// The terms of `e` in sets by their factors that are not `constant`, in order of first
/// appearance.
fn sets_by(e: &Expr, constant: impl Fn(&Expr) -> bool) -> Vec<Set> {
    let mut sets: Vec<Set> = Vec::new();
    // A long sum (a row of a large system) has hundreds of terms: found by hash, not by scan.
    let mut index: FastMap<Expr, usize> = FastMap::default();
    for term in e.terms() {
        let (number, rest) = term.split_coefficient();
        let (constants, varying): (Vec<Expr>, Vec<Expr>) =
            rest.factors().iter().cloned().partition(|f| constant(f));
        let constants = mul(std::iter::once(Expr::num(number)).chain(constants));
        let varying = mul(varying);
        match index.get(&varying) {
            Some(&i) => {
                sets[i].terms.push(term.clone());
                sets[i].constants.push(constants);
            }
            None => {
                index.insert(varying.clone(), sets.len());
                sets.push(Set {
                    varying,
                    terms: vec![term.clone()],
                    constants: vec![constants],
                });
            }
        }
    }
    sets
}

/// The number r with `a = r b`, as [`multiple_of`] finds it, without multiplying out
/// when both are one term: then they differ only in their numbers or not at all.
fn ratio(a: &Expr, b: &Expr) -> Option<Number> {
    match (a.terms(), b.terms()) {
        ([x], [y]) => {
            let ((p, x), (q, y)) = (x.split_coefficient(), y.split_coefficient());
            (x == y).then(|| q.recip().map(|q| p * q)).flatten()
        }
        _ => multiple_of(a, b),
    }
}

/// A named constant or a power of one (`c`, `L²`), not a function of one (`cos λ`).
fn is_plain_constant(factor: &Expr) -> bool {
    let base = match factor.node() {
        Node::Pow(base, exponent) if exponent.as_number().is_some() => base,
        _ => factor,
    };
    matches!(base.node(), Node::Sym(Symbol::Const(_)))
}

/// What one printed term of the sum is.
enum Shared<'a> {
    /// A term no other shares anything with, as it is.
    AsIs(&'a Expr),
    /// A sum of constants times a sum of varying parts, each with its number, and the
    /// terms it stands for.
    Sum {
        constant: Expr,
        varying: Expr,
        members: Vec<&'a Expr>,
    },
}

/// The sets in their order, each with the later ones whose constant sum is a number times
/// its own merged into it: −(r + z) θ̇² − 2 (r + z) ψ̇ θ̇ → −(r + z)(θ̇² + 2 ψ̇ θ̇).
fn shared_sums(sets: &[Set]) -> Vec<Shared<'_>> {
    let sums: Vec<Expr> = sets
        .iter()
        .map(|s| add(s.constants.iter().cloned()))
        .collect();
    let mut used = vec![false; sets.len()];
    let mut out = Vec::new();
    for (i, set) in sets.iter().enumerate() {
        if used[i] {
            continue;
        }
        used[i] = true;
        // The terms of constants alone stay as they are: (a + b) alone gains nothing, and
        // would pull out a bare fraction, ⅓ (a + b).
        if set.varying.is_one() {
            out.extend(set.terms.iter().map(Shared::AsIs));
            continue;
        }
        // A sum of numbers alone is no constant worth sharing.
        let symbolic = !sums[i].is_zero() && sums[i].as_number().is_none();
        // What the sets share: the sum without its common factor, R (m + 2 M) and
        // b (m + 2 M) sharing m + 2 M; one term as it is.
        let (own, base) = if sums[i].terms().len() > 1 {
            pull_common_factor(&sums[i])
        } else {
            (Expr::one(), sums[i].clone())
        };
        // Each set's varying part with its factor: over `sums[i]` (a number), and over `base`.
        let mut by_number = vec![set.varying.clone()];
        let mut by_base = vec![mul([own.clone(), set.varying.clone()])];
        let mut members: Vec<&Expr> = set.terms.iter().collect();
        if symbolic {
            for j in i + 1..sets.len() {
                let Some((f, r)) = (!used[j])
                    .then(|| factor_of(&sums[j], &sums[i], &own, &base))
                    .flatten()
                else {
                    continue;
                };
                used[j] = true;
                by_number.extend(r.map(|r| mul([Expr::num(r), sets[j].varying.clone()])));
                by_base.push(mul([f, sets[j].varying.clone()]));
                members.extend(&sets[j].terms);
            }
        }
        if members.len() == 1 || sums[i].is_zero() {
            out.extend(members.into_iter().map(Shared::AsIs));
            continue;
        }
        // Shared by numbers alone: the sum as it is, −(r + z)(θ̇² + 2 ψ̇ θ̇); else its
        // base, (m + 2 M)(R sin θ + b cos θ).
        let (constant, varying) = if by_number.len() == by_base.len() {
            (sums[i].clone(), by_number)
        } else {
            (base, by_base)
        };
        // Whole numbers inside: (r + z)(2 φ̇ θ̇ + ψ̇²) rather than 2 (r + z)(φ̇ θ̇ + ψ̇²/2).
        let shared = shared_number(&varying);
        let inverse = Expr::num(shared.recip().unwrap_or(Number::ONE));
        out.push(Shared::Sum {
            constant: mul([Expr::num(shared), constant]),
            varying: add(varying.into_iter().map(|v| mul([inverse.clone(), v]))),
            members,
        });
    }
    out
}

/// The factor f with `sum = f · base`, where `first = own · base` is the sum of the set
/// that shares it: a number r times `first` (`−2 (r + z)`), with r, or, for sums of several
/// terms, another common factor of the same sum (`b (m + 2 M)` beside `R (m + 2 M)`).
fn factor_of(sum: &Expr, first: &Expr, own: &Expr, base: &Expr) -> Option<(Expr, Option<Number>)> {
    if let Some(r) = ratio(sum, first) {
        return Some((mul([Expr::num(r), own.clone()]), Some(r)));
    }
    if base.terms().len() < 2 || sum.terms().len() != base.terms().len() {
        return None;
    }
    let (common, rest) = pull_common_factor(sum);
    if rest == *base {
        Some((common, None))
    } else if rest == base.neg() {
        Some((common.neg(), None))
    } else {
        None
    }
}

/// The gcd of the terms' numerators over the lcm of their denominators, or 1 where a
/// number is no fraction or the lcm would overflow.
fn shared_number(terms: &[Expr]) -> Number {
    let ratios: Option<Vec<(i64, i64)>> = terms
        .iter()
        .map(|t| match t.split_coefficient().0 {
            Number::Ratio(n, d) => Some((n.abs(), d)),
            Number::Real(_) => None,
        })
        .collect();
    let Some(ratios) = ratios else {
        return Number::ONE;
    };
    let numerator = ratios.iter().fold(0, |g, &(n, _)| gcd(g, n));
    let denominator = ratios
        .iter()
        .try_fold(1i64, |l, &(_, d)| (l / gcd(l, d)).checked_mul(d));
    match denominator {
        Some(d) if numerator > 0 => Number::ratio(numerator.into(), d.into()),
        _ => Number::ONE,
    }
}

/// Printed terms, each with its sign in front, as one sum: negated when most are negative
/// (whether it was is the first value), then its positive terms first.
pub(super) fn positive_first(terms: Vec<String>) -> (bool, String) {
    let negatives = terms.iter().filter(|t| t.starts_with('-')).count();
    let flip = 2 * negatives > terms.len();
    let terms = terms.into_iter().map(|t| {
        if !flip {
            t
        } else if let Some(rest) = t.strip_prefix('-') {
            rest.to_string()
        } else {
            format!("-{t}")
        }
    });
    let (first, then): (Vec<String>, Vec<String>) = terms.partition(|t| !t.starts_with('-'));
    let mut out = String::new();
    first
        .into_iter()
        .chain(then)
        .for_each(|t| push_signed(&mut out, t));
    (flip, out)
}

/// A sum `c` times `key` as it reads shortest: whole in brackets, with a factor every
/// term shares out, (r_F/σ_F)(…) f̂_x, or collected by its constants.
pub fn sum_times(c: &Expr, key: &str) -> String {
    // Whole, with the sign rule: (k s_B − R k/2), never (−R k/2 + k s_B).
    let whole = factored(&Expr::one(), c, key);
    // A factor pulled out wins a tie, as a textbook pulls it out.
    let shorter = [common_factor_out(c, key), component_collected(c, key)];
    shorter
        .into_iter()
        .flatten()
        .chain(std::iter::once(whole))
        .min_by_key(|t| shown_length(t))
        .unwrap_or_default()
}

/// A vector's component `c` (a sum) times `key` with its terms collected by their constants,
/// `−(c + w)(θ̇ + ψ̇ s_φ) b̂_z`, when that collects anything; the minus out when most of
/// the collected terms are negative, and the positive ones first.
fn component_collected(c: &Expr, key: &str) -> Option<String> {
    let terms = constants_collected_terms(c)?;
    if let [one] = terms.as_slice() {
        return Some(format!("{one} {key}"));
    }
    let (flipped, sum) = positive_first(terms);
    let sign = if flipped { "-" } else { "" };
    Some(format!("{sign}\\left({sum}\\right) {key}"))
}

/// `common (inner) key` when the terms of `e` share a factor other than ±1; else `None`.
pub fn common_factor_out(e: &Expr, key: &str) -> Option<String> {
    if e.terms().len() < 2 {
        return None;
    }
    let (common, inner) = pull_common_factor(e);
    let trivial = common
        .as_number()
        .is_some_and(|c| c.is_one() || c.neg().is_one());
    (!trivial).then(|| factored(&common, &inner, key))
}

/// `common (inner) key`, the sign of `common` in front.
pub fn factored(common: &Expr, inner: &Expr, key: &str) -> String {
    let (common, inner, inner_tex) = &signed_inner(common, inner);
    let (c, rest) = common.split_coefficient();
    let sign = if c.is_negative() { "-" } else { "" };
    let c = if c.is_negative() { c.neg() } else { c };
    let front = if rest.is_one() && c.is_one() {
        String::new()
    } else {
        format!("{} ", latex_term(c, &rest))
    };
    let inner =
        square_root_of_sum(inner).map_or_else(|| inner_tex.clone(), |root| square_tex(&root));
    let text = format!("{sign}{front}{inner} {key}");
    text.trim_end().to_string()
}

/// `common` and `inner` as [`factored`] writes them, with `inner` in LaTeX, in brackets
/// unless it is one product: collected by
/// its constants where that is shorter and leads with a plus; else, a sum that leads with a
/// minus as −k (a − b − c) when most of its terms are negative, or with its positive terms
/// first, as a textbook writes (I₃ − I₁).
fn signed_inner(common: &Expr, inner: &Expr) -> (Expr, Expr, String) {
    let parenthesized = |tex: String| format!("\\left({tex}\\right)");
    if let Some(terms) = constants_collected_terms(inner) {
        // Collected into one product, it needs no brackets of its own.
        let one = terms.len() == 1;
        let (flipped, tex) = positive_first(terms);
        let tex = if one { tex } else { parenthesized(tex) };
        return if flipped {
            (common.neg(), inner.neg(), tex)
        } else {
            (common.clone(), inner.clone(), tex)
        };
    }
    let negative = |t: &Expr| t.split_coefficient().0.is_negative();
    let negatives = inner.terms().iter().filter(|t| negative(t)).count();
    let positives = inner.terms().len() - negatives;
    if inner.terms().len() < 2 || !negative(&inner.terms()[0]) {
        return (common.clone(), inner.clone(), parenthesized(latex(inner)));
    }
    if negatives > positives {
        let (common, inner) = (common.neg(), inner.neg());
        let tex = parenthesized(latex(&inner));
        return (common, inner, tex);
    }
    let mut tex = String::new();
    let (first, then): (Vec<&Expr>, Vec<&Expr>) = inner.terms().iter().partition(|t| !negative(t));
    for t in first.into_iter().chain(then) {
        push_signed(&mut tex, latex(t));
    }
    (common.clone(), inner.clone(), parenthesized(tex))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::build::pow;

    #[test]
    fn terms_that_share_their_rates_are_written_once_with_their_constants_summed() {
        let c = Expr::constant;
        let (cc, w, x, z) = (c("c"), c("w"), c("x_B"), c("z_B"));
        let rate = pow(Expr::coord("theta", 1), Expr::int(2));
        let other = &Expr::coord("phi", 1) * &Expr::coord("psi", 1);
        // c θ̇² + w θ̇² − x_B θ̇² + z_B φ̇ ψ̇ → (c + w − x_B) θ̇² + z_B φ̇ ψ̇.
        let e = add([
            &cc * &rate,
            &w * &rate,
            &(&x * &Expr::int(-1)) * &rate,
            &z * &other,
        ]);
        assert_eq!(
            latex_constants_collected(&e).unwrap(),
            format!(
                "\\left({}\\right) {} + {}",
                latex(&add([cc.clone(), w.clone(), &x * &Expr::int(-1)])),
                latex(&rate),
                latex(&(&z * &other))
            )
        );
        // Nothing shared: left to `latex`.
        assert_eq!(
            latex_constants_collected(&add([&cc * &rate, &z * &other])),
            None
        );
    }

    #[test]
    fn a_sum_of_constants_is_collected_by_its_functions_of_constants() {
        let c = Expr::constant;
        use crate::symbolic::build::{cos, sin};
        let (cc, w, x, z, lambda) = (c("c"), c("w"), c("x_H"), c("z_H"), c("lambda"));
        // c cos λ + w cos λ − x_H cos λ + z_H sin λ → (c + w − x_H) cos λ + z_H sin λ.
        let e = add([
            &cc * &cos(lambda.clone()),
            &w * &cos(lambda.clone()),
            &(&x * &Expr::int(-1)) * &cos(lambda.clone()),
            &z * &sin(lambda.clone()),
        ]);
        let expected = format!(
            "\\left({}\\right) {} + {}",
            latex(&add([cc.clone(), w.clone(), &x * &Expr::int(-1)])),
            latex(&cos(lambda.clone())),
            latex(&(&z * &sin(lambda.clone())))
        );
        assert_eq!(latex_constants_collected(&e).unwrap(), expected);
        // Plain constants alone are left as they are: c + w − x_H.
        assert_eq!(latex_constants_collected(&add([cc, w, x])), None);
    }
}
