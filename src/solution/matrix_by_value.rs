//! Whether step 5's matrix goes by its values at the initial state, found before every
//! entry of a large system is simplified and printed only to be measured.

use crate::equations::LinearSystem;
use crate::symbolic::{latex_collected, latex_factored, Expr};

/// The most columns the whole table has.
pub(super) const MOST_COLUMNS: usize = 6;
/// The most characters of LaTeX the entries may print in all (about five pages). Past it,
/// entries are given by their values at the initial state, a large system being solved by
/// its numbers anyway: the few rows step 5 writes by name beside the table of dots, or all
/// of A and b as tables when more rows are by name.
pub(super) const ENTRIES_BUDGET: usize = 24_000;

/// The entries of `b`: collected by the products of rates, each coefficient's factor out,
/// as step 5 writes an equation, when that is shorter than factored.
pub(super) fn b_texts(b: &[Expr]) -> Vec<String> {
    b.iter()
        .map(|e| {
            let (factored, collected) = (latex_factored(e), latex_collected(e));
            if collected.len() < factored.len() {
                collected
            } else {
                factored
            }
        })
        .collect()
}

/// Whether `matrix` will give `A` and `b` by their values, known before every entry is
/// simplified and printed: where neither the whole table (up to six unknowns, every row
/// written out) nor the few rows by name beside the table of dots come first, the entries
/// of the `listed` rows are printed one by one until they pass [`ENTRIES_BUDGET`], as
/// `matrix` counts them. Where they do not pass it, `false`, and `matrix` goes on as it
/// would have. Asked only where Kane's or Lagrange's rows do not stand whole in step 5 and
/// no sliding row replaces a row.
pub(super) fn by_value_early(
    system: &LinearSystem,
    by_name: &[bool],
    listed: &impl Fn(usize) -> bool,
    shown: &impl Fn(&Expr) -> Expr,
) -> bool {
    let by_entries = by_name.iter().any(|&b| b);
    let named_rows = by_name.iter().filter(|&&named| named).count();
    let whole_first = system.unknowns.len() <= MOST_COLUMNS && !by_entries;
    let few_by_name = named_rows > 0 && 4 * named_rows <= system.a.len();
    if whole_first || few_by_name {
        return false;
    }
    let mut printed = 0;
    for i in (0..system.a.len()).filter(|&i| listed(i)) {
        for entry in &system.a[i] {
            printed += latex_factored(&shown(entry)).len();
            if printed > ENTRIES_BUDGET {
                return true;
            }
        }
        printed += b_texts(&[shown(&system.b[i])])[0].len();
        if printed > ENTRIES_BUDGET {
            return true;
        }
    }
    false
}
