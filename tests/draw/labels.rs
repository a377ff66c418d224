//! Every label stands at what it names, and nothing of a free body is drawn over anything
//! else of it: for every picture of every bundled problem (collar on a spinning shaft
//! included), by the Motion Law and by Newton–Euler, as drawn (SVG) and, for the handouts
//! an instructor reviewed, as their pages print them (smaller, the labels at their size in
//! points), each point's caption lies
//! within a few pixels of its point, each unit vector's name by its arrow's tip, no two
//! labels overlap, no label lies over an arrow, no two straight arrows cross (arrows that
//! meet at an end, two components at one pin, do not cross), and no weight runs over
//! another force on its line (a normal force arriving at a contact the weight reaches).

use super::drawings;
use crate::support::all_problems;
use mbd_tutor::equations::Method;
use mbd_tutor::render::draw::{
    text_size, Drawing, Item, Kind, Picture, Scene, View, ABOVE_A_TABLE, BESIDE_A_TABLE,
    CONFIGURATION,
};

/// How far (px) from its point a caption's box may be: 22 px where there is room, 36 px
/// where every spot that close would lie over a line, and the box's margin.
const NEAR: f64 = 40.0;
/// How far (px) at each end of an arrow another may meet it without crossing it.
const END: f64 = 6.0;
/// How far (px at 13 px labels) from its arrow's tip a unit vector's name may stand.
const NEAR_A_TIP: f64 = 40.0;
/// The least gap (px at 13 px labels) between a weight's line and another force's
/// parallel line where the two arrows lie within an arrow's length of each other.
const APART: f64 = 7.0;

type P2 = [f64; 2];

/// A label's box: centre and half size (a pixel less each way than the room it was
/// given, so that two labels set edge to edge do not count as overlapping).
#[derive(Clone, Copy, Debug)]
struct Box2 {
    center: P2,
    half: P2,
}

impl Box2 {
    /// The box of a label of `plain` text at `at`, its room `grow` times that at 13 px.
    fn of(at: P2, plain: &str, grow: f64) -> Box2 {
        let size = text_size(plain);
        Box2 {
            center: at,
            half: [grow * size[0] / 2.0 - 1.0, grow * size[1] / 2.0 - 2.0],
        }
    }

    fn distance_to(&self, p: P2) -> f64 {
        let dx = ((p[0] - self.center[0]).abs() - self.half[0]).max(0.0);
        let dy = ((p[1] - self.center[1]).abs() - self.half[1]).max(0.0);
        dx.hypot(dy)
    }

    /// Whether `o` stands beside this label on its line closer than a space (2 px at
    /// 13 px labels): the two read as one product (`T O_A`).
    fn runs_into(&self, o: &Box2, grow: f64) -> bool {
        let gap = (self.center[0] - o.center[0]).abs() - (self.half[0] + 1.0) - (o.half[0] + 1.0);
        let level = (self.center[1] - o.center[1]).abs() < self.half[1] + o.half[1];
        level && gap < 2.0 * grow
    }

    fn overlaps(&self, o: &Box2) -> bool {
        (self.center[0] - o.center[0]).abs() < self.half[0] + o.half[0]
            && (self.center[1] - o.center[1]).abs() < self.half[1] + o.half[1]
    }

    /// Whether the segment `a`–`b` passes through the box (sampled every half pixel).
    fn meets(&self, a: P2, b: P2) -> bool {
        let steps = ((b[0] - a[0]).hypot(b[1] - a[1]) * 2.0).ceil().max(1.0) as usize;
        (0..=steps).any(|k| {
            let t = k as f64 / steps as f64;
            self.distance_to([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]) == 0.0
        })
    }
}

/// The part of a segment `END` in from each end (`None` when it is shorter than that).
fn middle(a: P2, b: P2) -> Option<(P2, P2)> {
    let length = (b[0] - a[0]).hypot(b[1] - a[1]);
    if length <= 2.0 * END {
        return None;
    }
    let u = [(b[0] - a[0]) / length, (b[1] - a[1]) / length];
    Some((
        [a[0] + END * u[0], a[1] + END * u[1]],
        [b[0] - END * u[0], b[1] - END * u[1]],
    ))
}

