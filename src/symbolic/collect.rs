//! An equation as a textbook writes it: its terms collected by the second derivatives
//! (`(…) q̈₁ + (…) q̈₂`), then by the reactions, then by the products of rates
//! (`(…) q̇₁²`), then what is left, each coefficient with its common factor pulled out
//! (`−L₂ m₂ (L₂/3 + L₁ c₂/2) q̈₁`). Display only: the canonical form, which decides
//! equality, is a plain sum of monomials.

use super::build::{add, mul};
use super::collect_constants::sum_tex;
pub use super::collect_constants::{common_factor_out, factored, sum_times};
use super::expr::{Expr, Node, Symbol};
pub use super::factor::pull_common_factor;
use super::factor::{multiple_of, push_signed, signed_term, square_root_of_sum, square_tex};
use super::number::Number;
use super::print::{latex, list_by_runs};

/// What a factor of a term is collected by, in the order the groups are printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Kind {
    Acceleration,
    Reaction,
    Rate,
    /// A coordinate or a function of coordinates (`x₁`, `c₁`, a spring's `ℓ₁`).
    Position,
}

/// The kind of `factor`, or `None` for a constant (part of every coefficient).
fn kind(factor: &Expr) -> Option<Kind> {
    let base = match factor.node() {
        Node::Pow(base, exponent) if exponent.as_number().is_some() => base,
        _ => factor,
    };
    match base.node() {
        Node::Sym(Symbol::Coord(_, 2) | Symbol::Speed(_, 1)) => Some(Kind::Acceleration),
        Node::Sym(Symbol::Speed(_, _)) => Some(Kind::Rate),
        Node::Sym(Symbol::Unknown(_)) => Some(Kind::Reaction),
        Node::Sym(Symbol::Coord(_, 1)) => Some(Kind::Rate),
        Node::Sym(Symbol::Coord(_, _)) => Some(Kind::Position),
        _ if base.any_symbol(&|x| matches!(x, Symbol::Coord(_, 2) | Symbol::Speed(_, 1))) => None,
        _ if base.any_symbol(&|x| matches!(x, Symbol::Coord(_, 1) | Symbol::Speed(_, 0))) => {
            Some(Kind::Rate)
        }
        _ if base.any_symbol(&|x| matches!(x, Symbol::Coord(_, 0) | Symbol::Time)) => {
            Some(Kind::Position)
        }
        _ => None,
    }
}

/// `e` (a canonical sum) in LaTeX with its terms collected (see the module documentation).
pub fn latex_collected(e: &Expr) -> String {
    let e = &rate_sums_inlined(e);
    // Groups keyed by the product of the factors collected by, in order of first use.
    let mut groups: Vec<(Option<Kind>, Expr, Vec<Expr>)> = Vec::new();
    for term in e.terms() {
        // Collected by the factors of its first kind; the others join the coefficient.
        let first = term.factors().iter().filter_map(kind).min();
        let (mut key, mut rest) = (Vec::new(), Vec::new());
        for f in term.factors() {
            if first.is_some() && kind(f) == first {
                key.push(f.clone());
            } else {
                rest.push(f.clone());
            }
        }
        let key = mul(key);
        let coefficient = mul(rest);
        match groups.iter_mut().find(|(_, k, _)| *k == key) {
            Some((_, _, items)) => items.push(coefficient),
            None => groups.push((first, key, vec![coefficient])),
        }
    }
    // What is collected by comes first, by kind, then in the canonical order of the keys;
    // what is left keeps its place at the end.
    groups.sort_by(|(a, x, _), (b, y, _)| match (a, b) {
        (Some(a), Some(b)) => a.cmp(b).then_with(|| x.cmp(y)),
        (Some(_), None) => std::cmp::Ordering::Less,
        (None, Some(_)) => std::cmp::Ordering::Greater,
        (None, None) => std::cmp::Ordering::Equal,
    });
    let mut out = String::new();
    let groups = proportional_rates(squares_of_rates(sharing_coefficients(groups)));
    for (kind, keys, coefficients, square) in &groups {
        if kind.is_none() {
            // Constants: their sum, with its common factor out.
            let constant = add(coefficients.iter().cloned());
            let (common, inner) = pull_common_factor(&constant);
            if constant.terms().len() == 1 || common.as_number().is_some() {
                push_signed(&mut out, latex(&constant));
            } else {
                push_signed(&mut out, factored(&common, &inner, ""));
            }
            continue;
        }
        let coefficient = add(coefficients.iter().cloned());
        if coefficient.is_zero() {
            continue;
        }
        // Keyed by a coordinate it divides by (1/y, s₁c₃/Δ): one fraction of the whole,
        // `\frac{a d g m s_{1} c_{3}}{2 Δ}`, not a fraction times a fraction or a trailing
        // `\frac{1}{y}`.
        let key_factors: Vec<Expr> = keys.iter().flat_map(|k| k.factors().to_vec()).collect();
        let divisor = |f: &Expr| super::collect_constants::is_divisor(f);
        let divides = square.is_none()
            && (key_factors.iter().all(divisor)
                || (coefficient.terms().len() == 1 && key_factors.iter().any(divisor)));
        // Where it divides, the whole key joins the coefficient as one fraction.
        let (divisor_part, key_text) = if divides {
            (mul(keys.iter().cloned()), String::new())
        } else {
            let key = square.as_ref().map_or_else(|| keys_tex(keys), square_tex);
            (Expr::one(), key)
        };
        let text = if coefficient.terms().len() == 1 {
            let whole = mul([coefficient.clone(), divisor_part]);
            signed_term(&whole, &key_text).trim_end().to_string()
        } else {
            let (common, inner) = pull_common_factor(&coefficient);
            factored(&mul([common, divisor_part]), &inner, &key_text)
        };
        push_signed(&mut out, text);
    }
    if out.is_empty() {
        "0".into()
    } else {
        out
    }
}

