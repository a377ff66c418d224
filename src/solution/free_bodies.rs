//! Step 2's free bodies: each with the forces and couples that act on it from outside, the
//! distance forces, and the inertia forces and torques of its bodies.

use super::direction::simplest_tex;
use super::tex::{bodies_name, bodies_tex, initial_sign, vector_tex};
use crate::equations::Derivation;
use crate::mechanics::{is_particle, vector_of, Model, Vector};
use crate::plan::{is_external, ActionKind, Category, Source};
use crate::problem::BodyId;
use crate::render::context::{Force, FreeBody};
use crate::render::text::{MarkupLine, Math};
use crate::symbolic::{as_shown, latex, latex_name, roots_of_squares};

/// A free body of more bodies than this lists gravity and the inertia forces once, for
/// each body k, instead of body by body.
const MOST_BODIES_LISTED: usize = 2;

/// Where a force acts, as a textbook's table says it: a reaction at its joint's (or
/// closure's, or contact's) point by name, `at O`; another force at the body's mass centre
/// or origin as that; anything else by its position from the body's origin.
pub(super) fn acts_at(model: &Model, action: &crate::plan::Action, at: &Vector) -> String {
    if let Source::Reaction(site) = action.source {
        let name = model.problem.site_name(site);
        return format!("\\text{{at }} {}", latex_name(name));
    }
    let body = latex_name(model.problem.body_name(action.body));
    let center = Model::own(action.body, &model.bodies[action.body.0].center_offset);
    if *at == center {
        return format!("\\text{{at }} {body}^*");
    }
    if at.is_zero() {
        return format!("\\text{{at the origin of }} {body}");
    }
    format!("\\text{{at }} {}", vector_tex(model, at))
}

pub(super) fn free_bodies(derivation: &Derivation) -> Vec<FreeBody> {
    let model = &derivation.model;
    let problem = model.problem;
    let sets = super::pictures::free_body_sets(derivation);
    let shown = super::shown_names::shown_names(model);
    sets.iter()
        .map(|set| {
            let mut view = FreeBody {
                name: bodies_name(problem, set),
                name_tex: Math::from(bodies_tex(derivation, set)),
                bodies: bodies_name(problem, set),
                ..FreeBody::default()
            };
            // A free body of many bodies lists gravity and the inertia forces once, for each
            // body k, as a textbook does for a chain: body by body they would fill pages.
            let grouped = set.len() > MOST_BODIES_LISTED;
            for action in derivation.actions.iter().filter(|a| is_external(a, set)) {
                if grouped && action.source == Source::Gravity {
                    continue;
                }
                let (vector_tex, point_tex) = match &action.kind {
                    ActionKind::Force { offset, force } => {
                        let sign = initial_sign(model);
                        let at = Vector::new(action.body, offset.clone())
                            .map(|e| roots_of_squares(e, &sign));
                        let force = force.map(|e| roots_of_squares(&as_shown(e), &sign));
                        (simplest_tex(model, &force), acts_at(model, action, &at))
                    }
                    ActionKind::Couple { torque } => (
                        vector_tex(model, torque),
                        anywhere_on(model, action.body, &shown),
                    ),
                };
                let mut label = super::force_labels::table_label(model, action, &shown);
                if matches!(action.kind, ActionKind::Couple { .. }) && !label.contains("couple") {
                    label.push_str(" (couple)");
                }
                label.push_str(&super::force_labels::exerted_by(
                    model,
                    action,
                    &shown,
                    &vector_tex,
                ));
                if let Some(other) = opposite_of(derivation, action, &vector_tex) {
                    let other = super::force_labels::shown_name(problem.body_name(other), &shown);
                    label = format!("{label}, opposite to that on {other} (Newton's third law)");
                }
                let force = Force {
                    label: MarkupLine::from(label),
                    vector_tex: Math::from(vector_tex),
                    point_tex: Math::from(point_tex),
                };
                match action.category {
                    Category::Contact => view.contact.push(force),
                    Category::Distance => view.distance.push(force),
                }
            }
            if grouped {
                group_rows(&mut view, derivation, set);
            } else {
                for &body in set {
                    inertia_rows(&mut view, model, body, &shown);
                }
            }
            view
        })
        .collect()
}

/// The body on which `action`'s partner acts, where `action` is printed with its sign
/// turned (`−F_t n̂_y`): the force of a pair that the other body carries as drawn, this one
/// opposite to it (Newton's third law).
fn opposite_of(
    derivation: &Derivation,
    action: &crate::plan::Action,
    printed: &str,
) -> Option<BodyId> {
    let other = action.partner?;
    if !printed.starts_with('-') || other == BodyId::GROUND {
        return None;
    }
    let ActionKind::Force { force, .. } = &action.kind else {
        return None;
    };
    let turned = force.map(|e| -e.clone());
    let pair = derivation.actions.iter().any(|a| {
        a.source == action.source
            && a.body == other
            && matches!(&a.kind, ActionKind::Force { force, .. } if *force == turned)
    });
    pair.then_some(other)
}

