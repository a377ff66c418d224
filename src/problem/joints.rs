//! Reading the joints: names and coordinates first (they are names other sections use),
//! then parents, children, the tree, axes, sequences and positions.

use super::expressions::Context;
use super::graph::{self, Link, Orientation};
use super::json::{array, check_keys, index_path, key_path, object, required, string};
use super::model::*;
use super::names::{suggest, Kind};
use super::reader::{Owners, Reader};
use super::validate;
use serde_json::Value;

/// What is known of a joint after the first pass.
#[derive(Clone, Debug, Default)]
pub struct JointHead {
    /// The type, when it was valid.
    pub kind: Option<JointKind>,
    /// Its coordinates, as indices into the coordinate list.
    pub coordinates: Vec<usize>,
}

const TYPES: [JointKind; 8] = [
    JointKind::Revolute,
    JointKind::Prismatic,
    JointKind::Cylindrical,
    JointKind::Planar,
    JointKind::Universal,
    JointKind::Spherical,
    JointKind::Free,
    JointKind::Weld,
];

/// What each coordinate of a joint type measures, in order.
pub fn coordinate_kinds(kind: JointKind) -> &'static [CoordinateKind] {
    use CoordinateKind::{Angle as A, Distance as D};
    match kind {
        JointKind::Revolute => &[A],
        JointKind::Prismatic => &[D],
        JointKind::Cylindrical => &[D, A],
        JointKind::Planar => &[D, D, A],
        JointKind::Universal => &[A, A],
        JointKind::Spherical => &[A, A, A],
        JointKind::Free => &[D, D, D, A, A, A],
        JointKind::Weld => &[],
    }
}

fn coordinate_words(kind: JointKind) -> &'static str {
    match kind {
        JointKind::Revolute => "[angle]",
        JointKind::Prismatic => "[distance]",
        JointKind::Cylindrical => "[distance, angle]",
        JointKind::Planar => "[x, y, angle]",
        JointKind::Universal => "[angle 1, angle 2]",
        JointKind::Spherical => "[angle 1, angle 2, angle 3]",
        JointKind::Free => "[x, y, z, angle 1, angle 2, angle 3]",
        JointKind::Weld => "none",
    }
}

pub(super) fn has_axis(kind: JointKind) -> bool {
    matches!(
        kind,
        JointKind::Revolute | JointKind::Prismatic | JointKind::Cylindrical
    )
}

pub(super) fn has_sequence(kind: JointKind) -> bool {
    matches!(
        kind,
        JointKind::Universal | JointKind::Spherical | JointKind::Free
    )
}

/// Whether a joint (or closure) of this type may carry Coulomb friction: only a slider.
pub(super) fn has_friction(kind: JointKind) -> bool {
    kind == JointKind::Prismatic
}

/// What to do instead of friction on a joint that is not prismatic.
pub(super) const NO_FRICTION_HINT: &str = "Coulomb friction acts along a `prismatic` joint or closure, or at a `rolling`, `gear` or `contact` entry of `constraints`; remove `friction` here";

fn allowed_in_2d(kind: JointKind) -> bool {
    matches!(
        kind,
        JointKind::Revolute | JointKind::Prismatic | JointKind::Planar | JointKind::Weld
    )
}

impl Reader {
    /// First pass: every joint's name, type and coordinates, declaring the names.
    pub fn declare_joints(&mut self, values: &[Value]) -> (Vec<JointHead>, Owners) {
        let mut heads = Vec::new();
        let mut owners = Owners::new();
        for (i, value) in values.iter().enumerate() {
            let path = index_path("joints", i);
            let mut head = JointHead::default();
            let Some(fields) = object(value, &path, &mut self.diag) else {
                self.names.joints.push(String::new());
                heads.push(head);
                continue;
            };
            let name = required(fields, "name", &path, &mut self.diag)
                .and_then(|v| string(v, &key_path(&path, "name"), &mut self.diag));
            if let Some(name) = name {
                self.names
                    .declare(name, Kind::Joint, &key_path(&path, "name"), &mut self.diag);
            }
            let name = name.unwrap_or("");
            // A name that failed to declare is still kept, so that references to it do not
            // add a second error for the same mistake.
            self.names.joints.push(name.to_string());
            head.kind = required(fields, "type", &path, &mut self.diag)
                .and_then(|v| self.joint_type(v, &key_path(&path, "type")));
            self.check_joint_keys(fields, &path, head.kind);
            self.declare_coordinates(fields.get("coordinates"), &path, i, &mut head, &mut owners);
            heads.push(head);
        }
        (heads, owners)
    }

