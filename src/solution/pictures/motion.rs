//! `draw --animate`: the configuration over the simulated motion (step 6), as an SVG
//! animated with SMIL, no script.
//!
//! The motion is sampled at the frame rate from the same integration as `simulate` (the
//! frames are given, [`Frame`]). Each body is drawn once on a *sheet*, a plane fixed in
//! the body (its plane of motion in 2D, a disc's plane, or the plane of its points in 3D),
//! in metres. The orthographic picture
//! of a plane moving rigidly is an affine map of it, so each frame's map of the sheet is
//! exact, and [`crate::render::draw::motion_svg`] writes it as four `animateTransform`s. The points
//! (`cm-B`, `joint-J`) are circles outside the bodies' groups, moved by `<animate>` of
//! their centres, so that their attributes give their place.

use super::numbers::{add, dot, norm, scale, sub, unit, Numbers, P3};
use super::sheets;
use crate::equations::Derivation;
use crate::mechanics::SiteKind;
use crate::numeric::Frame;
use crate::problem::{BodyId, JointKind, LoadKind, Problem};
use crate::render::draw::{
    Gauge, Label, Motion, Part, Placed, Projection, Sheet, View, TITLE_STRIP,
};

/// The longest side of the motion's picture, and the room around it.
const LONGEST_SIDE: f64 = 520.0;
const MARGIN: f64 = 24.0;

/// The motion of `derivation`'s problem over `frames`, seen along `view` (the still
/// configuration's map, scaled and shifted so that the whole motion fits).
pub fn motion(derivation: &Derivation, frames: &[Frame], view: View) -> Motion {
    let model = &derivation.model;
    let problem = model.problem;
    let first = &frames[0];
    let still = super::draw(derivation, first.t, &first.q, &first.rates, None, view);
    let still_rows = still
        .first()
        .map_or(view.rows(false), |d| d.picture.projection.a);
    let numbers = Numbers::new(model, first.t, &first.q, &first.rates);
    let size = super::size_of(&numbers);
    let mut points: Vec<(String, bool)> = Vec::new();
    let mut grounded = Vec::new();
    let mut rolling = Vec::new();
    let mut joints = Vec::new();
    for site in &model.sites {
        if site.parent == site.child {
            continue;
        }
        if site.parent == BodyId::GROUND {
            match site.kind {
                // A support under a pin or ball on N, as the still picture draws it.
                SiteKind::Joint(j)
                    if matches!(
                        problem.joints[j].kind,
                        JointKind::Revolute | JointKind::Spherical | JointKind::Universal
                    ) =>
                {
                    grounded.push((points.len(), toward_body(&numbers, j)));
                }
                SiteKind::Joint(_) => {}
                _ => rolling.push(points.len()),
            }
        }
        points.push((format!("joint-{}", site.name), false));
        joints.push(match site.kind {
            SiteKind::Joint(j) => Some(j),
            _ => None,
        });
    }
    let mut bodies = Vec::new();
    let mut sheets = Vec::new();
    for (k, b) in problem.body_ids().enumerate() {
        let (body, mut on) = sheets::body_sheets(&numbers, b, k, points.len() + k, size);
        bodies.push(body);
        sheets.append(&mut on);
    }
    let owners: Vec<BodyId> = problem.body_ids().collect();
    let (mut placed, found): (Vec<Placed>, Vec<Vec<Option<Gauge>>>) = frames
        .iter()
        .map(|f| place(derivation, &owners, &sheets, f, size))
        .unzip();
    let gauges = steady_gauges(&numbers, size, &found, &mut placed);
    let mut captions: Vec<Option<String>> = joints
        .iter()
        .map(|j| j.and_then(|j| coordinates_of(problem, j, &gauges.1)))
        .collect();
    for b in problem.body_ids() {
        points.push((format!("cm-{}", problem.body_name(b)), true));
        captions.push(Some(problem.body_name(b).to_string()));
    }
    let floors = floors(&numbers, &rolling, &placed, size);
    let rims = rims(&numbers);
    let title = crate::render::draw::text_size(&problem.title)[0] + 2.0 * MARGIN;
    let (projection, size) = fit(still_rows, &sheets, (&floors, &rims), &placed, title);
    // After the fit: a rack as long as its pinion's travel runs through the picture.
    super::travel::stretch_carriers(derivation, frames, &owners, &mut sheets);
    let lanes = super::lanes::lanes(&problem.loads);
    let lanes_of = |spring: bool| -> Vec<f64> {
        problem
            .loads
            .iter()
            .zip(&lanes)
            .filter(|(load, _)| match load.kind {
                LoadKind::Spring { .. } => spring,
                LoadKind::Damper { .. } => !spring,
                _ => false,
            })
            .map(|(_, &lane)| lane)
            .collect()
    };
    Motion {
        title: problem.title.clone(),
        bodies,
        sheets,
        points,
        captions,
        grounded,
        rolling,
        floors,
        rims,
        gauges: gauges.0,
        spring_lanes: lanes_of(true),
        damper_lanes: lanes_of(false),
        frames: placed,
        projection,
        size,
    }
}