/// Whether `d` is a sum of rates kept whole only to keep expressions small (ω = q̇₁ + q̇₂),
/// printed as its value.
fn is_hidden_rate_sum(d: &super::expr::Definition) -> bool {
    !d.is_named()
        && d.value().terms().len() > 1
        && !d.value().any_symbol(&|s| {
            !matches!(
                s,
                Symbol::Coord(_, 1) | Symbol::Speed(_, 0) | Symbol::Const(_)
            )
        })
}

/// `e` with its hidden sums of rates written out, when that makes no more terms:
/// −k q̇₁² + k (q̇₁ + q̇₂)² is k (2 q̇₁ q̇₂ + q̇₂²), as a textbook simplifies it.
fn rate_sums_inlined(e: &Expr) -> Expr {
    let hidden = |s: &Symbol| matches!(s, Symbol::Defined(d) if is_hidden_rate_sum(d));
    if !e.any_symbol(&hidden) {
        return e.clone();
    }
    let inlined = super::simplify::simplify(&super::subst::substitute(e, &|s| match s {
        Symbol::Defined(d) if is_hidden_rate_sum(d) => Some(d.value().clone()),
        _ => None,
    }));
    if inlined.terms().len() <= e.terms().len() {
        inlined
    } else {
        e.clone()
    }
}

/// The groups of rates whose coefficients are one coefficient times numbers merged into
/// the first of them as that coefficient times their weighted sum: k q̇₁ q̇₂ + 2k q̇₂² →
/// k (q̇₁ q̇₂ + 2 q̇₂²).
fn proportional_rates(groups: Vec<Squared>) -> Vec<Squared> {
    let single_rate = |(kind, keys, _, square): &Squared| {
        *kind == Some(Kind::Rate) && keys.len() == 1 && square.is_none()
    };
    let totals: Vec<Expr> = groups
        .iter()
        .map(|(_, _, coefficients, _)| add(coefficients.iter().cloned()))
        .collect();
    let mut weights: Vec<Option<(usize, Number)>> = vec![None; groups.len()];
    for i in 0..groups.len() {
        if !single_rate(&groups[i]) || weights[i].is_some() || totals[i].is_zero() {
            continue;
        }
        for j in i + 1..groups.len() {
            if weights[j].is_none() && single_rate(&groups[j]) {
                if let Some(r) = multiple_of(&totals[j], &totals[i]) {
                    weights[j] = Some((i, r));
                }
            }
        }
    }
    let mut out: Vec<Squared> = Vec::new();
    let mut place = vec![usize::MAX; groups.len()];
    for (i, group) in groups.into_iter().enumerate() {
        match weights[i] {
            Some((first, r)) => {
                let (_, keys, _, _) = &mut out[place[first]];
                keys[0] = add([keys[0].clone(), mul([Expr::num(r), group.1[0].clone()])]);
            }
            None => {
                place[i] = out.len();
                out.push(group);
            }
        }
    }
    out
}