    pub(super) fn joint_type(&mut self, value: &Value, path: &str) -> Option<JointKind> {
        let name = string(value, path, &mut self.diag)?;
        if let Some(kind) = TYPES.iter().copied().find(|k| k.name() == name) {
            if self.dimension == Some(Dimension::Two) && !allowed_in_2d(kind) {
                self.diag.hint(
                    path,
                    format!("a {name} joint is only allowed in a 3D problem"),
                    "in 2D use revolute, prismatic, planar or weld, or set \"dimension\": 3",
                );
            }
            return Some(kind);
        }
        let names: Vec<&str> = TYPES.iter().map(|k| k.name()).collect();
        self.diag.hint(
            path,
            format!("unknown joint type `{name}`"),
            suggest(name, &names, "joint types"),
        );
        None
    }

    fn check_joint_keys(
        &mut self,
        fields: &serde_json::Map<String, Value>,
        path: &str,
        kind: Option<JointKind>,
    ) {
        let mut allowed = vec![
            "name",
            "type",
            "parent",
            "child",
            "coordinates",
            "at",
            "child_at",
        ];
        if kind.is_none_or(has_axis) {
            allowed.push("axis");
        }
        if kind.is_none_or(has_sequence) {
            allowed.push("sequence");
        }
        if kind.is_none_or(has_friction) {
            allowed.push("friction");
        }
        if kind.is_none_or(|k| k == JointKind::Revolute) {
            allowed.push("angle_from");
        }
        let Some(kind) = kind else {
            check_keys(fields, path, &allowed, &mut self.diag);
            return;
        };
        for key in ["axis", "sequence"] {
            if fields.contains_key(key) && !allowed.contains(&key) {
                let hint = if has_axis(kind) {
                    "this joint type takes an `axis`"
                } else if has_sequence(kind) {
                    "this joint type takes a `sequence`"
                } else {
                    "remove it"
                };
                self.diag.hint(
                    &key_path(path, key),
                    format!("a {} joint has no `{key}`", kind.name()),
                    hint,
                );
            }
        }
        if fields.contains_key("friction") && !has_friction(kind) {
            self.diag.hint(
                &key_path(path, "friction"),
                format!("a {} joint cannot have friction", kind.name()),
                NO_FRICTION_HINT,
            );
        }
        if fields.contains_key("angle_from") && kind != JointKind::Revolute {
            self.diag.hint(
                &key_path(path, "angle_from"),
                format!("a {} joint has no angle to measure from N", kind.name()),
                "only a revolute joint's angle may be measured from N; remove `angle_from`",
            );
        }
        let known: Vec<&str> = allowed
            .iter()
            .copied()
            .chain(["axis", "sequence", "friction", "angle_from"])
            .collect();
        let unknown: serde_json::Map<String, Value> = fields
            .iter()
            .filter(|(k, _)| !known.contains(&k.as_str()))
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect();
        check_keys(&unknown, path, &allowed, &mut self.diag);
    }

    /// A revolute joint's `angle_from`: N (an absolute angle, in a plane only) or its parent
    /// (the default, `None`).
    fn angle_from(&mut self, value: &Value, path: &str, parent: BodyId) -> Option<BodyId> {
        let from = self.body_ref(value, path)?;
        if from == parent {
            return None;
        }
        if from != BodyId::GROUND {
            self.diag.hint(
                path,
                format!("an angle is measured from N or from the parent, not from `{}`", self.names.bodies[from.0 - 1]),
                "write \"N\" for an absolute angle, or leave `angle_from` out for one relative to the parent",
            );
            return None;
        }
        if self.dimension != Some(Dimension::Two) {
            self.diag.hint(
                path,
                "an absolute angle is measured in a plane: in 3D a joint's angle is relative to its parent".to_string(),
                "remove `angle_from`, or make the problem 2D with \"dimension\": 2",
            );
            return None;
        }
        Some(from)
    }

