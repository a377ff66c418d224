//! The linearization section of the worked solution (`explain --linearize`): the
//! linearized equations `M δq'' + C δq' + K δq = 0`, the state matrix, the eigenvalues and
//! a table of the modes. Strings are of the kinds of [`crate::render::text`].

use crate::numeric::{is_stable, Linearization, Shape};
use crate::problem::Problem;
use crate::render::text::Math;
use crate::render::{EigenvalueRow, LinearizationSection, MatrixEntries, ModeRow};
use crate::symbolic::{fixed, latex};
use nalgebra::DMatrix;

/// `amsmath` typesets at most this many columns in a `bmatrix`; larger matrices are not
/// printed (`mbd-tutor linearize` gives them).
pub const MOST_COLUMNS: usize = 10;

/// A number in LaTeX math: `1.5`, `-2`, `3 \times 10^{-5}`.
pub fn tex_number(x: f64) -> String {
    let text = fixed(x);
    match text.split_once('e') {
        Some((mantissa, exponent)) => {
            let exponent = exponent.trim_start_matches('+');
            format!("{mantissa} \\times 10^{{{exponent}}}")
        }
        None => text,
    }
}

fn complex_tex(re: f64, im: f64) -> String {
    match (re == 0.0, im == 0.0) {
        (_, true) => tex_number(re),
        (true, false) => format!("{} i", tex_number(im)),
        (false, false) if im < 0.0 => format!("{} - {} i", tex_number(re), tex_number(-im)),
        _ => format!("{} + {} i", tex_number(re), tex_number(im)),
    }
}

fn bmatrix(m: &DMatrix<f64>) -> String {
    let rows: Vec<String> = m
        .row_iter()
        .map(|row| {
            row.iter()
                .map(|x| tex_number(*x))
                .collect::<Vec<_>>()
                .join(" & ")
        })
        .collect();
    format!(
        "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
        rows.join(" \\\\ ")
    )
}

/// The nonzero entries of `m` as `letter_{i,j} = value`, row by row.
fn entries(letter: &str, m: &DMatrix<f64>) -> Vec<String> {
    let mut out = Vec::new();
    for (i, row) in m.row_iter().enumerate() {
        for (j, x) in row.iter().enumerate().filter(|(_, x)| **x != 0.0) {
            out.push(format!(
                "{letter}_{{{},{}}} = {}",
                i + 1,
                j + 1,
                tex_number(*x)
            ));
        }
    }
    out
}

fn column(entries: &[String]) -> String {
    format!(
        "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
        entries.join(" \\\\ ")
    )
}

/// The section for `l`, a linearization of `problem`.
pub fn section(problem: &Problem, l: &Linearization) -> LinearizationSection {
    let n = problem.coordinates.len();
    let name = |i: usize, order: u8| latex(&problem.coordinate_expr(i, order));
    let mut state: Vec<String> = (0..n)
        .map(|i| format!("{} = {}", name(i, 0), tex_number(l.q[i])))
        .collect();
    state.extend((0..n).map(|i| format!("{} = {}", name(i, 1), tex_number(l.rates[i]))));
    if l.t != 0.0 {
        state.push(format!("t = {}", tex_number(l.t)));
    }
    let steady_note = if l.accelerations.iter().any(|a| a.abs() > 1e-9) {
        format!(
            "The second derivatives are not zero here ({}): the state is not steady, and the linearization describes the motion near it for an instant only.",
            (0..n)
                .map(|i| format!("{}'' = {}", problem.coordinates[i].name, fixed(l.accelerations[i])))
                .collect::<Vec<_>>()
                .join(", ")
        )
    } else {
        String::new()
    };
    let small = n <= MOST_COLUMNS;
    let mut listed = MatrixEntries::default();
    let (m_tex, c_tex, k_tex) = match (&l.matrices, small) {
        (Some(m), true) => {
            listed.m_tex = Math::all(entries("M", &m.m));
            listed.c_tex = Math::all(entries("C", &m.c));
            listed.k_tex = Math::all(entries("K", &m.k));
            (
                format!("\\mathbf{{M}} = {}", bmatrix(&m.m)),
                format!("\\mathbf{{C}} = {}", bmatrix(&m.c)),
                format!("\\mathbf{{K}} = {}", bmatrix(&m.k)),
            )
        }
        _ => Default::default(),
    };
    let deltas: Vec<String> = (0..n).map(|i| format!("\\delta {}", name(i, 0))).collect();
    let mut z: Vec<String> = (0..n).map(|i| name(i, 0)).collect();
    z.extend((0..n).map(|i| name(i, 1)));
    let a_tex = if 2 * n <= MOST_COLUMNS {
        listed.a_tex = Math::all(entries("A", &l.a));
        format!("\\mathbf{{A}} = {}", bmatrix(&l.a))
    } else {
        String::new()
    };
    let eigenvalues = l
        .eigen
        .iter()
        .enumerate()
        .map(|(i, e)| EigenvalueRow {
            value_tex: Math::from(format!(
                "\\lambda_{{{}}} = {}",
                i + 1,
                complex_tex(e.value.re, e.value.im)
            )),
        })
        .collect();
    let modes = l
        .modes
        .iter()
        .enumerate()
        .map(|(i, m)| ModeRow {
            figure: super::mode_shape::figure(&l.variables, &m.shape, i + 1),
            index: i + 1,
            natural_frequency: fixed(m.natural_frequency_hz),
            damped_frequency: fixed(m.damped_frequency_hz),
            damping_ratio: fixed(m.damping_ratio),
            shape_tex: Math::from(column(&match &m.shape {
                Shape::Real(values) => values.iter().map(|x| tex_number(*x)).collect::<Vec<_>>(),
                Shape::Complex(values) => values
                    .iter()
                    .map(|(magnitude, phase)| {
                        format!(
                            "{}\\, e^{{{} i}}",
                            tex_number(*magnitude),
                            tex_number(*phase)
                        )
                    })
                    .collect(),
            })),
        })
        .collect();
    let stability = if is_stable(&l.eigen, 0.0) {
        "No eigenvalue has a positive real part: the state is stable to first order (only marginally where eigenvalues lie on the imaginary axis, where the neglected terms decide)."
    } else {
        "An eigenvalue has a positive real part: small disturbances grow, and the state is unstable."
    };
    LinearizationSection {
        state_tex: Math::from(state.join(",\\ ")),
        steady_note,
        equation_tex: "\\mathbf{M}\\,\\delta\\ddot{\\mathbf{q}} + \\mathbf{C}\\,\\delta\\dot{\\mathbf{q}} + \\mathbf{K}\\,\\delta\\mathbf{q} = \\mathbf{0}".into(),
        q_tex: Math::from(format!("\\delta\\mathbf{{q}} = {}", column(&deltas))),
        m_tex: Math::from(m_tex),
        c_tex: Math::from(c_tex),
        k_tex: Math::from(k_tex),
        a_tex: Math::from(a_tex),
        z_tex: Math::from(format!(
            "\\mathbf{{{}}} = {}",
            crate::problem::MatrixNames::of(problem).z,
            column(&z)
        )),
        entries: listed,
        eigenvalues,
        modes,
        stability: stability.into(),
    }
}
