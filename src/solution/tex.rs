//! What every step writes the same way: vectors in their frames' unit vectors, sets of
//! bodies, a row's heading and its sum, a constraint's label, the sign a term has at the
//! initial state, and how the problem's numbers print.

use crate::equations::Derivation;
use crate::mechanics::{Model, Vector};
use crate::plan::ActionKind;
use crate::problem::{BodyId, Problem};
use crate::symbolic::{
    latex, latex_name, latex_unit_vector, list_by_runs, simplify, sum_times, Expr, Node, Symbol,
};

/// How the worked solution of `problem` prints numbers (the decimals it wrote as
/// decimals), and the letters of its sines and cosines, none of which the problem uses as a
/// name of its own (see `Style::avoiding`).
pub fn style_of(problem: &Problem) -> crate::symbolic::Style {
    let taken: Vec<String> = (problem.constants.iter().map(|c| c.name.as_str()))
        .chain(problem.coordinates.iter().map(|c| c.name.as_str()))
        .chain(problem.body_ids().map(|b| problem.body_name(b)))
        .map(latex_name)
        .collect();
    problem
        .decimals
        .iter()
        .fold(crate::symbolic::Style::default(), |style, (n, text)| {
            style.with_decimal(*n, text)
        })
        .avoiding(&taken)
}

/// A vector as a sum of components times unit vectors, each component simplified.
pub fn vector_tex(model: &Model, v: &Vector) -> String {
    vector_tex_by(model, v, component_term)
}

/// As [`vector_tex`], each nonzero component and its unit vector written by `term`.
pub(super) fn vector_tex_by(
    model: &Model,
    v: &Vector,
    term: impl Fn(&Expr, &str) -> String,
) -> String {
    let mut terms: Vec<String> = Vec::new();
    for (frame, components) in v.parts() {
        for (axis, c) in components.iter().enumerate() {
            let c = simplify(c);
            if c.is_zero() {
                continue;
            }
            let unit = latex_unit_vector(model.frames.name(*frame), axis as u8);
            terms.push(term(&c, &unit));
        }
    }
    if terms.is_empty() {
        return "\\mathbf{0}".into();
    }
    let mut out = terms[0].clone();
    for t in &terms[1..] {
        match t.strip_prefix('-') {
            Some(rest) => out.push_str(&format!(" - {rest}")),
            None => out.push_str(&format!(" + {t}")),
        }
    }
    out
}

/// A component times its unit vector: a sum in brackets, ±1 left out.
pub(super) fn component_term(c: &Expr, unit: &str) -> String {
    match c.node() {
        Node::Add(_) => sum_times(c, unit),
        _ if c.is_one() => unit.to_string(),
        _ if (-c).is_one() => format!("-{unit}"),
        _ => format!("{} {unit}", latex(c)),
    }
}

/// The shortest way to write a vector among the frames `N`, the body's and its parent's.
/// A frame not turned from its parent (a cart's) is written as that parent, so that one
/// table does not mix ĉ_x with the n̂_x it equals.
pub(super) fn shortest_tex(model: &Model, v: &Vector, body: BodyId) -> String {
    // A body spinning about its symmetry axis first in the frame that does not spin.
    let mut frames = vec![model.bodies[body.0].frame, body, BodyId::GROUND];
    if let Some(parent) = model.frames.info(body).parent {
        frames.push(parent);
    }
    let frames = frames.into_iter().map(|f| turned_ancestor(model, f));
    let mut best: Option<(usize, Vector)> = None;
    for frame in frames {
        let written = v.expressed_in(frame, &model.frames).map(simplify);
        let length = written.operation_count();
        if best.as_ref().is_none_or(|(l, _)| length < *l) {
            best = Some((length, written));
        }
    }
    best.map(|(_, w)| vector_tex(model, &w)).unwrap_or_default()
}

/// `frame`, or the first frame it descends from that is turned from its parent: a frame
/// whose unit vectors are its parent's is written as the parent.
fn turned_ancestor(model: &Model, frame: BodyId) -> BodyId {
    let mut frame = frame;
    while let Some(parent) = (model.frames.info(frame))
        .parent
        .filter(|_| model.frames.info(frame).rotations.is_empty())
    {
        frame = parent;
    }
    frame
}

/// A free body's bodies in LaTeX, `A + B`.
pub(super) fn bodies_tex(derivation: &Derivation, bodies: &[BodyId]) -> String {
    bodies_latex(derivation, bodies).join(" + ")
}

/// A free body's bodies in LaTeX, a run of four or more links by its ends,
/// `\\mathrm{link}_{2} + \\cdots + \\mathrm{link}_{10}`, as a heading in step 5 names it.
/// (The plan's table and step 2 name every body: the pictures' names are those.)
pub(super) fn bodies_tex_short(derivation: &Derivation, bodies: &[BodyId]) -> String {
    list_by_runs(&bodies_latex(derivation, bodies), " + ", "\\cdots")
}

/// A free body's bodies as a set's members, `\\mathrm{link}_{2}, \\ldots, \\mathrm{link}_{10}`.
pub(super) fn bodies_set_tex(derivation: &Derivation, bodies: &[BodyId]) -> String {
    list_by_runs(&bodies_latex(derivation, bodies), ", ", "\\ldots")
}

fn bodies_latex(derivation: &Derivation, bodies: &[BodyId]) -> Vec<String> {
    let problem = derivation.model.problem;
    bodies
        .iter()
        .map(|b| latex_name(problem.body_name(*b)))
        .collect()
}

