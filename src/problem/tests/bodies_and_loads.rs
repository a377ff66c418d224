//! Bodies and loads: each rule broken once.

use super::*;

#[test]
fn bodies() {
    rejects(
        base(),
        |p| p["bodies"]["A"]["mass"] = json!("-m"),
        "bodies.A.mass",
        "must not be negative",
    );
    // Mass 0 is a massless body, which has no inertia.
    rejects(
        base(),
        |p| {
            p["bodies"]["A"]["mass"] = json!(0);
            p["bodies"]["A"]["inertia"] = json!(1);
        },
        "bodies.A.inertia",
        "nonzero inertia",
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
