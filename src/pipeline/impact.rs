//! The impact at the initial state: the rates just after it, by the chosen method's own
//! equations of the impulsive problem ([`Problem::impulsive`]), and the collision's
//! impulse by restitution and Coulomb's law at the impact ([`crate::numeric::impact`]).
//!
//! The jumps are linear in the impulses: the equations are solved once with the applied
//! impulses alone and once more per component of the collision's impulse, and the
//! collision law is solved on the struck point's velocity changes.

use super::{derive, Purpose};
use crate::equations::Method;
use crate::error::Error;
use crate::mechanics::{own_components, Model};
use crate::numeric::{CollisionImpulse, Compiled, Contact, Motion, System};
use crate::problem::{BodyId, Collision, ForcePoint, Problem, ProblemError, ProblemErrors};
use crate::symbolic::{eval, Values};

/// What the impact does.
#[derive(Clone, Debug, PartialEq)]
pub struct ImpactSolution {
    /// The method whose equations gave the jumps.
    pub method: Method,
    /// The coordinates at the impact (assembled).
    pub q: Vec<f64>,
    /// The rates just before (the initial ones, assembled).
    pub before: Vec<f64>,
    /// The rates just after.
    pub after: Vec<f64>,
    /// The collision's name and impulse, if there is a collision.
    pub collision: Option<(String, CollisionImpulse)>,
    /// The impulsive reactions of `find.reactions`: name, force and moment impulses in the
    /// parent's unit vectors (a contact's in its `on` body's), as `solve` gives reactions.
    pub reactions: Vec<(String, [f64; 3], [f64; 3])>,
    /// Each prescribed coordinate: the impulse of its drive.
    pub drives: Vec<(String, f64)>,
    /// The kinetic energy just before and just after.
    pub energy: [f64; 2],
}

/// The impact at the initial state, assembled by `solver`, by `solver`'s method;
/// `model` is the problem's kinematics.
///
/// # Errors
/// As for [`impact`], and an initial state that cannot be assembled.
pub fn impact_at_start(
    problem: &Problem,
    model: &Model,
    solver: &super::Solver,
) -> Result<ImpactSolution, Error> {
    let mut state = problem.initial_state();
    solver.assemble(state.t, &mut state.q, &mut state.rates)?;
    impact(
        problem,
        model,
        solver.method(),
        &state.q,
        &state.rates,
        solver,
    )
}

/// The struck point's velocity relative to the surface body `on`, in `on`'s unit vectors,
/// as expressions of the state.
fn relative_velocity(model: &Model, collision: &Collision) -> [crate::symbolic::Expr; 3] {
    let (body, offset) = match &collision.point {
        ForcePoint::Point(p) => model.locate(*p),
        ForcePoint::Offset(v) => (collision.body, own_components(v, collision.body)),
    };
    let point = model.point_on(body, &offset);
    let on = &model.bodies[collision.on.0];
    let arm = point.position.minus(&on.origin.position);
    let carried = on
        .origin
        .velocity
        .plus(&on.omega.cross(&arm, &model.frames));
    point
        .velocity
        .minus(&carried)
        .components_in(collision.on, &model.frames)
}

/// Where the struck point is on `on`, from its origin in its unit vectors, as numbers.
fn point_on_surface(model: &Model, collision: &Collision, values: &Values) -> Vec<f64> {
    let (body, offset) = match &collision.point {
        ForcePoint::Point(p) => model.locate(*p),
        ForcePoint::Offset(v) => (collision.body, own_components(v, collision.body)),
    };
    let arm = model
        .position_on(body, &offset)
        .minus(&model.bodies[collision.on.0].origin.position);
    arm.components_in(collision.on, &model.frames)
        .iter()
        .map(|e| eval(e, values))
        .collect()
}

fn numbers(e: &[crate::symbolic::Expr; 3], values: &Values) -> [f64; 3] {
    std::array::from_fn(|k| eval(&e[k], values))
}

fn refused(path: &str, message: String, hint: &str) -> Error {
    Error::Problem(ProblemErrors(vec![ProblemError {
        path: path.to_string(),
        column: None,
        message,
        hint: Some(hint.to_string()),
    }]))
}

/// The solution of the impulsive equations with the collision's components `p`.
fn jumps(compiled: &Compiled, q: &[f64]) -> Result<Motion, Error> {
    let zero = vec![0.0; q.len()];
    Ok(compiled.motion(0.0, q, &zero)?)
}

/// `base + Σ s_k (x_k − base)` over every number of a solution.
fn combine(base: &Motion, parts: &[(f64, Motion)]) -> Motion {
    let mut out = base.clone();
    for (s, part) in parts {
        for (o, (x, b)) in out
            .accelerations
            .iter_mut()
            .zip(part.accelerations.iter().zip(&base.accelerations))
        {
            *o += s * (x - b);
        }
        for (o, (x, b)) in out
            .reactions
            .iter_mut()
            .zip(part.reactions.iter().zip(&base.reactions))
        {
            let add = |out: &mut [f64; 3], x: &[f64; 3], b: &[f64; 3]| {
                for (o, (x, b)) in out.iter_mut().zip(x.iter().zip(b)) {
                    *o += s * (x - b);
                }
            };
            add(&mut o.1, &x.1, &b.1);
            add(&mut o.2, &x.2, &b.2);
        }
        for (o, (x, b)) in out
            .drives
            .iter_mut()
            .zip(part.drives.iter().zip(&base.drives))
        {
            o.1 += s * (x.1 - b.1);
        }
    }
    out
}

