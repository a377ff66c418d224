//! The rules of the code's structure that docs/dev/architecture.md ("Invariants") states,
//! each read from the source tree: `symbolic` imports nothing of the project; `render`
//! reads no stage before the document; the Motion Law's planner is called by the Motion
//! Law's module and re-run only by `pipeline`; `solution` runs no stage and writes no
//! format; every source file within 600 lines; the same input gives the same bytes.

use crate::support::{problem, run_afresh};
use std::path::{Path, PathBuf};

/// The stages `render` must not read: everything before the document it writes.
const BEFORE_THE_DOCUMENT: [&str; 7] = [
    "problem",
    "mechanics",
    "plan",
    "equations",
    "numeric",
    "pipeline",
    "solution",
];

/// Every `.rs` file below `dir` (relative to the crate), sorted.
fn rust_files(dir: &str) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut folders = vec![PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(dir)];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).expect("a readable folder") {
            let path = entry.expect("a directory entry").path();
            if path.is_dir() && !path.ends_with("node_modules") {
                folders.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// The lines of `path` that are code: its comments (`//`, `//!`, `///`) left out.
fn code_lines(path: &Path) -> Vec<String> {
    let text = std::fs::read_to_string(path).expect("a readable source file");
    text.lines()
        .map(str::trim)
        .filter(|l| !l.starts_with("//"))
        .map(String::from)
        .collect()
}

/// `crate::NAME` paths of `path`'s code, for each stage in `names`, as "file: line"; a
/// grouped `use crate::{…}` that names one, over as many lines as it takes, as "file: group".
fn naming(path: &Path, names: &[&str]) -> Vec<String> {
    let lines = code_lines(path);
    let mut found: Vec<String> = (lines.iter())
        .filter(|line| {
            names.iter().any(|n| {
                line.contains(&format!("crate::{n}::")) || line.contains(&format!("crate::{n};"))
            })
        })
        .map(|line| format!("{}: {line}", path.display()))
        .collect();
    let code: String = lines.concat();
    found.extend(
        grouped_uses(&code)
            .into_iter()
            .filter(|group| names.iter().any(|n| group_names(group, n)))
            .map(|group| format!("{}: use crate::{group}", path.display())),
    );
    found
}

/// The `{…}` groups after `crate::` in `code`, braces matched, without white space.
fn grouped_uses(code: &str) -> Vec<String> {
    let mut groups = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("crate::{") {
        rest = &rest[at + "crate::".len()..];
        let mut depth = 0;
        let end = rest.char_indices().find_map(|(i, c)| {
            depth += match c {
                '{' => 1,
                '}' => -1,
                _ => 0,
            };
            (depth == 0).then_some(i)
        });
        let end = end.unwrap_or(rest.len() - 1);
        groups.push(
            rest[..=end]
                .chars()
                .filter(|c| !c.is_whitespace())
                .collect(),
        );
        rest = &rest[end + 1..];
    }
    groups
}

/// Whether a `{…}` group names the stage `name` at its top: `{name::…`, `,name,` or `{name}`.
fn group_names(group: &str, name: &str) -> bool {
    ["{", ","].iter().any(|before| {
        ["::", ",", "}"]
            .iter()
            .any(|after| group.contains(&format!("{before}{name}{after}")))
    })
}

#[test]
fn the_path_finder_sees_a_stage_named_in_code_and_not_in_a_comment() {
    let dir = std::env::temp_dir().join(format!("house-rules-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a scratch folder");
    let file = dir.join("probe.rs");
    std::fs::write(
        &file,
        "//! reads `crate::solution::pictures`\nuse crate::numeric::simulate;\n\
         use crate::{\n    symbolic::Expr,\n    pipeline::{run, Job},\n};\n",
    )
    .expect("written");
    let found = naming(&file, &BEFORE_THE_DOCUMENT);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(
        found[0].ends_with("use crate::numeric::simulate;"),
        "{found:?}"
    );
    assert!(found[1].contains("pipeline::{run,Job}"), "{found:?}");
}

#[test]
fn symbolic_imports_nothing_of_the_project() {
    let mut found = Vec::new();
    for path in rust_files("src/symbolic") {
        for line in code_lines(&path) {
            let mut rest = line.as_str();
            while let Some(at) = rest.find("crate::") {
                rest = &rest[at + "crate::".len()..];
                if !rest.starts_with("symbolic") {
                    found.push(format!("{}: {line}", path.display()));
                    break;
                }
            }
        }
    }
    assert!(
        found.is_empty(),
        "symbolic reads another part:\n{}",
        found.join("\n")
    );
}

#[test]
fn render_reads_no_stage_before_the_document() {
    let found: Vec<String> = (rust_files("src/render").iter())
        .flat_map(|p| naming(p, &BEFORE_THE_DOCUMENT))
        .collect();
    assert!(
        found.is_empty(),
        "render reads a stage:\n{}",
        found.join("\n")
    );
}

#[test]
fn only_the_motion_law_plans_and_only_pipeline_plans_again() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let planning: Vec<String> = (rust_files("src").iter())
        .filter(|p| !p.starts_with(root.join("src/plan")))
        .filter(|p| {
            code_lines(p).iter().any(|l| {
                (l.starts_with("use crate::plan::") && l.contains("choose"))
                    || l.contains("plan::choose(")
            })
        })
        .map(|p| {
            let relative = p.strip_prefix(&root).unwrap_or(p);
            relative.to_string_lossy().replace('\\', "/")
        })
        .collect();
    assert!(
        planning.iter().any(|p| p == "src/equations/motion_law.rs"),
        "the Motion Law's module no longer calls the planner: {planning:?}"
    );
    let elsewhere: Vec<&String> = (planning.iter())
        .filter(|p| *p != "src/equations/motion_law.rs" && !p.starts_with("src/pipeline/"))
        .collect();
    assert!(
        elsewhere.is_empty(),
        "the planner is called from {elsewhere:?}"
    );
}

#[test]
fn solution_runs_no_stage_and_writes_no_format() {
    let banned = [
        "pipeline::",
        "numeric::simulate",
        "Solver::",
        "render::draw::svg",
        "render::draw::tikz",
        "line_plot",
        "pgfplots",
    ];
    let found: Vec<String> = (rust_files("src/solution").iter())
        .flat_map(|p| code_lines(p).into_iter().map(move |l| (p.clone(), l)))
        .filter(|(_, l)| banned.iter().any(|b| l.contains(b)))
        .map(|(p, l)| format!("{}: {l}", p.display()))
        .collect();
    assert!(
        found.is_empty(),
        "solution runs or writes:\n{}",
        found.join("\n")
    );
}

#[test]
fn every_source_file_is_within_600_lines() {
    let long: Vec<String> = ["src", "tests", "benches", "fuzz"]
        .iter()
        .flat_map(|dir| rust_files(dir))
        .filter_map(|p| {
            let lines = std::fs::read_to_string(&p).ok()?.lines().count();
            (lines > 600).then(|| format!("{}: {lines} lines", p.display()))
        })
        .collect();
    assert!(long.is_empty(), "split by concern:\n{}", long.join("\n"));
}

#[test]
fn the_same_input_gives_the_same_bytes() {
    let path = problem("bowling-ball");
    for format in ["markdown", "latex", "html"] {
        let args = [
            "explain".as_ref(),
            path.as_os_str(),
            "--format".as_ref(),
            format.as_ref(),
        ];
        let (first, second) = (run_afresh(&args), run_afresh(&args));
        assert!(first.status.success(), "{format}: explain failed");
        assert!(
            first.stdout == second.stdout,
            "two runs of the same {format} handout differ"
        );
    }
}
