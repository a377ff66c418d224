//! A MathML structure checker for the HTML pages: a small tag-tree reader (no XML crate is
//! in the lock file) and the child-count and nesting rules of presentation MathML 3.

/// Elements with a fixed number of element children (MathML 3, section 3.1.3.2).
const ARITY: [(&str, usize); 8] = [
    ("msup", 2),
    ("msub", 2),
    ("mfrac", 2),
    ("mroot", 2),
    ("munder", 2),
    ("mover", 2),
    ("msubsup", 3),
    ("munderover", 3),
];

/// Token elements: text only, no element children.
const TOKENS: [&str; 6] = ["mi", "mn", "mo", "mtext", "ms", "mspace"];

/// The presentation elements a page may use.
const KNOWN: [&str; 28] = [
    "math",
    "mi",
    "mn",
    "mo",
    "ms",
    "mtext",
    "mspace",
    "mrow",
    "mfrac",
    "msqrt",
    "mroot",
    "msub",
    "msup",
    "msubsup",
    "munder",
    "mover",
    "munderover",
    "mtable",
    "mtr",
    "mtd",
    "mstyle",
    "merror",
    "mpadded",
    "mphantom",
    "menclose",
    "semantics",
    "annotation",
    "mlabeledtr",
];

struct Element {
    name: String,
    children: Vec<String>,
    text: bool,
}

/// Every structure error of every `<math>` element of `page`, each with the path of
/// elements that leads to it; empty when all are valid.
pub fn errors(page: &str) -> Vec<String> {
    let mut errors = Vec::new();
    let mut rest = page;
    let mut index = 0;
    while let Some(start) = rest.find("<math") {
        let after = &rest[start..];
        let Some(end) = after.find("</math>") else {
            errors.push(format!("math #{index}: no </math>"));
            break;
        };
        let math = &after[..end + "</math>".len()];
        for e in check(math) {
            errors.push(format!("math #{index}: {e} in {}", excerpt(math)));
        }
        rest = &after[end + "</math>".len()..];
        index += 1;
    }
    errors
}

fn excerpt(math: &str) -> String {
    math.chars().take(300).collect()
}

/// The errors of one `<math>…</math>`.
pub fn check(math: &str) -> Vec<String> {
    let mut errors = Vec::new();
    let mut stack: Vec<Element> = Vec::new();
    let mut rest = math;
    let path = |stack: &[Element]| {
        stack
            .iter()
            .map(|e| e.name.as_str())
            .collect::<Vec<_>>()
            .join(">")
    };
    while !rest.is_empty() {
        let Some(lt) = rest.find('<') else {
            if !rest.trim().is_empty() {
                errors.push("text after the last tag".into());
            }
            break;
        };
        let text = &rest[..lt];
        if !text.trim().is_empty() {
            match stack.last_mut() {
                Some(top) => top.text = true,
                None => errors.push(format!("text outside <math>: {text:?}")),
            }
        }
        let Some(gt) = rest[lt..].find('>') else {
            errors.push("a tag without `>`".into());
            break;
        };
        let tag = &rest[lt + 1..lt + gt];
        rest = &rest[lt + gt + 1..];
        if let Some(name) = tag.strip_prefix('/') {
            let name = name.trim();
            match stack.pop() {
                Some(open) if open.name == name => {
                    close(&open, &stack, &path(&stack), &mut errors);
                    if let Some(parent) = stack.last_mut() {
                        parent.children.push(open.name);
                    }
                }
                Some(open) => {
                    errors.push(format!(
                        "</{name}> closes <{}> at {}",
                        open.name,
                        path(&stack)
                    ));
                    return errors;
                }
                None => {
                    errors.push(format!("</{name}> without its opening tag"));
                    return errors;
                }
            }
            continue;
        }
        let self_closing = tag.ends_with('/');
        let name: String = tag
            .trim_end_matches('/')
            .split_whitespace()
            .next()
            .unwrap_or_default()
            .to_string();
        if !KNOWN.contains(&name.as_str()) {
            errors.push(format!(
                "<{name}> is not presentation MathML, at {}",
                path(&stack)
            ));
        }
        if name == "math" && !stack.is_empty() {
            errors.push(format!("<math> inside <math>, at {}", path(&stack)));
        }
        if stack.is_empty() && name != "math" {
            errors.push(format!("<{name}> outside <math>"));
        }
        let element = Element {
            name,
            children: Vec::new(),
            text: false,
        };
        if self_closing {
            close(&element, &stack, &path(&stack), &mut errors);
            if let Some(parent) = stack.last_mut() {
                parent.children.push(element.name);
            }
        } else {
            stack.push(element);
        }
    }
    if let Some(open) = stack.last() {
        errors.push(format!("<{}> is never closed", open.name));
    }
    errors
}

/// The rules for `element`, closed inside `stack`.
fn close(element: &Element, stack: &[Element], at: &str, errors: &mut Vec<String>) {
    let name = element.name.as_str();
    let here = if at.is_empty() {
        name.to_string()
    } else {
        format!("{at}>{name}")
    };
    if let Some((_, n)) = ARITY.iter().find(|(tag, _)| *tag == name) {
        if element.children.len() != *n {
            errors.push(format!(
                "<{name}> has {} children ({}), not {n}, at {here}",
                element.children.len(),
                element.children.join(", ")
            ));
        }
    }
    if TOKENS.contains(&name) && !element.children.is_empty() {
        errors.push(format!("token <{name}> holds elements, at {here}"));
    }
    if !TOKENS.contains(&name) && name != "annotation" && element.text {
        errors.push(format!("<{name}> holds bare text, at {here}"));
    }
    let parent = stack.last().map(|e| e.name.as_str());
    match name {
        "mtr" | "mlabeledtr" if parent != Some("mtable") => {
            errors.push(format!("<{name}> outside <mtable>, at {here}"))
        }
        "mtd" if !matches!(parent, Some("mtr" | "mlabeledtr")) => {
            errors.push(format!("<mtd> outside <mtr>, at {here}"))
        }
        "mtable" => {
            if let Some(bad) = element
                .children
                .iter()
                .find(|c| !c.starts_with("m") || !c.contains("tr"))
            {
                errors.push(format!("<mtable> holds <{bad}>, at {here}"));
            }
        }
        "mtr" => {
            if let Some(bad) = element.children.iter().find(|c| *c != "mtd") {
                errors.push(format!("<mtr> holds <{bad}>, at {here}"));
            }
        }
        _ => {}
    }
}
