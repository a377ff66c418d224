//! A reaction asked for, said once in words beside its components, as a textbook states a
//! force: what it is (friction, the normal force, a tooth force, the force of a pin), which
//! way (up or down where its unit vector is vertical, else along the signed unit vector)
//! and which body exerts it on which: "On the ball, the lane exerts sliding friction along
//! −n̂_x (against the slip) and a normal force up (+n̂_y)." The sizes are the component lines
//! above it, not said again. Where the components are along a body's unit vectors that are
//! not the ground's, the ground's are given too, with the force's size and direction in
//! the plane.

use super::answer_numbers::number_tex;
use super::joint_words::body_words;
use crate::mechanics::{Model, Site, SiteKind, Vector};
use crate::numeric::{Answer, Quantity, ReactionColumn};
use crate::problem::{BodyId, ConstraintKind, Dimension, Problem, Question, QuestionKind};
use crate::symbolic::{eval, latex_unit_vector, ComponentKind, Expr, Values};

/// A component smaller than this (N, N m) is round-off of zero.
const ROUND_OFF: f64 = 1e-10;
/// The cosine above which two unit vectors are taken as the same direction.
const ALIGNED: f64 = 0.999_999;

/// What a force component is, by its site and its direction.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// Along a contact's normal.
    Normal,
    /// Along a contact's tangent; sliding where it has reached μ times the normal force.
    Friction { sliding: bool },
    /// Along the tangent of meshing teeth.
    Tooth,
    /// Any other: a pin's or a slider's force.
    Force,
}

/// One component found: its unit vector's index in the answer's frame and its value.
type Found = (usize, f64);

/// The state the answer holds at, with the frame its components are along.
struct At<'m, 'p> {
    model: &'m Model<'p>,
    values: Values,
    frame: BodyId,
    /// The unit vector opposite to gravity, in `N`; `None` without gravity.
    up: Option<[f64; 3]>,
    /// Whether the system moves at this state: a reaction's components along fixed unit
    /// vectors are then of this instant (the top's floor force turns with it).
    moving: bool,
}

impl At<'_, '_> {
    /// Unit vector `axis` of the answer's frame, along `N`'s.
    fn unit_in_ground(&self, axis: usize) -> [f64; 3] {
        self.in_ground(&Vector::unit(self.frame, axis))
    }

    fn in_ground(&self, v: &Vector) -> [f64; 3] {
        let c = v.components_in(BodyId::GROUND, &self.model.frames);
        numbers(&c, &self.values)
    }
}

fn numbers(c: &[Expr; 3], values: &Values) -> [f64; 3] {
    std::array::from_fn(|k| eval(&c[k], values))
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|k| a[k] * b[k]).sum()
}

fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// The words under a reaction answer; `None` for another question or where the problem's
/// kinematics cannot be evaluated.
pub(super) fn note(problem: &Problem, question: &Question, answer: &Answer) -> Option<String> {
    let QuestionKind::Reaction { site } = question.kind else {
        return None;
    };
    let model = Model::build(problem).ok()?;
    let name = problem.site_name(site);
    let place = model.sites.iter().find(|s| s.name == name)?;
    let frame_name = answer.frame.clone().unwrap_or_else(|| {
        let id = crate::numeric::reaction_frame(problem, site);
        problem.body_name(id).to_string()
    });
    let frame = match frame_name == problem.body_name(BodyId::GROUND) {
        true => BodyId::GROUND,
        false => problem
            .body_ids()
            .find(|&b| problem.body_name(b) == frame_name)?,
    };
    let values = model.values_at(answer.time, &answer.q, &answer.rates);
    let up = gravity_up(problem, &values);
    let at = At {
        model: &model,
        values,
        frame,
        up,
        moving: answer.rates.iter().any(|r| r.abs() > ROUND_OFF),
    };
    let (forces, moments) = found(question, answer);
    if forces.is_empty() && moments.is_empty() {
        return None;
    }
    let mut out = sentence(problem, place, &at, (&frame_name, &forces, &moments));
    if let Some(more) = in_ground(problem, name, &at, &forces) {
        out = format!("{out} {more}");
    }
    Some(out)
}

