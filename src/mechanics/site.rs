//! What a site is: a place where a parent exerts a reaction on a child (a joint of the
//! tree, a closure or a rolling contact), and a rolling contact's geometry. Built in
//! [`super::sites`].

use super::joints::ReactionComponent;
use super::point::PointMotion;
use super::vector::{Components, Vector};
use crate::problem::BodyId;
use crate::symbolic::{Expr, Relation};

/// What a site is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SiteKind {
    /// A joint of the tree, by index into `Problem::joints`.
    Joint(usize),
    /// A closure, by index into `Problem::closures`.
    Closure(usize),
    /// A rolling contact, by index into `Problem::constraints`.
    Contact(usize),
}

/// A place where the parent exerts a reaction on the child.
#[derive(Clone, Debug)]
pub struct Site {
    /// The joint's, closure's or contact's name.
    pub name: String,
    /// What it is.
    pub kind: SiteKind,
    /// The body exerting the reaction (`N` for a contact).
    pub parent: BodyId,
    /// The body it acts on.
    pub child: BodyId,
    /// The point on the child, from its origin in its unit vectors (for a contact it
    /// moves over the body as it turns).
    pub child_offset: Components,
    /// The parent's material point there, from its origin in its unit vectors.
    pub parent_offset: Components,
    /// The motion of the child's material point at the site.
    pub point: PointMotion,
    /// The reaction components, each an unknown of the site (`O.Fx`).
    pub reactions: Vec<ReactionComponent>,
    /// The directions of the loop rows that no reaction enforces (across a light rod, see
    /// `super::light_rod`), by the rows' component index.
    pub across: Vec<(usize, Vector)>,
}

/// The geometry of a rolling contact: where it is and which ways it holds the disc.
#[derive(Clone, Debug)]
pub struct Contact {
    /// The contact point from the body's origin, in the body's unit vectors.
    pub offset: Components,
    /// The height of the centre above the plane minus what the disc's tilt allows; zero
    /// when the disc touches the plane.
    pub height: Expr,
    /// `|n − (n·a) a|`, the sine of the angle between the axle and the normal: the contact
    /// is undefined where it is zero.
    pub tilt: Expr,
    /// A relation the contact's rows are written with, which holds wherever its height is
    /// zero: a gear's unit line of centres has unit length there (`x² + y² = (R − r)²`
    /// inside a ring), so its no-slip row reads `r θ̇` rather than
    /// `r (x² + y²)/(R − r)² θ̇`. `None` for a plane's contact, whose normal is a unit
    /// vector everywhere.
    pub on_motion: Option<Relation>,
}
