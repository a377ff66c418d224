//! A laid-out picture in picture coordinates (y down), which both exporters write.

use super::numbers::{cross, dot, unit, P3};
use super::scene::{BodyKind, Kind, Label, Role};

/// A point in the picture, y pointing down.
pub type P2 = [f64; 2];

/// How a spatial system is viewed (planar ones are always drawn in their plane).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum View {
    /// Looking along −(1, 1, 1) of `N`, `N.z` up; with gravity, against it up (see
    /// [`View::rows_up`]).
    Isometric,
    /// Looking along this direction of `N`; `N.z` up (or `N.y`, looking along `N.z`).
    Along(P3),
}

impl View {
    /// Reads `--view`: `iso`, `front` (along +N.y), `side` (along −N.x), `top` (along −N.z),
    /// or a direction `X,Y,Z` to look along.
    ///
    /// # Errors
    /// A message naming what was expected.
    pub fn parse(text: &str) -> Result<View, String> {
        let text = text.trim();
        match text {
            "iso" | "isometric" => return Ok(View::Isometric),
            "front" => return Ok(View::Along([0.0, 1.0, 0.0])),
            "side" => return Ok(View::Along([-1.0, 0.0, 0.0])),
            "top" => return Ok(View::Along([0.0, 0.0, -1.0])),
            _ => {}
        }
        let parts: Vec<&str> = text.split(',').map(str::trim).collect();
        let numbers: Option<Vec<f64>> = parts
            .iter()
            .map(|p| p.parse::<f64>().ok().filter(|x| x.is_finite()))
            .collect();
        match numbers.as_deref() {
            Some([x, y, z]) if unit([*x, *y, *z]).is_some() => Ok(View::Along([*x, *y, *z])),
            Some([_, _, _]) => Err(format!("--view `{text}`: the direction must not be zero")),
            _ => Err(format!(
                "--view `{text}` is not a view: use iso, front, side, top or a direction X,Y,Z to look along"
            )),
        }
    }

    /// The rows of the projection with unit scale: picture x and picture y (down).
    pub fn rows(self, planar: bool) -> [P3; 2] {
        if planar {
            return [[1.0, 0.0, 0.0], [0.0, -1.0, 0.0]];
        }
        let look = match self {
            View::Isometric => [-1.0, -1.0, -1.0],
            View::Along(d) => d,
        };
        let look = unit(look).unwrap_or([-1.0, -1.0, -1.0]);
        let up = if cross(look, [0.0, 0.0, 1.0]).iter().all(|x| x.abs() < 1e-9) {
            [0.0, 1.0, 0.0]
        } else {
            [0.0, 0.0, 1.0]
        };
        rows_looking(look, up)
    }

    /// The rows for a spatial system with `up` (against gravity, where there is gravity) up
    /// the page in the isometric view: it looks down on the system from between the two
    /// other axes of `N`, as it does along −(1, 1, 1) when `N.z` is up, so that a bicycle
    /// whose `N.z` points down stands on its wheels. A view along a direction is as asked.
    pub fn rows_up(self, up: Option<P3>) -> [P3; 2] {
        match (self, up.and_then(unit)) {
            (View::Isometric, Some(u)) => {
                let nearest = (0..3)
                    .max_by(|&a, &b| u[a].abs().total_cmp(&u[b].abs()))
                    .unwrap_or(2);
                let mut look = [-u[0], -u[1], -u[2]];
                look[(nearest + 1) % 3] -= 1.0;
                look[(nearest + 2) % 3] -= 1.0;
                rows_looking(unit(look).unwrap_or([-1.0, -1.0, -1.0]), u)
            }
            _ => self.rows(false),
        }
    }
}

/// The rows of a view along the unit `look` with `up` (not along it) up the page.
fn rows_looking(look: P3, up: P3) -> [P3; 2] {
    let right = unit(cross(look, up)).unwrap_or([1.0, 0.0, 0.0]);
    let true_up = cross(right, look);
    [right, [-true_up[0], -true_up[1], -true_up[2]]]
}

