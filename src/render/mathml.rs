//! LaTeX math -> MathML for the HTML page, with the LaTeX source shown where it cannot be
//! converted (the conversion itself is [`crate::typeset`]'s).

use super::escape;
use crate::typeset::Display;

/// Converts LaTeX math to MathML; when it cannot, shows the LaTeX source as escaped code,
/// so that one bad formula does not cost the student the whole page.
pub fn to_mathml_or_source(latex: &str, display: Display) -> String {
    crate::typeset::to_mathml(latex, display)
        .unwrap_or_else(|_| format!("<code class=\"tex\">{}</code>", escape::html(latex)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_latex_falls_back_to_source() {
        let shown = to_mathml_or_source("\\input{x} <script>", Display::Block);
        assert_eq!(
            shown,
            "<code class=\"tex\">\\input{x} &lt;script&gt;</code>"
        );
    }
}
