//! `draw --animate`: the configuration over the simulated motion (step 6), as an SVG
//! animated with SMIL, no script.
//!
//! The motion is sampled at the frame rate from the same integration as `simulate`. Each
//! body is drawn once on a *sheet*, a plane fixed in the body (its plane of motion in 2D,
//! a disc's plane, or the plane of its points in 3D), in metres. The orthographic picture
//! of a plane moving rigidly is an affine map of it, so each frame's map of the sheet is
//! exact, and [`crate::render::draw::motion_svg`] writes it as four `animateTransform`s. The points
//! (`cm-B`, `joint-J`) are circles outside the bodies' groups, moved by `<animate>` of
//! their centres, so that their attributes give their place.

use super::numbers::{add, cross, dot, norm, scale, sub, unit, Numbers, P3};
use crate::equations::Derivation;
use crate::mechanics::model::vector_of;
use crate::numeric::simulate::{simulate_with_limits, Limits};
use crate::pipeline::Solver;
use crate::problem::{BodyId, ConstraintKind, Dimension, ForcePoint, LoadKind, Problem};
use crate::render::draw::motion::{Look, Motion, Placed, Sheet, TITLE_STRIP};
use crate::render::draw::picture::{Projection, View};
use crate::Error;

/// The most frames a motion may have (400 s at 25 frames per second): each frame adds a
/// value to every animation of the picture, and more would make a file no viewer plays.
pub const MAX_FRAMES: usize = 10_000;

/// Frames per second unless `--fps` says otherwise.
pub const DEFAULT_FPS: f64 = 25.0;

/// One sampled state.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// The time.
    pub t: f64,
    /// The coordinates.
    pub q: Vec<f64>,
    /// Their rates.
    pub rates: Vec<f64>,
}

/// The number of frames of `duration` seconds at `fps`, or a usage error when the numbers
/// are not usable or give more than [`MAX_FRAMES`]; checked before any work.
///
/// # Errors
/// [`Error::Usage`] naming the flag.
pub fn frame_count(duration: f64, fps: f64) -> Result<usize, Error> {
    if !(duration.is_finite() && duration > 0.0) {
        return Err(Error::Usage(
            "--duration must be a positive number of seconds".into(),
        ));
    }
    if !(fps.is_finite() && fps > 0.0) {
        return Err(Error::Usage(
            "--fps must be a positive number of frames per second".into(),
        ));
    }
    let frames = (duration * fps).ceil() + 1.0;
    if frames > MAX_FRAMES as f64 {
        return Err(Error::Usage(format!(
            "{duration} s at {fps} frames per second is {frames} frames, more than {MAX_FRAMES}: shorten --duration or lower --fps"
        )));
    }
    Ok(frames as usize)
}

/// The motion from the problem's initial state over `duration` seconds, sampled every
/// `1/fps` s by the integrator's dense output, as `simulate` integrates it. A run that stops
/// early gives the frames up to then.
///
/// # Errors
/// Unusable `duration` or `fps` (see [`frame_count`]); a simulation that cannot start.
pub fn frames(
    problem: &Problem,
    derivation: &Derivation,
    duration: f64,
    fps: f64,
) -> Result<Vec<Frame>, Error> {
    let count = frame_count(duration, fps)?;
    let solver = Solver::new(problem, derivation);
    let q0: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
    let rates0: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    let settings = crate::problem::SimulateSettings {
        duration,
        output_step: 1.0 / fps,
        ..problem.simulate.clone()
    };
    let limits = Limits {
        max_rows: count + 1,
        ..Limits::default()
    };
    let run =
        simulate_with_limits(&solver, &q0, &rates0, &settings, &limits).map_err(Error::Solve)?;
    let n = run.coordinates;
    let frames: Vec<Frame> = run
        .rows
        .iter()
        .map(|row| Frame {
            t: row[0],
            q: row[1..=n].to_vec(),
            rates: row[n + 1..=2 * n].to_vec(),
        })
        .collect();
    match (frames.len(), run.stopped) {
        (0 | 1, Some(reason)) => Err(Error::Solve(reason)),
        _ => Ok(frames),
    }
}

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
    let sheets: Vec<Sheet> = problem.body_ids().map(|b| sheet(&numbers, b)).collect();
    let mut points: Vec<(String, bool)> = Vec::new();
    let mut grounded = Vec::new();
    let mut rolling = Vec::new();
    let mut captions = Vec::new();
    for site in &model.sites {
        if site.parent == site.child {
            continue;
        }
        if site.parent == BodyId::GROUND {
            match site.kind {
                crate::mechanics::sites::SiteKind::Joint(j)
                    if problem.joints[j].kind == crate::problem::JointKind::Revolute =>
                {
                    grounded.push(points.len());
                }
                crate::mechanics::sites::SiteKind::Joint(_) => {}
                _ => rolling.push(points.len()),
            }
        }
        points.push((format!("joint-{}", site.name), false));
        captions.push(match site.kind {
            crate::mechanics::sites::SiteKind::Joint(j) => coordinates_of(problem, j),
            _ => None,
        });
    }
    for b in problem.body_ids() {
        points.push((format!("cm-{}", problem.body_name(b)), true));
        captions.push(Some(problem.body_name(b).to_string()));
    }
    let placed: Vec<Placed> = frames
        .iter()
        .map(|f| place(derivation, &sheets, f))
        .collect();
    let (projection, size) = fit(still_rows, &sheets, &placed);
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
        sheets,
        points,
        captions,
        grounded,
        rolling,
        spring_lanes: lanes_of(true),
        damper_lanes: lanes_of(false),
        frames: placed,
        projection,
        size,
    }
}

