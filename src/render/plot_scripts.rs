//! A plot's texts with their subscripts set low: the plotting library writes a text as it
//! is given, so a legend entry `q_A` (a subscript that has no Unicode subscript letter)
//! would print its underscore. Each `_RUN` inside a `<text>` becomes a lowered, smaller
//! `<tspan>`, as the pictures' own captions set theirs.

/// `svg` with every `_RUN` in its `<text>` elements set as a subscript; a run ends at a
/// space, a comma, a bracket or the end of the text.
pub fn lowered(svg: &str) -> String {
    let mut out = String::with_capacity(svg.len() + 64);
    let mut rest = svg;
    while let Some(open) = rest.find("<text") {
        let Some(start) = rest[open..].find('>').map(|k| open + k + 1) else {
            break;
        };
        let Some(end) = rest[start..].find("</text>").map(|k| start + k) else {
            break;
        };
        out.push_str(&rest[..start]);
        out.push_str(&scripts(&rest[start..end]));
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

/// One text's content with its `_RUN`s as subscript `<tspan>`s.
fn scripts(text: &str) -> String {
    let mut out = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        if c != '_' {
            out.push(c);
            continue;
        }
        let mut run = String::new();
        while let Some(&n) = chars.peek() {
            if n.is_whitespace() || matches!(n, ',' | '(' | ')' | '<' | '_') {
                break;
            }
            run.push(n);
            chars.next();
        }
        if run.is_empty() {
            out.push('_');
        } else {
            out.push_str(&format!(
                "<tspan baseline-shift=\"sub\" font-size=\"75%\">{run}</tspan>"
            ));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::lowered;

    #[test]
    fn a_legend_entry_sets_its_subscript_low_and_leaves_other_texts_alone() {
        let svg = "<g><text x=\"1\">\nq_A\n</text><text>\nE = K + V\n</text></g>";
        assert_eq!(
            lowered(svg),
            "<g><text x=\"1\">\nq<tspan baseline-shift=\"sub\" font-size=\"75%\">A</tspan>\n\
             </text><text>\nE = K + V\n</text></g>"
        );
        assert_eq!(
            lowered("<text>θ_AB (rad)</text>"),
            "<text>θ<tspan baseline-shift=\"sub\" font-size=\"75%\">AB</tspan> (rad)</text>"
        );
    }
}
