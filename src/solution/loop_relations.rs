//! A plane loop's dependent rates in symbols, as step 1 finds them from the loop's
//! derivative (`q̇₂ = −(1 + a sin(q₁ − q₃)/(b sin(q₁ + q₂ − q₃))) q̇₁`), for the sentence
//! that gives the dependent rates where the elimination in symbols is too long: relations
//! that hold at every state, not their numbers at the start.

use crate::mechanics::Model;
use crate::symbolic::{eval, latex, latex_factored, linear_split, Values};
use nalgebra::DMatrix;

/// `q̇_s = …` for each dependent rate `dependent[d]`, over the independent `rates`, from
/// the loop; `None` unless every coefficient equals `c`'s at `values`.
pub fn written(
    model: &Model,
    (dependent, rates): (&[usize], &[usize]),
    c: &DMatrix<f64>,
    values: &Values,
) -> Option<Vec<String>> {
    let problem = model.problem;
    let found = super::closure_loops::loop_rates(model)?;
    let symbols: Vec<_> = (rates.iter())
        .map(|&k| problem.coordinate_symbol(k, 1))
        .collect();
    let mut out = Vec::new();
    for (d, &s) in dependent.iter().enumerate() {
        let (_, value) = found.iter().find(|(i, _)| *i == s)?;
        let (coefficients, rest) = linear_split(value, &symbols).ok()?;
        if !rest.is_zero() {
            return None;
        }
        for (k, coefficient) in coefficients.iter().enumerate() {
            let x = eval(coefficient, values);
            if (x - c[(d, k)]).abs() > 1e-9 * c[(d, k)].abs().max(1.0) {
                return None;
            }
        }
        out.push(format!(
            "{} = {}",
            latex(&problem.coordinate_expr(s, 1)),
            latex_factored(value)
        ));
    }
    Some(out)
}
