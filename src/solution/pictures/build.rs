//! Building the scenes: the configuration, and each free body with its kinetic diagram.

use super::joint_symbols;
use super::load_symbols::{factor_tex, magnitude_symbol};
use super::numbers::{norm, scale, sub, unit, Numbers, P3};
use crate::equations::Derivation;
use crate::mechanics::ComponentKind;
use crate::plan::{is_external, Action, ActionKind, Source};
use crate::problem::{BodyId, ForcePoint, LoadKind, PointRef};
use crate::render::draw::{Arrow, Kind, Label, Marker, Role, Scene, Shape};
use crate::symbolic::{latex, latex_name, latex_unit_vector, simplify, Expr};

/// What every free-body picture's arrows mean, in one short line: every arrow is drawn
/// one length (a second along the same line a step longer), unknown components along
/// their positive senses, known forces the way they act at the state drawn.
pub const FREE_BODY_LEGEND: &str =
    "Not to scale. Unknowns (red) along + axes; known forces as they act.";

/// [`FREE_BODY_LEGEND`] where a free body carries a reaction's unknowns on the joint's
/// parent, drawn opposite the + axes: the equal and opposite of its partner's.
pub const FREE_BODY_LEGEND_THIRD_LAW: &str = "Not to scale. Unknowns (red) along + axes, \
     or opposite their partner's by Newton's third law; known forces as they act.";

/// What [`FREE_BODY_LEGEND`] (or [`FREE_BODY_LEGEND_THIRD_LAW`]) adds where a contact slides
/// at the state drawn: its friction, an unknown of the rows too, is drawn against the slip,
/// its label signed as it points (`−F^P_x`).
pub const SLIDING_FRICTION: &str = ", sliding friction against the slip";

/// The legend of a free body: with Newton's third law where it draws a partner's unknowns
/// opposite the + axes, with [`SLIDING_FRICTION`] where it draws a sliding friction.
pub fn legend_of(third_law: bool, sliding: bool) -> String {
    let legend = if third_law {
        FREE_BODY_LEGEND_THIRD_LAW
    } else {
        FREE_BODY_LEGEND
    };
    match sliding {
        true => legend.replacen(
            "; known forces",
            &format!("{SLIDING_FRICTION}; known forces"),
            1,
        ),
        false => legend.to_string(),
    }
}

/// What every picture of one problem shares.
pub struct Setting<'a, 'm, 'p> {
    /// The derivation whose plan gives the free bodies.
    pub derivation: &'a Derivation<'p>,
    /// The state, as numbers (with the q'' when they could be solved for).
    pub numbers: &'a Numbers<'m, 'p>,
    /// Whether `numbers` holds the q'' (otherwise the kinetic diagram has no arrows).
    pub accelerations: bool,
    /// The characteristic length of the system.
    pub size: f64,
}

/// The id of a named point in the markup.
pub fn point_id(problem: &crate::problem::Problem, point: PointRef) -> String {
    match point {
        PointRef::Named(i) => format!("point-{}", problem.points[i].name),
        PointRef::MassCenter(b) => format!("cm-{}", problem.body_name(b)),
        PointRef::Origin(b) => format!("origin-{}", problem.body_name(b)),
        PointRef::Joint(j) => format!("joint-{}", problem.joints[j].name),
    }
}

