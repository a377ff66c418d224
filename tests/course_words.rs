//! Every bundled handout, by every method, in the words of a course and with its algebra
//! finished: no name of the program's own (a generated constraint's `teeth.height`), no
//! word of its algorithms (pivoting, Newton's iterations, a starting guess, a command
//! line), no child or parent for the bodies a joint connects, and no s² + c² of one angle
//! left unsimplified in a sum.

use crate::support::run;
use std::path::PathBuf;

const METHODS: [&str; 4] = ["motion-law", "kane", "newton-euler", "lagrange"];

/// Every format a handout is written in.
const FORMATS: [&str; 3] = ["markdown", "latex", "html"];

/// The text a reader sees: an HTML page without its scripts, styles and tags (a script's
/// `parentNode` is no word of the handout's); Markdown and LaTeX whole.
fn readable(text: &str, format: &str) -> String {
    if format != "html" {
        return text.to_string();
    }
    let mut out = text.to_string();
    for (open, close) in [("<script", "</script>"), ("<style", "</style>")] {
        while let Some(start) = out.find(open) {
            let Some(length) = out[start..].find(close) else {
                break;
            };
            out.replace_range(start..start + length + close.len(), " ");
        }
    }
    let mut plain = String::with_capacity(out.len());
    let mut in_tag = false;
    for c in out.chars() {
        match c {
            '<' => in_tag = true,
            '>' if in_tag => {
                in_tag = false;
                plain.push(' ');
            }
            _ if !in_tag => plain.push(c),
            _ => {}
        }
    }
    plain
}

/// Words a course does not use in a handout.
const NOT_COURSE_WORDS: [&str; 12] = [
    "mesh.distance",
    "teeth.height",
    ".height left out",
    "pivoting",
    "Newton's method: ",
    "explain --verbose",
    "guess",
    "child",
    "parent",
    "dampers and friction only remove",
    "of the 2 slowest",
    "iterations;",
];

/// Every bundled problem (`problems/*.json`; the validation problems, some of which take
/// minutes a handout, are checked against their references elsewhere).
fn bundled() -> Vec<PathBuf> {
    crate::support::all_problems()
}

/// The signed terms of a line of math, split at ` + `, ` - ` and ` = ` outside braces, with any
/// brackets around a term taken off.
fn terms(line: &str) -> Vec<(char, String)> {
    let mut out = Vec::new();
    let (mut depth, mut sign, mut current) = (0i32, '+', String::new());
    let chars: Vec<char> = line.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        match c {
            '{' | '(' | '[' => depth += 1,
            '}' | ')' | ']' => depth -= 1,
            _ => {}
        }
        let split = depth <= 1
            && i + 2 < chars.len()
            && chars[i] == ' '
            && matches!(chars[i + 1], '+' | '-' | '=')
            && chars[i + 2] == ' ';
        if split {
            out.push((sign, current.clone()));
            // Each side of an equation starts with a term of its own.
            sign = if chars[i + 1] == '=' {
                '+'
            } else {
                chars[i + 1]
            };
            current.clear();
            i += 3;
            continue;
        }
        current.push(c);
        i += 1;
    }
    out.push((sign, current));
    out.into_iter()
        .map(|(s, t)| {
            let t = t
                .trim()
                .trim_start_matches(['[', '('])
                .trim_end_matches([']', ')']);
            (s, t.to_string())
        })
        .collect()
}

/// A pair of terms of `line` that differ only by s²_θ against c²_θ of one angle θ, with
/// one sign: their sum is the term without either.
fn pythagorean_pair(line: &str) -> Option<String> {
    let found = terms(line);
    for (sign, term) in &found {
        let mut from = 0;
        while let Some(at) = term[from..].find("s_{") {
            let start = from + at;
            let rest = &term[start + 3..];
            // The angle: the braces' content, nested braces allowed.
            let mut depth = 1;
            let end = rest.char_indices().find_map(|(k, c)| {
                match c {
                    '{' => depth += 1,
                    '}' => depth -= 1,
                    _ => {}
                }
                (depth == 0).then_some(k)
            })?;
            let angle = &rest[..end];
            let after = &rest[end + 1..];
            if let Some(tail) = after.strip_prefix("^{2}") {
                let other = format!("{}c_{{{angle}}}^{{2}}{tail}", &term[..start]);
                if found.iter().any(|(s, t)| s == sign && *t == other) {
                    return Some(format!("{term} + {other}"));
                }
            }
            from = start + 3;
        }
    }
    None
}

#[test]
fn the_pythagorean_pair_is_found_and_only_it() {
    let line = "-R g m + [R m \\ddot{x} s_{\\theta}^{2} + R m \\ddot{x} c_{\\theta}^{2}] = 0";
    assert!(pythagorean_pair(line).is_some());
    for fine in [
        "R m \\ddot{x} s_{\\theta}^{2} - R m \\ddot{x} c_{\\theta}^{2} = 0",
        "R m \\ddot{x} s_{\\theta}^{2} + m \\ddot{x} c_{\\theta}^{2} = 0",
        "s_{\\theta}^{2} + c_{\\phi}^{2} = 0",
        "s_{\\theta} c_{\\theta} = 0",
    ] {
        assert_eq!(pythagorean_pair(fine), None, "{fine}");
    }
}

/// Every handout in Markdown, LaTeX and HTML, two at a time.
#[test]
fn every_bundled_handout_speaks_a_course_and_finishes_its_algebra() {
    let paths = bundled();
    let jobs: Vec<(PathBuf, &str, &str)> = (paths.iter())
        .flat_map(|p| METHODS.iter().map(move |m| (p.clone(), *m)))
        .flat_map(|(p, m)| FORMATS.iter().map(move |f| (p.clone(), m, *f)))
        .collect();
    let found = std::sync::Mutex::new(Vec::new());
    let next = std::sync::atomic::AtomicUsize::new(0);
    std::thread::scope(|scope| {
        for _ in 0..2 {
            scope.spawn(|| loop {
                let k = next.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
                let Some((path, method, format)) = jobs.get(k) else {
                    break;
                };
                let out = run(&[
                    "explain".as_ref(),
                    path.as_os_str(),
                    "--method".as_ref(),
                    method.as_ref(),
                    "--format".as_ref(),
                    format.as_ref(),
                ]);
                if !out.status.success() {
                    // A method a problem cannot take is refused; other tests see to it.
                    continue;
                }
                let text = readable(&String::from_utf8_lossy(&out.stdout), format);
                let name = path.file_stem().unwrap_or_default().to_string_lossy();
                let mut wrong = found.lock().expect("lock");
                for word in NOT_COURSE_WORDS {
                    if let Some(line) = text.lines().find(|l| l.contains(word)) {
                        wrong.push(format!("{name} ({method}, {format}): `{word}` in: {line}"));
                    }
                }
                for line in text.lines() {
                    if let Some(pair) = pythagorean_pair(line) {
                        wrong.push(format!("{name} ({method}, {format}): s² + c² left: {pair}"));
                    }
                }
            });
        }
    });
    let wrong = found.into_inner().expect("lock");
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}
