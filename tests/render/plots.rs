//! The plots as `explain -o` writes them: one quantity per axis, legends and axis labels
//! as symbols (Unicode in the SVG files, math in pgfplots), and the energy checked against
//! its conservation (its drift plotted only where the check fails).

use super::{binary, scratch};
use std::path::Path;

fn explain(problem: &str, output: &Path, format: &str) {
    let run = binary()
        .args(["explain", "--format", format, "-o"])
        .arg(output)
        .arg(
            Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("problems")
                .join(problem),
        )
        .output()
        .expect("the binary runs");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
}

/// Whether an SVG picture prints `text` as one of its `<text>` elements.
fn prints(svg: &str, text: &str) -> bool {
    svg.contains(&format!(">\n{text}\n</text>"))
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The `(x, y)` points of each `\addplot` of the pgfplots axis whose `ylabel` is `label`.
fn pgfplots_series(tex: &str, label: &str) -> Vec<Vec<(f64, f64)>> {
    let start = tex
        .find(&format!("ylabel={{{label}}}"))
        .unwrap_or_else(|| panic!("no axis labelled {label}"));
    let axis = &tex[start..start + tex[start..].find("\\end{axis}").expect("closed")];
    axis.split("\\addplot")
        .skip(1)
        .map(|plot| {
            plot.lines()
                .filter_map(|l| l.trim().strip_prefix('(')?.strip_suffix(')'))
                .map(|p| {
                    let (x, y) = p.split_once(',').expect("x,y");
                    (x.parse().expect("x"), y.parse().expect("y"))
                })
                .collect()
        })
        .collect()
}

#[test]
fn a_conservative_double_pendulum_plots_a_flat_energy_and_no_drift() {
    let dir = scratch("plots-pendulum");
    explain("double-pendulum-rods.json", &dir.join("dp.md"), "markdown");
    let angles = read(&dir.join("dp-coordinates.svg"));
    for legend in ["q₁", "q₂", "t (s)", "angle (rad)"] {
        assert!(prints(&angles, legend), "the angles' plot lacks {legend}");
    }
    let energy = read(&dir.join("dp-energy.svg"));
    // T and V each swing over a visible part of the axis: the energies themselves.
    for legend in ["T", "V", "E = T + V"] {
        assert!(prints(&energy, legend), "the energy plot lacks {legend}");
    }
    // The energy holds within the check: its drift is not plotted (it is when it fails).
    assert!(!dir.join("dp-energy-drift.svg").exists());

    explain("double-pendulum-rods.json", &dir.join("dp.tex"), "latex");
    let tex = read(&dir.join("dp.tex"));
    assert!(tex.contains("xlabel={$t$ (s)}"));
    assert!(tex.contains("\\addlegendentry{$q_{1}$}"));
    // No load does work: T + V stays put, so the total's line is flat and the drift is
    // the integrator's error alone, zero at the start.
    let energies = pgfplots_series(&tex, "energy (J)");
    assert_eq!(energies.len(), 3, "T, V and E");
    let e0 = energies[2][0].1;
    for (&(t, kinetic), (&(_, potential), &(_, total))) in
        energies[0].iter().zip(energies[1].iter().zip(&energies[2]))
    {
        // The printed values have six significant digits.
        assert!(
            (kinetic + potential - total).abs() < 1e-5 * (1.0 + total.abs()),
            "T + V ≠ E at t = {t}"
        );
        assert!(
            (total - e0).abs() < 1e-5 * (1.0 + e0.abs()),
            "E moved at t = {t}"
        );
    }
    // V and E from the datum at O, as the answers give them: by hand, the rods' energy
    // at the start (q1 = 0.7, q2 = −0.4, q1' = 1, q2' = −0.5).
    let (m1, l1, m2, l2, g) = (1.2, 0.6, 0.8, 0.4, 9.81);
    let (q1, q2, u1, u2): (f64, f64, f64, f64) = (0.7, -0.4, 1.0, -0.5);
    let kinetic = m1 * (l1 * u1).powi(2) / 6.0
        + m2 * ((l1 * u1).powi(2) / 2.0
            + (l2 * (u1 + u2)).powi(2) / 6.0
            + l1 * l2 * u1 * (u1 + u2) * q2.cos() / 2.0);
    let potential =
        -g * (m1 * l1 / 2.0 * q1.cos() + m2 * (l1 * q1.cos() + l2 / 2.0 * (q1 + q2).cos()));
    assert!(
        (energies[1][0].1 - potential).abs() < 1e-5 * potential.abs(),
        "V at the start is {} on the plot, {potential} from the datum",
        energies[1][0].1
    );
    assert!(
        (e0 - (kinetic + potential)).abs() < 1e-5 * e0.abs(),
        "E at the start is {e0} on the plot, {} from the datum",
        kinetic + potential
    );
    assert!(!tex.contains("(E - E_{0})/|E_{0}|"));
}

#[test]
fn angles_and_distances_are_never_on_one_axis() {
    let dir = scratch("plots-cart-pole");
    explain("cart-pole.json", &dir.join("cp.md"), "markdown");
    let angles = read(&dir.join("cp-coordinates.svg"));
    let positions = read(&dir.join("cp-positions.svg"));
    assert!(
        prints(&angles, "θ") && !prints(&angles, "x"),
        "the angles' plot"
    );
    assert!(
        prints(&positions, "x") && !prints(&positions, "θ"),
        "the positions' plot"
    );
    assert!(prints(&positions, "position (m)"));
}

/// Every pgfplots axis of `tex`: its `ylabel`, and each `\addplot`'s options and points.
type Axis = (String, Vec<(String, Vec<(f64, f64)>)>);

fn axes(tex: &str) -> Vec<Axis> {
    tex.split("\\begin{axis}")
        .skip(1)
        .map(|axis| {
            let axis = &axis[..axis.find("\\end{axis}").expect("closed")];
            let label = axis
                .split("ylabel={")
                .nth(1)
                .and_then(|l| l.split("},").next())
                .unwrap_or_default()
                .to_string();
            let plots = axis
                .split("\\addplot+[")
                .skip(1)
                .map(|plot| {
                    let options = plot[..plot.find(']').expect("options")].to_string();
                    let points = plot
                        .lines()
                        .filter_map(|l| l.trim().strip_prefix('(')?.strip_suffix(')'))
                        .map(|p| {
                            let (x, y) = p.split_once(',').expect("x,y");
                            (x.parse().expect("x"), y.parse().expect("y"))
                        })
                        .collect();
                    (options, points)
                })
                .collect();
            (label, plots)
        })
        .collect()
}

fn range(points: &[(f64, f64)]) -> f64 {
    let (lo, hi) = points
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
            (l.min(p.1), h.max(p.1))
        });
    hi - lo
}

