//! Cancelling a sum against its own powers in a denominator, as a reader does by eye:
//! (r_A + r_B)² sin q / (r_A + r_B)² = sin q, (x² − y²)/(x + y) = x − y. The canonical form
//! expands every numerator into monomials, each over the power of the sum, so like
//! denominators must be gathered and their numerator divided exactly.

use super::build::{add, mul, pow};
use super::expr::{Expr, Node};
use super::number::Number;
use std::collections::BTreeMap;

/// The most steps one division may take before it gives up (a quotient that long would
/// not shorten anything).
const MOST_DIVISION_STEPS: usize = 400;

/// `e` (a canonical sum) with the terms over one power of a sum gathered and, where the sum
/// divides their numerator exactly, the quotient in their place; `e` itself otherwise.
pub fn cancel_sums(e: &Expr) -> Expr {
    let terms = e.terms();
    if !terms.iter().any(|t| !denominators(t).is_empty()) {
        return e.clone();
    }
    // Groups by the sums below, in order of first use: each term with its powers of them
    // and the rest of it.
    let mut groups: Vec<(Vec<Expr>, Vec<Member>)> = Vec::new();
    for t in terms {
        let below = denominators(t);
        let sums: Vec<Expr> = below.iter().map(|(s, _)| s.clone()).collect();
        let powers: Vec<i64> = below.iter().map(|(_, k)| *k).collect();
        let numerator = mul(t
            .factors()
            .iter()
            .filter(|f| !is_denominator(f))
            .cloned()
            .collect::<Vec<_>>());
        let member = (powers, numerator, t.clone());
        match groups.iter_mut().find(|(d, _)| *d == sums) {
            Some((_, members)) => members.push(member),
            None => groups.push((sums, vec![member])),
        }
    }
    let mut changed = false;
    let mut out: Vec<Expr> = Vec::new();
    for (sums, members) in groups {
        // Over the highest power of each sum: N₁/D + N₂/D² = (N₁ D + N₂)/D².
        let highest: Vec<i64> = (0..sums.len())
            .map(|k| members.iter().map(|(p, _, _)| p[k]).max().unwrap_or(0))
            .collect();
        let mut numerator = add(members.iter().map(|(powers, n, _)| {
            let raised = sums
                .iter()
                .zip(powers.iter().zip(&highest))
                .filter(|(_, (k, top))| k < top)
                .map(|(s, (k, top))| pow(s.clone(), Expr::int(top - k)));
            mul(std::iter::once(n.clone()).chain(raised))
        }));
        let mut below: Vec<(Expr, i64)> = sums.into_iter().zip(highest).collect();
        // A factor every term of a sum shares, and its sign, leave the sum for the
        // numerator: c d s₃ / (−a c s₁₃ − c d s₃) = −d s₃ / (a s₁₃ + d s₃).
        let mut simpler = false;
        for (sum, power) in below.iter_mut() {
            if let Some((common, rest)) = content(sum) {
                numerator = mul([numerator, pow(common, Expr::int(-*power))]);
                *sum = rest;
                simpler = true;
            }
        }
        let mut divided = false;
        for (sum, power) in below.iter_mut() {
            while *power > 0 {
                match divide(&numerator, sum) {
                    Some(quotient) => {
                        numerator = quotient;
                        *power -= 1;
                        divided = true;
                    }
                    None => break,
                }
            }
        }
        let mixed = members.iter().any(|(p, _, _)| *p != members[0].0);
        if !divided && (mixed || !simpler) {
            // Nothing cancels: the terms as they were, rather than one numerator multiplied
            // out over the highest powers.
            out.extend(members.into_iter().map(|(_, _, t)| t));
            continue;
        }
        changed = true;
        let mut factors = vec![numerator];
        factors.extend(
            below
                .into_iter()
                .filter(|(_, k)| *k > 0)
                .map(|(sum, k)| pow(sum, Expr::int(-k))),
        );
        out.push(mul(factors));
    }
    if changed {
        add(out)
    } else {
        e.clone()
    }
}

