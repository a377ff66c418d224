//! Every force and couple in the system, each acting on one body, sorted as the Motion Law
//! names them: contact forces and distance forces. (Inertia forces come from kinematics.)

use crate::mechanics::{ComponentKind, Components, MechanicsError, Model, RowOrigin, Site, Vector};
use crate::problem::{BodyId, ForcePoint, LoadKind, PointRef};
use crate::symbolic::{linear_split, Expr, Symbol};

pub(super) mod line;
use line::Lines;

/// Contact (touching) or distance (gravity) force, as the Motion Law sorts them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Category {
    /// Reactions, springs, dampers, applied forces and torques, joint loads.
    Contact,
    /// Gravity.
    Distance,
}

/// Where an action comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// Gravity on a body.
    Gravity,
    /// A load of the problem, by index.
    Load(usize),
    /// The reaction at a site (a joint, closure or rolling contact), by index into
    /// `Model::sites`.
    Reaction(usize),
    /// What enforces a constraint row that has no site (a multiplier or a drive), by index
    /// into `Model::constraints.rows`; it acts like a joint load on each coordinate.
    Constraint(usize),
}

/// A force at a point of a body, or a couple on it.
#[derive(Clone, Debug)]
pub enum ActionKind {
    /// A force applied at `offset` from the body's origin (body's unit vectors).
    Force {
        /// Where it acts, from the body's origin.
        offset: Components,
        /// The force.
        force: Vector,
    },
    /// A couple.
    Couple {
        /// Its moment.
        torque: Vector,
    },
}

/// One force or couple acting on one body.
#[derive(Clone, Debug)]
pub struct Action {
    /// The body acted on.
    pub body: BodyId,
    /// The other body of an action–reaction pair, if any: when both are inside a free body
    /// the pair is internal and drops out.
    pub partner: Option<BodyId>,
    /// Contact or distance.
    pub category: Category,
    /// Where it comes from.
    pub source: Source,
    /// A short name for tables, e.g. `spring k1 on B`, `reaction at O`.
    pub label: String,
    /// The force or couple.
    pub kind: ActionKind,
}

/// Every action in the system. Reactions come with their unknown components as symbols.
///
/// # Errors
/// When a spring or damper joins two points of the same body, or a force acts at a point
/// that is not on its body.
pub fn actions(model: &Model) -> Result<Vec<Action>, MechanicsError> {
    let problem = model.problem;
    let mut out = Vec::new();
    if let Some(g) = &problem.gravity {
        let g = crate::mechanics::vector_of(g);
        for body in problem.body_ids() {
            let state = &model.bodies[body.0];
            if state.mass.is_zero() {
                // A massless body has no weight.
                continue;
            }
            out.push(Action {
                body,
                partner: None,
                category: Category::Distance,
                source: Source::Gravity,
                label: format!("gravity on {}", problem.body_name(body)),
                kind: ActionKind::Force {
                    offset: state.center_offset.clone(),
                    force: g.scaled(&state.mass),
                },
            });
        }
    }
    for (j, site) in model.sites.iter().enumerate() {
        if site.reactions.is_empty() {
            continue;
        }
        let mut force = Vector::zero();
        let mut moment = Vector::zero();
        for component in &site.reactions {
            let unknown = Expr::sym(component.unknown(&site.name));
            let part = component.direction.scaled(&unknown);
            if component.kind == ComponentKind::Force {
                force = force.plus(&part);
            } else {
                moment = moment.plus(&part);
            }
        }
        // The site in words: `rear_contact` is the rear contact.
        let label = format!("reaction at {}", site.name.replace('_', " "));
        push_pair(
            &mut out,
            site,
            Category::Contact,
            Source::Reaction(j),
            &label,
            &force,
            &moment,
        );
    }
    for (r, (coordinate, value)) in constraint_generalized_forces(model).into_iter().enumerate() {
        for (c, value) in coordinate.into_iter().zip(value) {
            let row = &model.constraints.rows[r];
            // A prescribed coordinate's row is enforced by its drive, at its joint.
            let label = match row.origin {
                crate::mechanics::RowOrigin::Prescribed(i) => {
                    drive_label(problem, &problem.coordinates[i])
                }
                _ => format!("enforcing {}", row.name),
            };
            joint_load(
                &mut out,
                model,
                problem.coordinates[c].joint,
                c,
                &value,
                Source::Constraint(r),
                &label,
            );
        }
    }
    let mut lines = Lines::default();
    for (index, load) in problem.loads.iter().enumerate() {
        load_actions(
            model,
            index,
            &load.kind,
            &load.path,
            load.name.as_deref(),
            &mut lines,
            &mut out,
        )?;
    }
    Ok(out)
}

