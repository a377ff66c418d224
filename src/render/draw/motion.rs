//! The simulated motion as `draw --animate` writes it: each body drawn once on one or more
//! *sheets*, planes fixed in the body, in metres, and where every sheet, point, spring,
//! damper and coordinate's mark is at each frame. The orthographic picture of a plane moving
//! rigidly is an affine map of it, so each frame's map of a sheet is exact (a disc's rim is
//! the ellipse it projects to), and [`super::motion_svg`] writes it as four
//! `animateTransform`s.

use super::numbers::P3;
use super::picture::Projection;
use super::scene::{BodyKind, Label};

/// What is drawn on a sheet, in the sheet's coordinates (metres).
#[derive(Clone, Debug, PartialEq)]
pub enum Part {
    /// A wheel: the disc of `radius` about `center`, lightly filled, with spokes, the dark
    /// one towards the unit `mark`, so that it is seen to turn.
    Wheel {
        /// The centre.
        center: [f64; 2],
        /// The radius.
        radius: f64,
        /// The unit direction of the dark spoke.
        mark: [f64; 2],
    },
    /// A rod: a thick line through the points.
    Bar(Vec<[f64; 2]>),
    /// A light rod to a particle: a thin line.
    Line([f64; 2], [f64; 2]),
    /// A closed outline, lightly filled: a block, a plate, a disc's rim.
    Outline(Vec<[f64; 2]>),
}

/// A plane fixed in a body, in its own unit vectors, and what is drawn on it.
#[derive(Clone, Debug, PartialEq)]
pub struct Sheet {
    /// The body it belongs to (an index into [`Motion::bodies`]).
    pub body: usize,
    /// The sheet's origin, from the body's origin.
    pub origin: P3,
    /// The sheet's two unit vectors.
    pub axes: [P3; 2],
    /// What is drawn on it.
    pub parts: Vec<Part>,
}

/// A body as the motion draws it: `<g class="body" id="body-NAME" data-shape="KIND">`
/// around its sheets.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// Its name.
    pub name: String,
    /// What it is drawn as.
    pub kind: BodyKind,
    /// A ball at a marked point (an index into [`Motion::points`], its mass centre): a
    /// particle, drawn round whichever way the body turns.
    pub ball: Option<usize>,
}

/// A coordinate's mark at one frame, in `N`, as the still picture draws it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Gauge {
    /// An angle: an arc about `center` from the unit `from`, turning by `angle` about the
    /// unit `axis`, and a dashed reference line `reference` long along `from`.
    Angle {
        /// The arc's centre.
        center: P3,
        /// The unit direction the angle is measured from.
        from: P3,
        /// The unit axis it turns about.
        axis: P3,
        /// The angle, in radians.
        angle: f64,
        /// The length of the dashed reference line.
        reference: f64,
    },
    /// A distance: a dimension line from `from` to `to`, drawn on the side of the unit
    /// `along` (the coordinate's own direction, so the line keeps its side when the
    /// distance passes zero).
    Distance {
        /// Where the distance starts.
        from: P3,
        /// Where it ends.
        to: P3,
        /// The unit side the line is drawn on.
        along: P3,
    },
}

/// Where everything is at one frame, in `N`.
#[derive(Clone, Debug, PartialEq)]
pub struct Placed {
    /// The time.
    pub t: f64,
    /// Per sheet: its origin and its two unit vectors.
    pub sheets: Vec<[P3; 3]>,
    /// Per marked point (see [`Motion::points`]).
    pub points: Vec<P3>,
    /// Per spring: its ends.
    pub springs: Vec<[P3; 2]>,
    /// Per damper: its ends.
    pub dampers: Vec<[P3; 2]>,
    /// Per coordinate's mark (see [`Motion::gauges`]).
    pub gauges: Vec<Gauge>,
}

/// The whole motion, ready to write.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    /// The problem's title.
    pub title: String,
    /// The bodies as drawn.
    pub bodies: Vec<Body>,
    /// Their sheets, in the order of the bodies.
    pub sheets: Vec<Sheet>,
    /// The ids of the marked points (`cm-B`, `joint-J`) and whether each is a mass centre.
    pub points: Vec<(String, bool)>,
    /// Per marked point, the words that follow it: a body's name beside its mass centre,
    /// a joint's coordinates that no mark shows beside the joint.
    pub captions: Vec<Option<String>>,
    /// The pins and balls fixed to `N` (ids into `points`), drawn with a support, each
    /// with the unit direction towards the body it carries (the support is on the other
    /// side).
    pub grounded: Vec<(usize, P3)>,
    /// Rolling contacts' points (ids into `points`), whose track is drawn on the ground.
    pub rolling: Vec<usize>,
    /// The floors fixed in `N` that bodies roll on in 3D: each a parallelogram (its
    /// corners in order) around every contact of the whole motion.
    pub floors: Vec<[P3; 4]>,
    /// The fixed round tracks that bodies roll in or on (a cylinder seen end-on): each
    /// its rim's points, drawn whole with the ground.
    pub rims: Vec<Vec<P3>>,
    /// The coordinates' marks' labels, one per mark of [`Placed::gauges`].
    pub gauges: Vec<Label>,
    /// Per spring: its lane beside the others between the same points (the solution
    /// stage gives each its lane).
    pub spring_lanes: Vec<f64>,
    /// Per damper: its lane, likewise.
    pub damper_lanes: Vec<f64>,
    /// The frames.
    pub frames: Vec<Placed>,
    /// The map to the picture, chosen so that the whole motion fits.
    pub projection: Projection,
    /// The picture's size.
    pub size: [f64; 2],
}

/// The title's strip above the picture.
pub const TITLE_STRIP: f64 = 24.0;
