//! The TikZ exporter: the same laid-out [`Picture`] as a `tikzpicture` for pdflatex.

use super::picture::{Ink, Item, Picture, Stroke, P2};
use super::scene::Role;
use std::fmt::Write;

/// The scale at which a picture's labels print at `\footnotesize` (8 pt, its scripts
/// 6 pt) and keep the room the layout gave them at 13 px: the picture's natural size.
pub const NATURAL: f64 = 8.0 / 13.0;

/// The largest a picture may be on the page, in points: the text's width (A4 or letter
/// with 1.8 cm margins), and about half the text's height.
pub const PAGE_SIZE: Size = Size {
    width: 500.0,
    height: 380.0,
};
/// The largest a free body may be beside its table of forces: the handout puts it above
/// the table when the two are wider than the line, so no higher than there; about the
/// height of a rigid body's table of seven forces, so that little of it stands empty.
pub const BESIDE_A_TABLE: Size = Size {
    width: 500.0,
    height: 130.0,
};

/// The largest a free body may be above its table of forces: under a fifth of the text's
/// height, so that a one- or two-body handout keeps within four pages.
pub const ABOVE_A_TABLE: Size = Size {
    width: 500.0,
    height: 120.0,
};

/// The largest the system's picture may be at the head of a handout: under half the text's
/// height (a narrow one is set beside the first tables).
pub const CONFIGURATION: Size = Size {
    width: 500.0,
    height: 220.0,
};

/// The scale under which labels print a size smaller (`\scriptsize`, 7 pt), so that they
/// keep about the room the layout gave them.
const SMALL_LABELS: f64 = 7.5 / 13.0;

/// The room a picture may take on the page, in points.
#[derive(Clone, Copy, Debug)]
pub struct Size {
    /// Its width, in points.
    pub width: f64,
    /// Its height, in points.
    pub height: f64,
}

fn num(x: f64) -> String {
    let text = format!("{x:.2}");
    let text = text.trim_end_matches('0').trim_end_matches('.').to_string();
    if text == "-0" {
        "0".into()
    } else {
        text
    }
}

fn color(ink: Ink) -> String {
    let (r, g, b) = ink.rgb();
    format!("{{rgb,255:red,{r};green,{g};blue,{b}}}")
}

fn path(points: &[P2], closed: bool) -> String {
    let mut text = points
        .iter()
        .map(|p| format!("({},{})", num(p[0]), num(p[1])))
        .collect::<Vec<_>>()
        .join(" -- ");
    if closed {
        text.push_str(" -- cycle");
    }
    text
}

fn stroke(out: &mut String, s: &Stroke, unit: f64) {
    let mut options = format!("draw={},line width={}pt", color(s.ink), num(s.width * unit));
    if let Some(fill) = s.fill {
        let _ = write!(options, ",fill={}", color(fill));
    }
    if s.dashed {
        options.push_str(",dashed");
    }
    let _ = writeln!(out, "\\path[{options}] {};", path(&s.points, s.closed));
}

