//! Kane's auxiliary speeds of the forces that enforce constraints, with independent speeds
//! (Kane and Levinson, ch. 4): the speed `u_r` lets the one constraint its force enforces
//! give way, every other constraint kept, so the dependent rates move by the column of
//! `A_D⁻¹` of that constraint. Its partial velocities and partial angular velocities are
//! shown in the table with the independent speeds', and its `F̃*_r` is formed body by body
//! with them, as the independent speeds' are.

use super::partial_rows::{body_rows, site_partial, BodyPartials, Rigid};
use crate::equations::Derivation;
use crate::mechanics::{DependentSpeeds, RowOrigin, Vector};
use crate::plan::Sum;
use crate::problem::BodyId;
use crate::render::context::PartialVelocity;
use crate::render::text::Math;
use crate::symbolic::{latex, simplify, ComponentKind, Expr, Symbol};

/// What Kane's row `r` (1-based) of an auxiliary speed moves: the weights on the
/// coordinates' rates of the motion that breaks its constraint by a unit, and the
/// constraint's row (index into the model's constraint rows). `None` for a row of an
/// independent speed, of a drive, of a joint of the tree, or where the dependent rates are
/// evaluated at each state.
pub fn weights(derivation: &Derivation, r: usize) -> Option<(Vec<Expr>, usize)> {
    let speeds = derivation
        .dependent_speeds
        .as_ref()
        .filter(|s| !s.at_each_state)?;
    if r <= speeds.independent.len() {
        return None;
    }
    let model = &derivation.model;
    let row = (derivation.rows.iter())
        .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
        .nth(r - 1)?;
    let k = row.unknowns.iter().find_map(|u| speeds.row_of(model, u))?;
    let n = model.problem.coordinates.len();
    Some((speeds.violation_weights(k, n), speeds.rows[k]))
}

/// The table's lines of every auxiliary speed of a constraint force: each body that moves
/// with it, then the point where the force acts, relative to the body that exerts it.
pub fn table_rows(
    derivation: &Derivation,
    speeds: &DependentSpeeds,
    per_body: &[BodyPartials],
    rates: &[Symbol],
) -> Vec<PartialVelocity> {
    let model = &derivation.model;
    let rows = (derivation.rows.iter())
        .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
        .count();
    let mut out = Vec::new();
    for r in (speeds.independent.len() + 1)..=rows {
        let Some((weights, k)) = weights(derivation, r) else {
            // A tree joint's: its subtree slid along the force, the loop kept closed.
            let Some(motion) = motion(derivation, r) else {
                continue;
            };
            let row = (derivation.rows.iter())
                .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
                .nth(r - 1);
            let forces: Vec<String> = (row.iter().flat_map(|row| row.unknowns.iter()))
                .filter(|u| matches!(u, Symbol::Unknown(_)))
                .map(|u| latex(&Expr::sym(u.clone())))
                .collect();
            let speed = super::tex::auxiliary_speed_tex(r, &forces.join(", "));
            let rigid = motion.rigid.as_ref();
            out.extend(body_rows(
                derivation,
                per_body,
                &motion.weights,
                r - 1,
                (speed, rigid),
            ));
            continue;
        };
        let force = latex(&Expr::sym(model.constraints.rows[k].unknown.clone()));
        let speed = super::tex::auxiliary_speed_tex(r, &force);
        let mut lines = body_rows(derivation, per_body, &weights, r - 1, (speed.clone(), None));
        if let RowOrigin::Site { site, .. } = model.constraints.rows[k].origin {
            let of_site = (model.constraints.rows.iter())
                .filter(|c| matches!(c.origin, RowOrigin::Site { site: s, .. } if s == site));
            let point = site_partial(model, site, of_site, rates, &weights, r - 1);
            if let Some(mut point) = point.filter(|p| !said_by_body(model, site, &lines, p)) {
                if lines.is_empty() {
                    point.speed_tex = Math::from(speed);
                }
                lines.push(point);
            }
        }
        out.extend(lines);
    }
    out
}

/// Whether the body's line already says the contact point's partial velocity: the body
/// moves without turning, as fast as the point, and what it touches does not move (the
/// coin lifted straight up: ṽ^{D*} = n̂_z, so ṽ^P = n̂_z too).
fn said_by_body(
    model: &crate::mechanics::Model,
    site: usize,
    lines: &[PartialVelocity],
    point: &PartialVelocity,
) -> bool {
    let value = |tex: &str| tex.rsplit(" = ").next().unwrap_or_default().to_string();
    let site = &model.sites[site];
    let parent = model.problem.body_name(site.parent);
    let parent_moves = lines.iter().any(|l| l.body == parent);
    let body_says = lines.iter().any(|l| {
        l.body == point.body
            && l.omega_tex.as_str().ends_with("= \\mathbf{0}")
            && value(l.velocity_tex.as_str()) == value(point.velocity_tex.as_str())
    });
    body_says && !parent_moves
}

/// Whether some auxiliary speed of a constraint force has lines in the table.
pub fn any(derivation: &Derivation) -> bool {
    let rows = (derivation.rows.iter())
        .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
        .count();
    (1..=rows).any(|r| motion(derivation, r).is_some())
}

