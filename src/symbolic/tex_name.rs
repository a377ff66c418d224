//! Names in LaTeX: the one piece of printing that the styles need as well as the
//! printer, so it stands below both.

/// The letters a name spells out, set as symbols: the Greek ones and the script `ell` (ℓ), a
/// length as textbooks write it.
const GREEK: [&str; 25] = [
    "ell", "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
    "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi",
    "omega", "Omega",
];
const GREEK_UPPER: [&str; 10] = [
    "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi",
];

/// A name in LaTeX: Greek letters (and `ell`) spelled out become symbols, trailing digits and
/// `_suffix` become subscripts, longer words are set upright.
pub fn latex_name(name: &str) -> String {
    let (stem, subscript) = match name.split_once('_') {
        Some((stem, sub)) if !stem.is_empty() && !sub.is_empty() => {
            (stem.to_string(), Some(sub.to_string()))
        }
        _ => {
            let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
            if stem.is_empty() || stem.len() == name.len() {
                (name.to_string(), None)
            } else {
                (stem.to_string(), Some(name[stem.len()..].to_string()))
            }
        }
    };
    let greek = |word: &str| GREEK.contains(&word) || GREEK_UPPER.contains(&word);
    // A letter (or a Greek letter's name) followed by one more letter is a symbol with a
    // subscript, as textbooks write them: `Is` → I_s, `mT` → m_T, `tauL` → τ_L, `kp2` → k_{p2}.
    let split = stem
        .char_indices()
        .last()
        .filter(|&(i, c)| i > 0 && c.is_ascii_alphabetic())
        .map(|(i, _)| (&stem[..i], &stem[i..]))
        // After a Greek letter's name only a capital: `pin` is a word, not π_n.
        .filter(|(head, letter)| {
            head.chars().count() == 1 || (greek(head) && letter.starts_with(char::is_uppercase))
        })
        .filter(|_| !greek(&stem) && stem.chars().all(|c| c.is_ascii_alphabetic()));
    // An inertia component: `Ixx` → I_{xx}, `Jyz` → J_{yz}.
    let axes = stem.len() == 3
        && stem.starts_with(|c: char| c.is_ascii_uppercase())
        && stem[1..].chars().all(|c| "xyz".contains(c));
    let split = split.or_else(|| axes.then(|| (&stem[..1], &stem[1..])));
    if let Some((head, letter)) = split {
        let head = if greek(head) {
            format!("\\{head}")
        } else {
            head.to_string()
        };
        let sub = subscript.map(|s| latex_name_plain(&s)).unwrap_or_default();
        return format!("{head}_{{{letter}{sub}}}");
    }
    let body = if greek(&stem) {
        format!("\\{stem}")
    } else if stem.chars().count() == 1 {
        stem.clone()
    } else {
        format!("\\mathrm{{{}}}", stem.replace('_', "\\_"))
    };
    match subscript {
        Some(sub) => format!("{body}_{{{}}}", latex_name_plain(&sub)),
        None => body,
    }
}

/// A subscript in LaTeX: digits as they are, a word upright, `a_b` as `a,b`.
pub(crate) fn latex_name_plain(sub: &str) -> String {
    if sub.chars().all(|c| c.is_ascii_alphanumeric())
        && sub.chars().count() > 1
        && !sub.chars().all(|c| c.is_ascii_digit())
    {
        format!("\\mathrm{{{sub}}}")
    } else {
        sub.replace('_', ",")
    }
}

/// A two-part name, point `name` of body `of`, with one subscript group: `J4` of `L4` is
/// `J_{4,L_{4}}`, `P` of `C` is `P_{C}`; never a double subscript (`J_{4}_{L_{4}}`).
pub fn latex_name_of(name: &str, of: &str) -> String {
    let first = latex_name(name);
    let second = latex_name(of);
    // The last top-level subscript group of `first`, if it ends the name.
    let mut depth = 0usize;
    let mut group = None;
    for (i, c) in first.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth = depth.saturating_sub(1),
            '_' if depth == 0 && first[i + 1..].starts_with('{') => group = Some(i),
            _ => {}
        }
    }
    match group {
        Some(i) if first.ends_with('}') && closes_at_end(&first[i + 1..]) => {
            format!("{},{second}}}", &first[..first.len() - 1])
        }
        _ => format!("{first}_{{{second}}}"),
    }
}

/// Whether the brace group that opens `text` closes at its last character.
fn closes_at_end(text: &str) -> bool {
    let mut depth = 0usize;
    for (i, c) in text.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth = depth.saturating_sub(1);
                if depth == 0 {
                    return i + 1 == text.len();
                }
            }
            _ => {}
        }
    }
    false
}

#[cfg(test)]
mod two_part_tests {
    use super::latex_name_of;

    #[test]
    fn one_subscript_group() {
        assert_eq!(latex_name_of("J4", "L4"), "J_{4,L_{4}}");
        assert_eq!(latex_name_of("P", "C"), "P_{C}");
        assert_eq!(latex_name_of("P4", "C"), "P_{4,C}");
        assert_eq!(latex_name_of("link_1", "B0"), "\\mathrm{link}_{1,B_{0}}");
    }
}
