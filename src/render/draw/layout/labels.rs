//! Placing the labels of a panel once everything else in it is drawn: beside an arrow's
//! tip (pushing the arrow out along its line where the tip is crowded), or at the nearest
//! free spot.

use super::super::picture::{DrawnArrow, Item, P2};
use super::super::place::{Box2, Obstacles};
use super::super::strokes::{head, p2add, p2norm, p2scale, p2unit, tips_of};
use super::Painter;

/// What a waiting label stands beside.
#[derive(Clone, Copy, Debug)]
pub(super) enum Beside {
    /// The tip of the picture's arrow of this index.
    Arrow(usize),
    /// A point on a body's edge (a pin, a contact; the index of its marker): outside the
    /// bodies where there is room, else on its own body's side, not inside another's.
    Point(usize),
    /// Its anchor, wherever is free.
    Spot,
    /// A point's caption (a mass centre's; the index of its marker): close beside it,
    /// out of the bodies it does not belong to where there is room, even over a line,
    /// never far from what it names.
    Caption(usize),
    /// A unit vector's name: close by its arrow's tip, never far from it.
    Axis,
    /// An angle's name: beside the middle of its arc, never far from it, and not inside
    /// a body but the one its arc is drawn about (whose centre this is).
    Arc(P2),
    /// A couple's label: close by its curl where there is room (within 36 px), else the
    /// nearest free spot.
    Near,
}

/// How far from its anchor a couple's label is first looked for.
const NEAR_A_CURL: [f64; 4] = [4.0, 12.0, 22.0, 36.0];

/// How far (px) from its arrow's tip a unit vector's name may stand.
const NEAR_A_TIP: f64 = 16.0;

/// How far (px) from the middle of its arc an angle's name may stand.
const NEAR_AN_ARC: f64 = 22.0;

/// How many of the gaps around its point a caption may take (up to 22 px from it).
const CAPTION_GAPS: usize = 3;

/// How many of the spots nearest a point's caption are tried outside the bodies: two
/// rounds of sixteen directions, within 12 px of the point.
const NEAR_A_POINT: usize = 32;

impl Painter {
    /// Places the waiting labels, in the order they came, around everything drawn: an
    /// arrow's label beside its tip, or beside the tip pushed out along the arrow's line
    /// when the room there is taken; any label else at the nearest free spot.
    pub(super) fn place_labels(&mut self, arrows: &mut [DrawnArrow]) {
        for (anchor, toward, label, ink, beside) in std::mem::take(&mut self.pending) {
            let size = self.room(&label.plain);
            let tips = tips_of(arrows);
            let pushed = match beside {
                Beside::Arrow(k) => arrows
                    .get_mut(k)
                    .and_then(|a| self.push_apart(a, toward, size, &tips)),
                Beside::Point(k) => self.outside_bodies((anchor, toward), size, k, &tips),
                Beside::Caption(k) => self.off_other_bodies((anchor, toward), size, k, &tips),
                Beside::Near => (self.obstacles)
                    .free_near(anchor, toward, size, &NEAR_A_CURL)
                    .map(|b| self.obstacles.take(b)),
                Beside::Arc(center) => self
                    .beside_arc(anchor, toward, size, center)
                    .or_else(|| (self.obstacles).place_beside(anchor, toward, size, NEAR_AN_ARC)),
                Beside::Axis => (self.obstacles).place_beside(anchor, toward, size, NEAR_A_TIP),
                Beside::Spot => None,
            };
            let close = matches!(beside, Beside::Point(_) | Beside::Caption(_) | Beside::Axis);
            let at = match pushed {
                Some(at) => at,
                None if close => (self.obstacles).place_close(anchor, toward, size, CAPTION_GAPS),
                None => self.obstacles.place(anchor, toward, size),
            };
            self.texts.push(Item::Text { at, label, ink });
        }
    }

