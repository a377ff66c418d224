//! SVG path data in tenths of a pixel: the shortest decimals, each point after the first
//! as a step from the last, so that a picture's outlines stay small.

use super::picture::P2;

/// A number of tenths as the shortest decimal: `-5` → `-.5`, `30` → `3`.
pub(super) fn tenths(n: i64) -> String {
    let sign = if n < 0 { "-" } else { "" };
    let (whole, tenth) = (n.abs() / 10, n.abs() % 10);
    match (whole, tenth) {
        (w, 0) => format!("{sign}{w}"),
        (0, t) => format!("{sign}.{t}"),
        (w, t) => format!("{sign}{w}.{t}"),
    }
}

/// A point rounded to tenths of a pixel, as whole tenths.
pub(super) fn in_tenths(p: P2) -> (i64, i64) {
    // Pictures are a few hundred pixels: the tenths fit an i64 many times over.
    ((p[0] * 10.0).round() as i64, (p[1] * 10.0).round() as i64)
}

/// Numbers one after another, a space between two only where a minus sign does not already
/// part them, as path data allows.
fn push_numbers(d: &mut String, numbers: &[String]) {
    for n in numbers {
        if !d.is_empty() && !n.starts_with('-') && !d.ends_with(['M', 'l', 'm']) {
            d.push(' ');
        }
        d.push_str(n);
    }
}

/// Path data through `points`: the first absolute, each next one as the step from the last,
/// all in tenths of a pixel. The steps are taken between rounded points, so rounding never
/// adds up along a long outline.
pub(super) fn relative_path(d: &mut String, points: &[P2], closed: bool) {
    let Some((&first, rest)) = points.split_first() else {
        return;
    };
    let mut last = in_tenths(first);
    d.push('M');
    push_numbers(d, &[tenths(last.0), tenths(last.1)]);
    if !rest.is_empty() {
        d.push('l');
    }
    for &p in rest {
        let now = in_tenths(p);
        push_numbers(d, &[tenths(now.0 - last.0), tenths(now.1 - last.1)]);
        last = now;
    }
    if closed {
        d.push('z');
    }
}
