//! The templates compiled once per process: the embedded set on first use, and each
//! replacement from a `--templates` directory kept by its path and recompiled only when
//! its text changes (so that `serve` follows an edited template while `variants` and
//! `serve`'s rebuilds reuse the compiled one).

use super::{prepare, Format};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};

/// A template compiled with the filters registered, ready to render under its file name.
pub(super) type Compiled = Arc<tera::Tera>;

/// The embedded templates, compiled on first use, one slot per format.
static EMBEDDED: [OnceLock<Compiled>; 3] = [OnceLock::new(), OnceLock::new(), OnceLock::new()];

/// A replacement template's text and its compiled form.
type Kept = (String, Compiled);

/// The replacements compiled so far, by path.
static REPLACEMENTS: OnceLock<Mutex<HashMap<PathBuf, Kept>>> = OnceLock::new();

/// The embedded template of `format`, compiled once per process.
///
/// # Errors
/// Tera's error if the embedded template does not parse (a fault of the build, which the
/// tests rule out).
pub(super) fn embedded(format: Format) -> Result<Compiled, tera::Error> {
    let slot = &EMBEDDED[slot_of(format)];
    if let Some(compiled) = slot.get() {
        return Ok(compiled.clone());
    }
    let compiled = compile(format.template_name(), format.embedded())?;
    Ok(slot.get_or_init(|| compiled).clone())
}

/// The replacement at `path` whose text is `source`, compiled unless the same text from
/// the same path was compiled before in this process.
///
/// # Errors
/// Tera's error when the template does not parse.
pub(super) fn replacement(
    format: Format,
    path: &Path,
    source: &str,
) -> Result<Compiled, tera::Error> {
    let kept = REPLACEMENTS.get_or_init(|| Mutex::new(HashMap::new()));
    let known = |map: &HashMap<PathBuf, Kept>| {
        (map.get(path))
            .filter(|(text, _)| text == source)
            .map(|(_, compiled)| compiled.clone())
    };
    // A panic elsewhere while the map was held leaves it whole: every entry is inserted
    // in one step.
    if let Some(compiled) = known(&kept.lock().unwrap_or_else(|e| e.into_inner())) {
        return Ok(compiled);
    }
    let compiled = compile(format.template_name(), source)?;
    (kept.lock().unwrap_or_else(|e| e.into_inner()))
        .insert(path.to_path_buf(), (source.to_string(), compiled.clone()));
    Ok(compiled)
}

/// `source` compiled as the template `name`, the filters registered.
fn compile(name: &str, source: &str) -> Result<Compiled, tera::Error> {
    let mut tera = tera::Tera::default();
    // The HTML template's name ends in `.tera`, so Tera's default (`.html` only) would not
    // escape it.
    tera.autoescape_on(vec![".html.tera"]);
    prepare::register_filters(&mut tera);
    tera.add_raw_template(name, source)?;
    Ok(Arc::new(tera))
}

/// The slot of `format` among the embedded templates.
fn slot_of(format: Format) -> usize {
    match format {
        Format::Markdown => 0,
        Format::Latex => 1,
        Format::Html => 2,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The embedded template is compiled once: a second call hands back the same one.
    #[test]
    fn embedded_compiled_once() {
        let first = embedded(Format::Latex).unwrap();
        let second = embedded(Format::Latex).unwrap();
        assert!(Arc::ptr_eq(&first, &second));
    }

    /// A replacement is reused while its text is unchanged and compiled again when it
    /// changes, and a broken one is an error, not a kept entry.
    #[test]
    fn replacement_follows_its_text() {
        let path = Path::new("/nowhere/solution.md.tera");
        let a = replacement(Format::Markdown, path, "one").unwrap();
        let again = replacement(Format::Markdown, path, "one").unwrap();
        assert!(Arc::ptr_eq(&a, &again));
        let changed = replacement(Format::Markdown, path, "two").unwrap();
        assert!(!Arc::ptr_eq(&a, &changed));
        let rendered = changed
            .render("solution.md.tera", &tera::Context::new())
            .unwrap();
        assert_eq!(rendered, "two");
        assert!(replacement(Format::Markdown, path, "{{ open").is_err());
        let kept = replacement(Format::Markdown, path, "two").unwrap();
        assert!(Arc::ptr_eq(&changed, &kept));
    }
}
