//! The rows of Kane's table of constrained partial velocities (step 5): each body's
//! partial velocity and partial angular velocity for one independent or auxiliary speed,
//! and each site's point relative to its parent, both combined by the speed's weights.
//! Shared by the independent speeds' table (`independent.rs`) and the auxiliary speeds'
//! (`auxiliary_partials.rs`).

use crate::equations::Derivation;
use crate::mechanics::{is_particle, Model, Vector};
use crate::problem::BodyId;
use crate::render::context::PartialVelocity;
use crate::render::text::Math;
use crate::symbolic::{
    add, latex_name, linear_split, roots_of_squares, simplify, ComponentKind, Expr, Symbol,
};

/// A body with its velocity's and angular velocity's partials, one per coordinate's rate.
pub(super) type BodyPartials = (BodyId, Vec<Vector>, Vec<Vector>);

/// A subtree slid along, or turned about, `direction` by a unit: the rigid motion of a
/// tree joint's auxiliary speed (`auxiliary_partials.rs`).
pub struct Rigid {
    /// The joint's name.
    pub(super) site: String,
    /// The bodies of the subtree.
    pub(super) bodies: Vec<BodyId>,
    /// The unit it slides along, or turns about.
    pub(super) direction: Vector,
    /// Whether it turns (about `direction` through `pivot`) rather than slides.
    pub(super) turning: bool,
    /// The point it turns about.
    pub(super) pivot: Vector,
}

impl Rigid {
    /// The velocity it gives the point of `body` at `position`.
    pub fn velocity_at(&self, model: &Model, body: BodyId, position: &Vector) -> Vector {
        if !self.bodies.contains(&body) {
            Vector::zero()
        } else if self.turning {
            (self.direction).cross(&position.minus(&self.pivot), &model.frames)
        } else {
            self.direction.clone()
        }
    }

    /// The velocity it gives `body`'s mass centre.
    pub fn centre(&self, model: &Model, body: BodyId) -> Vector {
        self.velocity_at(model, body, &model.bodies[body.0].center.position)
    }

    /// The angular velocity it gives `body`.
    pub fn omega(&self, body: BodyId) -> Vector {
        match self.turning && self.bodies.contains(&body) {
            true => self.direction.clone(),
            false => Vector::zero(),
        }
    }
}

/// Each body's partial velocity and partial angular velocity (index into `per_body`'s
/// lists by coordinate) combined by `weights`, for speed `r` (0-based), one line per body
/// that moves with it, `speed` on the first; a tree joint's auxiliary speed adds the
/// `rigid` motion of its subtree.
pub(super) fn body_rows(
    derivation: &Derivation,
    per_body: &[BodyPartials],
    weights: &[Expr],
    r: usize,
    (speed, rigid): (String, Option<&Rigid>),
) -> Vec<PartialVelocity> {
    let model = &derivation.model;
    // A contact's geometry leaves √(cos²θ): the sign at the start writes it as cos θ.
    let sign = super::tex::initial_sign(model);
    // Finished with the position constraints where they combine its terms.
    let on_loop = super::kane_loop::OnTheLoop::of(derivation);
    let finished = |e: Expr| match &on_loop {
        Some(on_loop) => on_loop.reduce(&e),
        None => e,
    };
    let combined = |list: &[Vector], own: Vector| -> Vector {
        Vector::sum(
            list.iter()
                .zip(weights)
                .filter(|(_, w)| !w.is_zero())
                .map(|(v, w)| v.scaled(w)),
        )
        .plus(&own)
        .map(|e| finished(roots_of_squares(&simplify(e), &sign)))
    };
    let mut out = Vec::new();
    let mut first = true;
    for (body, v, w) in per_body {
        // A tree joint's auxiliary speed slides (or turns) its subtree as well.
        let (own_v, own_w) = match rigid {
            Some(rigid) => (rigid.centre(model, *body), rigid.omega(*body)),
            None => (Vector::zero(), Vector::zero()),
        };
        let v_tex = super::tex::shortest_tex(model, &combined(v, own_v), *body);
        let w_tex = super::tex::shortest_tex(model, &combined(w, own_w), *body);
        let line = Line {
            body: *body,
            r: r + 1,
            subscript: (r + 1).to_string(),
            constrained: true,
        };
        out.extend(body_line(
            model,
            &line,
            (&v_tex, &w_tex),
            &speed,
            &mut first,
        ));
    }
    out
}

/// Which line of a table of partial velocities: the body, the speed's number and the
/// partials' subscript, and whether the partials are the constrained ones (with a tilde).
pub(super) struct Line {
    /// The body whose mass centre's partial velocity and partial angular velocity it gives.
    pub body: crate::problem::BodyId,
    /// The speed's number, from 1.
    pub r: usize,
    /// The partials' subscript: the speed's number, or the rate itself.
    pub subscript: String,
    /// Constrained partials, `\tilde{\mathbf{v}}`.
    pub constrained: bool,
}

