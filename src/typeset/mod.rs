//! Typeset math: the part of LaTeX math every format can set, shared by the stage that
//! reads a problem (a question's symbol must be such math) and the one that writes the
//! handout (a problem's `$…$` spans, the HTML page's MathML).
//!
//! Entry: [`checked_math`] (what a problem's text may hold between `$…$`, or `None`) and
//! [`to_mathml`] (LaTeX math → one sanitized `<math>` element). Like `symbolic`, it imports
//! nothing of the project.

mod mathml;
mod safe_math;

pub use mathml::{to_mathml, Display, MathError};
pub use safe_math::{checked as checked_math, for_markdown};

/// The name of the LaTeX command whose backslash `chars` has just read (`sin` of `\\sin`),
/// read off `chars`; empty for a control symbol such as `\\,`, whose character stays.
pub fn command_name(chars: &mut std::iter::Peekable<std::str::Chars>) -> String {
    let mut name = String::new();
    while let Some(&next) = chars.peek().filter(|n| n.is_ascii_alphabetic()) {
        name.push(next);
        chars.next();
    }
    name
}
