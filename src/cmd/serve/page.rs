//! The pages `serve` shows: the worked solution, the page of a problem's errors, and the
//! script that reloads a tab when a new version is built.

use crate::cli::{ExplainArgs, MethodArg};
use crate::Error;
use std::path::Path;

/// Shown until the first build is done; its script reloads the tab when it is.
pub(crate) const FIRST_BUILD: &str = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
<title>Writing the worked solution…</title>\n</head>\n<body>\n<p>The worked solution is being written; this page shows it as soon as it is done.</p>\n</body>\n</html>\n";

/// The worked solution of the file as it is now, or the page of its errors.
pub(crate) fn page(path: &Path, method: MethodArg) -> String {
    let args = ExplainArgs {
        common: crate::cli::Common {
            problem: path.to_path_buf(),
            method,
            set: Vec::new(),
            output: None,
            max_bodies: crate::cli::MAX_BODIES,
            max_coordinates: crate::cli::MAX_COORDINATES,
            max_work: crate::symbolic::budget::DEFAULT_LIMIT / 1_000_000,
        },
        format: crate::cli::FormatArg::Html,
        templates: None,
        student: false,
        both: false,
        linearize: None,
        verbose: false,
        statics: false,
    };
    // A panic deep in a rebuild must not take the server down with it.
    let built = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        crate::cmd::explain::rendered(&args, path, None, false)
    }));
    match built {
        Ok(Ok((html, _))) => html,
        Ok(Err(error)) => error_page(path, &error),
        Err(_) => error_page(
            path,
            &Error::Usage("the worked solution could not be built (an internal error)".into()),
        ),
    }
}

/// The errors `check` gives, as a page: each with its JSON path, column and hint.
fn error_page(path: &Path, error: &Error) -> String {
    use crate::render::escape_html as html;
    let mut items = String::new();
    match error {
        Error::Problem(errors) => {
            for e in &errors.0 {
                let mut place = html(&e.path);
                if let Some(column) = e.column {
                    place.push_str(&format!(", column {column}"));
                }
                items.push_str("<li>");
                if !place.is_empty() {
                    items.push_str(&format!("<code class=\"path\">{place}</code>: "));
                }
                items.push_str(&html(&e.message));
                if let Some(hint) = &e.hint {
                    items.push_str(&format!(
                        " <span class=\"hint\">(hint: {})</span>",
                        html(hint)
                    ));
                }
                items.push_str("</li>\n");
            }
        }
        other => items.push_str(&format!("<li>{}</li>\n", html(&other.one_line()))),
    }
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Errors in {name}</title>\n\
<style>body {{ font-family: Georgia, serif; max-width: 60rem; margin: 2rem auto; padding: 0 1rem; }} \
.errors li {{ margin: 0.4rem 0; }} code.path {{ color: #c0392b; font-weight: bold; }} .hint {{ color: #555; }}</style>\n\
</head>\n<body>\n<h1>{name} cannot be explained</h1>\n<p>{summary}</p>\n<ul class=\"errors\" id=\"problem-errors\">\n{items}</ul>\n\
<p>Fix the file and save it: this page updates by itself.</p>\n</body>\n</html>\n",
        name = html(&path.display().to_string()),
        summary = html(&match error {
            Error::Problem(errors) => format!(
                "The problem has {} error{}:",
                errors.0.len(),
                if errors.0.len() == 1 { "" } else { "s" }
            ),
            _ => "The worked solution could not be made:".into(),
        }),
    )
}

/// The tab's script: waits for news, reloads on a new version, says "rebuilding…" when a
/// rebuild lasts over a second.
const LIVE_SCRIPT: &str = r#"<div id="mbd-rebuilding" style="display:none;position:fixed;top:0;right:0;padding:0.4rem 0.8rem;background:#222;color:#fff;font:14px sans-serif;z-index:9">rebuilding…</div>
<script>
(function () {
  var version = VERSION, timer = null;
  var banner = document.getElementById("mbd-rebuilding");
  function ask() {
    fetch("/wait?v=" + version + "&b=" + (timer === null ? 0 : 1), { cache: "no-store" })
      .then(function (r) { return r.json(); })
      .then(function (news) {
        if (news.version !== version) { location.reload(); return; }
        if (news.building && timer === null) {
          timer = setTimeout(function () { banner.style.display = "block"; }, 1000);
        }
        ask();
      })
      .catch(function () { setTimeout(ask, 500); });
  }
  ask();
})();
</script>
"#;

/// The page with its live script, just before `</body>`.
pub(crate) fn with_script(page: &str, version: u64) -> String {
    let script = LIVE_SCRIPT.replace("VERSION", &version.to_string());
    match page.rfind("</body>") {
        Some(at) => format!("{}{script}{}", &page[..at], &page[at..]),
        None => format!("{page}{script}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_script_goes_before_the_end_of_the_body() {
        let page = with_script("<html><body><p>x</p></body></html>", 7);
        assert!(page.contains("var version = 7,"));
        assert!(page.ends_with("</script>\n</body></html>"));
    }

    #[test]
    fn an_error_page_names_the_json_path_column_and_hint() {
        let error = Error::Problem(crate::problem::ProblemErrors(vec![
            crate::problem::ProblemError {
                path: "bodies[0].mass".into(),
                column: Some(3),
                message: "unknown name `mm`".into(),
                hint: Some("did you mean `m`?".into()),
            },
        ]));
        let page = error_page(Path::new("p.json"), &error);
        assert!(page.contains("<code class=\"path\">bodies[0].mass, column 3</code>"));
        assert!(page.contains("did you mean `m`?"));
    }
}
