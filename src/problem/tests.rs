//! End-to-end tests of [`load`]: valid problems give the model the format page describes;
//! each rule, broken once, gives an error at the right path.

use super::*;
use crate::symbolic::Expr;
use serde_json::{json, Value};

/// The example of the format page, verbatim.
const DOUBLE_PENDULUM: &str = r#"{
  "title": "Double pendulum of two uniform rods",
  "dimension": 2,
  "constants": {
    "m": { "value": 1.0, "unit": "kg", "description": "mass of each rod" },
    "L": { "value": 0.5, "unit": "m", "description": "length of each rod" },
    "g": 9.81
  },
  "coordinates": {
    "q1": { "initial": 0.5, "description": "angle of rod A from the downward vertical" },
    "q2": { "initial": 0.0, "description": "angle of rod B relative to rod A" }
  },
  "gravity": "-g*N.y",
  "bodies": {
    "A": { "mass": "m", "center": "-L/2*A.y", "inertia": "m*L^2/12" },
    "B": { "mass": "m", "center": "-L/2*B.y", "inertia": "m*L^2/12" }
  },
  "joints": [
    { "name": "O", "type": "revolute", "parent": "N", "child": "A", "axis": "N.z", "coordinates": ["q1"] },
    { "name": "P", "type": "revolute", "parent": "A", "child": "B", "axis": "A.z", "at": "-L*A.y", "coordinates": ["q2"] }
  ],
  "find": { "reactions": ["O"] }
}"#;

fn c(name: &str) -> Expr {
    Expr::constant(name)
}

#[test]
fn the_format_page_example_loads() {
    let p = load(DOUBLE_PENDULUM).unwrap();
    assert_eq!(p.title, "Double pendulum of two uniform rods");
    assert_eq!(p.dimension, Dimension::Two);
    let constants: Vec<(&str, f64)> = p
        .constants
        .iter()
        .map(|k| (k.name.as_str(), k.value))
        .collect();
    assert_eq!(constants, [("m", 1.0), ("L", 0.5), ("g", 9.81)]);
    assert_eq!(p.constants[0].unit.as_deref(), Some("kg"));
    assert_eq!(p.constants[2].unit, None);
    let names: Vec<&str> = p.coordinates.iter().map(|q| q.name.as_str()).collect();
    assert_eq!(names, ["q1", "q2"]);
    assert_eq!(
        (p.coordinates[0].initial, p.coordinates[0].rate),
        (0.5, 0.0)
    );
    assert_eq!(
        (p.coordinates[1].joint, p.coordinates[1].kind),
        (1, CoordinateKind::Angle)
    );
    assert_eq!(p.gravity.unwrap().terms, vec![(BodyId::GROUND, 1, -c("g"))]);
    assert_eq!(p.bodies[1].name, "B");
    assert_eq!(p.bodies[1].mass, c("m"));
    // -L/2*B.y: frame B is BodyId(2), axis y is 1.
    assert_eq!(
        p.bodies[1].center.terms,
        vec![(BodyId(2), 1, -(c("L") / Expr::int(2)))]
    );
    let twelfth = Expr::ratio(1, 12) * c("m") * c("L") * c("L");
    assert_eq!(p.bodies[0].inertia, Inertia::Planar(twelfth));
    let pin = &p.joints[1];
    assert_eq!(
        (pin.kind, pin.parent, pin.child),
        (JointKind::Revolute, BodyId(1), BodyId(2))
    );
    assert_eq!(
        pin.axis.as_ref().unwrap().terms,
        vec![(BodyId(1), 2, Expr::one())]
    );
    assert_eq!(pin.at.terms, vec![(BodyId(1), 1, -c("L"))]);
    assert!(pin.child_at.terms.is_empty());
    assert_eq!(pin.path, "joints[1]");
    assert_eq!(p.find_reactions, [0]);
    assert_eq!(
        p.simulate,
        SimulateSettings {
            duration: 5.0,
            output_step: 0.01,
            tolerance: 1e-9
        }
    );
}