/// The direction from joint `j` on `N` towards the body it carries, upright when it is
/// nearly so, at the first frame: its support is drawn on the other side, as the still
/// picture draws it.
fn toward_body(n: &Numbers, j: usize) -> P3 {
    let model = n.model;
    let vertical = if model.is_planar() {
        [0.0, 1.0, 0.0]
    } else {
        [0.0, 0.0, 1.0]
    };
    let at = n.vector(&model.joints[j].point.position);
    let child = n.vector(
        &model.bodies[model.problem.joints[j].child.0]
            .center
            .position,
    );
    match unit(sub(child, at)) {
        Some(v) if dot(v, vertical).abs() >= 0.5 => scale(vertical, dot(v, vertical).signum()),
        Some(v) => v,
        None => vertical,
    }
}

/// The coordinates' marks of every frame made steady: a mark that has no direction at a
/// frame keeps the nearest frame's, one that has none at any frame is left out, and a
/// distance's side is the one it starts on. The labels of the marks kept, and their
/// coordinates.
fn steady_gauges(
    n: &Numbers,
    size: f64,
    found: &[Vec<Option<Gauge>>],
    placed: &mut [Placed],
) -> (Vec<Label>, Vec<usize>) {
    let slots = super::gauges::gauges(n, size);
    let mut labels = Vec::new();
    let mut coordinates = Vec::new();
    let mut kept: Vec<Vec<Gauge>> = vec![Vec::new(); placed.len()];
    for (k, slot) in slots.iter().enumerate() {
        let track: Vec<Option<Gauge>> = found.iter().map(|f| f.get(k).copied().flatten()).collect();
        let Some(mut last) = track.iter().flatten().next().copied() else {
            continue;
        };
        // The side a distance is drawn on: where it points when it first has a length.
        let flip = track.iter().flatten().find_map(|g| match g {
            Gauge::Distance { from, to, along } if norm(sub(*to, *from)) > 1e-6 * size => {
                Some(dot(sub(*to, *from), *along) < 0.0)
            }
            _ => None,
        });
        for (frame, g) in track.iter().enumerate() {
            let mut g = g.unwrap_or(last);
            last = g;
            if let (Gauge::Distance { along, .. }, Some(true)) = (&mut g, flip) {
                *along = scale(*along, -1.0);
            }
            kept[frame].push(g);
        }
        labels.push(slot.label.clone());
        coordinates.push(slot.coordinate);
    }
    for (p, g) in placed.iter_mut().zip(kept) {
        p.gauges = g;
    }
    (labels, coordinates)
}

/// A joint's coordinates that no mark shows, as the pictures print them (`ψ, θ, φ`); none
/// for a free joint, whose six coordinates place the body anywhere: its point on the
/// parent (`N`'s origin, under a rolling coin) is no point of the motion to name them at.
fn coordinates_of(problem: &Problem, joint: usize, marked: &[usize]) -> Option<String> {
    if problem.joints[joint].kind == JointKind::Free {
        return None;
    }
    let names: Vec<String> = problem.joints[joint]
        .coordinates
        .iter()
        .filter(|c| !marked.contains(c))
        .map(|&c| {
            crate::render::unicode_of(&crate::symbolic::latex_name(&problem.coordinates[c].name))
        })
        .collect();
    (!names.is_empty()).then(|| names.join(", "))
}

/// The rims of the round tracks fixed in `N` that bodies roll in or on, as the still
/// picture draws them (`Shape::Track`).
fn rims(n: &Numbers) -> Vec<Vec<P3>> {
    let size = super::size_of(n);
    (super::bodies::surfaces(n, size).into_iter())
        .filter_map(|s| match s {
            crate::render::draw::Shape::Track {
                center,
                normal,
                radius,
                ..
            } => Some(super::numbers::circle(center, normal, radius)),
            _ => None,
        })
        .collect()
}

/// The floors fixed in `N` that bodies roll on in 3D, each around every contact on it over
/// the whole motion.
fn floors(n: &Numbers, rolling: &[usize], placed: &[Placed], size: f64) -> Vec<[P3; 4]> {
    let model = n.model;
    if model.is_planar() {
        return Vec::new();
    }
    let mut planes: Vec<(P3, Vec<P3>, f64)> = Vec::new();
    let sites = model.sites.iter().filter(|s| s.parent != s.child);
    for (i, site) in sites.enumerate() {
        let (SiteKind::Contact(c), true) = (site.kind, rolling.contains(&i)) else {
            continue;
        };
        let Some((up, radius)) = super::bodies::floor_of(n, c) else {
            continue;
        };
        let contacts = placed.iter().map(|p| p.points[i]);
        match planes.iter_mut().find(|(u, pts, _)| {
            dot(*u, up) > 1.0 - 1e-9
                && pts
                    .first()
                    .is_some_and(|p| dot(sub(placed[0].points[i], *p), up).abs() < 1e-6 * size)
        }) {
            Some((_, pts, pad)) => {
                pts.extend(contacts);
                *pad = pad.max(radius);
            }
            None => planes.push((up, contacts.collect(), radius)),
        }
    }
    planes
        .iter()
        .map(|(up, pts, radius)| super::bodies::patch(pts, *up, 1.5 * radius))
        .collect()
}