fn item(out: &mut String, item: &Item, unit: f64) {
    match item {
        Item::Stroke(s) => stroke(out, s, unit),
        Item::Circle {
            center,
            radius,
            ink,
            fill,
        } => {
            let _ = writeln!(
                out,
                "\\path[draw={},fill={},line width={}pt] ({},{}) circle[radius={}];",
                color(*ink),
                color(*fill),
                num(1.2 * unit),
                num(center[0]),
                num(center[1]),
                num(*radius)
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
            // The picture's y axis points down, and TikZ turns in the picture's axes: the
            // same angle as the SVG's.
            let _ = writeln!(
                out,
                "\\path[draw={},fill={},line width={}pt,rotate around={{{}:({},{})}}] ({},{}) ellipse[x radius={}, y radius={}];",
                color(*ink),
                color(*fill),
                num(1.2 * unit),
                num(*angle),
                num(center[0]),
                num(center[1]),
                num(center[0]),
                num(center[1]),
                num(*rx),
                num(*ry)
            );
        }
        Item::Body { items, .. } | Item::Group { items, .. } => {
            for inner in items {
                self::item(out, inner, unit);
            }
        }
        Item::Text { at, label, ink } => {
            let _ = writeln!(
                out,
                "\\node[text={},font=\\{},inner sep=0pt] at ({},{}) {{${}$}};",
                color(*ink),
                if unit < SMALL_LABELS {
                    "scriptsize"
                } else {
                    "footnotesize"
                },
                num(at[0]),
                num(at[1]),
                label.tex
            );
        }
    }
}

/// How much larger than the room the layout gave them (13 px) the labels print when the
/// picture is set in `room`: 1 at the natural size or larger, more when the picture shrinks
/// (its labels keep 7 or 8 pt).
pub fn label_growth(picture: &Picture, room: Size) -> f64 {
    let unit = unit_in(picture, room);
    let points = if unit < SMALL_LABELS { 7.0 } else { 8.0 };
    (points / unit / 13.0).max(1.0)
}

/// The picture as a `tikzpicture`, scaled to fit `room`; needs `tikz` and `amsmath`.
pub fn export(picture: &Picture, room: Size) -> String {
    let unit = unit_in(picture, room);
    let mut out = String::new();
    // Narrower than the picture at this scale, a page's line shrinks it further (the
    // labels keep their size): pgfmath takes the smaller when the picture is set.
    let scale = format!(
        "min({},(\\linewidth-6pt)/{})*1pt",
        num_fine(unit),
        num_fine(inked(picture)[0])
    );
    let _ = writeln!(
        out,
        "\\begin{{tikzpicture}}[x={{{scale}}},y={{-{scale}}},line cap=round,line join=round]"
    );
    for i in &picture.items {
        item(&mut out, i, unit);
    }
    for m in &picture.marks {
        let (r, fill) = match m.role {
            Role::Center => (4.5, Ink::White),
            _ => (2.6, Ink::Black),
        };
        item(
            &mut out,
            &Item::Circle {
                center: m.at,
                radius: r,
                ink: Ink::Black,
                fill,
            },
            unit,
        );
    }
    for a in &picture.arrows {
        let width = num(1.6 * unit);
        let ink = color(a.ink);
        match &a.arc {
            Some(arc) => {
                let steps = 24;
                let points: Vec<P2> = (0..=steps)
                    .map(|k| arc.at(arc.start + arc.sweep * k as f64 / steps as f64))
                    .collect();
                let _ = writeln!(
                    out,
                    "\\path[draw={ink},line width={width}pt] {};",
                    path(&points, false)
                );
            }
            None => {
                let _ = writeln!(
                    out,
                    "\\path[draw={ink},line width={width}pt] {};",
                    path(&[a.tail, a.head], false)
                );
            }
        }
        for h in &a.heads {
            let _ = writeln!(out, "\\path[fill={ink}] {};", path(h, true));
        }
        if let Some((from, to)) = a.leader {
            let _ = writeln!(
                out,
                "\\path[draw={ink},line width={}pt,dash pattern=on 1.5pt off 1pt] {};",
                num((1.2 * unit).max(0.5)),
                path(&[from, to], false)
            );
        }
    }
    // The handout heads each picture with its title already, and TikZ's own bounding box
    // fits what is drawn: no strip of margin above or below.
    let captions = picture.texts.len().saturating_sub(picture.legend.lines);
    for t in picture.texts.get(1..captions).unwrap_or_default() {
        item(&mut out, t, unit);
    }
    out.push_str("\\end{tikzpicture}\n");
    out
}

/// The width and height of what `picture` draws on a page (its ink, without the title and
/// legend the handout prints apart, nor the empty margin round them), with a few points to
/// spare, since a label's width is estimated before TeX sets it; the picture's own size
/// where it draws nothing.
fn inked(picture: &Picture) -> [f64; 2] {
    const SPARE: f64 = 8.0;
    match super::extent::drawn(picture) {
        Some((lo, hi)) => [hi[0] - lo[0] + SPARE, hi[1] - lo[1] + SPARE],
        None => [picture.width, picture.height - picture.legend.height],
    }
}

/// Points per picture unit where `picture` is set in `room`: its ink fills the room (a free
/// body as large as its page allows), never past its natural size.
fn unit_in(picture: &Picture, room: Size) -> f64 {
    let [width, height] = inked(picture);
    (room.width / width).min(room.height / height).min(NATURAL)
}

fn num_fine(x: f64) -> String {
    format!("{x:.4}")
}
