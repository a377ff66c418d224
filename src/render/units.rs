//! Units as mathematics: `m/s^2` is set as \(\mathrm{m/s^{2}}\), `kg*m^2` as
//! \(\mathrm{kg\,m^{2}}\), `μm`, `Ω` and `°` with their LaTeX symbols (\(\mu\),
//! \(\Omega\), \(^{\circ}\)), so that pdflatex needs no Unicode. A unit with anything
//! else in it is set as text of its ASCII letters, digits and `/ . -` only.

/// `unit` (the problem's text) in LaTeX math; empty for an empty unit.
pub fn unit_tex(unit: &str) -> String {
    let unit = unit.trim();
    if unit.is_empty() {
        return String::new();
    }
    let allowed =
        |c: char| c.is_ascii_alphanumeric() || "/*^.-() ·".contains(c) || symbol(c).is_some();
    if !unit.chars().all(allowed) {
        let escaped: String = unit
            .chars()
            .filter(|c| c.is_ascii_alphanumeric() || " /.-".contains(*c))
            .collect();
        return format!("\\text{{{escaped}}}");
    }
    let chars: Vec<char> = unit.chars().collect();
    let mut out = String::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        match c {
            '^' => {
                // The exponent: an optional sign and digits (or one letter).
                let start = i + 1;
                let mut end = start;
                if end < chars.len() && chars[end] == '-' {
                    end += 1;
                }
                while end < chars.len() && chars[end].is_ascii_digit() {
                    end += 1;
                }
                if end == start && end < chars.len() {
                    end += 1;
                }
                let exponent: String = chars[start..end].iter().collect();
                out.push_str(&format!("^{{{exponent}}}"));
                i = end;
                continue;
            }
            '*' | '·' | ' ' => {
                if !out.ends_with("\\,") {
                    out.push_str("\\,");
                }
            }
            _ => match symbol(c) {
                Some(command) => {
                    out.push_str(command);
                    if chars.get(i + 1).is_some_and(char::is_ascii_alphabetic) {
                        out.push(' ');
                    }
                }
                None => out.push(c),
            },
        }
        i += 1;
    }
    format!("\\mathrm{{{}}}", out.trim_end_matches("\\,"))
}

/// The LaTeX of a unit's letter or sign that is not ASCII: micro (Greek mu or the micro
/// sign), ohm (Greek Omega or the ohm sign) and the degree.
fn symbol(c: char) -> Option<&'static str> {
    match c {
        'μ' | 'µ' => Some("\\mu"),
        'Ω' | 'Ω' => Some("\\Omega"),
        '°' => Some("^{\\circ}"),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::unit_tex;

    #[test]
    fn units_are_set_as_upright_math_with_raised_exponents() {
        assert_eq!(unit_tex("m/s^2"), "\\mathrm{m/s^{2}}");
        assert_eq!(unit_tex("rad/s^2"), "\\mathrm{rad/s^{2}}");
        assert_eq!(unit_tex("kg*m^2"), "\\mathrm{kg\\,m^{2}}");
        assert_eq!(unit_tex("N m"), "\\mathrm{N\\,m}");
        assert_eq!(unit_tex("s^-1"), "\\mathrm{s^{-1}}");
        assert_eq!(unit_tex(""), "");
        assert_eq!(unit_tex("rad"), "\\mathrm{rad}");
    }

    #[test]
    fn anything_else_is_text_with_the_markup_taken_out() {
        assert_eq!(unit_tex("\\input{x}"), "\\text{inputx}");
        assert_eq!(unit_tex("m$"), "\\text{m}");
        assert_eq!(unit_tex("Жm{"), "\\text{m}");
    }

    #[test]
    fn micro_ohm_and_degree_are_latex_symbols() {
        assert_eq!(unit_tex("μm"), "\\mathrm{\\mu m}");
        assert_eq!(unit_tex("µs"), "\\mathrm{\\mu s}");
        assert_eq!(unit_tex("kΩ"), "\\mathrm{k\\Omega}");
        assert_eq!(unit_tex("°/s"), "\\mathrm{^{\\circ}/s}");
        assert!(unit_tex("μm").is_ascii());
    }
}