/// The heavy top spins at 150 rad/s, precesses at about 3 rad/s and nods by hundredths of a
/// radian: on one axis the precession and the nutation lie flat beside the spin. Each angle
/// is on an axis whose other angles' ranges are within 8 times its own, and the energy's
/// three lines each have their own style (dashes), which the legend shows.
#[test]
fn angles_of_very_different_ranges_have_axes_of_their_own() {
    let dir = scratch("plots-top");
    explain("heavy-symmetric-top.json", &dir.join("top.tex"), "latex");
    let tex = read(&dir.join("top.tex"));
    let all = axes(&tex);
    let angles: Vec<&Axis> = all.iter().filter(|(l, _)| l == "angle (rad)").collect();
    assert_eq!(angles.len(), 3, "spin, precession and nutation apart");
    for (_, plots) in &angles {
        let ranges: Vec<f64> = plots.iter().map(|(_, p)| range(p)).collect();
        let (lo, hi) = ranges
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(l, h), r| (l.min(*r), h.max(*r)));
        assert!(hi <= 8.0 * lo, "ranges {ranges:?} on one axis");
    }
    // By hand: the spin φ turns about φ̇ t = 150 rad/s over the run, the precession ψ about
    // 3 rad/s: fifty times apart, never on one axis.
    let duration = all[0].1[0].1.last().expect("points").0;
    let spin = angles
        .iter()
        .flat_map(|(_, p)| p)
        .map(|(_, p)| range(p))
        .fold(0.0, f64::max);
    assert!(
        (spin / duration - 150.0).abs() < 15.0,
        "the spin's range {spin} over {duration} s"
    );
    let energy = all
        .iter()
        .find(|(l, _)| l == "energy (J)" || l == "energy change (J)")
        .expect("the energy's plot");
    let styles: Vec<&str> = energy.1.iter().map(|(o, _)| o.as_str()).collect();
    assert_eq!(styles.len(), 3, "T, V and E");
    assert!(
        styles[0].contains("solid")
            && styles[1].contains("dashed")
            && styles[2].contains("opacity"),
        "{styles:?}"
    );

    // The SVG plots alike: the energy's V dashed and E a wide, half-clear band, their
    // legend's samples too.
    let dir = scratch("plots-top-svg");
    explain("heavy-symmetric-top.json", &dir.join("top.md"), "markdown");
    let energy = read(&dir.join("top-energy.svg"));
    for pattern in ["stroke-dasharray=\"9,5\"", "stroke-opacity=\"0.45\""] {
        assert_eq!(
            energy.matches(pattern).count(),
            2,
            "{pattern}: line and sample"
        );
    }
    for file in [
        "top-coordinates.svg",
        "top-angles-2.svg",
        "top-nutation.svg",
    ] {
        assert!(dir.join(file).exists(), "{file}");
    }
}
