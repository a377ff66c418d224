//! The plots' tests: deterministic, labelled, thinned, and each line told apart.

use super::*;

fn sine() -> Vec<Series> {
    let points: Vec<(f64, f64)> = (0..=500)
        .map(|i| i as f64 * 0.01)
        .map(|t| (t, (3.0 * t).sin()))
        .collect();
    let cosine: Vec<(f64, f64)> = points.iter().map(|(t, _)| (*t, (3.0 * t).cos())).collect();
    vec![
        Series {
            name: Label::math("q_{1}", ""),
            points,
        },
        Series {
            name: Label::math("\\theta_{2}", ""),
            points: cosine,
        },
    ]
}

fn time() -> Label {
    Label::math("t", "(s)")
}

#[test]
fn svg_is_deterministic_and_labelled() {
    let value = Label::words("value");
    let first = line_plot("Coordinates", &time(), &value, &sine()).unwrap();
    let second = line_plot("Coordinates", &time(), &value, &sine()).unwrap();
    assert_eq!(first, second);
    assert!(first.starts_with("<svg"), "{}", &first[..60]);
    assert!(first.trim_end().ends_with("</svg>"));
    assert!(!first.contains("e-16"), "round-off in a tick label");
    for text in [
        "\nCoordinates\n",
        "\nt (s)\n",
        "\nq₁\n",
        "\nθ₂\n",
        "\n0\n",
        "<polyline",
    ] {
        assert!(first.contains(text), "missing {text}");
    }
    // The first line solid, the second dashed, in the plot and in its legend.
    let dashed = first
        .split("<polyline")
        .filter(|tag| tag.contains("stroke=\"#D62728\" stroke-dasharray=\"9,5\""))
        .count();
    assert_eq!(dashed, 2, "the second line and its legend's sample");
    let first_dashed = first
        .split("<polyline")
        .any(|tag| tag.contains("stroke=\"#1F77B4\" stroke-dasharray"));
    assert!(!first_dashed, "the first line is solid");
}

/// No line is dotted like the grid, in either format: each is solid or long dashes,
/// the third (E on V) a wide half-transparent band, in the plot and in its legend.
#[test]
fn no_line_is_dotted_and_the_third_is_a_band() {
    for (dash, _, _, pgf) in DASHES {
        assert!(!pgf.contains("dot") || pgf.contains("dashdot"), "{pgf}");
        assert!(dash.is_empty() || dash.split(',').any(|d| d.parse::<u32>().unwrap_or(0) >= 9));
    }
    let mut three = sine();
    three.push(Series {
        name: Label::math("E", ""),
        points: three[0].points.clone(),
    });
    let svg = line_plot("Energy", &time(), &Label::words("energy (J)"), &three).unwrap();
    let band = svg
        .split("<polyline")
        .filter(|tag| {
            tag.contains("stroke=\"#2CA02C\" stroke-opacity=\"0.45\"")
                && tag.contains("stroke-width=\"7\"")
        })
        .count();
    assert_eq!(band, 2, "the third line and its legend's sample");
}

/// Two plots to a row are drawn higher than three or four, whose row is low, and lower
/// than wide (7.6 cm, the template's width for two).
#[test]
fn two_plots_to_a_row_are_high() {
    let q = Label::math("q", "");
    for (row, height) in [
        (2, "height=3.6cm"),
        (3, "height=2.9cm"),
        (4, "height=2.9cm"),
    ] {
        let text = pgfplots(&time(), &q, &sine(), row);
        assert!(text.contains(height), "{row} to a row: {text}");
    }
}

#[test]
fn svg_of_nothing_is_an_error() {
    let q = Label::math("q", "");
    let empty = vec![Series {
        name: q.clone(),
        points: vec![(f64::NAN, 1.0)],
    }];
    assert!(matches!(
        line_plot("Empty", &time(), &q, &empty),
        Err(PlotError::NoData { .. })
    ));
    // A flat line still gets an axis.
    let flat = vec![Series {
        name: q.clone(),
        points: vec![(0.0, 2.0), (1.0, 2.0)],
    }];
    assert!(line_plot("Flat", &time(), &q, &flat).is_ok());
}

#[test]
fn a_legend_of_four_to_a_row_holds_what_its_narrower_plot_fits() {
    let named = |names: &[&str]| -> Vec<Series> {
        names
            .iter()
            .map(|n| Series {
                name: Label::math(n, ""),
                points: vec![(0.0, 0.0)],
            })
            .collect()
    };
    let energies = named(&["T", "V", "E = T + V"]);
    let angles = named(&["\\psi", "\\phi", "\\theta", "\\theta_{R}", "\\delta"]);
    // Three to a row: every entry of a short legend on one row, at most four.
    assert_eq!(legend_columns(&energies, 3), 3);
    assert_eq!(legend_columns(&angles, 3), 4);
    // Four to a row: "E = T + V" with its sample takes more than half the row.
    assert_eq!(legend_columns(&energies, 4), 1);
    assert_eq!(legend_columns(&angles, 4), 3);
}

#[test]
fn pgfplots_is_thinned_and_its_labels_are_math() {
    let energy = Label::math("E", "(J)");
    let text = pgfplots(&time(), &energy, &sine(), 3);
    assert!(text.starts_with("\\begin{tikzpicture}\n\\begin{axis}["));
    assert!(!text.contains("title="), "the caption is the title");
    assert!(text.contains("xlabel={$t$ (s)}"));
    assert!(text.contains("ylabel={$E$ (J)}"));
    assert!(text.contains("\\addlegendentry{$\\theta_{2}$}"));
    // Each line its own style, which its legend entry shows.
    assert!(text.contains("\\addplot+[mark=none, thick, solid] coordinates"));
    assert!(text.contains("\\addplot+[mark=none, thick, dashed] coordinates"));
    assert_eq!(text.matches("\\addplot").count(), 2);
    let points = text.lines().filter(|l| l.starts_with("  (")).count();
    assert_eq!(points, 2 * PGFPLOTS_MAX_POINTS);
    // First and last points kept, at fixed precision: sin(15) = 0.650288...
    assert!(text.contains("  (0,0)\n"));
    assert!(text.contains("  (5,0.650288)\n"));
}

#[test]
fn math_labels_print_as_unicode_in_pictures() {
    assert_eq!(unicode_of("\\theta_{12}"), "θ₁₂");
    assert_eq!(unicode_of("(E - E_{0})/|E_{0}|"), "(E − E₀)/|E₀|");
    assert_eq!(unicode_of("x_{\\mathrm{cart}}"), "x_cart");
    // As LaTeX and MathML set them: \phi is ϕ, \varphi φ.
    assert_eq!(unicode_of("\\phi_{2}"), "ϕ₂");
    assert_eq!(unicode_of("\\varphi"), "φ");
    assert_eq!(Label::math("E - E_{0}", "(J)").text, "E − E₀ (J)");
}

#[test]
fn thinning_keeps_ends() {
    let points: Vec<(f64, f64)> = (0..10).map(|i| (i as f64, 0.0)).collect();
    assert_eq!(
        thin(&points, 4),
        vec![(0.0, 0.0), (3.0, 0.0), (6.0, 0.0), (9.0, 0.0)]
    );
    assert_eq!(thin(&points, 20).len(), 10);
    assert_eq!(thin(&points, 1), vec![(0.0, 0.0), (9.0, 0.0)]);
}
