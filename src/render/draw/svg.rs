//! The SVG exporter: a laid-out [`Picture`] as an SVG 1.1 document (no scripts, no
//! external references), with the markup the command-line contract defines.

use super::picture::{Ink, Item, Picture, Stroke, P2};
use super::scene::{Label, Role};
use super::svg_path::{in_tenths, relative_path, tenths};
use crate::render::escape::html as xml;
use std::fmt::Write;

/// A number the contract reads (a point's centre, an arrow's line, the size): three
/// decimals, no negative zero.
fn num(x: f64) -> String {
    decimals(x, 3)
}

/// A number only the eye reads (an outline, an arrowhead, a label's place): a tenth of a
/// pixel is finer than a screen or a printer shows.
fn coarse(x: f64) -> String {
    decimals(x, 1)
}

fn decimals(x: f64, places: usize) -> String {
    let text = format!("{x:.places$}");
    let text = text.trim_end_matches('0').trim_end_matches('.').to_string();
    if text == "-0" {
        "0".into()
    } else {
        text
    }
}

/// A colour as `#rgb` where each channel's two digits are alike (`#222`), else `#rrggbb`.
fn color(ink: Ink) -> String {
    let (r, g, b) = ink.rgb();
    if [r, g, b].iter().all(|c| c % 17 == 0) {
        format!("#{:x}{:x}{:x}", r / 17, g / 17, b / 17)
    } else {
        format!("#{r:02x}{g:02x}{b:02x}")
    }
}

/// An open, unfilled line's look: lines that share it can be one `<path>`.
fn line_style(item: &Item) -> Option<(Ink, u64, bool)> {
    match item {
        Item::Stroke(s) if !s.closed && s.fill.is_none() && s.points.len() > 1 => {
            Some((s.ink, s.width.to_bits(), s.dashed))
        }
        _ => None,
    }
}

/// The shapes, a run of lines drawn alike as one `<path>`. A chain of links is drawn link by
/// link as outline then fill; such a run of pairs becomes two paths, every outline and then
/// every fill, so the links read as one bar with the joints' circles on it.
fn shapes(out: &mut String, items: &[Item], prefix: &str) {
    let mut i = 0;
    while i < items.len() {
        if matches!(items[i], Item::Body { .. }) {
            body(out, &items[i], prefix);
            i += 1;
            continue;
        }
        let (Some(a), b) = (line_style(&items[i]), items.get(i + 1).and_then(line_style)) else {
            item(out, &items[i]);
            i += 1;
            continue;
        };
        let alike = |start: usize, style| items.get(start).and_then(line_style) == Some(style);
        let pairs = b.map_or(0, |b| {
            (0..)
                .take_while(|k| alike(i + 2 * k, a) && alike(i + 2 * k + 1, b))
                .count()
        });
        if pairs >= 2 {
            let run = &items[i..i + 2 * pairs];
            merged(out, run.iter().step_by(2));
            merged(out, run.iter().skip(1).step_by(2));
            i += 2 * pairs;
            continue;
        }
        let singles = (i..).take_while(|&k| alike(k, a)).count();
        merged(out, items[i..i + singles].iter());
        i += singles;
    }
}

/// Lines of one look as one `<path>` (one line as a `<polyline>`).
fn merged<'a>(out: &mut String, lines: impl Iterator<Item = &'a Item>) {
    let strokes: Vec<&Stroke> = lines
        .filter_map(|i| match i {
            Item::Stroke(s) => Some(s),
            _ => None,
        })
        .collect();
    let [first, ..] = strokes[..] else {
        return;
    };
    if strokes.len() == 1 {
        stroke(out, first);
        return;
    }
    // A line that starts where the last ended goes on from there (a chain of links).
    let mut runs: Vec<Vec<P2>> = Vec::new();
    for s in &strokes {
        match (runs.last_mut(), s.points.split_first()) {
            (Some(run), Some((&start, rest)))
                if run.last().map(|&p| in_tenths(p)) == Some(in_tenths(start)) =>
            {
                run.extend_from_slice(rest);
            }
            _ => runs.push(s.points.clone()),
        }
    }
    let mut d = String::new();
    for run in &runs {
        relative_path(&mut d, run, false);
    }
    let dash = if first.dashed {
        " stroke-dasharray=\"4 3\""
    } else {
        ""
    };
    let _ = writeln!(
        out,
        "<path d=\"{d}\"{} stroke-width=\"{}\"{dash}/>",
        outline(first.ink),
        num(first.width)
    );
}

