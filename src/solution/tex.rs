//! What every step writes the same way: vectors in their frames' unit vectors, sets of
//! bodies, a row's heading and its sum, a constraint's label, the sign a term has at the
//! initial state, and how the problem's numbers print.

use crate::equations::Derivation;
use crate::mechanics::{Model, RowOrigin, Vector};
use crate::plan::{ActionKind, Sum};
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
pub(super) fn shortest_tex(model: &Model, v: &Vector, body: BodyId) -> String {
    // A body spinning about its symmetry axis first in the frame that does not spin.
    let mut frames = vec![model.bodies[body.0].frame, body, BodyId::GROUND];
    if let Some(parent) = model.frames.info(body).parent {
        frames.push(parent);
    }
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
    let problem = model.problem;
    let q0: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
    let rates0: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    let values = model.values_at(0.0, &q0, &rates0);
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
/// inertia) is a point, named as the body, `P_{1}`, as textbooks name a particle.
pub fn centre_tex(model: &Model, body: BodyId) -> String {
    let name = latex_name(model.problem.body_name(body));
    let light = crate::mechanics::is_massless(model, body);
    if !light && crate::mechanics::is_particle(model, body) {
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

/// Row `i`'s equation as step 5 heads it: `B\colon \sum \mathbf{M}_{P} \cdot
/// \hat{\mathbf{a}}_{z}`, `F_{1} + F^{*}_{1}`, or what a constraint row constrains.
pub fn row_heading_tex(derivation: &Derivation, i: usize) -> String {
    let row = &derivation.rows[i];
    let direction = row
        .direction
        .as_ref()
        .map(|d| format!(" \\cdot {}", d.latex))
        .unwrap_or_default();
    match &row.sum {
        Sum::Constraint { name } => constraint_label_tex(&derivation.model, name),
        Sum::Generalized { .. } => sum_tex(derivation, &row.sum),
        _ => format!(
            "{}\\colon {}{direction}",
            bodies_tex_short(derivation, &row.free_body),
            sum_tex(derivation, &row.sum)
        ),
    }
}

/// A sum as an equation's column names it: `\sum \mathbf{F}`, `\sum \mathbf{M}_{O}`,
/// `F_{r} + F^{*}_{r}` (r among Kane's rows), or what a constraint constrains.
pub fn sum_tex(derivation: &Derivation, sum: &Sum) -> String {
    match sum {
        Sum::Force => "\\sum \\mathbf{F}".into(),
        Sum::Moment { point, .. } => format!("\\sum \\mathbf{{M}}_{{{}}}", point_tex(point)),
        Sum::Generalized { .. } if derivation.method == crate::equations::Method::Lagrange => {
            super::lagrange::equation_tex(derivation, sum).unwrap_or_default()
        }
        Sum::Generalized { .. } => {
            let r = derivation
                .rows
                .iter()
                .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
                .position(|x| x.sum == *sum)
                .map_or("r".to_string(), |i| (i + 1).to_string());
            if derivation.dependent_speeds.is_some() {
                format!("\\tilde{{F}}_{{{r}}} + \\tilde{{F}}^{{*}}_{{{r}}}")
            } else {
                format!("F_{{{r}}} + F^{{*}}_{{{r}}}")
            }
        }
        Sum::Constraint { name } => constraint_what_tex(&derivation.model, name),
    }
}

/// A constraint row's label in the matrix form: what it constrains and, for a site's row,
/// the direction of its reaction, e.g. `\text{loop closure at C} \cdot \hat{\mathbf{a}}_{x}`.
pub(super) fn constraint_label_tex(model: &Model, name: &str) -> String {
    let what = constraint_what_tex(model, name);
    match constraint_direction_tex(model, name) {
        Some(direction) => format!("{what} \\cdot {direction}"),
        None => what,
    }
}

/// What a constraint row constrains, in LaTeX: `\text{no slip at floor}`, or
/// `\text{prescribed motion of } \theta` with the coordinate as a symbol.
pub(super) fn constraint_what_tex(model: &Model, name: &str) -> String {
    use crate::mechanics::SiteKind;
    let problem = model.problem;
    // A site's name in words: `rear_contact` is the rear contact.
    let text = |words: String| {
        format!(
            "\\text{{{}}}",
            crate::render::escape_latex(&words.replace('_', " "), crate::render::Lines::One)
        )
    };
    let sticking = model
        .constraints
        .friction
        .iter()
        .find(|f| f.stick.iter().any(|r| r.name == name));
    if let Some(site) = sticking {
        // A friction site's no-slip row holds only while it sticks (rolls).
        return text(format!("no slip at {} while it sticks", site.name));
    }
    let row = model.constraints.rows.iter().find(|r| r.name == name);
    match row.map(|r| &r.origin) {
        Some(RowOrigin::Site { site, .. }) => match model.sites.get(*site) {
            Some(s) if matches!(s.kind, SiteKind::Contact(_)) => {
                let kind = match s.kind {
                    SiteKind::Contact(k) => problem.constraints.get(k).map(|c| &c.kind),
                    _ => None,
                };
                // A position-level row holds the body on the surface (the normal) or,
                // for a gear, the distance between the centres; a velocity-level row is
                // the no-slip condition along the contact's tangent (a gear's meshing).
                let holonomic = row.is_some_and(|r| r.position.is_some());
                let gear = matches!(kind, Some(crate::problem::ConstraintKind::Gear { .. }));
                match (gear, holonomic) {
                    (false, true) => text(format!("no penetration at {}", s.name)),
                    (false, false) => text(format!("no slip at {}", s.name)),
                    (true, true) => text(format!("distance between the centres at {}", s.name)),
                    (true, false) => text(format!("no slip at {}", s.name)),
                }
            }
            Some(s) if matches!(s.kind, SiteKind::Closure(_)) => {
                text(format!("loop closure at {}", s.name))
            }
            Some(s) => text(format!("constraint at {}", s.name)),
            None => text(format!("constraint {name}")),
        },
        Some(RowOrigin::Position(_)) => text(format!("position constraint {name}")),
        Some(RowOrigin::Velocity(_)) => text(format!("velocity constraint {name}")),
        Some(RowOrigin::Prescribed(c)) if *c < problem.coordinates.len() => {
            let symbol = latex(&problem.coordinate_expr(*c, 0));
            if problem.coordinates[*c].held {
                format!("{symbol} \\text{{ held by its support}}")
            } else {
                format!("\\text{{prescribed motion of }} {symbol}")
            }
        }
        Some(RowOrigin::Prescribed(_)) => text(format!("prescribed motion {name}")),
        None => text(format!("constraint {name}")),
    }
}

/// What a constraint row's heading adds: the row is the constraint differentiated.
pub const ACCELERATION_LEVEL: &str = "(differentiated to the acceleration level)";

/// The direction of a closure's or a contact's constraint row: that of the reaction
/// component that enforces it (the row is the relative motion along it).
pub(super) fn constraint_direction_tex(model: &Model, name: &str) -> Option<String> {
    // A no-slip row of a friction site: along the tangent its friction component takes.
    for friction in &model.constraints.friction {
        if let Some(row) = friction.stick.iter().find(|r| r.name == name) {
            let site = model.sites.get(friction.site)?;
            let component =
                (site.reactions.iter()).find(|c| c.unknown(&site.name) == row.unknown)?;
            return Some(super::direction::simplest_tex(model, &component.direction));
        }
    }
    let row = model.constraints.rows.iter().find(|r| r.name == name)?;
    let RowOrigin::Site { site, component } = row.origin else {
        return None;
    };
    let direction = model.sites.get(site)?.row_direction(component)?;
    Some(super::direction::simplest_tex(model, direction))
}

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
