//! Pictures of steps 1 and 2: the configuration, and each free body of the plan with its
//! kinetic diagram.
//!
//! One [`Scene`] per picture, built in `N`'s coordinates by the solution stage
//! (`crate::solution::pictures`), is laid out once into a [`Picture`] ([`layout`]: projection,
//! fixed-size arrows, label placement), and written by two exporters, `svg` and `tikz`,
//! so the two never disagree (a page that prints a picture small lays it out again with
//! more room for its labels, which print at a fixed size: the same bodies and arrows).
//!
//! Entry: [`Drawing`] (a laid-out picture, written as SVG or TikZ) and the scene's types;
//! [`motion_svg`] writes the motion. The other modules are private; what the solution
//! uses is re-exported here.

mod extent;
mod fit;
mod ground;
pub mod layout;
mod motion;
mod motion_bodies;
mod motion_labels;
mod motion_marks;
pub mod motion_svg;
mod motion_timing;
pub mod numbers;
mod picture;
mod place;
mod scene;
mod strokes;
mod svg;
mod svg_path;
mod tikz;

pub use fit::CONTENT;
pub use motion::{Body, Gauge, Motion, Part, Placed, Sheet, TITLE_STRIP};
pub use picture::{DrawnArrow, Ink, Item, Picture, Projection, View};
pub use place::text_size;
pub use scene::{Arrow, BodyKind, Kind, Label, Marker, Role, Scene, Shape};
pub use strokes::in_lane;
pub use tikz::{Size, ABOVE_A_TABLE, BESIDE_A_TABLE, CONFIGURATION};

/// One picture of a problem.
#[derive(Clone, Debug)]
pub struct Drawing {
    /// Its name: `configuration` or `fbd-NAME` (the plan's free body without spaces).
    pub name: String,
    /// Its caption.
    pub title: String,
    /// The free body it shows, as the plan's table names it (empty for the configuration).
    pub free_body: String,
    /// The laid-out picture.
    pub picture: Picture,
    /// The scene it was laid out from, and the view: a page that prints the picture
    /// smaller than its labels lays it out again with room for them.
    pub scene: Scene,
    /// The view it was laid out for.
    pub view: View,
}

impl Drawing {
    /// The picture as an SVG document, its ids prefixed by `prefix`.
    pub fn svg(&self, prefix: &str) -> String {
        svg::export(&self.picture, &self.title, prefix)
    }

    /// The picture as a `tikzpicture`.
    pub fn tikz(&self) -> String {
        self.tikz_in(tikz::PAGE_SIZE)
    }

    /// The picture as a `tikzpicture` in `room`: where the page prints it so small that its
    /// labels (which keep their size in points) would take more room than the layout gave
    /// them, it is laid out again with their labels' room grown to what they print at.
    fn tikz_in(&self, room: tikz::Size) -> String {
        tikz::export(&self.laid_out_in(room), room)
    }

    /// The picture as a page that sets it in `room` prints it: as laid out where its labels
    /// keep their room there, else laid out again with their room grown to what they
    /// print at (its arrows longer and the system smaller, so that it keeps about its
    /// size; once more where it still prints smaller than that growth allowed for).
    pub fn laid_out_in(&self, room: tikz::Size) -> std::borrow::Cow<'_, Picture> {
        let grow = tikz::label_growth(&self.picture, room);
        if grow <= 1.02 {
            return std::borrow::Cow::Borrowed(&self.picture);
        }
        let picture = layout::lay_out_with(&self.scene, self.view, grow);
        let again = tikz::label_growth(&picture, room);
        std::borrow::Cow::Owned(if again > 1.02 * grow {
            layout::lay_out_with(&self.scene, self.view, again)
        } else {
            picture
        })
    }

    /// The picture to embed in a page: its ids prefixed by its name, so that a page of
    /// several pictures keeps them unique.
    pub fn figure(&self) -> crate::render::context::Figure {
        self.figure_in(tikz::CONFIGURATION)
    }

    /// The picture to embed in a page beside a narrow table, a little smaller (see
    /// [`tikz::BESIDE_A_TABLE`]); as [`figure_above_a_table`](Self::figure_above_a_table)
    /// when the picture is much wider than high, since it would then be too small to read
    /// there and goes above its table anyway.
    pub fn figure_beside_a_table(&self) -> crate::render::context::Figure {
        const WIDEST_BESIDE: f64 = 4.0;
        let height = self.picture.height - self.picture.legend.height;
        if self.picture.width > WIDEST_BESIDE * height {
            return self.figure_above_a_table();
        }
        self.figure_in(tikz::BESIDE_A_TABLE)
    }

    /// The picture to embed in a page above a wide table (see `tikz::ABOVE_A_TABLE`).
    pub fn figure_above_a_table(&self) -> crate::render::context::Figure {
        self.figure_in(tikz::ABOVE_A_TABLE)
    }

    fn figure_in(&self, room: tikz::Size) -> crate::render::context::Figure {
        // A free body's page heads it with its name already; the configuration's caption
        // says which state it shows.
        let svg = svg::export_with(
            &self.picture,
            &self.title,
            &format!("{}-", self.name),
            self.free_body.is_empty(),
        );
        crate::render::context::Figure {
            // The XML declaration-free SVG element, one line per element, no blank lines
            // (a blank line would end a Markdown HTML block).
            svg_inline: crate::render::text::InlineSvg::from(svg.trim_end().to_string()),
            picture_latex: crate::render::text::LatexCode::from(self.tikz_in(room)),
        }
    }
}
