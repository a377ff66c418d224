//! Step 6's plots show what the handout says of them, over every bundled problem: each
//! energy that changes spans a visible part of its axis (a ladder's loss of 0.049 J is not
//! drawn on a 0–120 J axis), and no coordinate is drawn as a flat line (the collar's θ and y
//! that stay at 0 are said in words).

use crate::support::all_problems;
use crate::support::handouts::{bundled, handout_of, two_at_a_time};

/// A plot's y label and its series, each a legend and its values.
type Axis = (String, Vec<(String, Vec<f64>)>);

/// The plots of a LaTeX handout.
fn plots(tex: &str) -> Vec<Axis> {
    let mut found = Vec::new();
    for axis in tex.split("\\begin{axis}[").skip(1) {
        let axis = axis.split("\\end{axis}").next().unwrap_or("");
        let label = axis.split("ylabel={").nth(1).unwrap_or("");
        let label = label.split("},").next().unwrap_or("").to_string();
        let mut series = Vec::new();
        for plot in axis.split("coordinates {").skip(1) {
            let (points, rest) = plot.split_once("};").unwrap_or((plot, ""));
            let values: Vec<f64> = (points.lines())
                .filter_map(|l| l.trim().strip_prefix('(')?.strip_suffix(')'))
                .filter_map(|p| p.split_once(',')?.1.parse().ok())
                .collect();
            let legend = rest.split("\\addlegendentry{").nth(1).unwrap_or("");
            let legend = legend.lines().next().unwrap_or("").trim_end_matches('}');
            series.push((legend.to_string(), values));
        }
        found.push((label, series));
    }
    found
}

/// The largest value less the smallest.
fn range(values: &[f64]) -> f64 {
    let high = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let low = values.iter().copied().fold(f64::INFINITY, f64::min);
    high - low
}

/// What is wrong with the plots of `tex` (the handout of `name`).
fn wrong_plots(name: &str, tex: &str) -> Vec<String> {
    let mut wrong = Vec::new();
    for (label, series) in plots(tex) {
        let all: Vec<f64> = series.iter().flat_map(|s| s.1.clone()).collect();
        let span = range(&all);
        let size = all.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (legend, values) in &series {
            let moved = range(values);
            if label.contains("energy") {
                // A constant energy is a flat line, as said of it; one that changes spans
                // a twentieth of its axis at least.
                if moved > 1e-4 * size && moved < 0.05 * span {
                    wrong.push(format!(
                        "{name}: {legend} spans {moved} of its axis's {span} ({label})"
                    ));
                }
            } else if moved == 0.0 && !values.is_empty() {
                wrong.push(format!("{name}: {legend} is a flat line ({label})"));
            }
        }
    }
    wrong
}

#[test]
fn every_plotted_quantity_shows_on_its_axis() {
    let problems = all_problems();
    let wrong = two_at_a_time(&problems, |path| {
        let name = path.file_stem().unwrap_or_default().to_string_lossy();
        match handout_of(path, "motion-law", "latex") {
            Some(tex) => wrong_plots(&name, &tex),
            None => Vec::new(),
        }
    });
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The ladder's loss and its kinetic energy each on an axis where they show, named as what
/// they are; the collar's θ and y said to stay at 0, not drawn.
#[test]
fn small_changes_are_plotted_as_changes_and_still_coordinates_said() {
    let ladder = bundled("ladder-about-to-slip", "motion-law", "latex");
    assert!(ladder.contains("\\addlegendentry{$E - E_{0}$}"));
    assert!(ladder.contains("Energy changes from the start"));
    assert!(wrong_plots("ladder", &ladder).is_empty());
    let collar = bundled("collar-on-rough-rod", "motion-law", "latex");
    assert!(
        collar.contains("$y$ stays at 0 m and $\\theta$ at 0 rad throughout,"),
        "no sentence for the still coordinates"
    );
    assert!(!collar.contains("\\addlegendentry{$\\theta$}"));
    assert!(!collar.contains("\\addlegendentry{$y$}"));
    // The test finds a loss drawn too small to see.
    let hidden = "\\begin{axis}[\n  ylabel={energy (J)},\n]\n\\addplot+[] coordinates {\n  (0,100)\n  (1,99.95)\n};\n\\addlegendentry{$E$}\n\\addplot+[] coordinates {\n  (0,0)\n  (1,100)\n};\n\\addlegendentry{$T$}\n\\end{axis}";
    assert_eq!(wrong_plots("made up", hidden).len(), 1);
}