fn inertia_rows(view: &mut FreeBody, model: &Model, body: BodyId, shown: &[(String, String)]) {
    if model.bodies[body.0].mass.is_zero() {
        // A massless body's kinetic diagram is empty.
        return;
    }
    let name = model.problem.body_name(body);
    // In math a name is set as a symbol (`rod_a` would be a double subscript).
    let symbol = latex_name(name);
    let name = super::force_labels::shown_name(name, shown);
    let centre = super::tex::centre_tex(model, body);
    let mass = latex(&model.bodies[body.0].mass);
    view.inertia.push(Force {
        label: MarkupLine::from(format!("inertia force of {name}")),
        vector_tex: Math::from(format!("-{mass}\\, {{}}^{{N}}\\mathbf{{a}}^{{{centre}}}")),
        point_tex: Math::from(format!("\\text{{at }} {centre}")),
    });
    if is_particle(model, body) {
        // A particle has no rotational inertia: no inertia torque to write.
        return;
    }
    view.inertia.push(Force {
        label: MarkupLine::from(format!("inertia torque of {name} (couple)")),
        vector_tex: Math::from(torque_tex(&symbol, model.is_planar())),
        point_tex: Math::from(anywhere_on(model, body, shown)),
    });
}

/// Where a couple acts, in the table's column of points: anywhere on its body, since its
/// moment is the same about every point (`anywhere on A`).
pub(super) fn anywhere_on(model: &Model, body: BodyId, shown: &[(String, String)]) -> String {
    let name = latex_name(model.problem.body_name(body));
    let name = match shown.iter().find(|(word, _)| *word == name) {
        Some((_, letter)) => letter.clone(),
        None => name,
    };
    format!("\\text{{anywhere on }} {name}")
}

/// Body `k`'s inertia torque, −I·α − ω × I·ω (−I·α in a plane).
fn torque_tex(k: &str, planar: bool) -> String {
    let terms = super::long::inertia_torque_terms(k, planar);
    format!("-{}", terms.join(" - "))
}

/// Gravity and the inertia forces and torques of every body of `set` as one row each,
/// written for a body k of the set.
fn group_rows(view: &mut FreeBody, derivation: &Derivation, set: &[BodyId]) {
    let model = &derivation.model;
    let every = format!(
        "k \\in \\{{{}\\}}",
        super::tex::bodies_set_tex(derivation, set)
    );
    let at_center = format!("\\text{{at }} k^*,\\; {every}");
    // The bodies' one mass by its own name when they share it (the bars of a four-bar,
    // each of mass m); otherwise body k's, m_k, said so.
    let masses: Vec<String> = set
        .iter()
        .map(|&b| latex(&model.bodies[b.0].mass))
        .collect();
    let (mass, of_mass) = match masses.split_first() {
        Some((first, rest)) if rest.iter().all(|m| m == first) && !first.contains(' ') => {
            (first.clone(), String::new())
        }
        _ => ("m_{k}".to_string(), ", of mass $m_{k}$".to_string()),
    };
    if let Some(g) = &model.problem.gravity {
        let g = vector_of(g);
        view.distance.push(Force {
            label: MarkupLine::from(format!("weight of each body k{of_mass}")),
            vector_tex: Math::from(times_mass(&mass, &vector_tex(model, &g))),
            point_tex: Math::from(at_center.clone()),
        });
    }
    let of_mass = if model.problem.gravity.is_some() {
        String::new()
    } else {
        of_mass
    };
    view.inertia.push(Force {
        label: MarkupLine::from(format!("inertia force of each body k{of_mass}")),
        vector_tex: Math::from(format!("-{mass}\\, {{}}^{{N}}\\mathbf{{a}}^{{k^*}}")),
        point_tex: Math::from(at_center),
    });
    if set.iter().all(|&body| is_particle(model, body)) {
        return;
    }
    view.inertia.push(Force {
        label: "inertia torque of each body k (couple)".into(),
        vector_tex: Math::from(torque_tex("k", model.is_planar())),
        point_tex: Math::from(format!("\\text{{anywhere on }} k,\\; {every}")),
    });
}

/// `mass` times the field `g`: `-m_k g n̂_y` for `-g n̂_y`, `m_k (…)` for a sum.
fn times_mass(mass: &str, g: &str) -> String {
    let single = !g[1..].contains(" + ") && !g[1..].contains(" - ");
    match g.strip_prefix('-') {
        Some(rest) if single => format!("-{mass}\\, {rest}"),
        _ if single => format!("{mass}\\, {g}"),
        _ => format!("{mass} \\left({g}\\right)"),
    }
}

/// The most symbols a row of a free body's table may print in its vector and point columns
/// for the table to fit beside a picture of [`BESIDE_A_TABLE`](crate::render::draw::BESIDE_A_TABLE)
/// in small type: a chain link's pin forces in two components.
const NARROW_TABLE: usize = 36;

/// Whether the free body's table of forces is narrow enough to sit beside its picture.
pub fn table_is_narrow(body: &FreeBody) -> bool {
    let width = |tex: &str| crate::render::printed_width(tex);
    let (vectors, points): (Vec<usize>, Vec<usize>) =
        [&body.contact, &body.distance, &body.inertia]
            .into_iter()
            .flatten()
            .map(|f| (width(&f.vector_tex), width(&f.point_tex)))
            .unzip();
    let widest = |w: &[usize]| w.iter().copied().max().unwrap_or(0);
    widest(&vectors) + widest(&points) <= NARROW_TABLE
}