    /// The place of a straight arrow's label of `size` close beside its tip; when there is
    /// none, the arrow is made longer along its own line, a step at a time, until there is
    /// (its new end crossing no label, nor within a head's length of another arrow's tip,
    /// `tips`). `None` when neither serves.
    fn push_apart(
        &mut self,
        arrow: &mut DrawnArrow,
        toward: f64,
        size: P2,
        tips: &[P2],
    ) -> Option<P2> {
        /// The least distance between two tips, a head's length and a little.
        const APART: f64 = 12.0;
        const NEAR: [f64; 3] = [4.0, 12.0, 22.0];
        if arrow.arc.is_some() {
            return None;
        }
        if let Some(free) = self.obstacles.free_near(arrow.head, toward, size, &NEAR) {
            return Some(self.obstacles.take(free));
        }
        let u = p2unit([arrow.head[0] - arrow.tail[0], arrow.head[1] - arrow.tail[1]])?;
        for step in [14.0, 28.0, 42.0, 56.0] {
            let tip = p2add(arrow.head, p2scale(u, step * self.reach));
            if self.obstacles.crosses_label(arrow.head, tip) {
                return None;
            }
            // Nor across another arrow (a weight drawn aside next to a pin's force).
            if tips
                .iter()
                .any(|t| p2norm([t[0] - tip[0], t[1] - tip[1]]) < APART)
                || self.crossings(arrow.tail, tip) > 0
            {
                continue;
            }
            // The longer arrow first, so that its label keeps clear of it too.
            let mut heads = vec![head(tip, u)];
            if arrow.heads.len() > 1 {
                heads.push(head(p2add(tip, p2scale(u, -7.0)), u));
            }
            let mut longer = self.obstacles.clone();
            longer.segment(arrow.head, tip);
            for h in &heads {
                longer.polyline(h, true);
            }
            let Some(free) = longer.free_near(tip, toward, size, &NEAR[..2]) else {
                continue;
            };
            self.obstacles = longer;
            arrow.head = tip;
            arrow.heads = heads;
            return Some(self.obstacles.take(free));
        }
        None
    }

    /// The first free spot for a label of `size` close around a point on a body's edge
    /// whose middle lies outside every body (a contact's name below the wheel, not inside
    /// it), else outside every body but those the point (marker `k`) belongs to (a rack's
    /// joint under the pinion: on the rack's side); `None` when none is free there.
    fn outside_bodies(
        &mut self,
        (anchor, toward): (P2, f64),
        size: P2,
        k: usize,
        tips: &[P2],
    ) -> Option<P2> {
        let spots = || {
            Obstacles::spots(anchor, toward, size)
                .take(NEAR_A_POINT)
                .filter(|b| !by_a_tip(b, anchor, tips))
        };
        let free = spots()
            .find(|b| {
                self.obstacles.clash(b) == 0
                    && !(self.items.iter()).any(|item| super::beside::inside(item, b.center))
            })
            .or_else(|| spots().find(|b| self.free_of_others(b, k)))?;
        Some(self.obstacles.take(free))
    }

    /// The first free spot for an angle's name of `size` close around the middle of its
    /// arc (`anchor`) that lies in no body but those holding the arc's `center` (a
    /// pinion's angle inside or beside the pinion, not on the gear it meshes with);
    /// `None` when none is free there.
    fn beside_arc(&mut self, anchor: P2, toward: f64, size: P2, center: P2) -> Option<P2> {
        let foreign = |p: P2| {
            (self.items.iter())
                .any(|item| super::beside::inside(item, p) && !super::beside::inside(item, center))
        };
        let free = Obstacles::spots(anchor, toward, size)
            .take(16 * CAPTION_GAPS)
            .find(|b| self.obstacles.clash(b) == 0 && !foreign(b.center))?;
        Some(self.obstacles.take(free))
    }

    /// The first free spot for a mass centre's caption of `size` close around it (within
    /// [`CAPTION_GAPS`] of it) whose middle lies in no body but the point's own (marker
    /// `k`); `None` when none is free there.
    fn off_other_bodies(
        &mut self,
        (anchor, toward): (P2, f64),
        size: P2,
        k: usize,
        tips: &[P2],
    ) -> Option<P2> {
        let free = Obstacles::spots(anchor, toward, size)
            .take(16 * CAPTION_GAPS)
            .find(|b| !by_a_tip(b, anchor, tips) && self.free_of_others(b, k))?;
        Some(self.obstacles.take(free))
    }

    /// Whether a label at `b` meets nothing and its middle lies in no body that marker `k`
    /// does not belong to.
    fn free_of_others(&self, b: &super::super::place::Box2, k: usize) -> bool {
        let own = self.owners.get(k).map(Vec::as_slice).unwrap_or_default();
        let foreign = |id: &str| !own.iter().any(|name| id.ends_with(&format!("body-{name}")));
        self.obstacles.clash(b) == 0
            && !(self.items.iter()).any(|item| match item {
                Item::Body { id, .. } => foreign(id) && super::beside::inside(item, b.center),
                _ => false,
            })
    }
}

/// Closer than this (px) to an arrow's tip, a point's name reads as that arrow's label.
const OFF_A_TIP: f64 = 8.0;

/// Whether a point's name at `b` stands by the tip of an arrow that does not end at its
/// point `anchor` (a contact's name at the tip of the weight above it).
fn by_a_tip(b: &Box2, anchor: P2, tips: &[P2]) -> bool {
    tips.iter()
        .filter(|t| p2norm([t[0] - anchor[0], t[1] - anchor[1]]) > 3.0)
        .any(|t| {
            let dx = ((t[0] - b.center[0]).abs() - b.half[0]).max(0.0);
            let dy = ((t[1] - b.center[1]).abs() - b.half[1]).max(0.0);
            dx.hypot(dy) < OFF_A_TIP
        })
}
