//! Hostile text in a problem file, end to end through `explain`: LaTeX that compiles
//! without reading any file the text names, HTML without a script, and Markdown where
//! template syntax stays literal text.

use super::scratch;
use serde_json::Value;
use std::path::Path;
use std::process::Command;

/// Text that would act if it reached TeX, a browser or Tera unescaped. `canary.tex` is a
/// file in the working directory that announces itself in the log if TeX ever reads it.
const HOSTILE: [&str; 11] = [
    r"\input{/etc/passwd}",
    r"\input{canary}\immediate\write18{touch pwned}",
    // Math spans: only the allowed commands pass as math, the rest is text.
    r"$\input{canary}$ $\write18{touch pwned}$ $\immediate\write18{touch pwned}$",
    r"$x^{$ $}$ $\frac{a}$ $a^b^c$ $\def\x{\input{canary}}\x$ $\catcode`\^=7$",
    "$</script><script>alert(2)</script>$ $<img src=x onerror=alert(3)>$",
    "*emph <script>alert(4)</script>* `\\input{canary}` **{{ x }}**",
    "- \\input{canary}\n1. $\\input{canary}$\n2. {{ x }}",
    "<script>alert(1)</script><SCRIPT src=x></SCRIPT>",
    "{{ x }} {{ __tera_context }}",
    "{% raw %}{% include \"/etc/passwd\" %}{% endraw %}",
    "$x$ 100% & # _ ~ ^ \\\\ } { \\end{document}",
];

/// The simple pendulum with every text field (title, statement, descriptions, units, the
/// questions' texts) replaced by hostile text.
fn hostile_problem(dir: &Path) -> std::path::PathBuf {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/simple-pendulum.json"
    ))
    .expect("read");
    let mut problem: Value = serde_json::from_str(&text).expect("JSON");
    let all = HOSTILE.join(" ");
    problem["title"] = Value::from(format!("Pendulum {}", HOSTILE[0]));
    problem["statement"] = Value::from(HOSTILE.join("\n\n"));
    let mut i = 0;
    let mut next = || {
        i += 1;
        Value::from(HOSTILE[i % HOSTILE.len()])
    };
    for section in ["constants", "coordinates", "bodies"] {
        if let Some(map) = problem[section].as_object_mut() {
            for entry in map.values_mut() {
                if let Some(fields) = entry.as_object_mut() {
                    fields.insert("description".into(), next());
                    if section != "bodies" {
                        fields.insert("unit".into(), next());
                    }
                }
            }
        }
    }
    problem["bodies"]["bob"]["description"] = Value::from(all);
    if let Some(questions) = problem["find"]["questions"].as_array_mut() {
        for question in questions {
            question["text"] = next();
        }
    }
    let path = dir.join("hostile.json");
    std::fs::write(&path, serde_json::to_string_pretty(&problem).expect("JSON")).expect("written");
    path
}

