//! `gear` contacts: a gear pair driven by a torque (the reflected inertia), and a disc
//! rolling inside a fixed cylinder (its small-oscillation period), against closed forms
//! worked by hand below.

use crate::support::{
    assert_close, column, method_json, problem, problem_json, scratch, simulate, solve_all, METHODS,
};
use mbd_tutor::equations::Method;
use mbd_tutor::numeric::{Compiled, System};
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::plan::Sum;
use mbd_tutor::problem::load_file;
use mbd_tutor::symbolic::{add, linear_split, mul, pow, Expr, Symbol};

/// `problems/gear-pair-torque.json`.
const RA: f64 = 0.05;
const RB: f64 = 0.15;
const IA: f64 = 0.002;
const IB: f64 = 0.03;
const T: f64 = 1.2;

/// No slip at the pitch point, rA qA' = −rB qB', makes the pair one wheel of inertia
/// IA + IB (rA/rB)² under T. The tooth force F on B along the common tangent N.y turns B:
/// IB qB'' = −rB F.
#[test]
fn a_gear_pair_turns_with_the_reflected_inertia_by_every_method() {
    let qa_dd = T / (IA + IB * (RA / RB).powi(2));
    let qb_dd = -RA / RB * qa_dd;
    let tooth = -IB * qb_dd / RB;
    for s in solve_all("gear-pair-torque", &[]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("qA"), qa_dd, 1e-9, 1.0, &what("qA''"));
        assert_close(s.acc("qB"), qb_dd, 1e-9, 1.0, &what("qB''"));
        let rate = |q: &str| s.json["state"][q].as_f64().unwrap();
        assert_close(
            RA * rate("qA'"),
            -RB * rate("qB'"),
            1e-12,
            1.0,
            &what("no slip"),
        );
        // The force of A on B, in A's unit vectors: F N.y seen from A turned by qA.
        let qa = rate("qA");
        let force = s.force("mesh");
        assert_close(force[0], tooth * qa.sin(), 1e-9, 1.0, &what("mesh x"));
        assert_close(force[1], tooth * qa.cos(), 1e-9, 1.0, &what("mesh y"));
    }
}

#[test]
fn the_gear_pair_gains_the_work_of_its_torque() {
    let (columns, rows) = simulate("gear-pair-torque", &[]);
    let at = |name: &str| column(&columns, name);
    let (qa, wa, wb) = (at("qA"), at("qA'"), at("qB'"));
    let balance = |r: &[f64]| IA * r[wa].powi(2) / 2.0 + IB * r[wb].powi(2) / 2.0 - T * r[qa];
    let start = balance(&rows[0]);
    for row in &rows {
        assert_close(
            balance(row),
            start,
            1e-7,
            10.0,
            "kinetic energy − work of T",
        );
        assert_close(RA * row[wa], -RB * row[wb], 1e-7, 1.0, "no slip");
    }
}

/// `problems/disc-in-cylinder.json`: m = 1, r = 0.1, R = 0.5, g = 9.81.
const R_DISC: f64 = 0.1;
const R_CYL: f64 = 0.5;
const G: f64 = 9.81;

/// With φ the angle of the line of centres from the bottom, rolling inside gives the
/// disc's spin ω = −(R − r) φ'/r, and energy (3/4) m (R − r)² φ'² − m g (R − r) cos φ,
/// so φ'' = −(2g / (3(R − r))) sin φ.
#[test]
fn a_disc_inside_a_cylinder_by_every_method() {
    let arm = R_CYL - R_DISC;
    let (x, x_d) = (0.05, 0.3);
    let phi = (x / arm).asin();
    let phi_d = x_d / (arm * phi.cos());
    let phi_dd = -2.0 * G / (3.0 * arm) * phi.sin();
    for s in solve_all("disc-in-cylinder", &["--state", "x=0.05,x'=0.3"]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        let theta_d = s.json["state"]["theta'"].as_f64().unwrap();
        assert_close(theta_d, -arm * phi_d / R_DISC, 1e-9, 1.0, &what("theta'"));
        let x_dd = arm * (phi.cos() * phi_dd - phi.sin() * phi_d.powi(2));
        let y_dd = arm * (phi.sin() * phi_dd + phi.cos() * phi_d.powi(2));
        assert_close(s.acc("x"), x_dd, 1e-9, 1.0, &what("x''"));
        assert_close(s.acc("y"), y_dd, 1e-9, 1.0, &what("y''"));
        assert_close(
            s.acc("theta"),
            -arm * phi_dd / R_DISC,
            1e-9,
            1.0,
            &what("theta''"),
        );
    }
    // Rolling at the bottom: the contact point is at rest, so the spin is −v/r.
    for s in solve_all("disc-in-cylinder", &["--state", "x=0,x'=0.3"]) {
        let theta_d = s.json["state"]["theta'"].as_f64().unwrap();
        assert_close(theta_d, -0.3 / R_DISC, 1e-9, 1.0, "spin at the bottom");
    }
}

