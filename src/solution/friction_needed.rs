//! The friction a contact at rest needs to stick, in symbols where the rows give it
//! simply: with every rate zero and the no-slip condition in place, step 5's rows solved
//! for the friction and the normal force (the ladder: F_x = −(mg/2) tan θ, F_y = mg), and
//! the condition that friction can give that much, |F_t| ≤ μ|N|, in symbols (tan θ ≤ 2μ).
//! Written only where the symbols give the numbers of the solve.

use crate::equations::Derivation;
use crate::mechanics::FrictionSite;
use crate::symbolic::{eval, latex, simplify, substitute, Expr, Symbol};

/// The longest force in symbols (LaTeX characters) worth writing beside its number.
const LONGEST: usize = 120;

/// The sticking solution in symbols.
pub struct Needed {
    /// `F_x = …, \quad F_y = …`.
    pub forces: String,
    /// `|F_x| ≤ μ|F_y|` with each side in symbols, and the ratio where it cancels.
    pub condition: String,
}

/// The friction needed to stick at `site`, whose sticking solution is `tangential` along
/// its tangent and `normal`; `None` where the contact does not start at rest, has more
/// than one tangent, or the symbols do not come out short.
pub fn needed(
    derivation: &Derivation,
    site: &FrictionSite,
    tangential: &[f64],
    normal: f64,
) -> Option<Needed> {
    let problem = derivation.model.problem;
    let ([stick], [normal_symbol], [t]) = (&site.stick[..], &site.normal[..], tangential) else {
        return None;
    };
    let at_rest = (problem.coordinates.iter()).all(|c| c.rate == 0.0 && c.rate_expr.is_none());
    if !at_rest || problem.moves_with_time() {
        return None;
    }
    let system = &derivation.system;
    let column = |s: &Symbol| system.unknowns.iter().position(|u| u == s);
    let (f, n) = (column(&stick.unknown)?, column(normal_symbol)?);
    let rates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|k| problem.coordinate_symbol(k, 1))
        .collect();
    let still = |e: &Expr| simplify(&substitute(e, &|s| rates.contains(s).then(Expr::zero)));
    let a = (system.a.iter())
        .map(|row| row.iter().map(still).collect())
        .collect();
    let b = system.b.iter().map(still).collect();
    let v = super::switch_steps::initial_values(problem);
    let x = super::switch_steps::eliminate(a, b, &v)?;
    let (friction, pressing) = (simplify(&x[f]), simplify(&x[n]));
    let agrees = |e: &Expr, value: f64| {
        let found = eval(e, &v);
        found.is_finite() && (found - value).abs() <= 1e-6 * value.abs().max(1.0)
    };
    if !agrees(&friction, *t) || !agrees(&pressing, normal) || normal == 0.0 || *t == 0.0 {
        return None;
    }
    // The sizes, each by its sign at this state.
    let size = |e: &Expr, value: f64| match value < 0.0 {
        true => simplify(&(Expr::int(-1) * e.clone())),
        false => e.clone(),
    };
    let (needed, available) = (size(&friction, *t), size(&pressing, normal));
    let (friction_tex, pressing_tex) = (latex(&friction), latex(&pressing));
    if friction_tex.len() > LONGEST || pressing_tex.len() > LONGEST {
        return None;
    }
    let name = |s: &Symbol| latex(&Expr::sym(s.clone()));
    let (f_name, n_name) = (name(&stick.unknown), name(normal_symbol));
    let forces = format!("{f_name} = {friction_tex}, \\quad {n_name} = {pressing_tex}");
    let mu = latex(&site.coefficient);
    let mut condition = format!(
        "\\left|{f_name}\\right| = {} \\le {mu} \\left|{n_name}\\right| = {mu} {}",
        latex(&needed),
        grouped(&available)
    );
    // Where the normal force cancels out of the ratio (the ladder's m g), the ratio alone.
    let ratio = simplify(&(&needed / &available));
    let ratio_tex = latex(&ratio);
    if ratio_tex.len() < latex(&needed).len() && agrees(&ratio, t.abs() / normal.abs()) {
        condition.push_str(&format!(
            " \\quad \\Leftrightarrow \\quad {ratio_tex} \\le {mu}"
        ));
    }
    Some(Needed { forces, condition })
}

/// `e` in parentheses where it is a sum, to be multiplied by μ.
fn grouped(e: &Expr) -> String {
    match e.terms().len() > 1 {
        true => format!("\\left({}\\right)", latex(e)),
        false => latex(e),
    }
}
