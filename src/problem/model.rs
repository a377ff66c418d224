//! The validated problem: names resolved to typed ids, expressions parsed.
//!
//! Everything here has passed validation, so later stages can index without checks.
//! Each item keeps the JSON path it came from, so later stages can still point at it.

use crate::symbolic::Expr;

/// A body, as an index: `BodyId::GROUND` is `N`, the declared bodies follow in file order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct BodyId(pub usize);

impl BodyId {
    /// The Newtonian body and frame `N`.
    pub const GROUND: BodyId = BodyId(0);
}

/// Planar (`2`) or spatial (`3`) motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dimension {
    /// Motion in the plane of `N.x` and `N.y`.
    Two,
    /// Spatial motion.
    Three,
}

/// A vector written as a sum of scalar expressions times unit vectors of body frames.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct VectorExpr {
    /// `(frame, axis 0..3 for x y z, coefficient)`, in the order written, like frames merged.
    pub terms: Vec<(BodyId, u8, Expr)>,
}

/// A named constant with its value (before any `--set`).
#[derive(Clone, Debug, PartialEq)]
pub struct Constant {
    /// The name expressions use.
    pub name: String,
    /// The value, in the problem's units.
    pub value: f64,
    /// The unit as written (`m/s^2`), if given.
    pub unit: Option<String>,
    /// What it is, in the statement's words, if given.
    pub description: Option<String>,
    /// The range a randomized variant draws the value from.
    pub vary: Option<super::vary::Vary>,
}

/// What a coordinate measures.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoordinateKind {
    /// An angle in radians.
    Angle,
    /// A distance.
    Distance,
}

/// A generalized coordinate, in the order the joints first name them.
#[derive(Clone, Debug, PartialEq)]
pub struct Coordinate {
    /// The name expressions use (`theta`; its rates `theta'`, `theta''`).
    pub name: String,
    /// Initial value (default 0).
    pub initial: f64,
    /// Initial rate (default 0).
    pub rate: f64,
    /// `initial` when written as an expression of constants; `--set` evaluates it again.
    pub initial_expr: Option<Expr>,
    /// `rate` when written as an expression of constants; `--set` evaluates it again.
    pub rate_expr: Option<Expr>,
    /// The unit as written, if given.
    pub unit: Option<String>,
    /// What it measures, in the statement's words, if given.
    pub description: Option<String>,
    /// The joint that owns it, as an index into [`Problem::joints`](super::Problem::joints).
    pub joint: usize,
    /// Its position among that joint's coordinates.
    pub index_in_joint: usize,
    /// An angle or a distance, from the joint's type.
    pub kind: CoordinateKind,
    /// Marked `dependent`: solved from the position constraints (its `initial` is a guess).
    pub dependent: bool,
    /// Marked `dependent_rate`: its rate is solved from the velocity constraints.
    pub dependent_rate: bool,
    /// A prescribed motion `q(t)` (constants and `t`): then not a degree of freedom.
    pub motion: Option<Expr>,
    /// The name its drive goes by in the statement (`drive.symbol`, e.g. `tau_m`).
    pub drive_symbol: Option<String>,
    /// Marked `held`: kept at its initial value by a support (then `motion` is that
    /// constant value, and the support's generalized force is its drive).
    pub held: bool,
}

/// The central inertia of a body.
#[derive(Clone, Debug, PartialEq)]
pub enum Inertia {
    /// 2D: the moment of inertia about the axis through the mass center parallel to `N.z`.
    Planar(Expr),
    /// 3D: the symmetric matrix of the inertia dyadic in the body's unit vectors,
    /// `[[xx, xy, zx], [xy, yy, yz], [zx, yz, zz]]`.
    Spatial([[Expr; 3]; 3]),
}

