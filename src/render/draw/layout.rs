//! Laying a scene out: the projection that fits it on the page, the shapes in picture
//! coordinates, arrows of a fixed length and labels placed where they overlap nothing.

use super::fit::{fit, TITLE};
use super::numbers::{add, cross, dot, scale, sub, unit, P3};
use super::picture::{
    Arc, DrawnArrow, Ink, Item, Legend, Mark, Picture, Projection, Stroke, View, P2,
};
use super::place::{text_size, Obstacles};
use super::scene::{Arrow, Label, Role, Scene, Shape};
use super::strokes::{
    arrow_length, clear_of_tips, dashpot, ellipse_of, head, in_lane, p2add, p2norm, p2scale,
    p2unit, stack_of, tips_of, wrap, zigzag,
};

mod beside;
mod captions;
mod crossing;
mod curl;
mod labels;
mod marks;
pub use marks::{ARC, ROUND_A_VELOCITY, SENSE, SHORT_ANGLE};
mod room;
mod triad;
mod velocity;
mod weights;

use labels::Beside;
use room::Room;

/// The radius of a 2D couple's arc.
const COUPLE: f64 = 16.0;
/// How much wider a couple's curl is drawn where straight forces act at its point too.
const CROWDED_CURL: f64 = 1.5;

pub(super) struct Painter {
    pub(super) projection: Projection,
    shift: P2,
    pub(super) items: Vec<Item>,
    texts: Vec<Item>,
    pub(super) obstacles: Obstacles,
    scale: f64,
    /// Put before a body's group id: empty in the free body, `kinetic-` beside it.
    body_prefix: &'static str,
    /// Labels wait until every line of their panel is drawn, so that none crosses them;
    /// an arrow's label knows its arrow (an index into the picture's arrows).
    pending: Vec<(P2, f64, Label, Ink, Beside)>,
    /// The straight arrows drawn so far, tail to tip: a later one keeps off their lines.
    lines: Vec<(P2, P2)>,
    /// Where the panel's straight arrows act (on the page) and which way (`N`'s
    /// coordinates): an arrow ends at its point only where no other there points the
    /// opposite way.
    straight: Vec<(P2, P3)>,
    /// How much room a label takes beyond its size at 13 px (1, or more for a page that
    /// prints the picture small and its labels at their size in points).
    grow: f64,
    /// How many times its length at 13 px every arrow is drawn (more than 1 where the
    /// picture prints small, so that it prints long enough to read).
    reach: f64,
    /// Where the panel's other straight forces act (on the page) and which way (a unit
    /// vector on the page): a weight keeps off their lines.
    others: Vec<(P2, P2)>,
    /// The bodies each marked point belongs to, in the scene's order of markers: its
    /// caption keeps out of the others.
    owners: Vec<Vec<String>>,
    /// The ground's lines drawn, each from one end to the other with the page's unit
    /// vector away from the ground: the unit vectors keep above them.
    pub(super) grounds: Vec<(P2, P2, P2)>,
    /// Where the picture's velocities start (on the page): an angle's arc about one of
    /// them goes round outside its arrow.
    moving: Vec<P2>,
    /// The marked points (on the page): a weight moved aside keeps its arrow off the others.
    points: Vec<P2>,
}

impl Painter {
    /// What the scene's arrows and velocities take before anything is drawn: the
    /// straight forces' points and directions, and where the velocities start.
    fn survey(&mut self, scene: &Scene) {
        self.moving = self.velocities(&scene.shapes);
        self.straight = (scene.arrows.iter())
            .filter(|a| !(a.couple && scene.planar))
            .map(|a| (self.at(a.at), a.direction))
            .collect();
        self.others = self.other_forces(&scene.arrows);
    }

    pub(super) fn at(&self, p: P3) -> P2 {
        p2add(self.projection.point(p), self.shift)
    }

    pub(super) fn stroke(
        &mut self,
        points: Vec<P2>,
        width: f64,
        ink: Ink,
        fill: Option<Ink>,
        closed: bool,
    ) {
        self.obstacles.wide_polyline(&points, closed, width);
        self.items.push(Item::Stroke(Stroke {
            points,
            closed,
            width,
            ink,
            fill,
            dashed: false,
        }));
    }

