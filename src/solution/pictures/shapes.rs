//! The shapes of bodies, joints and elements, chosen from what the problem gives: rods as
//! bars between their points, blocks and discs where the inertia suggests them, particles
//! as dots.

use super::numbers::{add, circle, dot, norm, scale, sub, Numbers, P3};
use crate::problem::{BodyId, Inertia, JointKind, LoadKind, PointRef};
use crate::render::draw::Shape;

/// The points of `body` that a picture must reach, in the body's own unit vectors: its
/// joint points, declared points, load ends and mass center.
pub fn key_points(n: &Numbers, body: BodyId) -> Vec<P3> {
    let model = n.model;
    let problem = model.problem;
    let mut out: Vec<P3> = Vec::new();
    let mut push = |p: P3| {
        if p.iter().all(|x| x.is_finite()) {
            out.push(p);
        }
    };
    for (j, joint) in problem.joints.iter().enumerate() {
        if joint.child == body {
            push(n.local(&model.joints[j].child_at));
        }
        if joint.parent == body {
            let jm = &model.joints[j];
            push(n.local(&jm.at));
            if matches!(joint.kind, JointKind::Prismatic | JointKind::Cylindrical) {
                // A rail or rod reaches at least to where the child now slides.
                let slid = std::array::from_fn(|i| &jm.at[i] + &jm.motion.translation[i]);
                push(n.local(&slid));
            }
        }
    }
    // Closures reach their points on both bodies; a wheel reaches its contact.
    for site in model.sites.iter().skip(problem.joints.len()) {
        if site.parent == site.child {
            continue; // a constraint entry with no site
        }
        if site.child == body {
            push(n.local(&site.child_offset));
        }
        if site.parent == body && site.parent != BodyId::GROUND {
            push(n.local(&site.parent_offset));
        }
    }
    for (i, point) in problem.points.iter().enumerate() {
        if point.on == body {
            let (_, offset) = model.locate(PointRef::Named(i));
            push(n.local(&offset));
        }
    }
    for load in &problem.loads {
        for p in named_points(&load.kind) {
            let (b, offset) = model.locate(p);
            if b == body {
                push(n.local(&offset));
            }
        }
    }
    if body != BodyId::GROUND {
        push(n.local(&model.bodies[body.0].center_offset));
    }
    out
}

/// The radius of gyration about the axis of largest inertia, and that axis (body's unit
/// vectors), when the inertia is that of a disc (two equal moments, the third larger).
fn disc_of(n: &Numbers, body: BodyId) -> Option<(f64, P3)> {
    let declared = n.model.problem.body(body);
    let mass = n.scalar(&declared.mass);
    if mass.is_nan() || mass <= 0.0 {
        return None;
    }
    match &declared.inertia {
        Inertia::Planar(izz) => {
            let i = n.scalar(izz);
            (i > 0.0).then(|| ((2.0 * i / mass).sqrt(), [0.0, 0.0, 1.0]))
        }
        Inertia::Spatial(m) => {
            let d: Vec<f64> = (0..3).map(|k| n.scalar(&m[k][k])).collect();
            let (axis, largest) =
                d.iter().enumerate().fold(
                    (0, f64::MIN),
                    |best, (k, v)| if *v > best.1 { (k, *v) } else { best },
                );
            if largest.is_nan() || largest <= 0.0 {
                return None;
            }
            let mut e = [0.0; 3];
            e[axis] = 1.0;
            Some(((2.0 * largest / mass).sqrt(), e))
        }
    }
}

