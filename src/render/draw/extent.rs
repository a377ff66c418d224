//! How far a laid-out picture's ink reaches: the box of its shapes, points, arrows and
//! labels (not its title or legend, which a handout prints apart). A page scales a picture
//! by this box, not by the margin the layout kept round it, so that a free body fills the
//! room its page gives it.

use super::picture::{Item, Picture, P2};
use super::place::text_size;

/// The least and greatest corner of the box round everything `picture` draws but its
/// title and legend; `None` for a picture with nothing in it.
pub fn drawn(picture: &Picture) -> Option<(P2, P2)> {
    let mut reach = Reach::default();
    for item in &picture.items {
        reach.item(item, picture.grow);
    }
    for m in &picture.marks {
        reach.disc(m.at, 4.5);
    }
    for a in &picture.arrows {
        match &a.arc {
            Some(arc) => reach.disc(arc.center, arc.radius),
            None => reach.points(&[a.tail, a.head]),
        }
        for h in &a.heads {
            reach.points(h);
        }
        if let Some((from, to)) = a.leader {
            reach.points(&[from, to]);
        }
    }
    let captions = picture.texts.len().saturating_sub(picture.legend.lines);
    for t in picture.texts.get(1..captions).unwrap_or_default() {
        reach.item(t, picture.grow);
    }
    reach.corners()
}

/// The box grown so far.
#[derive(Default)]
struct Reach {
    corners: Option<(P2, P2)>,
}

impl Reach {
    fn point(&mut self, p: P2) {
        if !(p[0].is_finite() && p[1].is_finite()) {
            return;
        }
        let (lo, hi) = self.corners.get_or_insert((p, p));
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }

    fn points(&mut self, points: &[P2]) {
        points.iter().for_each(|p| self.point(*p));
    }

    fn disc(&mut self, center: P2, radius: f64) {
        self.point([center[0] - radius, center[1] - radius]);
        self.point([center[0] + radius, center[1] + radius]);
    }

    fn item(&mut self, item: &Item, grow: f64) {
        match item {
            Item::Stroke(s) => self.points(&s.points),
            Item::Circle { center, radius, .. } => self.disc(*center, *radius),
            Item::Ellipse { center, rx, ry, .. } => self.disc(*center, rx.max(*ry)),
            Item::Text { at, label, .. } => {
                let size = text_size(&label.plain);
                let half = [size[0] * grow / 2.0, size[1] * grow / 2.0];
                self.point([at[0] - half[0], at[1] - half[1]]);
                self.point([at[0] + half[0], at[1] + half[1]]);
            }
            Item::Group { items, .. } | Item::Body { items, .. } => {
                items.iter().for_each(|i| self.item(i, grow));
            }
        }
    }

    fn corners(self) -> Option<(P2, P2)> {
        self.corners
    }
}