/// A shape's outline colour, left out when it is the shapes group's (see `export`).
fn outline(ink: Ink) -> String {
    if ink == Ink::Black {
        String::new()
    } else {
        format!(" stroke=\"{}\"", color(ink))
    }
}

fn stroke(out: &mut String, s: &Stroke) {
    // No fill is the shapes group's default (see `export`).
    let fill = s
        .fill
        .map_or(String::new(), |ink| format!(" fill=\"{}\"", color(ink)));
    let dash = if s.dashed {
        " stroke-dasharray=\"4 3\""
    } else {
        ""
    };
    let mut d = String::new();
    relative_path(&mut d, &s.points, s.closed);
    let _ = writeln!(
        out,
        "<path d=\"{d}\"{fill}{} stroke-width=\"{}\"{dash}/>",
        outline(s.ink),
        num(s.width)
    );
}

/// A label's plain text with `^` and `_` as raised and lowered `<tspan>`s.
pub(super) fn label_spans(label: &Label) -> String {
    let mut out = String::new();
    let mut shift = 0.0f64;
    let mut script = 0.0f64;
    let mut run = String::new();
    let flush = |out: &mut String, run: &mut String, shift: &mut f64, script: f64| {
        if run.is_empty() {
            return;
        }
        let dy = script - *shift;
        if dy == 0.0 && script == 0.0 {
            // On the baseline already: plain text, no span.
            out.push_str(&xml(run));
            run.clear();
            return;
        }
        // Scripts take the picture's small size (its `<style>`); a run back on the baseline
        // is marked to take the full size again.
        let class = if script != 0.0 { "" } else { " class=\"b\"" };
        let _ = write!(out, "<tspan{class} dy=\"{}\">{}</tspan>", num(dy), xml(run));
        *shift = script;
        run.clear();
    };
    let plain = label.plain.as_str();
    // Words (a load's name) are not scripts.
    let words = label.tex.starts_with("\\text{");
    // Inside braces (a script with a script inside), every character is the script's.
    let mut braced = 0usize;
    let mut chars = plain.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '{' if !words => braced += 1,
            '}' if !words && braced > 0 => braced -= 1,
            // A script inside a script (the star of a^{A^*}, the 4 of J_4) is set in the
            // same run: the picture has one script size, and a literal `^` or `_` would
            // print. Before a word, a comma keeps the parts apart (rear,contact).
            '^' if !words && braced > 0 => {}
            '_' if !words && braced > 0 => {
                if chars.peek().is_some_and(|n| !n.is_ascii_digit()) {
                    run.push(',');
                }
            }
            _ if braced > 0 => run.push(c),
            '^' if !words => {
                flush(&mut out, &mut run, &mut shift, script);
                script = -5.0;
            }
            '_' if !words => {
                flush(&mut out, &mut run, &mut shift, script);
                script = 4.0;
            }
            ' ' if script != 0.0 => {
                flush(&mut out, &mut run, &mut shift, script);
                script = 0.0;
                run.push(' ');
            }
            _ => run.push(c),
        }
    }
    // A script that ends the label needs no return to the baseline: nothing follows.
    flush(&mut out, &mut run, &mut shift, script);
    out
}

