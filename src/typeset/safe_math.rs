//! The math a problem's text may hold between `$…$`, checked before it reaches TeX, a
//! browser or a Markdown renderer.
//!
//! Only a small, harmless part of LaTeX passes: letters, digits, operators, the commands
//! of `COMMANDS` (Greek letters, `\frac`, `\sqrt`, accents, functions, relations) and
//! balanced braces, and only if the MathML converter can also parse it, so that a span is
//! math in every format or text in every format. Anything else (`\input`, `\write18`,
//! `\def`, `#`, `%`, `&`, an unbalanced brace) makes the whole span plain text, which the
//! caller then escapes.

use super::command_name;
use super::mathml::{self, Display};

/// The commands allowed in a problem's math: nothing here reads, writes, defines or
/// changes catcodes; each one only sets a symbol or a layout.
const COMMANDS: &[&str] = &[
    // Greek letters.
    "alpha",
    "beta",
    "gamma",
    "delta",
    "epsilon",
    "varepsilon",
    "zeta",
    "eta",
    "theta",
    "vartheta",
    "iota",
    "kappa",
    "lambda",
    "mu",
    "nu",
    "xi",
    "pi",
    "varpi",
    "rho",
    "varrho",
    "sigma",
    "varsigma",
    "tau",
    "upsilon",
    "phi",
    "varphi",
    "chi",
    "psi",
    "omega",
    "Gamma",
    "Delta",
    "Theta",
    "Lambda",
    "Xi",
    "Pi",
    "Sigma",
    "Upsilon",
    "Phi",
    "Psi",
    "Omega",
    // Layout.
    "frac",
    "dfrac",
    "tfrac",
    "sqrt",
    "left",
    "right",
    "quad",
    "qquad",
    // Accents and alphabets.
    "dot",
    "ddot",
    "hat",
    "bar",
    "vec",
    "tilde",
    "mathbf",
    "mathrm",
    "mathit",
    "boldsymbol",
    "operatorname",
    // Functions.
    "sin",
    "cos",
    "tan",
    "cot",
    "sec",
    "csc",
    "arcsin",
    "arccos",
    "arctan",
    "sinh",
    "cosh",
    "tanh",
    "exp",
    "ln",
    "log",
    "max",
    "min",
    "lim",
    "sum",
    "int",
    "prod",
    // Operators, relations, symbols.
    "cdot",
    "times",
    "div",
    "pm",
    "mp",
    "le",
    "leq",
    "ge",
    "geq",
    "ne",
    "neq",
    "approx",
    "equiv",
    "sim",
    "propto",
    "to",
    "rightarrow",
    "leftarrow",
    "Rightarrow",
    "ldots",
    "cdots",
    "dots",
    "circ",
    "prime",
    "partial",
    "nabla",
    "infty",
    "ell",
    "perp",
    "parallel",
    "vert",
    "Vert",
    "langle",
    "rangle",
];

/// Characters after a backslash that stand for themselves or a space (`\{`, `\,`).
const ESCAPED: &str = ",;:! {}|";

/// ASCII characters other than letters and digits allowed as they are.
const PLAIN: &str = " +-*/=<>()[]|,.;:!?'^_{}";

/// Greek letters and a few signs typed as Unicode, and the commands they become.
const UNICODE: [(char, &str); 36] = [
    ('α', "\\alpha"),
    ('β', "\\beta"),
    ('γ', "\\gamma"),
    ('δ', "\\delta"),
    ('ε', "\\varepsilon"),
    ('ζ', "\\zeta"),
    ('η', "\\eta"),
    ('θ', "\\theta"),
    ('κ', "\\kappa"),
    ('λ', "\\lambda"),
    ('μ', "\\mu"),
    ('ν', "\\nu"),
    ('ξ', "\\xi"),
    ('π', "\\pi"),
    ('ρ', "\\rho"),
    ('σ', "\\sigma"),
    ('τ', "\\tau"),
    ('φ', "\\varphi"),
    ('ϕ', "\\phi"),
    ('χ', "\\chi"),
    ('ψ', "\\psi"),
    ('ω', "\\omega"),
    ('Γ', "\\Gamma"),
    ('Δ', "\\Delta"),
    ('Θ', "\\Theta"),
    ('Λ', "\\Lambda"),
    ('Π', "\\Pi"),
    ('Σ', "\\Sigma"),
    ('Φ', "\\Phi"),
    ('Ψ', "\\Psi"),
    ('Ω', "\\Omega"),
    ('·', "\\cdot"),
    ('×', "\\times"),
    ('−', "-"),
    ('≤', "\\leq"),
    ('≥', "\\geq"),
];

/// The longest math span taken as math, in bytes; a longer one is shown as text.
const MAX_LENGTH: usize = 1000;

/// The deepest nesting of braces taken as math.
const MAX_DEPTH: usize = 16;

