//! Step 4's vectors: each body's angular velocity and acceleration and its mass centre's
//! velocity and acceleration, in the shortest of their multiplied-out and named forms.

use super::tex::{component_term, shortest_tex, vector_tex_by};
use crate::equations::Derivation;
use crate::mechanics::{same_at, sample_states, Model, Vector};
use crate::problem::BodyId;
use crate::render::context::{Kinematics, Named};
use crate::render::printed_width;
use crate::render::text::Math;
use crate::symbolic::{
    add, factored, latex_name, linear_split, pull_common_factor, simplify, Expr,
};

/// Step 4's vectors, body by body, and whether an acceleration is written by the partial
/// velocities (`Σ_r ᴺv_r q̈_r + ᴺã`), which the where list then defines: of mass centres
/// only, or of joint points too.
pub(super) fn kinematics(derivation: &Derivation) -> (Vec<Kinematics>, ByPartials) {
    let model = &derivation.model;
    let inertia = derivation.inertia();
    // The shorter of the vector multiplied out and as the equations use it (named parts).
    let shorter = |expanded: &Vector, named: &Vector, body: BodyId| {
        let b = shortest_tex(model, named, body);
        // Multiplied out to many times the named form's size, a vector cannot come out the
        // shorter, and simplifying it (in three frames) is most of a large handout's time.
        if expanded.operation_count() > 4 * named.operation_count().max(100) {
            return b;
        }
        let a = shortest_tex(model, expanded, body);
        if b.len() < a.len() {
            b
        } else {
            a
        }
    };
    let mut by_partials = false;
    // The joint points' named accelerations without the q'' (`ã^{head}`), which the where
    // list defines when a child's acceleration is built on them: a long pin acceleration
    // is then written by the rule with them, not multiplied out a second time.
    let joint_rests = crate::symbolic::named_definitions(
        inertia
            .acceleration
            .iter()
            .flat_map(|v| v.parts())
            .flat_map(|(_, c)| c.iter()),
    );
    let states = sample_states(model);
    // A body named by a word is headed by the letter the handout prints for it.
    let shown = super::shown_names::shown_names(model);
    let mut pins_by_partials = false;
    let views = model
        .order
        .iter()
        .map(|&body| {
            let state = &model.bodies[body.0];
            let name = model.problem.body_name(body);
            let symbol = latex_name(name);
            let centre = super::tex::centre_tex(model, body);
            let partials = by_partial_velocities(model, &inertia.acceleration[body.0], body);
            let direct_velocity = match &partials {
                Some(named) => shorter(&state.center.velocity, named, body),
                None => shortest_tex(model, &state.center.velocity, body),
            };
            let direct_acceleration = shorter(
                &state.center.acceleration,
                &inertia.acceleration[body.0],
                body,
            );
            let pin = pin_of(model, body);
            let mut acceleration = match pin {
                Some(site) => {
                    from_pin(model, body, site, Motion::Acceleration, direct_acceleration)
                }
                None => from_parent(model, body, Motion::Acceleration, direct_acceleration),
            };
            // Written out over lines, the acceleration repeats the velocity's coefficients;
            // by the rule it is one line when its rest is named.
            if partials.is_some() && printed_width(&acceleration) > LINE {
                let rule = by_the_rule(model, &inertia.acceleration[body.0], body, &centre);
                if let Some(rule) = rule.filter(|r| printed_width(r) <= LINE) {
                    acceleration = rule;
                    by_partials = true;
                }
            }
            let light = crate::mechanics::is_massless(model, body);
            let particle = !light && crate::mechanics::is_point_particle(model, body);
            // A particle's turning carries no inertia: a textbook gives it no ω or α.
            let (omega_tex, alpha_tex) = if particle {
                (String::new(), String::new())
            } else {
                one_line_if_short(
                    format!(
                        "{{}}^{{N}}\\boldsymbol{{\\omega}}^{{{symbol}}} = {}",
                        shorter(&state.omega, &state.omega_named, body)
                    ),
                    format!(
                        "{{}}^{{N}}\\boldsymbol{{\\alpha}}^{{{symbol}}} = {}",
                        shorter(&state.alpha, &inertia.alpha[body.0], body)
                    ),
                )
            };
            let velocity = match pin {
                Some(site) => from_pin(model, body, site, Motion::Velocity, direct_velocity),
                None => from_parent(model, body, Motion::Velocity, direct_velocity),
            };
            let (velocity_tex, acceleration_tex) = one_line_if_short(
                format!("{{}}^{{N}}\\mathbf{{v}}^{{{centre}}} = {velocity}"),
                format!("{{}}^{{N}}\\mathbf{{a}}^{{{centre}}} = {acceleration}"),
            );
            let ((pin_velocity_tex, pin_acceleration_tex), pin_by_rule) =
                pin_lines(model, pin, &joint_rests, &states);
            if pin_by_rule {
                (by_partials, pins_by_partials) = (true, true);
            }
            Kinematics {
                body: super::force_labels::shown_name(name, &shown),
                particle,
                light,
                position_tex: Math::from(if model.order.len() <= MOST_BODIES_PLACED {
                    position_line(model, body)
                } else {
                    String::new()
                }),
                omega_tex: Math::from(omega_tex),
                alpha_tex: Math::from(alpha_tex),
                pin_velocity_tex: Math::from(pin_velocity_tex),
                pin_acceleration_tex: Math::from(pin_acceleration_tex),
                velocity_tex: Math::from(velocity_tex),
                acceleration_tex: Math::from(acceleration_tex),
            }
        })
        .collect();
    let by = match (by_partials, pins_by_partials) {
        (false, _) => ByPartials::None,
        (true, false) => ByPartials::MassCentres,
        (true, true) => ByPartials::AndJointPoints,
    };
    (views, by)
}

