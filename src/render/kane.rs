//! Kane's method as Kane and Levinson teach it: for each generalized speed `u_r`, the partial
//! velocity of every mass centre and the partial angular velocity of every body; then, row by
//! row, the generalized active force `F_r` and the generalized inertia force `F_r^*` apart,
//! before their sum `F_r + F_r^* = 0`.

use super::context::PartialVelocity;
use super::derived::shortest_tex;
use super::long::LONG_EQUATION;
use crate::equations::kane::partials;
use crate::equations::rows::{Equation, Groups, Sum};
use crate::equations::{Derivation, Method};
use crate::symbolic::print::{latex, latex_name};
use crate::symbolic::simplify::simplify;
use crate::symbolic::{add, Expr, Symbol};

/// The generalized speeds are the rates of the coordinates: `u_r = \dot{q}_r`; declared
/// speeds are written by name (step 1 defines them).
pub fn speed_tex(derivation: &Derivation, r: usize) -> String {
    let problem = derivation.model.problem;
    if problem.has_speeds() {
        return latex(&Expr::sym(problem.speed_symbol(r, 1)));
    }
    format!(
        "u_{{{}}} = {}",
        r + 1,
        latex(&problem.coordinate_expr(r, 1))
    )
}

/// The table of partial velocities (empty unless the method is Kane's): for each speed, one
/// line per body whose partial velocity or partial angular velocity is not zero, in `N`.
pub fn partial_velocities(derivation: &Derivation) -> Vec<PartialVelocity> {
    if derivation.method != Method::Kane {
        return Vec::new();
    }
    let model = &derivation.model;
    let problem = model.problem;
    let rates: Vec<Symbol> = problem.speed_symbols(1);
    let per_body: Vec<_> = model
        .order
        .iter()
        .map(|&body| {
            let state = &model.bodies[body.0];
            (
                body,
                partials(&state.center.velocity, &rates),
                partials(&state.omega, &rates),
            )
        })
        .collect();
    let zero = "\\mathbf{0}";
    let mut out = Vec::new();
    for r in 0..rates.len() {
        let mut first = true;
        for (body, v, w) in &per_body {
            // Plain brackets, so that TeX can break a long entry inside its table cell.
            let plain = |t: String| {
                t.replace("\\left(", "(")
                    .replace("\\right)", ")")
                    .replace("\\left[", "[")
                    .replace("\\right]", "]")
            };
            let v_tex = plain(shortest_tex(model, &v[r], *body));
            let w_tex = plain(shortest_tex(model, &w[r], *body));
            if v_tex == zero && w_tex == zero {
                continue;
            }
            let name = problem.body_name(*body);
            let symbol = latex_name(name);
            out.push(PartialVelocity {
                r: r + 1,
                speed_tex: if std::mem::take(&mut first) {
                    speed_tex(derivation, r)
                } else {
                    String::new()
                },
                body: name.to_string(),
                velocity_tex: format!(
                    "{{}}^{{N}}\\mathbf{{v}}^{{{symbol}^*}}_{{{}}} = {v_tex}",
                    r + 1
                ),
                omega_tex: format!(
                    "{{}}^{{N}}\\boldsymbol{{\\omega}}^{{{symbol}}}_{{{}}} = {w_tex}",
                    r + 1
                ),
            });
        }
    }
    out
}

/// Which of Kane's rows `row` is, 1-based (the speeds first, then the auxiliary speeds of
/// the requested reactions); `None` for a row that is not Kane's.
pub fn row_number(derivation: &Derivation, row: &Equation) -> Option<usize> {
    derivation
        .rows
        .iter()
        .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
        .position(|x| std::ptr::eq(x, row))
        .map(|r| r + 1)
}

/// The most characters of LaTeX a generalized force is written out with when its row's sum
/// is written out after it (about two lines): every term of it is in the sum, collected,
/// and a long force printed twice doubles the row.
const LONGEST_BESIDE_THE_SUM: usize = 400;

/// `F_r = …` and `F_r^* = …` of Kane's row `r`, simplified; each written as its definition
/// when it is too long to read expanded, or long and `sum_written_out`.
pub fn generalized_forces(
    groups: &Groups,
    r: usize,
    sum_written_out: bool,
    shown: impl Fn(&Expr) -> Expr,
) -> (String, String) {
    let active = shown(&simplify(&add(vec![
        groups.contact.clone(),
        groups.distance.clone(),
    ])));
    let inertia = shown(&simplify(&add(vec![
        groups.inertia_force.clone(),
        groups.inertia_torque.clone(),
    ])));
    // The value alone, since the definitions stand above the rows; the definition when the
    // value is too long to read.
    let written = |e: &Expr, name: String, definition: String| {
        let text = crate::symbolic::collect::latex_collected(e);
        if text.len() > LONG_EQUATION {
            format!("{name} = {definition} \\quad \\text{{(too long to print whole)}}")
        } else if sum_written_out && text.len() > LONGEST_BESIDE_THE_SUM {
            format!("{name} = {definition} \\quad \\text{{(collected in their sum below)}}")
        } else {
            format!("{name} = {text}")
        }
    };
    (
        written(
            &active,
            format!("F_{{{r}}}"),
            format!(
                "\\sum_{{P}} \\mathbf{{v}}^{{P}}_{{{r}}} \\cdot \\mathbf{{R}}_{{P}} + \\sum_{{B}} \\boldsymbol{{\\omega}}^{{B}}_{{{r}}} \\cdot \\mathbf{{T}}_{{B}}"
            ),
        ),
        written(
            &inertia,
            format!("F^{{*}}_{{{r}}}"),
            format!(
                "\\sum_{{B}} \\left(\\mathbf{{v}}^{{B^*}}_{{{r}}} \\cdot \\mathbf{{R}}^{{*}}_{{B}} + \\boldsymbol{{\\omega}}^{{B}}_{{{r}}} \\cdot \\mathbf{{T}}^{{*}}_{{B}}\\right)"
            ),
        ),
    )
}