/// A drive named as a course names it: the motor's torque that holds an angle (or turns it
/// as prescribed), the actuator's force that holds a distance.
fn drive_label(
    problem: &crate::problem::Problem,
    coordinate: &crate::problem::Coordinate,
) -> String {
    let (agent, at) = match coordinate.kind {
        crate::problem::CoordinateKind::Angle => ("the motor's torque", "at"),
        crate::problem::CoordinateKind::Distance => ("the actuator's force", "along"),
    };
    let joint = &problem.joints[coordinate.joint].name;
    let name = &coordinate.name;
    if coordinate.held {
        format!("{agent} {at} {joint} holding {name}")
    } else {
        format!("{agent} {at} {joint} driving {name} as prescribed")
    }
}

/// A force through a site's point and a couple on the child, and their opposites on the parent.
fn push_pair(
    out: &mut Vec<Action>,
    site: &Site,
    category: Category,
    source: Source,
    label: &str,
    force: &Vector,
    couple: &Vector,
) {
    let minus = Expr::int(-1);
    let sides = [
        (
            site.child,
            site.parent,
            site.child_offset.clone(),
            force.clone(),
            couple.clone(),
        ),
        (
            site.parent,
            site.child,
            site.parent_offset.clone(),
            force.scaled(&minus),
            couple.scaled(&minus),
        ),
    ];
    for (body, partner, offset, f, c) in sides {
        if body == BodyId::GROUND {
            continue;
        }
        if !f.is_zero() {
            let kind = ActionKind::Force { offset, force: f };
            out.push(Action {
                body,
                partner: Some(partner),
                category,
                source,
                label: label.to_string(),
                kind,
            });
        }
        if !c.is_zero() {
            let kind = ActionKind::Couple { torque: c };
            out.push(Action {
                body,
                partner: Some(partner),
                category,
                source,
                label: label.to_string(),
                kind,
            });
        }
    }
}

/// Where a force on `on` acts, from `on`'s origin; the message when the point is on
/// another body.
fn force_offset(model: &Model, on: BodyId, at: &ForcePoint) -> Result<Components, String> {
    match at {
        ForcePoint::Point(point) => {
            let (body, offset) = model.locate(*point);
            if body != on {
                let problem = model.problem;
                return Err(format!(
                    "the point is on `{}`, not on `{}`",
                    problem.body_name(body),
                    problem.body_name(on)
                ));
            }
            Ok(offset)
        }
        ForcePoint::Offset(v) => {
            Ok(crate::mechanics::vector_of(v).components_in(on, &model.frames))
        }
    }
}

