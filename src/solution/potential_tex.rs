//! The potential energy `V` as a course writes it: gravity's terms, then each spring's
//! ½ k (l − l₀)² with its stretch written in the coordinates (½ k₂ (x₂ − x₁)²), not
//! multiplied out. The derivatives ∂V/∂q_r of step 3 are taken from the same energy.

use crate::mechanics::Model;
use crate::problem::{LoadKind, PointRef};
use crate::symbolic::{add, latex, latex_collected, roots_of_squares, simplify, Expr};

/// `V` in LaTeX: gravity's terms (collected), then every spring's ½ k (stretch)², then
/// the potential of each force that has one (a gas law); `0` when nothing has a potential.
pub fn potential_tex(model: &Model) -> String {
    let sign = super::tex::initial_sign(model);
    let mut parts = Vec::new();
    let gravity = roots_of_squares(&simplify(&gravity_potential(model)), &sign);
    if !gravity.is_zero() {
        parts.push(latex_collected(&gravity));
    }
    let problem = model.problem;
    for (index, load) in problem.loads.iter().enumerate() {
        let (stiffness, stretch) = match &load.kind {
            LoadKind::Spring {
                between,
                stiffness,
                free_length,
            } => (
                stiffness,
                spring_stretch(model, between, free_length, &sign),
            ),
            LoadKind::JointSpring {
                coordinate,
                stiffness,
                rest,
                ..
            } => (
                stiffness,
                simplify(&(&problem.coordinate_expr(*coordinate, 0) - rest)),
            ),
            LoadKind::Force { .. } => {
                if let Some(v) = crate::equations::force_potential(model, index) {
                    parts.push(latex_collected(&v));
                }
                continue;
            }
            _ => continue,
        };
        if !stretch.is_zero() && !stiffness.is_zero() {
            parts.push(half_square(stiffness, &stretch));
        }
    }
    joined(&parts)
}

/// −Σ m g·r*: the potential of gravity, zero at the origin's level.
pub(super) fn gravity_potential(model: &Model) -> Expr {
    let Some(g) = &model.problem.gravity else {
        return Expr::zero();
    };
    let g = crate::mechanics::vector_of(g);
    add(model.order.iter().map(|&body| {
        let state = &model.bodies[body.0];
        -(&state.mass * &g.dot(&state.center.position, &model.frames))
    }))
}

/// A spring's stretch l − l₀, its length l written without a root where it is the
/// square root of a square (the sign that makes it positive at the initial state).
fn spring_stretch(
    model: &Model,
    between: &[PointRef; 2],
    free_length: &Expr,
    sign: &dyn Fn(&Expr) -> f64,
) -> Expr {
    let d = model
        .position(between[1])
        .minus(&model.position(between[0]));
    let length2 = simplify(&d.dot(&d, &model.frames));
    let length = crate::symbolic::pow(length2, Expr::ratio(1, 2));
    let length = roots_of_squares(&simplify(&length), sign);
    simplify(&(&length - free_length))
}

/// `\frac{1}{2} k \left(s\right)^{2}`, or `\frac{1}{2} k s^{2}` for a single symbol.
fn half_square(stiffness: &Expr, stretch: &Expr) -> String {
    let k = match stiffness.as_number() {
        Some(_) => latex(&simplify(&(&Expr::ratio(1, 2) * stiffness))),
        None if stiffness.terms().len() > 1 => {
            format!("\\frac{{1}}{{2}} \\left({}\\right)", latex(stiffness))
        }
        None => format!("\\frac{{1}}{{2}} {}", latex(stiffness)),
    };
    let s = positive_first(stretch);
    match stretch.as_symbol() {
        Some(_) => format!("{k} {s}^{{2}}"),
        None => format!("{k} \\left({s}\\right)^{{2}}"),
    }
}

/// A sum with its positive terms first, as a stretch is written: `x_{2} - x_{1}`,
/// `r - l_{0}`.
fn positive_first(e: &Expr) -> String {
    let terms = e.terms();
    let negative = |t: &Expr| latex(t).starts_with('-');
    if terms.len() < 2 || terms.iter().all(negative) {
        return latex(e);
    }
    let mut out = (terms.iter().filter(|t| !negative(t)))
        .map(latex)
        .collect::<Vec<_>>()
        .join(" + ");
    for term in terms.iter().filter(|t| negative(t)) {
        out.push_str(&format!(" - {}", latex(&simplify(&-term))));
    }
    out
}

/// The parts joined by their signs: `a + b`, `a - c`.
fn joined(parts: &[String]) -> String {
    let mut out = String::new();
    for part in parts {
        match (out.is_empty(), part.strip_prefix('-')) {
            (true, _) => out.push_str(part),
            (false, Some(rest)) => out.push_str(&format!(" - {}", rest.trim_start())),
            (false, None) => out.push_str(&format!(" + {part}")),
        }
    }
    if out.is_empty() {
        "0".into()
    } else {
        out
    }
}

/// What has a potential, in `V`: gravity, the springs, each force with a potential by its
/// name (the gas); and whether they are said in the plural.
pub(super) fn sources(derivation: &crate::equations::Derivation) -> (Vec<String>, bool) {
    use crate::plan::Source;
    use crate::problem::LoadKind;
    let model = &derivation.model;
    let mut names = Vec::new();
    if (derivation.actions.iter()).any(|a| a.source == Source::Gravity) {
        names.push("gravity".to_string());
    }
    let loads = &model.problem.loads;
    if (loads.iter()).any(|l| {
        matches!(
            l.kind,
            LoadKind::Spring { .. } | LoadKind::JointSpring { .. }
        )
    }) {
        names.push("the springs".into());
    }
    // A force with a potential (a gas law) by its name.
    for (i, load) in loads.iter().enumerate() {
        if crate::equations::force_potential(model, i).is_some() {
            names.push(
                load.name
                    .as_ref()
                    .map_or("the applied force".into(), |n| format!("the {n}")),
            );
        }
    }
    let plural = names.len() > 1 || names.iter().any(|n| n == "the springs");
    (names, plural)
}

/// `text` with its first letter a capital.
pub(super) fn capitalized(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map_or(String::new(), |c| c.to_uppercase().chain(chars).collect())
}

/// `a, b and c`.
pub(super) fn listed(names: &[String]) -> String {
    match names.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => names.concat(),
    }
}
