//! The rows of requested reactions by composite bodies.
//!
//! Kane's method finds the reaction components of a joint `j` with an auxiliary speed per
//! component: the bodies outboard of `j` move as one rigid body, along the force's
//! direction or turning about the joint's point about the moment's. The row is that
//! motion's `u_a · F + ω_a · M(O_j)` for the forces on those bodies from outside, the
//! reaction itself included: the resultant of the joint's generalized rows
//! ([`super::forces`]), whose pairs between two bodies outboard of `j` cancel, with the
//! joint's reaction and joint loads added. Its q'' part is `u_a · L_s + ω_a · H_s(O_j)` for
//! the momenta at `O_j` of every speed that moves those bodies: the joint's own and the
//! outboard ones' from [`super::mass`], and those of the joints inboard from the
//! composite of `j` moving with each one's motion, carried out to `j`.

use super::forces::{moments_about_joint, Resultant};
use super::mass::{Composite, Momenta};
use super::tree::SpeedMotion;
use super::tree::{apply, in_frame, joint_offset, named_components, named_dcm, path_in, sum};
use crate::mechanics::{cross3, ComponentKind, Components, Model, Vector};
use crate::plan::{is_joint_load, Action, Source};
use crate::symbolic::{add, linear_split, Expr, Symbol};

/// The speeds, the momenta and the resultants of a system by composite bodies.
pub type Parts<'a> = (&'a [Vec<SpeedMotion>], &'a Momenta, &'a [Resultant]);

/// The rows (`A`'s and `b`'s entries) of the reactions of `reaction_joints` in `unknowns`,
/// in the order Kane's rows take them; `None` when one is not linear in the unknowns.
pub fn rows(
    model: &Model,
    actions: &[Action],
    (speeds, momenta, resultants): Parts,
    reaction_joints: &[usize],
    unknowns: &[Symbol],
) -> Option<Vec<(Vec<Expr>, Expr)>> {
    let problem = model.problem;
    let accelerations = problem.speed_symbols(2);
    let mut rows = Vec::new();
    for &j in reaction_joints {
        let joint = &problem.joints[j];
        let body = joint.child;
        // The joint's reaction and its own joint loads act on the child from outside.
        let outside = actions.iter().filter(|a| {
            a.body == body
                && (a.source == Source::Reaction(j)
                    || (is_joint_load(model, a) && a.partner == Some(joint.parent)))
        });
        let (forces, moments) = moments_about_joint(model, j, outside);
        let force = Vector::sum(forces).plus(&resultants[j].force);
        let moment = Vector::sum(moments).plus(&resultants[j].moment);
        let moving = moving(model, speeds, momenta, j);
        for component in &model.sites[j].reactions {
            let d = &component.direction;
            let (omega, velocity) = match component.kind {
                ComponentKind::Force => (Vector::zero(), d.clone()),
                ComponentKind::Moment => (d.clone(), Vector::zero()),
            };
            let along = |(linear, angular): (&Vector, &Vector)| {
                omega.dot(angular, &model.frames) + velocity.dot(linear, &model.frames)
            };
            let inertia = moving.iter().map(|(s, linear, angular)| {
                -(&along((linear, angular)) * &Expr::sym(accelerations[*s].clone()))
            });
            let row = add(inertia.chain([along((&force, &moment))]));
            let (coefficients, rest) = linear_split(&row, unknowns).ok()?;
            rows.push((coefficients, -rest));
        }
    }
    Some(rows)
}

/// Every speed that moves the child of joint `j`, with its momenta at `j`'s point: those of
/// `j` and outboard from `momenta`, and the composite of `j` moving with each inboard
/// speed's motion.
fn moving(
    model: &Model,
    speeds: &[Vec<SpeedMotion>],
    momenta: &Momenta,
    j: usize,
) -> Vec<(usize, Vector, Vector)> {
    let body = model.problem.joints[j].child;
    let mut moving: Vec<(usize, Vector, Vector)> = momenta.at[j]
        .iter()
        .map(|m| (m.speed, m.linear.clone(), m.angular.clone()))
        .collect();
    let path = path_in(model, j);
    for (depth, &i) in path.iter().enumerate().skip(1) {
        for s in &speeds[i] {
            let (omega, velocity) = carried_out(model, s, &path[..depth]);
            let composite: &Composite = &momenta.composites[j];
            let (linear, angular) =
                composite.momentum(body, &omega, &Vector::new(body, velocity), model);
            moving.push((s.speed, linear, angular));
        }
    }
    moving
}

/// The motion of speed `s` of a joint inboard carried out through the joints of `outward`
/// (from the outermost in), to the last one's child: its angular velocity and its point at
/// that joint's velocity, in the child's unit vectors.
fn carried_out(model: &Model, s: &SpeedMotion, outward: &[usize]) -> (Components, Components) {
    let problem = model.problem;
    let owner = problem.coordinates[s.speed].joint;
    let mut body = problem.joints[owner].child;
    let mut omega = s.omega.clone();
    let mut velocity = in_frame(model, &s.velocity, body);
    let mut point = model.joints[owner].child_at.clone();
    for &c in outward.iter().rev() {
        let child = problem.joints[c].child;
        let turn = named_dcm(model, child, body);
        let at_joint = sum(&velocity, &cross3(&omega, &joint_offset(model, c, &point)));
        let speed = &problem.coordinates[s.speed].name;
        let what = |quantity: &str| {
            format!(
                "{quantity} per unit {speed}' at the joint of {}",
                model.frames.name(child)
            )
        };
        omega = named_components(
            model,
            child,
            (
                &format!("S.{speed}.w"),
                "\\omega",
                &what("angular velocity"),
            ),
            apply(&turn, &omega),
        );
        velocity = named_components(
            model,
            child,
            (&format!("S.{speed}.v"), "v", &what("velocity")),
            apply(&turn, &at_joint),
        );
        body = child;
        point = model.joints[c].child_at.clone();
    }
    (omega, velocity)
}
