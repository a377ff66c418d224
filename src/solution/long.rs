//! Equations too long to read whole, written with named coefficients: a row of step 5 as
//! `A_{i,1} x_1 + … = b_i`, and a right-hand side collected by the products of rates.

use crate::equations::Derivation;
use crate::plan::{Equation, Sum};
use crate::render::context::Equation as EquationView;
use crate::symbolic::{latex, latex_name, list_by_runs, Expr, Node, Symbol};
use std::collections::HashMap;

/// The most characters of LaTeX an equation of step 5 is shown with; a longer one is shown
/// with the coefficients of the matrix form by name (and, as formed, not at all).
pub const LONG_EQUATION: usize = 1500;

/// Row `i` of the system as `A_{i,1} x_1 + … = b_i`, with the nonzero coefficients.
pub fn coefficient_form(derivation: &Derivation, i: usize) -> String {
    let system = &derivation.system;
    let names = crate::problem::MatrixNames::of(derivation.model.problem);
    let terms: Vec<String> = system.a[i]
        .iter()
        .zip(&system.unknowns)
        .enumerate()
        .filter(|(_, (a, _))| !a.is_zero())
        .map(|(j, (_, x))| {
            let x = latex(&Expr::sym(x.clone()));
            format!("{}_{{{},{}}} {x}", names.a, i + 1, j + 1)
        })
        .collect();
    // A long row by its first two terms and its last, as a textbook writes row i of A x.
    const MOST_TERMS: usize = 4;
    let left = match terms.as_slice() {
        [] => "0".to_string(),
        [first, second, .., last] if terms.len() > MOST_TERMS => {
            format!("{first} + {second} + \\cdots + {last}")
        }
        _ => terms.join(" + "),
    };
    format!("{left} = {}_{{{}}}", names.b, i + 1)
}

/// `e` as a sum over the products of rates its terms hold: (product of rates, its
/// coefficient), in the order the products first appear, the part without rates last.
pub fn by_rates(e: &Expr) -> Vec<(Expr, Expr)> {
    let is_rate =
        |f: &Expr| f.any_symbol(&|s| matches!(s, Symbol::Coord(_, 1) | Symbol::Speed(_, 0)));
    let mut groups: Vec<(Expr, Vec<Expr>)> = Vec::new();
    let mut index: std::collections::HashMap<Expr, usize> = std::collections::HashMap::new();
    for term in e.terms() {
        let (rates, rest): (Vec<Expr>, Vec<Expr>) =
            term.factors().iter().cloned().partition(|f| is_rate(f));
        let key = crate::symbolic::mul(rates);
        let coefficient = crate::symbolic::mul(rest);
        match index.get(&key) {
            Some(&k) => groups[k].1.push(coefficient),
            None => {
                index.insert(key.clone(), groups.len());
                groups.push((key, vec![coefficient]));
            }
        }
    }
    // The part without rates goes last, as a textbook writes the gravity terms.
    groups.sort_by_key(|(key, _)| key.is_one());
    groups
        .into_iter()
        .map(|(key, terms)| (key, crate::symbolic::add(terms)))
        .collect()
}

/// The inertia terms of a row written by the names of steps 2 and 4: each body's inertia
/// force `m a*` (its moment about the row's point in a moment row) and its inertia torque,
/// written out body by body up to [`MOST_BODIES_WRITTEN`] bodies, as a sum over the named
/// set `k ∈ {…}` past that (`sum`, empty otherwise). None for rows that are not sums of
/// forces or moments.
struct NamedInertia {
    sum: String,
    force: String,
    torque: Option<String>,
}

/// The most bodies of a free body whose inertia terms a row writes one by one; past it,
/// as a sum over the named set.
const MOST_BODIES_WRITTEN: usize = 4;

/// Body `body`'s mass as a factor: `m_{1}`, or `(m_1 + m_2)` for a sum.
fn mass_factor(derivation: &Derivation, body: crate::problem::BodyId) -> String {
    let m = &derivation.model.bodies[body.0].mass;
    if m.terms().len() > 1 {
        format!("\\left({}\\right)", latex(m))
    } else {
        latex(m)
    }
}

