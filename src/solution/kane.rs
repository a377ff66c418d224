//! Kane's method as Kane and Levinson teach it: for each generalized speed `u_r`, the partial
//! velocity of every mass centre and the partial angular velocity of every body; then, row by
//! row, the generalized active force `F_r` and the generalized inertia force `F_r^*` apart,
//! before their sum `F_r + F_r^* = 0`.

use super::long::LONG_EQUATION;
use super::tex::shortest_tex;
use crate::equations::{partials, Derivation, Method};
use crate::mechanics::{same_at, sample_states, Model, Vector};
use crate::plan::{Equation, Groups, Sum};
use crate::problem::BodyId;
use crate::render::context::PartialVelocity;
use crate::symbolic::{add, latex, linear_split, simplify, Expr, Symbol, Values};

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

/// The rate of coordinate `r`, `\\dot{x}`: what a partial velocity is taken with when the
/// rows combine the coordinates' rates by `C` evaluated at each state.
fn rate_tex(derivation: &Derivation, r: usize) -> String {
    latex(&derivation.model.problem.coordinate_expr(r, 1))
}

/// The table of partial velocities (empty unless the method is Kane's): for each speed, one
/// line per body whose partial velocity or partial angular velocity is not zero, in `N`.
pub fn partial_velocities(derivation: &Derivation) -> Vec<PartialVelocity> {
    if derivation.method != Method::Kane {
        return Vec::new();
    }
    // With C evaluated at each state, the rows combine the generalized forces of the
    // coordinates' rates by name: the table gives those rates' partial velocities.
    let by_rate = derivation
        .dependent_speeds
        .as_ref()
        .is_some_and(|speeds| speeds.at_each_state);
    if let Some(speeds) = derivation.dependent_speeds.as_ref().filter(|_| !by_rate) {
        return super::independent::partial_velocities(derivation, speeds);
    }
    let model = &derivation.model;
    let problem = model.problem;
    let rates: Vec<Symbol> = problem.speed_symbols(1);
    let accelerations: Vec<Symbol> = problem.speed_symbols(2);
    let states = sample_states(model);
    let inertia = derivation.inertia();
    let per_body: Vec<_> = model
        .order
        .iter()
        .map(|&body| {
            let state = &model.bodies[body.0];
            let v = partials(&state.center.velocity, &rates);
            let w = partials(&state.omega, &rates);
            let by_name = |of: &Vector, partials: &[Vector]| {
                named_partials(model, of, body, &accelerations, partials, &states)
            };
            let named_v = by_name(&inertia.acceleration[body.0], &v);
            let named_w = by_name(&inertia.alpha[body.0], &w);
            (body, v, w, named_v, named_w)
        })
        .collect();
    let mut out = Vec::new();
    for r in 0..rates.len() {
        let mut first = true;
        // The speed's label and the partials' subscript: `u_1 = q̇_1` and 1, or the rate
        // itself where the rows combine the coordinates' rates.
        let (speed, subscript) = if by_rate {
            (rate_tex(derivation, r), rate_tex(derivation, r))
        } else {
            (speed_tex(derivation, r), (r + 1).to_string())
        };
        for (body, v, w, named_v, named_w) in &per_body {
            // Plain brackets, so that TeX can break a long entry inside its table cell.
            let plain = |t: String| {
                t.replace("\\left(", "(")
                    .replace("\\right)", ")")
                    .replace("\\left[", "[")
                    .replace("\\right]", "]")
            };
            let shortest = |expanded: &Vector, named: Option<&Vector>| {
                let text = shortest_tex(model, expanded, *body);
                match named.map(|n| shortest_tex(model, n, *body)) {
                    Some(by_name) if by_name.len() < text.len() => by_name,
                    _ => text,
                }
            };
            let v_tex = plain(shortest(&v[r], named_v.as_ref().map(|n| &n[r])));
            let w_tex = plain(shortest(&w[r], named_w.as_ref().map(|n| &n[r])));
            let line = super::partial_rows::Line {
                body: *body,
                r: r + 1,
                subscript: subscript.clone(),
                constrained: false,
            };
            let tex = (v_tex.as_str(), w_tex.as_str());
            out.extend(super::partial_rows::body_line(
                model, &line, tex, &speed, &mut first,
            ));
        }
    }
    out
}

/// Whether step 5 writes row `i` of the system with its signs changed. Kane's row of a
/// speed is `F_r + F^*_r = 0` with `F^*_r = −M q̈ + …`: changed, it reads `M q̈ = …`, the
/// mass matrix positive, as a textbook writes it; the matrix form changes the row alike.
/// A row of an auxiliary speed keeps its reaction positive (`F^O_x − m a = 0`).
pub fn sign_changed(derivation: &Derivation, i: usize) -> bool {
    let Some(row) = derivation.rows.get(i) else {
        return false;
    };
    matches!(derivation.method, Method::Kane | Method::Lagrange)
        && matches!(row.sum, Sum::Generalized { .. })
        && row_number(derivation, row).is_some_and(|r| r <= speed_rows(derivation))
}