fn load_actions(
    model: &Model,
    index: usize,
    kind: &LoadKind,
    path: &str,
    name: Option<&str>,
    lines: &mut Lines,
    out: &mut Vec<Action>,
) -> Result<(), MechanicsError> {
    let problem = model.problem;
    let source = Source::Load(index);
    let named = |default: String| name.map(str::to_string).unwrap_or(default);
    let error = |message: String, hint: &str| MechanicsError {
        path: path.to_string(),
        message,
        hint: Some(hint.into()),
    };
    let contact = |body: BodyId, partner: Option<BodyId>, label: String, kind: ActionKind| Action {
        body,
        partner,
        category: Category::Contact,
        source,
        label,
        kind,
    };
    match kind {
        LoadKind::Force { on, at, vector } => {
            let offset = force_offset(model, *on, at).map_err(|message| {
                error(
                    message,
                    "a force acts at a point of the body it is applied to",
                )
            })?;
            let force = crate::mechanics::vector_of(vector);
            if *on != BodyId::GROUND {
                out.push(contact(
                    *on,
                    None,
                    named(format!("force on {}", problem.body_name(*on))),
                    ActionKind::Force { offset, force },
                ));
            }
        }
        LoadKind::Torque {
            on,
            vector,
            reaction_on,
        } => {
            let torque = crate::mechanics::vector_of(vector);
            let label = named(format!("torque on {}", problem.body_name(*on)));
            if *on != BodyId::GROUND {
                out.push(contact(
                    *on,
                    *reaction_on,
                    label.clone(),
                    ActionKind::Couple {
                        torque: torque.clone(),
                    },
                ));
            }
            if let Some(other) = reaction_on.filter(|b| *b != BodyId::GROUND) {
                let opposite = torque.scaled(&Expr::int(-1));
                out.push(contact(
                    other,
                    Some(*on),
                    label,
                    ActionKind::Couple { torque: opposite },
                ));
            }
        }
        LoadKind::Spring {
            between,
            stiffness,
            free_length,
        } => {
            let line = lines.get(model, between, path)?;
            // The tension k (ℓ - ℓ0) along û pulls the first point toward the second; with
            // ℓ0 = 0 it is k Δ, without a square root.
            let force = if free_length.is_zero() {
                line.delta.scaled(stiffness)
            } else {
                // The stretch stays one factor, `k (ℓ - ℓ0) û`, rather than two terms.
                let stretch =
                    Expr::defined(&format!("load{index}.stretch"), &line.length - free_length);
                line.unit.scaled(&(stiffness * &stretch))
            };
            let ends = ends(model, between);
            push_two_point(out, ends, &force, contact, &named("spring".into()));
        }
        LoadKind::Damper {
            between,
            coefficient,
        } => {
            let line = lines.get(model, between, path)?;
            // c ℓ̇ along û: pulls the points together while they separate.
            let force = line.unit.scaled(&(coefficient * &line.rate));
            let ends = ends(model, between);
            push_two_point(out, ends, &force, contact, &named("damper".into()));
        }
        LoadKind::JointSpring { .. }
        | LoadKind::JointDamper { .. }
        | LoadKind::JointActuator { .. } => {
            if let Some((joint, coordinate, value)) = joint_load_value(problem, kind) {
                let label = match kind {
                    LoadKind::JointSpring { .. } => "joint spring",
                    LoadKind::JointDamper { .. } => "joint damper",
                    _ => "actuator",
                };
                joint_load(
                    out,
                    model,
                    joint,
                    coordinate,
                    &value,
                    source,
                    &named(label.into()),
                );
            }
        }
    }
    Ok(())
}

type Ends = [(BodyId, Components); 2];

/// The bodies of two points and the points' offsets from their origins.
fn ends(model: &Model, between: &[PointRef; 2]) -> Ends {
    [model.locate(between[0]), model.locate(between[1])]
}

/// `force_on_first` on the first point, its opposite on the second.
fn push_two_point(
    out: &mut Vec<Action>,
    ends: Ends,
    force_on_first: &Vector,
    contact: impl Fn(BodyId, Option<BodyId>, String, ActionKind) -> Action,
    label: &str,
) {
    let [(b1, o1), (b2, o2)] = ends;
    if b1 != BodyId::GROUND {
        out.push(contact(
            b1,
            Some(b2),
            label.to_string(),
            ActionKind::Force {
                offset: o1,
                force: force_on_first.clone(),
            },
        ));
    }
    if b2 != BodyId::GROUND {
        let opposite = force_on_first.scaled(&Expr::int(-1));
        out.push(contact(
            b2,
            Some(b1),
            label.to_string(),
            ActionKind::Force {
                offset: o2,
                force: opposite,
            },
        ));
    }
}