    fn thin_dashed(&mut self, a: P2, b: P2) {
        self.obstacles.segment(a, b);
        self.items.push(Item::Stroke(Stroke {
            points: vec![a, b],
            closed: false,
            width: 0.8,
            ink: Ink::Grey,
            fill: None,
            dashed: true,
        }));
    }

    fn circle(&mut self, center: P2, radius: f64, ink: Ink, fill: Ink) {
        self.obstacles.spot(center, radius);
        self.items.push(Item::Circle {
            center,
            radius,
            ink,
            fill,
        });
    }

    /// The room a label of `plain` text takes.
    fn room(&self, plain: &str) -> P2 {
        p2scale(text_size(plain), self.grow)
    }

    fn label(&mut self, anchor: P2, toward: f64, label: &Label, ink: Ink) {
        self.pending
            .push((anchor, toward, label.clone(), ink, Beside::Spot));
    }

    /// A caption at a fixed place, which later labels keep clear of.
    fn fixed_text(&mut self, at: P2, label: Label, ink: Ink) {
        self.obstacles.reserve(at, self.room(&label.plain));
        self.texts.push(Item::Text { at, label, ink });
    }

    /// A wheel: a circle (an ellipse, seen obliquely) with a spoke and a hub.
    fn wheel(&mut self, center: P3, normal: P3, radius: f64, mark: P3) {
        let c = self.at(center);
        let rim = super::numbers::circle(center, normal, radius);
        let outline: Vec<P2> = rim.iter().map(|p| self.at(*p)).collect();
        self.obstacles.polyline(&outline, true);
        // The image of the disc: M = A [u v] r; its semi-axes from M Mᵀ.
        let u = unit(sub(rim[0], center)).unwrap_or([1.0, 0.0, 0.0]);
        let v = cross(normal, u);
        let (du, dv) = (
            p2scale(self.projection.direction(u), radius),
            p2scale(self.projection.direction(v), radius),
        );
        let (rx, ry, angle) = ellipse_of(du, dv);
        if rx - ry < 1e-6 * rx.max(1e-12) {
            self.items.push(Item::Circle {
                center: c,
                radius: rx,
                ink: Ink::Black,
                fill: Ink::Body,
            });
        } else {
            self.items.push(Item::Ellipse {
                center: c,
                rx,
                ry,
                angle,
                ink: Ink::Black,
                fill: Ink::Body,
            });
        }
        // The spoke, fixed in the body, turns with it; a hub at the centre.
        let mark = sub(mark, scale(normal, dot(mark, normal)));
        let tip = self.at(add(center, scale(unit(mark).unwrap_or(u), radius)));
        self.stroke(vec![c, tip], 1.6, Ink::Black, None, false);
        self.items.push(Item::Circle {
            center: c,
            radius: 2.2,
            ink: Ink::Black,
            fill: Ink::Black,
        });
    }