fn named_inertia(derivation: &Derivation, row: &Equation) -> Option<NamedInertia> {
    if !matches!(row.sum, Sum::Force | Sum::Moment { .. }) {
        return None;
    }
    let problem = derivation.model.problem;
    let bodies: Vec<String> = row
        .free_body
        .iter()
        .map(|b| latex_name(problem.body_name(*b)))
        .collect();
    let many = bodies.len() > MOST_BODIES_WRITTEN;
    // Up to four bodies each by its own letter and mass; more: the sum over `k` in the free
    // body.
    let (sum, each): (String, Vec<(String, String)>) = if many {
        (
            format!(
                "\\sum_{{k \\in \\{{{}\\}}}} ",
                list_by_runs(&bodies, ", ", "\\ldots")
            ),
            vec![("k".to_string(), "m_{k}".to_string())],
        )
    } else {
        let masses = row.free_body.iter().map(|&b| mass_factor(derivation, b));
        (String::new(), bodies.iter().cloned().zip(masses).collect())
    };
    let inertia_force =
        |(k, mass): &(String, String)| format!("{mass}\\, {{}}^{{N}}\\mathbf{{a}}^{{{k}^*}}");
    match &row.sum {
        Sum::Force => Some(NamedInertia {
            sum,
            force: each
                .iter()
                .map(inertia_force)
                .collect::<Vec<_>>()
                .join(" + "),
            torque: None,
        }),
        Sum::Moment { point, position } => {
            let point = &super::moment_point::shown_point(&derivation.model, point, position);
            // About a body's own mass centre its inertia force has no moment.
            let about_own_centre = row.free_body.len() == 1
                && row
                    .free_body
                    .first()
                    .is_some_and(|b| point.strip_suffix('*') == Some(problem.body_name(*b)));
            let point = super::tex::point_tex(point);
            let planar = derivation.model.is_planar();
            let torque = (each.iter())
                .flat_map(|(k, _)| inertia_torque_terms(k, planar))
                .collect::<Vec<_>>()
                .join(" + ");
            let force = match about_own_centre {
                true => String::new(),
                false => (each.iter())
                    .map(|body| {
                        format!(
                            "\\mathbf{{r}}^{{{point} {}^*}} \\times {}",
                            body.0,
                            inertia_force(body)
                        )
                    })
                    .collect::<Vec<_>>()
                    .join(" + "),
            };
            Some(NamedInertia {
                sum,
                force,
                torque: Some(torque),
            })
        }
        _ => None,
    }
}

/// The terms of body `k`'s inertia torque with their sign changed, I·α and ω × I·ω, as a
/// textbook writes them; in a plane I·α alone, since there I is a moment of inertia about
/// the normal, along which ω lies, and ω × I·ω is zero.
pub fn inertia_torque_terms(k: &str, planar: bool) -> Vec<String> {
    let mut terms = vec![format!(
        "\\mathbf{{I}}^{{{k}}} \\cdot \\boldsymbol{{\\alpha}}^{{{k}}}"
    )];
    if !planar {
        terms.push(format!(
            "\\boldsymbol{{\\omega}}^{{{k}}} \\times \\mathbf{{I}}^{{{k}}} \\cdot \\boldsymbol{{\\omega}}^{{{k}}}"
        ));
    }
    terms
}