#[test]
fn a_3d_problem_with_every_joint_type_loads() {
    let p = load(include_str!("../../problems/validation/all-joints-3d.json")).unwrap();
    assert_eq!(p.dimension, Dimension::Three);
    let kinds: Vec<JointKind> = p.joints.iter().map(|j| j.kind).collect();
    use JointKind::*;
    assert_eq!(
        kinds,
        [
            Revolute,
            Prismatic,
            Cylindrical,
            Universal,
            Spherical,
            Free,
            Weld
        ]
    );
    // The coordinates in the order the joints name them, with the kinds the table gives.
    let (a, d) = (CoordinateKind::Angle, CoordinateKind::Distance);
    let order: Vec<(&str, CoordinateKind)> = p
        .coordinates
        .iter()
        .map(|q| (q.name.as_str(), q.kind))
        .collect();
    assert_eq!(
        order,
        [
            ("qA", a),
            ("sB", d),
            ("sC", d),
            ("qC", a),
            ("qD1", a),
            ("qD2", a),
            ("qE1", a),
            ("qE2", a),
            ("qE3", a),
            ("xF", d),
            ("yF", d),
            ("zF", d),
            ("qF1", a),
            ("qF2", a),
            ("qF3", a),
        ]
    );
    assert_eq!(
        (p.coordinates[3].joint, p.coordinates[3].index_in_joint),
        (2, 1)
    );
    assert_eq!(
        (p.coordinates[11].initial, p.coordinates[11].rate),
        (1.0, 0.5)
    );
    assert_eq!(p.joints[3].sequence, [0, 1]);
    assert_eq!(p.joints[4].sequence, [2, 0, 1]);
    assert_eq!(p.joints[5].coordinates, (9..15).collect::<Vec<_>>());
    assert!(p.joints[6].coordinates.is_empty() && p.joints[6].axis.is_none());
    assert_eq!(p.find_reactions, [0, 6]);
    let Inertia::Spatial(d_inertia) = &p.bodies[3].inertia else {
        panic!("3D inertia expected")
    };
    assert_eq!(d_inertia[0][1], d_inertia[1][0]);
    assert!(d_inertia[1][2].is_zero());
    assert_eq!(p.loads.len(), 8);
    assert!(matches!(
        p.loads[6].kind,
        LoadKind::Force {
            at: ForcePoint::Point(PointRef::Named(1)),
            ..
        }
    ));
    assert!(matches!(
        p.loads[7].kind,
        LoadKind::Force {
            at: ForcePoint::Offset(_),
            ..
        }
    ));
    assert!(matches!(
        p.loads[4].kind,
        LoadKind::Spring {
            between: [PointRef::Named(0), PointRef::MassCenter(BodyId(6))],
            ..
        }
    ));
    assert!(matches!(
        p.loads[0].kind,
        LoadKind::Torque {
            reaction_on: Some(BodyId::GROUND),
            ..
        }
    ));
    assert_eq!(p.simulate.duration, 2.0);
}

#[test]
fn every_example_problem_loads() {
    let directory = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems");
    for entry in std::fs::read_dir(directory).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "json") {
            if let Err(e) = load_file(&path) {
                panic!("{}: {e}", path.display());
            }
        }
    }
}

/// A small valid 2D problem to break one rule at a time.
fn base() -> Value {
    json!({
        "title": "Pendulum on a cart",
        "dimension": 2,
        "constants": { "m": 1.0, "L": 0.5, "g": 9.81, "k": 10 },
        "gravity": "-g*N.y",
        "bodies": {
            "A": { "mass": "m", "inertia": 0 },
            "B": { "mass": "m", "center": "-L/2*B.y", "inertia": "m*L^2/12" }
        },
        "joints": [
            { "name": "S", "type": "prismatic", "parent": "N", "child": "A", "axis": "N.x", "coordinates": ["x"] },
            { "name": "O", "type": "revolute", "parent": "A", "child": "B", "coordinates": ["q"] }
        ],
        "points": { "P": { "on": "B", "at": "-L*B.y" } },
        "loads": [
            { "type": "joint_spring", "joint": "S", "coordinate": "x", "stiffness": "k" },
            { "type": "force", "on": "B", "at": "P", "vector": "sin(t)*N.x" }
        ]
    })
}

