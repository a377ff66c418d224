//! A frame's unit vectors on the page: two or three short grey arrows from one origin,
//! moved off any body outline, pin, line or label they would lie on to the nearest clear
//! spot, and drawn as one group (`<g class="triad">`).

use super::super::numbers::P3;
use super::super::picture::{Ink, Item, P2};
use super::super::place::Box2;
use super::super::scene::Label;
use super::super::strokes::{head, p2add, p2norm, p2scale};
use super::Painter;

/// The length of a unit vector's arrow on the page.
const LENGTH: f64 = 24.0;
/// Room kept around the arrows (their heads and a margin).
const MARGIN: f64 = 5.0;
/// The room kept round another frame's arrows for the names at their tips.
const NAMES: f64 = 16.0;
/// Half the room (px) a unit vector's name takes beyond its arrow's tip.
const TIP_NAME: f64 = 9.0;
/// How far the origin may move, nearest first.
const SHIFTS: [f64; 10] = [0.0, 6.0, 12.0, 18.0, 26.0, 36.0, 48.0, 62.0, 80.0, 100.0];

impl Painter {
    /// The unit vectors `axes` at `origin` (`None`: in the picture's lower left corner).
    pub(super) fn triad(&mut self, origin: Option<P3>, axes: &[(P3, Label)]) {
        let wanted = match origin {
            Some(p) => self.at(p),
            // In 3D, room left and below for the names at the tips (n̂_x's, down left).
            None => {
                let room = if axes.len() > 2 {
                    [46.0, 40.0]
                } else {
                    [22.0, 30.0]
                };
                [
                    self.shift[0] + room[0],
                    self.obstacles.bounds.map_or(300.0, |b| b.1[1]) - room[1],
                ]
            }
        };
        let arrows: Vec<(P2, &Label)> = axes
            .iter()
            .map(|(direction, label)| {
                let d = p2scale(self.projection.direction(*direction), 1.0 / self.scale);
                (d, label)
            })
            .filter(|(d, _)| p2norm(*d) >= 0.2)
            .collect();
        let directions: Vec<P2> = arrows.iter().map(|(d, _)| *d).collect();
        let o = self.clear_origin(wanted, &directions);
        let outside = std::mem::take(&mut self.items);
        for (d, label) in arrows {
            let tip = p2add(o, p2scale(d, LENGTH));
            let u = p2scale(d, 1.0 / p2norm(d));
            self.stroke(vec![o, tip], 0.9, Ink::Grey, None, false);
            self.stroke(head(tip, u).to_vec(), 0.6, Ink::Grey, Some(Ink::Grey), true);
            self.pending.push((
                tip,
                u[1].atan2(u[0]),
                label.clone(),
                Ink::Grey,
                super::labels::Beside::Axis,
            ));
        }
        let items = std::mem::replace(&mut self.items, outside);
        self.items.push(Item::Group {
            class: "triad",
            items,
        });
    }

    /// The origin nearest `wanted` whose arrows' box meets nothing drawn; the least
    /// crowded one tried when none is clear.
    fn clear_origin(&self, wanted: P2, directions: &[P2]) -> P2 {
        let sum = directions
            .iter()
            .fold([0.0, 0.0], |s, d| [s[0] + d[0], s[1] + d[1]]);
        // Away from where the arrows point first: an arrow pointing into a bar is moved
        // back out of it.
        let toward = (-sum[1]).atan2(-sum[0]);
        let mut best = (usize::MAX, wanted);
        for gap in SHIFTS {
            for k in 0..16 {
                let turn = if k % 2 == 0 { k / 2 } else { 16 - k / 2 - 1 };
                let t = toward + f64::from(turn as u8) * std::f64::consts::PI / 8.0;
                let o = [wanted[0] + gap * t.cos(), wanted[1] + gap * t.sin()];
                let room = Self::triad_box(o, directions);
                let cost = self.obstacles.clash(&room)
                    + Self::names_room(o, directions)
                        .iter()
                        .map(|b| self.obstacles.clash(b))
                        .sum::<usize>()
                    + 10 * self.over_bodies(&room)
                    + 10 * self.under_ground(&room)
                    + 10 * self.over_triads(&room);
                if cost == 0 {
                    return o;
                }
                if cost < best.0 {
                    best = (cost, o);
                }
                if gap == 0.0 {
                    break;
                }
            }
        }
        best.1
    }

    /// How many of the triads drawn before, with the room round their tips that their
    /// names will take, `room` meets: two frames' unit vectors (a rack's and its pinion's)
    /// stand apart, their names not mixed.
    fn over_triads(&self, room: &Box2) -> usize {
        (self.items.iter())
            .filter_map(|item| match item {
                Item::Group {
                    class: "triad",
                    items,
                } => Some(items),
                _ => None,
            })
            .filter(|items| {
                let points = items.iter().flat_map(|i| match i {
                    Item::Stroke(s) => s.points.clone(),
                    _ => Vec::new(),
                });
                let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
                for p in points {
                    for k in 0..2 {
                        lo[k] = lo[k].min(p[k]);
                        hi[k] = hi[k].max(p[k]);
                    }
                }
                (0..2).all(|k| {
                    lo[k] - NAMES < room.center[k] + room.half[k]
                        && room.center[k] - room.half[k] < hi[k] + NAMES
                })
            })
            .count()
    }

    /// How many points of a grid over `room` fall inside a body.
    fn over_bodies(&self, room: &Box2) -> usize {
        const STEPS: usize = 6;
        let mut count = 0;
        for i in 0..=STEPS {
            for j in 0..=STEPS {
                let f = |k: usize, axis: usize| {
                    room.center[axis] + room.half[axis] * (2.0 * k as f64 / STEPS as f64 - 1.0)
                };
                let p = [f(i, 0), f(j, 1)];
                if self.items.iter().any(|item| super::beside::inside(item, p)) {
                    count += 1;
                }
            }
        }
        count
    }

    /// The room a name takes beyond each arrow's tip, so that the origin chosen leaves
    /// every name beside its own arrow.
    fn names_room(o: P2, directions: &[P2]) -> Vec<Box2> {
        directions
            .iter()
            .map(|d| {
                let u = p2scale(*d, 1.0 / p2norm(*d));
                Box2 {
                    center: p2add(o, p2scale(u, LENGTH + TIP_NAME)),
                    half: [TIP_NAME, 0.8 * TIP_NAME],
                }
            })
            .collect()
    }

    /// The box the arrows from `o` along `directions` take, with their heads.
    pub(super) fn triad_box(o: P2, directions: &[P2]) -> Box2 {
        let (mut lo, mut hi) = (o, o);
        for d in directions {
            let tip = p2add(o, p2scale(*d, LENGTH));
            for k in 0..2 {
                lo[k] = lo[k].min(tip[k]);
                hi[k] = hi[k].max(tip[k]);
            }
        }
        Box2 {
            center: [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0],
            half: [
                (hi[0] - lo[0]) / 2.0 + MARGIN,
                (hi[1] - lo[1]) / 2.0 + MARGIN,
            ],
        }
    }
}