/// The shapes of one body; `size` is the picture's characteristic length.
pub fn body(n: &Numbers, body: BodyId, size: f64) -> Vec<Shape> {
    let problem = n.model.problem;
    let mut local: Vec<P3> = Vec::new();
    for p in key_points(n, body) {
        if local.iter().all(|q| norm(sub(*q, p)) > 1e-6 * size) {
            local.push(p);
        }
    }
    let world = |p: &P3| n.point_on(body, p);
    let slides = problem.joint_of(body).is_some_and(|j| {
        matches!(
            problem.joints[j].kind,
            JointKind::Prismatic | JointKind::Cylindrical
        )
    });
    let planar = n.model.is_planar();
    let center = n.local(&n.model.bodies[body.0].center_offset);
    let disc = disc_of(n, body);
    // The two points farthest apart, and how far the others stray from their line.
    let mut far = (0, 0, 0.0);
    for i in 0..local.len() {
        for j in i + 1..local.len() {
            let d = norm(sub(local[i], local[j]));
            if d > far.2 {
                far = (i, j, d);
            }
        }
    }
    let mut shapes = Vec::new();
    if far.2 <= 1e-6 * size {
        // One point: a block if it slides, a disc if it has inertia, else a particle.
        if slides {
            let half = disc
                .map_or(0.08 * size, |(r, _)| (r * 0.8).max(0.06 * size))
                .min(0.2 * size);
            let corners = [[-1.0, -0.6], [1.0, -0.6], [1.0, 0.6], [-1.0, 0.6]]
                .map(|[x, y]| world(&add(center, [x * half, y * half, 0.0])));
            shapes.push(Shape::Polygon(corners.to_vec()));
        } else if let Some((radius, axis)) = disc.filter(|(r, _)| *r > 1e-3 * size) {
            let radius = radius.clamp(0.03 * size, 0.3 * size);
            let normal = n.in_ground(body, &axis);
            shapes.push(Shape::Outline(circle(world(&center), normal, radius)));
        } else {
            shapes.push(Shape::Dot(world(&center)));
        }
        return shapes;
    }
    if slides && planar {
        // A sliding body is a block around its points, at least half as wide as it is tall.
        let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
        for p in &local {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let span = [hi[0] - lo[0], hi[1] - lo[1]];
        for k in 0..2 {
            let pad = (0.5 * span[1 - k] - span[k]).max(0.0) / 2.0 + 0.03 * size;
            lo[k] -= pad;
            hi[k] += pad;
        }
        let corners = [
            [lo[0], lo[1]],
            [hi[0], lo[1]],
            [hi[0], hi[1]],
            [lo[0], hi[1]],
        ];
        shapes.push(Shape::Polygon(
            corners.iter().map(|[x, y]| world(&[*x, *y, 0.0])).collect(),
        ));
        return shapes;
    }
    let (a, b) = (local[far.0], local[far.1]);
    let along = scale(sub(b, a), 1.0 / far.2);
    let stray = local
        .iter()
        .map(|p| {
            let r = sub(*p, a);
            norm(sub(r, scale(along, dot(r, along))))
        })
        .fold(0.0, f64::max);
    if stray <= 0.05 * far.2 || !planar {
        if stray <= 0.05 * far.2 {
            shapes.push(Shape::Bar(vec![world(&a), world(&b)]));
        } else {
            // A spatial body of several arms: a bar from its center to each point.
            for p in &local {
                if norm(sub(*p, center)) > 1e-6 * size {
                    shapes.push(Shape::Bar(vec![world(&center), world(p)]));
                }
            }
        }
        // A rotor on its axle: the disc too, when it is wider than the bar is long.
        if let Some((radius, axis)) = disc {
            if !planar && radius > 0.5 * far.2 && dot(axis, along).abs() > 0.9 {
                let normal = n.in_ground(body, &axis);
                let radius = radius.min(0.3 * size);
                shapes.push(Shape::Outline(circle(world(&center), normal, radius)));
            }
        }
        return shapes;
    }
    // A planar body spread over an area: its bounding box in its own axes.
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    for p in &local {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let corners = [
        [lo[0], lo[1]],
        [hi[0], lo[1]],
        [hi[0], hi[1]],
        [lo[0], hi[1]],
    ];
    shapes.push(Shape::Polygon(
        corners.iter().map(|[x, y]| world(&[*x, *y, 0.0])).collect(),
    ));
    shapes
}

/// The body origins that loads name.
pub fn origins_used(problem: &crate::problem::Problem) -> Vec<BodyId> {
    let mut out = Vec::new();
    for load in &problem.loads {
        for p in named_points(&load.kind) {
            if let PointRef::Origin(b) = p {
                if !out.contains(&b) {
                    out.push(b);
                }
            }
        }
    }
    out
}

/// The named points a load acts at: a spring's or damper's ends, a force's point.
fn named_points(kind: &LoadKind) -> Vec<PointRef> {
    match kind {
        LoadKind::Spring { between, .. } | LoadKind::Damper { between, .. } => between.to_vec(),
        LoadKind::Force {
            at: crate::problem::ForcePoint::Point(p),
            ..
        } => vec![*p],
        _ => vec![],
    }
}
