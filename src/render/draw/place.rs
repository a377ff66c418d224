//! Greedy placement of labels: each goes to the first of a few spots around its anchor
//! that overlaps no other label, line or point placed before it.

use super::picture::P2;

/// How far from its anchor a label may go, nearest first.
const GAPS: [f64; 8] = [4.0, 12.0, 22.0, 36.0, 52.0, 72.0, 96.0, 124.0];

/// A box in the picture: centre and half sizes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Box2 {
    /// Centre.
    pub center: P2,
    /// Half width, half height.
    pub half: P2,
}

/// The least space (px) between two labels side by side on one line: closer, `T` beside
/// `O_A` reads as the product `T O_A`.
const BETWEEN_LABELS: f64 = 5.0;

impl Box2 {
    fn overlaps(&self, other: &Box2) -> bool {
        (self.center[0] - other.center[0]).abs() < self.half[0] + other.half[0]
            && (self.center[1] - other.center[1]).abs() < self.half[1] + other.half[1]
    }

    /// Whether another label at `other` overlaps this one or runs into it on its line.
    fn crowds(&self, other: &Box2) -> bool {
        (self.center[0] - other.center[0]).abs() < self.half[0] + other.half[0] + BETWEEN_LABELS
            && (self.center[1] - other.center[1]).abs() < self.half[1] + other.half[1]
    }

    fn meets_segment(&self, a: P2, b: P2) -> bool {
        // Liang–Barsky clipping of the segment against the box.
        let (lo, hi) = (
            [self.center[0] - self.half[0], self.center[1] - self.half[1]],
            [self.center[0] + self.half[0], self.center[1] + self.half[1]],
        );
        let d = [b[0] - a[0], b[1] - a[1]];
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for k in 0..2 {
            for (p, q) in [(-d[k], a[k] - lo[k]), (d[k], hi[k] - a[k])] {
                if p.abs() < 1e-12 {
                    if q < 0.0 {
                        return false;
                    }
                } else {
                    let r = q / p;
                    if p < 0.0 {
                        t0 = t0.max(r);
                    } else {
                        t1 = t1.min(r);
                    }
                }
            }
        }
        t0 <= t1
    }
}

/// What labels must avoid.
#[derive(Clone, Debug, Default)]
pub struct Obstacles {
    /// Lines, each with half its stroke's width.
    segments: Vec<(P2, P2, f64)>,
    boxes: Vec<Box2>,
    labels: Vec<Box2>,
    /// The picture's extent (labels stay inside).
    pub bounds: Option<(P2, P2)>,
}

impl Obstacles {
    /// Nothing to avoid yet; labels stay inside `lo`..`hi`.
    pub fn within(lo: P2, hi: P2) -> Obstacles {
        Obstacles {
            bounds: Some((lo, hi)),
            ..Obstacles::default()
        }
    }

    /// A line to avoid.
    pub fn segment(&mut self, a: P2, b: P2) {
        self.segments.push((a, b, 1.0));
    }

    /// A polyline drawn `width` wide to avoid.
    pub fn wide_polyline(&mut self, points: &[P2], closed: bool, width: f64) {
        let pad = (width / 2.0).max(1.0);
        for w in points.windows(2) {
            self.segments.push((w[0], w[1], pad));
        }
        if closed && points.len() > 2 {
            self.segments
                .push((points[points.len() - 1], points[0], pad));
        }
    }

    /// A polyline to avoid.
    pub fn polyline(&mut self, points: &[P2], closed: bool) {
        for w in points.windows(2) {
            self.segment(w[0], w[1]);
        }
        if closed && points.len() > 2 {
            self.segment(points[points.len() - 1], points[0]);
        }
    }

    /// Room a text at a fixed place takes: labels placed later keep clear of it.
    pub fn reserve(&mut self, center: P2, size: P2) {
        self.labels.push(Box2 {
            center,
            half: [size[0] / 2.0, size[1] / 2.0],
        });
    }

    /// A round spot to avoid.
    pub fn spot(&mut self, at: P2, radius: f64) {
        self.boxes.push(Box2 {
            center: at,
            half: [radius, radius],
        });
    }

