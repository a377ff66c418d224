//! Where reactions act: the joints of the tree, the closures that close loops, and the
//! rolling contacts. Each is a site with a parent, a child, a point, and the directions
//! that carry a reaction; every method treats the three kinds alike.

use super::error::MechanicsError;
use super::joints::{reaction_components, Axis, ComponentKind, JointMotion, ReactionComponent};
use super::model::Model;
use super::point::PointMotion;
pub use super::site::{Contact, Site, SiteKind};
use super::vector::{cross3, dot3, zero3, Components, Vector};
use super::vector::{own_components, vector_of};
use crate::problem::{BodyId, ConstraintKind, Dimension, ForcePoint, Joint, JointKind, VectorExpr};
use crate::symbolic::{eval, pow, sqrt, Expr};

impl Site {
    /// The site of tree joint `j`.
    pub fn of_joint(model: &Model, j: usize) -> Site {
        let joint = &model.problem.joints[j];
        let jm = &model.joints[j];
        Site {
            name: joint.name.clone(),
            kind: SiteKind::Joint(j),
            parent: joint.parent,
            child: joint.child,
            child_offset: jm.child_at.clone(),
            parent_offset: std::array::from_fn(|i| &jm.at[i] + &jm.motion.translation[i]),
            point: jm.point.clone(),
            reactions: jm.reactions.clone(),
            across: Vec::new(),
        }
    }

    /// The direction of the site's constraint row `component`: its reaction component's,
    /// or, across a light rod, the direction no force has.
    pub fn row_direction(&self, component: usize) -> Option<&Vector> {
        match self.reactions.get(component) {
            Some(reaction) => Some(&reaction.direction),
            None => (self.across.iter())
                .find(|(k, _)| *k == component)
                .map(|(_, d)| d),
        }
    }
}

fn unit(axis: usize) -> Components {
    let mut c = zero3();
    c[axis] = Expr::one();
    c
}

/// The site of closure `c`, with the reaction components its type carries.
///
/// # Errors
/// An axis that is zero or not fixed in the parent.
pub fn closure_site(model: &Model, c: usize) -> Result<Site, MechanicsError> {
    let problem = model.problem;
    let closure = &problem.closures[c];
    let frames = &model.frames;
    let at = own_components(&closure.at, closure.parent);
    let child_at = own_components(&closure.child_at, closure.child);
    let point = model.point_on(closure.child, &child_at);
    let mut reactions = match closure.kind {
        JointKind::Universal => universal_reactions(model, closure),
        _ => {
            let (axis, written_axis) = match closure.kind {
                JointKind::Revolute | JointKind::Prismatic | JointKind::Cylindrical => {
                    let (axis, flipped) =
                        super::joints::joint_axis(problem, closure, frames, &model.values)?;
                    let written = std::array::from_fn(|i| {
                        if flipped {
                            -axis[i].clone()
                        } else {
                            axis[i].clone()
                        }
                    });
                    (Some(axis), Some(written))
                }
                _ => (None, None),
            };
            let motion = JointMotion {
                rotations: Vec::new(),
                translation: zero3(),
                axis,
                written_axis,
            };
            reaction_components(problem, closure, &motion, &model.values)
        }
    };
    // A spherical closure in a planar problem cannot occur; keep 2D reactions in the plane.
    if problem.dimension == Dimension::Two {
        reactions.retain(|r| r.axis != Axis::Unit(2) || r.kind == ComponentKind::Moment);
    }
    // Where the child's point is, as a point of the parent (it slides along a prismatic
    // or cylindrical closure's axis; otherwise it is the closure's point on the parent).
    let parent_offset = if matches!(closure.kind, JointKind::Prismatic | JointKind::Cylindrical) {
        let parent_origin = &model.bodies[closure.parent.0].origin.position;
        point
            .position
            .minus(parent_origin)
            .components_in(closure.parent, frames)
    } else {
        at
    };
    Ok(Site {
        name: closure.name.clone(),
        kind: SiteKind::Closure(c),
        parent: closure.parent,
        child: closure.child,
        child_offset: child_at,
        parent_offset,
        point,
        reactions,
        across: Vec::new(),
    })
}

/// A universal closure: the points coincide, and a couple keeps its axes perpendicular.
fn universal_reactions(model: &Model, closure: &Joint) -> Vec<ReactionComponent> {
    let first = Vector::new(closure.parent, unit(closure.sequence[0] as usize));
    let second = Vector::new(closure.child, unit(closure.sequence[1] as usize));
    let mut out: Vec<ReactionComponent> = (0..3)
        .map(|a| ReactionComponent {
            kind: ComponentKind::Force,
            axis: Axis::Unit(a as u8),
            direction: Vector::unit(closure.parent, a),
        })
        .collect();
    out.push(ReactionComponent {
        kind: ComponentKind::Moment,
        axis: Axis::Numbered(1),
        direction: first.cross(&second, &model.frames),
    });
    out
}

