//! `draw`: the pictures put every marked point where forward kinematics puts it, draw
//! known forces the way they act and every reaction at a free body's cut (none inside),
//! compile as TikZ, and refuse bad flags with a usage error.

use crate::support::all_problems;
use crate::svg_reader::{apply, parse, Element};
use mbd_tutor::cmd::derivation_at;
use mbd_tutor::equations::{Derivation, Method};
use mbd_tutor::mechanics::Vector;
use mbd_tutor::problem::{BodyId, LoadKind, PointRef, Problem, State};
use mbd_tutor::render::draw::{Drawing, View};
use mbd_tutor::solution::draw_pictures as draw;
use mbd_tutor::symbolic::{eval, Values};
use nalgebra::DMatrix;
use std::collections::BTreeMap;

/// A picture read back: its projection, its marked points and its arrows.
struct Read {
    name: String,
    projection: [f64; 8],
    points: BTreeMap<String, [f64; 2]>,
    arrows: Vec<(Element, [f64; 6])>,
}

impl Read {
    fn project(&self, p: [f64; 3]) -> [f64; 2] {
        let a = &self.projection;
        [
            a[0] * p[0] + a[1] * p[1] + a[2] * p[2] + a[6],
            a[3] * p[0] + a[4] * p[1] + a[5] * p[2] + a[7],
        ]
    }

    fn project_direction(&self, v: [f64; 3]) -> [f64; 2] {
        let a = &self.projection;
        [
            a[0] * v[0] + a[1] * v[1] + a[2] * v[2],
            a[3] * v[0] + a[4] * v[1] + a[5] * v[2],
        ]
    }
}

fn read(name: &str, svg: &str) -> Read {
    let root = parse(svg).unwrap_or_else(|e| panic!("{name}: not well-formed: {e}"));
    assert_eq!(root.name, "svg", "{name}");
    let numbers: Vec<f64> = root
        .attr("data-projection")
        .unwrap_or_else(|| panic!("{name}: no data-projection"))
        .split_whitespace()
        .map(|x| x.parse().expect("a number"))
        .collect();
    let projection: [f64; 8] = numbers.try_into().expect("eight numbers");
    let mut points = BTreeMap::new();
    let mut ids = std::collections::BTreeSet::new();
    let mut arrows = Vec::new();
    for (e, m) in root.walk() {
        assert!(
            e.name != "script" && e.attr("href").is_none(),
            "{name}: a script or reference"
        );
        if let Some(id) = e.attr("id") {
            assert!(ids.insert(id.to_string()), "{name}: id {id} twice");
            if e.name == "circle" {
                points.insert(id.to_string(), apply(m, [e.number("cx"), e.number("cy")]));
            }
        }
        if e.name == "g"
            && e.attr("class")
                .is_some_and(|c| c.split(' ').any(|w| w == "force"))
        {
            arrows.push((e.clone(), m));
        }
    }
    Read {
        name: name.to_string(),
        projection,
        points,
        arrows,
    }
}

fn values(problem: &Problem, q: &[f64], rates: &[f64]) -> Values {
    let mut v = Values::new();
    for c in &problem.constants {
        v.set(
            mbd_tutor::symbolic::Symbol::Const(c.name.as_str().into()),
            c.value,
        );
    }
    for i in 0..q.len() {
        v.set(problem.coordinate_symbol(i, 0), q[i]);
        v.set(problem.coordinate_symbol(i, 1), rates[i]);
    }
    v
}

/// A vector's components in N, evaluated (a path apart from the drawing's own rotations).
fn in_n(d: &Derivation, v: &Vector, values: &Values) -> [f64; 3] {
    let c = v.components_in(BodyId::GROUND, &d.model.frames);
    std::array::from_fn(|i| eval(&c[i], values))
}

