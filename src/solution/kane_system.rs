//! Kane's system past six unknowns (the rolling coin's nine, the bicycle): its rows, as step
//! 5 writes them collected by the unknowns, are the linear system itself. A student reads the
//! coefficients off them and solves the system numerically; a table of where its entries are
//! would tell nothing more (docs/conventions/rows.md).

use crate::equations::{Derivation, Method};

/// The sentence that says so, in markup; `None` for another method or a system small
/// enough for its matrix form to be written out.
pub fn rows_are_the_system(derivation: &Derivation) -> Option<String> {
    let linear = rows_are_linear(derivation)?;
    Some(format!(
        "{}; they are solved with the numbers of the initial state.",
        linear.trim_end_matches('.')
    ))
}

/// Its first half alone, where the solution in numbers follows and says the rest.
pub fn rows_are_linear(derivation: &Derivation) -> Option<String> {
    let n = derivation.system.unknowns.len();
    if derivation.method != Method::Kane || n <= super::matrix_by_value::MOST_COLUMNS {
        return None;
    }
    let rows = derivation.system.a.len();
    Some(format!("The {rows} rows are linear in the {n} unknowns."))
}
