//! The handout's matrices by names the problem does not use: with bodies A, B, C and M
//! the system matrix is not `A`, its right-hand side not `b` (body B's unit vectors are b̂),
//! in every method and format; a problem whose names are free keeps `A x = b`.

use crate::support::{explain, run};
use std::path::PathBuf;

fn fixture() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/names/bodies-a-b-c-m.json")
}

fn handout(method: &str, format: &str) -> String {
    let out = run(&[
        "explain".as_ref(),
        fixture().as_os_str(),
        "--method".as_ref(),
        method.as_ref(),
        "--format".as_ref(),
        format.as_ref(),
    ]);
    assert!(
        out.status.success(),
        "{method} {format}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn no_matrix_takes_the_name_of_a_body() {
    // Bodies A, B, C, M and constants m, L, g: A and b are taken, so the first free names
    // of the lists, S and f, name the matrix and the right-hand side.
    for method in ["motion-law", "newton-euler", "kane", "lagrange"] {
        for format in ["markdown", "latex"] {
            let text = handout(method, format);
            for taken in ["\\mathbf{A}", "A_{1,", "A_{ij}", "\\mathbf{b}\\", "b_{1} ="] {
                assert!(!text.contains(taken), "{method} {format}: {taken}");
            }
        }
        let markdown = handout(method, "markdown");
        // Where step 5 writes every row out the matrix form is left out (it would repeat
        // them); where it is printed, it is S x = f.
        if !markdown.contains("In matrix form") {
            assert!(method == "motion-law" || method == "kane", "{method}");
            continue;
        }
        assert!(
            markdown.contains("$\\mathbf{S}\\,\\mathbf{x} = \\mathbf{f}$"),
            "{method}"
        );
        // MathML writes a bold letter as its bold character (b̂ is a 𝐛 under a hat): the
        // matrix form reads 𝐒 𝐱 = 𝐟.
        let html = handout(method, "html");
        let matrix = |a: &str, b: &str| {
            format!("<mrow><mi>{a}</mi></mrow><mspace width=\"0.16666667em\" /><mrow><mi>𝐱</mi></mrow><mo>=</mo><mrow><mi>{b}</mi></mrow>")
        };
        assert!(html.contains(&matrix("𝐒", "𝐟")), "{method} html");
        assert!(!html.contains(&matrix("𝐀", "𝐛")), "{method} html");
    }
    // Names that are free stay as a textbook writes them.
    let pendulum = explain(
        "simple-pendulum",
        &["--method", "motion-law", "--format", "markdown"],
    );
    assert!(pendulum.contains("$\\mathbf{A}\\,\\mathbf{x} = \\mathbf{b}$"));
}

/// A matrix's name clashes with nothing the handout names: the rack and pinion prints the
/// energy E and has a body S and a constant b, so its system is A z = f, not E z = h; the
/// bowling ball's body B keeps the matrix A with the right-hand side f.
#[test]
fn no_matrix_takes_a_name_the_handout_gives_a_meaning() {
    for name in ["rack-and-pinion", "bowling-ball"] {
        let text = explain(name, &["--method", "motion-law", "--format", "markdown"]);
        assert!(
            text.contains("$\\mathbf{A}\\,\\mathbf{z} = \\mathbf{f}$"),
            "{name}"
        );
        assert!(!text.contains("\\mathbf{E}\\,"), "{name}");
        assert!(!text.contains("\\mathbf{S}\\,"), "{name}");
    }
}