    /// Whether a label at `b` would meet nothing: `cost(b) == 0`, answered at the first
    /// thing it meets.
    fn is_clear(&self, b: &Box2) -> bool {
        if let Some((lo, hi)) = self.bounds {
            if b.center[0] - b.half[0] < lo[0]
                || b.center[1] - b.half[1] < lo[1]
                || b.center[0] + b.half[0] > hi[0]
                || b.center[1] + b.half[1] > hi[1]
            {
                return false;
            }
        }
        !(self.labels.iter().any(|o| o.crowds(b))
            || self.boxes.iter().any(|o| o.overlaps(b))
            || self.segments.iter().any(|(p, q, pad)| {
                let wide = Box2 {
                    center: b.center,
                    half: [b.half[0] + pad, b.half[1] + pad],
                };
                wide.meets_segment(*p, *q)
            }))
    }

    fn cost(&self, b: &Box2) -> usize {
        let mut cost = 0;
        if let Some((lo, hi)) = self.bounds {
            if b.center[0] - b.half[0] < lo[0]
                || b.center[1] - b.half[1] < lo[1]
                || b.center[0] + b.half[0] > hi[0]
                || b.center[1] + b.half[1] > hi[1]
            {
                cost += 100;
            }
        }
        cost += 50 * self.labels.iter().filter(|o| o.overlaps(b)).count();
        cost += 5 * self.labels.iter().filter(|o| o.crowds(b)).count();
        cost += 10 * self.boxes.iter().filter(|o| o.overlaps(b)).count();
        cost += self
            .segments
            .iter()
            .filter(|(p, q, pad)| {
                let wide = Box2 {
                    center: b.center,
                    half: [b.half[0] + pad, b.half[1] + pad],
                };
                wide.meets_segment(*p, *q)
            })
            .count();
        cost
    }

    /// The boxes of half size `half` around `anchor`, `gap` clear of it, turning away from
    /// the direction `toward` (radians, picture coordinates) both ways in eighths of a turn.
    fn around(anchor: P2, toward: f64, half: P2, gap: f64) -> impl Iterator<Item = Box2> {
        const TURNS: [f64; 16] = [
            0.0, 0.5, -0.5, 1.0, -1.0, 1.5, -1.5, 2.0, -2.0, 2.5, -2.5, 3.0, -3.0, 3.5, -3.5, 4.0,
        ];
        TURNS.into_iter().map(move |turn| {
            let t = toward + turn * std::f64::consts::FRAC_PI_4;
            let (s, c) = t.sin_cos();
            // Far enough along t that the box clears the anchor by `gap`.
            let reach = gap + (half[0] * c.abs()).max(half[1] * s.abs());
            Box2 {
                center: [anchor[0] + reach * c, anchor[1] + reach * s],
                half,
            }
        })
    }

    fn half_of(size: P2) -> P2 {
        [size[0] / 2.0 + 1.0, size[1] / 2.0 + 1.0]
    }

    /// Every box [`Obstacles::place`] tries for a label of `size` around `anchor`, nearest
    /// and most like `toward` first.
    pub fn spots(anchor: P2, toward: f64, size: P2) -> impl Iterator<Item = Box2> {
        let half = Self::half_of(size);
        GAPS.into_iter()
            .flat_map(move |gap| Self::around(anchor, toward, half, gap))
    }

    /// How much a label at `b` would meet: 0 when nothing.
    pub fn clash(&self, b: &Box2) -> usize {
        self.cost(b)
    }

    /// The first box for a label of `size` around `anchor`, at one of `gaps`, that meets
    /// nothing; nothing is taken.
    pub fn free_near(&self, anchor: P2, toward: f64, size: P2, gaps: &[f64]) -> Option<Box2> {
        let half = Self::half_of(size);
        gaps.iter()
            .flat_map(|&gap| Self::around(anchor, toward, half, gap))
            .find(|b| self.is_clear(b))
    }

    /// Whether the line from `a` to `b` meets a label placed before.
    pub fn crosses_label(&self, a: P2, b: P2) -> bool {
        self.labels.iter().any(|l| l.meets_segment(a, b))
    }