/// Which accelerations of step 4 are written by the partial velocities.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum ByPartials {
    /// None: the where list needs no rule.
    None,
    /// Mass centres' only.
    MassCentres,
    /// Joint points' as well.
    AndJointPoints,
}

/// The velocity and acceleration of the joint point of `pin`, where a body is pinned to
/// its parent, and whether the acceleration is written by the rule with the joint points'
/// named accelerations `joint_rests`.
fn pin_lines(
    model: &Model,
    pin: Option<usize>,
    joint_rests: &[crate::symbolic::Definition],
    states: &[crate::symbolic::Values],
) -> ((String, String), bool) {
    match pin {
        // A pin at the parent's mass centre (a bob's) has that centre's motion,
        // written above: v^{B*} follows from v^{A*}.
        Some(site) if at_parent_centre(model, site) => ((String::new(), String::new()), false),
        Some(site) => {
            let mut acceleration = pin_line(model, site, Motion::Acceleration);
            let mut by_rule = false;
            if printed_width(&acceleration) > LINE {
                let rule = pin_by_the_rule(model, site, joint_rests, states);
                if let Some(rule) = rule.filter(|r| printed_width(r) < printed_width(&acceleration))
                {
                    acceleration = rule;
                    by_rule = true;
                }
            }
            let lines = one_line_if_short(pin_line(model, site, Motion::Velocity), acceleration);
            (lines, by_rule)
        }
        None => ((String::new(), String::new()), false),
    }
}

/// A long acceleration of the pin `site` by the rule, `Σ_r ᴺv^P_r q̈_r + ã^P`, its rest by
/// the names the where list already gives it (each checked by value at `states`), else
/// written out; `None` when no rest is named.
fn pin_by_the_rule(
    model: &Model,
    site: usize,
    named: &[crate::symbolic::Definition],
    states: &[crate::symbolic::Values],
) -> Option<String> {
    use crate::mechanics::SiteKind;
    let pin = &model.sites[site];
    let SiteKind::Joint(j) = pin.kind else {
        return None;
    };
    let joint = &model.problem.joints[j].name;
    let accelerations = model.problem.speed_symbols(2);
    let components =
        pin_motion(model, site, Motion::Acceleration).components_in(pin.parent, &model.frames);
    let mut any_named = false;
    let mut rest = Vec::with_capacity(3);
    for (axis, a) in components.iter().enumerate() {
        let (_, without) = linear_split(&simplify(a), &accelerations).ok()?;
        let key = format!("{joint}.a.{}", crate::mechanics::AXES[axis]);
        let name = named
            .iter()
            .find(|d| d.name() == key && same_at(d.value(), &without, states));
        rest.push(match name {
            Some(d) => {
                any_named = true;
                Expr::sym(crate::symbolic::Symbol::Defined(d.clone()))
            }
            None => without,
        });
    }
    if !any_named {
        return None;
    }
    let rest = Vector::new(pin.parent, rest.try_into().ok()?);
    let rest_tex = vector_tex_by(model, &rest, component_term);
    let point = latex_name(&pin.name);
    let speed = if model.problem.has_speeds() {
        "\\dot{u}_{r}"
    } else {
        "\\ddot{q}_{r}"
    };
    let sign = if rest_tex.starts_with('-') { "" } else { "+ " };
    Some(format!(
        "{} = \\sum_{{r}} {{}}^{{N}}\\mathbf{{v}}^{{{point}}}_{{r}}\\, {speed} {sign}{rest_tex}",
        pin_symbol(model, site, Motion::Acceleration)
    ))
}