pub(super) fn bodies_name(problem: &Problem, bodies: &[BodyId]) -> String {
    bodies
        .iter()
        .map(|b| problem.body_name(*b).to_string())
        .collect::<Vec<_>>()
        .join(" + ")
}

/// The sign an expression has at the initial state, for [`roots_of_squares`].
pub fn initial_sign(model: &Model) -> impl Fn(&Expr) -> f64 {
    let state = model.problem.initial_state();
    let values = model.values_at(state.t, &state.q, &state.rates);
    move |e: &Expr| crate::symbolic::eval(e, &values).signum()
}

/// Every component of every force and couple.
pub(super) fn action_components<'d>(derivation: &'d Derivation) -> impl Iterator<Item = &'d Expr> {
    derivation
        .actions
        .iter()
        .flat_map(|a| match &a.kind {
            ActionKind::Force { force, .. } => force.parts(),
            ActionKind::Couple { torque } => torque.parts(),
        })
        .flat_map(|(_, c)| c.iter())
}

/// Whether the forces use a quantity shown otherwise than it is computed (see
/// [`as_shown`]); checked once, since the equations are far larger than the forces.
pub(super) fn uses_shown(derivation: &Derivation) -> bool {
    action_components(derivation)
        .any(|c| c.any_symbol(&|s| matches!(s, Symbol::Defined(d) if d.shown().is_some())))
}

/// A row's unknowns, a run such as q̈₁, …, q̈₁₀ by its ends: a ten-link row otherwise wraps
/// in its column.
pub(super) fn unknowns_tex(unknowns: &[Symbol]) -> String {
    let items: Vec<String> = unknowns
        .iter()
        .map(|u| latex(&Expr::sym(u.clone())))
        .collect();
    list_by_runs(&items, ", ", "\\dots")
}

/// A body's mass centre as LaTeX, `B^*`; a particle (a body with mass and no moment of
/// inertia that nothing holds against turning) is a point, named as the body, `P_{1}`, as
/// textbooks name a particle.
pub fn centre_tex(model: &Model, body: BodyId) -> String {
    let name = latex_name(model.problem.body_name(body));
    let light = crate::mechanics::is_massless(model, body);
    if !light && crate::mechanics::is_point_particle(model, body) {
        name
    } else {
        format!("{name}^*")
    }
}

/// A moment point as LaTeX: `O`, or `A^{*}` for the mass centre `A*`.
pub fn point_tex(point: &str) -> String {
    match point.strip_suffix('*') {
        Some(stem) => format!("{}^{{*}}", latex_name(stem)),
        None => latex_name(point),
    }
}

/// What a constraint row's heading adds: the row is the constraint differentiated.
pub const ACCELERATION_LEVEL: &str = "(differentiated to the acceleration level)";

/// `Σ x_k symbol_k` with numbers written to the digits of the tables and a coefficient of
/// one left out; `None` when every `|x_k|` is at most `zero`.
pub(super) fn numeric_sum(
    terms: impl IntoIterator<Item = (f64, String)>,
    zero: f64,
) -> Option<String> {
    let mut sum = String::new();
    for (x, symbol) in terms {
        if x.abs() <= zero {
            continue;
        }
        let sign = match (sum.is_empty(), x < 0.0) {
            (true, true) => "-",
            (true, false) => "",
            (false, true) => " - ",
            (false, false) => " + ",
        };
        let size = if x.abs() == 1.0 {
            String::new()
        } else {
            format!("{} ", crate::symbolic::fixed(x.abs()))
        };
        sum.push_str(&format!("{sign}{size}{symbol}"));
    }
    (!sum.is_empty()).then_some(sum)
}

/// `v` (LaTeX) as a factor of a product: in parentheses where it is a sum or opens with a
/// sign, so that `u\, (a + b)` and `(a + b) \times r` read as the product they are.
pub fn factor_of_product(v: &str) -> String {
    let mut depth = 0i32;
    let mut several = v.trim_start().starts_with('-');
    let bytes = v.as_bytes();
    for (i, &c) in bytes.iter().enumerate() {
        match c {
            b'(' | b'[' | b'{' => depth += 1,
            b')' | b']' | b'}' => depth -= 1,
            b'+' | b'-' if depth == 0 && i > 0 && bytes[i - 1] == b' ' => several = true,
            _ => {}
        }
    }
    if several {
        format!("\\left({v}\\right)")
    } else {
        v.to_string()
    }
}

/// Kane's auxiliary speed `r` by the force it brings in, as a textbook says it:
/// `u_{4}\text{, for } F^{R}_{x}` (the speed along which that force does work).
pub fn auxiliary_speed_tex(r: usize, forces: &str) -> String {
    format!("u_{{{r}}}\\text{{, for }} {forces}")
}

#[cfg(test)]
mod factor_tests {
    use super::factor_of_product;

    #[test]
    fn a_sum_or_a_signed_direction_is_bracketed_as_a_factor() {
        let sum = "-S_{\\psi} \\hat{\\mathbf{n}}_{x} + C_{\\psi} \\hat{\\mathbf{n}}_{y}";
        assert_eq!(factor_of_product(sum), format!("\\left({sum}\\right)"));
        assert_eq!(
            factor_of_product("-\\hat{\\mathbf{n}}_{x}"),
            "\\left(-\\hat{\\mathbf{n}}_{x}\\right)"
        );
        // One term, its sums inside its own brackets: as it is.
        let one = "\\left(a + b\\right) \\hat{\\mathbf{n}}_{x}";
        assert_eq!(factor_of_product(one), one);
        assert_eq!(
            factor_of_product("\\hat{\\mathbf{n}}_{y}"),
            "\\hat{\\mathbf{n}}_{y}"
        );
    }
}