/// The factor all terms of `s` share (atoms to their least power, and −1 when the first
/// term is negative) and `s` divided by it; `None` when that factor is 1.
fn content(s: &Expr) -> Option<(Expr, Expr)> {
    let terms = s.terms();
    let mut least: Vec<(Expr, i64)> = Vec::new();
    for (i, t) in terms.iter().enumerate() {
        let powers: Vec<(Expr, i64)> = t
            .factors()
            .iter()
            .filter(|f| f.as_number().is_none())
            .map(split_power)
            // A power of a sum stays: taken out, its reciprocal would be multiplied out.
            .filter(|(base, _)| !matches!(base.node(), Node::Add(_)))
            .collect();
        if i == 0 {
            least = powers;
        } else {
            // The power nearest zero of one sign: x² and x give x; x⁻³ and x⁻² give x⁻².
            least.retain_mut(|(atom, k)| match powers.iter().find(|(a, _)| a == atom) {
                Some((_, j)) if (*j > 0) == (*k > 0) => {
                    *k = if *k > 0 { (*k).min(*j) } else { (*k).max(*j) };
                    true
                }
                _ => false,
            });
        }
    }
    let negative = terms[0].split_coefficient().0.is_negative();
    if least.is_empty() && !negative {
        return None;
    }
    let mut factors: Vec<Expr> = least
        .into_iter()
        .map(|(atom, k)| pow(atom, Expr::int(k)))
        .collect();
    if negative {
        factors.push(Expr::int(-1));
    }
    let common = mul(factors);
    let rest = mul([pow(common.clone(), Expr::int(-1)), s.clone()]);
    Some((common, rest))
}

/// A term of a group: its powers of the group's sums, the rest of it, and the term itself.
type Member = (Vec<i64>, Expr, Expr);

/// Whether `f` is a negative integer power of a sum.
fn is_denominator(f: &Expr) -> bool {
    match f.node() {
        Node::Pow(base, exponent) => {
            matches!(base.node(), Node::Add(_))
                && exponent
                    .as_number()
                    .and_then(Number::as_integer)
                    .is_some_and(|k| k < 0)
        }
        _ => false,
    }
}

/// The sums `t` is divided by, each with its power (positive), in the term's order.
fn denominators(t: &Expr) -> Vec<(Expr, i64)> {
    t.factors()
        .iter()
        .filter(|f| is_denominator(f))
        .filter_map(|f| match f.node() {
            Node::Pow(base, exponent) => Some((base.clone(), -exponent.as_number()?.as_integer()?)),
            _ => None,
        })
        .collect()
}

/// A polynomial in the atoms of a divisor: each monomial's exponents (one per atom), with
/// its coefficient, free of the atoms.
type Polynomial = BTreeMap<Vec<i64>, Expr>;

/// `n / s` when `s` (a sum) divides `n` exactly as polynomials in the atoms of `s`.
fn divide(n: &Expr, s: &Expr) -> Option<Expr> {
    let atoms = atoms_of(s)?;
    // An atom's negative powers in the numerator (x³/y over x² + y²) are multiplied out
    // first and put back on the quotient.
    let lowest: Vec<i64> = atoms
        .iter()
        .map(|a| {
            n.terms()
                .iter()
                .flat_map(|t| t.factors().iter().map(split_power))
                .filter(|(b, _)| b == a)
                .map(|(_, k)| k)
                .min()
                .unwrap_or(0)
                .min(0)
        })
        .collect();
    let lift: Vec<i64> = lowest.iter().map(|k| -k).collect();
    let n = &mul(std::iter::once(n.clone()).chain(monomial(&atoms, &lift)));
    let quotient = divide_polynomials(n, s, &atoms)?;
    let back: Vec<Expr> = atoms
        .iter()
        .zip(&lowest)
        .filter(|(_, k)| **k < 0)
        .map(|(a, k)| pow(a.clone(), Expr::int(*k)))
        .collect();
    Some(mul(std::iter::once(quotient).chain(back)))
}

/// `n / s` for `n` a polynomial in `atoms` (no negative powers), when exact.
fn divide_polynomials(n: &Expr, s: &Expr, atoms: &[Expr]) -> Option<Expr> {
    let atoms = atoms.to_vec();
    let divisor = polynomial(s, &atoms)?;
    let mut rest = polynomial(n, &atoms)?;
    // The divisor's coefficients are numbers: its leading one divides any coefficient.
    let (lead, lead_coefficient) = divisor.iter().next_back()?;
    let lead_number = lead_coefficient.as_number()?.recip()?;
    if divisor.values().any(|c| c.as_number().is_none()) {
        return None;
    }
    let mut quotient: Vec<Expr> = Vec::new();
    for _ in 0..MOST_DIVISION_STEPS {
        let Some((top, coefficient)) = rest.iter().next_back().map(|(k, c)| (k.clone(), c.clone()))
        else {
            return Some(add(quotient));
        };
        let shift: Vec<i64> = top.iter().zip(lead).map(|(a, b)| a - b).collect();
        if shift.iter().any(|&k| k < 0) {
            return None;
        }
        let factor = mul([Expr::num(lead_number), coefficient]);
        quotient.push(mul(
            std::iter::once(factor.clone()).chain(monomial(&atoms, &shift))
        ));
        for (exponents, c) in &divisor {
            let at: Vec<i64> = exponents.iter().zip(&shift).map(|(a, b)| a + b).collect();
            let change = mul([Expr::int(-1), c.clone(), factor.clone()]);
            let now = add([rest.remove(&at).unwrap_or_else(Expr::zero), change]);
            if !now.is_zero() {
                rest.insert(at, now);
            }
        }
    }
    None
}