fn item(out: &mut String, item: &Item) {
    match item {
        Item::Stroke(s) => stroke(out, s),
        Item::Circle {
            center,
            radius,
            ink,
            fill,
        } => {
            let _ = writeln!(
                out,
                "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"{}/>",
                coarse(center[0]),
                coarse(center[1]),
                coarse(*radius),
                color(*fill),
                outline(*ink)
            );
        }
        Item::Ellipse {
            center,
            rx,
            ry,
            angle,
            ink,
            fill,
        } => {
            // Turned by the plain `rotate(A)` about the origin, its centre written turned
            // back by A, so that after the transform it is where the disc's centre is.
            let (turn, at) = if angle.abs() < 0.05 {
                (String::new(), *center)
            } else {
                let (s, c) = angle.to_radians().sin_cos();
                (
                    format!(" transform=\"rotate({})\"", decimals(*angle, 3)),
                    [
                        center[0] * c + center[1] * s,
                        -center[0] * s + center[1] * c,
                    ],
                )
            };
            let _ = writeln!(
                out,
                "<ellipse cx=\"{}\" cy=\"{}\" rx=\"{}\" ry=\"{}\"{turn} fill=\"{}\"{}/>",
                decimals(at[0], 2),
                decimals(at[1], 2),
                coarse(*rx),
                coarse(*ry),
                color(*fill),
                outline(*ink)
            );
        }
        Item::Text { .. } => text(out, item, true),
        Item::Body { .. } => body(out, item, ""),
        Item::Group { class, items } => {
            let _ = writeln!(out, "<g class=\"{class}\">");
            shapes(out, items, "");
            out.push_str("</g>\n");
        }
    }
}

/// A body's group: `<g class="body" id="body-A" data-shape="rod">` around its items.
fn body(out: &mut String, item: &Item, prefix: &str) {
    if let Item::Body { id, kind, items } = item {
        let _ = writeln!(
            out,
            "<g class=\"body\" id=\"{}{}\" data-shape=\"{}\">",
            xml(prefix),
            xml(id),
            kind.name()
        );
        shapes(out, items, prefix);
        out.push_str("</g>\n");
    }
}

/// A label, with its colour or (`coloured` false) without, when a group around it gives it.
fn text(out: &mut String, item: &Item, coloured: bool) {
    if let Item::Text { at, label, ink } = item {
        let fill = if coloured {
            format!(" fill=\"{}\"", color(*ink))
        } else {
            String::new()
        };
        let _ = writeln!(
            out,
            "<text x=\"{}\" y=\"{}\"{fill}>{}</text>",
            coarse(at[0]),
            coarse(at[1] + 4.5),
            label_spans(label)
        );
    }
}

/// The size of a label's scripts, and of a run back on the baseline after one: said once in
/// each picture rather than on every `<tspan>`.
pub(super) const SCRIPT_STYLE: &str =
    "<style type=\"text/css\">.mbd tspan{font-size:9px}.mbd tspan.b{font-size:13px}</style>";

/// A title as the `<title>` element's plain text, read aloud or shown as a tooltip: its
/// scripts follow their letter without the `_` and `^` that the drawn title sets as
/// tspans (`q_A` reads `qA`).
pub(super) fn title_text(title: &str) -> String {
    title
        .chars()
        .filter(|c| !matches!(c, '_' | '^' | '{' | '}'))
        .collect()
}

/// The picture as an SVG document; every id (and `data-at`) starts with `prefix`.
pub fn export(picture: &Picture, title: &str, prefix: &str) -> String {
    export_with(picture, title, prefix, true)
}