fn point_of(problem: &Problem, id: &str) -> Option<PointRef> {
    let body = |name: &str| {
        problem
            .body_ids()
            .find(|b| problem.body_name(*b) == name)
            .or((name == "N").then_some(BodyId::GROUND))
    };
    if let Some(n) = id.strip_prefix("joint-") {
        return problem
            .joints
            .iter()
            .position(|j| j.name == n)
            .map(PointRef::Joint);
    }
    if let Some(n) = id.strip_prefix("cm-") {
        return body(n).map(PointRef::MassCenter);
    }
    if let Some(n) = id.strip_prefix("origin-") {
        return body(n).map(PointRef::Origin);
    }
    if let Some(n) = id.strip_prefix("point-") {
        return problem
            .points
            .iter()
            .position(|p| p.name == n)
            .map(PointRef::Named);
    }
    None
}

fn line(e: &Element, m: [f64; 6]) -> Option<([f64; 2], [f64; 2])> {
    let l = e.children.iter().find(|c| c.name == "line")?;
    Some((
        apply(m, [l.number("x1"), l.number("y1")]),
        apply(m, [l.number("x2"), l.number("y2")]),
    ))
}

fn angle_between(a: [f64; 2], b: [f64; 2]) -> f64 {
    let cross = a[0] * b[1] - a[1] * b[0];
    let dot = a[0] * b[0] + a[1] * b[1];
    cross.atan2(dot).abs()
}

fn drawings(
    problem: &Problem,
    method: Method,
    view: View,
) -> (Derivation<'_>, Vec<Drawing>, State) {
    let mut state = State {
        t: 0.0,
        q: problem.initial_coordinates(),
        rates: problem.coordinates.iter().map(|c| c.rate).collect(),
    };
    let (derivation, accelerations) =
        derivation_at(problem, method, &mut state).unwrap_or_else(|e| panic!("{e}"));
    let pictures = draw(
        &derivation,
        0.0,
        &state.q,
        &state.rates,
        accelerations.as_deref(),
        view,
    );
    (derivation, pictures, state)
}

/// The least-squares affine map from model to picture coordinates and its largest residual.
fn fit(model: &[[f64; 3]], picture: &[[f64; 2]], planar: bool) -> (DMatrix<f64>, f64) {
    let columns = if planar { 3 } else { 4 };
    let a = DMatrix::from_fn(model.len(), columns, |i, j| match (planar, j) {
        (true, 2) | (false, 3) => 1.0,
        _ => model[i][j],
    });
    let b = DMatrix::from_fn(picture.len(), 2, |i, j| picture[i][j]);
    let x = a
        .clone()
        .svd(true, true)
        .solve(&b, 1e-12)
        .expect("a least-squares fit");
    let residual = (&a * &x - &b).abs().max();
    (x, residual)
}

