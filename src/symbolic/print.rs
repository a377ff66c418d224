//! Printing expressions as plain text (the input grammar) and as textbook LaTeX.

use super::expr::{Expr, Func, Node, Symbol};
use super::number::Number;
use super::style::abbreviation;
pub use super::tex_name::{latex_name, latex_name_of};
use std::ops::Neg;

/// Plain text in the grammar of the problem format, e.g. `-m*L^2*sin(q1)/12`.
pub fn plain(e: &Expr) -> String {
    Printer { latex: false }.sum(e)
}

/// LaTeX as a textbook writes it: `\ddot{q}_{1}`, `\frac{m L^{2}}{12}`, no `*` signs.
pub fn latex(e: &Expr) -> String {
    Printer { latex: true }.sum(e)
}

/// A unit vector as a bold hat over one letter: `\hat{\mathbf{a}}_{x}`, `\hat{\mathbf{b}}_{1,x}` (frame B1),
/// `\hat{\mathbf{x}}_{\mathrm{wedge}}`.
pub fn latex_unit_vector(frame: &str, axis: u8) -> String {
    let axis = ["x", "y", "z"].get(axis as usize).copied().unwrap_or("?");
    let name = latex_name(&frame.to_lowercase());
    // The hat sits over one letter only, as textbooks print it: the frame's letter (`a_x`,
    // `b_{1,x}` for B1), or, for a frame named by a word, the axis with the word below
    // (`x_wedge`).
    match name.split_once("_{") {
        _ if name.chars().count() == 1 => format!("\\hat{{\\mathbf{{{name}}}}}_{{{axis}}}"),
        Some((stem, index)) if stem.chars().count() == 1 => {
            let index = index.trim_end_matches('}');
            format!("\\hat{{\\mathbf{{{stem}}}}}_{{{index},{axis}}}")
        }
        _ => format!("\\hat{{\\mathbf{{{axis}}}}}_{{{name}}}"),
    }
}

fn latex_symbol(s: &Symbol) -> String {
    match s {
        Symbol::Const(name) => latex_name(name),
        Symbol::Coord(name, order) => {
            let base = latex_name(name);
            let (stem, sub) = match base.split_once('_') {
                Some((stem, sub)) => (stem.to_string(), format!("_{sub}")),
                None => (base.clone(), String::new()),
            };
            match order {
                0 => base,
                1 => format!("\\dot{{{stem}}}{sub}"),
                _ => format!("\\ddot{{{stem}}}{sub}"),
            }
        }
        Symbol::Time => "t".into(),
        Symbol::Speed(name, 0) => latex_name(name),
        Symbol::Speed(name, _) => {
            let base = latex_name(name);
            match base.split_once('_') {
                Some((stem, sub)) => format!("\\dot{{{stem}}}_{sub}"),
                None => format!("\\dot{{{base}}}"),
            }
        }
        Symbol::Unknown(unknown) => unknown.latex(),
        Symbol::UnitVector(frame, axis) => latex_unit_vector(frame, *axis),
        Symbol::Defined(d) => match d.latex() {
            Some(name) => name.to_string(),
            None => format!(
                "\\left({}\\right)",
                Printer { latex: true }.sum_positive_first(d.value())
            ),
        },
    }
}

fn plain_symbol(s: &Symbol) -> String {
    match s {
        Symbol::Const(name) => name.to_string(),
        Symbol::Unknown(unknown) => unknown.to_string(),
        Symbol::Coord(name, order) | Symbol::Speed(name, order) => {
            format!("{name}{}", "'".repeat(*order as usize))
        }
        Symbol::Time => "t".into(),
        Symbol::UnitVector(frame, axis) => {
            format!("{frame}.{}", ["x", "y", "z"][(*axis as usize).min(2)])
        }
        Symbol::Defined(d) if d.is_named() => d.name().to_string(),
        Symbol::Defined(d) => format!(
            "({})",
            Printer { latex: false }.sum_positive_first(d.value())
        ),
    }
}

/// The argument of a function as LaTeX prints it: `(q_{1})`, `\left(q_{1} + q_{2}\right)`.
pub(crate) fn latex_argument(arg: &Expr) -> String {
    Printer { latex: true }.argument(arg)
}

