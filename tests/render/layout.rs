//! Nothing shrunk, nothing past the margin: the linearization's matrices are shown whole
//! when they fit the line and entry by entry when they do not, never scaled down.

use super::{binary, compile, overfull_lines, scratch};

/// The five-link chain's 5 × 5 matrices are wider than the page: listed entry by entry.
#[test]
fn linearization_is_never_shrunk() {
    let dir = scratch("linearize-layout");
    let tex = dir.join("chain.tex");
    let output = binary()
        .args(["explain", "--linearize", "--format", "latex", "-o"])
        .arg(&tex)
        .arg(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/problems/five-link-chain.json"
        ))
        .output()
        .expect("the binary runs");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let source = std::fs::read_to_string(&tex).expect("written");
    assert!(!source.contains("resizebox") && !source.contains("scalebox"));
    assert!(
        source.contains("\\widedisplay{"),
        "the matrices are not in \\widedisplay"
    );
    assert!(source.contains("entry by entry, the others 0: $M_{1,1} = "));
    if !crate::support::pdflatex_present("the handout") {
        return;
    }
    let log = compile(&dir, "chain-compiled", &source);
    let wide = overfull_lines(&log, &source);
    assert!(wide.is_empty(), "lines past the margin: {wide:?}");
}