/// A rigid body.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// The name, also its frame's (`A.x`) and its mass centre's (`A*`).
    pub name: String,
    /// The mass, a scalar of constants.
    pub mass: Expr,
    /// The mass center from the body's origin, in the body's unit vectors.
    pub center: VectorExpr,
    /// The central inertia.
    pub inertia: Inertia,
    /// What it is, in the statement's words, if given.
    pub description: Option<String>,
    /// How pictures draw it (`shape`); the mechanics never read it.
    pub shape: Option<BodyShape>,
    /// The JSON path, e.g. `bodies.A`.
    pub path: String,
}

/// A body's `shape`: positions from the body's origin in its own unit vectors, lengths of
/// constants.
#[derive(Clone, Debug, PartialEq)]
pub enum BodyShape {
    /// A bar between two points.
    Rod {
        /// One end.
        from: VectorExpr,
        /// The other end.
        to: VectorExpr,
    },
    /// A disc seen end-on; `center` defaults to the mass centre, `axis` to the body's z.
    Disc {
        /// The radius, a scalar of constants.
        radius: Expr,
        /// The centre, if not the mass centre.
        center: Option<VectorExpr>,
        /// The axle, if not the body's z.
        axis: Option<VectorExpr>,
    },
    /// A rectangle (a box in 3D) with sides along the body's x, y (and z).
    Block {
        /// The side lengths along x, y (and z).
        size: Vec<Expr>,
        /// The centre.
        center: VectorExpr,
    },
    /// A ball at the mass centre.
    Particle,
    /// A plate through the points.
    Polygon {
        /// The corners, in order around the plate.
        points: Vec<VectorExpr>,
    },
}

/// The joint types of the format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointKind {
    /// A turn about a fixed axis: one angle.
    Revolute,
    /// A slide along a fixed axis: one distance.
    Prismatic,
    /// A slide along and a turn about one axis: a distance, then an angle.
    Cylindrical,
    /// In-plane motion: two distances and an angle.
    Planar,
    /// Two successive turns about body-fixed axes (`sequence`): two angles.
    Universal,
    /// Three successive turns about body-fixed axes (`sequence`): three angles.
    Spherical,
    /// Three distances, then three successive turns: six coordinates.
    Free,
    /// No relative motion: no coordinate.
    Weld,
}

impl JointKind {
    /// How many coordinates the joint has.
    pub fn dof(self) -> usize {
        match self {
            JointKind::Revolute | JointKind::Prismatic => 1,
            JointKind::Cylindrical | JointKind::Universal => 2,
            JointKind::Planar | JointKind::Spherical => 3,
            JointKind::Free => 6,
            JointKind::Weld => 0,
        }
    }

    /// The name as written in a problem.
    pub fn name(self) -> &'static str {
        match self {
            JointKind::Revolute => "revolute",
            JointKind::Prismatic => "prismatic",
            JointKind::Cylindrical => "cylindrical",
            JointKind::Planar => "planar",
            JointKind::Universal => "universal",
            JointKind::Spherical => "spherical",
            JointKind::Free => "free",
            JointKind::Weld => "weld",
        }
    }
}

/// A joint between a parent and its outboard child.
#[derive(Clone, Debug, PartialEq)]
pub struct Joint {
    /// The name, also its point on the child.
    pub name: String,
    /// The type.
    pub kind: JointKind,
    /// The inboard body (`N` for the ground).
    pub parent: BodyId,
    /// The outboard body, which the joint's coordinates move.
    pub child: BodyId,
    /// Indices into [`Problem::coordinates`](super::Problem::coordinates), in the joint's order.
    pub coordinates: Vec<usize>,
    /// Revolute, prismatic, cylindrical: the axis as written (not yet normalized), in any frame.
    pub axis: Option<VectorExpr>,
    /// Universal, spherical, free: the body-fixed rotation axes, 0 1 2 for x y z.
    pub sequence: Vec<u8>,
    /// The joint's point on the parent, from the parent's origin in its unit vectors.
    pub at: VectorExpr,
    /// The joint's point on the child, from the child's origin in its unit vectors.
    pub child_at: VectorExpr,
    /// Prismatic: the coefficient of Coulomb friction μ ≥ 0 along the axis, a scalar of
    /// constants; `None` for a smooth slider.
    pub friction: Option<Expr>,
    /// Revolute in a plane: `Some(N)` when its angle is measured from N's axes (an absolute
    /// angle) rather than from the parent's; `None` for the parent's.
    pub angle_from: Option<BodyId>,
    /// The JSON path, e.g. `joints[1]`.
    pub path: String,
}