    fn declare_coordinates(
        &mut self,
        value: Option<&Value>,
        path: &str,
        joint: usize,
        head: &mut JointHead,
        owners: &mut Owners,
    ) {
        let list_path = key_path(path, "coordinates");
        let items: &[Value] = match value {
            Some(v) => match array(v, &list_path, &mut self.diag) {
                Some(items) => items,
                None => return,
            },
            None => &[],
        };
        if let Some(kind) = head.kind {
            let wanted = kind.dof();
            if items.len() != wanted && (value.is_some() || wanted > 0) {
                let message = match (value, wanted) {
                    (None, _) => format!(
                        "`coordinates` is required: a {} joint has {wanted}",
                        kind.name()
                    ),
                    (Some(_), 0) => "a weld joint has no coordinates".to_string(),
                    (Some(_), 1) => format!(
                        "a {} joint has 1 coordinate, not {}",
                        kind.name(),
                        items.len()
                    ),
                    (Some(_), _) => format!(
                        "a {} joint has {wanted} coordinates, not {}",
                        kind.name(),
                        items.len()
                    ),
                };
                let hint = format!("{}: {}", kind.name(), coordinate_words(kind));
                self.diag.hint(&list_path, message, hint);
            }
        }
        let kinds = head.kind.map(coordinate_kinds).unwrap_or(&[]);
        for (k, item) in items.iter().enumerate() {
            let item_path = index_path(&list_path, k);
            let Some(name) = string(item, &item_path, &mut self.diag) else {
                continue;
            };
            if let Some(existing) = self.names.coordinate(name) {
                let (owner, _, _) = owners[existing];
                let owner_name = self.names.joints.get(owner).cloned().unwrap_or_default();
                let message = if owner == joint {
                    format!("the coordinate `{name}` is listed twice")
                } else {
                    format!("the coordinate `{name}` already belongs to joint `{owner_name}` (joints[{owner}])")
                };
                self.diag.hint(
                    &item_path,
                    message,
                    "each coordinate belongs to exactly one joint; give this one its own name",
                );
                continue;
            }
            if self
                .names
                .declare(name, Kind::Coordinate, &item_path, &mut self.diag)
            {
                let kind = kinds.get(k).copied().unwrap_or(CoordinateKind::Angle);
                owners.push((joint, k, kind));
                head.coordinates.push(owners.len() - 1);
            }
        }
    }

    /// Second pass: parents and children (and the tree they form), axes, sequences, positions.
    pub fn joints(&mut self, values: &[Value], heads: &[JointHead]) -> Vec<Joint> {
        let mut links = vec![Link::default(); values.len()];
        for (i, value) in values.iter().enumerate() {
            let path = index_path("joints", i);
            let Some(fields) = value.as_object() else {
                continue;
            };
            links[i].kind = heads[i].kind;
            let body = |key: &str, r: &mut Reader| {
                required(fields, key, &path, &mut r.diag)
                    .and_then(|v| r.body_ref(v, &key_path(&path, key)))
            };
            links[i].parent = body("parent", self);
            links[i].child = body("child", self);
        }
        graph::check_tree(&links, &self.names, &mut self.diag);
        self.orientation = Some(Orientation::new(self.names.bodies.len(), &links));

        let mut joints = Vec::new();
        for (i, value) in values.iter().enumerate() {
            let path = index_path("joints", i);
            let (parent, child) = (
                links[i].parent.unwrap_or(BodyId::GROUND),
                links[i].child.unwrap_or(BodyId::GROUND),
            );
            let kind = heads[i].kind.unwrap_or(JointKind::Weld);
            let mut joint = Joint {
                name: self.names.joints[i].clone(),
                kind,
                parent,
                child,
                coordinates: heads[i].coordinates.clone(),
                axis: None,
                sequence: Vec::new(),
                at: VectorExpr::default(),
                child_at: VectorExpr::default(),
                friction: None,
                angle_from: None,
                path: path.clone(),
            };
            if let Some(fields) = value.as_object() {
                if kind == JointKind::Revolute {
                    if let Some(v) = fields.get("angle_from") {
                        joint.angle_from =
                            self.angle_from(v, &key_path(&path, "angle_from"), parent);
                    }
                }
                if heads[i].kind.is_some_and(has_friction) {
                    joint.friction = self.friction(fields, &path);
                }
                if heads[i].kind.is_some_and(has_axis) {
                    joint.axis =
                        self.axis(fields.get("axis"), &key_path(&path, "axis"), kind, parent);
                }
                if heads[i].kind.is_some_and(has_sequence) {
                    joint.sequence =
                        self.sequence(fields.get("sequence"), &key_path(&path, "sequence"), kind);
                }
                for (key, body, slot) in [
                    ("at", parent, &mut joint.at),
                    ("child_at", child, &mut joint.child_at),
                ] {
                    let key_path = key_path(&path, key);
                    if let Some(v) = fields
                        .get(key)
                        .and_then(|v| self.position(v, &key_path, body, "the joint's point"))
                    {
                        validate::vector(&v, &self.values, &key_path, &mut self.diag);
                        *slot = v;
                    }
                }
            }
            joints.push(joint);
        }
        joints
    }