/// The most bodies whose mass centres step 4 places from their pins: a long chain's
/// places are its links' lengths over again, and would add pages.
const MOST_BODIES_PLACED: usize = 4;

/// The mass centre's place from the pin that holds `body` (its joint to its parent at a
/// point fixed in both), in the body's unit vectors, `\mathbf{r}^{O A^*} = -L \hat{…}_y`;
/// empty when the body is held otherwise or its mass centre is at the pin.
fn position_line(model: &Model, body: BodyId) -> String {
    use crate::mechanics::{SiteKind, Vector};
    use crate::problem::JointKind;
    let Some(site) = model.sites.iter().find(|site| {
        site.child == body
            && matches!(site.kind, SiteKind::Joint(j) if matches!(
                model.problem.joints[j].kind,
                JointKind::Revolute | JointKind::Universal | JointKind::Spherical | JointKind::Weld
            ))
    }) else {
        return String::new();
    };
    let centre = &model.bodies[body.0].center_offset;
    let from_pin = Vector::new(
        body,
        std::array::from_fn(|k| simplify(&(&centre[k] - &site.child_offset[k]))),
    );
    if from_pin.is_zero() {
        return String::new();
    }
    format!(
        "\\mathbf{{r}}^{{{} {}}} = {}",
        latex_name(&site.name),
        super::tex::centre_tex(model, body),
        super::tex::vector_tex(model, &from_pin)
    )
}

/// The where list's entry for accelerations written by the partial velocities, of mass
/// centres (`k^*`) or of points (`P`) when joint points are written so too.
pub(super) fn partial_velocity_definition(derivation: &Derivation, by: ByPartials) -> Named {
    let rate = if derivation.model.problem.has_speeds() {
        "u_{r}"
    } else {
        "\\dot{q}_{r}"
    };
    let (point, whose) = match by {
        ByPartials::AndJointPoints => ("P", "each mass centre and joint point"),
        _ => ("k^*", "each mass centre"),
    };
    Named::new(
        format!("{{}}^{{N}}\\mathbf{{v}}^{{{point}}}_{{r}} = \\partial\\, {{}}^{{N}}\\mathbf{{v}}^{{{point}}} / \\partial {rate}"),
        format!("the partial velocities of {whose}: the coefficient of each rate in its velocity above, and of the rate's derivative in its acceleration"),
    )
}

/// A pair such as ω and α, or v* and a*, in one display, `ω = …, α = …`, when together they
/// fit most of a line, as a textbook sets a pair of short results; else each in its own
/// (the second's then empty here).
fn one_line_if_short(first: String, second: String) -> (String, String) {
    const MOST_OF_A_LINE: usize = 60;
    if crate::render::printed_width(&first) + crate::render::printed_width(&second)
        <= MOST_OF_A_LINE
    {
        (format!("{first}, \\qquad {second}"), String::new())
    } else {
        (first, second)
    }
}

/// The mass centre's velocity as `Σ v_r q̇_r`, with the partial velocities named in its
/// acceleration `Σ v_r q̈_r + ã` (∂a/∂q̈_r = ∂v/∂q̇_r), or `None` when the velocity has a part
/// the rates do not carry (a driven coordinate's time) or a coefficient differs.
fn by_partial_velocities(model: &Model, acceleration: &Vector, body: BodyId) -> Option<Vector> {
    let rates = model.problem.speed_symbols(1);
    let accelerations = model.problem.speed_symbols(2);
    let velocity = model.bodies[body.0]
        .center
        .velocity
        .components_in(body, &model.frames);
    let named = acceleration.components_in(body, &model.frames);
    let states = sample_states(model);
    let mut components = Vec::with_capacity(3);
    for (v, a) in velocity.iter().zip(&named) {
        let (by_rate, rest) = linear_split(&simplify(v), &rates).ok()?;
        let (partials, _) = linear_split(a, &accelerations).ok()?;
        if !rest.is_zero() {
            return None;
        }
        let mut terms = Vec::with_capacity(rates.len());
        for ((partial, expanded), rate) in partials.iter().zip(&by_rate).zip(&rates) {
            // The named partial may be built on its parent's: compared by value at the
            // planner's sample states, where an identity holds and a slip would not.
            if !same_at(partial, expanded, &states) {
                return None;
            }
            terms.push(partial * &Expr::sym(rate.clone()));
        }
        components.push(add(terms));
    }
    let components: [Expr; 3] = components.try_into().ok()?;
    Some(Vector::new(body, components))
}