/// Where the sheets, points, springs and dampers are at one frame, and the coordinates'
/// marks as found there.
fn place(
    derivation: &Derivation,
    owners: &[BodyId],
    sheets: &[Sheet],
    frame: &Frame,
    size: f64,
) -> (Placed, Vec<Option<Gauge>>) {
    let model = &derivation.model;
    let problem = model.problem;
    let n = Numbers::new(model, frame.t, &frame.q, &frame.rates);
    let sheets = sheets
        .iter()
        .map(|s| {
            let body = owners[s.body];
            [
                n.point_on(body, &s.origin),
                n.in_ground(body, &s.axes[0]),
                n.in_ground(body, &s.axes[1]),
            ]
        })
        .collect();
    let mut points: Vec<P3> = model
        .sites
        .iter()
        .filter(|site| site.parent != site.child)
        .map(|site| n.vector(&site.point.position))
        .collect();
    points.extend(
        problem
            .body_ids()
            .map(|b| n.vector(&model.bodies[b.0].center.position)),
    );
    let ends = |spring: bool| -> Vec<[P3; 2]> {
        problem
            .loads
            .iter()
            .filter_map(|load| match &load.kind {
                LoadKind::Spring { between, .. } if spring => Some(between),
                LoadKind::Damper { between, .. } if !spring => Some(between),
                _ => None,
            })
            .map(|between| between.map(|p| n.vector(&model.position(p))))
            .collect()
    };
    let placed = Placed {
        t: frame.t,
        sheets,
        points,
        springs: ends(true),
        dampers: ends(false),
        gauges: Vec::new(),
    };
    let gauges = super::gauges::gauges(&n, size)
        .into_iter()
        .map(|g| g.at)
        .collect();
    (placed, gauges)
}

/// Every point the picture shows at one frame, in `N`: the points, the springs' ends, the
/// ends of the coordinates' marks and each body's outline.
fn extent(sheets: &[Sheet], placed: &Placed) -> Vec<P3> {
    let mut out = placed.points.clone();
    out.extend(placed.springs.iter().flatten());
    out.extend(placed.dampers.iter().flatten());
    for gauge in &placed.gauges {
        match *gauge {
            Gauge::Angle {
                center,
                from,
                reference,
                ..
            } => out.extend([center, add(center, scale(from, reference))]),
            Gauge::Distance { from, to, .. } => out.extend([from, to]),
        }
    }
    for (sheet, [o, e1, e2]) in sheets.iter().zip(&placed.sheets) {
        let at = |p: [f64; 2]| add(*o, add(scale(*e1, p[0]), scale(*e2, p[1])));
        for part in &sheet.parts {
            match part {
                Part::Wheel { center, radius, .. } => out.extend((0..16).map(|k| {
                    let a = f64::from(k) * std::f64::consts::PI / 8.0;
                    at([center[0] + radius * a.cos(), center[1] + radius * a.sin()])
                })),
                Part::Bar(points) | Part::Outline(points) => {
                    out.extend(points.iter().map(|p| at(*p)));
                }
                Part::Line(a, b) => out.extend([at(*a), at(*b)]),
            }
        }
    }
    out
}

/// The projection with the still picture's orientation (`rows`, any scale), scaled and
/// shifted so that every frame and the floors fit in the picture, and the picture's size:
/// at least `least_width` wide (the title's room), the motion centred in it.
fn fit(
    rows: [P3; 2],
    sheets: &[Sheet],
    (floors, rims): (&[[P3; 4]], &[Vec<P3>]),
    placed: &[Placed],
    least_width: f64,
) -> (Projection, [f64; 2]) {
    let unit_scale = norm(rows[0]).max(1e-12);
    let rows = rows.map(|r| scale(r, 1.0 / unit_scale));
    let (mut low, mut high) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    let floor_points = (floors.iter().flatten())
        .chain(rims.iter().flatten())
        .copied();
    for p in placed
        .iter()
        .flat_map(|frame| extent(sheets, frame))
        .chain(floor_points)
    {
        let xy = [dot(rows[0], p), dot(rows[1], p)];
        if xy.iter().all(|v| v.is_finite()) {
            for i in 0..2 {
                low[i] = low[i].min(xy[i]);
                high[i] = high[i].max(xy[i]);
            }
        }
    }
    if !low[0].is_finite() {
        (low, high) = ([-1.0; 2], [1.0; 2]);
    }
    let span = (high[0] - low[0]).max(high[1] - low[1]).max(1e-9);
    let s = LONGEST_SIDE / span;
    let width = (high[0] - low[0]) * s + 2.0 * MARGIN;
    let extra = (least_width.min(LONGEST_SIDE + 2.0 * MARGIN) - width).max(0.0);
    let size = [
        width + extra,
        (high[1] - low[1]) * s + 2.0 * MARGIN + TITLE_STRIP,
    ];
    let projection = Projection {
        a: rows.map(|r| scale(r, s)),
        b: [
            MARGIN + extra / 2.0 - s * low[0],
            MARGIN + TITLE_STRIP - s * low[1],
        ],
    };
    (projection, size)
}