/// A row of the Motion Law or of Newton–Euler in vector form, for a row too long to print
/// as formed: the direction dotted with the external forces (or their moments about the
/// point) and each body's inertia force (and inertia torque), every one named as in steps 2
/// and 4. Empty for rows that are not sums of forces or moments.
pub fn vector_form(derivation: &Derivation, row: &Equation) -> String {
    let (Some(direction), Some(named)) = (&row.direction, named_inertia(derivation, row)) else {
        return String::new();
    };
    let NamedInertia { sum, force, torque } = named;
    let inside = match (&row.sum, torque) {
        (Sum::Moment { point, position }, Some(torque)) => {
            let point = super::moment_point::shown_point(&derivation.model, point, position);
            let point = super::tex::point_tex(&point);
            let inertia = match force.as_str() {
                "" => torque,
                _ => format!("{force} + {torque}"),
            };
            format!("\\sum \\mathbf{{M}}_{{{point}}} - {sum}\\left( {inertia} \\right)")
        }
        _ if force.contains(" + ") => {
            format!("\\sum \\mathbf{{F}} - {sum}\\left( {force} \\right)")
        }
        _ => format!("\\sum \\mathbf{{F}} - {sum}{force}"),
    };
    format!("{} \\cdot \\left( {inside} \\right) = 0", direction.latex)
}

/// The most terms an inertia group of a row as formed is written out with; a longer one
/// is written by the names of step 4, as `− m a^{B*} · d̂`, since multiplied out it
/// repeats step 4's acceleration in the row's direction and hides the forces.
pub const MOST_INERTIA_TERMS: usize = 3;

/// The inertia force (`torque` false) or inertia torque of a row as formed, by name and
/// with its sign: `- m\, {}^{N}\mathbf{a}^{B^*} \cdot \hat{\mathbf{x}}`. None where the row
/// has no direction or is not a sum of forces or moments.
pub fn named_inertia_group(
    derivation: &Derivation,
    row: &Equation,
    torque: bool,
) -> Option<String> {
    let direction = row.direction.as_ref()?;
    let named = named_inertia(derivation, row)?;
    let term = if torque { named.torque? } else { named.force };
    if term.is_empty() {
        return None;
    }
    let single = !term.contains(" + ") && !term.contains("\\times") && !term.contains("\\cdot");
    let body = if single {
        term
    } else {
        format!("\\left( {term} \\right)")
    };
    Some(format!("- {}{body} \\cdot {}", named.sum, direction.latex))
}

/// Rows written in vector form that an earlier such row repeats but for its direction (the
/// same free body's moments about the same point along another axis) refer to that row
/// instead of printing the same display again, as a textbook writes "likewise along ŷ".
pub fn refer_to_repeated_vector_forms(derivation: &Derivation, views: &mut [EquationView]) {
    let mut seen: Vec<(String, usize)> = Vec::new();
    for (i, (row, view)) in derivation.rows.iter().zip(views.iter_mut()).enumerate() {
        // A row in vector form reads `d · (…) = 0`, as `vector_form` writes it.
        let Some(rest) = row
            .direction
            .as_ref()
            .and_then(|d| view.grouped_tex.strip_prefix(&d.latex))
            .filter(|rest| rest.starts_with(" \\cdot \\left( "))
        else {
            continue;
        };
        match seen.iter().find(|(key, _)| key == rest) {
            Some((_, first)) => {
                view.grouped_tex.clear();
                let then = match view.simplified_note.as_str() {
                    "" => "Simplified:",
                    note => note,
                };
                view.simplified_note =
                    format!("Formed as row {first}, along this row's direction. {then}");
            }
            None => seen.push((rest.to_string(), i + 1)),
        }
    }
}

/// The constraint rows say once, at the first, that they are differentiated to the
/// acceleration level: repeated on every heading it would take a line of its own.
pub fn say_the_acceleration_level_once(views: &mut [EquationView]) {
    let rows: Vec<usize> = (views.iter().enumerate())
        .filter(|(_, v)| v.label == super::tex::ACCELERATION_LEVEL)
        .map(|(i, _)| i)
        .collect();
    let [first, later @ ..] = rows.as_slice() else {
        return;
    };
    if !later.is_empty() {
        let list = super::rejected::row_list(later);
        let rows = if later.len() == 1 {
            "is row"
        } else {
            "are rows"
        };
        views[*first].label =
            format!("(differentiated to the acceleration level, as {rows} {list})");
    }
    for &i in later {
        views[i].label.clear();
    }
}