/// |n − (n·â)â|, the cosine of the wheel's lean from the normal, named σ_B where it is a
/// root of a sum (the bicycle's √(C₃₁² + C₃₃²)), which would otherwise be written out in
/// every term of the contact's velocity. A root of one square (the coin's √(cos²θ)) stays,
/// as the worked solution writes it as cos θ.
fn tilt_named(body: &str, square: Expr) -> Expr {
    let length = sqrt(square.clone());
    if crate::symbolic::simplify(&square).terms().len() < 2 {
        return length;
    }
    Expr::named(
        &format!("{body}.tilt"),
        &format!("\\sigma_{{{}}}", crate::symbolic::latex_name(body)),
        &format!("length of the normal's part in the plane of {body}: the cosine of its lean"),
        length,
    )
}

/// The site of rolling contact `k` (before the normal is perhaps dropped) and its geometry.
///
/// # Errors
/// An axle or normal that is zero.
pub fn contact_site(model: &Model, k: usize) -> Result<(Site, Contact), MechanicsError> {
    let problem = model.problem;
    let constraint = &problem.constraints[k];
    let ConstraintKind::Rolling {
        body,
        on,
        radius,
        axis,
        center,
        normal,
        offset,
    } = &constraint.kind
    else {
        return Err(MechanicsError {
            path: constraint.path.clone(),
            message: "not a rolling contact".into(),
            hint: None,
        });
    };
    let frames = &model.frames;
    let (body, on) = (*body, *on);
    let normalized = |written: &VectorExpr, frame: BodyId, key: &str| {
        unit_direction(model, written, frame, || MechanicsError {
            path: format!("{}.{key}", constraint.path),
            message: format!("the {key} is zero"),
            hint: Some("give a nonzero direction".into()),
        })
    };
    // The plane's normal, fixed in `on`, in `on`'s unit vectors.
    let n_in_n: Components = normalized(normal, on, "normal")?;
    let a: Components = normalized(axis, body, "axis")?;
    let center_offset = offset_on(model, center, body);
    let n_vec = Vector::new(on, n_in_n.clone());
    let n_in_body = n_vec.components_in(body, frames);
    // Towards the contact from the centre: -(n - (n.a) a) / |n - (n.a) a|.
    let n_dot_a = dot3(&n_in_body, &a);
    let planar = problem.dimension == Dimension::Two;
    let (toward, tilt) = if planar {
        (n_in_body.clone(), Expr::one())
    } else {
        let w: Components = std::array::from_fn(|i| &n_in_body[i] - &(&n_dot_a * &a[i]));
        let length = tilt_named(model.problem.body_name(body), dot3(&w, &w));
        let inverse = pow(length.clone(), Expr::int(-1));
        (std::array::from_fn(|i| &w[i] * &inverse), length)
    };
    let offset_c: Components = std::array::from_fn(|i| &center_offset[i] - &(radius * &toward[i]));
    // The centre's height above the plane, measured from `on`'s origin.
    let center_position = from_origin_of(model, on, model.position_on(body, &center_offset));
    let height = &(&center_position.dot(&n_vec, frames) - offset) - &(radius * &tilt);
    let tangents = tangents_of(&n_in_n, planar, model, on);
    let reactions = contact_reactions(&tangents, &n_vec);
    let contact = Contact {
        offset: offset_c,
        height,
        tilt,
        on_motion: None,
    };
    Ok(contact_site_of(
        model,
        k,
        (on, body),
        reactions,
        contact,
        |point| from_origin_of(model, on, point.position.clone()).components_in(on, frames),
    ))
}

/// Where a point given by name or by offset is on `body`: from its origin, in its unit
/// vectors.
pub(super) fn offset_on(model: &Model, point: &ForcePoint, body: BodyId) -> Components {
    match point {
        ForcePoint::Point(p) => model.locate(*p).1,
        ForcePoint::Offset(v) => vector_of(v).components_in(body, &model.frames),
    }
}

/// A direction written in the problem, in `frame`'s unit vectors and of unit length; the
/// error `zero` when it has no length at the constants' values.
pub(super) fn unit_direction(
    model: &Model,
    written: &VectorExpr,
    frame: BodyId,
    zero: impl FnOnce() -> MechanicsError,
) -> Result<Components, MechanicsError> {
    let c = vector_of(written).components_in(frame, &model.frames);
    let length = c
        .iter()
        .map(|e| eval(e, &model.values).powi(2))
        .sum::<f64>()
        .sqrt();
    if length.is_nan() || length <= 1e-12 {
        return Err(zero());
    }
    let scale = pow(dot3(&c, &c), Expr::ratio(-1, 2));
    Ok(std::array::from_fn(|i| &c[i] * &scale))
}