/// How many of Kane's rows are the speeds' (generalized or independent); the rows after
/// them are the auxiliary speeds'.
pub fn speed_rows(derivation: &Derivation) -> usize {
    match &derivation.dependent_speeds {
        Some(speeds) => speeds.independent.len(),
        None => derivation.model.problem.coordinates.len(),
    }
}

/// The system as step 5 writes it: Kane's rows of speeds with their signs changed (see
/// [`sign_changed`]); the same equations, the mass matrix positive.
pub fn shown_system(derivation: &Derivation) -> crate::equations::LinearSystem {
    let mut system = derivation.system.clone();
    let rows = system.a.iter_mut().zip(system.b.iter_mut()).enumerate();
    for (i, (a, b)) in rows {
        if sign_changed(derivation, i) {
            a.iter_mut().for_each(|entry| *entry = -entry.clone());
            *b = -b.clone();
        }
    }
    system
}

/// How Kane's system of an unconstrained tree with reactions asked for is solved, where it
/// is block-triangular: the rows of the speeds hold only the q̈ and are solved first, then
/// each auxiliary row gives its one reaction. `None` where the system is not so.
pub fn solve_order_note(derivation: &Derivation) -> Option<String> {
    if derivation.dependent_speeds.is_some() || derivation.kept_forces.is_some() {
        return None;
    }
    let system = &derivation.system;
    let speeds = derivation.model.problem.speed_symbols(2).len();
    let n = system.a.len();
    if n <= speeds || system.unknowns.len() != n {
        return None;
    }
    let first_only_q = system.a[..speeds]
        .iter()
        .all(|row| row[speeds..].iter().all(Expr::is_zero));
    let one_each = system.a[speeds..].iter().enumerate().all(|(k, row)| {
        row[speeds..]
            .iter()
            .enumerate()
            .all(|(j, a)| a.is_zero() == (j != k))
    });
    if !first_only_q || !one_each {
        return None;
    }
    let rows = |from: usize, to: usize| match to - from {
        0 => format!("row {from}"),
        1 => format!("rows {from} and {to}"),
        _ => format!("rows {from}–{to}"),
    };
    let first = if speeds == 1 {
        "Row 1 contains no reaction and gives the second derivative".to_string()
    } else {
        format!(
            "R{} contain no reaction and give the second derivatives",
            &rows(1, speeds)[1..]
        )
    };
    let then = if n == speeds + 1 {
        format!("row {n} then gives the reaction")
    } else {
        format!(
            "each of {} then gives its one reaction",
            rows(speeds + 1, n)
        )
    };
    Some(format!("{first}; {then}."))
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

/// `F_r = …` and `F_r^* = …` of Kane's row `r`, simplified; a force too long to read
/// expanded (or long, and `sum_written_out`) by its name alone, since its definition stands
/// above the rows.
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
    let written = |e: &Expr, name: String| {
        let text = crate::symbolic::latex_collected(e);
        if text.len() > LONG_EQUATION {
            format!("{name}\\ \\text{{(a long expression, not written out)}}")
        } else if sum_written_out && text.len() > LONGEST_BESIDE_THE_SUM {
            format!("{name}\\ \\text{{collected in their sum below}}")
        } else {
            format!("{name} = {text}")
        }
    };
    (
        written(&active, format!("F_{{{r}}}")),
        written(&inertia, format!("F^{{*}}_{{{r}}}")),
    )
}

/// The partial velocities (or partial angular velocities) by the names step 4 writes the
/// acceleration with, a^{B*} = Σ v_r q̈_r + ã: the coefficient of each q̈_r (or u̇_r) in the
/// body's unit vectors, since ∂a/∂q̈_r = ∂v/∂q̇_r. `None` when a coefficient differs from
/// `expanded`'s at the sample states (then an identity does not hold as written).
fn named_partials(
    model: &Model,
    acceleration: &Vector,
    body: BodyId,
    accelerations: &[Symbol],
    expanded: &[Vector],
    states: &[Values],
) -> Option<Vec<Vector>> {
    let components = acceleration.components_in(body, &model.frames);
    let mut by_axis = Vec::with_capacity(3);
    for c in &components {
        by_axis.push(linear_split(c, accelerations).ok()?.0);
    }
    let named: Vec<Vector> = (0..accelerations.len())
        .map(|r| {
            let parts: [Expr; 3] = std::array::from_fn(|axis| by_axis[axis][r].clone());
            Vector::new(body, parts)
        })
        .collect();
    for (n, e) in named.iter().zip(expanded) {
        let e = e.components_in(body, &model.frames);
        let n = n.components_in(body, &model.frames);
        if n.iter().zip(&e).any(|(a, b)| !same_at(a, b, states)) {
            return None;
        }
    }
    Some(named)
}