/// A term as LaTeX prints it, from its coefficient (not negative) and the rest.
pub(crate) fn latex_term(coefficient: Number, rest: &Expr) -> String {
    Printer { latex: true }.product(coefficient, rest)
}

struct Printer {
    latex: bool,
}

/// Whether `e` is a mass, `m`, `M`, `m_A`, or a sum of masses with numbers (`m_1 + 2 m_2`).
fn is_mass(e: &Expr) -> bool {
    match e.node() {
        Node::Sym(Symbol::Const(name)) => {
            let tex = latex_name(name);
            ["m", "M"].contains(&tex.as_str()) || tex.starts_with("m_{") || tex.starts_with("M_{")
        }
        Node::Add(terms) => terms.iter().all(|t| {
            let (_, rest) = t.split_coefficient();
            !rest.is_one() && rest.factors().iter().all(is_mass)
        }),
        _ => false,
    }
}

/// The factors of a product in the order a textbook writes them: gravity's `g` after the
/// masses it multiplies (`m g L`, `(m_1 + m_2) g`), the others as they are.
fn mass_before_gravity(factors: &[Expr]) -> Vec<Expr> {
    let mut out = factors.to_vec();
    let is_g = |e: &Expr| matches!(e.node(), Node::Sym(Symbol::Const(name)) if &**name == "g");
    let Some(g) = out.iter().position(is_g) else {
        return out;
    };
    if let Some(last) = out.iter().rposition(is_mass).filter(|&m| m > g) {
        let g = out.remove(g);
        out.insert(last, g);
    }
    out
}

impl Printer {
    fn sum(&self, e: &Expr) -> String {
        self.terms(e.terms())
    }

    /// A sum with a positive term first when it has one: `ℓ₁ - l₁`, not `-l₁ + ℓ₁`.
    fn sum_positive_first(&self, e: &Expr) -> String {
        let terms = e.terms();
        let negative = |t: &Expr| t.split_coefficient().0.is_negative();
        match terms.iter().position(|t| !negative(t)) {
            Some(first) if first > 0 => {
                let mut reordered = vec![terms[first].clone()];
                reordered.extend(
                    terms
                        .iter()
                        .enumerate()
                        .filter(|(i, _)| *i != first)
                        .map(|(_, t)| t.clone()),
                );
                self.terms(&reordered)
            }
            _ => self.terms(terms),
        }
    }

    fn terms(&self, terms: &[Expr]) -> String {
        let signed: Vec<(bool, String)> = terms
            .iter()
            .map(|term| {
                let (coefficient, rest) = term.split_coefficient();
                let negative = coefficient.is_negative();
                let magnitude = if negative {
                    coefficient.neg()
                } else {
                    coefficient
                };
                (negative, self.product(magnitude, &rest))
            })
            .collect();
        let mut out = String::new();
        let mut i = 0;
        while i < signed.len() {
            let (negative, body) = &signed[i];
            match (i, negative) {
                (0, true) => out.push('-'),
                (0, false) => {}
                (_, true) => out.push_str(" - "),
                (_, false) => out.push_str(" + "),
            }
            out.push_str(body);
            let run = if self.latex {
                // Only added terms make a run.
                indexed_run(
                    signed[i..]
                        .iter()
                        .map(|(negative, body)| (!negative).then_some(body.as_str())),
                )
            } else {
                1
            };
            if run > 1 {
                out.push_str(" + \\cdots + ");
                out.push_str(&signed[i + run - 1].1);
            }
            i += run;
        }
        out
    }