fn base_3d() -> Value {
    json!({
        "title": "Top",
        "dimension": 3,
        "constants": { "m": 1.0, "r": 0.1 },
        "bodies": { "A": { "mass": "m", "inertia": { "xx": "m*r^2/4", "yy": "m*r^2/4", "zz": "m*r^2/2" } } },
        "joints": [ { "name": "O", "type": "spherical", "parent": "N", "child": "A", "sequence": "zxz", "coordinates": ["a", "b", "c"] } ]
    })
}

/// The errors of `problem` as `path: message`.
fn errors_of(problem: &Value) -> Vec<String> {
    match load(&problem.to_string()) {
        Ok(_) => Vec::new(),
        Err(ProblemErrors(errors)) => errors
            .iter()
            .map(|e| format!("{}: {}", e.path, e.message))
            .collect(),
    }
}

/// Edits the base problem and expects exactly one error, at `path`, saying `words`.
#[track_caller]
fn rejects(mut problem: Value, edit: impl FnOnce(&mut Value), path: &str, words: &str) {
    edit(&mut problem);
    let errors = errors_of(&problem);
    assert!(
        errors.len() == 1
            && errors[0].starts_with(&format!("{path}: "))
            && errors[0].contains(words),
        "expected one error at {path} saying {words:?}, got {errors:#?}"
    );
}

/// Edits the base problem and expects, among its errors, one at `path` saying `words`.
#[track_caller]
fn reports(mut problem: Value, edit: impl FnOnce(&mut Value), path: &str, words: &str) {
    edit(&mut problem);
    let errors = errors_of(&problem);
    assert!(
        errors
            .iter()
            .any(|e| e.starts_with(&format!("{path}: ")) && e.contains(words)),
        "expected an error at {path} saying {words:?}, got {errors:#?}"
    );
}

fn push_load(problem: &mut Value, load: Value) {
    if let Some(loads) = problem["loads"].as_array_mut() {
        loads.push(load);
    }
}

#[test]
fn the_bases_are_valid() {
    assert_eq!(errors_of(&base()), Vec::<String>::new());
    assert_eq!(errors_of(&base_3d()), Vec::<String>::new());
}

#[test]
fn names() {
    rejects(
        base(),
        |p| p["constants"]["N"] = json!(1),
        "constants.N",
        "may not be declared",
    );
    rejects(
        base(),
        |p| p["constants"]["t"] = json!(1),
        "constants.t",
        "reserved",
    );
    rejects(
        base(),
        |p| p["constants"]["pi"] = json!(3),
        "constants.pi",
        "reserved",
    );
    rejects(
        base(),
        |p| p["constants"]["A"] = json!(1),
        "bodies.A",
        "already a constant",
    );
    rejects(
        base(),
        |p| p["points"]["q"] = json!({"on": "A"}),
        "points.q",
        "already a coordinate",
    );
    rejects(
        base(),
        |p| p["constants"]["2x"] = json!(1),
        "constants[\"2x\"]",
        "not a valid name",
    );
    rejects(
        base(),
        |p| p["joints"][1]["name"] = json!("S"),
        "joints[1].name",
        "already a joint",
    );
}

#[test]
fn duplicate_keys_in_the_text() {
    let text = DOUBLE_PENDULUM.replace("\"g\": 9.81", "\"g\": 9.81, \"g\": 10");
    let errors = load(&text).unwrap_err().0;
    assert_eq!(errors.len(), 1);
    assert_eq!(errors[0].path, "constants.g");
}

#[test]
fn unknown_keys_get_suggestions() {
    let mut p = base();
    p["bodies"]["A"]["mas"] = json!("m");
    p["titel"] = json!("x");
    let errors = load(&p.to_string()).unwrap_err().0;
    let found: Vec<(&str, Option<&str>)> = errors
        .iter()
        .map(|e| (e.path.as_str(), e.hint.as_deref()))
        .collect();
    // File order: `titel` comes last in the text, the body first.
    assert_eq!(found[0].0, "bodies.A.mas");
    assert!(
        found
            .iter()
            .any(|(path, hint)| *path == "titel" && *hint == Some("did you mean `title`?")),
        "{found:?}"
    );
}