fn joint_load(
    out: &mut Vec<Action>,
    model: &Model,
    j: usize,
    coordinate: usize,
    value: &Expr,
    source: Source,
    label: &str,
) {
    let index = model.problem.coordinates[coordinate].index_in_joint;
    let Some(axis) = model.joints[j].load_axes.get(index) else {
        return;
    };
    let force = axis.force.scaled(value);
    let couple = axis.torque.scaled(value);
    push_pair(
        out,
        &model.sites[j],
        Category::Contact,
        source,
        label,
        &force,
        &couple,
    );
}

/// The generalized force that joint loads put directly on each coordinate (for Kane's method).
pub fn joint_load_generalized_forces(model: &Model) -> Vec<Expr> {
    let mut q = load_generalized_forces(model);
    for (coordinates, values) in constraint_generalized_forces(model) {
        for (c, value) in coordinates.into_iter().zip(values) {
            q[c] = &q[c] + &value;
        }
    }
    q
}

/// The generalized forces of the joint loads alone (springs, dampers, actuators on the
/// joints' coordinates), one per coordinate: without what enforces the constraints.
pub fn load_generalized_forces(model: &Model) -> Vec<Expr> {
    let problem = model.problem;
    let mut q = vec![Expr::zero(); problem.coordinates.len()];
    for load in &problem.loads {
        let Some((_, c, value)) = joint_load_value(problem, &load.kind) else {
            continue;
        };
        q[c] = &q[c] + &value;
    }
    q
}

/// For each constraint row (in `Model::constraints.rows` order), the generalized forces
/// that its multiplier or drive puts on the coordinates: `λ ∂(row)/∂q'_c` for each
/// coordinate `c` the velocity row involves. Rows of sites give none (their reactions are
/// forces at the site).
pub fn constraint_generalized_forces(model: &Model) -> Vec<(Vec<usize>, Vec<Expr>)> {
    let problem = model.problem;
    let rates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|i| problem.coordinate_symbol(i, 1))
        .collect();
    model
        .constraints
        .rows
        .iter()
        .map(|row| {
            if matches!(row.origin, RowOrigin::Site { .. }) {
                return (Vec::new(), Vec::new());
            }
            let Ok((coefficients, _)) = linear_split(&row.velocity, &rates) else {
                return (Vec::new(), Vec::new());
            };
            let unknown = Expr::sym(row.unknown.clone());
            coefficients
                .into_iter()
                .enumerate()
                .filter(|(_, c)| !c.is_zero())
                .map(|(i, c)| (i, &unknown * &c))
                .unzip()
        })
        .collect()
}

/// A joint load's joint, coordinate and generalized force: `-k (q - rest)`, `-c q'` or the
/// actuator's value; `None` for other loads.
pub fn joint_load_value(
    problem: &crate::problem::Problem,
    kind: &LoadKind,
) -> Option<(usize, usize, Expr)> {
    match kind {
        LoadKind::JointSpring {
            joint,
            coordinate,
            stiffness,
            rest,
        } => Some((
            *joint,
            *coordinate,
            -(stiffness * &(&problem.coordinate_expr(*coordinate, 0) - rest)),
        )),
        LoadKind::JointDamper {
            joint,
            coordinate,
            coefficient,
        } => Some((
            *joint,
            *coordinate,
            -(coefficient * &problem.coordinate_expr(*coordinate, 1)),
        )),
        LoadKind::JointActuator {
            joint,
            coordinate,
            value,
        } => Some((*joint, *coordinate, value.clone())),
        _ => None,
    }
}

/// Whether an action is a joint load (so that Kane's method can take it as a generalized force).
pub fn is_joint_load(model: &Model, action: &Action) -> bool {
    matches!(action.source, Source::Constraint(_))
        || matches!(action.source, Source::Load(i) if matches!(
            model.problem.loads[i].kind,
            LoadKind::JointSpring { .. } | LoadKind::JointDamper { .. } | LoadKind::JointActuator { .. }
        ))
}
