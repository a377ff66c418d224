//! Where `motion.svg`'s words go, frame by frame. Each label is tried at the spots the
//! still picture tries around its anchor ([`Obstacles::spots`]), against everything drawn
//! at that frame: the bodies, the ground and floors, the springs and dampers, the
//! coordinates' marks, the points and the labels placed before it. It keeps the spot that
//! is clear over the most frames, and goes elsewhere only at the frames where that one is
//! taken, so that it stays put as far as the motion lets it.

use super::motion::{Motion, TITLE_STRIP};
use super::picture::P2;
use super::place::{text_size, Box2, Obstacles};

/// Everything of the motion drawn in lines besides the bodies, in the picture: what is
/// written, and what the labels keep clear of.
pub(super) struct Lines {
    pub(super) floors: Vec<super::motion_marks::Floor>,
    pub(super) ground: Ground,
    /// Per spring, per frame: its zig-zag.
    pub(super) springs: Vec<Vec<Vec<P2>>>,
    /// Per damper, per frame: its pieces.
    pub(super) dampers: Vec<Vec<Vec<Vec<P2>>>>,
    /// Per coordinate's mark, per frame.
    pub(super) marks: Vec<Vec<super::motion_marks::Drawn>>,
}

/// The fixed ground: each support's pieces (whether each closes), and each rolling
/// contact's track.
pub(super) struct Ground {
    pub(super) supports: Vec<Vec<(Vec<P2>, bool)>>,
    pub(super) tracks: Vec<Vec<P2>>,
}

/// Each label's centre per frame: the marks' labels, then the points' captions (`None`
/// for a point without one).
pub(super) struct Placed {
    pub(super) gauges: Vec<Vec<P2>>,
    pub(super) captions: Vec<Option<Vec<P2>>>,
}

/// Where a mass centre's name would go (above right) and a joint's coordinates (below
/// right), in radians on the page.
const NAME_TOWARD: f64 = -0.52;
const COORDINATES_TOWARD: f64 = std::f64::consts::FRAC_PI_4;

/// The spots close to their anchor, the first of [`Obstacles::spots`] (three gaps of
/// sixteen directions): a label that no steady close spot keeps clear moves among them
/// rather than stand far from what it names.
const NEAR: usize = 48;

/// Places every label of the motion clear of `lines`, the bodies and the points.
pub(super) fn place(motion: &Motion, lines: &Lines) -> Placed {
    let mut clear = obstacles(motion, lines);
    let gauges = motion
        .gauges
        .iter()
        .zip(&lines.marks)
        .map(|(label, frames)| {
            let wanted: Vec<(P2, f64)> = frames.iter().map(|d| (d.anchor, d.toward)).collect();
            place_one(&mut clear, &wanted, text_size(&label.plain))
        })
        .collect();
    let p = &motion.projection;
    let captions = motion
        .points
        .iter()
        .zip(&motion.captions)
        .enumerate()
        .map(|(i, ((_, center), caption))| {
            let caption = caption.as_ref()?;
            let toward = if *center {
                NAME_TOWARD
            } else {
                COORDINATES_TOWARD
            };
            let wanted: Vec<(P2, f64)> = motion
                .frames
                .iter()
                .map(|f| (p.point(f.points[i]), toward))
                .collect();
            Some(place_one(&mut clear, &wanted, text_size(caption)))
        })
        .collect();
    Placed { gauges, captions }
}