#[test]
fn the_tree() {
    // B then has no joint to a parent either: that is reported too.
    reports(
        base(),
        |p| p["joints"][1]["child"] = json!("A"),
        "joints[1].child",
        "itself",
    );
    reports(
        base(),
        |p| p["joints"][1]["child"] = json!("N"),
        "joints[1].child",
        "cannot be a child",
    );
    reports(
        base(),
        |p| p["joints"][0]["parent"] = json!("B"),
        "joints[0]",
        "closed loop (B -> A -> B)",
    );
    rejects(
        base(),
        |p| p["bodies"]["C"] = json!({"mass": "m"}),
        "bodies.C",
        "not connected",
    );
    let mut two_parents = base();
    two_parents["joints"][1]["child"] = json!("A");
    two_parents["joints"][1]["parent"] = json!("N");
    let errors = errors_of(&two_parents);
    assert!(
        errors
            .iter()
            .any(|e| e.starts_with("joints[1].child") && e.contains("already has a parent")),
        "{errors:?}"
    );
}

#[test]
fn joints() {
    rejects(
        base(),
        |p| p["joints"][1]["coordinates"] = json!(["q", "r"]),
        "joints[1].coordinates",
        "1 coordinate, not 2",
    );
    rejects(
        base(),
        |p| p["joints"][1]["coordinates"] = json!(["x"]),
        "joints[1].coordinates[0]",
        "already belongs to joint `S`",
    );
    rejects(
        base(),
        |p| p["joints"][1]["type"] = json!("revolut"),
        "joints[1].type",
        "unknown joint type",
    );
    rejects(
        base(),
        |p| p["joints"][0]["axis"] = json!("N.z"),
        "joints[0].axis",
        "`N.z` component",
    );
    rejects(
        base(),
        |p| p["joints"][0]["axis"] = json!("0*N.x"),
        "joints[0].axis",
        "zero",
    );
    rejects(
        base(),
        |p| p["joints"][0]["axis"] = json!("(L - 0.5)*N.x"),
        "joints[0].axis",
        "zero",
    );
    rejects(
        base(),
        |p| p["joints"][1]["axis"] = json!("A.x"),
        "joints[1].axis",
        "along z",
    );
    rejects(
        base(),
        |p| p["joints"][1]["axis"] = json!("q*N.z"),
        "joints[1].axis",
        "a coordinate",
    );
    rejects(
        base(),
        |p| p["joints"][0]["sequence"] = json!("xy"),
        "joints[0].sequence",
        "has no `sequence`",
    );
    rejects(
        base(),
        |p| {
            p["joints"][0]
                .as_object_mut()
                .unwrap()
                .remove("axis")
                .map(drop)
                .unwrap_or(())
        },
        "joints[0].axis",
        "needs an `axis`",
    );
    rejects(
        base(),
        |p| p["coordinates"] = json!({"z": {"initial": 1}}),
        "coordinates.z",
        "no joint names",
    );
    for three_d_only in ["spherical", "universal", "free", "cylindrical"] {
        let mut p = base();
        p["joints"][1] = json!({"name": "O", "type": three_d_only, "parent": "A", "child": "B"});
        let errors = errors_of(&p);
        assert!(
            errors
                .iter()
                .any(|e| e.starts_with("joints[1].type") && e.contains("3D")),
            "{errors:?}"
        );
    }
    // The prismatic axis must not turn relative to the parent: B turns, N does not.
    let mut p = base();
    p["bodies"]["C"] = json!({"mass": "m"});
    let slider = json!({"name": "R", "type": "prismatic", "parent": "B", "child": "C", "axis": "N.x", "coordinates": ["s"]});
    p["joints"].as_array_mut().unwrap().push(slider);
    assert!(
        errors_of(&p)[0].contains("turns relative to `B`"),
        "{:?}",
        errors_of(&p)
    );
}