/// `source` (what stood between the dollars) as LaTeX math every format can show, or
/// `None` when it holds anything outside the allowed part of LaTeX.
///
/// Unicode Greek letters and `·`, `×`, `−`, `≤`, `≥` become their commands, so that
/// pdflatex needs no Unicode math font.
pub fn checked(source: &str) -> Option<String> {
    if source.trim().is_empty() || source.len() > MAX_LENGTH {
        return None;
    }
    let mut out = String::with_capacity(source.len() + 8);
    let mut depth = 0usize;
    let mut chars = source.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => {
                let name = command_name(&mut chars);
                if name.is_empty() {
                    let next = chars.next().filter(|n| ESCAPED.contains(*n))?;
                    out.push('\\');
                    out.push(next);
                    continue;
                }
                if !COMMANDS.contains(&name.as_str()) {
                    return None;
                }
                out.push('\\');
                out.push_str(&name);
                // `\theta x` must not become `\thetax`.
                if chars.peek().is_some_and(|n| n.is_ascii_alphabetic()) {
                    out.push(' ');
                }
            }
            '{' => {
                depth += 1;
                if depth > MAX_DEPTH {
                    return None;
                }
                out.push(c);
            }
            '}' => {
                depth = depth.checked_sub(1)?;
                out.push(c);
            }
            // A script needs its argument: `a^'`, `a^^b`, `a_}` and a dangling `a^` stop TeX.
            '^' | '_' if chars.peek().is_none_or(|n| "'^_}".contains(*n)) => return None,
            // `<` before a letter or `/`, `!`, `?` reads as an HTML tag in a Markdown
            // renderer: as a relation it is written with a space (`a < b`).
            '<' if chars
                .peek()
                .is_some_and(|n| n.is_ascii_alphabetic() || "/!?".contains(*n)) =>
            {
                return None
            }
            _ if c.is_ascii_alphanumeric() || PLAIN.contains(c) => out.push(c),
            '\t' | '\n' | '\r' => out.push(' '),
            _ => {
                let (_, command) = UNICODE.iter().find(|(u, _)| *u == c)?;
                out.push_str(command);
                if chars.peek().is_some_and(|n| n.is_ascii_alphabetic()) {
                    out.push(' ');
                }
            }
        }
    }
    if depth != 0 {
        return None;
    }
    // The same span must be math everywhere: what the MathML converter cannot parse (a
    // double superscript, `\frac` without its arguments) would stop TeX too.
    mathml::to_mathml(&out, Display::Inline).ok()?;
    Some(out)
}

/// `math` for a Markdown renderer's `$…$`: `<` and `>` as `\lt` and `\gt`, so that no
/// renderer can take them for the start of an HTML tag, and `|` as `\vert`.
pub fn for_markdown(math: &str) -> String {
    math.replace('<', "\\lt ")
        .replace('>', "\\gt ")
        .replace("\\|", "\\Vert ")
        .replace('|', "\\vert ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn textbook_math_passes() {
        let cases = [
            ("\\ddot\\theta", "\\ddot\\theta"),
            ("\\dot{\\theta}^2", "\\dot{\\theta}^2"),
            ("\\frac{m g d}{I_s s}", "\\frac{m g d}{I_s s}"),
            ("T = 4\\sqrt{L/g}", "T = 4\\sqrt{L/g}"),
            ("9.81\\ \\mathrm{m/s^2}", "9.81\\ \\mathrm{m/s^2}"),
            ("θ = 0.5", "\\theta = 0.5"),
            ("\\omega\\times r", "\\omega\\times r"),
            ("\\thetax", ""),
            ("\\left(a + b\\right)^{2}", "\\left(a + b\\right)^{2}"),
        ];
        for (source, expected) in cases {
            let expected = (!expected.is_empty()).then(|| expected.to_string());
            assert_eq!(checked(source), expected, "{source}");
        }
        assert_eq!(checked("2θx").as_deref(), Some("2\\theta x"));
    }

    #[test]
    fn anything_else_is_text() {
        for source in [
            "\\input{/etc/passwd}",
            "\\write18{rm -rf /}",
            "\\immediate",
            "\\def\\x{y}",
            "\\catcode",
            "a # b",
            "50 % off",
            "a & b",
            "{a",
            "a}",
            "}{",
            "\\frac{a}",
            "a^b^c",
            "\\\\",
            "\\$",
            "\\left( a",
            "\\text{x}",
            "a^'",
            "a^^b",
            "a_}",
            "x^",
            "<img src=x onerror=alert(1)>",
            "a<b",
            "</script>",
            "😀",
            "",
            "  ",
        ] {
            assert_eq!(checked(source), None, "{source}");
        }
        let deep = format!("{}x{}", "{".repeat(40), "}".repeat(40));
        assert_eq!(checked(&deep), None);
        assert_eq!(checked(&"x+".repeat(600)), None);
    }

    #[test]
    fn markdown_gets_no_angle_brackets() {
        assert_eq!(for_markdown("a<b>c"), "a\\lt b\\gt c");
        assert_eq!(for_markdown("|x|"), "\\vert x\\vert ");
    }
}