/// The motion of an auxiliary speed: the weights on the coordinates' rates and, for a
/// joint of the tree, the subtree's rigid motion along (or about) the reaction's direction
/// (the four-bar's pin O slid along n̂_x, A and B with it), the dependent rates restoring
/// the constraints it would break.
pub struct Motion {
    /// The weights on the coordinates' rates.
    pub weights: Vec<Expr>,
    /// The subtree's rigid motion, for a joint of the tree.
    pub rigid: Option<Rigid>,
}

/// The motion of Kane's auxiliary row `r` (1-based): a constraint's (see [`weights`]) or
/// a tree joint's; `None` for any other row, or where the constraints are not all at
/// sites whose velocity conditions the restoring rates can be checked against.
pub fn motion(derivation: &Derivation, r: usize) -> Option<Motion> {
    if let Some((weights, _)) = weights(derivation, r) {
        return Some(Motion {
            weights,
            rigid: None,
        });
    }
    let speeds = derivation
        .dependent_speeds
        .as_ref()
        .filter(|s| !s.at_each_state)?;
    if r <= speeds.independent.len() {
        return None;
    }
    let model = &derivation.model;
    let problem = model.problem;
    let row = (derivation.rows.iter())
        .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
        .nth(r - 1)?;
    let (site, component) = super::relaxed::relaxed_reaction(derivation, row)?;
    let j = (problem.joints.iter()).position(|joint| joint.name.as_str() == site)?;
    let rigid = Rigid {
        site: site.to_string(),
        bodies: model.subtree(j),
        direction: component.direction.clone(),
        turning: component.kind == ComponentKind::Moment,
        pivot: model.sites[j].point.position.clone(),
    };
    let n = problem.coordinates.len();
    let rates: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
    // What the rigid motion breaks each kept constraint by, the child's point relative to
    // the parent's along the constraint's direction.
    let mut broken = Vec::new();
    for &k in &speeds.rows {
        let constraint = &model.constraints.rows[k];
        let RowOrigin::Site { site, .. } = constraint.origin else {
            return None;
        };
        let s = &model.sites[site];
        let along = (s.reactions.iter()).find(|c| c.unknown(&s.name) == constraint.unknown)?;
        let on_parent = model.point_on(s.parent, &s.parent_offset);
        let gap = rigid
            .velocity_at(model, s.child, &s.point.position)
            .minus(&rigid.velocity_at(model, s.parent, &on_parent.position));
        broken.push(simplify(&along.direction.dot(&gap, &model.frames)));
    }
    // The rates that restore them, checked against the row as the equations formed it:
    // its generalized inertia force is what this motion's partial velocities give.
    let restored = |sign: &Expr| -> Vec<Expr> {
        let mut weights = vec![Expr::zero(); n];
        for (k, by) in broken.iter().enumerate() {
            if by.is_zero() {
                continue;
            }
            let restoring = speeds.violation_weights(k, n);
            for (w, v) in weights.iter_mut().zip(&restoring) {
                *w = simplify(&(&*w - &(&(by * sign) * v)));
            }
        }
        weights
    };
    let weights = [Expr::one(), Expr::int(-1)]
        .iter()
        .map(restored)
        .find(|weights| forms_the_row(derivation, row, &rigid, weights, &rates))?;
    Some(Motion {
        weights,
        rigid: Some(rigid),
    })
}

/// Whether the motion (`rigid` and `weights` on `rates`) gives `row`'s generalized inertia
/// force, at a sample state with every second derivative given a value.
fn forms_the_row(
    derivation: &Derivation,
    row: &crate::plan::Equation,
    rigid: &Rigid,
    weights: &[Expr],
    rates: &[Symbol],
) -> bool {
    let model = &derivation.model;
    let problem = model.problem;
    let inertia = derivation.inertia();
    let mut terms = Vec::new();
    for &body in &model.order {
        let state = &model.bodies[body.0];
        let combined = |list: Vec<Vector>, own: Vector| {
            Vector::sum(
                list.iter()
                    .zip(weights)
                    .filter(|(_, w)| !w.is_zero())
                    .map(|(v, w)| v.scaled(w)),
            )
            .plus(&own)
        };
        let v = combined(
            crate::equations::partials(&state.center.velocity, rates),
            rigid.centre(model, body),
        );
        let w = combined(
            crate::equations::partials(&state.omega, rates),
            rigid.omega(body),
        );
        terms.push(inertia.force[body.0].dot(&v, &model.frames));
        terms.push(inertia.torque[body.0].dot(&w, &model.frames));
    }
    let mut values = (crate::mechanics::sample_states(model).into_iter())
        .next()
        .unwrap_or_default();
    for i in 0..problem.coordinates.len() {
        values.set(problem.coordinate_symbol(i, 2), 0.37 + 0.61 * i as f64);
    }
    let eval = |e: &Expr| crate::symbolic::eval(e, &values);
    let formed = eval(&row.groups.inertia_force) + eval(&row.groups.inertia_torque);
    let here: f64 = terms.iter().map(eval).sum();
    formed.is_finite() && (formed - here).abs() <= 1e-9 * (1.0 + formed.abs())
}

