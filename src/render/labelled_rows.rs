//! An aligned display's rows under words that open its first line, as LaTeX's `alignat*`
//! sets them: a page may break between the rows (`\allowdisplaybreaks`), where the same
//! rows in an `aligned` block inside `\[ … \]` are one box that a page cannot break, and a
//! tall one leaves the foot of the page before it empty.

/// The rows of `\begin{aligned} … \end{aligned}` with `&&` opening each, so that they fill
/// the second column pair of `\begin{alignat*}{2}`, whose first holds the words; rows are
/// split at `\\` outside any group or inner environment (a matrix's rows stay its own).
/// Math that is not one aligned block is returned as it is.
pub fn labelled_rows(latex: &str) -> String {
    let trimmed = latex.trim();
    let Some(body) = trimmed
        .strip_prefix("\\begin{aligned}")
        .and_then(|rest| rest.strip_suffix("\\end{aligned}"))
    else {
        return latex.to_string();
    };
    let body = body.strip_prefix("[t]").unwrap_or(body);
    let rows: Vec<&str> = top_level_rows(body);
    rows.iter()
        .map(|row| format!("&& {}", row.trim()))
        .collect::<Vec<_>>()
        .join(" \\\\ ")
}

/// `body` split at each `\\` that no brace group and no inner `\begin … \end` holds.
fn top_level_rows(body: &str) -> Vec<&str> {
    let bytes = body.as_bytes();
    let mut rows = Vec::new();
    let (mut depth, mut start, mut i) = (0i32, 0usize, 0usize);
    while i < bytes.len() {
        let rest = &body[i..];
        if rest.starts_with("\\begin{") {
            depth += 1;
            i += "\\begin".len();
            continue;
        }
        if rest.starts_with("\\end{") {
            depth -= 1;
            i += "\\end".len();
            continue;
        }
        match bytes[i] {
            b'\\' if depth == 0 && rest.starts_with("\\\\") => {
                rows.push(&body[start..i]);
                i += 2;
                start = i;
                continue;
            }
            // An escaped character (`\{`, `\}`, `\,`) is no group and no row's end.
            b'\\' => i += 1,
            b'{' => depth += 1,
            b'}' => depth -= 1,
            _ => {}
        }
        i += 1;
    }
    rows.push(&body[start..]);
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_row_opens_the_second_column_pair() {
        let aligned =
            "\\begin{aligned}[t] a &= b \\\\ c &= d \\\\ &\\text{with } e = f \\end{aligned}";
        assert_eq!(
            labelled_rows(aligned),
            "&& a &= b \\\\ && c &= d \\\\ && &\\text{with } e = f"
        );
    }

    #[test]
    fn a_matrix_and_a_group_keep_their_rows() {
        let aligned = "\\begin{aligned} M &= \\begin{bmatrix} 1 \\\\ 2 \\end{bmatrix} \\\\ \\left\\{ x \\right\\} &= {y \\\\ z} \\end{aligned}";
        assert_eq!(
            labelled_rows(aligned),
            "&& M &= \\begin{bmatrix} 1 \\\\ 2 \\end{bmatrix} \\\\ && \\left\\{ x \\right\\} &= {y \\\\ z}"
        );
    }

    #[test]
    fn math_that_is_not_one_aligned_block_is_left_alone() {
        assert_eq!(labelled_rows("a = b"), "a = b");
        assert_eq!(labelled_rows(""), "");
    }
}
