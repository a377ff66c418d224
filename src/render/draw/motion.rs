//! The simulated motion as `draw --animate` writes it: each body drawn once on a *sheet*,
//! a plane fixed in the body, in metres, and where every sheet, point, spring and damper is
//! at each frame. The orthographic picture of a plane moving rigidly is an affine map of
//! it, so each frame's map of the sheet is exact, and [`super::motion_svg`] writes it as
//! four `animateTransform`s.

use super::numbers::P3;
use super::picture::Projection;
use crate::problem::BodyId;

/// What a body is drawn as on its sheet.
#[derive(Clone, Debug, PartialEq)]
pub enum Look {
    /// A wheel of this radius about the sheet's origin, with spokes that show it turning.
    Disc(f64),
    /// Rods from the mass centre to each of the body's points (sheet coordinates).
    Rods {
        center: [f64; 2],
        points: Vec<[f64; 2]>,
    },
    /// A ball at the sheet's origin (the mass centre), with light rods to these points.
    Particle { rods: Vec<[f64; 2]> },
}

/// A plane fixed in a body, in its own unit vectors, and what is drawn on it.
#[derive(Clone, Debug, PartialEq)]
pub struct Sheet {
    /// The body.
    pub body: BodyId,
    /// Its name.
    pub name: String,
    /// The sheet's origin, from the body's origin.
    pub origin: P3,
    /// The sheet's two unit vectors.
    pub axes: [P3; 2],
    /// What is drawn.
    pub look: Look,
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
}

/// The whole motion, ready to write.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    /// The problem's title.
    pub title: String,
    /// The bodies as drawn.
    pub sheets: Vec<Sheet>,
    /// The ids of the marked points (`cm-B`, `joint-J`) and whether each is a mass centre.
    pub points: Vec<(String, bool)>,
    /// Per marked point, the words that follow it: a body's name beside its mass centre,
    /// a joint's coordinates beside the joint.
    pub captions: Vec<Option<String>>,
    /// The joints fixed to `N` (ids into `points`), drawn with a support.
    pub grounded: Vec<usize>,
    /// Rolling contacts' points (ids into `points`), whose track is drawn as the ground.
    pub rolling: Vec<usize>,
    /// Per spring, then per damper: its lane beside the others between the same points
    /// (the solution stage gives each its lane).
    pub spring_lanes: Vec<f64>,
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
