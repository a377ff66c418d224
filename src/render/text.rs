//! The kinds of string the worked solution holds, each a type of its own, so that the
//! renderer treats a string by what it is (see `render::prepare`) and not by its field's
//! name. A plain `String` in the content is plain text: user text, names, numbers.
//!
//! Each kind serializes as a one-entry map whose key names the kind (a key no field and no
//! user text can have), which the renderer turns into the string the format needs before
//! a template sees it.

use serde::{Serialize, Serializer};
use std::fmt;

/// The keys that mark the kinds in the serialized content.
pub(super) mod key {
    pub const MATH: &str = "\u{0}math";
    pub const MARKUP: &str = "\u{0}markup";
    pub const MARKUP_LINE: &str = "\u{0}markup-line";
    pub const LATEX_CODE: &str = "\u{0}latex";
    pub const INLINE_SVG: &str = "\u{0}svg-inline";
    pub const SVG_DOCUMENT: &str = "\u{0}svg-document";
    pub const FILE_NAME: &str = "\u{0}file-name";
}

macro_rules! kind {
    ($(#[$doc:meta])* $name:ident, $key:expr, $index:expr) => {
        $(#[$doc])*
        #[derive(Clone, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub struct $name(pub String);

        impl $name {
            /// The string itself.
            pub fn as_str(&self) -> &str {
                &self.0
            }

            /// Each of `texts` as this kind.
            pub fn all(texts: Vec<String>) -> Vec<$name> {
                texts.into_iter().map($name).collect()
            }

            /// Leaves nothing to show.
            pub fn clear(&mut self) {
                self.0.clear();
            }

            /// Whether there is nothing to show.
            pub fn is_empty(&self) -> bool {
                self.0.is_empty()
            }
        }

        impl std::ops::Deref for $name {
            type Target = str;
            fn deref(&self) -> &str {
                &self.0
            }
        }

        impl From<String> for $name {
            fn from(text: String) -> $name {
                $name(text)
            }
        }

        impl From<&str> for $name {
            fn from(text: &str) -> $name {
                $name(text.to_string())
            }
        }

        impl From<&String> for $name {
            fn from(text: &String) -> $name {
                $name(text.clone())
            }
        }

        impl PartialEq<str> for $name {
            fn eq(&self, other: &str) -> bool {
                self.0 == other
            }
        }

        impl PartialEq<&str> for $name {
            fn eq(&self, other: &&str) -> bool {
                self.0 == *other
            }
        }

        impl PartialEq<String> for $name {
            fn eq(&self, other: &String) -> bool {
                &self.0 == other
            }
        }

        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(&self.0)
            }
        }

        impl Serialize for $name {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                serializer.serialize_newtype_variant("Text", $index, $key, &self.0)
            }
        }
    };
}

kind!(
    /// LaTeX math without `$`: verbatim in Markdown (inside `$…$`) and LaTeX, MathML in HTML
    /// (the template's `mathml` filter).
    Math,
    key::MATH,
    0
);
kind!(
    /// The problem's own markup with its paragraphs (the statement: paragraphs, lists, emphasis, `$…$` math; see
    /// `super::markup`): written out for each format.
    Markup,
    key::MARKUP,
    1
);
kind!(
    /// One line of the problem's markup (a question, a description, a note that quotes
    /// it): written out for each format, without paragraphs.
    MarkupLine,
    key::MARKUP_LINE,
    6
);
kind!(
    /// LaTeX code, e.g. a pgfplots or TikZ picture: kept in LaTeX, removed elsewhere.
    LatexCode,
    key::LATEX_CODE,
    2
);
kind!(
    /// An SVG element to inline: kept in Markdown and HTML, removed in LaTeX.
    InlineSvg,
    key::INLINE_SVG,
    3
);
kind!(
    /// A whole SVG document: a `data:` URI in HTML (for `<img src>`), removed elsewhere.
    SvgDocument,
    key::SVG_DOCUMENT,
    4
);
kind!(
    /// A file name the Markdown links to: percent-encoded there.
    FileName,
    key::FILE_NAME,
    5
);