/// The impact of `problem` by `method` at coordinates `q` with rates `before` (both
/// assembled), `model` the problem's kinematics and `original` its equations (for the
/// energies).
///
/// # Errors
/// No `impact`; a collision whose point is not approaching the surface (at
/// `impact.collision`); equations that cannot be derived or solved.
pub fn impact(
    problem: &Problem,
    model: &Model,
    method: Method,
    q: &[f64],
    before: &[f64],
    original: &dyn System,
) -> Result<ImpactSolution, Error> {
    let Some(impact) = &problem.impact else {
        return Err(refused(
            "impact",
            "the problem has no `impact`".into(),
            "add \"impact\": { \"impulses\": [...] } or a \"collision\"",
        ));
    };
    let values = model.values_at(0.0, q, before);
    let collision = impact.collision.as_ref();
    let velocity = collision.map(|c| relative_velocity(model, c));
    let on_point = collision
        .filter(|c| c.on != BodyId::GROUND)
        .map(|c| point_on_surface(model, c, &values));
    let on_vector = on_point
        .as_ref()
        .zip(collision)
        .map(|(p, c)| crate::problem::VectorExpr {
            terms: p
                .iter()
                .enumerate()
                .map(|(k, x)| (c.on, k as u8, crate::symbolic::Expr::real(*x)))
                .collect(),
        });
    let Some(impulsive) = problem.impulsive(q, on_vector) else {
        return Err(refused("impact", "the problem has no `impact`".into(), ""));
    };
    let derivation = derive(&impulsive.problem, method, Purpose::Own)?;
    let mut compiled = Compiled::new(&derivation);
    let base = jumps(&compiled, q)?;
    let mut motion = base.clone();
    let mut found = None;
    if let (Some(c), Some(velocity)) = (collision, &velocity) {
        let mut parts = Vec::new();
        for &index in &impulsive.collision {
            compiled.set_constant(index, 1.0);
            parts.push(jumps(&compiled, q)?);
            compiled.set_constant(index, 0.0);
        }
        let p = collide(
            problem, c, velocity, &values, model, q, before, &base, &parts,
        )?;
        let scaled: Vec<(f64, Motion)> = parts
            .into_iter()
            .zip(p.components)
            .map(|(m, s)| (s, m))
            .collect();
        motion = combine(&base, &scaled);
        found = Some((c.name.clone(), p));
    }
    let after: Vec<f64> = before
        .iter()
        .zip(&motion.accelerations)
        .map(|(v, d)| v + d)
        .collect();
    let energy = [
        original.energies(0.0, q, before)?.0,
        original.energies(0.0, q, &after)?.0,
    ];
    Ok(ImpactSolution {
        method,
        q: q.to_vec(),
        before: before.to_vec(),
        after,
        collision: found,
        reactions: motion.reactions,
        drives: motion.drives,
        energy,
    })
}

/// The collision's impulse: its contact refused unless approaching, then the law.
#[allow(clippy::too_many_arguments)]
fn collide(
    problem: &Problem,
    c: &Collision,
    velocity: &[crate::symbolic::Expr; 3],
    values: &Values,
    model: &Model,
    q: &[f64],
    before: &[f64],
    base: &Motion,
    parts: &[Motion],
) -> Result<CollisionImpulse, Error> {
    let value = |e: &crate::symbolic::Expr| eval(e, values);
    let normal_raw: [f64; 3] = {
        let n = crate::mechanics::vector_of(&c.normal).components_in(c.on, &model.frames);
        numbers(&n, values)
    };
    let size = normal_raw.iter().map(|x| x * x).sum::<f64>().sqrt();
    let normal = normal_raw.map(|x| x / size);
    let restitution = value(&c.restitution);
    if !(0.0..=1.0).contains(&restitution) {
        // Read in range; a `--set` may have moved it.
        return Err(refused(
            &format!("{}.restitution", c.path),
            format!(
                "the coefficient of restitution must lie in [0, 1]; it is {}",
                crate::symbolic::fixed(restitution)
            ),
            "give 0 for a plastic impact (the point stays on the surface), 1 for an elastic one",
        ));
    }
    let v_before = numbers(velocity, values);
    let approach: f64 = (0..3).map(|k| normal[k] * v_before[k]).sum();
    let scale = v_before.iter().map(|x| x.abs()).fold(0.0, f64::max);
    if approach.is_nan() || approach >= -1e-12 * scale {
        return Err(refused(
            &c.path,
            format!(
                "the point of `{}` is not approaching the surface: its normal velocity before the impact is {} (it must be negative)",
                problem.body_name(c.body),
                crate::symbolic::fixed(approach)
            ),
            "give initial rates that carry the point into the surface, or check the normal's direction (it points out of the surface, towards the body)",
        ));
    }
    let change = |m: &Motion| -> [f64; 3] {
        let rates: Vec<f64> = before
            .iter()
            .zip(m.accelerations.iter())
            .map(|(v, d)| v + d)
            .collect();
        let after = numbers(velocity, &model.values_at(0.0, q, &rates));
        std::array::from_fn(|k| after[k] - v_before[k])
    };
    let applied = change(base);
    let response = parts
        .iter()
        .map(|m| {
            let total = change(m);
            std::array::from_fn(|k| total[k] - applied[k])
        })
        .collect();
    let contact = Contact {
        normal,
        before: v_before,
        applied,
        response,
        restitution,
        friction: c.friction.as_ref().map(value),
    };
    contact.solve().ok_or_else(|| {
        refused(
            &c.path,
            format!(
                "nothing with mass moves the point of `{}` along the normal: the collision has no impulse",
                problem.body_name(c.body)
            ),
            "check the point and the normal: the joints may already hold the point there",
        )
    })
}