/// The affine map from `N` coordinates to picture coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    /// The linear part, two rows.
    pub a: [P3; 2],
    /// The translation.
    pub b: P2,
}

impl Projection {
    /// Where a point of `N` lands.
    pub fn point(&self, p: P3) -> P2 {
        [dot(self.a[0], p) + self.b[0], dot(self.a[1], p) + self.b[1]]
    }

    /// Where a direction of `N` points.
    pub fn direction(&self, v: P3) -> P2 {
        [dot(self.a[0], v), dot(self.a[1], v)]
    }

    /// The eight numbers of `data-projection`.
    pub fn numbers(&self) -> [f64; 8] {
        let [r, s] = self.a;
        [r[0], r[1], r[2], s[0], s[1], s[2], self.b[0], self.b[1]]
    }
}

/// A colour, by its use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ink {
    /// Outlines and text.
    Black,
    /// Bodies' fill.
    Body,
    /// Thin construction lines and the frames' unit vectors.
    Grey,
    /// Known forces.
    Known,
    /// Unknown reactions.
    Unknown,
    /// Gravity.
    Weight,
    /// The kinetic diagram.
    Inertia,
    /// The paper.
    White,
    /// A floor's patch.
    Floor,
}

impl Ink {
    /// The colour as red, green, blue.
    pub fn rgb(self) -> (u8, u8, u8) {
        match self {
            Ink::Black => (34, 34, 34),
            Ink::Body => (214, 226, 236),
            Ink::Grey => (120, 120, 120),
            Ink::Known => (31, 95, 168),
            Ink::Unknown => (192, 57, 43),
            Ink::Weight => (46, 125, 50),
            Ink::Inertia => (123, 31, 162),
            Ink::White => (255, 255, 255),
            Ink::Floor => (238, 238, 238),
        }
    }

    /// The colour of an arrow of `kind`.
    pub fn of(kind: Kind) -> Ink {
        match kind {
            Kind::Reaction => Ink::Unknown,
            Kind::Gravity => Ink::Weight,
            Kind::Inertia => Ink::Inertia,
            _ => Ink::Known,
        }
    }
}

/// A drawn line or curve.
#[derive(Clone, Debug, PartialEq)]
pub struct Stroke {
    /// The points, in order.
    pub points: Vec<P2>,
    /// Joined back to the first point.
    pub closed: bool,
    /// The width of the line.
    pub width: f64,
    /// Its colour.
    pub ink: Ink,
    /// The fill of a closed curve.
    pub fill: Option<Ink>,
    /// Dashed.
    pub dashed: bool,
}

/// A drawn item that is not an arrow or a marker.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A polyline or polygon.
    Stroke(Stroke),
    /// A circle.
    Circle {
        /// Its centre.
        center: P2,
        /// Its radius.
        radius: f64,
        /// Its outline's colour.
        ink: Ink,
        /// Its fill.
        fill: Ink,
    },
    /// An ellipse (a disc seen obliquely): semi-axes `rx`, `ry`, turned by `angle`
    /// (degrees, clockwise on the page).
    Ellipse {
        /// Its centre.
        center: P2,
        /// The semi-axis along its own x.
        rx: f64,
        /// The semi-axis along its own y.
        ry: f64,
        /// How far it is turned, in degrees, clockwise on the page.
        angle: f64,
        /// Its outline's colour.
        ink: Ink,
        /// Its fill.
        fill: Ink,
    },
    /// Text: a label centered at `at`.
    Text {
        /// Its centre.
        at: P2,
        /// What it says.
        label: Label,
        /// Its colour.
        ink: Ink,
    },
    /// Items drawn as one, such as a frame's unit vectors: a group of that class.
    Group {
        /// The group's class.
        class: &'static str,
        /// Its items.
        items: Vec<Item>,
    },
    /// One body's items, as a group with its id (`body-A`) and its shape's kind.
    Body {
        /// The group's id.
        id: String,
        /// What the body is drawn as.
        kind: BodyKind,
        /// Its items.
        items: Vec<Item>,
    },
}