/// The picture as [`export`] writes it, its title drawn over it only when `drawn_title`
/// (a page that heads the picture with its title leaves it out, as the LaTeX does); the
/// `<title>` element names it either way.
pub fn export_with(picture: &Picture, title: &str, prefix: &str, drawn_title: bool) -> String {
    let mut out = String::new();
    let projection: Vec<String> = picture
        .projection
        .numbers()
        .iter()
        .map(|x| format!("{x:.9}"))
        .collect();
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" class=\"mbd\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" data-projection=\"{}\" font-family=\"DejaVu Serif, Times New Roman, serif\" font-size=\"13\" text-anchor=\"middle\" stroke-linecap=\"round\" stroke-linejoin=\"round\">",
        projection.join(" "),
        w = num(picture.width),
        h = num(picture.height),
    );
    let _ = writeln!(out, "<title>{}</title>", xml(&title_text(title)));
    out.push_str(SCRIPT_STYLE);
    out.push('\n');
    let _ = writeln!(
        out,
        "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"#fff\"/>",
        num(picture.width),
        num(picture.height)
    );
    // Outlines are black and thin unless a shape says otherwise.
    let _ = writeln!(
        out,
        "<g class=\"shapes\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.2\">",
        color(Ink::Black)
    );
    shapes(&mut out, &picture.items, prefix);
    out.push_str("</g>\n");
    marks(&mut out, picture, prefix);
    arrows(&mut out, picture, prefix);
    out.push_str("<g class=\"labels\" fill=\"none\">\n");
    // A run of labels of one colour shares it, given once.
    let mut texts = picture
        .texts
        .iter()
        .skip(usize::from(!drawn_title))
        .peekable();
    while let Some(t) = texts.next() {
        let Item::Text { ink, .. } = t else {
            item(&mut out, t);
            continue;
        };
        let same = |next: &&Item| matches!(next, Item::Text { ink: other, .. } if other == ink);
        if !texts.peek().is_some_and(same) {
            item(&mut out, t);
            continue;
        }
        let _ = writeln!(out, "<g fill=\"{}\">", color(*ink));
        text(&mut out, t, false);
        while let Some(next) = texts.next_if(same) {
            text(&mut out, next, false);
        }
        out.push_str("</g>\n");
    }
    out.push_str("</g>\n</svg>\n");
    out
}

/// The marked points, each a `<circle>` with its id; the mass centres' black quarters all
/// in one path after them.
fn marks(out: &mut String, picture: &Picture, prefix: &str) {
    // Every point's circle has the same outline, given once.
    out.push_str("<g class=\"points\" stroke=\"#222\" stroke-width=\"1.2\">\n");
    let mut quarters = String::new();
    for m in &picture.marks {
        let (r, fill, class) = match m.role {
            Role::Joint => (2.6, "#222", "joint"),
            Role::Center => (4.5, "#fff", "center"),
            Role::Point => (2.6, "#222", "point"),
        };
        let _ = writeln!(
            out,
            "<circle id=\"{}{}\" class=\"{class}\" cx=\"{}\" cy=\"{}\" r=\"{r}\" fill=\"{fill}\"/>",
            xml(prefix),
            xml(&m.id),
            num(m.at[0]),
            num(m.at[1])
        );
        if m.role == Role::Center {
            // The quartered circle of a mass center. After `z` the pen is back at the
            // centre: the second quarter starts `m0 0`.
            let (x, y) = in_tenths(m.at);
            let _ = write!(
                quarters,
                "M{},{}h4.5a4.5 4.5 0 0 0-4.5-4.5zm0 0h-4.5a4.5 4.5 0 0 0 4.5 4.5z",
                tenths(x),
                tenths(y)
            );
        }
    }
    if !quarters.is_empty() {
        let _ = writeln!(
            out,
            "<path d=\"{quarters}\" fill=\"#222\" stroke=\"none\"/>"
        );
    }
    out.push_str("</g>\n");
}