/// The force and the moment components shown, each nonzero.
fn found(question: &Question, answer: &Answer) -> (Vec<Found>, Vec<Found>) {
    let (mut forces, mut moments) = (Vec::new(), Vec::new());
    for (quantity, value) in &answer.values {
        let Quantity::Reaction(ReactionColumn::Component { kind, axis, .. }) = quantity else {
            continue;
        };
        if value.abs() < ROUND_OFF || crate::numeric::is_free_moment(question, quantity, *value) {
            continue;
        }
        match kind {
            ComponentKind::Force => forces.push((*axis, *value)),
            ComponentKind::Moment => moments.push((*axis, *value)),
        }
    }
    (forces, moments)
}

/// The unit vector opposite to the problem's gravity, where gravity is given along the
/// ground's unit vectors.
fn gravity_up(problem: &Problem, values: &Values) -> Option<[f64; 3]> {
    let gravity = problem.gravity.as_ref()?;
    let mut g = [0.0; 3];
    for (frame, axis, coefficient) in &gravity.terms {
        if *frame != BodyId::GROUND || *axis > 2 {
            return None;
        }
        g[*axis as usize] += eval(coefficient, values);
    }
    let size = norm(g);
    (size > 0.0).then(|| g.map(|x| -x / size))
}

/// "On the ball, the lane exerts …": each component in words, joined.
fn sentence(
    problem: &Problem,
    site: &Site,
    at: &At,
    (frame, forces, moments): (&str, &[Found], &[Found]),
) -> String {
    let kinds: Vec<Kind> = (forces.iter())
        .map(|&(axis, _)| kind(problem, site, at, axis, forces))
        .collect();
    let mut parts: Vec<String> = Vec::new();
    let plain: Vec<String> = (forces.iter().zip(&kinds))
        .filter(|(_, k)| **k == Kind::Force)
        .map(|(&(axis, value), _)| sense(at, frame, axis, value))
        .collect();
    if !plain.is_empty() {
        parts.push(format!("a force {}", plain.join(" and ")));
    }
    for (&(axis, value), kind) in forces.iter().zip(&kinds) {
        let words = sense(at, frame, axis, value);
        match kind {
            Kind::Normal => parts.push(format!("a normal force {words}")),
            Kind::Friction { sliding: true } => {
                parts.push(format!("sliding friction {words} (against the slip)"))
            }
            Kind::Friction { sliding: false } => parts.push(format!("friction {words}")),
            Kind::Tooth => parts.push(format!("a tangential tooth force {words}")),
            Kind::Force => {}
        }
    }
    for &(axis, value) in moments {
        parts.push(format!("a couple {}", sense(at, frame, axis, value)));
    }
    let on = body_words(problem, site.child);
    let by = exerter(problem, site);
    let point = match site.kind {
        SiteKind::Joint(_) | SiteKind::Closure(_) if is_letter(&site.name) => {
            format!(" at {}", site.name)
        }
        _ => String::new(),
    };
    let teeth = match kinds.contains(&Kind::Tooth) {
        true => {
            " Its component across the common pitch tangent is zero by \
                 assumption, not as a result: the pressure angle is neglected, so the teeth \
                 push only along that tangent, and the joints carry the load across it."
        }
        false => "",
    };
    let when = if at.moving { ", at this instant" } else { "" };
    // Sliding from rest: the answer to whether friction can hold it comes first.
    let held = match kinds.contains(&Kind::Friction { sliding: true }) && !at.moving {
        true => format!(
            "Friction cannot hold {on} at rest: sticking would need more than μ times the normal force (the check in step 5), so it slides. "
        ),
        false => String::new(),
    };
    let side = match site.kind {
        SiteKind::Closure(_) if kinds.contains(&Kind::Normal) => {
            rod_side(at, forces, &kinds, (&on, &by))
        }
        _ => String::new(),
    };
    format!(
        "{held}On {on}{point}, {by} exerts {}{when}.{teeth}{side}",
        join_and(&parts)
    )
}