#[test]
fn sequences() {
    rejects(
        base_3d(),
        |p| p["joints"][0]["sequence"] = json!("zxzz"),
        "joints[0].sequence",
        "three letters, not 4",
    );
    rejects(
        base_3d(),
        |p| p["joints"][0]["sequence"] = json!("zwx"),
        "joints[0].sequence",
        "`w` is not an axis",
    );
    rejects(
        base_3d(),
        |p| p["joints"][0]["sequence"] = json!("zzx"),
        "joints[0].sequence",
        "same axis",
    );
    let mut universal = base_3d();
    universal["joints"][0] = json!({"name": "O", "type": "universal", "parent": "N", "child": "A", "sequence": "xyz", "coordinates": ["a", "b"]});
    assert!(errors_of(&universal)[0].contains("two letters, not 3"));
}

#[test]
fn bodies() {
    rejects(
        base(),
        |p| p["bodies"]["A"]["mass"] = json!("-m"),
        "bodies.A.mass",
        "positive",
    );
    rejects(
        base(),
        |p| p["bodies"]["A"]["mass"] = json!(0),
        "bodies.A.mass",
        "positive",
    );
    rejects(
        base(),
        |p| p["bodies"]["A"]["mass"] = json!("m/0"),
        "bodies.A.mass",
        "evaluates to",
    );
    rejects(
        base(),
        |p| p["bodies"]["A"]["mass"] = json!("m*q'"),
        "bodies.A.mass",
        "a rate",
    );
    rejects(
        base(),
        |p| p["bodies"]["A"]["inertia"] = json!("-1"),
        "bodies.A.inertia",
        "negative",
    );
    rejects(
        base(),
        |p| p["bodies"]["A"]["inertia"] = json!({"xx": 1}),
        "bodies.A.inertia",
        "one scalar",
    );
    rejects(
        base(),
        |p| p["bodies"]["A"]["center"] = json!("L*A.z"),
        "bodies.A.center",
        "`A.z` component",
    );
    rejects(
        base(),
        |p| p["bodies"]["A"]["center"] = json!("3"),
        "bodies.A.center",
        "has no unit vector",
    );
    rejects(
        base(),
        |p| p["bodies"]["A"]["center"] = json!("L*B.x"),
        "bodies.A.center",
        "turns relative to `A`",
    );
    rejects(
        base_3d(),
        |p| p["bodies"]["A"]["inertia"] = json!("1"),
        "bodies.A.inertia",
        "an object",
    );
    rejects(
        base_3d(),
        |p| p["bodies"]["A"]["inertia"]["zz"] = json!("m*r^2"),
        "bodies.A.inertia",
        "triangle",
    );
    rejects(
        base_3d(),
        |p| p["bodies"]["A"]["inertia"]["xz"] = json!(0),
        "bodies.A.inertia.xz",
        "unknown key",
    );
}

#[test]
fn loads() {
    rejects(
        base(),
        |p| p["loads"][1]["on"] = json!("C"),
        "loads[1].on",
        "unknown body",
    );
    rejects(
        base(),
        |p| p["loads"][1]["at"] = json!("Q"),
        "loads[1].at",
        "unknown point",
    );
    rejects(
        base(),
        |p| p["loads"][1]["on"] = json!("A"),
        "loads[1].at",
        "not fixed on `A`",
    );
    rejects(
        base(),
        |p| p["loads"][1]["vector"] = json!("3"),
        "loads[1].vector",
        "has no unit vector",
    );
    rejects(
        base(),
        |p| p["loads"][1]["vector"] = json!("N.x*N.y"),
        "loads[1].vector",
        "linearly",
    );
    rejects(
        base(),
        |p| p["loads"][1]["vector"] = json!("q''*N.x"),
        "loads[1].vector",
        "second rate",
    );
    rejects(
        base(),
        |p| p["loads"][0]["coordinate"] = json!("q"),
        "loads[0].coordinate",
        "of joint `O`, not of `S`",
    );
    rejects(
        base(),
        |p| p["loads"][0]["joint"] = json!("Z"),
        "loads[0].joint",
        "unknown joint",
    );
    rejects(
        base(),
        |p| p["loads"][0]["type"] = json!("joint_sping"),
        "loads[0].type",
        "unknown load type",
    );
    rejects(
        base(),
        |p| p["loads"][0]["stiffness"] = json!("k/0"),
        "loads[0].stiffness",
        "evaluates to",
    );
    rejects(
        base(),
        |p| push_load(p, json!({"type": "torque", "on": "B", "vector": "N.x"})),
        "loads[2].vector",
        "about N.z",
    );
    rejects(
        base(),
        |p| {
            push_load(
                p,
                json!({"type": "spring", "between": ["P", "P"], "stiffness": "k"}),
            )
        },
        "loads[2].between",
        "same point",
    );
    rejects(
        base(),
        |p| {
            push_load(
                p,
                json!({"type": "damper", "between": ["B*", "A.x"], "coefficient": 1}),
            )
        },
        "loads[2].between[1]",
        "unknown point",
    );
    // Loads may use coordinates, first rates and time.
    let mut p = base();
    push_load(
        &mut p,
        json!({"type": "joint_actuator", "joint": "O", "coordinate": "q", "value": "-q'*k*sin(t) + x"}),
    );
    assert!(errors_of(&p).is_empty());
}

