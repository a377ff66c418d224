//! A class's submissions graded into one gradebook: each submission against the variant
//! it names (`"variant": "variant-07.json"`, found beside the key), the worked solution of
//! each variant derived once, one CSV row per student.

use super::{grade, read, Reference, Report};
use crate::equations::Method;
use crate::solution::csv_cell;
use crate::Error;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One submission of the class and what became of it.
struct Graded {
    file: String,
    student: String,
    variant: String,
    /// The grade, or why the submission could not be graded.
    result: Result<Report, String>,
}

/// The variant files the key lists (its `file` column).
fn variants_of(key: &Path) -> Result<Vec<String>, Error> {
    let text = std::fs::read_to_string(key).map_err(|source| Error::Io {
        path: key.to_path_buf(),
        source,
    })?;
    let mut lines = text.lines();
    let header = lines.next().unwrap_or("");
    if header.split(',').next() != Some("file") {
        return Err(Error::Usage(format!(
            "{}: not a key written by `variants` (its first column is not `file`)",
            key.display()
        )));
    }
    Ok(lines
        .filter_map(|l| l.split(',').next())
        .map(|f| f.trim_matches('"').to_string())
        .filter(|f| !f.is_empty())
        .collect())
}

/// The JSON files of `dir`, sorted by name.
fn submissions_in(dir: &Path) -> Result<Vec<PathBuf>, Error> {
    let entries = std::fs::read_dir(dir).map_err(|source| Error::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    let mut files: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "json") && p.is_file())
        .collect();
    files.sort();
    Ok(files)
}

/// Grades every submission in `dir` against its variant beside `key` by `method`, and
/// gives the gradebook as CSV.
///
/// # Errors
/// An unreadable directory or key. A submission that cannot be graded gets its row, with
/// the reason in the `note` column.
pub fn grade_batch(dir: &Path, key: &Path, method: Method) -> Result<String, Error> {
    let listed = variants_of(key)?;
    let home = key.parent().unwrap_or(Path::new("."));
    let mut graded: Vec<Graded> = Vec::new();
    let mut by_variant: BTreeMap<String, Vec<(usize, super::Submission)>> = BTreeMap::new();
    for path in submissions_in(dir)? {
        let file = path
            .file_name()
            .map(|f| f.to_string_lossy().to_string())
            .unwrap_or_default();
        if listed.contains(&file) && same_dir(dir, home) {
            continue;
        }
        let stem = path
            .file_stem()
            .map(|f| f.to_string_lossy().to_string())
            .unwrap_or_default();
        let read = std::fs::read_to_string(&path)
            .map_err(|e| e.to_string())
            .and_then(|text| read(&text).map_err(|e| e.to_string()));
        let mut entry = Graded {
            file,
            student: stem,
            variant: String::new(),
            result: Err(String::new()),
        };
        match read {
            Err(why) => entry.result = Err(why),
            Ok(submission) => {
                if let Some(s) = &submission.student {
                    entry.student = s.clone();
                }
                match &submission.variant {
                    None => entry.result = Err("the submission names no `variant`".into()),
                    Some(v) if !listed.contains(v) => {
                        entry.variant = v.clone();
                        entry.result = Err(format!("{v} is not in {}", key.display()));
                    }
                    Some(v) => {
                        entry.variant = v.clone();
                        by_variant
                            .entry(v.clone())
                            .or_default()
                            .push((graded.len(), submission));
                    }
                }
            }
        }
        graded.push(entry);
    }
    for (variant, submissions) in by_variant {
        let problem = crate::problem::load_file(&home.join(&variant));
        let problem = match problem {
            Ok(p) => p,
            Err(e) => {
                for (i, _) in submissions {
                    graded[i].result = Err(format!("{variant}: {e}"));
                }
                continue;
            }
        };
        let asked = super::asked_questions(submissions.iter().map(|(_, s)| s));
        match Reference::answering(&problem, method, &asked) {
            Ok(reference) => {
                for (i, submission) in submissions {
                    graded[i].result = Ok(grade(&reference, &submission));
                }
            }
            Err(e) => {
                for (i, _) in submissions {
                    graded[i].result = Err(format!("{variant}: {}", e.one_line()));
                }
            }
        }
    }
    Ok(gradebook(&graded))
}

fn same_dir(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(x), Ok(y)) => x == y,
        _ => false,
    }
}

/// A cell a spreadsheet reads as text: one that would start a formula (`=`, `+`, `-`,
/// `@`, a tab or a carriage return) gets a leading apostrophe, then RFC 4180 quoting.
pub fn neutralised(text: &str) -> String {
    let starts_formula = text.starts_with(['=', '+', '-', '@', '\t', '\r']);
    match starts_formula {
        true => csv_cell(&format!("'{text}")),
        false => csv_cell(text),
    }
}

/// The gradebook: student, file, variant, one column per item (the union, in order of
/// first appearance), the total, out of, and a note for a submission not graded.
fn gradebook(graded: &[Graded]) -> String {
    let mut columns: Vec<String> = Vec::new();
    for g in graded {
        if let Ok(report) = &g.result {
            for item in &report.items {
                if !columns.contains(&item.item) {
                    columns.push(item.item.clone());
                }
            }
        }
    }
    let mut header: Vec<String> = ["student", "file", "variant"].map(String::from).to_vec();
    header.extend(columns.iter().cloned());
    header.extend(["score", "out_of", "note"].map(String::from));
    let mut out = line(&header);
    for g in graded {
        let mut row = vec![g.student.clone(), g.file.clone(), g.variant.clone()];
        match &g.result {
            Ok(report) => {
                for column in &columns {
                    let score = report.items.iter().find(|i| &i.item == column);
                    row.push(score.map(|i| number(i.score)).unwrap_or_default());
                }
                row.push(number(report.score()));
                row.push(report.out_of().to_string());
                row.push(String::new());
            }
            Err(why) => {
                row.extend(columns.iter().map(|_| String::new()));
                row.extend([String::new(), String::new(), why.replace('\n', " ")]);
            }
        }
        out.push_str(&line(&row));
    }
    out
}

fn number(x: f64) -> String {
    crate::solution::full_digits(x)
}

fn line(cells: &[String]) -> String {
    let cells: Vec<String> = cells.iter().map(|c| neutralised(c)).collect();
    format!("{}\n", cells.join(","))
}

#[cfg(test)]
mod tests {
    use super::neutralised;

    #[test]
    fn formulas_are_neutralised() {
        assert_eq!(neutralised("=1+1"), "'=1+1");
        assert_eq!(neutralised("@SUM(A1)"), "'@SUM(A1)");
        assert_eq!(neutralised("-2"), "'-2");
        assert_eq!(neutralised("s017"), "s017");
        assert_eq!(neutralised("a,b"), "\"a,b\"");
    }
}