/// A joint's coordinates as the pictures print them (`θ`, `q₁, q₂`), if it has any.
fn coordinates_of(problem: &Problem, joint: usize) -> Option<String> {
    let names: Vec<String> = problem.joints[joint]
        .coordinates
        .iter()
        .map(|&c| {
            crate::render::plot::unicode_of(&crate::symbolic::print::latex_name(
                &problem.coordinates[c].name,
            ))
        })
        .collect();
    (!names.is_empty()).then(|| names.join(", "))
}

/// A body's sheet and look, from its points at the first frame.
fn sheet(n: &Numbers, body: BodyId) -> Sheet {
    let model = n.model;
    let problem = model.problem;
    let name = problem.body_name(body).to_string();
    let center = n.local(&model.bodies[body.0].center_offset);
    for constraint in &problem.constraints {
        if let ConstraintKind::Rolling {
            body: b,
            radius,
            axis,
            center: at,
            ..
        } = &constraint.kind
        {
            if *b != body {
                continue;
            }
            let axis = n.local(&vector_of(axis).components_in(body, &model.frames));
            let origin = match at {
                ForcePoint::Point(p) => n.local(&model.locate(*p).1),
                ForcePoint::Offset(v) => n.local(&vector_of(v).components_in(body, &model.frames)),
            };
            let axes = plane_across(axis);
            return Sheet {
                body,
                name,
                origin,
                axes,
                look: Look::Disc(n.scalar(radius).abs()),
            };
        }
    }
    // The body's points, from its origin in its own unit vectors.
    let mut local: Vec<P3> = Vec::new();
    for site in &model.sites {
        if site.parent == site.child {
            continue;
        }
        if site.child == body {
            local.push(n.local(&site.child_offset));
        }
        if site.parent == body {
            local.push(n.local(&site.parent_offset));
        }
    }
    for point in problem.points.iter().filter(|p| p.on == body) {
        local.push(n.local(&crate::mechanics::model::own_components(&point.at, body)));
    }
    for load in &problem.loads {
        if let LoadKind::Spring { between, .. } | LoadKind::Damper { between, .. } = &load.kind {
            for p in between {
                let (on, offset) = model.locate(*p);
                if on == body {
                    local.push(n.local(&offset));
                }
            }
        }
    }
    let axes = if problem.dimension == Dimension::Two {
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    } else {
        plane_through(center, &local)
    };
    let on_sheet = |p: P3| {
        let d = sub(p, center);
        [dot(d, axes[0]), dot(d, axes[1])]
    };
    let mut points: Vec<[f64; 2]> = local
        .iter()
        .map(|&p| on_sheet(p))
        .filter(|p| p[0].hypot(p[1]) > 1e-12)
        .collect();
    let body_data = problem.body(body);
    let mass = n.scalar(&body_data.mass);
    let inertia = match &body_data.inertia {
        crate::problem::Inertia::Planar(i) => n.scalar(i),
        crate::problem::Inertia::Spatial(m) => {
            (0..3).map(|k| n.scalar(&m[k][k])).fold(0.0, f64::max)
        }
    };
    if let [joint] = points[..] {
        // A uniform rod on one joint (I = m d²/3 within 1 %): drawn to its far end.
        let d2 = joint[0].powi(2) + joint[1].powi(2);
        if (inertia - mass * d2 / 3.0).abs() <= 0.01 * inertia {
            points.push([-joint[0], -joint[1]]);
        }
    }
    let look = if inertia == 0.0 {
        Look::Particle { rods: points }
    } else if points.is_empty() {
        Look::Particle { rods: Vec::new() }
    } else {
        Look::Rods {
            center: [0.0, 0.0],
            points,
        }
    };
    Sheet {
        body,
        name,
        origin: center,
        axes,
        look,
    }
}