impl Setting<'_, '_, '_> {
    pub(super) fn problem(&self) -> &crate::problem::Problem {
        self.derivation.model.problem
    }

    fn position(&self, point: PointRef) -> P3 {
        self.numbers.vector(&self.derivation.model.position(point))
    }

    /// The marker of a point, with its caption.
    fn marker(&self, point: PointRef) -> Marker {
        let problem = self.problem();
        let (role, caption) = match point {
            PointRef::Named(i) => (Role::Point, latex_name(&problem.points[i].name)),
            PointRef::MassCenter(b) => (
                Role::Center,
                crate::solution::tex::centre_tex(&self.derivation.model, b),
            ),
            PointRef::Origin(b) => (
                Role::Point,
                // Braced: `B0` is `B_{0}`, and a second subscript needs a group to hang on.
                format!("{{{}}}_{{o}}", latex_name(problem.body_name(b))),
            ),
            PointRef::Joint(j) => (Role::Joint, latex_name(&problem.joints[j].name)),
        };
        // A joint that carries no force (a planar or free joint) is no point a student
        // names: its mark stays, unlabelled.
        let carries = match point {
            PointRef::Joint(j) => !self.derivation.model.sites[j].reactions.is_empty(),
            _ => true,
        };
        let on = match point {
            PointRef::Named(i) => vec![problem.points[i].on],
            PointRef::MassCenter(b) | PointRef::Origin(b) => vec![b],
            PointRef::Joint(j) => vec![problem.joints[j].child, problem.joints[j].parent],
        };
        Marker {
            id: point_id(problem, point),
            at: self.position(point),
            role,
            caption: carries.then(|| Label::from_tex(&caption)),
            on: self.names(&on),
        }
    }

    /// The markers of the points on `bodies` (every joint that touches them).
    fn markers(&self, bodies: &[BodyId], ground: bool) -> Vec<Marker> {
        let problem = self.problem();
        let on = |b: BodyId| bodies.contains(&b) || (ground && b == BodyId::GROUND);
        let mut out = Vec::new();
        for (j, joint) in problem.joints.iter().enumerate() {
            if on(joint.child) || on(joint.parent) {
                out.push(self.marker(PointRef::Joint(j)));
            }
        }
        // Closures and rolling contacts: their points on the child, like joints'.
        let model = &self.derivation.model;
        for site in model.sites.iter().skip(problem.joints.len()) {
            let placeholder = site.parent == site.child;
            if !placeholder && (on(site.child) || on(site.parent)) {
                out.push(Marker {
                    id: format!("joint-{}", site.name),
                    at: self.numbers.vector(&site.point.position),
                    role: Role::Joint,
                    caption: Some(Label::from_tex(&latex_name(&site.name))),
                    on: self.names(&[site.child, site.parent]),
                });
            }
        }
        for &b in bodies {
            out.push(self.marker(PointRef::MassCenter(b)));
        }
        for b in super::shapes::origins_used(problem) {
            if on(b) {
                out.push(self.marker(PointRef::Origin(b)));
            }
        }
        for (i, point) in problem.points.iter().enumerate() {
            if on(point.on) {
                out.push(self.marker(PointRef::Named(i)));
            }
        }
        out
    }

    fn body_ids(&self) -> Vec<BodyId> {
        self.problem().body_ids().collect()
    }

    /// The springs and dampers, with ground marks at their ends on `N`.
    fn elements(&self, shapes: &mut Vec<Shape>) {
        let model = &self.derivation.model;
        let lanes = super::lanes::lanes(&self.problem().loads);
        for (load, &lane) in self.problem().loads.iter().zip(&lanes) {
            let (between, spring) = match &load.kind {
                LoadKind::Spring { between, .. } => (between, true),
                LoadKind::Damper { between, .. } => (between, false),
                _ => continue,
            };
            let [from, to] = between.map(|p| self.position(p));
            shapes.push(if spring {
                Shape::Spring { from, to, lane }
            } else {
                Shape::Damper { from, to, lane }
            });
            for (end, other) in [(between[0], to), (between[1], from)] {
                if model.locate(end).0 == BodyId::GROUND {
                    let at = self.position(end);
                    let up = unit(sub(other, at)).unwrap_or([0.0, 1.0, 0.0]);
                    shapes.push(Shape::Ground {
                        at,
                        along: [0.0; 3],
                        up,
                    });
                }
            }
        }
    }

    /// The unit vectors of every frame at its origin (`N`'s in a corner).
    fn triads(&self, shapes: &mut Vec<Shape>) {
        let n = self.numbers;
        let axes_count = if self.derivation.model.is_planar() {
            2
        } else {
            3
        };
        let mut frames = vec![BodyId::GROUND];
        // A long chain would drown in arrows: its bodies' unit vectors are left out.
        if self.body_ids().len() <= 3 {
            frames.extend(self.body_ids());
        }
        let model = &self.derivation.model;
        for body in frames {
            // A body spinning about its symmetry axis: the frame its equations use, that
            // does not spin (Resal's), at its origin; none where that is the parent's.
            let spin =
                (model.spin_frames.iter()).find(|s| s.body == body && body != BodyId::GROUND);
            let (frame, name) = match spin {
                Some(s) if !s.added => continue,
                Some(s) => (s.frame, model.frames.name(s.frame)),
                None => (body, self.problem().body_name(body)),
            };
            let axes = (0..axes_count)
                .map(|k| {
                    let mut e = [0.0; 3];
                    e[k] = 1.0;
                    let tex = latex_unit_vector(name, k as u8);
                    (n.in_ground(frame, &e), Label::from_tex(&tex))
                })
                .collect();
            let origin = super::triads::beside(n, body, self.size)
                .unwrap_or_else(|| super::triads::within(n, body));
            shapes.push(Shape::Triad {
                origin: (body != BodyId::GROUND).then_some(origin),
                axes,
            });
        }
    }

    /// The picture of the whole system at the state.
    pub fn configuration(&self, title: String) -> Scene {
        // A floor goes under everything on it; the other surfaces after the bodies.
        let (mut shapes, surfaces): (Vec<Shape>, Vec<Shape>) =
            super::bodies::surfaces(self.numbers, self.size)
                .into_iter()
                .partition(|s| matches!(s, Shape::Floor { .. }));
        let bodies = self.body_ids();
        for &b in &bodies {
            shapes.push(super::bodies::body(self.numbers, b, self.size));
        }
        shapes.extend(surfaces);
        shapes.extend(super::contact_surfaces::contact_surfaces(
            self.numbers,
            self.size,
        ));
        self.elements(&mut shapes);
        for j in 0..self.problem().joints.len() {
            shapes.extend(joint_symbols::joint(self.numbers, j, self.size));
        }
        shapes.extend(super::gauges::shapes(self.numbers, self.size));
        shapes.extend(self.load_angles());
        shapes.extend(super::gauges::named_lengths(self.numbers, self.size));
        shapes.extend(super::velocities::velocities(self.numbers, self.size));
        self.triads(&mut shapes);
        let mut markers = self.markers(&bodies, true);
        let mut arrows = self.applied(&mut markers);
        arrows.extend(self.blows(&mut markers));
        Scene {
            title,
            planar: self.derivation.model.is_planar(),
            shapes,
            markers,
            arrows,
            kinetic: None,
            down: super::bodies::down(self.numbers),
            legend: String::new(),
            content: crate::render::draw::CONTENT,
        }
    }

    /// The free-body diagram of `set` with its kinetic diagram, the system `content` px
    /// across at most.
    pub fn free_body(&self, set: &[BodyId], title: String, content: f64) -> Scene {
        let problem = self.problem();
        let mut shapes = Vec::new();
        for &b in set {
            shapes.push(super::bodies::body(self.numbers, b, self.size));
        }
        let body_shapes = shapes.clone();
        // Joints inside the group hold it together; the cut ones are replaced by arrows.
        for (j, joint) in problem.joints.iter().enumerate() {
            if set.contains(&joint.child) && set.contains(&joint.parent) {
                shapes.extend(
                    joint_symbols::joint(self.numbers, j, self.size)
                        .into_iter()
                        .filter(|s| !matches!(s, Shape::Ground { .. })),
                );
            }
        }
        let mut markers = self.markers(set, false);
        let mut arrows = Vec::new();
        let (mut third_law, mut sliding) = (false, false);
        for action in self
            .derivation
            .actions
            .iter()
            .filter(|a| is_external(a, set))
        {
            let drawn = self.action_arrows(action, &mut markers);
            third_law |= self.is_partners(action) && drawn.iter().any(|a| a.kind == Kind::Reaction);
            sliding |= self.slides(action);
            arrows.extend(drawn);
        }
        let kinetic: Vec<Arrow> = set.iter().flat_map(|&b| self.inertia_arrows(b)).collect();
        // A joint inside the group carries no force on it: its pin is drawn with the bodies,
        // not marked and named as a point forces act at.
        let inside = self.joints_inside(set);
        let acted_at = |id: &String| arrows.iter().chain(&kinetic).any(|a| &a.at_id == id);
        // A joint of a body in the group that carries nothing on it (a planar joint's)
        // would be a stray name: only joints where arrows act are marked.
        markers.retain(|m| {
            acted_at(&m.id) || !(inside.contains(&m.id) || matches!(m.role, Role::Joint))
        });
        Scene {
            title,
            planar: self.derivation.model.is_planar(),
            shapes,
            markers,
            arrows,
            kinetic: Some((body_shapes, kinetic)),
            down: super::bodies::down(self.numbers),
            legend: legend_of(third_law, sliding),
            content,
        }
    }

    /// Whether `action` is a reaction with a friction component that slides at the state
    /// drawn.
    fn slides(&self, action: &Action) -> bool {
        let model = &self.derivation.model;
        match action.source {
            Source::Reaction(j) => (model.sites[j].reactions.iter())
                .any(|c| super::sliding::sliding(model, self.numbers, j, c).is_some()),
            _ => false,
        }
    }

    /// Whether `action` is a reaction on its joint's parent, whose unknowns are drawn
    /// opposite the + axes (the child feels them along).
    fn is_partners(&self, action: &Action) -> bool {
        match action.source {
            Source::Reaction(j) => action.body != self.derivation.model.sites[j].child,
            _ => false,
        }
    }

    /// The ids of the joints, closures and contacts both of whose bodies are in `set`.
    fn joints_inside(&self, set: &[BodyId]) -> Vec<String> {
        let inside = |a: BodyId, b: BodyId| set.contains(&a) && set.contains(&b);
        self.derivation
            .model
            .sites
            .iter()
            .filter(|site| site.parent != site.child && inside(site.parent, site.child))
            .map(|site| format!("joint-{}", site.name))
            .collect()
    }

    /// The id of the marker at `at` on the action's body, adding one if there is none.
    fn marker_at(&self, action: &Action, at: P3, markers: &mut Vec<Marker>) -> String {
        let problem = self.problem();
        let preferred = match action.source {
            Source::Gravity => Some(point_id(problem, PointRef::MassCenter(action.body))),
            Source::Reaction(j) => Some(format!("joint-{}", self.derivation.model.sites[j].name)),
            Source::Constraint(_) => None,
            Source::Load(i) => match &problem.loads[i].kind {
                LoadKind::Force {
                    at: ForcePoint::Point(p),
                    ..
                } => Some(point_id(problem, *p)),
                LoadKind::Spring { between, .. } | LoadKind::Damper { between, .. } => between
                    .iter()
                    .find(|p| self.derivation.model.locate(**p).0 == action.body)
                    .map(|p| point_id(problem, *p)),
                LoadKind::JointSpring { joint, .. }
                | LoadKind::JointDamper { joint, .. }
                | LoadKind::JointActuator { joint, .. } => {
                    Some(point_id(problem, PointRef::Joint(*joint)))
                }
                LoadKind::Torque { on, .. } => Some(point_id(problem, PointRef::MassCenter(*on))),
                LoadKind::Force { .. } => None,
            },
        };
        if let Some(id) = preferred.filter(|id| markers.iter().any(|m| &m.id == id)) {
            return id;
        }
        let close = |m: &&Marker| norm(sub(m.at, at)) <= 1e-9 * self.size.max(1.0);
        if let Some(m) = markers.iter().find(close) {
            return m.id.clone();
        }
        let id = format!("at-{}", markers.len() + 1);
        markers.push(Marker {
            id: id.clone(),
            at,
            role: Role::Point,
            caption: None,
            on: self.names(&[action.body]),
        });
        id
    }

    /// The arrows of one external action: one per unknown component of a reaction.
    pub(super) fn action_arrows(&self, action: &Action, markers: &mut Vec<Marker>) -> Vec<Arrow> {
        let n = self.numbers;
        let model = &self.derivation.model;
        let problem = self.problem();
        let (at, couple, value) = match &action.kind {
            ActionKind::Force { offset, force } => {
                (n.point_on(action.body, &n.local(offset)), false, force)
            }
            ActionKind::Couple { torque } => {
                let at = match action.source {
                    Source::Reaction(j) => n.vector(&model.sites[j].point.position),
                    // A drive turns its coordinate's joint: drawn there, as a motor at its
                    // bearing; a multiplier's couple at the mass centre.
                    Source::Constraint(r) => match model.constraints.rows[r].origin {
                        crate::mechanics::RowOrigin::Prescribed(i) => {
                            let j = problem.coordinates[i].joint;
                            n.vector(&model.joints[j].point.position)
                        }
                        _ => n.vector(&model.bodies[action.body.0].center.position),
                    },
                    Source::Load(i) => {
                        match crate::plan::joint_load_value(problem, &problem.loads[i].kind) {
                            Some((j, _, _)) => n.vector(&model.joints[j].point.position),
                            None => n.vector(&model.bodies[action.body.0].center.position),
                        }
                    }
                    Source::Gravity => n.vector(&model.bodies[action.body.0].center.position),
                };
                (at, true, torque)
            }
        };
        let at_id = self.marker_at(action, at, markers);
        let arrow = |kind, label, direction| Arrow {
            kind,
            label,
            at_id: at_id.clone(),
            at,
            direction,
            couple,
        };
        match action.source {
            Source::Reaction(j) => {
                let joint = &model.sites[j];
                // The parent feels the opposite of what the child feels.
                let sign = if action.body == joint.child {
                    1.0
                } else {
                    -1.0
                };
                joint
                    .reactions
                    .iter()
                    .filter(|c| (c.kind == ComponentKind::Moment) == couple)
                    .filter_map(|c| {
                        if let Some((along, label)) = super::sliding::sliding(model, n, j, c) {
                            // Sliding friction, an unknown of the rows: drawn against the
                            // slip, its label signed as it points.
                            let direction = scale(along, sign);
                            unit(direction)?;
                            return Some(arrow(Kind::Reaction, label, direction));
                        }
                        let direction = scale(n.vector(&c.direction), sign);
                        unit(direction)?;
                        let symbol = c.unknown(&joint.name);
                        // Plain as the joint is named: `F^P2_x` for `F^{P_{2}}_{x}`.
                        // A name with an underscore (`rear_contact`) is braced, one run.
                        let name = if joint.name.contains('_') {
                            format!("{{{}}}", joint.name)
                        } else {
                            joint.name.clone()
                        };
                        let plain = if c.axis == crate::symbolic::Axis::Member {
                            format!("T^{name}")
                        } else {
                            format!("{}^{name}_{}", c.kind.letter(), c.axis.subscript())
                        };
                        let label = Label {
                            plain,
                            tex: latex(&Expr::sym(symbol)),
                        };
                        Some(arrow(Kind::Reaction, label, direction))
                    })
                    .collect()
            }
            Source::Gravity => {
                let direction = n.vector(value);
                let label = Label::from_tex(&self.weight_tex(action.body));
                unit(direction)
                    .map(|_| arrow(Kind::Gravity, label, direction))
                    .into_iter()
                    .collect()
            }
            Source::Constraint(r) => {
                // A drive or a multiplier: an unknown, drawn along its positive direction.
                let unknown = &model.constraints.rows[r].unknown;
                let along = value.map(|e| {
                    crate::symbolic::substitute(e, &|s| {
                        (s == unknown).then(crate::symbolic::Expr::one)
                    })
                });
                let direction = n.vector(&along);
                let label = Label::from_tex(&latex(&Expr::sym(unknown.clone())));
                unit(direction)
                    .map(|_| arrow(Kind::JointLoad, label, direction))
                    .into_iter()
                    .collect()
            }
            Source::Load(i) => {
                let kind = match &problem.loads[i].kind {
                    LoadKind::Spring { .. } => Kind::Spring,
                    LoadKind::Damper { .. } => Kind::Damper,
                    LoadKind::Force { .. } | LoadKind::Torque { .. } => Kind::Load,
                    _ => Kind::JointLoad,
                };
                let direction = n.vector(value);
                let label = magnitude_symbol(&problem.loads[i].kind).map_or_else(
                    || Label::text(&action.label),
                    |e| Label::from_tex(&latex(&e)),
                );
                // A force that vanishes at this state has no direction to draw.
                unit(direction)
                    .map(|_| arrow(kind, label, direction))
                    .into_iter()
                    .collect()
            }
        }
    }

    /// The weight's symbol: the mass times the size of gravity, `m_{1} g`.
    fn weight_tex(&self, body: BodyId) -> String {
        let problem = self.problem();
        let mass = &problem.body(body).mass;
        if let Some([(_, _, c)]) = problem.gravity.as_ref().map(|g| g.terms.as_slice()) {
            let size = if self.numbers.scalar(c) < 0.0 {
                -c.clone()
            } else {
                c.clone()
            };
            return format!("{} {}", factor_tex(mass), factor_tex(&simplify(&size)));
        }
        format!("{} g", factor_tex(mass))
    }

    /// The kinetic diagram's `m a*` and `I α` (or the rate of angular momentum) of a body.
    fn inertia_arrows(&self, body: BodyId) -> Vec<Arrow> {
        if !self.accelerations {
            return Vec::new();
        }
        let n = self.numbers;
        let model = &self.derivation.model;
        let inertia = self.derivation.inertia();
        let name = latex_name(self.problem().body_name(body));
        let at = n.vector(&model.bodies[body.0].center.position);
        let at_id = point_id(self.problem(), PointRef::MassCenter(body));
        let mass = factor_tex(&model.bodies[body.0].mass);
        let force = scale(n.vector(&inertia.force[body.0]), -1.0);
        let torque = scale(n.vector(&inertia.torque[body.0]), -1.0);
        let mut out = Vec::new();
        let scale_of = force
            .iter()
            .chain(&torque)
            .fold(0.0f64, |m, x| m.max(x.abs()));
        if unit(force).is_some() && norm(force) > 1e-9 * scale_of {
            out.push(Arrow {
                kind: Kind::Inertia,
                label: Label::from_tex(&format!(
                    "{mass} \\mathbf{{a}}^{{{}}}",
                    crate::solution::tex::centre_tex(model, body)
                )),
                at_id: at_id.clone(),
                at,
                direction: force,
                couple: false,
            });
        }
        if unit(torque).is_some() && norm(torque) > 1e-9 * scale_of {
            // The moment of inertia named as in the tables of step 2, `I^A` (about A*).
            let tex = if model.is_planar() {
                format!("I^{{{name}}} \\alpha^{{{name}}}")
            } else {
                format!("\\dot{{\\mathbf{{H}}}}^{{{name}^{{*}}}}")
            };
            out.push(Arrow {
                kind: Kind::Inertia,
                label: Label::from_tex(&tex),
                at_id,
                at,
                direction: torque,
                couple: true,
            });
        }
        out
    }
}