/// A point that a load or a point definition can name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointRef {
    /// A declared point, as an index into [`Problem::points`](super::Problem::points).
    Named(usize),
    /// `A*`, the mass center of a body.
    MassCenter(BodyId),
    /// `A.o`, the origin of a body (`N.o` the fixed origin).
    Origin(BodyId),
    /// A joint's name: its point on the child.
    Joint(usize),
}

/// A point fixed on a body.
#[derive(Clone, Debug, PartialEq)]
pub struct PointDef {
    /// The name forces and springs use.
    pub name: String,
    /// The body it is fixed on.
    pub on: BodyId,
    /// From the body's origin, in its unit vectors.
    pub at: VectorExpr,
}

/// Where a force acts on its body.
#[derive(Clone, Debug, PartialEq)]
pub enum ForcePoint {
    /// A named point (declared, `A*`, `A.o` or a joint).
    Point(PointRef),
    /// A point given from the body's origin in its unit vectors.
    Offset(VectorExpr),
}

/// What a load does.
#[derive(Clone, Debug, PartialEq)]
pub enum LoadKind {
    /// A force applied at a point of a body.
    Force {
        /// The body it acts on.
        on: BodyId,
        /// Where it acts.
        at: ForcePoint,
        /// The force.
        vector: VectorExpr,
    },
    /// A couple on a body, and its opposite on `reaction_on` if given.
    Torque {
        /// The body it acts on.
        on: BodyId,
        /// The couple's moment.
        vector: VectorExpr,
        /// The body that takes the opposite couple, if any.
        reaction_on: Option<BodyId>,
    },
    /// A linear spring between two points.
    Spring {
        /// Its ends.
        between: [PointRef; 2],
        /// Its stiffness k.
        stiffness: Expr,
        /// Its free length.
        free_length: Expr,
    },
    /// A linear damper between two points.
    Damper {
        /// Its ends.
        between: [PointRef; 2],
        /// Its damping coefficient c.
        coefficient: Expr,
    },
    /// A spring along one coordinate of a joint; `coordinate` indexes
    /// [`Problem::coordinates`](super::Problem::coordinates).
    JointSpring {
        /// The joint, by index.
        joint: usize,
        /// The coordinate it acts along, by index.
        coordinate: usize,
        /// Its stiffness.
        stiffness: Expr,
        /// The coordinate's value at which it is relaxed.
        rest: Expr,
    },
    /// A damper along one coordinate of a joint.
    JointDamper {
        /// The joint, by index.
        joint: usize,
        /// The coordinate it acts along, by index.
        coordinate: usize,
        /// Its damping coefficient.
        coefficient: Expr,
    },
    /// A given generalized force along one coordinate of a joint (a motor's torque).
    JointActuator {
        /// The joint, by index.
        joint: usize,
        /// The coordinate it acts along, by index.
        coordinate: usize,
        /// The force or torque, of constants, coordinates, rates and `t`.
        value: Expr,
    },
}

/// A load with its optional name.
#[derive(Clone, Debug, PartialEq)]
pub struct Load {
    /// The name, if given.
    pub name: Option<String>,
    /// What it does.
    pub kind: LoadKind,
    /// The JSON path, e.g. `loads[2]`.
    pub path: String,
}