#[test]
fn the_disc_inside_a_cylinder_oscillates_with_the_textbook_period() {
    let omega = (2.0 * G / (3.0 * (R_CYL - R_DISC))).sqrt();
    let period = 2.0 * std::f64::consts::PI * (3.0 * (R_CYL - R_DISC) / (2.0 * G)).sqrt();
    assert_close(
        2.0 * std::f64::consts::PI / omega,
        period,
        1e-12,
        1.0,
        "period",
    );
    for method in METHODS {
        let path = problem("disc-in-cylinder");
        let l = method_json("linearize", &path, method, &["--state", "x=0,x'=0"]);
        let largest = l["eigenvalues"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| e["im"].as_f64().unwrap())
            .fold(0.0f64, f64::max);
        assert_close(largest, omega, 1e-7, 1.0, &format!("{method}: ω"));
    }
}

/// Kane's method with the disc's one independent speed x' (y' and θ' follow from the
/// contact): one row for x', one auxiliary row for each of the contact's two requested force
/// components, then the two constraint rows, and no other constraint force an unknown. The
/// no-slip row reads r θ' (the line of centres is a unit vector on the motion), and with it
/// θ' = (R − r)/(r y) x'.
///
/// By hand, with φ the angle of the line of centres from the bottom, x = (R − r) sin φ and
/// y = −(R − r) cos φ, (3/2)(R − r) φ'' = −g sin φ; released at rest, x'' = (R − r) cos φ φ''.
#[test]
fn the_disc_inside_a_cylinder_has_kanes_rows_of_its_one_independent_speed() {
    let path = problem("disc-in-cylinder");
    let disc = load_file(&path).expect("valid");
    let kane = derive(&disc, Method::Kane, Purpose::Rows).expect("derives");
    assert!(kane.kept_forces.is_none(), "{:?}", kane.kept_forces);
    let speeds = kane.dependent_speeds.as_ref().expect("independent speeds");
    let index = |name: &str| {
        disc.coordinates
            .iter()
            .position(|c| c.name == name)
            .unwrap()
    };
    assert_eq!(speeds.independent, [index("x")]);
    let rows: Vec<String> = kane
        .rows
        .iter()
        .map(|row| match &row.sum {
            Sum::Generalized { speed } => speed.clone(),
            Sum::Constraint { name } => name.clone(),
            other => panic!("not one of Kane's rows: {other:?}"),
        })
        .collect();
    assert_eq!(
        rows,
        [
            "x'",
            "u(contact.Ft1)",
            "u(contact.Fn)",
            "contact.Ft1",
            "contact.Fn"
        ]
    );
    let x_dd = Symbol::Coord("x".into(), 2);
    assert_eq!(kane.rows[0].unknowns, [x_dd], "x' row: no constraint force");
    // r θ' in the no-slip row; θ' = (R − r)/(r y) x'.
    let (r, big, y) = (
        Expr::constant("r"),
        Expr::constant("R"),
        Expr::coord("y", 0),
    );
    let slip = &kane.model.constraints.rows[0];
    let rates: Vec<Symbol> = ["x", "y", "theta"]
        .map(|q| Symbol::Coord(q.into(), 1))
        .to_vec();
    let (coefficients, _) = linear_split(&slip.velocity, &rates).expect("linear");
    assert_eq!(coefficients[2], r, "no-slip row: {}", slip.velocity);
    let spin = speeds
        .dependent
        .iter()
        .position(|&d| d == index("theta"))
        .unwrap();
    let expected = mul([
        add([big, -r.clone()]),
        pow(r, Expr::int(-1)),
        pow(y, Expr::int(-1)),
    ]);
    assert_eq!(speeds.c[spin][0], expected);
    // x'' at the initial state, released at rest.
    let compiled = Compiled::new(&kane);
    let mut q: Vec<f64> = disc.initial_coordinates();
    let mut rates = vec![0.0; q.len()];
    compiled
        .assemble(0.0, &mut q, &mut rates)
        .expect("assembles");
    let arm = R_CYL - R_DISC;
    assert_close(
        q[index("y")],
        -(arm * arm - 0.05f64.powi(2)).sqrt(),
        1e-12,
        1.0,
        "y",
    );
    let phi = (0.05 / arm).asin();
    let phi_dd = -G * phi.sin() / (1.5 * arm);
    let ours = compiled.solve(0.0, &q, &rates).expect("solves");
    assert_close(
        ours.accelerations[index("x")],
        arm * phi.cos() * phi_dd,
        1e-12,
        1.0,
        "x''",
    );
}

