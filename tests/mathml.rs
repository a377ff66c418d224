//! The HTML worked solution's MathML against the structure rules of presentation MathML
//! (child counts of the script, fraction and root elements, tables, tokens), for every
//! bundled problem and every method.

use crate::support::{self, mathml, METHODS};
use std::path::PathBuf;

/// The validation problems whose worked solution takes under a few seconds. Left out:
/// `all-joints-3d` (8 to 16 s a method), `spherical-chain-3` and `whipple-bicycle` (over
/// 20 s a method; the bicycle's page is 43 MB).
const FAST_VALIDATION: [&str; 2] = ["sleeping-top", "ten-link-chain"];

#[test]
fn the_checker_finds_what_browsers_draw_wrongly() {
    let good = "<math><msup><mi>x</mi><mn>2</mn></msup><mspace width=\"1em\" /></math>";
    assert_eq!(mathml::check(good), Vec::<String>::new());
    let three = "<math><msup><mspace width=\"0.1667em\" /><mi>sin</mi><mn>2</mn></msup></math>";
    assert_eq!(mathml::check(three).len(), 1, "{:?}", mathml::check(three));
    let bad = [
        "<math><mfrac><mi>a</mi></mfrac></math>",
        "<math><msubsup><mi>a</mi><mi>b</mi></msubsup></math>",
        "<math><mtable><mtd><mi>a</mi></mtd></mtable></math>",
        "<math><mi><mn>1</mn></mi></math>",
        "<math><mrow><mi>a</mi></math>",
        "<math><mrow>a</mrow></math>",
        "<math><div>a</div></math>",
    ];
    for markup in bad {
        assert!(!mathml::check(markup).is_empty(), "{markup} passed");
    }
    assert_eq!(
        mathml::errors("<p>x</p><math><mi>a</mi></math><math><mroot><mi>a</mi></mroot></math>")
            .len(),
        1
    );
}

#[test]
fn every_html_page_has_valid_mathml() {
    let mut problems = support::all_problems();
    let validation = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("problems/validation");
    problems.extend(
        FAST_VALIDATION
            .iter()
            .map(|n| validation.join(format!("{n}.json"))),
    );
    let mut failures = Vec::new();
    let mut pages = 0;
    for problem in &problems {
        let stem = problem
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or("problem");
        for method in METHODS {
            // As printed: the run `course_words` and others read too.
            let out = support::handouts::explained(problem, method, "html", false);
            assert!(
                out.status.success(),
                "{stem} {method}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            let html = String::from_utf8_lossy(&out.stdout);
            assert!(html.contains("<math"), "{stem} {method}: no MathML");
            let errors = mathml::errors(&html);
            if let Some(first) = errors.first() {
                failures.push(format!(
                    "{stem} {method}: {} errors, first: {first}",
                    errors.len()
                ));
            }
            pages += 1;
        }
    }
    assert_eq!(pages, problems.len() * METHODS.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