/// `a, b and c`.
fn join_and(parts: &[String]) -> String {
    match parts {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// Whether a site's name reads as a point's letter (`O`, `R`, `P2`), not a word.
fn is_letter(name: &str) -> bool {
    name.chars().count() <= 3
        && name.chars().next().is_some_and(char::is_uppercase)
        && name.chars().all(char::is_alphanumeric)
}

/// The body that exerts the site's reaction: the parent, or for a contact with the ground
/// named by a word, the surface by its name ("the lane", "the floor"), and likewise a
/// closure with the ground named by a word ("the rod" a collar slides on).
fn exerter(problem: &Problem, site: &Site) -> String {
    let surface = site.parent == BodyId::GROUND
        && matches!(site.kind, SiteKind::Contact(_) | SiteKind::Closure(_))
        && !is_letter(&site.name)
        && site.name != "contact";
    match surface {
        true => super::force_labels::place(&site.name),
        false => body_words(problem, site.parent),
    }
}

/// `along $-\hat{\mathbf{n}}_{x}$`, or `up ($+\hat{\mathbf{n}}_{y}$)` where the unit
/// vector is vertical: the component's sense, its size being on its line above.
fn sense(at: &At, frame: &str, axis: usize, value: f64) -> String {
    let sign = if value > 0.0 { "+" } else { "-" };
    let vector = format!("${sign}{}$", latex_unit_vector(frame, axis as u8));
    let vertical = at
        .up
        .map_or(0.0, |up| dot(at.unit_in_ground(axis), up) * value.signum());
    match vertical {
        v if v > ALIGNED => format!("up ({vector})"),
        v if v < -ALIGNED => format!("down ({vector})"),
        _ => format!("along {vector}"),
    }
}

/// What component `axis` of the answer is at `site`: along a contact's normal, along its
/// tangent (friction, or a tooth force where teeth mesh), or a pin's force.
fn kind(problem: &Problem, site: &Site, at: &At, axis: usize, forces: &[Found]) -> Kind {
    if let SiteKind::Closure(k) = site.kind {
        return rod_kind(problem, k, at, axis, forces);
    }
    let SiteKind::Contact(k) = site.kind else {
        return Kind::Force;
    };
    let Some(n) = normal_in_ground(problem, site, at) else {
        return Kind::Force;
    };
    let u = at.unit_in_ground(axis);
    let along = dot(u, n);
    if along.abs() > ALIGNED {
        return Kind::Normal;
    }
    if along.abs() > 1.0 - ALIGNED {
        return Kind::Force;
    }
    let constraint = problem.constraints.get(k);
    let teeth = matches!(
        constraint.map(|c| &c.kind),
        Some(ConstraintKind::Gear { .. })
    ) || ["teeth", "tooth", "mesh"]
        .iter()
        .any(|w| site.name.to_lowercase().contains(w));
    if teeth {
        return Kind::Tooth;
    }
    let sliding = constraint
        .and_then(|c| c.friction.as_ref())
        .is_some_and(|mu| reaches_limit(eval(mu, &at.values), n, at, forces));
    Kind::Friction { sliding }
}

/// The fixed rod of a rough prismatic closure with the ground in the plane, which a collar
/// slides on: along it friction, across it in the plane the normal force.
fn rod_axis(problem: &Problem, k: usize, at: &At) -> Option<(f64, [f64; 3])> {
    let closure = problem.closures.get(k)?;
    let rough = closure.kind == crate::problem::JointKind::Prismatic
        && closure.parent == BodyId::GROUND
        && problem.dimension == Dimension::Two;
    let mu = eval(closure.friction.as_ref().filter(|_| rough)?, &at.values);
    let a = at.in_ground(&crate::mechanics::vector_of(closure.axis.as_ref()?));
    let size = norm(a);
    (size > 1e-12).then(|| (mu, a.map(|x| x / size)))
}

/// What component `axis` of a closure's reaction is: friction or the normal force on a
/// rough rod (see [`rod_axis`]), else a slider's force.
fn rod_kind(problem: &Problem, k: usize, at: &At, axis: usize, forces: &[Found]) -> Kind {
    let Some((mu, a)) = rod_axis(problem, k, at) else {
        return Kind::Force;
    };
    let u = at.unit_in_ground(axis);
    let along = dot(u, a);
    let n = [-a[1], a[0], 0.0];
    match along.abs() {
        x if x > ALIGNED => Kind::Friction {
            sliding: reaches_limit(mu, n, at, forces),
        },
        x if x < 1.0 - ALIGNED && u[2].abs() < 1.0 - ALIGNED => Kind::Normal,
        _ => Kind::Force,
    }
}

/// Which side of a horizontal rod the body bears on, by the sense of the rod's vertical
/// force on it: pushed down, it presses up on the rod's underside.
fn rod_side(at: &At, forces: &[Found], kinds: &[Kind], (on, by): (&str, &str)) -> String {
    let Some(up) = at.up else {
        return String::new();
    };
    let vertical: f64 = (forces.iter().zip(kinds))
        .filter(|(_, k)| **k == Kind::Normal)
        .map(|(&(axis, value), _)| value * dot(at.unit_in_ground(axis), up))
        .sum();
    match vertical {
        v if v < -ROUND_OFF => format!(
            " {} pushes {on} down, so {on} presses up against {by} from below: it bears on the underside.",
            capital(by)
        ),
        v if v > ROUND_OFF => format!(
            " {} pushes {on} up, so {on} presses down on {by} from above: it bears on the top side.",
            capital(by)
        ),
        _ => String::new(),
    }
}

/// `the rod` → `The rod`.
fn capital(words: &str) -> String {
    let mut chars = words.chars();
    chars
        .next()
        .map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}

/// The unit normal of a contact site along `N`'s unit vectors: the plane's normal as the
/// problem writes it, or for gears the line of centres (the contact point from the centre
/// of the disc that rolls).
fn normal_in_ground(problem: &Problem, site: &Site, at: &At) -> Option<[f64; 3]> {
    let SiteKind::Contact(k) = site.kind else {
        return None;
    };
    let n = match &problem.constraints.get(k)?.kind {
        ConstraintKind::Rolling { normal, .. } | ConstraintKind::Contact { normal, .. } => {
            at.in_ground(&crate::mechanics::vector_of(normal))
        }
        ConstraintKind::Gear { body, .. } => {
            let centre = &at.model.bodies[body.0].origin.position;
            at.in_ground(&site.point.position.minus(centre))
        }
        _ => return None,
    };
    let size = norm(n);
    (size > 1e-12).then(|| n.map(|x| x / size))
}

/// Whether the tangential force found is μ times the normal force: the contact slides.
/// `n` is the unit normal along `N`'s unit vectors.
fn reaches_limit(mu: f64, n: [f64; 3], at: &At, forces: &[Found]) -> bool {
    let total: [f64; 3] = std::array::from_fn(|k| {
        (forces.iter())
            .map(|&(axis, value)| value * at.unit_in_ground(axis)[k])
            .sum()
    });
    let along = dot(total, n);
    let tangential = (norm(total).powi(2) - along * along).max(0.0).sqrt();
    (tangential - mu * along.abs()).abs() <= 1e-9 * (1.0 + tangential)
}

/// Where the components are along a turning body's unit vectors in a plane: the same force
/// along the ground's, its size and its angle from `n̂_x`.
fn in_ground(problem: &Problem, name: &str, at: &At, forces: &[Found]) -> Option<String> {
    if at.frame == BodyId::GROUND || problem.dimension != Dimension::Two || forces.is_empty() {
        return None;
    }
    let f: [f64; 3] = std::array::from_fn(|k| {
        (forces.iter())
            .map(|&(axis, value)| value * at.unit_in_ground(axis)[k])
            .sum()
    });
    let turned = (0..3).any(|a| (at.unit_in_ground(a)[a] - 1.0).abs() > 1e-9);
    if !turned {
        return None;
    }
    let site = name.replace('_', "\\_");
    let component = |axis: usize| {
        format!(
            "$\\mathbf{{F}}^{{\\mathrm{{{site}}}}} \\cdot {} = {}\\ \\mathrm{{N}}$",
            latex_unit_vector("N", axis as u8),
            number_tex(f[axis])
        )
    };
    let angle = f[1].atan2(f[0]).to_degrees();
    let toward = if angle >= 0.0 { "+" } else { "-" };
    Some(format!(
        "Along the ground's unit vectors, {} and {}: a force of ${}\\ \\mathrm{{N}}$ at ${}^\\circ$ from $+{}$ toward ${toward}{}$.",
        component(0),
        component(1),
        number_tex(f[0].hypot(f[1])),
        number_tex((angle.abs() * 10.0).round() / 10.0),
        latex_unit_vector("N", 0),
        latex_unit_vector("N", 1)
    ))
}