fn check_positions(d: &Derivation, r: &Read, values: &Values) {
    let problem = d.model.problem;
    let mut model = Vec::new();
    let mut drawn = Vec::new();
    for (id, at) in &r.points {
        // Closures and rolling contacts are sites after the joints, with their own points.
        let site = id.strip_prefix("joint-").and_then(|n| {
            d.model
                .sites
                .iter()
                .skip(problem.joints.len())
                .find(|s| s.name == n)
        });
        let position = match (point_of(problem, id), site) {
            (Some(point), _) => d.model.point(point).position,
            (None, Some(site)) => site.point.position.clone(),
            (None, None) => {
                assert!(id.starts_with("at-"), "{}: unknown id {id}", r.name);
                continue;
            }
        };
        let p = in_n(d, &position, values);
        let projected = r.project(p);
        for k in 0..2 {
            assert!(
                (projected[k] - at[k]).abs() < 0.01,
                "{}: {id} drawn at {at:?}, data-projection puts it at {projected:?}",
                r.name
            );
        }
        model.push(p);
        drawn.push(*at);
    }
    assert!(
        r.points.keys().any(|k| k.starts_with("cm-")),
        "{}: no mass center",
        r.name
    );
    let planar = d.model.is_planar();
    let (x, residual) = fit(&model, &drawn, planar);
    assert!(
        residual < 0.01,
        "{}: the drawn points fit no affine map (residual {residual})",
        r.name
    );
    let p = &r.projection;
    if planar {
        // The N.x-N.y plane seen from +N.z (version 3): a uniform scale, a rotation and
        // a flip of y, [[c, -s], [-s, -c]] times the scale.
        let scale = p[0].hypot(p[1]);
        assert!(
            p[2] == 0.0 && p[5] == 0.0 && scale > 0.0,
            "{}: {p:?}",
            r.name
        );
        assert!(
            (p[0] + p[4]).abs() < 1e-9 * scale && (p[1] - p[3]).abs() < 1e-9 * scale,
            "{}: {p:?}",
            r.name
        );
        // The fitted map, where the points determine it, is the declared one.
        let spread = DMatrix::from_fn(
            model.len(),
            3,
            |i, j| if j == 2 { 1.0 } else { model[i][j] },
        );
        let values = spread.svd(false, false).singular_values;
        if values.len() == 3 && values[2] > 1e-6 * values[0] {
            for (k, want) in [(0, 0, p[0]), (1, 1, p[4]), (0, 1, p[3]), (1, 0, p[1])]
                .map(|(i, j, w)| ((i, j), w))
            {
                assert!(
                    (x[k] - want).abs() < 1e-3 * p[0],
                    "{}: fitted {x} vs {p:?}",
                    r.name
                );
            }
        }
    } else {
        // A parallel projection: orthogonal rows of equal length.
        let rows = [[p[0], p[1], p[2]], [p[3], p[4], p[5]]];
        let n0 = rows[0].iter().map(|x| x * x).sum::<f64>().sqrt();
        let n1 = rows[1].iter().map(|x| x * x).sum::<f64>().sqrt();
        let dot: f64 = (0..3).map(|k| rows[0][k] * rows[1][k]).sum();
        assert!(
            (n0 - n1).abs() < 1e-9 * n0 && dot.abs() < 1e-9 * n0 * n0,
            "{}: {p:?}",
            r.name
        );
    }
}

fn gravity(problem: &Problem, values: &Values) -> [f64; 3] {
    let mut g = [0.0; 3];
    for (frame, axis, c) in &problem.gravity.as_ref().expect("gravity").terms {
        assert_eq!(
            *frame,
            BodyId::GROUND,
            "gravity is written in N in the bundled problems"
        );
        g[*axis as usize] += eval(c, values);
    }
    g
}

fn check_arrows(d: &Derivation, r: &Read, values: &Values) {
    let problem = d.model.problem;
    for (g, m) in &r.arrows {
        let name = &r.name;
        let kind = g.attr("data-kind").expect("data-kind");
        assert!(
            [
                "gravity",
                "spring",
                "damper",
                "load",
                "joint-load",
                "reaction",
                "inertia"
            ]
            .contains(&kind),
            "{name}: kind {kind}"
        );
        assert!(
            !g.attr("data-label").unwrap_or("").is_empty(),
            "{name}: an arrow without a label"
        );
        let at = g.attr("data-at").expect("data-at");
        let at_point = *r
            .points
            .get(at)
            .unwrap_or_else(|| panic!("{name}: data-at {at} is no circle"));
        let class = g.attr("class").unwrap_or("");
        let planar_couple = class.contains("couple") && d.model.is_planar();
        if planar_couple {
            assert!(
                g.children.iter().any(|c| c.name == "path"),
                "{name}: a couple without its arc"
            );
            assert!(
                matches!(g.attr("data-sense"), Some("+1" | "-1")),
                "{name}: data-sense"
            );
            continue;
        }
        let (tail, head) = line(g, *m).unwrap_or_else(|| panic!("{name}: an arrow without a line"));
        let drawn = [head[0] - tail[0], head[1] - tail[1]];
        assert!(
            drawn[0].hypot(drawn[1]) > 5.0,
            "{name}: a {kind} arrow too short to see"
        );
        // A force starts at its point, or ends there (a push drawn outside its body); a
        // moment vector is free, drawn off another arrow's line where it would lie on it.
        let near = |p: [f64; 2]| (p[0] - at_point[0]).hypot(p[1] - at_point[1]) < 0.01;
        let led = leaders::leads_to(g, *m, at_point, [tail, head]);
        // A push whose point lies in a bar's stroke ends at the bar's edge, on its line,
        // a few px short of the point.
        let short = {
            let length = drawn[0].hypot(drawn[1]);
            let to = [at_point[0] - head[0], at_point[1] - head[1]];
            let along = (to[0] * drawn[0] + to[1] * drawn[1]) / length;
            let across = (to[0] * drawn[1] - to[1] * drawn[0]).abs() / length;
            (0.0..8.0).contains(&along) && across < 0.01
        };
        if kind != "inertia" && !class.contains("couple") {
            assert!(
                near(tail) || near(head) || led || short,
                "{name}: the {kind} arrow neither starts nor ends at {at}"
            );
        }
        if kind == "gravity" {
            let expected = r.project_direction(gravity(problem, values));
            assert!(
                angle_between(drawn, expected) < 1e-3,
                "{name}: gravity drawn along {drawn:?}"
            );
        }
        if kind == "spring" {
            check_spring(d, r, g, drawn, values);
        }
    }
}