/// `problems/rack-and-pinion.json`: the pinion's pitch circle rolls on the moving rack,
/// x' = r θ', so (I + M r²) θ'' = T, and the rack's push on the pinion is −M r θ'' N.x.
#[test]
fn a_pinion_drives_its_rack_by_every_method() {
    let (r, i, m, t) = (0.04, 0.001, 2.0, 0.5);
    let theta_dd = t / (i + m * r * r);
    for s in solve_all("rack-and-pinion", &[]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("theta"), theta_dd, 1e-9, 1.0, &what("theta''"));
        assert_close(s.acc("x"), r * theta_dd, 1e-9, 1.0, &what("x''"));
        let rate = |q: &str| s.json["state"][q].as_f64().unwrap();
        assert_close(rate("x'"), 0.1, 1e-12, 1.0, &what("the given x' is kept"));
        assert_close(rate("theta'"), 0.1 / r, 1e-9, 1.0, &what("theta'"));
        let teeth = s.force("teeth");
        assert_close(teeth[0], -m * r * theta_dd, 1e-9, 1.0, &what("tooth force"));
    }
}

/// The same gear pair written in 3D (axles along z, the common axle given as `B.z`) gives
/// the planar answers.
#[test]
fn the_gear_pair_in_3d_agrees_with_the_plane() {
    let mut p = problem_json("gear-pair-torque");
    p["dimension"] = 3.into();
    p["bodies"]["A"]["inertia"] = serde_json::json!({ "xx": "IA/2", "yy": "IA/2", "zz": "IA" });
    p["bodies"]["B"]["inertia"] = serde_json::json!({ "xx": "IB/2", "yy": "IB/2", "zz": "IB" });
    p["constraints"][0]["axis"] = "B.z".into();
    let path = scratch("gear-3d", "gear-pair-3d", &p);
    let qa_dd = T / (IA + IB * (RA / RB).powi(2));
    for method in METHODS {
        let s = method_json("solve", &path, method, &[]);
        let acc = s["accelerations"]["qA"].as_f64().unwrap();
        assert_close(acc, qa_dd, 1e-9, 1.0, &format!("{method}: 3D qA''"));
    }
    std::fs::remove_dir_all(path.parent().expect("its folder")).ok();
}

/// The rack slides on its underside S, 2b below its pitch line, its mass centre b below
/// it. It only translates, so about S: M_z^S + (2b n̂_y) × (F n̂_x) = (b n̂_y) × (M ẍ n̂_x),
/// with F = M ẍ the pinion's push on it at the pitch line: M_z^S = 2bF − bMẍ = b M ẍ.
#[test]
fn the_rack_bears_on_its_slide_with_the_couple_of_its_push() {
    let (b, m) = (0.02, 2.0);
    let mut p = problem_json("rack-and-pinion");
    p["find"]["reactions"] = serde_json::json!(["teeth", "S"]);
    let path = scratch("rack-slide", "rack-slide", &p);
    for method in METHODS {
        let s = method_json("solve", &path, method, &[]);
        let xdd = s["accelerations"]["x"].as_f64().unwrap();
        let couple = s["reactions"]["S"]["moment"][2].as_f64().unwrap();
        let normal = s["reactions"]["S"]["force"][1].as_f64().unwrap();
        assert_close(couple, b * m * xdd, 1e-9, 1.0, &format!("{method}: M_z^S"));
        assert_close(normal, m * 9.81, 1e-9, 1.0, &format!("{method}: F_y^S"));
    }
    std::fs::remove_dir_all(path.parent().expect("its folder")).ok();
}