/// `e` (a canonical sum) in LaTeX as it is, but for the terms whose rates make the square
/// of a sum, written as that square after the others: (L s/2) q̇_A² + (L s/2) q̇_C² +
/// L s q̇_A q̇_C → (L s/2)(q̇_A + q̇_C)². For a definition, which keeps its terms' order
/// rather than being collected (see [`latex_collected`]).
pub fn latex_with_squares(e: &Expr) -> String {
    // Each term as its rates and the rest; a term without rates takes no part.
    let items: Vec<Option<(Expr, Expr)>> = e
        .terms()
        .iter()
        .map(|t| {
            let (rates, rest): (Vec<Expr>, Vec<Expr>) = t
                .factors()
                .iter()
                .cloned()
                .partition(|f| kind(f) == Some(Kind::Rate));
            let rates = mul(rates);
            (!rates.is_one()).then(|| (rates, mul(rest)))
        })
        .collect();
    let found = squares(&items);
    if found.is_empty() {
        return sum_tex(e);
    }
    let mut used = vec![false; items.len()];
    let mut squared = String::new();
    for (members, root) in &found {
        members.iter().for_each(|&j| used[j] = true);
        if let Some((_, coefficient)) = &items[members[0]] {
            push_signed(&mut squared, signed_term(coefficient, &square_tex(root)));
        }
    }
    let others = add(e
        .terms()
        .iter()
        .zip(&used)
        .filter(|(_, used)| !**used)
        .map(|(t, _)| t.clone()));
    let mut out = if others.is_zero() {
        String::new()
    } else {
        sum_tex(&others)
    };
    push_signed(&mut out, squared);
    out
}

/// Among `items` (each a product of rates and its coefficient, or `None` to leave out), the
/// runs whose coefficients are the first one's times numbers that, as weights of their
/// rates, make the square of a sum: k q̇₁², k q̇₂², 2k q̇₁ q̇₂. Each as its items' indices,
/// the first one's first, and the sum squared.
fn squares(items: &[Option<(Expr, Expr)>]) -> Vec<(Vec<usize>, Expr)> {
    let mut used = vec![false; items.len()];
    let mut out = Vec::new();
    for (i, item) in items.iter().enumerate() {
        let Some((_, base)) = item.as_ref().filter(|(_, c)| !used[i] && !c.is_zero()) else {
            continue;
        };
        let members: Vec<(usize, Number)> = (i..items.len())
            .filter(|&j| !used[j])
            .filter_map(|j| {
                let (_, coefficient) = items[j].as_ref()?;
                multiple_of(coefficient, base).map(|r| (j, r))
            })
            .collect();
        if members.len() < 3 {
            continue;
        }
        let weighted = add(members.iter().filter_map(|&(j, r)| {
            let (rates, _) = items[j].as_ref()?;
            Some(mul([Expr::num(r), rates.clone()]))
        }));
        if let Some(root) = square_root_of_sum(&weighted) {
            members.iter().for_each(|&(j, _)| used[j] = true);
            out.push((members.into_iter().map(|(j, _)| j).collect(), root));
        }
    }
    out
}

/// A group to print: what it is collected by, its keys (more than one when they share a
/// coefficient) and the terms of that coefficient.
type Shared = (Option<Kind>, Vec<Expr>, Vec<Expr>);

/// The groups with second derivatives of the same coefficient merged into the first of
/// them, as a textbook writes −(L²m/12)(q̈₁ + ⋯ + q̈₁₀) rather than ten terms.
fn sharing_coefficients(groups: Vec<(Option<Kind>, Expr, Vec<Expr>)>) -> Vec<Shared> {
    let mut out: Vec<(Shared, Expr)> = Vec::new();
    for (kind, key, coefficients) in groups {
        let total = add(coefficients.iter().cloned());
        let merged = (kind == Some(Kind::Acceleration) && !total.is_zero())
            .then(|| {
                out.iter_mut()
                    .find(|((k, _, _), t)| *k == kind && *t == total)
            })
            .flatten();
        match merged {
            Some(((_, keys, _), _)) => keys.push(key),
            None => out.push(((kind, vec![key], coefficients), total)),
        }
    }
    out.into_iter().map(|(group, _)| group).collect()
}