/// How many symbols a line of a display holds.
const LINE: usize = crate::render::LINE_SYMBOLS as usize;

/// A long acceleration as Kane writes it, `Σ_r ᴺv_r q̈_r + ᴺã`: the q̈ coefficients are the
/// partial velocities the velocity above is written with (∂a/∂q̈_r = ∂v/∂q̇_r), so only the
/// rest, ã, is new. `None` when no rest is left to write.
fn by_the_rule(model: &Model, acceleration: &Vector, body: BodyId, centre: &str) -> Option<String> {
    let problem = model.problem;
    let accelerations = problem.speed_symbols(2);
    let mut rest = Vec::with_capacity(3);
    for a in acceleration.components_in(body, &model.frames) {
        let (_, without) = linear_split(&a, &accelerations).ok()?;
        rest.push(without);
    }
    let rest = Vector::new(body, rest.try_into().ok()?);
    let speed = if problem.has_speeds() {
        "\\dot{u}_{r}"
    } else {
        "\\ddot{q}_{r}"
    };
    let rest_tex = vector_tex_by(model, &rest, component_term);
    (!rest_tex.is_empty()).then(|| {
        let sign = if rest_tex.starts_with('-') { "" } else { "+ " };
        format!(
            "\\sum_{{r}} {{}}^{{N}}\\mathbf{{v}}^{{{centre}}}_{{r}}\\, {speed} {sign}{rest_tex}"
        )
    })
}

/// The mass centre's velocity or acceleration.
#[derive(Clone, Copy)]
enum Motion {
    Velocity,
    Acceleration,
}

/// `direct`, or, when shorter, the same vector as the parent's mass centre's plus the
/// difference, each part in its own unit vectors: down a chain, `v^{k*} = v^{(k-1)*} + …` is
/// a few terms where the vector written out grows with k.
fn from_parent(model: &Model, body: BodyId, motion: Motion, direct: String) -> String {
    let Some(parent) = model
        .frames
        .info(body)
        .parent
        .filter(|p| *p != BodyId::GROUND)
    else {
        return direct;
    };
    let of = |b: BodyId| {
        let center = &model.bodies[b.0].center;
        match motion {
            Motion::Velocity => &center.velocity,
            Motion::Acceleration => &center.acceleration,
        }
    };
    let difference = of(body).minus(of(parent));
    let (letter, parent_name) = (
        match motion {
            Motion::Velocity => "v",
            Motion::Acceleration => "a",
        },
        super::tex::centre_tex(model, parent),
    );
    let text = plus_difference(
        model,
        format!("{{}}^{{N}}\\mathbf{{{letter}}}^{{{parent_name}}}"),
        &difference,
    );
    if text.len() < direct.len() {
        text
    } else {
        direct
    }
}

/// `reference + difference`, the difference written component by component in its own unit
/// vectors with a common factor out, `(L/2)(q̇1 + … + q̇6) x̂6`, as a textbook writes it.
fn plus_difference(model: &Model, reference: String, difference: &Vector) -> String {
    let mut text = reference;
    if difference.is_zero() {
        return text;
    }
    let rest = vector_tex_by(model, difference, |c, unit| {
        let (common, inner) = pull_common_factor(c);
        if c.terms().len() > 1 && !common.is_one() {
            factored(&common, &inner, unit)
        } else {
            component_term(c, unit)
        }
    });
    match rest.strip_prefix('-') {
        Some(negative) => text.push_str(&format!(" - {negative}")),
        None => text.push_str(&format!(" + {rest}")),
    }
    text
}

/// The mass centre's velocity of `body` as step 4 chains it from a pin at its parent's
/// mass centre (a bob's), `{}^{N}\mathbf{v}^{A^*} + L_2 \dot{q}_2 \hat{…}_x`, with the
/// parent's name; `None` for a body held otherwise.
pub(super) fn velocity_from_parent_centre(model: &Model, body: BodyId) -> Option<(BodyId, String)> {
    let site = pin_of(model, body)?;
    if !at_parent_centre(model, site) {
        return None;
    }
    let relative =
        model.bodies[body.0]
            .center
            .velocity
            .minus(&pin_motion(model, site, Motion::Velocity));
    let text = plus_difference(model, pin_symbol(model, site, Motion::Velocity), &relative);
    Some((model.sites[site].parent, text))
}

