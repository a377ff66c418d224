//! What every animated element of `motion.svg` shares: its timing (length, key times,
//! looping) and how numbers and inks are written.

use super::motion::Placed;
use super::picture::{Ink, P2};
use std::fmt::Write;

/// Three decimals, no negative zero, no trailing zeros.
pub(super) fn num(x: f64) -> String {
    decimals(x, 3)
}

/// A number only the eye reads: to a tenth of a pixel, which keeps a long motion's file
/// small.
pub(super) fn coarse(x: f64) -> String {
    decimals(x, 1)
}

fn decimals(x: f64, places: usize) -> String {
    let text = format!("{x:.places$}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".into()
    } else {
        text.to_string()
    }
}

/// Path data through `points`, each number written by `write`.
pub(super) fn polyline(points: &[P2], write: fn(f64) -> String) -> String {
    let mut d = String::new();
    for (i, [x, y]) in points.iter().enumerate() {
        let _ = std::fmt::Write::write_fmt(
            &mut d,
            format_args!(
                "{}{} {}",
                if i == 0 { "M" } else { "L" },
                write(*x),
                write(*y)
            ),
        );
    }
    d
}

/// Six significant digits, for the sheets' scales (metres to pixels).
pub(super) fn fine(x: f64) -> String {
    let text = format!("{x:.6e}");
    match text.parse::<f64>() {
        Ok(v) if v != 0.0 => format!("{v}"),
        _ => "0".into(),
    }
}

pub(super) fn color(ink: Ink) -> String {
    let (r, g, b) = ink.rgb();
    format!("#{r:02x}{g:02x}{b:02x}")
}

/// The animation's common attributes: its length, its key times, looping.
pub(super) struct Timing {
    attributes: String,
}

impl Timing {
    pub(super) fn new(frames: &[Placed]) -> Timing {
        let start = frames.first().map_or(0.0, |f| f.t);
        let end = frames.last().map_or(1.0, |f| f.t);
        let length = (end - start).max(1e-9);
        let times: Vec<String> = frames
            .iter()
            .enumerate()
            .map(|(i, f)| {
                if i + 1 == frames.len() {
                    "1".to_string()
                } else {
                    // Key times must not decrease; rounding could otherwise tie them.
                    format!("{:.6}", (f.t - start) / length)
                        .trim_end_matches('0')
                        .trim_end_matches('.')
                        .to_string()
                }
            })
            .collect();
        Timing {
            attributes: format!(
                "dur=\"{}s\" keyTimes=\"{}\" calcMode=\"linear\" repeatCount=\"indefinite\"",
                fine(length),
                times.join(";")
            ),
        }
    }

    /// A circle whose centre follows `track` (a point in the picture per frame):
    /// `<circle {lead} cx cy {rest}>`, its centre animated.
    pub(super) fn moving_circle(&self, out: &mut String, track: &[P2], lead: &str, rest: &str) {
        let xs: Vec<String> = track.iter().map(|q| num(q[0])).collect();
        let ys: Vec<String> = track.iter().map(|q| num(q[1])).collect();
        let _ = writeln!(
            out,
            "<circle {lead} cx=\"{}\" cy=\"{}\" {rest}>",
            xs[0], ys[0]
        );
        self.animate(out, "cx", &xs);
        self.animate(out, "cy", &ys);
        out.push_str("</circle>\n");
    }

    pub(super) fn animate(&self, out: &mut String, attribute: &str, values: &[String]) {
        let _ = writeln!(
            out,
            "<animate attributeName=\"{attribute}\" values=\"{}\" {}/>",
            values.join(";"),
            self.attributes
        );
    }

    pub(super) fn transform(&self, out: &mut String, kind: &str, values: &[String]) {
        let _ = writeln!(
            out,
            "<animateTransform attributeName=\"transform\" type=\"{kind}\" additive=\"sum\" values=\"{}\" {}/>",
            values.join(";"),
            self.attributes
        );
    }
}