/// Whether two segments cross (properly: each one's ends on either side of the other).
fn cross((a, b): (P2, P2), (c, d): (P2, P2)) -> bool {
    let side = |p: P2, q: P2, r: P2| (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    side(a, b, c) * side(a, b, d) < 0.0 && side(c, d, a) * side(c, d, b) < 0.0
}

/// The labels of a picture (its title and legend left out), as (plain text, box).
fn labels(picture: &Picture) -> Vec<(String, Box2)> {
    let texts = &picture.texts;
    let last = texts.len() - picture.legend.lines;
    (texts[1..last].iter())
        .filter_map(|t| match t {
            Item::Text { at, label, .. } => Some((
                label.plain.clone(),
                Box2::of(*at, &label.plain, picture.grow),
            )),
            _ => None,
        })
        .collect()
}

/// The tips of the unit vectors' arrows (each triad's lines, from its origin).
fn triad_tips(picture: &Picture) -> Vec<P2> {
    (picture.items.iter())
        .filter_map(|item| match item {
            Item::Group { class, items } if *class == "triad" => Some(items),
            _ => None,
        })
        .flatten()
        .filter_map(|item| match item {
            Item::Stroke(s) if !s.closed && s.points.len() == 2 => Some(s.points[1]),
            _ => None,
        })
        .collect()
}

/// Whether two straight arrows `a` and `b` lie on one line: parallel within 10°, their
/// lines closer than `gap`, and the two within an arrow's length of each other along it.
fn on_one_line((a0, a1): (P2, P2), (b0, b1): (P2, P2), gap: f64) -> bool {
    let length = (a1[0] - a0[0]).hypot(a1[1] - a0[1]);
    let other = (b1[0] - b0[0]).hypot(b1[1] - b0[1]);
    if length < 1.0 || other < 1.0 {
        return false;
    }
    let u = [(a1[0] - a0[0]) / length, (a1[1] - a0[1]) / length];
    let v = [(b1[0] - b0[0]) / other, (b1[1] - b0[1]) / other];
    if (u[0] * v[0] + u[1] * v[1]).abs() < 10f64.to_radians().cos() {
        return false;
    }
    // Along the first's line and across it, each end of the second.
    let along = |p: P2| (p[0] - a0[0]) * u[0] + (p[1] - a0[1]) * u[1];
    let across = |p: P2| ((p[0] - a0[0]) * u[1] - (p[1] - a0[1]) * u[0]).abs();
    let (lo, hi) = (along(b0).min(along(b1)), along(b0).max(along(b1)));
    // Two arrows on one line that do not run over each other (a weight down from a pin
    // whose reaction goes up from it; a weight ending short of a contact) read apart.
    across(b0).min(across(b1)) < gap && lo < length - END && hi > END
}

/// What is wrong with one picture of `scene`, a line each.
fn faults_of(name: &str, scene: &Scene, picture: &Picture) -> Vec<String> {
    let mut faults = Vec::new();
    let labels = labels(picture);
    let grow = picture.grow;
    for (marker, mark) in scene.markers.iter().zip(&picture.marks) {
        let Some(caption) = &marker.caption else {
            continue;
        };
        let nearest = (labels.iter())
            // Points at one dot are named together there: `C^*, S`.
            .filter(|(plain, _)| plain.split(", ").any(|name| name == caption.plain))
            .map(|(_, b)| b.distance_to(mark.at))
            .fold(f64::INFINITY, f64::min);
        if nearest > NEAR * grow {
            faults.push(format!(
                "{name}: {} {nearest:.0} px from {}",
                caption.plain, mark.id
            ));
        }
    }
    for (i, (a, ba)) in labels.iter().enumerate() {
        for (b, bb) in &labels[i + 1..] {
            if ba.overlaps(bb) {
                faults.push(format!("{name}: label {a} over label {b}"));
            } else if ba.runs_into(bb, grow) {
                faults.push(format!("{name}: label {a} runs into label {b}"));
            }
        }
    }
    let tips = triad_tips(picture);
    for (label, b) in labels.iter().filter(|(l, _)| l.contains('\u{302}')) {
        let nearest = (tips.iter())
            .map(|t| b.distance_to(*t))
            .fold(f64::INFINITY, f64::min);
        if nearest > NEAR_A_TIP * grow {
            faults.push(format!("{name}: {label} {nearest:.0} px from its arrow"));
        }
    }
    let drawn =
        |a: &&mbd_tutor::render::draw::DrawnArrow| a.arc.is_none() && a.kind != Kind::Inertia;
    for w in (picture.arrows.iter())
        .filter(drawn)
        .filter(|a| a.kind == Kind::Gravity)
    {
        for o in (picture.arrows.iter())
            .filter(drawn)
            .filter(|a| a.kind != Kind::Gravity)
        {
            if !o.couple && on_one_line((w.tail, w.head), (o.tail, o.head), APART * grow) {
                faults.push(format!(
                    "{name}: weight {} on the line of {}",
                    w.label.plain, o.label.plain
                ));
            }
        }
    }
    let straight: Vec<(String, (P2, P2))> = (picture.arrows.iter())
        .filter(|a| a.arc.is_none())
        .filter_map(|a| middle(a.tail, a.head).map(|m| (a.label.plain.clone(), m)))
        .collect();
    for (label, b) in &labels {
        for (arrow, (p, q)) in &straight {
            if b.meets(*p, *q) {
                faults.push(format!("{name}: label {label} over arrow {arrow}"));
            }
        }
    }
    for (i, (a, sa)) in straight.iter().enumerate() {
        for (b, sb) in &straight[i + 1..] {
            if cross(*sa, *sb) {
                faults.push(format!("{name}: arrow {a} crosses arrow {b}"));
            }
        }
    }
    faults
}

/// The faults of a picture as drawn, and as a handout's page prints it: the configuration
/// at the head of the handout, a free body beside its table of forces or above it.
fn faults_printed(name: &str, d: &Drawing) -> Vec<String> {
    let mut faults = faults_of(name, &d.scene, &d.picture);
    let rooms = if d.free_body.is_empty() {
        vec![("printed", CONFIGURATION)]
    } else {
        vec![("beside", BESIDE_A_TABLE), ("above", ABOVE_A_TABLE)]
    };
    for (how, room) in rooms {
        let printed = d.laid_out_in(room);
        if printed.grow > 1.0 {
            faults.extend(faults_of(&format!("{name} {how}"), &d.scene, &printed));
        }
    }
    faults
}

/// The handouts an instructor reviewed as printed pages.
const REVIEWED: [&str; 9] = [
    "bowling-ball",
    "disc-in-cylinder",
    "disc-on-cart",
    "double-pendulum-rods",
    "four-bar",
    "gear-pair-torque",
    "heavy-symmetric-top",
    "rack-and-pinion",
    "rolling-coin",
];

fn all_faults(method: Method) -> Vec<String> {
    let mut faults = Vec::new();
    for path in all_problems() {
        let problem = mbd_tutor::problem::load_file(&path).expect("a bundled problem");
        let (_, pictures, _) = drawings(&problem, method, View::Isometric);
        let stem = path.file_stem().unwrap_or_default().to_string_lossy();
        for d in &pictures {
            let name = format!("{stem} {}", d.name);
            faults.extend(if REVIEWED.contains(&stem.as_ref()) {
                faults_printed(&name, d)
            } else {
                faults_of(&name, &d.scene, &d.picture)
            });
        }
    }
    faults
}

/// Faults known and left, as (picture, what the fault says). The gimbal's free body ring +
/// rotor crowds a pin's three forces, two moments, a weight and two captions into one corner
/// of a 3D view: every spot within 36 px of the gimbal pin lies over an arrow, so its caption
/// stands a little further off. On the inclines the triad's arrows (and the applied push)
/// fill the ring round B*: its name stands just past them rather than over one.
/// The gears' pinion is small: its pin and mass centre, at one dot, are named together
/// below its support, every closer spot lying over its spoke, its reference line, the mesh
/// point or the arc of q_A. The held slider's pin Q, joint S and mass centre stand at one
/// dot amid five arrows in a small block: their one name, `S, Q, C^*`, stands just above
/// the block. The two-wheeled cart's ĉ_z keeps a space from the names beside
/// it and stands a little further off.
const KNOWN: [(&str, &str); 8] = [
    ("gear-pair-torque configuration", " px from joint-OA"),
    ("gear-pair-torque configuration", " px from cm-A"),
    ("two-wheeled-cart configuration", " px from its arrow"),
    ("gyroscope-gimbal fbd-ring+rotor", " over arrow "),
    ("gyroscope-gimbal fbd-ring+rotor", "gimbal 52 px from"),
    ("block-on-rough-incline configuration", "B^* 41 px from"),
    ("statics-block-on-incline configuration", "B^* 43 px from"),
    ("statics-crank-held fbd-C", " 52 px from "),
];

#[test]
fn labels_stand_at_what_they_name_and_nothing_lies_over_anything() {
    let mut faults = Vec::new();
    for method in [Method::MotionLaw, Method::NewtonEuler] {
        faults.extend(
            all_faults(method)
                .into_iter()
                .filter(|f| {
                    !(KNOWN.iter())
                        .any(|(picture, what)| f.starts_with(picture) && f.contains(what))
                })
                .map(|f| format!("{method:?} {f}")),
        );
    }
    assert!(
        faults.is_empty(),
        "{} faults:\n{}",
        faults.len(),
        faults.join("\n")
    );
}

#[test]
fn the_checks_find_what_they_look_for() {
    let label = Box2::of([50.0, 50.0], "A*", 1.0);
    assert!(label.distance_to([50.0, 50.0]) == 0.0);
    assert!(label.distance_to([50.0, 100.0]) > NEAR);
    assert!(label.overlaps(&Box2::of([56.0, 52.0], "O", 1.0)));
    assert!(!label.overlaps(&Box2::of([90.0, 50.0], "O", 1.0)));
    // Printed twice as large, the same two labels meet.
    assert!(Box2::of([50.0, 50.0], "A*", 2.0).overlaps(&Box2::of([75.0, 50.0], "O", 2.0)));
    assert!(!label.overlaps(&Box2::of([75.0, 50.0], "O", 1.0)));
    // `T` just left of `O_A` on its line runs into it; a line lower, or well apart, not.
    let o = Box2::of([50.0, 50.0], "O_A", 1.0);
    let t = |x: f64, y: f64| Box2::of([x, y], "T", 1.0);
    let width = text_size("O_A")[0] / 2.0 + text_size("T")[0] / 2.0;
    assert!(o.runs_into(&t(50.0 - width - 1.0, 50.0), 1.0));
    assert!(!o.runs_into(&t(50.0 - width - 6.0, 50.0), 1.0));
    assert!(!o.runs_into(&t(50.0 - width, 80.0), 1.0));
    // A weight down from a pin whose vertical reaction arrives at the pin from below
    // lies over it; one going up from the pin, or ending short of it, does not; moved
    // 16 px aside it does not either; a horizontal reaction never does.
    let weight = ([100.0, 100.0], [100.0, 144.0]);
    assert!(on_one_line(weight, ([100.0, 144.0], [100.0, 100.0]), APART));
    assert!(on_one_line(weight, ([100.0, 170.0], [100.0, 130.0]), APART));
    assert!(!on_one_line(weight, ([100.0, 100.0], [100.0, 56.0]), APART));
    assert!(!on_one_line(
        weight,
        ([100.0, 190.0], [100.0, 153.0]),
        APART
    ));
    assert!(!on_one_line(
        ([84.0, 100.0], [84.0, 144.0]),
        ([100.0, 100.0], [100.0, 56.0]),
        APART
    ));
    assert!(!on_one_line(
        weight,
        ([100.0, 100.0], [144.0, 100.0]),
        APART
    ));
    // Far apart along one line (a long bar's two ends), they are two arrows.
    assert!(!on_one_line(
        weight,
        ([100.0, 400.0], [100.0, 444.0]),
        APART
    ));
    assert!(label.meets([0.0, 50.0], [100.0, 50.0]));
    assert!(!label.meets([0.0, 80.0], [100.0, 80.0]));
    let a = ([0.0, 0.0], [40.0, 0.0]);
    assert!(cross(
        middle(a.0, a.1).unwrap(),
        ([20.0, -20.0], [20.0, 20.0])
    ));
    // Two components from one pin meet at their tails: no crossing.
    let m = |(p, q): (P2, P2)| middle(p, q).unwrap();
    assert!(!cross(m(a), m(([0.0, 0.0], [0.0, 40.0]))));
}
