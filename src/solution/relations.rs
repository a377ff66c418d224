//! The dependent rates in symbols, `θ̇ = ẋ/r` rather than `θ̇ = 25 ẋ`: the velocity
//! constraints solved for the dependent rates by elimination in symbols, each relation
//! kept only where it is short and equals the numbers of `C` at the initial state.

use crate::mechanics::{Model, RowOrigin};
use crate::symbolic::{add, eval, latex, linear_split, simplify, Expr, Values};
use nalgebra::DMatrix;

/// The longest relation written in symbols (characters of LaTeX, which spends about
/// half of them on markup: `\dot{\theta} = \frac{(R - r) \dot{x}}{r y}` reads short).
const LONGEST: usize = 110;

/// The most dependent rates solved in symbols, and the most operations in the
/// constraints' coefficients: past them the relations are long (and the elimination
/// in symbols grows past what a handout can print, as the bicycle's six would).
const MOST_DEPENDENT: usize = 3;
const MOST_OPERATIONS: usize = 120;

/// One `q̇_s = Σ C_sk q̇_k` per dependent rate `dependent[d]`, over the independent
/// `rates`, in symbols, from as many independent velocity constraints as there are
/// dependent rates; `None` unless every relation is short and each equals `c` at `values`.
pub fn in_symbols(
    model: &Model,
    dependent: &[usize],
    rates: &[usize],
    c: &DMatrix<f64>,
    values: &Values,
) -> Option<Vec<String>> {
    let problem = model.problem;
    let n = problem.coordinates.len();
    let symbols: Vec<_> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
    // Each coefficient as step 1 prints it: a root of a square taken by the initial sign.
    let sign = super::tex::initial_sign(model);
    let printed = |c: Vec<Expr>| -> Vec<Expr> {
        (c.iter())
            .map(|e| crate::symbolic::roots_of_squares(&simplify(e), &sign))
            .collect()
    };
    let rows: Vec<Vec<Expr>> = (model.constraints.rows.iter())
        .filter(|r| !matches!(r.origin, RowOrigin::Prescribed(_)))
        .map(|r| {
            linear_split(&r.velocity, &symbols)
                .ok()
                .map(|(c, _)| printed(c))
        })
        .collect::<Option<Vec<Vec<Expr>>>>()?
        .into_iter()
        // A row without rates constrains none of them.
        .filter(|row| row.iter().any(|c| !simplify(c).is_zero()))
        .collect();
    if dependent.is_empty() || dependent.len() > MOST_DEPENDENT {
        return None;
    }
    let rows = independent_rows(rows, dependent, values)?;
    let operations: usize = rows.iter().flatten().map(Expr::operation_count).sum();
    if operations > MOST_OPERATIONS {
        return None;
    }
    let a_d: Vec<Vec<Expr>> = (rows.iter())
        .map(|row| dependent.iter().map(|&s| row[s].clone()).collect())
        .collect();
    // Column k of C: A_D x = −(column of the independent rate k).
    let mut columns = Vec::new();
    for &k in rates {
        let b: Vec<Expr> = rows.iter().map(|row| simplify(&(-&row[k]))).collect();
        columns.push(super::switch_steps::eliminate(a_d.clone(), b, values)?);
    }
    let rate = |i: usize| problem.coordinate_expr(i, 1);
    let mut written = Vec::new();
    for (d, &s) in dependent.iter().enumerate() {
        for (k, column) in columns.iter().enumerate() {
            let x = eval(&column[d], values);
            if (x - c[(d, k)]).abs() > 1e-9 * c[(d, k)].abs().max(1.0) {
                return None;
            }
        }
        let sum = simplify(&add(
            (columns.iter().zip(rates)).map(|(column, &k)| &column[d] * &rate(k))
        ));
        let sum = finished(model, sum, values);
        let text = format!(
            "{} = {}",
            latex(&rate(s)),
            crate::symbolic::latex_factored(&sum)
        );
        if text.len() > LONGEST {
            return None;
        }
        written.push(text);
    }
    Some(written)
}

/// A relation finished with what holds on the motion (a disc in a cylinder's
/// x² + y² = (R − r)²: θ̇ = (R − r)ẋ/(r y)): the sum, or the sum times a coordinate that
/// brings its terms over one denominator, reduced by each relation and divided back, where
/// that is shorter and equal at `values`.
fn finished(model: &Model, sum: Expr, values: &Values) -> Expr {
    let problem = model.problem;
    let at = eval(&sum, values);
    let mut best = sum;
    for (_, relation) in &model.constraints.relations {
        let mut candidates = vec![relation.reduce(&best)];
        for i in 0..problem.coordinates.len() {
            if !best.contains(&problem.coordinate_symbol(i, 0)) {
                continue;
            }
            let q = problem.coordinate_expr(i, 0);
            let over = relation.reduce(&simplify(&(&best * &q)));
            candidates.push(simplify(&(&over / &q)));
        }
        for candidate in candidates {
            let equal = (eval(&candidate, values) - at).abs() <= 1e-9 * at.abs().max(1.0);
            if equal && candidate.operation_count() < best.operation_count() {
                best = candidate;
            }
        }
    }
    best
}

/// As many of `rows` as there are dependent rates, whose coefficients of those rates are
/// independent at `values`: a row that repeats the others there adds nothing. `None` when
/// there are too few.
fn independent_rows(
    rows: Vec<Vec<Expr>>,
    dependent: &[usize],
    values: &Values,
) -> Option<Vec<Vec<Expr>>> {
    let mut kept: Vec<Vec<Expr>> = Vec::new();
    for row in rows {
        if kept.len() == dependent.len() {
            break;
        }
        let candidate: Vec<&Vec<Expr>> = kept.iter().chain(std::iter::once(&row)).collect();
        let numbers = DMatrix::from_fn(candidate.len(), dependent.len(), |r, k| {
            eval(&candidate[r][dependent[k]], values)
        });
        if numbers.rank(1e-9) == candidate.len() {
            kept.push(row);
        }
    }
    (kept.len() == dependent.len()).then_some(kept)
}