    /// A product with a non-negative coefficient.
    fn product(&self, coefficient: Number, rest: &Expr) -> String {
        let mut numerator: Vec<String> = Vec::new();
        let mut denominator: Vec<String> = Vec::new();
        let (mut coefficient_num, mut coefficient_den) = (String::new(), String::new());
        match coefficient {
            Number::Ratio(n, d)
                if self.latex && d != 1 && super::style::decimal(n, d).is_some() =>
            {
                coefficient_num = super::style::decimal(n, d).unwrap_or_default();
            }
            Number::Ratio(n, d) => {
                if n != 1 || rest.is_one() {
                    coefficient_num = n.to_string();
                }
                if d != 1 {
                    coefficient_den = d.to_string();
                }
            }
            Number::Real(x) => {
                if x != 1.0 || rest.is_one() {
                    coefficient_num = Number::Real(x).to_string();
                }
            }
        }
        if !rest.is_one() {
            let factors = match self.latex {
                true => mass_before_gravity(rest.factors()),
                false => rest.factors().to_vec(),
            };
            for factor in &factors {
                match factor.node() {
                    Node::Pow(base, exponent)
                        if exponent.as_number().is_some_and(Number::is_negative) =>
                    {
                        let positive = exponent.as_number().map(Number::neg).unwrap_or(Number::ONE);
                        denominator.push(self.power(base, &Expr::num(positive)));
                    }
                    _ => numerator.push(self.factor(factor)),
                }
            }
        }
        if !coefficient_num.is_empty() {
            numerator.insert(0, coefficient_num);
        }
        if !coefficient_den.is_empty() {
            denominator.insert(0, coefficient_den);
        }
        let join = if self.latex { " " } else { "*" };
        let top = if numerator.is_empty() {
            "1".to_string()
        } else {
            numerator.join(join)
        };
        if denominator.is_empty() {
            return top;
        }
        if self.latex {
            format!("\\frac{{{top}}}{{{}}}", denominator.join(" "))
        } else {
            let bottom = if denominator.len() > 1 {
                format!("({})", denominator.join("*"))
            } else {
                denominator.join("")
            };
            format!("{top}/{bottom}")
        }
    }

    fn factor(&self, e: &Expr) -> String {
        match e.node() {
            Node::Pow(base, exponent) => self.power(base, exponent),
            Node::Add(_) => self.parens(&self.sum(e)),
            _ => self.atom(e),
        }
    }

    fn power(&self, base: &Expr, exponent: &Expr) -> String {
        let half = exponent.as_number() == Some(Number::Ratio(1, 2));
        if half {
            return if self.latex {
                format!("\\sqrt{{{}}}", self.sum(base))
            } else {
                format!("sqrt({})", self.sum(base))
            };
        }
        if exponent.is_one() {
            return self.factor(base);
        }
        let base_text = match base.node() {
            Node::Sym(_) => self.atom(base),
            Node::Num(n) if !n.is_negative() && matches!(n, Number::Ratio(_, 1)) => self.atom(base),
            Node::Func(..) if self.latex => self.atom(base),
            _ => self.parens(&self.sum(base)),
        };
        let exponent_text = self.sum(exponent);
        if self.latex {
            if let Node::Func(f, args) = base.node() {
                if let Some(name) = abbreviation(*f, &args[0], latex_argument) {
                    return format!("{}^{{{exponent_text}}}", grouped_for_power(&name));
                }
                if matches!(f, Func::Sin | Func::Cos | Func::Tan) {
                    return format!(
                        "\\{}^{{{exponent_text}}}{}",
                        f.name(),
                        self.argument(&args[0])
                    );
                }
            }
            format!("{}^{{{exponent_text}}}", grouped_for_power(&base_text))
        } else if exponent
            .as_number()
            .is_some_and(|n| !n.is_negative() && matches!(n, Number::Ratio(_, 1)))
        {
            format!("{base_text}^{exponent_text}")
        } else {
            format!("{base_text}^({exponent_text})")
        }
    }

    fn parens(&self, inner: &str) -> String {
        if self.latex {
            format!("\\left({inner}\\right)")
        } else {
            format!("({inner})")
        }
    }

    fn argument(&self, arg: &Expr) -> String {
        if matches!(arg.node(), Node::Sym(Symbol::Defined(d)) if !d.is_named()) {
            self.atom(arg)
        } else if self.latex && matches!(arg.node(), Node::Sym(_)) {
            format!("({})", self.atom(arg))
        } else {
            self.parens(&self.sum(arg))
        }
    }

    fn atom(&self, e: &Expr) -> String {
        match e.node() {
            Node::Num(Number::Ratio(n, d)) if self.latex && *d != 1 => {
                match super::style::decimal(*n, *d) {
                    Some(text) if *n < 0 => format!("-{text}"),
                    Some(text) => text,
                    None => Number::Ratio(*n, *d).to_string(),
                }
            }
            Node::Num(n) => n.to_string(),
            Node::Sym(s) if self.latex => latex_symbol(s),
            Node::Sym(s) => plain_symbol(s),
            Node::Func(f, args) => self.call(*f, args),
            _ => self.parens(&self.sum(e)),
        }
    }