/// The `simulate` settings.
#[derive(Clone, Debug, PartialEq)]
pub struct SimulateSettings {
    /// Seconds; default 5.
    pub duration: f64,
    /// Seconds between output rows; default 0.01.
    pub output_step: f64,
    /// The integrator's tolerance; default 1e-9.
    pub tolerance: f64,
}

impl Default for SimulateSettings {
    fn default() -> Self {
        SimulateSettings {
            duration: 5.0,
            output_step: 0.01,
            tolerance: 1e-9,
        }
    }
}

/// A declared generalized speed (`speeds`): `u = equals`, linear in the first rates with
/// coefficients of constants and coordinates (a row of `W` in `u = W(q) q'`).
#[derive(Clone, Debug, PartialEq)]
pub struct Speed {
    /// The name (`u1`; its rate `u1'`).
    pub name: String,
    /// The speed as a combination of the coordinates' first rates.
    pub equals: Expr,
    /// The unit as written, if given.
    pub unit: Option<String>,
    /// What it measures, in the statement's words, if given.
    pub description: Option<String>,
    /// The JSON path, e.g. `speeds.u1`.
    pub path: String,
}

/// Where a disc's centre is on its body.
#[derive(Clone, Debug, PartialEq)]
pub enum ConstraintKind {
    /// A thin disc on `body` rolling without slipping on a plane fixed in `on` (`N` or a
    /// moving body).
    Rolling {
        /// The disc's body.
        body: BodyId,
        /// The body the plane is fixed in.
        on: BodyId,
        /// The disc's radius.
        radius: Expr,
        /// The axle, fixed in the body (as written, not yet normalized).
        axis: VectorExpr,
        /// The disc's centre.
        center: ForcePoint,
        /// The plane's normal, fixed in `on` (as written).
        normal: VectorExpr,
        /// The plane's distance from `on`'s origin along the normal.
        offset: Expr,
    },
    /// Two discs with parallel axles rolling on each other without slipping: `body`'s disc
    /// on `on`'s, outside it or (`internal`) inside it.
    Gear {
        /// The body of the disc that rolls.
        body: BodyId,
        /// Its pitch radius.
        radius: Expr,
        /// Its centre.
        center: ForcePoint,
        /// The body of the disc it rolls on.
        on: BodyId,
        /// That disc's pitch radius.
        on_radius: Expr,
        /// That disc's centre.
        on_center: ForcePoint,
        /// Inside `on`'s disc (a ring gear) rather than outside it.
        internal: bool,
        /// The common axle, fixed in `body` (as written); `None` in 2D (N.z).
        axis: Option<VectorExpr>,
    },
    /// A point of `body` that stays on a plane fixed in `on` and may slide on it.
    Contact {
        /// The body that touches the plane.
        body: BodyId,
        /// The point that touches the plane.
        point: ForcePoint,
        /// The body the plane is fixed in.
        on: BodyId,
        /// The plane's normal, fixed in `on` (as written).
        normal: VectorExpr,
        /// The plane's distance from `on`'s origin along the normal.
        offset: Expr,
    },
    /// `expression = 0`, of constants, coordinates and `t`.
    Position {
        /// The expression that stays zero.
        expression: Expr,
    },
    /// `expression = 0`, affine in the first rates.
    Velocity {
        /// The expression that stays zero.
        expression: Expr,
    },
}

/// An entry of `constraints`.
#[derive(Clone, Debug, PartialEq)]
pub struct Constraint {
    /// The name, also its site's.
    pub name: String,
    /// What it constrains.
    pub kind: ConstraintKind,
    /// The coefficient of Coulomb friction μ ≥ 0 (a `rolling`, `gear` or `contact`), a
    /// scalar of constants; `None` for a contact that never slips (`rolling`, `gear`) or
    /// is smooth (`contact`).
    pub friction: Option<Expr>,
    /// The JSON path, e.g. `constraints[0]`.
    pub path: String,
}