    /// Takes the room of a label at `chosen`; its centre.
    pub fn take(&mut self, chosen: Box2) -> P2 {
        self.labels.push(chosen);
        chosen.center
    }

    /// Places a label of `size` (width, height) near `anchor`, preferring the direction
    /// `toward` (radians, picture coordinates); returns its centre and takes its room.
    pub fn place(&mut self, anchor: P2, toward: f64, size: P2) -> P2 {
        let half = Self::half_of(size);
        let mut best: Option<(usize, Box2)> = None;
        for gap in GAPS {
            for candidate in Self::around(anchor, toward, half, gap) {
                let cost = self.cost(&candidate);
                if best.as_ref().is_none_or(|(c, _)| cost < *c) {
                    best = Some((cost, candidate));
                }
                if cost == 0 {
                    break;
                }
            }
            if best.as_ref().is_some_and(|(c, _)| *c == 0) {
                break;
            }
        }
        if best.as_ref().is_some_and(|(c, _)| *c > 0) {
            // Crowded round the anchor: the free spot nearest to it anywhere in the picture.
            if let Some(free) = self.nearest_free(anchor, half) {
                best = Some((0, free));
            }
        }
        let chosen = best.map(|(_, b)| b).unwrap_or(Box2 {
            center: anchor,
            half,
        });
        self.take(chosen)
    }
}

impl Obstacles {
    /// Places a label of `size` close to `anchor`, at one of the first `gaps` of
    /// [`GAPS`]: the first spot there that meets nothing, else the free one nearest to it
    /// within a gap further (on a fine grid), else the free one nearest anywhere in the
    /// picture (a caption a little away from its point rather than over a line), else the
    /// one of the first `gaps` that meets least; returns its centre and takes its room.
    pub fn place_close(&mut self, anchor: P2, toward: f64, size: P2, gaps: usize) -> P2 {
        let half = Self::half_of(size);
        let mut best: Option<(usize, Box2)> = None;
        for gap in GAPS.into_iter().take(gaps) {
            for candidate in Self::around(anchor, toward, half, gap) {
                let cost = self.cost(&candidate);
                if cost == 0 {
                    return self.take(candidate);
                }
                if best.as_ref().is_none_or(|(c, _)| cost < *c) {
                    best = Some((cost, candidate));
                }
            }
        }
        if let Some(&gap) = GAPS.get(gaps) {
            if let Some(b) = self.free_within(anchor, half, gap) {
                return self.take(b);
            }
        }
        // Nothing free close by: a name further off reads; one over a line does not.
        if let Some(b) = self.nearest_free(anchor, half) {
            return self.take(b);
        }
        let chosen = best.map_or(
            Box2 {
                center: anchor,
                half,
            },
            |(_, b)| b,
        );
        self.take(chosen)
    }

    /// A free spot for a label of `size` that should stay beside `anchor` (an angle's
    /// name by its arc, a unit vector's by its arrow's tip): the first free spot at a
    /// small gap around it, most like `toward` first; else the free one nearest to it
    /// within `reach`; `None` when nothing close is free (then the label is placed as any
    /// other, off what it would lie over). Takes its room.
    pub fn place_beside(&mut self, anchor: P2, toward: f64, size: P2, reach: f64) -> Option<P2> {
        let half = Self::half_of(size);
        let free = self
            .free_near(anchor, toward, size, &[2.0, 6.0, 12.0])
            .or_else(|| self.free_within(anchor, half, reach))?;
        Some(self.take(free))
    }