    fn call(&self, f: Func, args: &[Expr]) -> String {
        if !self.latex {
            let inner: Vec<String> = args.iter().map(|a| self.sum(a)).collect();
            return format!("{}({})", f.name(), inner.join(", "));
        }
        if let Some(name) = abbreviation(f, &args[0], latex_argument) {
            return name;
        }
        let inner: Vec<String> = args.iter().map(|a| self.sum(a)).collect();
        match f {
            Func::Sin | Func::Cos | Func::Tan | Func::Exp | Func::Ln => {
                format!("\\{}{}", f.name(), self.argument(&args[0]))
            }
            Func::Asin => format!("\\arcsin{}", self.argument(&args[0])),
            Func::Acos => format!("\\arccos{}", self.argument(&args[0])),
            Func::Atan => format!("\\arctan{}", self.argument(&args[0])),
            Func::Sqrt => format!("\\sqrt{{{}}}", inner[0]),
            Func::Abs => format!("\\left|{}\\right|", inner[0]),
            Func::Min | Func::Max => format!("\\{}\\left({}\\right)", f.name(), inner.join(", ")),
            Func::Atan2 | Func::Sign => format!(
                "\\operatorname{{{}}}\\left({}\\right)",
                f.name(),
                inner.join(", ")
            ),
        }
    }
}

/// How many items from the first are one symbol with consecutive indices
/// (`\\dot{q}_{1}`, `\\dot{q}_{2}`, …) when at least four; else 1 (`None` is no symbol). A
/// textbook writes such a run by its ends: q̇₁ + ⋯ + q̇₉, {link₂, …, link₁₀}.
pub(crate) fn indexed_run<'a>(items: impl IntoIterator<Item = Option<&'a str>>) -> usize {
    const SHORTEST_RUN: usize = 4;
    fn indexed(text: &str) -> Option<(&str, u64)> {
        let (stem, index) = text.rsplit_once("_{")?;
        let index: u64 = index.strip_suffix('}')?.parse().ok()?;
        let one_symbol = !stem.contains(' ') && !stem.contains("\\frac");
        one_symbol.then_some((stem, index))
    }
    let mut items = items.into_iter();
    let Some((stem, first)) = items.next().flatten().and_then(indexed) else {
        return 1;
    };
    let length = 1 + items
        .zip(1u64..)
        .take_while(|(item, k)| {
            let expected = first.checked_add(*k).map(|index| (stem, index));
            expected.is_some() && item.and_then(indexed) == expected
        })
        .count();
    if length >= SHORTEST_RUN {
        length
    } else {
        1
    }
}

/// A list written with `separator`, each run of four or more consecutive indexed symbols by
/// its ends: `\\mathrm{link}_{2}, \\ldots, \\mathrm{link}_{10}`.
pub fn list_by_runs(items: &[String], separator: &str, ellipsis: &str) -> String {
    let mut out: Vec<&str> = Vec::new();
    let mut i = 0;
    while i < items.len() {
        let run = indexed_run(items[i..].iter().map(|s| Some(s.as_str())));
        out.push(&items[i]);
        if run > 1 {
            out.push(ellipsis);
            out.push(&items[i + run - 1]);
        }
        i += run;
    }
    out.join(separator)
}

/// A base that already carries a superscript, such as the named direction cosine
/// `{}^{N}C^{F}_{31}`, braced so that its power is not a second superscript (a LaTeX error).
fn grouped_for_power(base: &str) -> String {
    let mut depth = 0i32;
    let has_superscript = base.chars().any(|c| {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            _ => {}
        }
        c == '^' && depth == 0
    });
    if has_superscript {
        format!("{{{base}}}")
    } else {
        base.to_string()
    }
}