#[test]
fn find_simulate_and_the_top_level() {
    rejects(
        base(),
        |p| p["find"] = json!({"reactions": ["P"]}),
        "find.reactions[0]",
        "not a joint",
    );
    rejects(
        base(),
        |p| p["find"] = json!({"reactions": ["Q"]}),
        "find.reactions[0]",
        "unknown joint",
    );
    rejects(
        base(),
        |p| p["simulate"] = json!({"duration": -1, "output_step": 0.001}),
        "simulate.duration",
        "positive",
    );
    rejects(
        base(),
        |p| p["simulate"] = json!({"duration": 1, "output_step": 2}),
        "simulate.output_step",
        "longer than the duration",
    );
    rejects(base(), |p| p["dimension"] = json!(4), "dimension", "2 or 3");
    rejects(
        base(),
        |p| p["format"] = json!(2),
        "format",
        "not supported",
    );
    rejects(
        base(),
        |p| p["constants"]["m"] = json!("1"),
        "constants.m",
        "expected a number or an object",
    );
}

#[test]
fn not_json() {
    for (text, words) in [
        ("", "empty"),
        ("{", "not valid JSON"),
        ("[1, 2]", "expected an object"),
    ] {
        let errors = load(text).unwrap_err().0;
        assert!(errors[0].message.contains(words), "{text:?}: {errors:?}");
    }
}

#[test]
fn overrides_are_checked_again() {
    let mut p = load(DOUBLE_PENDULUM).unwrap();
    apply_overrides(&mut p, &[("m".into(), 2.0)]).unwrap();
    assert_eq!(p.constants[0].value, 2.0);
    let e = apply_overrides(&mut p, &[("m".into(), -1.0)])
        .unwrap_err()
        .0;
    // Both masses, and both inertias m*L^2/12, are now negative.
    let paths: Vec<&str> = e.iter().map(|e| e.path.as_str()).collect();
    assert_eq!(
        paths,
        [
            "bodies.A.mass",
            "bodies.A.inertia",
            "bodies.B.mass",
            "bodies.B.inertia"
        ]
    );
    assert_eq!(
        p.constants[0].value, 2.0,
        "a failed override leaves the problem as it was"
    );
    let e = apply_overrides(&mut p, &[("mm".into(), 1.0)])
        .unwrap_err()
        .0;
    assert_eq!(e[0].hint.as_deref(), Some("did you mean `m`?"));
    let e = apply_overrides(&mut p, &[("q1".into(), 1.0)])
        .unwrap_err()
        .0;
    assert!(e[0].hint.as_deref().unwrap().contains("coordinate"));
}

#[test]
fn display_lists_every_error_with_its_hint() {
    let errors = ProblemErrors(vec![
        ProblemError {
            path: "joints[1].axis".into(),
            column: Some(3),
            message: "bad".into(),
            hint: Some("fix it".into()),
        },
        ProblemError::file("the file is empty"),
    ]);
    assert_eq!(
        errors.to_string(),
        "the problem has 2 errors:\n  joints[1].axis, column 3: bad\n    hint: fix it\n  the file is empty"
    );
}
