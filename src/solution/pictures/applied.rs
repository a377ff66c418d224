//! What the configuration shows beyond the bodies: the forces and couples the problem
//! applies, and the bodies each marked point belongs to.

use super::build::Setting;
use crate::plan::Source;
use crate::problem::{BodyId, LoadKind};
use crate::render::draw::{Arrow, Kind, Label, Marker, Role, Shape};
use crate::symbolic::latex;

impl Setting<'_, '_, '_> {
    /// The forces the problem applies (a pull), as the statement's figure shows them: each
    /// once, on the body it acts on, the way it acts (a drive's couple is left to the free
    /// body, where it does not crowd the axle's names).
    pub(super) fn applied(&self, markers: &mut Vec<Marker>) -> Vec<Arrow> {
        let problem = self.problem();
        let mut seen = Vec::new();
        let mut out = Vec::new();
        for action in &self.derivation.actions {
            let Source::Load(i) = action.source else {
                continue;
            };
            let applied = matches!(problem.loads[i].kind, LoadKind::Force { .. });
            if applied && !seen.contains(&i) {
                seen.push(i);
                out.extend(self.action_arrows(action, markers));
            }
        }
        out
    }

    /// The angle of each applied force written by its size and angle (a rope's pull `P`
    /// at `β` above the rod): an arc at its point from the line the angle is measured
    /// from (dashed) to the force, named by the angle's symbol.
    pub(super) fn load_angles(&self) -> Vec<Shape> {
        use super::numbers::{add, cross, scale, unit};
        use crate::plan::ActionKind;
        let n = self.numbers;
        let problem = self.problem();
        let mut seen = Vec::new();
        let mut out = Vec::new();
        for action in &self.derivation.actions {
            let (Source::Load(i), ActionKind::Force { offset, .. }) = (action.source, &action.kind)
            else {
                continue;
            };
            let Some(polar) = super::load_symbols::polar(&problem.loads[i].kind) else {
                continue;
            };
            if seen.contains(&i) {
                continue;
            }
            seen.push(i);
            let axis_of = |k: u8| {
                let mut e = [0.0; 3];
                e[usize::from(k)] = 1.0;
                n.in_ground(polar.frame, &e)
            };
            let (from, toward) = (axis_of(polar.axes.0), axis_of(polar.axes.1));
            let Some(axis) = unit(cross(from, toward)) else {
                continue;
            };
            let center = n.point_on(action.body, &n.local(offset));
            out.push(Shape::Dashed {
                from: center,
                to: add(center, scale(from, 0.3 * self.size)),
            });
            out.push(Shape::Angle {
                center,
                from,
                axis,
                angle: n.scalar(&polar.angle),
                label: Label::from_tex(&latex(&polar.angle)),
            });
        }
        out
    }

    /// The blows of an impact, each an arrow at the point struck, the way it acts,
    /// labelled by its impulse's symbol (`J`) where it is one constant times a unit vector,
    /// else by its name; none for an impulsive couple alone.
    pub(super) fn blows(&self, markers: &mut Vec<Marker>) -> Vec<Arrow> {
        use crate::mechanics::{own_components, vector_of};
        use crate::problem::ForcePoint;
        let n = self.numbers;
        let problem = self.problem();
        let Some(impact) = problem.impact.as_ref() else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for (i, blow) in impact.impulses.iter().enumerate() {
            let Some(linear) = blow.linear.as_ref() else {
                continue;
            };
            let at = match &blow.point {
                ForcePoint::Point(p) => n.vector(&self.derivation.model.position(*p)),
                ForcePoint::Offset(v) => {
                    n.point_on(blow.body, &n.local(&own_components(v, blow.body)))
                }
            };
            let direction = n.vector(&vector_of(linear));
            if super::numbers::norm(direction) < 1e-12 {
                continue;
            }
            let label = match linear.terms.as_slice() {
                [(_, _, c)] if c.as_symbol().is_some() => {
                    Label::from_tex(&crate::symbolic::latex(c))
                }
                _ => Label::from_tex(&format!("\\text{{{}}}", blow.name)),
            };
            let id = format!("at-blow-{}", i + 1);
            markers.push(Marker {
                id: id.clone(),
                at,
                role: Role::Point,
                caption: None,
                on: self.names(&[blow.body]),
            });
            out.push(Arrow {
                kind: Kind::Load,
                label,
                at_id: id,
                at,
                direction,
                couple: false,
            });
        }
        out
    }

    /// The names of `bodies`, `N` left out (it has no shape to keep out of).
    pub(super) fn names(&self, bodies: &[BodyId]) -> Vec<String> {
        (bodies.iter())
            .filter(|b| **b != BodyId::GROUND)
            .map(|b| self.problem().body_name(*b).to_string())
            .collect()
    }
}