    fn shape(&mut self, shape: &Shape) {
        match shape {
            Shape::Body { name, kind, parts } => {
                let outside = std::mem::take(&mut self.items);
                for part in parts {
                    self.shape(part);
                }
                let items = std::mem::replace(&mut self.items, outside);
                self.items.push(Item::Body {
                    id: format!("{}body-{name}", self.body_prefix),
                    kind: *kind,
                    items,
                });
            }
            Shape::Wheel {
                center,
                normal,
                radius,
                mark,
            } => self.wheel(*center, *normal, *radius, *mark),
            Shape::LightRod { from, to } => {
                let (a, b) = (self.at(*from), self.at(*to));
                self.stroke(vec![a, b], 1.1, Ink::Black, None, false);
            }
            Shape::Surface {
                at,
                along,
                up,
                fixed,
            } => self.surface(*at, *along, *up, *fixed),
            Shape::Floor { corners, up } => self.floor(corners, *up),
            Shape::Track {
                center,
                normal,
                radius,
                inside,
            } => self.track(*center, *normal, *radius, *inside),
            Shape::Bar(points) => self.bar(points),
            Shape::Polygon(points) | Shape::Outline(points) => {
                let points: Vec<P2> = points.iter().map(|p| self.at(*p)).collect();
                self.stroke(points, 1.4, Ink::Black, Some(Ink::Body), true);
            }
            Shape::Dot(p) => {
                let c = self.at(*p);
                self.circle(c, 5.0, Ink::Black, Ink::Black);
            }
            Shape::Pin(p) => {
                let c = self.at(*p);
                self.circle(c, 4.5, Ink::Black, Ink::White);
            }
            Shape::Ball(p) => {
                let c = self.at(*p);
                self.circle(c, 6.0, Ink::Black, Ink::Body);
            }
            Shape::Weld(p) => self.weld(*p),
            Shape::Slider { at, axis } => self.slider(*at, *axis),
            Shape::Ground { at, along, up } => self.ground(*at, *along, *up),
            Shape::Spring { from, to, lane } => {
                let (a, b) = (self.at(*from), self.at(*to));
                let ([a, b], legs) = in_lane(a, b, *lane);
                for leg in legs {
                    self.stroke(leg, 1.3, Ink::Black, None, false);
                }
                self.stroke(zigzag(a, b), 1.3, Ink::Black, None, false);
            }
            Shape::Damper { from, to, lane } => {
                let (a, b) = (self.at(*from), self.at(*to));
                let ([a, b], legs) = in_lane(a, b, *lane);
                for part in legs.into_iter().chain(dashpot(a, b)) {
                    self.stroke(part, 1.3, Ink::Black, None, false);
                }
            }
            Shape::Triad { origin, axes } => self.triad(*origin, axes),
            Shape::Angle {
                center,
                from,
                axis,
                angle,
                label,
            } => self.angle(*center, (*from, *axis), *angle, label),
            Shape::Distance { from, to, label } => self.distance(*from, *to, label),
            Shape::Velocity {
                at,
                direction,
                label,
            } => self.velocity(*at, *direction, label),
            Shape::Dashed { from, to } => {
                let (a, b) = (self.at(*from), self.at(*to));
                self.thin_dashed(a, b);
            }
        }
    }

    /// An arrow of fixed size at its point; `stack` counts arrows already drawn there along
    /// its line; `index` is its place among the picture's arrows.
    fn arrow(&mut self, arrow: &Arrow, planar: bool, stack: usize, index: usize) -> DrawnArrow {
        let ink = Ink::of(arrow.kind);
        let at = self.at(arrow.at);
        let d = self.projection.direction(arrow.direction);
        let u = p2unit(d).unwrap_or([0.0, -1.0]);
        let mut drawn = DrawnArrow {
            kind: arrow.kind,
            label: arrow.label.clone(),
            at_id: arrow.at_id.clone(),
            couple: arrow.couple,
            tail: at,
            head: at,
            arc: None,
            heads: Vec::new(),
            ink,
            leader: None,
        };
        if arrow.couple && planar {
            let sense: i8 = if arrow.direction[2] >= 0.0 { 1 } else { -1 };
            // Round the straight forces at its point, not over their tails: wider there.
            let rays = self.rays_at(at);
            let round = if rays.is_empty() { 1.0 } else { CROWDED_CURL };
            let radius = COUPLE * self.reach.min(1.4) * round + 7.0 * stack as f64;
            // Counterclockwise in N is clockwise on the page, whose y points down.
            let sweep = -f64::from(sense) * 1.5 * std::f64::consts::PI;
            let start = self.curl_start(at, radius, sweep, &rays);
            let arc = Arc {
                center: at,
                radius,
                start,
                sweep,
                sense,
            };
            let end = arc.end();
            let t_end = start + sweep;
            let tangent = [-t_end.sin() * sweep.signum(), t_end.cos() * sweep.signum()];
            drawn.tail = arc.at(start);
            drawn.head = end;
            drawn.heads.push(head(end, tangent));
            let steps = 24;
            let points: Vec<P2> = (0..=steps)
                .map(|k| arc.at(start + sweep * k as f64 / steps as f64))
                .collect();
            self.obstacles.polyline(&points, false);
            for h in &drawn.heads {
                self.obstacles.polyline(h, true);
            }
            drawn.arc = Some(arc);
            // Its label close by the curl, as a point's caption is.
            let toward = (start + sweep / 2.0) + std::f64::consts::PI;
            self.pending.push((
                p2add(at, [toward.cos() * radius, toward.sin() * radius]),
                toward,
                arrow.label.clone(),
                ink,
                Beside::Near,
            ));
            return drawn;
        }
        let length = arrow_length(stack) * self.reach;
        // A force starts at its point, or ends there where starting there would run it
        // inside its body (a push at a contact, a pin force along a bar); an inertia force,
        // drawn at the mass centre, may stand beside a bar or another arrow.
        let pushes = self.pushes_at(arrow, at, u, length);
        let point = at;
        let mut at = if arrow.kind == super::scene::Kind::Inertia && !arrow.couple {
            self.beside_bodies(at, u)
        } else if arrow.couple {
            // A moment vector is free: off the arrows it would cross or lie on.
            self.free_couple(at, u, length, arrow.kind == super::scene::Kind::Inertia)
        } else if pushes {
            // Its head at the body's edge, not hidden in a bar's stroke at the point.
            let back = self.clear_of_a_bar(at, u);
            p2add(at, p2scale(u, -(length + back)))
        } else {
            at
        };
        let mut length = length;
        if arrow.kind == super::scene::Kind::Gravity && !arrow.couple {
            (at, length) = self.weight(&mut drawn, (point, at), u, (length, pushes));
        }
        drawn.tail = at;
        let tip = p2add(at, p2scale(u, length));
        self.lines.push((at, tip));
        drawn.head = tip;
        drawn.heads.push(head(tip, u));
        if arrow.couple {
            // A moment vector: a double head.
            drawn.heads.push(head(p2add(tip, p2scale(u, -7.0)), u));
        }
        self.obstacles.segment(at, tip);
        for h in &drawn.heads {
            self.obstacles.polyline(h, true);
        }
        if pushes {
            // Its label by its tail, out in the open, away from the point.
            self.pending.push((
                at,
                (-u[1]).atan2(-u[0]),
                arrow.label.clone(),
                ink,
                Beside::Spot,
            ));
        } else {
            self.pending.push((
                tip,
                u[1].atan2(u[0]),
                arrow.label.clone(),
                ink,
                Beside::Arrow(index),
            ));
        }
        drawn
    }