// The plain form is what an expression displays as (`{}`, `to_string`).
impl std::fmt::Display for Expr {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&plain(self))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::build::{cos, sin};

    #[test]
    fn latex_of_rates_and_names() {
        assert_eq!(latex(&Expr::coord("q1", 1)), "\\dot{q}_{1}");
        assert_eq!(latex(&Expr::coord("q1", 2)), "\\ddot{q}_{1}");
        assert_eq!(latex(&Expr::coord("theta", 2)), "\\ddot{\\theta}");
        assert_eq!(latex_name("theta2"), "\\theta_{2}");
        assert_eq!(latex_name("m_A"), "m_{A}");
        assert_eq!(latex_unit_vector("A", 0), "\\hat{\\mathbf{a}}_{x}");
        // The hat over one letter: the frame's, or the axis's under a word.
        assert_eq!(latex_unit_vector("B1", 0), "\\hat{\\mathbf{b}}_{1,x}");
        assert_eq!(
            latex_unit_vector("wedge", 1),
            "\\hat{\\mathbf{y}}_{\\mathrm{wedge}}"
        );
        assert_eq!(
            latex_unit_vector("link1", 2),
            "\\hat{\\mathbf{z}}_{\\mathrm{link}_{1}}"
        );
    }

    #[test]
    fn latex_of_products_and_fractions() {
        let m = Expr::constant("m");
        let l = Expr::constant("L");
        let e = &(&(&m * &l) * &l) / &Expr::int(12);
        assert_eq!(latex(&e), "\\frac{L^{2} m}{12}");
        assert_eq!(plain(&e), "L^2*m/12");
        let q = Expr::coord("q1", 0);
        assert_eq!(
            latex(&(-(sin(q.clone()) * Expr::coord("q1", 1)))),
            "-\\dot{q}_{1} \\sin(q_{1})"
        );
        assert_eq!(plain(&(cos(q.clone()) - Expr::one())), "-1 + cos(q1)");
    }

    #[test]
    fn a_run_of_four_or_more_indexed_rates_is_written_by_its_ends() {
        let rates = |range: std::ops::RangeInclusive<u32>| {
            crate::symbolic::build::add(range.map(|i| Expr::coord(&format!("q{i}"), 1)))
        };
        assert_eq!(
            latex(&rates(1..=3)),
            "\\dot{q}_{1} + \\dot{q}_{2} + \\dot{q}_{3}"
        );
        assert_eq!(
            latex(&rates(1..=10)),
            "\\dot{q}_{1} + \\cdots + \\dot{q}_{10}"
        );
        // A term with a coefficient, or a gap, ends the run.
        let gap = &rates(1..=4) + &Expr::coord("q6", 1);
        assert_eq!(
            latex(&gap),
            "\\dot{q}_{1} + \\cdots + \\dot{q}_{4} + \\dot{q}_{6}"
        );
        let scaled = &rates(1..=3) + &(&Expr::int(2) * &Expr::coord("q4", 1));
        assert!(!latex(&scaled).contains("cdots"));
        assert!(!plain(&rates(1..=10)).contains("cdots"));
    }

    #[test]
    fn a_power_of_a_name_with_a_superscript_is_braced() {
        let value = &(&Expr::constant("a") * &Expr::constant("b")) + &Expr::constant("c");
        let c = Expr::named("C_N_F_31", "{}^{N}C^{F}_{31}", "", value);
        let squared = crate::symbolic::build::pow(c, Expr::int(2));
        assert_eq!(latex(&squared), "{{}^{N}C^{F}_{31}}^{2}");
        let x = crate::symbolic::build::pow(Expr::constant("x"), Expr::int(2));
        assert_eq!(latex(&x), "x^{2}");
    }

    #[test]
    fn a_letter_and_one_more_is_a_subscripted_symbol() {
        assert_eq!(latex_name("Is"), "I_{s}");
        assert_eq!(latex_name("mT"), "m_{T}");
        assert_eq!(latex_name("tauL"), "\\tau_{L}");
        assert_eq!(latex_name("kp2"), "k_{p2}");
        assert_eq!(latex_name("qL"), "q_{L}");
        assert_eq!(latex_name("Ixy"), "I_{xy}");
        // Words, Greek letters and names with digits inside stay as they were.
        assert_eq!(latex_name("bob"), "\\mathrm{bob}");
        assert_eq!(latex_name("pin"), "\\mathrm{pin}");
        assert_eq!(latex_name("theta"), "\\theta");
        assert_eq!(latex_name("mu"), "\\mu");
        assert_eq!(latex_name("q12"), "q_{12}");
        assert_eq!(latex_name("L_p"), "L_{p}");
    }
}
