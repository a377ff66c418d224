//! The SVG exporter: a laid-out [`Picture`] as an SVG 1.1 document (no scripts, no
//! external references), with the markup the command-line contract defines.

use super::picture::{Ink, Item, Picture, Stroke, P2};
use super::scene::{Label, Role};
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

fn points(ps: &[P2]) -> String {
    ps.iter()
        .map(|p| format!("{},{}", coarse(p[0]), coarse(p[1])))
        .collect::<Vec<_>>()
        .join(" ")
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
fn shapes(out: &mut String, items: &[Item]) {
    let mut i = 0;
    while i < items.len() {
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
    let mut d = String::new();
    let mut end = String::new();
    for s in &strokes {
        for (k, p) in s.points.iter().enumerate() {
            let at = format!("{},{}", coarse(p[0]), coarse(p[1]));
            // A line that starts where the last ended goes on from there (a chain of links).
            if k == 0 && at == end {
                continue;
            }
            d.push(if k == 0 { 'M' } else { 'L' });
            d.push_str(&at);
            end = at;
        }
    }
    let dash = if first.dashed {
        " stroke-dasharray=\"4 3\""
    } else {
        ""
    };
    let _ = writeln!(
        out,
        "<path d=\"{d}\" stroke=\"{}\" stroke-width=\"{}\"{dash}/>",
        color(first.ink),
        num(first.width)
    );
}

fn stroke(out: &mut String, s: &Stroke) {
    let tag = if s.closed { "polygon" } else { "polyline" };
    // No fill is the shapes group's default (see `export`).
    let fill = s
        .fill
        .map_or(String::new(), |ink| format!(" fill=\"{}\"", color(ink)));
    let dash = if s.dashed {
        " stroke-dasharray=\"4 3\""
    } else {
        ""
    };
    let _ = writeln!(
        out,
        "<{tag} points=\"{}\"{fill} stroke=\"{}\" stroke-width=\"{}\"{dash}/>",
        points(&s.points),
        color(s.ink),
        num(s.width)
    );
}

/// A label's plain text with `^` and `_` as raised and lowered `<tspan>`s.
fn label_spans(label: &Label) -> String {
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
        let size = if script != 0.0 {
            " font-size=\"9\""
        } else {
            ""
        };
        let _ = write!(out, "<tspan dy=\"{}\"{size}>{}</tspan>", num(dy), xml(run));
        *shift = script;
        run.clear();
    };
    let plain = label.plain.as_str();
    // Words (a load's name) are not scripts.
    let words = label.tex.starts_with("\\text{");
    for c in plain.chars() {
        match c {
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
                "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\" stroke=\"{}\" stroke-width=\"1.2\"/>",
                coarse(center[0]),
                coarse(center[1]),
                coarse(*radius),
                color(*fill),
                color(*ink)
            );
        }
        Item::Text { .. } => text(out, item, true),
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

/// The picture as an SVG document; every id (and `data-at`) starts with `prefix`.
pub fn export(picture: &Picture, title: &str, prefix: &str) -> String {
    let mut out = String::new();
    let projection: Vec<String> = picture
        .projection
        .numbers()
        .iter()
        .map(|x| format!("{x:.9}"))
        .collect();
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" data-projection=\"{}\" font-family=\"DejaVu Serif, Times New Roman, serif\" font-size=\"13\" text-anchor=\"middle\" stroke-linecap=\"round\" stroke-linejoin=\"round\">",
        projection.join(" "),
        w = num(picture.width),
        h = num(picture.height),
    );
    let _ = writeln!(out, "<title>{}</title>", xml(title));
    let _ = writeln!(
        out,
        "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"#fff\"/>",
        num(picture.width),
        num(picture.height)
    );
    out.push_str("<g class=\"shapes\" fill=\"none\">\n");
    shapes(&mut out, &picture.items);
    // Every point's circle has the same outline, given once.
    out.push_str("</g>\n<g class=\"points\" stroke=\"#222\" stroke-width=\"1.2\">\n");
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
            // The quartered circle of a mass center.
            let (x, y) = (m.at[0], m.at[1]);
            // After `z` the pen is back at the centre: the second quarter starts `m0 0`.
            let _ = writeln!(
                out,
                "<path d=\"M{},{}h4.5a4.5 4.5 0 0 0-4.5-4.5zm0 0h-4.5a4.5 4.5 0 0 0 4.5 4.5z\" fill=\"#222\" stroke=\"none\"/>",
                coarse(x),
                coarse(y)
            );
        }
    }
    // Every arrow's line or arc has the same width, and its heads no outline, given once.
    out.push_str("</g>\n<g class=\"arrows\" stroke-width=\"1.6\" stroke=\"none\">\n");
    for a in &picture.arrows {
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
        let ink = color(a.ink);
        let _ = writeln!(
            out,
            "<g class=\"{class}\" data-kind=\"{}\" data-label=\"{}\" data-at=\"{}{}\"{sense} fill=\"{ink}\">",
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
                    "<path d=\"M{} {} A{} {} 0 {large} {sweep_flag} {} {}\" fill=\"none\" stroke=\"{ink}\"/>",
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
                    "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{ink}\"/>",
                    num(a.tail[0]),
                    num(a.tail[1]),
                    num(a.head[0]),
                    num(a.head[1])
                );
            }
        }
        for h in &a.heads {
            let _ = writeln!(out, "<polygon points=\"{}\"/>", points(h));
        }
        out.push_str("</g>\n");
    }
    out.push_str("</g>\n<g class=\"labels\" fill=\"none\">\n");
    // A run of labels of one colour shares it, given once.
    let mut texts = picture.texts.iter().peekable();
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
        shapes(&mut out, &items);
        // Every outline under every fill, each coordinate to a tenth, a link that starts
        // where the last ended going on from it.
        let outline = format!(
            "<path d=\"M0,0L10,0L10,5.3\" stroke=\"{}\" stroke-width=\"7\"/>\n",
            color(Ink::Black)
        );
        let fill = format!(
            "<path d=\"M0,0L10,0L10,5.3\" stroke=\"{}\" stroke-width=\"4.6\"/>\n",
            color(Ink::Body)
        );
        assert_eq!(out, format!("{outline}{fill}"));
        // One link alone stays a polyline.
        let mut one = String::new();
        shapes(&mut one, &items[..2]);
        assert_eq!(one.matches("<polyline").count(), 2, "{one}");
    }
}