/// Two unit vectors across `axis` (a disc's plane).
fn plane_across(axis: P3) -> [P3; 2] {
    let a = unit(axis).unwrap_or([0.0, 0.0, 1.0]);
    let helper = if a[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let e1 = unit(cross(helper, a)).unwrap_or([0.0, 1.0, 0.0]);
    [e1, cross(a, e1)]
}

/// Two unit vectors of a plane through `center` that holds the points as well as a plane
/// can: along the farthest point, then across towards the point farthest from that line.
fn plane_through(center: P3, points: &[P3]) -> [P3; 2] {
    let offsets: Vec<P3> = points.iter().map(|&p| sub(p, center)).collect();
    let farthest = offsets
        .iter()
        .copied()
        .max_by(|a, b| norm(*a).total_cmp(&norm(*b)));
    let Some(e1) = farthest.and_then(unit) else {
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    };
    let across = offsets
        .iter()
        .map(|&d| sub(d, scale(e1, dot(d, e1))))
        .max_by(|a, b| norm(*a).total_cmp(&norm(*b)));
    match across.and_then(|v| unit(v).filter(|_| norm(v) > 1e-6 * norm(farthest.unwrap_or(e1)))) {
        Some(e2) => [e1, e2],
        None => {
            let [_, e2] = plane_across(e1);
            [e1, e2]
        }
    }
}

/// Where the sheets, points, springs and dampers are at one frame.
fn place(derivation: &Derivation, sheets: &[Sheet], frame: &Frame) -> Placed {
    let model = &derivation.model;
    let problem = model.problem;
    let n = Numbers::new(model, frame.t, &frame.q, &frame.rates);
    let sheets = sheets
        .iter()
        .map(|s| {
            [
                n.point_on(s.body, &s.origin),
                n.in_ground(s.body, &s.axes[0]),
                n.in_ground(s.body, &s.axes[1]),
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
    let springs = problem
        .loads
        .iter()
        .filter_map(|load| match &load.kind {
            LoadKind::Spring { between, .. } => Some(between.map(|p| n.vector(&model.position(p)))),
            _ => None,
        })
        .collect();
    let dampers = problem
        .loads
        .iter()
        .filter_map(|load| match &load.kind {
            LoadKind::Damper { between, .. } => Some(between.map(|p| n.vector(&model.position(p)))),
            _ => None,
        })
        .collect();
    Placed {
        t: frame.t,
        sheets,
        points,
        springs,
        dampers,
    }
}

/// Every point the picture shows at one frame, in `N`: the points, the springs' ends and
/// each body's outline.
fn extent(sheets: &[Sheet], placed: &Placed) -> Vec<P3> {
    let mut out = placed.points.clone();
    out.extend(placed.springs.iter().flatten());
    out.extend(placed.dampers.iter().flatten());
    for (sheet, [o, e1, e2]) in sheets.iter().zip(&placed.sheets) {
        let at = |u: f64, v: f64| add(*o, add(scale(*e1, u), scale(*e2, v)));
        match &sheet.look {
            Look::Disc(r) => out.extend((0..16).map(|k| {
                let a = f64::from(k) * std::f64::consts::PI / 8.0;
                at(r * a.cos(), r * a.sin())
            })),
            Look::Rods { points, .. } => out.extend(points.iter().map(|p| at(p[0], p[1]))),
            Look::Particle { rods } => {
                out.push(*o);
                out.extend(rods.iter().map(|p| at(p[0], p[1])));
            }
        }
    }
    out
}

/// The projection with the still picture's orientation (`rows`, any scale), scaled and
/// shifted so that every frame fits in the picture, and the picture's size.
fn fit(rows: [P3; 2], sheets: &[Sheet], placed: &[Placed]) -> (Projection, [f64; 2]) {
    let unit_scale = norm(rows[0]).max(1e-12);
    let rows = rows.map(|r| scale(r, 1.0 / unit_scale));
    let (mut low, mut high) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for frame in placed {
        for p in extent(sheets, frame) {
            let xy = [dot(rows[0], p), dot(rows[1], p)];
            if xy.iter().all(|v| v.is_finite()) {
                for i in 0..2 {
                    low[i] = low[i].min(xy[i]);
                    high[i] = high[i].max(xy[i]);
                }
            }
        }
    }
    if !low[0].is_finite() {
        (low, high) = ([-1.0; 2], [1.0; 2]);
    }
    let span = (high[0] - low[0]).max(high[1] - low[1]).max(1e-9);
    let s = LONGEST_SIDE / span;
    let size = [
        (high[0] - low[0]) * s + 2.0 * MARGIN,
        (high[1] - low[1]) * s + 2.0 * MARGIN + TITLE_STRIP,
    ];
    let projection = Projection {
        a: rows.map(|r| scale(r, s)),
        b: [MARGIN - s * low[0], MARGIN + TITLE_STRIP - s * low[1]],
    };
    (projection, size)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn absurd_frame_counts_are_refused_before_any_work() {
        assert_eq!(frame_count(5.0, 25.0).ok(), Some(126));
        assert!(frame_count(1e6, 25.0).is_err());
        assert!(frame_count(5.0, 0.0).is_err());
        assert!(frame_count(f64::NAN, 25.0).is_err());
    }

    #[test]
    fn a_sheet_across_an_axle_is_square_to_it() {
        let [e1, e2] = plane_across([0.0, 2.0, 0.0]);
        assert!(dot(e1, [0.0, 1.0, 0.0]).abs() < 1e-12);
        assert!(dot(e2, [0.0, 1.0, 0.0]).abs() < 1e-12);
        assert!(dot(e1, e2).abs() < 1e-12);
    }
}