/// A marked point: a circle whose id the markup carries.
#[derive(Clone, Debug, PartialEq)]
pub struct Mark {
    /// The id, e.g. `joint-O`.
    pub id: String,
    /// The centre.
    pub at: P2,
    /// How it is drawn.
    pub role: Role,
}

/// A 2D couple's arc.
#[derive(Clone, Debug, PartialEq)]
pub struct Arc {
    /// The centre.
    pub center: P2,
    /// The radius.
    pub radius: f64,
    /// The start angle, radians, in picture coordinates.
    pub start: f64,
    /// The signed sweep, radians, in picture coordinates.
    pub sweep: f64,
    /// +1 counterclockwise about `N.z`, −1 clockwise.
    pub sense: i8,
}

impl Arc {
    /// The point at angle `t`.
    pub fn at(&self, t: f64) -> P2 {
        [
            self.center[0] + self.radius * t.cos(),
            self.center[1] + self.radius * t.sin(),
        ]
    }

    /// The end point.
    pub fn end(&self) -> P2 {
        self.at(self.start + self.sweep)
    }
}

/// A drawn force or couple.
#[derive(Clone, Debug, PartialEq)]
pub struct DrawnArrow {
    /// What it stands for.
    pub kind: Kind,
    /// Its symbol.
    pub label: Label,
    /// The id of the point it acts at (without a page's prefix).
    pub at_id: String,
    /// A couple.
    pub couple: bool,
    /// The tail and head of its line (a 2D couple: the arc's ends).
    pub tail: P2,
    /// The head.
    pub head: P2,
    /// A 2D couple's arc.
    pub arc: Option<Arc>,
    /// The arrowheads, as triangles.
    pub heads: Vec<[P2; 3]>,
    /// Its colour.
    pub ink: Ink,
    /// A thin dashed leader from the point it acts at to its tail, where the arrow is
    /// drawn a little aside (a weight moved off a reaction's line): `None` when it starts
    /// or ends at its point.
    pub leader: Option<(P2, P2)>,
}

/// One laid-out picture.
#[derive(Clone, Debug, PartialEq)]
pub struct Picture {
    /// Its width.
    pub width: f64,
    /// Its height.
    pub height: f64,
    /// The map from `N` to the picture.
    pub projection: Projection,
    /// Shapes, drawn first.
    pub items: Vec<Item>,
    /// The marked points.
    pub marks: Vec<Mark>,
    /// The arrows.
    pub arrows: Vec<DrawnArrow>,
    /// Labels and captions, drawn last: the first is the picture's title.
    pub texts: Vec<Item>,
    /// The legend under the picture, which a handout that states it once leaves out.
    pub legend: Legend,
    /// How many times its room at 13 px each label was given (more than 1 for a picture
    /// printed small, whose labels keep their size in points).
    pub grow: f64,
}

/// The legend of a picture: its lines are the last of the picture's `texts`, in a strip
/// at the bottom.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Legend {
    /// How many of the texts.
    pub lines: usize,
    /// The strip's height.
    pub height: f64,
}

#[cfg(test)]
mod tests {
    use super::{dot, View};

    #[test]
    fn gravity_points_down_the_page_in_the_isometric_view() {
        for g in [
            [0.0, 0.0, -1.0],
            [0.0, 0.0, 1.0],
            [0.0, -1.0, 0.0],
            [1.0, 0.0, 0.0],
        ] {
            let rows = View::Isometric.rows_up(Some([-g[0], -g[1], -g[2]]));
            // The picture's y points down: gravity along it, none of it across the page.
            assert!(dot(rows[1], g) > 0.8, "{g:?}: {rows:?}");
            assert!(dot(rows[0], g).abs() < 1e-12, "{g:?}: {rows:?}");
        }
        // With N.z up the view is the one it always was.
        assert_eq!(
            View::Isometric.rows_up(Some([0.0, 0.0, 1.0])),
            View::Isometric.rows(false)
        );
    }
}