/// A group to print, with the sum whose square it is collected by, when it is one.
type Squared = (Option<Kind>, Vec<Expr>, Vec<Expr>, Option<Expr>);

/// The groups of rates whose coefficients are one coefficient times numbers that make the
/// square of a sum merged into one: k q̇₁² + k q̇₂² + 2k q̇₁ q̇₂ → k (q̇₁ + q̇₂)², as a
/// textbook writes the speed of two rates that always turn together.
fn squares_of_rates(groups: Vec<Shared>) -> Vec<Squared> {
    let items: Vec<Option<(Expr, Expr)>> = groups
        .iter()
        .map(|(kind, keys, coefficients)| match keys.as_slice() {
            [key] if *kind == Some(Kind::Rate) => {
                Some((key.clone(), add(coefficients.iter().cloned())))
            }
            _ => None,
        })
        .collect();
    let mut roots: Vec<Option<Expr>> = vec![None; groups.len()];
    let mut merged = vec![false; groups.len()];
    for (members, root) in squares(&items) {
        members.iter().skip(1).for_each(|&j| merged[j] = true);
        roots[members[0]] = Some(root);
    }
    groups
        .into_iter()
        .zip(roots)
        .zip(merged)
        .filter(|(_, merged)| !merged)
        .map(|(((kind, keys, coefficients), root), _)| (kind, keys, coefficients, root))
        .collect()
}

/// One key as it is, several as their sum in parentheses, a run by its ends.
fn keys_tex(keys: &[Expr]) -> String {
    match keys {
        [key] if key.terms().len() > 1 => format!("\\left({}\\right)", latex(key)),
        [key] => latex(key),
        _ => {
            let items: Vec<String> = keys.iter().map(latex).collect();
            format!("\\left({}\\right)", list_by_runs(&items, " + ", "\\cdots"))
        }
    }
}