    /// The axis, fixed in the parent; in 2D a revolute axis is along z and a prismatic
    /// one in the plane. A 2D revolute joint without an axis turns about `N.z`.
    pub(super) fn axis(
        &mut self,
        value: Option<&Value>,
        path: &str,
        kind: JointKind,
        parent: BodyId,
    ) -> Option<VectorExpr> {
        let two_d = self.dimension == Some(Dimension::Two);
        let Some(value) = value else {
            if two_d && kind == JointKind::Revolute {
                return Some(VectorExpr {
                    terms: vec![(BodyId::GROUND, 2, crate::symbolic::Expr::one())],
                });
            }
            if self.dimension.is_none() && kind == JointKind::Revolute {
                // Maybe a 2D problem with a mistyped dimension: that error is enough.
                return None;
            }
            self.diag.hint(
                path,
                format!("a {} joint needs an `axis`", kind.name()),
                format!(
                    "a direction fixed in the parent, e.g. \"{}.z\"",
                    self.names.body_name(parent)
                ),
            );
            return None;
        };
        let axis = self.vector(value, path, Context::constant("an axis"))?;
        let before = self.diag.errors.len();
        self.fixed_in(&axis, parent, path, "the axis");
        if two_d && kind == JointKind::Revolute {
            if let Some((frame, a, _)) = axis.terms.iter().find(|(_, a, _)| *a != 2) {
                let f = format!(
                    "{}.{}",
                    self.names.body_name(*frame),
                    ["x", "y", "z"][usize::from(*a).min(2)]
                );
                self.diag.hint(
                    path,
                    format!("in a 2D problem a revolute axis is along z, but this one has a `{f}` component"),
                    "write \"N.z\" (or leave the axis out, which means N.z)",
                );
            }
        } else {
            self.in_plane(&axis, path, "a prismatic axis");
        }
        if self.diag.errors.len() == before {
            validate::axis(&axis, &self.values, path, &mut self.diag);
        }
        Some(axis)
    }

    pub(super) fn sequence(
        &mut self,
        value: Option<&Value>,
        path: &str,
        kind: JointKind,
    ) -> Vec<u8> {
        let length = if kind == JointKind::Universal { 2 } else { 3 };
        let example = if length == 2 { "\"xy\"" } else { "\"zxy\"" };
        let Some(value) = value else {
            self.diag.hint(
                path,
                format!("a {} joint needs a `sequence`", kind.name()),
                format!("the body-fixed rotation axes, e.g. {example}"),
            );
            return Vec::new();
        };
        let Some(text) = string(value, path, &mut self.diag) else {
            return Vec::new();
        };
        let mut axes = Vec::new();
        for (column, c) in text.chars().enumerate() {
            match "xyz".find(c) {
                Some(a) => axes.push(a as u8),
                None => {
                    self.diag.push(
                        path,
                        Some(column + 1),
                        format!("`{c}` is not an axis"),
                        Some("the letters are x, y and z"),
                    );
                    return Vec::new();
                }
            }
        }
        if axes.len() != length {
            let letters = if length == 2 { "two" } else { "three" };
            self.diag.hint(
                path,
                format!(
                    "a {} joint's sequence has {letters} letters, not {}",
                    kind.name(),
                    axes.len()
                ),
                format!("e.g. {example}"),
            );
            return Vec::new();
        }
        if let Some(k) = axes.windows(2).position(|w| w[0] == w[1]) {
            self.diag.push(
                path,
                Some(k + 2),
                format!(
                    "two rotations in a row about the same axis `{}`",
                    &text[k..k + 1]
                ),
                Some(format!("neighbouring letters must differ, e.g. {example}")),
            );
            return Vec::new();
        }
        axes
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_type_has_as_many_kinds_as_coordinates() {
        for kind in TYPES {
            assert_eq!(coordinate_kinds(kind).len(), kind.dof(), "{}", kind.name());
        }
    }
}