/// A spring arrow lies along the spring, pulling when it is longer than its free length.
fn check_spring(d: &Derivation, r: &Read, g: &Element, drawn: [f64; 2], values: &Values) {
    let problem = d.model.problem;
    let at = g.attr("data-at").expect("data-at");
    let label = g.attr("data-label").unwrap_or("");
    let mut matched = false;
    for load in &problem.loads {
        let LoadKind::Spring {
            between,
            free_length,
            ..
        } = &load.kind
        else {
            continue;
        };
        if load.name.as_deref().unwrap_or("spring") != label {
            continue;
        }
        let ids: Vec<String> = between
            .iter()
            .map(|p| mbd_tutor::solution::point_id(problem, *p))
            .collect();
        let Some(k) = ids.iter().position(|i| i == at) else {
            continue;
        };
        let here = in_n(d, &d.model.point(between[k]).position, values);
        let there = in_n(d, &d.model.point(between[1 - k]).position, values);
        let toward: [f64; 3] = std::array::from_fn(|i| there[i] - here[i]);
        let length = toward.iter().map(|x| x * x).sum::<f64>().sqrt();
        let stretch = length - eval(free_length, values);
        let mut expected = r.project_direction(toward);
        if stretch < 0.0 {
            expected = [-expected[0], -expected[1]];
        }
        assert!(
            angle_between(drawn, expected) < 1e-3,
            "{}: spring {label} drawn along {drawn:?}",
            r.name
        );
        matched = true;
    }
    assert!(
        matched,
        "{}: spring arrow {label} at {at} matches no spring",
        r.name
    );
}

/// The reactions drawn on a free body are exactly those of the joints its cut crosses,
/// each along its positive direction on the child (the opposite on the parent).
fn check_reactions(d: &Derivation, r: &Read, set: &[BodyId], values: &Values) {
    let problem = d.model.problem;
    let mut expected: Vec<(String, String, [f64; 3])> = Vec::new();
    // Every site: the joints, then the closures and rolling contacts.
    let _ = problem;
    for joint in &d.model.sites {
        let child = set.contains(&joint.child);
        if child == set.contains(&joint.parent) {
            continue;
        }
        for c in &joint.reactions {
            let (letter, rest) = (c.kind.letter(), c.axis.subscript());
            let sign = if child { 1.0 } else { -1.0 };
            let dir = in_n(d, &c.direction, values).map(|x| x * sign);
            // A light rod's tension is one unknown, T^Q, without a subscript; a point named
            // by a word is printed by the handout's letter for it (the lane's contact: P).
            let name = shown_letter(d, &joint.name);
            if let Some(slip) = slip_along(d, joint, c, values) {
                // Sliding friction, an unknown of the rows: drawn against the slip, not
                // along the + axis, and labelled by the rows' unknown signed as it points.
                let against = dir.map(|x| -x * slip.signum());
                let unknown = format!("{letter}^{name}_{rest}");
                check_sliding(
                    r,
                    &format!("joint-{}", joint.name),
                    against,
                    (&unknown, slip),
                );
                continue;
            }
            let label = match c.axis {
                mbd_tutor::symbolic::Axis::Member => format!("T^{name}"),
                _ => format!("{letter}^{name}_{rest}"),
            };
            expected.push((label, format!("joint-{}", joint.name), dir));
        }
    }
    let mut drawn: Vec<(String, String)> = Vec::new();
    for (g, m) in r
        .arrows
        .iter()
        .filter(|(g, _)| g.attr("data-kind") == Some("reaction"))
        // A sliding friction, signed as it points, is checked above against the slip.
        .filter(|(g, _)| !g.attr("data-label").is_some_and(|l| l.starts_with('-')))
    {
        let label = g.attr("data-label").unwrap_or("").to_string();
        let at = g.attr("data-at").unwrap_or("").to_string();
        let (_, _, dir) = expected
            .iter()
            .find(|(l, a, _)| *l == label && *a == at)
            .unwrap_or_else(|| panic!("{}: reaction {label} at {at} is not at the cut", r.name));
        if let Some((tail, head)) = line(g, *m) {
            let want = r.project_direction(*dir);
            if want[0].hypot(want[1]) > 1e-6 * r.projection[0].abs().max(1.0) {
                let got = [head[0] - tail[0], head[1] - tail[1]];
                assert!(
                    angle_between(got, want) < 1e-3,
                    "{}: {label} drawn along {got:?}, not {want:?}",
                    r.name
                );
            }
        } else {
            let sense = if dir[2] > 0.0 { "+1" } else { "-1" };
            assert_eq!(g.attr("data-sense"), Some(sense), "{}: {label}", r.name);
        }
        drawn.push((label, at));
    }
    let mut want: Vec<(String, String)> = expected.into_iter().map(|(l, a, _)| (l, a)).collect();
    want.sort();
    drawn.sort();
    assert_eq!(drawn, want, "{}: the reactions at the cut", r.name);
}

