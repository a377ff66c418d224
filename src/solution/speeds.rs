//! Step 1 with declared speeds: each speed's definition, the kinematic differential
//! equations `u = W(q) q'` as a matrix, and their inverse `q' = W⁻¹(q) u`.

use crate::equations::Derivation;
use crate::render::context::{SpeedRow, SpeedsView};
use crate::render::text::{MarkupLine, Math};
use crate::symbolic::{add, latex, Expr};

/// The view of the declared speeds, or `None` when the speeds are the rates.
pub fn speeds(derivation: &Derivation) -> Option<SpeedsView> {
    let model = &derivation.model;
    let problem = model.problem;
    let speeds = model.speeds.as_ref()?;
    let u = |r: usize| Expr::sym(problem.speed_symbol(r, 1));
    let rows = problem
        .speeds
        .iter()
        .enumerate()
        .map(|(r, s)| SpeedRow {
            name_tex: Math::from(latex(&u(r))),
            definition_tex: Math::from(format!("{} = {}", latex(&u(r)), latex(&s.equals))),
            unit_tex: Math::from(crate::render::unit_tex(
                s.unit.as_deref().unwrap_or_default(),
            )),
            description: MarkupLine::from(s.description.clone().unwrap_or_default()),
        })
        .collect();
    let n = problem.coordinates.len();
    let column = |entries: Vec<String>| {
        format!(
            "\\left[\\begin{{array}}{{c}} {} \\end{{array}}\\right]",
            entries.join(" \\\\ ")
        )
    };
    let matrix = |m: &[Vec<Expr>]| {
        let body: Vec<String> = m
            .iter()
            .map(|row| row.iter().map(latex).collect::<Vec<_>>().join(" & "))
            .collect();
        format!(
            "\\left[\\begin{{array}}{{{}}} {} \\end{{array}}\\right]",
            "c".repeat(n),
            body.join(" \\\\ ")
        )
    };
    let us = column((0..n).map(|r| latex(&u(r))).collect());
    let rates = column(
        (0..n)
            .map(|s| latex(&problem.coordinate_expr(s, 1)))
            .collect(),
    );
    let inverse_tex = (0..n)
        .map(|s| {
            let value = add((0..n).map(|r| &speeds.inverse[s][r] * &u(r)));
            format!(
                "{} = {}",
                latex(&problem.coordinate_expr(s, 1)),
                latex(&value)
            )
        })
        .map(Math::from)
        .collect();
    Some(SpeedsView {
        rows,
        matrix_tex: Math::from(format!("{us} = {} {rates}", matrix(&speeds.w))),
        inverse_tex,
    })
}