/// The joint that holds `body` to a moving parent at a moving point fixed in both (a pin: a
/// revolute, universal, spherical joint or a weld), as an index of `Model::sites`. Step 4
/// goes through it as a textbook does: the pin's velocity first, then the mass centre's
/// from the pin, `v^{B*} = v^P + ω^B × r^{PB*}`.
fn pin_of(model: &Model, body: BodyId) -> Option<usize> {
    use crate::mechanics::SiteKind;
    use crate::problem::JointKind;
    let parent = model.frames.info(body).parent?;
    if parent == BodyId::GROUND {
        return None;
    }
    let site = model.sites.iter().position(|site| {
        site.child == body
            && matches!(site.kind, SiteKind::Joint(j) if matches!(
                model.problem.joints[j].kind,
                JointKind::Revolute | JointKind::Universal | JointKind::Spherical | JointKind::Weld
            ))
    })?;
    // A pin that does not move (on a parent that only turns about it) is a fixed point:
    // the mass centre's motion is written directly, as for a body pinned to the ground.
    let still = pin_motion(model, site, Motion::Velocity)
        .expressed_in(BodyId::GROUND, &model.frames)
        .map(simplify)
        .is_zero();
    (!still).then_some(site)
}

/// The motion of the pin `site` as a point of its parent.
fn pin_motion(model: &Model, site: usize, motion: Motion) -> Vector {
    let site = &model.sites[site];
    let point = model.point_on(site.parent, &site.parent_offset);
    match motion {
        Motion::Velocity => point.velocity,
        Motion::Acceleration => point.acceleration,
    }
}

/// `{}^{N}\mathbf{v}^{P}` (or `a`) for the pin `site`; the parent's mass centre's,
/// `\mathbf{v}^{A^*}`, for a pin there.
fn pin_symbol(model: &Model, site: usize, motion: Motion) -> String {
    let letter = match motion {
        Motion::Velocity => "v",
        Motion::Acceleration => "a",
    };
    let point = if at_parent_centre(model, site) {
        let parent = model.sites[site].parent;
        super::tex::centre_tex(model, parent)
    } else {
        latex_name(&model.sites[site].name)
    };
    format!("{{}}^{{N}}\\mathbf{{{letter}}}^{{{point}}}")
}

/// Whether the pin `site` is at its parent's mass centre.
fn at_parent_centre(model: &Model, site: usize) -> bool {
    let site = &model.sites[site];
    let centre = &model.bodies[site.parent.0].center_offset;
    (0..3).all(|k| {
        crate::symbolic::eval(&(&site.parent_offset[k] - &centre[k]), &model.values).abs() < 1e-12
    })
}

/// The pin's velocity or acceleration: from the parent's own pin down a chain
/// (`v^{P2} = v^{P1} + ω^A × r^{P1P2}`, written out), else as it is, whichever is shorter.
fn pin_line(model: &Model, site: usize, motion: Motion) -> String {
    let parent = model.sites[site].parent;
    let own = pin_motion(model, site, motion);
    let direct = shortest_tex(model, &own, parent);
    let text = match pin_of(model, parent) {
        Some(previous) => {
            let chained = plus_difference(
                model,
                pin_symbol(model, previous, motion),
                &own.minus(&pin_motion(model, previous, motion)),
            );
            if chained.len() < direct.len() {
                chained
            } else {
                direct
            }
        }
        None => direct,
    };
    format!("{} = {text}", pin_symbol(model, site, motion))
}

/// The mass centre's velocity or acceleration from its pin, `v^{B*} = v^P + …`, the rest
/// written out; `direct` when that is shorter by more than half (a spatial body whose
/// named form is far shorter).
fn from_pin(model: &Model, body: BodyId, site: usize, motion: Motion, direct: String) -> String {
    let center = &model.bodies[body.0].center;
    let own = match motion {
        Motion::Velocity => &center.velocity,
        Motion::Acceleration => &center.acceleration,
    };
    let text = plus_difference(
        model,
        pin_symbol(model, site, motion),
        &own.minus(&pin_motion(model, site, motion)),
    );
    if model.is_planar() || text.len() <= 2 * direct.len() {
        text
    } else {
        direct
    }
}