/// `position` from `on`'s origin (as it is when `on` is the ground).
pub(super) fn from_origin_of(model: &Model, on: BodyId, position: Vector) -> Vector {
    match on {
        BodyId::GROUND => position,
        _ => position.minus(&model.position_on(on, &zero3())),
    }
}

/// A contact's force components: one along each of `tangents`, then the normal, last.
pub(super) fn contact_reactions(tangents: &[Vector], normal: &Vector) -> Vec<ReactionComponent> {
    let mut reactions: Vec<ReactionComponent> = tangents
        .iter()
        .enumerate()
        .map(|(i, t)| ReactionComponent {
            kind: ComponentKind::Force,
            axis: match direction_axis(t, i + 1) {
                // The one tangent of a contact in a plane is F_t, not F_t1.
                Axis::Tangent(_) if tangents.len() == 1 => Axis::SoleTangent,
                axis => axis,
            },
            direction: t.clone(),
        })
        .collect();
    reactions.push(ReactionComponent {
        kind: ComponentKind::Force,
        axis: direction_axis(normal, 0),
        direction: normal.clone(),
    });
    reactions
}

/// The site of contact entry `k`, where `body` touches `on` at `contact.offset`, carrying
/// `reactions`; `parent_offset` gives `on`'s material point there from the point's motion.
pub(super) fn contact_site_of(
    model: &Model,
    k: usize,
    (on, body): (BodyId, BodyId),
    reactions: Vec<ReactionComponent>,
    contact: Contact,
    parent_offset: impl FnOnce(&PointMotion) -> Components,
) -> (Site, Contact) {
    let point = model.point_on(body, &contact.offset);
    let site = Site {
        name: model.problem.constraints[k].name.clone(),
        kind: SiteKind::Contact(k),
        parent: on,
        child: body,
        child_offset: contact.offset.clone(),
        parent_offset: parent_offset(&point),
        point,
        reactions,
        across: Vec::new(),
    };
    (site, contact)
}

/// `Fx` when `d` is a unit vector of `N`, `Fn` for the normal otherwise, `Ft1`, `Ft2`.
pub(super) fn direction_axis(d: &Vector, index: usize) -> Axis {
    let c = d
        .parts()
        .first()
        .map(|(_, c)| c.clone())
        .unwrap_or_else(zero3);
    let ones: Vec<usize> = (0..3).filter(|&i| c[i].is_one()).collect();
    if ones.len() == 1 && c.iter().filter(|e| e.is_zero()).count() == 2 {
        return Axis::Unit(ones[0] as u8);
    }
    if index == 0 {
        Axis::Normal
    } else {
        Axis::Tangent(index as u8)
    }
}

/// Unit directions in the plane: N's unit vectors when the normal is one of them.
pub(super) fn tangents_of(
    n: &Components,
    planar: bool,
    model: &Model,
    frame: BodyId,
) -> Vec<Vector> {
    let axis_of = |c: &Components| -> Option<usize> {
        let nonzero: Vec<usize> = (0..3).filter(|&i| !c[i].is_zero()).collect();
        (nonzero.len() == 1).then(|| nonzero[0])
    };
    if planar {
        if let Some(a) = axis_of(n).filter(|&a| a < 2) {
            return vec![Vector::unit(frame, 1 - a)];
        }
        let t = cross3(&unit(2), n);
        return vec![Vector::new(frame, t)];
    }
    if let Some(a) = axis_of(n) {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        let (first, second) = if b < c { (b, c) } else { (c, b) };
        return vec![Vector::unit(frame, first), Vector::unit(frame, second)];
    }
    let magnitudes: Vec<f64> = n.iter().map(|c| eval(c, &model.values).abs()).collect();
    let least = (0..3)
        .min_by(|&i, &j| magnitudes[i].total_cmp(&magnitudes[j]))
        .unwrap_or(0);
    let raw = cross3(n, &unit(least));
    let scale = pow(dot3(&raw, &raw), Expr::ratio(-1, 2));
    let first: Components = std::array::from_fn(|i| &raw[i] * &scale);
    let second = cross3(n, &first);
    vec![Vector::new(frame, first), Vector::new(frame, second)]
}

/// The reaction unknowns of the given sites (joints, closures, contacts), in that order.
pub fn reaction_unknowns(model: &super::Model, sites: &[usize]) -> Vec<crate::symbolic::Symbol> {
    sites
        .iter()
        .flat_map(|&j| {
            let site = &model.sites[j];
            site.reactions.iter().map(move |c| c.unknown(&site.name))
        })
        .collect()
}