/// The arrows, each a `<g>` with the contract's class and data; a run of one colour inside
/// a group that gives it, to line and head alike.
fn arrows(out: &mut String, picture: &Picture, prefix: &str) {
    // Every arrow's line or arc has the same width, given once.
    out.push_str("<g class=\"arrows\" stroke-width=\"1.6\">\n");
    let mut run_ink = None;
    for a in &picture.arrows {
        if run_ink != Some(a.ink) {
            if run_ink.is_some() {
                out.push_str("</g>\n");
            }
            let ink = color(a.ink);
            let _ = writeln!(out, "<g fill=\"{ink}\" stroke=\"{ink}\">");
            run_ink = Some(a.ink);
        }
        let mut class = String::from("force");
        if a.couple {
            class.push_str(" couple");
        }
        if a.kind == super::scene::Kind::Inertia {
            class.push_str(" inertia");
        } else {
            class.push(' ');
            class.push_str(a.kind.name());
        }
        let sense = a
            .arc
            .as_ref()
            .map(|arc| format!(" data-sense=\"{:+}\"", arc.sense))
            .unwrap_or_default();
        let _ = writeln!(
            out,
            "<g class=\"{class}\" data-kind=\"{}\" data-label=\"{}\" data-at=\"{}{}\"{sense}>",
            a.kind.name(),
            xml(&a.label.plain),
            xml(prefix),
            xml(&a.at_id)
        );
        match &a.arc {
            Some(arc) => {
                let large = u8::from(arc.sweep.abs() > std::f64::consts::PI);
                let sweep_flag = u8::from(arc.sweep > 0.0);
                let _ = writeln!(
                    out,
                    "<path d=\"M{} {} A{} {} 0 {large} {sweep_flag} {} {}\" fill=\"none\"/>",
                    num(a.tail[0]),
                    num(a.tail[1]),
                    num(arc.radius),
                    num(arc.radius),
                    num(a.head[0]),
                    num(a.head[1])
                );
            }
            None => {
                let _ = writeln!(
                    out,
                    "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>",
                    num(a.tail[0]),
                    num(a.tail[1]),
                    num(a.head[0]),
                    num(a.head[1])
                );
            }
        }
        if let Some((from, to)) = a.leader {
            // Drawn aside: a dashed leader from the point it acts at.
            let _ = writeln!(
                out,
                "<line class=\"leader\" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke-width=\"1.2\" stroke-dasharray=\"3 2\"/>",
                num(from[0]),
                num(from[1]),
                num(to[0]),
                num(to[1])
            );
        }
        // The heads, filled; the arrow's outline around them only rounds their corners.
        let mut d = String::new();
        for h in &a.heads {
            relative_path(&mut d, h, true);
        }
        if !d.is_empty() {
            let _ = writeln!(out, "<path d=\"{d}\"/>");
        }
        out.push_str("</g>\n");
    }
    if run_ink.is_some() {
        out.push_str("</g>\n");
    }
    out.push_str("</g>\n");
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(points: &[P2], ink: Ink, width: f64) -> Item {
        Item::Stroke(Stroke {
            points: points.to_vec(),
            closed: false,
            width,
            ink,
            fill: None,
            dashed: false,
        })
    }

    #[test]
    fn a_colour_of_doubled_digits_is_written_short() {
        assert_eq!(color(Ink::Black), "#222");
        assert_eq!(color(Ink::White), "#fff");
        assert_eq!(color(Ink::Weight), "#2e7d32");
        assert_eq!(color(Ink::Grey), "#787878");
    }

    #[test]
    fn links_drawn_outline_then_fill_become_two_paths() {
        let (a, b, c) = ([0.0, 0.0], [10.0, 0.0], [10.04, 5.26]);
        let items = [
            line(&[a, b], Ink::Black, 7.0),
            line(&[a, b], Ink::Body, 4.6),
            line(&[b, c], Ink::Black, 7.0),
            line(&[b, c], Ink::Body, 4.6),
        ];
        let mut out = String::new();
        shapes(&mut out, &items, "");
        // Every outline under every fill, each coordinate to a tenth, a link that starts
        // where the last ended going on from it, each point as the step from the last.
        // The outline's black is the shapes group's and is not repeated.
        let outline = "<path d=\"M0 0l10 0 0 5.3\" stroke-width=\"7\"/>\n".to_string();
        let fill = format!(
            "<path d=\"M0 0l10 0 0 5.3\" stroke=\"{}\" stroke-width=\"4.6\"/>\n",
            color(Ink::Body)
        );
        assert_eq!(out, format!("{outline}{fill}"));
        // One link alone is a path of its own.
        let mut one = String::new();
        shapes(&mut one, &items[..2], "");
        assert_eq!(one.matches("<path").count(), 2, "{one}");
    }

    #[test]
    fn steps_are_taken_between_rounded_points() {
        // 0.04 three times: each point alone rounds to 0, 0.1 and 0.1, so the steps are
        // 1, 0 in tenths and the last point lands where it would alone (0.12 → 0.1).
        let mut d = String::new();
        relative_path(&mut d, &[[0.0, 0.0], [0.06, -0.5], [0.12, -1.25]], true);
        assert_eq!(d, "M0 0l.1-.5 0-.8z");
        assert_eq!(tenths(-5), "-.5");
        assert_eq!(tenths(30), "3");
        assert_eq!(tenths(-123), "-12.3");
    }
}