    /// How many steps longer than the least `arrow` is drawn: one for each arrow drawn
    /// before it at its spot along its line, more while its heads would meet another's.
    fn stack(
        &self,
        drawn_at: &mut Vec<(P2, Option<P2>)>,
        arrows: &[DrawnArrow],
        arrow: &Arrow,
        planar: bool,
    ) -> usize {
        let (at, u) = (self.at(arrow.at), self.page_direction(arrow, planar));
        let stack = stack_of(drawn_at, at, u);
        let reach = self.reach;
        clear_of_tips(
            at,
            u,
            stack,
            &tips_of(arrows),
            |k| arrow_length(k) * reach,
            7.0,
        )
    }

    /// The direction an arrow points on the page (a 2D couple, an arc: none).
    fn page_direction(&self, arrow: &Arrow, planar: bool) -> Option<P2> {
        if arrow.couple && planar {
            return None;
        }
        Some(p2unit(self.projection.direction(arrow.direction)).unwrap_or([0.0, -1.0]))
    }
}

/// Lays `scene` out for `view`.
pub fn lay_out(scene: &Scene, view: View) -> Picture {
    lay_out_with(scene, view, 1.0)
}

/// Lays `scene` out for `view`, each label taking `grow` times its room at 13 px (a
/// picture printed small lays its labels out at the size they print).
pub fn lay_out_with(scene: &Scene, view: View, grow: f64) -> Picture {
    let room = Room::of(scene.content, grow);
    let (mut projection, [mut panel_width, height]) = fit(scene, view, room.margin, room.content);
    let panels = if scene.kinetic.is_some() { 2.0 } else { 1.0 };
    // A caption wider than the system widens the panels, the system centred in them.
    let extra = (text_size(&scene.title)[0] + 40.0 - panels * panel_width).max(0.0) / panels;
    panel_width += extra;
    projection.b[0] += extra / 2.0;
    let width = panels * panel_width;
    let legend_lines = wrap(&scene.legend, width - 24.0);
    let legend = legend_height(legend_lines.len());
    let height = height + legend;
    let scale = p2norm([projection.a[0][0], projection.a[1][0]])
        .max(p2norm([projection.a[0][1], projection.a[1][1]]))
        .max(1e-12);
    let mut painter = Painter {
        projection,
        shift: [0.0, 0.0],
        items: Vec::new(),
        texts: Vec::new(),
        obstacles: Obstacles::within([0.0, TITLE], [panel_width, height - legend]),
        scale,
        body_prefix: "",
        pending: Vec::new(),
        lines: Vec::new(),
        straight: Vec::new(),
        grow,
        reach: room.reach,
        others: Vec::new(),
        owners: Vec::new(),
        grounds: Vec::new(),
        moving: Vec::new(),
        points: Vec::new(),
    };
    painter.survey(scene);
    for shape in scene
        .shapes
        .iter()
        .filter(|s| !matches!(s, Shape::Triad { .. }))
    {
        painter.shape(shape);
    }
    let mut marks = Vec::new();
    for m in &scene.markers {
        let at = painter.at(m.at);
        painter.obstacles.spot(at, 4.0);
        painter.points.push(at);
        marks.push(Mark {
            id: m.id.clone(),
            at,
            role: m.role,
        });
    }
    let mut arrows = Vec::new();
    let mut drawn_at = Vec::new();
    for arrow in &scene.arrows {
        let stack = painter.stack(&mut drawn_at, &arrows, arrow, scene.planar);
        let index = arrows.len();
        arrows.push(painter.arrow(arrow, scene.planar, stack, index));
    }
    for shape in scene
        .shapes
        .iter()
        .filter(|s| matches!(s, Shape::Triad { .. }))
    {
        painter.shape(shape);
    }
    painter.caption_marks(&scene.markers, &marks);
    let panel_captions = [
        (panel_width / 2.0, "free body"),
        (panel_width * 1.5, "kinetic diagram"),
    ];
    let equals = [panel_width, (TITLE + height - legend) / 2.0];
    if scene.kinetic.is_some() {
        let (x, caption) = panel_captions[0];
        painter.fixed_text([x, TITLE + 8.0], Label::text(caption), Ink::Grey);
        painter.obstacles.reserve(equals, painter.room("="));
    }
    painter.place_labels(&mut arrows);
    if let Some((shapes, inertia)) = &scene.kinetic {
        painter.shift = [panel_width, 0.0];
        painter.obstacles = Obstacles::within([panel_width, TITLE], [width, height - legend]);
        painter.body_prefix = "kinetic-";
        let (x, caption) = panel_captions[1];
        painter.fixed_text([x, TITLE + 8.0], Label::text(caption), Ink::Grey);
        for shape in shapes {
            painter.shape(shape);
        }
        for m in scene.markers.iter().filter(|m| m.role == Role::Center) {
            let at = painter.at(m.at);
            painter.circle(at, 4.5, Ink::Black, Ink::White);
        }
        let mut drawn_at = Vec::new();
        for arrow in inertia {
            let stack = painter.stack(&mut drawn_at, &arrows, arrow, scene.planar);
            let index = arrows.len();
            arrows.push(painter.arrow(arrow, scene.planar, stack, index));
        }
        painter.fixed_text(equals, Label::from_tex("="), Ink::Black);
        painter.place_labels(&mut arrows);
    }
    let texts = texts(
        &scene.title,
        std::mem::take(&mut painter.texts),
        &legend_lines,
        [width, height, legend],
    );
    Picture {
        width,
        height,
        projection,
        items: painter.items,
        marks,
        arrows,
        texts,
        legend: Legend {
            lines: legend_lines.len(),
            height: legend,
        },
        grow,
    }
}

/// The height of a legend of `lines` lines under a picture.
fn legend_height(lines: usize) -> f64 {
    18.0 * lines as f64 + if lines == 0 { 0.0 } else { 12.0 }
}

/// The picture's texts: its title above, the labels `placed`, the legend's lines below;
/// `width`, `height` and the `legend`'s height are the picture's.
fn texts(
    title: &str,
    mut placed: Vec<Item>,
    legend_lines: &[String],
    [width, height, legend]: [f64; 3],
) -> Vec<Item> {
    let mut texts = vec![Item::Text {
        at: [width / 2.0, 16.0],
        label: Label::text(title),
        ink: Ink::Black,
    }];
    texts.append(&mut placed);
    for (k, line) in legend_lines.iter().enumerate() {
        texts.push(Item::Text {
            at: [width / 2.0, height - legend + 14.0 + 18.0 * k as f64],
            label: Label::text(line),
            ink: Ink::Grey,
        });
    }
    texts
}
