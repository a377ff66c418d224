//! Kane's generalized inertia force of one speed written body by body,
//! `F^*_r = F^*_{r,A} + F^*_{r,B} + …` with `F^*_{r,B} = v^{B*}_r · R^*_B + ω^B_r · T^*_B`:
//! what a student sums, where the whole would be too long to read beside the row's sum.

use crate::equations::{partials, Derivation};
use crate::mechanics::Vector;
use crate::symbolic::{latex_collected, latex_name, simplify, Expr, Symbol};

/// The most bodies whose contributions are written apart: a longer chain's are long, and
/// its rows are read by the names of step 4.
const MOST_BODIES: usize = 4;

/// The most characters of LaTeX one body's contribution may take, broken over lines (see
/// [`super::aligned::line`]): a longer one is read better in the row's sum.
const LONGEST_LINE: usize = 900;

/// `F^*_r` (or `F̃^*_r` with independent speeds) of Kane's speed row `r` (1-based) as the
/// sum of each body's contribution, then each contribution, as an `aligned` block; `whole`
/// is the row's `F^*_r = …` as written so far, kept as the last line when it is a formula.
/// `None` for an auxiliary row, where fewer than two bodies contribute, or where one
/// contribution is itself too long to read.
pub fn inertia_by_body(
    derivation: &Derivation,
    r: usize,
    whole: &str,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Option<String> {
    let model = &derivation.model;
    if model.order.len() > MOST_BODIES {
        return None;
    }
    let problem = model.problem;
    let frames = &model.frames;
    let inertia = derivation.inertia();
    // The partial velocities of speed r: of the coordinates' rates, or combined by the
    // dependent speeds' weights (C in symbols) into the constrained ones.
    let (rates, weights): (Vec<Symbol>, Vec<Expr>) = match &derivation.dependent_speeds {
        None => {
            let rates = problem.speed_symbols(1);
            let mut weights = vec![Expr::zero(); rates.len()];
            *weights.get_mut(r.checked_sub(1)?)? = Expr::one();
            (rates, weights)
        }
        Some(speeds) if !speeds.at_each_state && r <= speeds.independent.len() => {
            let n = problem.coordinates.len();
            let rates = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
            (rates, speeds.independent_weights(r - 1, n))
        }
        Some(_) => return None,
    };
    let combined = |list: &[Vector]| -> Vector {
        Vector::sum(
            list.iter()
                .zip(&weights)
                .filter(|(_, w)| !w.is_zero())
                .map(|(v, w)| v.scaled(w)),
        )
    };
    let tilde = if derivation.dependent_speeds.is_some() {
        "\\tilde{F}"
    } else {
        "F"
    };
    // With the rates as speeds the block stands where the whole was too long: a shorter
    // line, as a body's part of a long sum is itself long.
    let longest = if derivation.dependent_speeds.is_some() {
        LONGEST_LINE
    } else {
        LONGEST_LINE * 2 / 3
    };
    let mut names = Vec::new();
    let mut lines = Vec::new();
    for &body in &model.order {
        let state = &model.bodies[body.0];
        let v = combined(&partials(&state.center.velocity, &rates));
        let w = combined(&partials(&state.omega, &rates));
        let term = &inertia.force[body.0].dot(&v, frames) + &inertia.torque[body.0].dot(&w, frames);
        let term = shown(&simplify(&term));
        if term.is_zero() {
            continue;
        }
        let name = format!(
            "{tilde}^{{*}}_{{{r},{}}}",
            latex_name(problem.body_name(body))
        );
        let text = latex_collected(&term);
        if text.len() > longest {
            return None;
        }
        lines.push(super::aligned::line(&name, "=", &text));
        names.push(name);
    }
    if names.len() < 2 {
        return None;
    }
    super::aligned::sum_of_parts(
        &format!("{tilde}^{{*}}_{{{r}}}"),
        &names,
        lines,
        whole,
        model.order.len() == 1,
    )
}