/// Kane's auxiliary rows after the first at a joint refer to it for what their speed does,
/// rather than saying again that it moves the same bodies against the joint.
pub fn refer_to_the_first_auxiliary_row(views: &mut [EquationView]) {
    const OPENING: &str = "(an auxiliary speed: it moves ";
    let mut seen: Vec<(String, usize)> = Vec::new();
    for (i, view) in views.iter_mut().enumerate() {
        if !view.label.starts_with(OPENING) {
            continue;
        }
        match seen.iter().find(|(label, _)| *label == view.label) {
            Some((_, first)) => view.label = format!("(an auxiliary speed, as in row {first})"),
            None => seen.push((view.label.clone(), i + 1)),
        }
    }
}

/// The size of a row as formed, in nodes written out as a tree, past which it is shown by
/// its coefficients without being simplified first. Simplifying shortens a row, but not
/// by this much: of the rows of every bundled problem by every method, the largest that
/// prints within [`LONG_EQUATION`] simplified has 1,881 nodes as formed (the planetary
/// gear train's, 151 characters), and every row past 3,800 nodes prints past it; the
/// bicycle's longest rows have 22,152 and 47,655 nodes (65,200 and 156,603 characters).
pub const SURELY_LONG: usize = 20_000;

/// Whether `e`, a row as formed, is too long to print whole however it simplifies (see
/// [`SURELY_LONG`]): counted without simplifying, at most to that size.
pub fn surely_long(e: &Expr) -> bool {
    written_size(e, SURELY_LONG) > SURELY_LONG
}

/// The number of nodes of `e` written out as a tree (a shared part counted at each use),
/// counted up to just past `most`.
fn written_size(e: &Expr, most: usize) -> usize {
    fn count(e: &Expr, most: usize, seen: &mut HashMap<*const Node, usize>) -> usize {
        let key = std::rc::Rc::as_ptr(&e.0);
        if let Some(&n) = seen.get(&key) {
            return n;
        }
        let pair;
        let children: &[Expr] = match e.node() {
            Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => items,
            Node::Pow(base, exponent) => {
                pair = [base.clone(), exponent.clone()];
                &pair
            }
            Node::Num(_) | Node::Sym(_) => &[],
        };
        let mut n = 1usize;
        for child in children {
            n = n.saturating_add(count(child, most, seen));
            if n > most {
                break;
            }
        }
        let n = n.min(most + 1);
        seen.insert(key, n);
        n
    }
    count(e, most, &mut HashMap::new())
}

#[cfg(test)]
mod tests {
    use super::{surely_long, written_size, SURELY_LONG};
    use crate::symbolic::{cos, sin, Expr};

    /// `y₀ = a + b`, `yₖ₊₁ = sin yₖ + cos yₖ`: each level holds the one before twice, so
    /// written out as a tree it has `s₀ = 3`, `sₖ₊₁ = 2 (sₖ + 1) + 1` nodes, that is
    /// `sₖ = 6·2ᵏ − 3`, while as shared parts it has only `2k + 3`.
    fn nested(levels: u32) -> Expr {
        let mut y = &Expr::constant("a") + &Expr::constant("b");
        for _ in 0..levels {
            y = &sin(y.clone()) + &cos(y);
        }
        y
    }

    #[test]
    fn a_shared_part_is_counted_at_each_use() {
        for k in 0..6 {
            assert_eq!(
                written_size(&nested(k), usize::MAX - 1),
                6 * 2usize.pow(k) - 3
            );
        }
        // Counted no further than just past the limit.
        assert_eq!(written_size(&nested(20), 100), 101);
    }

    #[test]
    fn a_row_is_surely_long_only_past_the_limit() {
        // 6·2¹¹ − 3 = 12,285 nodes; 6·2¹² − 3 = 24,573.
        assert!(6 * 2usize.pow(11) - 3 < SURELY_LONG && SURELY_LONG < 6 * 2usize.pow(12) - 3);
        assert!(!surely_long(&nested(11)));
        assert!(surely_long(&nested(12)));
    }
}