/// The line of `line.body` for speed number `subscript`, its partial velocity `v_tex` and
/// partial angular velocity `w_tex` (in `N`), with `speed` on the speed's first line
/// (`first`, then cleared); `None` where it would show nothing but zero. A body without
/// rotational inertia shows its partial angular velocity only where it is zero (a cart
/// that slides): a turning one's does nothing.
pub(super) fn body_line(
    model: &Model,
    line: &Line,
    (v_tex, w_tex): (&str, &str),
    speed: &str,
    first: &mut bool,
) -> Option<PartialVelocity> {
    let zero = "\\mathbf{0}";
    let body = line.body;
    let particle = is_particle(model, body) && w_tex != zero;
    if v_tex == zero && (particle || w_tex == zero) {
        return None;
    }
    let name = model.problem.body_name(body);
    let accent = |symbol: &str| match line.constrained {
        true => format!("\\tilde{{{symbol}}}"),
        false => symbol.to_string(),
    };
    let index = &line.subscript;
    Some(PartialVelocity {
        r: line.r,
        speed_tex: Math::from(match std::mem::take(first) {
            true => speed.to_string(),
            false => String::new(),
        }),
        body: name.to_string(),
        velocity_tex: Math::from(format!(
            "{{}}^{{N}}{}^{{{}}}_{{{index}}} = {v_tex}",
            accent("\\mathbf{v}"),
            super::tex::centre_tex(model, body),
        )),
        omega_tex: Math::from(match particle {
            true => String::new(),
            false => format!(
                "{{}}^{{N}}{}^{{{}}}_{{{index}}} = {w_tex}",
                accent("\\boldsymbol{\\omega}"),
                latex_name(name)
            ),
        }),
        point: false,
    })
}

/// The constrained partial velocities of each rough contact point along its tangents (the
/// slip's): what the friction force there is dotted with in `F̃_r`, so that a student can
/// check its term (the bowling ball's ṽ^{lane}_2 = R n̂_x gives R F_x).
pub(super) fn slip_partials(
    model: &Model,
    rates: &[Symbol],
    weights: &[Expr],
    r: usize,
) -> Vec<PartialVelocity> {
    let friction = model.constraints.friction.iter();
    friction
        .filter_map(|f| site_partial(model, f.site, f.stick.iter(), rates, weights, r))
        .collect()
}

/// The partial velocity of site `index`'s point of its child, relative to its parent, for
/// speed `r` (0-based) of `weights`: each of `rows` (velocity conditions along the site's
/// reaction directions) gives its direction's component; `None` where it is zero.
pub(super) fn site_partial<'r>(
    model: &Model,
    index: usize,
    rows: impl Iterator<Item = &'r crate::mechanics::ConstraintRow>,
    rates: &[Symbol],
    weights: &[Expr],
    r: usize,
) -> Option<PartialVelocity> {
    let problem = model.problem;
    let site = &model.sites[index];
    let states = crate::mechanics::sample_states(model);
    let mut v = Vector::zero();
    for row in rows {
        let Ok((a, _)) = linear_split(&row.velocity, rates) else {
            continue;
        };
        let along = site
            .reactions
            .iter()
            .find(|c| c.unknown(&site.name) == row.unknown);
        // A moment's condition is on the turning, not on the point's velocity: it is the
        // body's partial angular velocity, in its own column.
        let Some(component) = along.filter(|c| c.kind != ComponentKind::Moment) else {
            continue;
        };
        let weight = simplify(&add(a.iter().zip(weights).map(|(a, w)| a * w)));
        // An auxiliary speed's motion gives way by a unit along its own direction and not
        // along the others: the weight is 1 or 0 identically, however it is written (the
        // four-bar's (cos/Δ)(a sin(q₁ − q₃) + d sin q₃) with Δ that very bracket).
        let weight = [Expr::zero(), Expr::one()]
            .into_iter()
            .find(|unit| crate::mechanics::same_at(&weight, unit, &states))
            .unwrap_or(weight);
        v = v.plus(&component.direction.scaled(&weight));
    }
    // In the unit vectors of the child or of the parent, it moves relative to: the
    // four-bar's pin R gives way along b̂_x of the coupler B.
    let v = v.map(simplify);
    let v_tex = [site.child, site.parent]
        .into_iter()
        .filter(|&b| b != crate::problem::BodyId::GROUND)
        .map(|b| super::tex::shortest_tex(model, &v, b))
        .min_by_key(|t| (t.len(), t.clone()))
        .unwrap_or_else(|| super::tex::shortest_tex(model, &v, site.child));
    // A velocity relative to a moving body in that body's own unit vectors where they write
    // it as short: the cart's ĉ_x, not the n̂_x it equals.
    let v_tex = match site.parent {
        crate::problem::BodyId::GROUND => v_tex,
        parent => {
            let own =
                super::tex::vector_tex(model, &v.expressed_in(parent, &model.frames).map(simplify));
            if own.len() <= v_tex.len() {
                own
            } else {
                v_tex
            }
        }
    };
    if v_tex == "\\mathbf{0}" {
        return None;
    }
    // Relative to what it slides on: N's, or a moving body's.
    let frame = if site.parent == crate::problem::BodyId::GROUND {
        "N".to_string()
    } else {
        latex_name(problem.body_name(site.parent))
    };
    Some(PartialVelocity {
        r: r + 1,
        speed_tex: Math::from(String::new()),
        // The point is in the partial velocity's name: the body alone keeps the column narrow.
        body: problem.body_name(site.child).to_string(),
        velocity_tex: Math::from(format!(
            "{{}}^{{{frame}}}\\tilde{{\\mathbf{{v}}}}^{{{}}}_{{{}}} = {v_tex}",
            latex_name(&site.name),
            r + 1
        )),
        omega_tex: Math::from(String::new()),
        point: true,
    })
}
