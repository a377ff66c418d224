//! The pictures' scenes (steps 1 and 2, and the motion of step 6): the configuration and
//! each free body of the plan with its kinetic diagram, built in `N`'s coordinates from the
//! model at a state ([`build`]) and laid out by [`crate::render::draw`], which writes them.

mod applied;
pub(super) mod bodies;
pub(super) mod build;
mod carriers;
mod contact_surfaces;
pub(super) mod gauges;
mod guide;
mod joint_symbols;
pub(super) mod lanes;
mod load_symbols;
pub(super) mod motion;
mod names;
pub(super) mod numbers;
pub(super) mod shapes;
pub(super) mod sheets;
mod sliding;
mod travel;
mod triads;
mod velocities;

use crate::equations::Derivation;
use crate::problem::BodyId;
use crate::render::draw::{layout, Drawing, View};
pub use build::{point_id, FREE_BODY_LEGEND, FREE_BODY_LEGEND_THIRD_LAW, SLIDING_FRICTION};
use numbers::{norm, sub, Numbers};

/// The configuration of the derivation's problem at its initial state, for the student's
/// handout.
pub fn initial_configuration(derivation: &Derivation) -> Option<Drawing> {
    let problem = derivation.model.problem;
    let state = problem.initial_state();
    let at = (state.t, state.q.as_slice(), state.rates.as_slice());
    let names = crate::solution::shown_names::shown_names(&derivation.model);
    drawings(derivation, at, None, View::Isometric, (true, &names, START))
        .into_iter()
        .next()
}

/// The legend of the free bodies among `drawings`: the one that names Newton's third law
/// where any of them draws a reaction opposite its + axes, and sliding friction where any
/// draws it.
pub fn free_body_legend(drawings: &[Drawing]) -> String {
    let any = |f: fn(&str) -> bool| drawings.iter().any(|d| f(&d.scene.legend));
    build::legend_of(
        any(|l| l.contains("Newton's third law")),
        any(|l| l.contains(build::SLIDING_FRICTION)),
    )
}

/// The free bodies of the plan, in the order its rows first use them, then one for each
/// reaction asked for that none of them shows on its body.
pub fn free_body_sets(derivation: &Derivation) -> Vec<Vec<BodyId>> {
    let mut sets: Vec<Vec<BodyId>> = Vec::new();
    for row in &derivation.rows {
        // An auxiliary row whose force is inside its bodies is shown on another.
        let elsewhere = crate::solution::auxiliary::drawn_on(derivation, row).is_some();
        if !row.free_body.is_empty() && !elsewhere && !sets.contains(&row.free_body) {
            sets.push(row.free_body.clone());
        }
    }
    super::asked_bodies::with_asked(derivation, sets)
}

/// How far across a free body is drawn: as the configuration for a few, smaller for a
/// long chain's many, whose step 2 would otherwise take two pictures a page (the labels
/// keep their size; only the bodies and their arrows' spacing shrink).
fn free_body_content(free_bodies: usize) -> f64 {
    /// The most free bodies drawn at the configuration's size.
    const MOST_AT_FULL_SIZE: usize = 3;
    /// A long chain's free body: a link about 3 cm long on the page, narrow enough
    /// upright for its table of forces beside it.
    const MANY: f64 = 140.0;
    if free_bodies <= MOST_AT_FULL_SIZE {
        crate::render::draw::CONTENT
    } else {
        MANY
    }
}

/// The plan table's name of a free body, e.g. `A + B`.
pub fn free_body_name(problem: &crate::problem::Problem, set: &[BodyId]) -> String {
    set.iter()
        .map(|b| problem.body_name(*b).to_string())
        .collect::<Vec<_>>()
        .join(" + ")
}

/// The system's characteristic length: the spread of its points, or its bodies' size.
pub(super) fn size_of(n: &Numbers) -> f64 {
    let model = n.model;
    let mut points: Vec<numbers::P3> = model
        .joints
        .iter()
        .map(|j| n.vector(&j.point.position))
        .collect();
    points.extend(model.bodies.iter().map(|b| n.vector(&b.center.position)));
    for (i, _) in model.problem.points.iter().enumerate() {
        points.push(n.vector(&model.position(crate::problem::PointRef::Named(i))));
    }
    let points: Vec<_> = points
        .into_iter()
        .filter(|p| p.iter().all(|x| x.is_finite()))
        .collect();
    let mut spread = 0.0f64;
    for a in &points {
        for b in &points {
            spread = spread.max(norm(sub(*a, *b)));
        }
    }
    if spread > 1e-9 {
        return spread;
    }
    // Everything at one point (a top, a gimbal): the size the inertia gives.
    let radius = model
        .problem
        .body_ids()
        .filter_map(|b| {
            let body = model.problem.body(b);
            let m = n.scalar(&body.mass);
            let i = match &body.inertia {
                crate::problem::Inertia::Planar(i) => n.scalar(i),
                crate::problem::Inertia::Spatial(m) => {
                    (0..3).map(|k| n.scalar(&m[k][k])).fold(0.0, f64::max)
                }
            };
            (m > 0.0 && i > 0.0).then(|| (2.0 * i / m).sqrt())
        })
        .fold(0.0, f64::max);
    if radius > 0.0 {
        4.0 * radius
    } else {
        1.0
    }
}