    /// The box of half size `half` that meets nothing and whose edge is nearest to
    /// `anchor`, no further than `reach` from it, on a fine grid round the anchor (the
    /// gaps between lines that the sixteen directions of [`Obstacles::around`] miss).
    fn free_within(&self, anchor: P2, half: P2, reach: f64) -> Option<Box2> {
        const STEP: f64 = 2.0;
        let steps = |h: f64| ((h + reach) / STEP).floor() as i64;
        let (nx, ny) = (steps(half[0]), steps(half[1]));
        let mut best: Option<(f64, Box2)> = None;
        for j in -ny..=ny {
            for i in -nx..=nx {
                let offset = [i as f64 * STEP, j as f64 * STEP];
                let dx = (offset[0].abs() - half[0]).max(0.0);
                let dy = (offset[1].abs() - half[1]).max(0.0);
                // The edge's distance first, then the centre's: nearest and most even.
                let d = dx.hypot(dy) + 1e-3 * offset[0].hypot(offset[1]);
                if dx.hypot(dy) > reach || best.as_ref().is_some_and(|(b, _)| d >= *b) {
                    continue;
                }
                let candidate = Box2 {
                    center: [anchor[0] + offset[0], anchor[1] + offset[1]],
                    half,
                };
                if self.is_clear(&candidate) {
                    best = Some((d, candidate));
                }
            }
        }
        best.map(|(_, b)| b)
    }

    /// The box of half size `half` nearest to `anchor` that meets nothing, on a grid over
    /// the picture's bounds.
    fn nearest_free(&self, anchor: P2, half: P2) -> Option<Box2> {
        let (lo, hi) = self.bounds?;
        const STEP: f64 = 6.0;
        let mut best: Option<(f64, Box2)> = None;
        let mut y = lo[1] + half[1];
        while y <= hi[1] - half[1] {
            let mut x = lo[0] + half[0];
            while x <= hi[0] - half[0] {
                let d = (x - anchor[0]).hypot(y - anchor[1]);
                if best.as_ref().is_none_or(|(b, _)| d < *b) {
                    let candidate = Box2 {
                        center: [x, y],
                        half,
                    };
                    if self.is_clear(&candidate) {
                        best = Some((d, candidate));
                    }
                }
                x += STEP;
            }
            y += STEP;
        }
        best.map(|(_, b)| b)
    }
}

/// The size of a label's plain text at the font size the pictures use.
pub fn text_size(plain: &str) -> P2 {
    let mut width = 0.0f64;
    let mut small = false;
    for c in plain.chars() {
        match c {
            '^' | '_' => small = true,
            ' ' => {
                small = false;
                width += 3.5;
            }
            // An italic capital (and m, w) is wider than a lower-case letter: O is 6.7 pt
            // at 8 pt, O_B 12.8 pt, B^* 11.1 pt, x 4.6 pt; a comma and the space after it
            // 5.2 pt in all (13 px to 8 pt).
            ',' => width += 5.0,
            '*' if small => width += 7.0,
            c if c.is_ascii_uppercase() || c == 'm' || c == 'w' => {
                width += if small { 10.0 } else { 11.0 };
            }
            _ => width += if small { 6.0 } else { 8.0 },
        }
    }
    // Scripts reach above and below the letters' line: room for both.
    let scripted = plain.contains(['^', '_']);
    [width.max(6.0) + 4.0, if scripted { 21.0 } else { 16.0 }]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `is_clear` says `cost == 0` for boxes on a grid over a picture with a line, a spot,
    /// a label and its bounds: free, on each obstacle alone, and out of bounds.
    #[test]
    fn clear_is_no_cost() {
        let mut obstacles = Obstacles::within([0.0, 0.0], [100.0, 60.0]);
        obstacles.wide_polyline(&[[10.0, 10.0], [90.0, 50.0]], false, 3.0);
        obstacles.spot([20.0, 45.0], 4.0);
        obstacles.reserve([70.0, 12.0], [16.0, 10.0]);
        let (mut clear, mut met) = (0, 0);
        for i in 0..=25 {
            for j in 0..=15 {
                let b = Box2 {
                    center: [i as f64 * 4.0, j as f64 * 4.0],
                    half: [5.0, 3.0],
                };
                assert_eq!(obstacles.is_clear(&b), obstacles.cost(&b) == 0, "{b:?}");
                if obstacles.is_clear(&b) {
                    clear += 1;
                } else {
                    met += 1;
                }
            }
        }
        // Both kinds occur, so the comparison above is not empty on either side.
        assert!(clear > 50 && met > 50, "{clear} clear, {met} met");
    }
}
