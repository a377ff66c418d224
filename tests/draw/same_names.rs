//! `draw` and the handout print one name for each force: a contact or body named by a word
//! is called by the handout's letter in both (the bowling ball's lane contact is P, its
//! friction -F^P_x), never by the word in one and the letter in the other.

use crate::support::{all_problems, run};
use std::collections::BTreeSet;

/// The `data-label` of every force arrow in `svg` (one or many pictures).
fn force_labels(svg: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for piece in svg.split("<g class=\"force").skip(1) {
        let tag = &piece[..piece.find('>').unwrap_or(piece.len())];
        if let Some(at) = tag.find("data-label=\"") {
            let rest = &tag[at + 12..];
            out.insert(rest[..rest.find('"').unwrap_or(0)].to_string());
        }
    }
    out
}

#[test]
fn draw_and_the_handout_name_every_force_alike() {
    let dir = std::env::temp_dir().join(format!("mbd-same-names-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let mut differ = Vec::new();
    let mut words = 0;
    for problem in all_problems() {
        let name = problem.file_stem().unwrap().to_string_lossy().into_owned();
        if name.starts_with("statics-") || name.starts_with("impact-") {
            continue;
        }
        let (pictures, page) = (dir.join(&name), dir.join(format!("{name}.html")));
        let p = problem.to_string_lossy();
        for args in [
            vec!["draw", &p, "-o", &pictures.to_string_lossy()],
            vec![
                "explain",
                &p,
                "--format",
                "html",
                "-o",
                &page.to_string_lossy(),
            ],
        ] {
            let out = run(&args);
            assert!(
                out.status.success(),
                "{args:?}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
        }
        let mut drawn = BTreeSet::new();
        for entry in std::fs::read_dir(&pictures).expect("pictures written") {
            let file = entry.expect("an entry").path();
            drawn.extend(force_labels(
                &std::fs::read_to_string(file).expect("a picture"),
            ));
        }
        let handout = force_labels(&std::fs::read_to_string(&page).expect("the handout"));
        let text = std::fs::read_to_string(problem).expect("the problem");
        if text.contains("\"lane\"") {
            words += 1;
            assert!(drawn.contains("-F^P_x"), "{name}: {drawn:?}");
        }
        if drawn != handout {
            differ.push(format!("{name}: draw {drawn:?}, handout {handout:?}"));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(words > 0, "the bowling ball's lane is among the problems");
    assert!(differ.is_empty(), "{}", differ.join("\n"));
}