/// The distinct atoms of `s`'s monomials, when each is a product of atoms to positive
/// integer powers times a number.
fn atoms_of(s: &Expr) -> Option<Vec<Expr>> {
    let mut atoms: Vec<Expr> = Vec::new();
    for t in s.terms() {
        for f in t.factors() {
            if f.as_number().is_some() {
                continue;
            }
            let (base, k) = split_power(f);
            if k <= 0 {
                return None;
            }
            if !atoms.contains(&base) {
                atoms.push(base);
            }
        }
    }
    atoms.sort();
    (!atoms.is_empty()).then_some(atoms)
}

/// A factor as an atom and its integer power (1 for anything else).
fn split_power(f: &Expr) -> (Expr, i64) {
    if let Node::Pow(base, exponent) = f.node() {
        if let Some(k) = exponent.as_number().and_then(Number::as_integer) {
            return (base.clone(), k);
        }
    }
    (f.clone(), 1)
}

/// `e` as a polynomial in `atoms`; `None` where an atom has a negative power.
fn polynomial(e: &Expr, atoms: &[Expr]) -> Option<Polynomial> {
    let mut out = Polynomial::new();
    for t in e.terms() {
        let mut exponents = vec![0; atoms.len()];
        let mut rest = Vec::new();
        for f in t.factors() {
            let (base, k) = split_power(f);
            match atoms.iter().position(|a| *a == base) {
                Some(i) if k > 0 => exponents[i] += k,
                Some(_) => return None,
                None => rest.push(f.clone()),
            }
        }
        let coefficient = mul(rest);
        let sum = add([
            out.remove(&exponents).unwrap_or_else(Expr::zero),
            coefficient,
        ]);
        if !sum.is_zero() {
            out.insert(exponents, sum);
        }
    }
    Some(out)
}

/// The atoms to the powers `exponents`.
fn monomial(atoms: &[Expr], exponents: &[i64]) -> Vec<Expr> {
    atoms
        .iter()
        .zip(exponents)
        .filter(|(_, &k)| k > 0)
        .map(|(a, &k)| pow(a.clone(), Expr::int(k)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(name: &str) -> Expr {
        Expr::constant(name)
    }

    #[test]
    fn a_sum_cancels_against_its_own_powers() {
        let s = c("a") + c("b");
        let sin = crate::symbolic::build::func(
            crate::symbolic::expr::Func::Sin,
            vec![Expr::sym(crate::symbolic::Symbol::Coord("q".into(), 0))],
        );
        assert_eq!(cancel_sums(&(s.clone() / s.clone())), Expr::one());
        let squared = pow(s.clone(), Expr::int(2));
        let e = &(&squared * &sin) * &pow(s.clone(), Expr::int(-2));
        assert_eq!(cancel_sums(&e), sin);
        // (x² − y²)/(x + y) = x − y; x²/(x + y) stays.
        let (x, y) = (c("x"), c("y"));
        let e = (&x * &x - &y * &y) / (&x + &y);
        assert_eq!(cancel_sums(&e), &x - &y);
        let e = (&x * &x) / (&x + &y);
        assert_eq!(cancel_sums(&e), e);
        // A shared factor and a sign leave the denominator: x y / (−x y − x²) = −y / (x + y).
        let e = (&x * &y) / (-(&x * &y) - &x * &x);
        assert_eq!(cancel_sums(&e), -(y.clone() / (&x + &y)));
        // Terms over different powers of one sum: x/(x + y) + y/(x + y)² · (x + y) = 1.
        let s = &x + &y;
        let e = &(&x / &s) + &(&(&y * &y + &x * &y) * &pow(s.clone(), Expr::int(-2)));
        assert_eq!(cancel_sums(&e), Expr::one());
    }
}
