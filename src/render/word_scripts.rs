//! Names in words in the HTML handout: a name written with an underscore (`link_1`,
//! `rail_1`) in a table cell or a sentence is set as the LaTeX sets it, `link` with the
//! subscript `1`, never as a literal underscore. Text in HTML elements takes `<sub>`; text
//! in an inline SVG picture a lowered `<tspan>`. Math (MathML), scripts, styles and
//! attributes are left alone.

/// `html` with every `word_sub` in its text nodes written as a subscript.
pub fn subscripts_in_words(html: &str) -> String {
    let mut out = String::with_capacity(html.len());
    let mut rest = html;
    // How deep inside `<math>`, `<script>`, `<style>` (left alone), `<title>` (plain text
    // only) and `<svg>`.
    let (mut skip, mut svg, mut title) = (0usize, 0usize, 0usize);
    while let Some(open) = rest.find('<') {
        let (text, tag_on) = rest.split_at(open);
        if skip == 0 {
            out.push_str(&scripts(text, svg > 0));
        } else if skip == title {
            out.push_str(&plain_scripts(text));
        } else {
            out.push_str(text);
        }
        let close = tag_on.find('>').map_or(tag_on.len(), |i| i + 1);
        let tag = &tag_on[..close];
        let name: String = tag
            .trim_start_matches(['<', '/'])
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric())
            .collect();
        let closing = tag.starts_with("</");
        let alone = tag.ends_with("/>");
        let counter = match name.as_str() {
            "math" | "script" | "style" | "title" | "textarea" => Some(&mut skip),
            "svg" => Some(&mut svg),
            _ => None,
        };
        if name == "title" && !alone {
            title = if closing {
                title.saturating_sub(1)
            } else {
                title + 1
            };
        }
        if let (Some(counter), false) = (counter, alone) {
            if closing {
                *counter = counter.saturating_sub(1);
            } else {
                *counter += 1;
            }
        }
        out.push_str(tag);
        rest = &tag_on[close..];
    }
    if skip == 0 {
        out.push_str(&scripts(rest, svg > 0));
    } else {
        out.push_str(rest);
    }
    out
}

/// A `<title>`'s text, which holds no markup: `word_12` as `word₁₂`, another `word_sub`
/// joined, `wordsub`.
fn plain_scripts(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    for (i, &c) in chars.iter().enumerate() {
        let before = i > 0 && chars[i - 1].is_alphanumeric();
        let after = chars.get(i + 1).is_some_and(|n| n.is_alphanumeric());
        if c == '_' && before && after {
            continue;
        }
        let lowered = chars[..i]
            .iter()
            .rev()
            .take_while(|p| p.is_ascii_digit() || **p == '_')
            .any(|p| *p == '_');
        match c.to_digit(10).filter(|_| lowered) {
            Some(d) => out.extend(char::from_u32(0x2080 + d)),
            None => out.push(c),
        }
    }
    out
}

/// One text node with its `word_sub` runs as subscripts.
fn scripts(text: &str, in_svg: bool) -> String {
    if !text.contains('_') {
        return text.to_string();
    }
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len() + 16);
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let before = i > 0 && chars[i - 1].is_alphanumeric();
        let after = chars.get(i + 1).is_some_and(|n| n.is_alphanumeric());
        if c == '_' && before && after {
            let end = (i + 1..chars.len())
                .find(|&k| !(chars[k].is_alphanumeric() || chars[k] == '_'))
                .unwrap_or(chars.len());
            // A second underscore joins the parts with a comma, as the subscript does.
            let sub: String = chars[i + 1..end]
                .iter()
                .map(|&c| if c == '_' { ',' } else { c })
                .collect();
            if in_svg {
                out.push_str(&format!(
                    "<tspan baseline-shift=\"sub\" font-size=\"75%\">{sub}</tspan>"
                ));
            } else {
                out.push_str(&format!("<sub>{sub}</sub>"));
            }
            i = end;
            continue;
        }
        out.push(c);
        i += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::subscripts_in_words;

    #[test]
    fn names_in_words_take_subscripts_and_math_is_left_alone() {
        assert_eq!(
            subscripts_in_words("<td>rail_1 (prismatic)</td>"),
            "<td>rail<sub>1</sub> (prismatic)</td>"
        );
        assert_eq!(
            subscripts_in_words("<svg><text>push_1</text></svg>"),
            "<svg><text>push<tspan baseline-shift=\"sub\" font-size=\"75%\">1</tspan></text></svg>"
        );
        let math = "<math><mi>a_b</mi></math><a href=\"x_y\">_</a>";
        assert_eq!(subscripts_in_words(math), math);
    }
}