fn explain(problem: &Path, format: &str, out: &Path, student: bool) -> String {
    let mut command = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"));
    command
        .arg("explain")
        .arg(problem)
        .args(["--format", format, "-o"])
        .arg(out);
    if student {
        command.arg("--student");
    }
    let output = command.output().expect("the binary runs");
    assert_eq!(
        output.status.code(),
        Some(0),
        "explain --format {format}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    std::fs::read_to_string(out).expect("written")
}

#[test]
fn latex_compiles_and_reads_no_file_the_text_names() {
    let dir = scratch("hostile-latex");
    let problem = hostile_problem(&dir);
    std::fs::write(
        dir.join("canary.tex"),
        "\\immediate\\write16{CANARY-WAS-READ}\n",
    )
    .expect("written");
    for (name, student) in [("solution", false), ("handout", true)] {
        let tex = explain(&problem, "latex", &dir.join(format!("{name}.tex")), student);
        assert!(
            !tex.contains(r"\input{/etc/passwd}"),
            "{name}: the command survived unescaped"
        );
        assert!(
            !tex.contains(r"\input{canary}"),
            "{name}: the command survived unescaped"
        );
        assert!(
            !tex.contains(r"\write18"),
            "{name}: the command survived unescaped"
        );
        if !crate::support::pdflatex_present("the hostile LaTeX") {
            continue;
        }
        let typeset = crate::support::pdflatex_afresh(&dir.join(format!("{name}.tex")));
        assert!(typeset.compiled(), "{name}: {}", typeset.faults());
        assert!(typeset.pages() > 0, "{name}: no PDF");
        let log = typeset.log;
        // pdflatex logs every file it opens as "(path"; the canary logs itself if read.
        assert!(
            !log.contains("(/etc/passwd"),
            "{name}: /etc/passwd was read"
        );
        assert!(
            !log.contains("CANARY-WAS-READ"),
            "{name}: canary.tex was read"
        );
        assert!(!dir.join("pwned").exists(), "{name}: a shell command ran");
    }
    std::fs::remove_dir_all(&dir).expect("removed");
}

#[test]
fn html_holds_no_script() {
    let dir = scratch("hostile-html");
    let problem = hostile_problem(&dir);
    for (name, student) in [("solution", false), ("handout", true)] {
        let html = explain(&problem, "html", &dir.join(format!("{name}.html")), student);
        // Step 6's motion controls are the one script allowed (cli.md, "draw --animate").
        let page = crate::support::without_motion_script(&html).to_lowercase();
        assert!(!page.contains("<script"), "{name}: a script element");
        assert!(!page.contains("<\\/script"), "{name}");
        // The text is shown, escaped, not dropped.
        assert!(
            html.contains("&lt;script&gt;alert(1)&lt;&#x2F;script&gt;")
                || html.contains("&lt;script&gt;alert(1)&lt;/script&gt;"),
            "{name}: the hostile title is not shown as text"
        );
        assert!(
            html.contains("{{ x }}"),
            "{name}: template syntax was not kept as text"
        );
    }
    std::fs::remove_dir_all(&dir).expect("removed");
}

#[test]
fn markdown_keeps_template_syntax_literally() {
    let dir = scratch("hostile-markdown");
    let problem = hostile_problem(&dir);
    for (name, student) in [("solution", false), ("handout", true)] {
        let source = explain(
            &problem,
            "markdown",
            &dir.join(format!("{name}.md")),
            student,
        );
        // Raw HTML passes through Markdown renderers: there must be none.
        assert!(
            !source.to_lowercase().contains("<script"),
            "{name}: a script element"
        );
        let md = unescape(&source);
        // Tera would have replaced `{{ x }}` (or failed on an unknown variable), dropped
        // the raw tags and tried to include /etc/passwd: all of it is still text.
        assert!(
            md.contains("{{ x }}"),
            "{name}: `{{{{ x }}}}` was evaluated"
        );
        assert!(
            md.contains("{{ __tera_context }}"),
            "{name}: the context was dumped"
        );
        assert!(md.contains("{% raw %}"), "{name}: raw tags were evaluated");
        assert!(
            md.contains("{% include"),
            "{name}: the include was evaluated"
        );
        assert!(
            !md.contains("root:x:0:0"),
            "{name}: /etc/passwd was included"
        );
    }
    std::fs::remove_dir_all(&dir).expect("removed");
}

/// The text that a CommonMark renderer shows for `markdown`'s backslash escapes: a
/// backslash before ASCII punctuation stands for that character.
fn unescape(markdown: &str) -> String {
    let mut out = String::with_capacity(markdown.len());
    let mut chars = markdown.chars().peekable();
    while let Some(c) = chars.next() {
        match chars.peek() {
            Some(&next) if c == '\\' && next.is_ascii_punctuation() => {
                out.push(next);
                chars.next();
            }
            _ => out.push(c),
        }
    }
    out
}

#[test]
fn unescape_follows_commonmark() {
    assert_eq!(unescape(r"\{\{ x \}\} \_a\\b c\d"), r"{{ x }} _a\b c\d");
}

/// The elements a CommonMark renderer makes from Markdown itself, and those of the
/// free-body diagrams the handout writes inline as SVG.
const MARKDOWN_ELEMENTS: [&str; 39] = [
    "svg",
    "g",
    "path",
    "line",
    "circle",
    "rect",
    "text",
    "tspan",
    "title",
    "style",
    "defs",
    "marker",
    "polygon",
    "polyline",
    "p",
    "em",
    "strong",
    "h1",
    "h2",
    "h3",
    "h4",
    "h5",
    "h6",
    "ul",
    "ol",
    "li",
    "code",
    "pre",
    "blockquote",
    "hr",
    "br",
    "img",
    "a",
    "table",
    "thead",
    "tbody",
    "tr",
    "th",
    "td",
];

/// What a reader of the Markdown handout sees: the file rendered by a CommonMark renderer
/// with its defaults (raw HTML passes through, as on most sites that show Markdown).
#[test]
fn markdown_rendered_by_a_commonmark_renderer_runs_nothing() {
    let dir = scratch("hostile-commonmark");
    let problem = hostile_problem(&dir);
    for (name, student) in [("solution", false), ("handout", true)] {
        let source = explain(
            &problem,
            "markdown",
            &dir.join(format!("{name}.md")),
            student,
        );
        let mut page = String::new();
        pulldown_cmark::html::push_html(&mut page, pulldown_cmark::Parser::new(&source));
        // Escaped text never holds `<`: every `<` in the page opens an element the
        // renderer made from Markdown, and only Markdown's own elements may appear.
        for tag in page
            .split('<')
            .skip(1)
            .map(|rest| &rest[..rest.find('>').unwrap_or(rest.len())])
        {
            let element = tag
                .trim_start_matches('/')
                .split([' ', '/'])
                .next()
                .unwrap_or("");
            assert!(
                MARKDOWN_ELEMENTS.contains(&element.to_lowercase().as_str()),
                "{name}: an element Markdown does not make: <{tag}>"
            );
            let lower = tag.to_lowercase();
            assert!(
                !lower.contains(" on") && !lower.contains("javascript:"),
                "{name}: an active attribute: <{tag}>"
            );
            if element == "img" {
                assert!(
                    tag.starts_with(&format!("img src=\"{name}-")) && tag.contains(".svg\""),
                    "{name}: an image that is not one of its plots: <{tag}>"
                );
            }
        }
        // The hostile text is shown, escaped, not dropped.
        assert!(
            page.contains("&lt;script&gt;alert(1)&lt;/script&gt;"),
            "{name}: the script text is not shown as text"
        );
        assert!(page.contains("{{ x }}"), "{name}: template text lost");
    }
    std::fs::remove_dir_all(&dir).expect("removed");
}

/// The pictures of `draw` (SVG), with every text field of the problem hostile: nothing in
/// them can act in a browser, and every `&` starts an entity.
#[test]
fn svg_pictures_hold_no_markup_from_the_problem() {
    let dir = scratch("hostile-svg");
    let problem = hostile_problem(&dir);
    let out = dir.join("pictures");
    let output = Command::new(env!("CARGO_BIN_EXE_mbd-tutor"))
        .arg("draw")
        .arg(&problem)
        .arg("-o")
        .arg(&out)
        .output()
        .expect("the binary runs");
    assert_eq!(
        output.status.code(),
        Some(0),
        "draw: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    let mut seen = 0;
    for entry in std::fs::read_dir(&out).expect("pictures written") {
        let path = entry.expect("entry").path();
        if path.extension().and_then(|e| e.to_str()) != Some("svg") {
            continue;
        }
        seen += 1;
        let svg = std::fs::read_to_string(&path).expect("read");
        let lower = svg.to_lowercase();
        for active in [
            "<script",
            "<img",
            "<iframe",
            "<foreignobject",
            "javascript:",
            "onerror=",
        ] {
            assert!(!lower.contains(active), "{}: `{active}`", path.display());
        }
        for (at, _) in svg.match_indices('&') {
            let entity = &svg[at..svg.len().min(at + 10)];
            assert!(
                entity.find(';').is_some_and(|end| end > 1
                    && entity[1..end]
                        .chars()
                        .all(|c| c.is_ascii_alphanumeric() || c == '#')),
                "{}: a bare `&` at byte {at}: {entity:?}",
                path.display()
            );
        }
    }
    assert!(seen > 0, "draw wrote no SVG");
    std::fs::remove_dir_all(&dir).expect("removed");
}
