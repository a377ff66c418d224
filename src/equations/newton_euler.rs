//! Newton–Euler: every body is a free body, with F along each axis in play and M about its
//! mass center. The unknowns are every q'' and every reaction component.

use super::unknowns::{Inputs, MethodRows, Setup};
use crate::mechanics::Model;
use crate::plan::{resultant, unit_direction, unknowns_in, Action, Equation, Inertia, Sum};
use crate::problem::BodyId;
use crate::symbolic::Symbol;

/// The rows of Newton–Euler: 3 per body in 2D, 6 in 3D.
pub fn equations(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    unknowns: &[Symbol],
) -> Vec<Equation> {
    let planar = model.is_planar();
    let mut rows = Vec::new();
    for &body in &model.order {
        let free_body = vec![body];
        let force_axes: &[usize] = if planar { &[0, 1] } else { &[0, 1, 2] };
        // Forces along N or along the body's own axes, whichever writes shorter.
        // (A body spinning about its symmetry axis: the axes that do not spin.)
        let own = model.bodies[body.0].frame;
        let candidates = [BodyId::GROUND, own].map(|frame| {
            force_axes
                .iter()
                .map(|&axis| {
                    let direction = unit_direction(model, frame, axis);
                    let groups =
                        resultant(model, actions, inertia, &free_body, None, &direction.vector);
                    (direction, groups)
                })
                .collect::<Vec<_>>()
        });
        let length = |rows: &Vec<(crate::plan::Direction, crate::plan::Groups)>| -> usize {
            rows.iter().map(|(_, g)| g.total().operation_count()).sum()
        };
        let [in_ground, in_body] = candidates;
        let chosen = if length(&in_body) < length(&in_ground) {
            in_body
        } else {
            in_ground
        };
        for (direction, groups) in chosen {
            let expression = groups.total();
            rows.push(Equation {
                free_body: free_body.clone(),
                sum: Sum::Force,
                direction: Some(direction),
                unknowns: unknowns_in(&expression, unknowns),
                groups,
                expression,
            });
        }
        let center = model.bodies[body.0].center.position.clone();
        let point = format!("{}*", model.problem.body_name(body));
        let moment_axes: &[usize] = if planar { &[2] } else { &[0, 1, 2] };
        for &axis in moment_axes {
            let direction = unit_direction(model, if planar { BodyId::GROUND } else { own }, axis);
            let groups = resultant(
                model,
                actions,
                inertia,
                &free_body,
                Some(&center),
                &direction.vector,
            );
            let expression = groups.total();
            rows.push(Equation {
                free_body: free_body.clone(),
                sum: Sum::Moment {
                    point: point.clone(),
                    position: center.clone(),
                },
                direction: Some(direction),
                unknowns: unknowns_in(&expression, unknowns),
                groups,
                expression,
            });
        }
    }
    rows
}

/// Newton–Euler's rows: every body's, then the constraint rows; every reaction unknown.
pub(super) fn rows(inputs: &Inputs, setup: Setup) -> MethodRows {
    let Inputs {
        model,
        actions,
        inertia,
        ..
    } = *inputs;
    let rows = equations(model, actions, inertia, &setup.every_unknown);
    setup.with_given(rows)
}
