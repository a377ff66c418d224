//! Light rods as two-force members: a massless body pinned at two points, with no load on
//! it, carries its pins' forces along the line between them (its force and moment balances
//! about either pin leave nothing across it). Where one of the pins closes a loop (the light
//! connecting rod of a slider-crank), that closure's reaction is written as one unknown,
//! the rod's tension `T^Q`, in place of its components, as a textbook writes it; the loop's
//! row along the rod is enforced by the tension, the row across it by nothing (no force
//! acts across a light rod).

use super::joints::ReactionComponent;
use super::site::SiteKind;
use super::vector::Vector;
use super::Model;
use crate::problem::BodyId;
use crate::symbolic::{eval, Axis, ComponentKind, Expr};

/// Gives each closure at the end of a light rod one force unknown along the rod (its
/// tension, positive pulling the closure's other body toward the rod's pin); returns the
/// closures' names.
pub fn closures_along_rods(model: &mut Model) -> Vec<String> {
    let mut changed = Vec::new();
    for s in 0..model.sites.len() {
        let Some(direction) = rod_direction(model, s) else {
            continue;
        };
        let site = &model.sites[s];
        let member = ReactionComponent {
            kind: ComponentKind::Force,
            axis: Axis::Member,
            direction,
        };
        let tension = member.unknown(&site.name);
        // The loop's row along the rod: written along the tension's direction, enforced by it.
        let along: Vec<(usize, f64)> = (site.reactions.iter().enumerate())
            .map(|(k, c)| {
                (
                    k,
                    eval(
                        &c.direction.dot(&member.direction, &model.frames),
                        &model.values,
                    ),
                )
            })
            .filter(|(_, cosine)| (cosine.abs() - 1.0).abs() < 1e-9)
            .collect();
        let [(component, cosine)] = along[..] else {
            continue;
        };
        let name = site.name.clone();
        // The tension is the site's one reaction, index 0; the rows across the rod follow,
        // 1, 2, …, each with the direction no force has.
        let others: Vec<usize> = (0..site.reactions.len())
            .filter(|&k| k != component)
            .collect();
        let across = (others.iter().enumerate())
            .map(|(i, &k)| (i + 1, site.reactions[k].direction.clone()))
            .collect();
        for row in &mut model.constraints.rows {
            let super::constraints::RowOrigin::Site {
                site: at,
                component: k,
            } = &mut row.origin
            else {
                continue;
            };
            if *at != s {
                continue;
            }
            if *k != component {
                *k = 1 + others.iter().position(|o| o == k).unwrap_or(others.len());
                continue;
            }
            *k = 0;
            row.unknown = tension.clone();
            if cosine < 0.0 {
                row.velocity = -row.velocity.clone();
                row.position = row.position.take().map(|p| -p);
                row.loop_acceleration = row.loop_acceleration.take().map(|a| -a);
            }
        }
        model.sites[s].across = across;
        model.sites[s].reactions = vec![member];
        changed.push(name);
    }
    changed
}

/// The unit vector from closure site `s` toward the light rod's other pin, when `s` is a
/// closure whose parent is a light rod (no mass, no inertia, no load) pinned at two points
/// (its own joint and this closure, both carrying forces alone), the pins apart along one
/// of the rod's unit vectors.
fn rod_direction(model: &Model, s: usize) -> Option<Vector> {
    let problem = model.problem;
    let site = &model.sites[s];
    if !matches!(site.kind, SiteKind::Closure(_)) {
        return None;
    }
    let rod: BodyId = site.parent;
    let state = model.bodies.get(rod.0)?;
    let light = state.mass.is_zero() && state.inertia.iter().flatten().all(Expr::is_zero);
    let touching: Vec<usize> = (0..model.sites.len())
        .filter(|&k| model.sites[k].parent == rod || model.sites[k].child == rod)
        .collect();
    let [first, second] = touching[..] else {
        return None;
    };
    let pin = if first == s { second } else { first };
    let joint = match model.sites[pin].kind {
        SiteKind::Joint(j) if model.sites[pin].child == rod => j,
        _ => return None,
    };
    let forces_only =
        |k: usize| (model.sites[k].reactions.iter()).all(|r| r.kind == ComponentKind::Force);
    if !light
        || !forces_only(s)
        || !forces_only(pin)
        || super::two_force::loaded(problem, rod, joint)
    {
        return None;
    }
    let number = |e: &Expr| eval(e, &model.values);
    // From this closure to the pin, in the rod's unit vectors.
    let reach: [f64; 3] = std::array::from_fn(|k| {
        number(&(&model.sites[pin].child_offset[k] - &site.parent_offset[k]))
    });
    super::two_force::unit_along(rod, reach)
}
