//! The rows of Kane's table of constrained partial velocities (step 5): each body's
//! partial velocity and partial angular velocity for one independent or auxiliary speed,
//! and each site's point relative to its parent, both combined by the speed's weights.
//! Shared by the independent speeds' table (`independent.rs`) and the auxiliary speeds'
//! (`auxiliary_partials.rs`).

use crate::equations::Derivation;
use crate::mechanics::{is_particle, Model, Vector};
use crate::render::context::PartialVelocity;
use crate::render::text::Math;
use crate::symbolic::{add, latex_name, linear_split, roots_of_squares, simplify, Expr, Symbol};

/// A body with its velocity's and angular velocity's partials, one per coordinate's rate.
pub(super) type BodyPartials = (crate::problem::BodyId, Vec<Vector>, Vec<Vector>);

/// Each body's partial velocity and partial angular velocity (index into `per_body`'s
/// lists by coordinate) combined by `weights`, for speed `r` (0-based), one line per body
/// that moves with it, `speed` on the first.
pub(super) fn body_rows(
    derivation: &Derivation,
    per_body: &[BodyPartials],
    weights: &[Expr],
    r: usize,
    speed: String,
) -> Vec<PartialVelocity> {
    let model = &derivation.model;
    let problem = model.problem;
    // A contact's geometry leaves √(cos²θ): the sign at the start writes it as cos θ.
    let sign = super::tex::initial_sign(model);
    let combined = |list: &[Vector]| -> Vector {
        Vector::sum(
            list.iter()
                .zip(weights)
                .filter(|(_, w)| !w.is_zero())
                .map(|(v, w)| v.scaled(w)),
        )
        .map(|e| roots_of_squares(&simplify(e), &sign))
    };
    let zero = "\\mathbf{0}";
    let mut out = Vec::new();
    let mut first = true;
    for (body, v, w) in per_body {
        let v_tex = super::tex::shortest_tex(model, &combined(v), *body);
        // A body without rotational inertia shows its partial angular velocity only
        // where it is zero (a cart that slides): a turning one's does nothing.
        let w_tex = super::tex::shortest_tex(model, &combined(w), *body);
        let particle = is_particle(model, *body) && w_tex != zero;
        if v_tex == zero && (particle || w_tex == zero) {
            continue;
        }
        let symbol = latex_name(problem.body_name(*body));
        out.push(PartialVelocity {
            r: r + 1,
            speed_tex: if std::mem::take(&mut first) {
                Math::from(speed.clone())
            } else {
                Math::from(String::new())
            },
            body: problem.body_name(*body).to_string(),
            velocity_tex: Math::from(format!(
                "{{}}^{{N}}\\tilde{{\\mathbf{{v}}}}^{{{}}}_{{{}}} = {v_tex}",
                super::tex::centre_tex(model, *body),
                r + 1
            )),
            omega_tex: if particle {
                Math::from(String::new())
            } else {
                Math::from(format!(
                    "{{}}^{{N}}\\tilde{{\\boldsymbol{{\\omega}}}}^{{{symbol}}}_{{{}}} = {w_tex}",
                    r + 1
                ))
            },
            point: false,
        });
    }
    out
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
    let mut v = Vector::zero();
    for row in rows {
        let Ok((a, _)) = linear_split(&row.velocity, rates) else {
            continue;
        };
        let along = site
            .reactions
            .iter()
            .find(|c| c.unknown(&site.name) == row.unknown);
        let Some(component) = along else {
            continue;
        };
        let weight = simplify(&add(a.iter().zip(weights).map(|(a, w)| a * w)));
        v = v.plus(&component.direction.scaled(&weight));
    }
    let v_tex = super::tex::shortest_tex(model, &v.map(simplify), site.child);
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