/// Every picture of `derivation` at time `t`, coordinates `q` and rates `rates`, seen
/// along `view`: the configuration, then one per free body of the plan. With the q''
/// (`accelerations`) the kinetic diagrams carry `m a*` and `I α`; without, only the bodies.
/// Word-named bodies and points are printed by the letters the handout gives them (the
/// contact `lane` is P: F^P, not F^lane), so that a picture and its handout agree.
pub fn draw(
    derivation: &Derivation,
    t: f64,
    q: &[f64],
    rates: &[f64],
    accelerations: Option<&[f64]>,
    view: View,
) -> Vec<Drawing> {
    let names = crate::solution::shown_names::shown_names(&derivation.model);
    let when = format!("at t = {} s", signed(t));
    drawings(
        derivation,
        (t, q, rates),
        accelerations,
        view,
        (true, &names, &when),
    )
}

/// The pictures of [`draw`] as a handout prints them: word-named bodies and points by
/// their letters (see `names`).
pub fn draw_in_handout(
    derivation: &Derivation,
    (q, rates): (&[f64], &[f64]),
    accelerations: Option<&[f64]>,
) -> Vec<Drawing> {
    let names = crate::solution::shown_names::shown_names(&derivation.model);
    let at = (0.0, q, rates);
    drawings(
        derivation,
        at,
        accelerations,
        View::Isometric,
        (true, &names, START),
    )
}

/// The pictures of [`draw`] for a system at rest at `q`: the free bodies without kinetic
/// diagrams (there are no inertia forces to draw).
pub fn draw_at_rest(derivation: &Derivation, q: &[f64], rates: &[f64], view: View) -> Vec<Drawing> {
    drawings(
        derivation,
        (0.0, q, rates),
        None,
        view,
        (false, &[], "at rest"),
    )
}

/// The pictures at time, coordinates and rates `(t, q, rates)`; `kinetic` with the
/// kinetic diagrams; every label with `names` replaced (see `names`); `when` says in the
/// configuration's caption which state it shows (`at the start`).
fn drawings(
    derivation: &Derivation,
    (t, q, rates): (f64, &[f64], &[f64]),
    accelerations: Option<&[f64]>,
    view: View,
    (kinetic, names, when): (bool, &[(String, String)], &str),
) -> Vec<Drawing> {
    let model = &derivation.model;
    let problem = model.problem;
    let mut numbers = Numbers::new(model, t, q, rates);
    if let Some(a) = accelerations {
        numbers.set_accelerations(a);
    }
    let size = size_of(&numbers);
    let setting = build::Setting {
        derivation,
        numbers: &numbers,
        accelerations: accelerations.is_some(),
        size,
    };
    let title = configuration_caption(problem, when, q);
    let mut scene = setting.configuration(title.clone());
    names::rename(&mut scene, names);
    let mut out = vec![Drawing {
        name: "configuration".into(),
        title,
        free_body: String::new(),
        picture: layout::lay_out(&scene, view),
        scene,
        view,
    }];
    let sets = free_body_sets(derivation);
    let content = free_body_content(sets.len());
    for set in sets {
        let name = free_body_name(problem, &set);
        let title = format!("Free body {name}");
        let mut scene = setting.free_body(&set, title.clone(), content);
        if !kinetic {
            scene.kinetic = None;
        }
        names::rename(&mut scene, names);
        out.push(Drawing {
            name: format!("fbd-{}", name.replace(' ', "")),
            title,
            free_body: name,
            picture: layout::lay_out(&scene, view),
            scene,
            view,
        });
    }
    out
}

/// The caption of the configuration at the state a handout starts from.
const START: &str = "at the start";

/// The configuration's caption in a course's words: `The configuration at the start:
/// q₁ = 0.7 rad, q₂ = −0.4 rad` (`when` is `at the start`), each coordinate with its unit,
/// a minus sign for minus, and `\phi` as LaTeX sets it (ϕ).
pub fn configuration_caption(problem: &crate::problem::Problem, when: &str, q: &[f64]) -> String {
    let state: Vec<String> = (problem.coordinates.iter().enumerate())
        .zip(q)
        .map(|((i, c), v)| {
            let symbol = crate::render::unicode_of(&crate::symbolic::latex_name(&c.name));
            let unit = crate::numeric::coordinate_unit(problem, i, 0);
            format!("{symbol} = {} {unit}", signed(*v))
        })
        .collect();
    format!("The configuration {when}: {}", state.join(", "))
}

/// A number as [`fixed`](crate::symbolic::fixed) writes it, with a minus sign (−) for its
/// hyphen.
fn signed(x: f64) -> String {
    if x < 0.0 {
        format!("\u{2212}{}", crate::symbolic::fixed(-x))
    } else {
        crate::symbolic::fixed(x)
    }
}