/// The name a picture prints for the site `name`: the handout's letter for a word (the
/// bowling ball's `lane` is P), else the name itself.
fn shown_letter(d: &Derivation, name: &str) -> String {
    let tex = mbd_tutor::symbolic::latex_name(name);
    mbd_tutor::solution::shown_names(&d.model)
        .into_iter()
        .find(|(word, _)| *word == tex)
        .map_or_else(|| name.to_string(), |(_, letter)| letter)
}

fn check_problem(path: &std::path::Path, method: Method) {
    let problem = mbd_tutor::problem::load_file(path).expect("a bundled problem");
    let (derivation, pictures, state) = drawings(&problem, method, View::Isometric);
    let values = values(&problem, &state.q, &state.rates);
    let sets = mbd_tutor::solution::free_body_sets(&derivation);
    assert_eq!(pictures.len(), sets.len() + 1, "{}", path.display());
    assert_eq!(pictures[0].name, "configuration");
    for (k, picture) in pictures.iter().enumerate() {
        let r = read(
            &format!("{} {}", path.display(), picture.name),
            &picture.svg(""),
        );
        check_positions(&derivation, &r, &values);
        check_arrows(&derivation, &r, &values);
        if k > 0 {
            let set = &sets[k - 1];
            let name: String = set
                .iter()
                .map(|b| problem.body_name(*b))
                .collect::<Vec<_>>()
                .join("+");
            assert_eq!(picture.name, format!("fbd-{name}"));
            check_reactions(&derivation, &r, set, &values);
        } else {
            let applied = |(g, _): &(Element, [f64; 6])| g.attr("data-kind") == Some("load");
            assert!(
                r.arrows.iter().all(applied),
                "the configuration: applied forces only"
            );
        }
    }
}

#[test]
fn every_bundled_problem_is_drawn_where_its_kinematics_puts_it() {
    for path in all_problems() {
        check_problem(&path, Method::MotionLaw);
    }
}

#[test]
fn every_body_of_newton_euler_is_cut_free_with_all_its_reactions() {
    for path in all_problems() {
        check_problem(&path, Method::NewtonEuler);
    }
}

mod browser;
mod clear;
mod closed_forms;
mod commands;
mod corners;
mod crowded;
mod handouts;
mod labels;
mod leaders;
mod marked;
mod overlap;
mod placement;
mod readable;
mod same_names;
mod sliding;
mod textbook;
mod truths;

use sliding::{check_sliding, slip_along};