/// A sum with the factor all its terms share pulled out, `\frac{L^{2} m}{2} (3 s_{2} + s_{23})`,
/// when that is shorter; otherwise as it is.
pub fn latex_factored(e: &Expr) -> String {
    let whole = latex(e);
    match common_factor_out(e, "") {
        Some(text) if text.len() < whole.len() => text,
        _ => whole,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::build::{cos, sin};

    fn c(name: &str) -> Expr {
        Expr::constant(name)
    }

    #[test]
    fn terms_are_collected_by_accelerations_then_rates_with_common_factors_out() {
        let (l1, l2, m2, g) = (c("L1"), c("L2"), c("m2"), c("g"));
        let q2 = Expr::coord("q2", 0);
        let a1 = Expr::coord("q1", 2);
        let w1 = Expr::coord("q1", 1);
        // −L₂²m₂/3 q̈₁ − L₁L₂m₂ cos q₂ q̈₁/2 − L₁L₂m₂ sin q₂ q̇₁²/2 − m₂ g sin q₂ (mass before g)
        let e = add([
            &(&(&l2 * &l2) * &m2) * &(&a1 * &Expr::ratio(-1, 3)),
            &(&(&(&l1 * &l2) * &m2) * &cos(q2.clone())) * &(&a1 * &Expr::ratio(-1, 2)),
            &(&(&(&l1 * &l2) * &m2) * &sin(q2.clone())) * &(&(&w1 * &w1) * &Expr::ratio(-1, 2)),
            &(&g * &m2) * &(&sin(q2.clone()) * &Expr::int(-1)),
        ]);
        assert_eq!(
            latex_collected(&e),
            "-\\frac{L_{2} m_{2}}{6} \\left(2 L_{2} + 3 L_{1} \\cos(q_{2})\\right) \\ddot{q}_{1} - \\frac{L_{1} L_{2} m_{2} \\sin(q_{2})}{2} \\dot{q}_{1}^{2} - m_{2} g \\sin(q_{2})"
        );
    }

    #[test]
    fn rates_that_make_a_square_are_written_as_the_square_of_their_sum() {
        let (l, m) = (c("L"), c("m"));
        let q = Expr::coord("q3", 0);
        let (w1, w2, w3) = (
            Expr::coord("q1", 1),
            Expr::coord("q2", 1),
            Expr::coord("q3", 1),
        );
        // L m cos q₃ (q̇₁² + q̇₂² − 2 q̇₁ q̇₂) + L q̇₃²: the first three are L m cos q₃ (q̇₁ − q̇₂)².
        let k = &(&l * &m) * &cos(q.clone());
        let e = add([
            &k * &(&w1 * &w1),
            &k * &(&w2 * &w2),
            &(&k * &Expr::int(-2)) * &(&w1 * &w2),
            &l * &(&w3 * &w3),
        ]);
        assert_eq!(
            latex_collected(&e),
            "L m \\cos(q_{3}) \\left(\\dot{q}_{1} - \\dot{q}_{2}\\right)^{2} + L \\dot{q}_{3}^{2}"
        );
        // A sum that is not a square stays as it is: q̇₁² + q̇₂² + q̇₁ q̇₂.
        let not = add([&w1 * &w1, &w2 * &w2, &w1 * &w2]);
        assert_eq!(square_root_of_sum(&not), None);
        // Inside a factored coefficient too: m/2 (q̇₁² + 2 q̇₁ q̇₂ + q̇₂²) → m/2 (q̇₁ + q̇₂)².
        let square = add([&w1 * &w1, &w2 * &w2, &(&w1 * &w2) * &Expr::int(2)]);
        assert_eq!(square_root_of_sum(&square), Some(&w1 + &w2));
        assert_eq!(
            factored(&(&m * &Expr::ratio(1, 2)), &square, ""),
            "\\frac{m}{2} \\left(\\dot{q}_{1} + \\dot{q}_{2}\\right)^{2}"
        );
    }

    #[test]
    fn a_definition_keeps_its_terms_but_writes_a_square_of_rates_as_one() {
        let (l, a) = (c("L"), c("a"));
        let (w1, w2, w3) = (
            Expr::coord("q1", 1),
            Expr::coord("q2", 1),
            Expr::coord("q3", 1),
        );
        // a + L q̇₃ + (L/2) q̇₁² + (L/2) q̇₂² + L q̇₁ q̇₂ = a + L q̇₃ + (L/2)(q̇₁ + q̇₂)².
        let half = &l * &Expr::ratio(1, 2);
        let e = add([
            a.clone(),
            &l * &w3,
            &half * &(&w1 * &w1),
            &half * &(&w2 * &w2),
            &l * &(&w1 * &w2),
        ]);
        assert_eq!(
            latex_with_squares(&e),
            format!(
                "{} + \\frac{{L}}{{2}} \\left(\\dot{{q}}_{{1}} + \\dot{{q}}_{{2}}\\right)^{{2}}",
                latex(&add([a.clone(), &l * &w3]))
            )
        );
        // Nothing to square: as `latex` writes it.
        let plain = add([a.clone(), &l * &(&w1 * &w2)]);
        assert_eq!(latex_with_squares(&plain), latex(&plain));
    }

    #[test]
    fn a_shared_fraction_is_pulled_out_with_the_factors() {
        let (a, b, m) = (c("a"), c("b"), c("m"));
        let sum = &(&(&a * &m) * &Expr::ratio(1, 4)) + &(&(&b * &m) * &Expr::ratio(3, 4));
        let (common, inner) = pull_common_factor(&sum);
        assert_eq!(common, &m * &Expr::ratio(1, 4));
        assert_eq!(inner, &a + &(&b * &Expr::int(3)));
    }

    #[test]
    fn a_divisor_of_every_term_is_pulled_out() {
        // r a/σ + r b/σ² = (r/σ)(a + b/σ); a divisor of only some terms stays inside.
        let (a, b, r, sigma) = (c("a"), c("b"), c("r"), c("sigma"));
        let over = |n: i64| crate::symbolic::build::pow(sigma.clone(), Expr::int(-n));
        let sum = &(&(&r * &a) * &over(1)) + &(&(&r * &b) * &over(2));
        let (common, inner) = pull_common_factor(&sum);
        assert_eq!(common, &r * &over(1));
        assert_eq!(inner, &a + &(&b * &over(1)));
        let (common, _) = pull_common_factor(&(&(&(&r * &a) * &over(1)) + &(&r * &b)));
        assert_eq!(common, r);
    }
}