/// How a body moves with an auxiliary speed, read from its partial velocity and partial
/// angular velocity on the loop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Moves {
    /// Both zero: it adds nothing to the row.
    Still,
    /// It moves without turning.
    Slides,
    /// It turns, its mass centre still.
    Turns,
    /// It moves and turns.
    Both,
}

/// How each body moves with Kane's auxiliary row `r` (1-based), on the loop: a partial
/// velocity zero at the loop's states is zero there, as the table writes it. `None` where
/// the row has no motion of its own (see [`motion`]) or the loop is not known.
pub fn body_motions(derivation: &Derivation, r: usize) -> Option<Vec<(BodyId, Moves)>> {
    let motion = motion(derivation, r)?;
    let on_loop = super::kane_loop::OnTheLoop::of(derivation)?;
    let model = &derivation.model;
    let problem = model.problem;
    let n = problem.coordinates.len();
    let rates: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
    let zero = |v: &Vector, body: BodyId| {
        (v.components_in(body, &model.frames).iter()).all(|c| on_loop.is_zero(c))
    };
    let mut out = Vec::new();
    for &body in &model.order {
        let state = &model.bodies[body.0];
        let combined = |list: Vec<Vector>, own: Vector| {
            Vector::sum(
                list.iter()
                    .zip(&motion.weights)
                    .filter(|(_, w)| !w.is_zero())
                    .map(|(v, w)| v.scaled(w)),
            )
            .plus(&own)
        };
        let (own_v, own_w) = match &motion.rigid {
            Some(rigid) => (rigid.centre(model, body), rigid.omega(body)),
            None => (Vector::zero(), Vector::zero()),
        };
        let v = combined(
            crate::equations::partials(&state.center.velocity, &rates),
            own_v,
        );
        let w = combined(crate::equations::partials(&state.omega, &rates), own_w);
        let moves = match (zero(&v, body), zero(&w, body)) {
            (true, true) => Moves::Still,
            (false, true) => Moves::Slides,
            (true, false) => Moves::Turns,
            (false, false) => Moves::Both,
        };
        out.push((body, moves));
    }
    Some(out)
}

/// Where the auxiliary speeds' partial velocities come from, as a student finds them: with
/// the independent rates held at zero, each auxiliary speed's motion moves the dependent
/// rates by what keeps the other constraints (`q̇₂ = −cos q₃/Δ u₂, …`), and the velocities
/// written with those rates are the speed times its partial velocities. Empty where no
/// auxiliary speed has a motion of its own.
pub fn rates_text(derivation: &Derivation, speeds: &DependentSpeeds) -> String {
    let model = &derivation.model;
    let problem = model.problem;
    let on_loop = super::kane_loop::OnTheLoop::of(derivation);
    let finished = |e: &Expr| {
        let e = simplify(e);
        on_loop
            .as_ref()
            .map_or(e.clone(), |l| simplify(&l.reduce(&e)))
    };
    let rows = (derivation.rows.iter())
        .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
        .count();
    let mut each = Vec::new();
    let mut pins: Vec<String> = Vec::new();
    for r in (speeds.independent.len() + 1)..=rows {
        let Some(motion) = motion(derivation, r) else {
            continue;
        };
        if let Some(rigid) = &motion.rigid {
            let pin = format!("${}$", crate::symbolic::latex_name(&rigid.site));
            if !pins.contains(&pin) {
                pins.push(pin);
            }
        }
        let speed = format!("u_{{{r}}}");
        let rates: Vec<String> = (speeds.dependent.iter())
            .filter_map(|&d| {
                let w = finished(&motion.weights[d]);
                let rate = latex(&problem.coordinate_expr(d, 1));
                (!w.is_zero())
                    .then(|| format!("{rate} = {}", super::tex::component_term(&w, &speed)))
            })
            .collect();
        if !rates.is_empty() {
            each.push(format!("${speed}$: ${}$", rates.join(",\\; ")));
        }
    }
    // No dependent rate moves with any auxiliary speed: the table says the rest.
    if each.is_empty() {
        return String::new();
    }
    let held: Vec<String> = (speeds.independent.iter())
        .map(|&i| format!("{} = 0", latex(&problem.coordinate_expr(i, 1))))
        .collect();
    let slide = match pins.as_slice() {
        [] => String::new(),
        [pin] => format!(" (at {pin}, a joint of the chain, the bodies beyond it move with the speed as well)"),
        [rest @ .., last] => format!(" (at {} and {last}, joints of the chain, the bodies beyond each move with the speed as well)", rest.join(", ")),
    };
    format!(
        "With the independent rates held, ${}$, each auxiliary speed's relaxed constraint gives way by that speed{slide} and the other constraints stay satisfied, which fixes the dependent rates (those not listed stay zero): {}. Each velocity of step 4 written with these rates is the speed times the partial velocity, read off as its coefficient",
        held.join(",\\; "),
        each.join("; ")
    )
}