/// What labels keep clear of at each frame.
fn obstacles(motion: &Motion, lines: &Lines) -> Vec<Obstacles> {
    let p = &motion.projection;
    let [width, height] = motion.size;
    let mut fixed = Obstacles::within([0.0, TITLE_STRIP], [width, height]);
    for floor in &lines.floors {
        fixed.wide_polyline(&floor.outline, true, 1.0);
        for tick in &floor.ticks {
            fixed.segment(tick[0], tick[1]);
        }
    }
    for pieces in &lines.ground.supports {
        for (points, closed) in pieces {
            fixed.wide_polyline(points, *closed, 1.2);
        }
    }
    for track in &lines.ground.tracks {
        fixed.wide_polyline(track, false, 1.2);
    }
    motion
        .frames
        .iter()
        .enumerate()
        .map(|(f, frame)| {
            let mut clear = fixed.clone();
            for s in 0..motion.sheets.len() {
                for (points, closed, width) in super::motion_bodies::sheet_lines(motion, f, s) {
                    clear.wide_polyline(&points, closed, width);
                }
            }
            for body in &motion.bodies {
                if let Some(at) = body.ball.and_then(|i| frame.points.get(i)) {
                    clear.spot(p.point(*at), 7.0);
                }
            }
            let at_frame = |frames: &Vec<Vec<Vec<P2>>>| frames.get(f).cloned().unwrap_or_default();
            for spring in &lines.springs {
                if let Some(points) = spring.get(f) {
                    clear.wide_polyline(points, false, 1.4);
                }
            }
            for damper in &lines.dampers {
                for part in at_frame(damper) {
                    clear.wide_polyline(&part, false, 1.4);
                }
            }
            for mark in lines.marks.iter().filter_map(|m| m.get(f)) {
                for dashed in &mark.dashed {
                    clear.polyline(dashed, false);
                }
                clear.polyline(&mark.line, false);
                for head in &mark.heads {
                    clear.polyline(head, true);
                }
            }
            for (at, (_, center)) in frame.points.iter().zip(&motion.points) {
                clear.spot(p.point(*at), if *center { 5.0 } else { 4.0 });
            }
            clear
        })
        .collect()
}

/// Places one label of `size` that would go beside `wanted` (per frame: anchor and
/// direction), and takes its room at every frame; its centre per frame.
fn place_one(clear: &mut [Obstacles], wanted: &[(P2, f64)], size: P2) -> Vec<P2> {
    // Per frame, every spot tried and what it meets there.
    let tried: Vec<Vec<(Box2, usize)>> = wanted
        .iter()
        .zip(clear.iter())
        .map(|(&(anchor, toward), obstacles)| {
            Obstacles::spots(anchor, toward, size)
                .map(|b| (b, obstacles.clash(&b)))
                .collect()
        })
        .collect();
    let count = tried.first().map_or(0, Vec::len);
    // The spots in the order they are liked: those close to the anchor first, then clear
    // over the most frames, then meeting the least, then as the still picture likes them.
    let mut ranking: Vec<usize> = (0..count).collect();
    ranking.sort_by_key(|&k| {
        let costs = tried.iter().map(|frame| frame[k].1);
        (
            k >= NEAR,
            costs.clone().filter(|&c| c > 0).count(),
            costs.sum::<usize>(),
        )
    });
    let Some(&best) = ranking.first() else {
        return wanted.iter().map(|w| w.0).collect();
    };
    let mut current = best;
    let mut centres = Vec::with_capacity(tried.len());
    for (frame, obstacles) in tried.iter().zip(clear.iter_mut()) {
        let free = |k: usize| frame[k].1 == 0;
        current = if free(best) {
            best
        } else if free(current) {
            current
        } else {
            ranking
                .iter()
                .copied()
                .find(|&k| free(k))
                .or_else(|| ranking.iter().copied().min_by_key(|&k| frame[k].1))
                .unwrap_or(best)
        };
        centres.push(obstacles.take(frame[current].0));
    }
    centres
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_label_keeps_to_a_side_that_stays_clear_over_the_motion() {
        // A label would go right of a fixed point; a vertical line passes through that
        // side at the middle frame only.
        let anchor = [100.0, 100.0];
        let size = text_size("x");
        let line = |o: &mut Obstacles| o.segment([110.0, 0.0], [110.0, 200.0]);
        let mut clear: Vec<Obstacles> = (0..3)
            .map(|_| Obstacles::within([0.0, 0.0], [200.0, 200.0]))
            .collect();
        line(&mut clear[1]);
        let centres = place_one(&mut clear, &[(anchor, 0.0); 3], size);
        assert!(centres.iter().all(|c| *c == centres[0]), "{centres:?}");
        let mut again = Obstacles::within([0.0, 0.0], [200.0, 200.0]);
        line(&mut again);
        let b = Box2 {
            center: centres[0],
            half: [size[0] / 2.0, size[1] / 2.0],
        };
        assert_eq!(again.clash(&b), 0, "{centres:?}");
        // Its room is taken at every frame.
        assert!(clear.iter().all(|o| o.clash(&b) > 0));
    }
}
