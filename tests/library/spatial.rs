//! Spatial rotation: the spherical pendulum, the heavy symmetric top, the gyroscope in a
//! gimbal and the torque-free satellite.
//!
//! For body-fixed x-y-z angles (rates a, b, c) at q2 = q3 = 0 the angular velocity in body
//! axes is w = (a, b, c), and differentiating the rotating unit vectors
//! (e2 = R1 y turns with a x, e3 = R1 R2 z with a x + b e2) gives
//! w' = (q1'' + b c, q2'' - a c, q3'' + a b).

use super::v3::{self, add, cross, dot, e, matmul, mul, rot, scale, transpose};
use crate::support::{assert_close, column, simulate, solve_all};
use crate::support::{method_json, problem, Solution, METHODS};

const G: f64 = 9.81;

/// Euler's equations I w' + w x (I w) = M for a body with inertia `i` about its fixed point
/// (or mass center), solved for w' with a 3x3 solve.
fn euler(i: v3::M, w: v3::V, moment: v3::V) -> v3::V {
    let rhs = add(moment, scale(-1.0, cross(w, mul(i, w))));
    let x = super::solve_linear(i.iter().map(|r| r.to_vec()).collect(), rhs.to_vec());
    [x[0], x[1], x[2]]
}

/// For x-y-z angles at q2 = q3 = 0: the angle accelerations from w'.
fn xyz_angle_accelerations(rates: v3::V, w_dot: v3::V) -> v3::V {
    let [a, b, c] = rates;
    [w_dot[0] - b * c, w_dot[1] + a * c, w_dot[2] - a * b]
}

/// The angular velocity, in the parent's axes, of x-y-z angles q with rates r.
fn xyz_angular_velocity(q: v3::V, r: v3::V) -> v3::V {
    let r1 = rot(0, q[0]);
    let r12 = matmul(r1, rot(1, q[1]));
    add(
        add(scale(r[0], e(0)), scale(r[1], mul(r1, e(1)))),
        scale(r[2], mul(r12, e(2))),
    )
}

fn xyz_rotation(q: v3::V) -> v3::M {
    matmul(matmul(rot(0, q[0]), rot(1, q[1])), rot(2, q[2]))
}

const BALL: (f64, f64, f64) = (1.0, 0.05, 1.0); // m, R, L

#[test]
fn spherical_pendulum_eulers_equations_and_socket_force() {
    // q1 = pi/2 (the rod horizontal) is a state where the Motion Law's usual plan is
    // singular though the system is not: solve must plan for it.
    for q1 in [0.5_f64, std::f64::consts::FRAC_PI_2] {
        spherical_pendulum_at(q1);
    }
}

fn spherical_pendulum_at(q1: f64) {
    let (m, radius, l) = BALL;
    let i0 = 0.4 * m * radius * radius;
    let (across, along) = (i0 + m * l * l, i0);
    let rates = [0.2, 1.0, 0.3];
    // About the fixed socket O, in body axes (rotated by q1 about N.x), gravity's moment is
    // (-L e3) x (-m g (sin q1 e2 + cos q1 e3)) = -m g L sin q1 e1.
    let i_o = [[across, 0.0, 0.0], [0.0, across, 0.0], [0.0, 0.0, along]];
    let w_dot = euler(i_o, rates, [-m * G * l * q1.sin(), 0.0, 0.0]);
    let acc = xyz_angle_accelerations(rates, w_dot);
    // The same, written out: q1'' = -b c + ((I - Ia) b c - m g L sin q1) / I,
    // q2'' = a c + (Ia - I) a c / I, q3'' = -a b.
    let [a, b, c] = rates;
    assert_close(
        acc[0],
        -b * c + ((across - along) * b * c - m * G * l * q1.sin()) / across,
        1e-12,
        1.0,
        "q1''",
    );
    assert_close(
        acc[1],
        a * c + (along - across) * a * c / across,
        1e-12,
        1.0,
        "q2''",
    );
    assert_close(acc[2], -a * b, 1e-12, 1.0, "q3''");
    // The socket's force: F = m a_G + m g N.z, a_G = w' x r + w x (w x r), r = -L e3.
    let r = [0.0, 0.0, -l];
    let a_g = add(cross(w_dot, r), cross(rates, cross(rates, r)));
    let force = add(mul(rot(0, q1), scale(m, a_g)), [0.0, 0.0, m * G]);
    let state = format!("q1={q1},q2=0,q3=0");
    for s in solve_all("spherical-pendulum", &["--state", &state]) {
        for (k, q) in ["q1", "q2", "q3"].iter().enumerate() {
            assert_close(
                s.acc(q),
                acc[k],
                1e-9,
                G / l,
                &format!("{} at q1 = {q1}: {q}''", s.method),
            );
        }
        let f = s.force("O");
        for k in 0..3 {
            assert_close(
                f[k],
                force[k],
                1e-9,
                m * G,
                &format!("{}: O force[{k}]", s.method),
            );
            assert_close(
                s.moment("O")[k],
                0.0,
                1e-9,
                m * G * l,
                &format!("{}: O moment[{k}]", s.method),
            );
        }
    }
}

#[test]
fn spherical_pendulum_conserves_vertical_angular_momentum_and_energy() {
    let (m, radius, l) = BALL;
    let i0 = 0.4 * m * radius * radius;
    let i_o = [
        [i0 + m * l * l, 0.0, 0.0],
        [0.0, i0 + m * l * l, 0.0],
        [0.0, 0.0, i0],
    ];
    let (columns, rows) = simulate("spherical-pendulum", &[]);
    let qs = ["q1", "q2", "q3"].map(|c| column(&columns, c));
    let rs = ["q1'", "q2'", "q3'"].map(|c| column(&columns, c));
    // H_O = R I_O R^t w in N's axes; gravity has no moment about the vertical N.z through O.
    let invariants = |row: &Vec<f64>| {
        let q = qs.map(|i| row[i]);
        let w = xyz_angular_velocity(q, rs.map(|i| row[i]));
        let rr = xyz_rotation(q);
        let h = mul(matmul(matmul(rr, i_o), transpose(rr)), w);
        let height = mul(rr, [0.0, 0.0, -l])[2];
        (h[2], 0.5 * dot(w, h) + m * G * height)
    };
    let (h0, e0) = invariants(&rows[0]);
    for row in &rows {
        let (h, energy) = invariants(row);
        assert_close(h, h0, 1e-7, m * l * l, &format!("H_z at t = {}", row[0]));
        assert_close(
            energy,
            e0,
            1e-7,
            m * G * l,
            &format!("energy at t = {}", row[0]),
        );
    }
}

/// The top, about its fixed tip: I1 = It + m h^2 across the axis, I3 along it.
/// Lagrange in z-x-z Euler angles with w3 = phi' + psi' cos th:
///   I1 th'' = I1 psi'^2 sin th cos th - I3 w3 psi' sin th + m g h sin th,
/// and the conserved p_phi = I3 w3 and p_psi = I1 psi' sin^2 th + I3 w3 cos th.
struct Top {
    m: f64,
    h: f64,
    i3: f64,
    i1: f64,
}

const TOP: Top = Top {
    m: 0.5,
    h: 0.04,
    i3: 4.0e-4,
    i1: 2.5e-4 + 0.5 * 0.04 * 0.04,
};

#[test]
fn heavy_top_steady_precession_at_both_rates() {
    let Top { m, h, i3, i1 } = TOP;
    let (th, w3) = (0.5_f64, 150.0);
    // Steady precession (th'' = 0, th' = 0): I1 cos th W^2 - I3 w3 W + m g h = 0, so
    // W = (I3 w3 -+ sqrt(I3^2 w3^2 - 4 I1 m g h cos th)) / (2 I1 cos th); the slow root is
    // written as 2 m g h / (I3 w3 + sqrt(...)) to avoid cancellation.
    let root = ((i3 * w3).powi(2) - 4.0 * i1 * m * G * h * th.cos()).sqrt();
    let slow = 2.0 * m * G * h / (i3 * w3 + root);
    let fast = (i3 * w3 + root) / (2.0 * i1 * th.cos());
    // The classic approximation for a fast top: W ~ m g h / (I3 w3).
    assert_close(
        slow,
        m * G * h / (i3 * w3),
        0.1,
        1.0,
        "slow precession near m g h / (I3 w3)",
    );
    for precession in [slow, fast] {
        let spin = w3 - precession * th.cos();
        let state =
            format!("psi=0,theta={th},phi=0,psi'={precession:.17e},theta'=0,phi'={spin:.17e}");
        // The tip's force: the mass center runs round a circle of radius h sin th at W, so
        // F = m a_G + m g N.z = (0, m W^2 h sin th, m g) at psi = 0 (G is toward -N.y).
        let force = [0.0, m * precession * precession * h * th.sin(), m * G];
        let scale = i3 * w3 * precession / i1;
        for s in solve_all("heavy-symmetric-top", &["--state", &state]) {
            for q in ["psi", "theta", "phi"] {
                assert_close(
                    s.acc(q),
                    0.0,
                    1e-9,
                    scale,
                    &format!("{}: {q}'' at W = {precession}", s.method),
                );
            }
            let f = s.force("tip");
            for k in 0..3 {
                assert_close(
                    f[k],
                    force[k],
                    1e-9,
                    m * G,
                    &format!("{}: tip force[{k}] at W = {precession}", s.method),
                );
            }
        }
    }
}

#[test]
fn heavy_top_nutation_equations() {
    let Top { m, h, i3, i1 } = TOP;
    let (th, psid, thd, phid) = (0.5_f64, 3.0, 0.4, 150.0);
    let w3 = phid + psid * th.cos();
    let thdd = (i1 * psid * psid * th.sin() * th.cos() - i3 * w3 * psid * th.sin()
        + m * G * h * th.sin())
        / i1;
    // d/dt p_psi = 0 with w3 constant: I1 (psi'' sin^2 th + 2 psi' th' sin th cos th) = I3 w3 th' sin th.
    let psidd = (i3 * w3 * thd - 2.0 * i1 * psid * thd * th.cos()) / (i1 * th.sin());
    // w3' = 0: phi'' = -psi'' cos th + psi' th' sin th.
    let phidd = -psidd * th.cos() + psid * thd * th.sin();
    let scale = i3 * w3 * psid / i1;
    for s in solve_all("heavy-symmetric-top", &["--state", "theta'=0.4"]) {
        assert_close(
            s.acc("theta"),
            thdd,
            1e-9,
            scale,
            &format!("{}: theta''", s.method),
        );
        assert_close(
            s.acc("psi"),
            psidd,
            1e-9,
            scale,
            &format!("{}: psi''", s.method),
        );
        assert_close(
            s.acc("phi"),
            phidd,
            1e-9,
            scale,
            &format!("{}: phi''", s.method),
        );
    }
}

/// The gyroscope with the axle horizontal (th = 0, th' = 0), in the ring's axes: the ring
/// turns at W about its z (the vertical), the rotor spins at s about y. The angular momentum
/// about O is H = (Jx + It + m d^2) th' x + Is s y + (Jd + It + m d^2) W z, constant in the ring's
/// axes except through the rates, so dH/dt = H' + W z x H. Gravity's moment is -m g d x (the
/// rotor's center is at d y); the motor and the bearing drag are internal. So
///   Ix th'' - W Is s = -m g d,   Iz psi'' = 0,   Is phi'' = tau - c s (the rotor alone),
/// with Ix = Jx + It + m d^2; steady precession W = m g d / (Is s).
struct Gyro {
    m: f64,
    is: f64,
    it: f64,
    d: f64,
    mr: f64,
    jx: f64,
    c: f64,
}

const GYRO: Gyro = Gyro {
    m: 0.4,
    is: 2.0e-4,
    it: 1.1e-4,
    d: 0.02,
    mr: 0.1,
    jx: 1.6e-4,
    c: 1.0e-5,
};

#[test]
fn gyroscope_steady_precession_rate() {
    let Gyro { m, is, d, mr, .. } = GYRO;
    let spin = 300.0;
    let precession = m * G * d / (is * spin);
    let state = format!("psi=0,theta=0,phi=0,psi'={precession:.17e},theta'=0,phi'={spin}");
    let scale = precession * is * spin / (GYRO.jx + GYRO.it + m * d * d);
    for s in solve_all("gyroscope-gimbal", &["--state", &state]) {
        for q in ["psi", "theta", "phi"] {
            assert_close(s.acc(q), 0.0, 1e-9, scale, &format!("{}: {q}''", s.method));
        }
        // The gimbal carries the weight and turns the rotor's center round its circle.
        let force = [0.0, -m * d * precession * precession, (m + mr) * G];
        let f = s.force("gimbal");
        for k in 0..3 {
            assert_close(
                f[k],
                force[k],
                1e-9,
                (m + mr) * G,
                &format!("{}: gimbal force[{k}]", s.method),
            );
            assert_close(
                s.moment("gimbal")[k],
                0.0,
                1e-9,
                m * G * d,
                &format!("{}: gimbal moment[{k}]", s.method),
            );
        }
    }
}

#[test]
fn gyroscope_tilts_when_precessing_too_fast_and_slows_without_its_motor() {
    let Gyro {
        m,
        is,
        it,
        d,
        mr,
        jx,
        c,
    } = GYRO;
    let (precession, spin) = (2.0, 300.0);
    let ix = jx + it + m * d * d;
    let thdd = (precession * is * spin - m * G * d) / ix;
    let phidd = -c * spin / is;
    // The rotor's center d y has a_G = th'' d z - W^2 d y (psi'' = 0, th' = 0).
    let a_g = [0.0, -precession * precession * d, thdd * d];
    // The gimbal: F = m a_G + (m + mr) g z; its moment about the one direction it holds,
    // the ring's y, is the rate of change of the spin momentum, Is phi'' = tau - c s.
    let gimbal_force = add(scale(m, a_g), [0.0, 0.0, (m + mr) * G]);
    let gimbal_moment = [0.0, is * phidd, 0.0];
    // The axle: F = m a_G + m g z; about x it turns the ring, so its moment on the rotor
    // is -Jx th'' (the ring alone: Jx th'' = -M_x).
    let axle_force = add(scale(m, a_g), [0.0, 0.0, m * G]);
    let axle_moment = [-jx * thdd, 0.0, 0.0];
    let state = format!("psi=0,theta=0,phi=0,psi'={precession},theta'=0,phi'={spin}");
    for s in solve_with_axle(&["--set", "tau=0", "--state", &state]) {
        let what = |w: &str| format!("{}: {w}", s.method);
        assert_close(s.acc("theta"), thdd, 1e-9, thdd.abs(), &what("theta''"));
        assert_close(s.acc("psi"), 0.0, 1e-9, thdd.abs(), &what("psi''"));
        assert_close(s.acc("phi"), phidd, 1e-9, thdd.abs(), &what("phi''"));
        for k in 0..3 {
            let fscale = (m + mr) * G;
            assert_close(
                s.force("gimbal")[k],
                gimbal_force[k],
                1e-9,
                fscale,
                &what(&format!("gimbal force[{k}]")),
            );
            assert_close(
                s.force("axle")[k],
                axle_force[k],
                1e-9,
                fscale,
                &what(&format!("axle force[{k}]")),
            );
            let mscale = m * G * d;
            assert_close(
                s.moment("gimbal")[k],
                gimbal_moment[k],
                1e-9,
                mscale,
                &what(&format!("gimbal moment[{k}]")),
            );
            assert_close(
                s.moment("axle")[k],
                axle_moment[k],
                1e-9,
                mscale,
                &what(&format!("axle moment[{k}]")),
            );
        }
    }
}

/// The gyroscope solved by every method with the axle's reaction requested too: the bundled
/// problem asks for the gimbal's alone, as its statement does.
fn solve_with_axle(extra: &[&str]) -> Vec<Solution> {
    let text = std::fs::read_to_string(problem("gyroscope-gimbal")).expect("bundled");
    let mut json: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    json["find"]["reactions"] = serde_json::json!(["gimbal", "axle"]);
    let path = std::env::temp_dir().join(format!("gyroscope-axle-{}.json", std::process::id()));
    std::fs::write(&path, json.to_string()).expect("a scratch file");
    let solutions = (METHODS.iter())
        .map(|&method| Solution {
            method: method.to_string(),
            json: method_json("solve", &path, method, extra),
        })
        .collect();
    let _ = std::fs::remove_file(&path);
    solutions
}

const SATELLITE: [[f64; 3]; 3] = [[4.0, -0.5, 0.2], [-0.5, 6.0, 0.3], [0.2, 0.3, 8.0]];

#[test]
fn torque_free_body_eulers_equations_with_products_of_inertia() {
    // At zero angles the body axes are N's: w = (a1', a2', a3'), and with no moment
    // I w' = -w x (I w); the mass center moves at constant velocity.
    let rates = [0.2, -0.1, 2.0];
    let w_dot = euler(SATELLITE, rates, [0.0; 3]);
    let acc = xyz_angle_accelerations(rates, w_dot);
    let state = "a1=0,a2=0,a3=0,a1'=0.2,a2'=-0.1,a3'=2.0";
    for s in solve_all("torque-free-body", &["--state", state]) {
        for (k, q) in ["a1", "a2", "a3"].iter().enumerate() {
            assert_close(s.acc(q), acc[k], 1e-9, 1.0, &format!("{}: {q}''", s.method));
        }
        for q in ["x", "y", "z"] {
            assert_close(s.acc(q), 0.0, 1e-9, 1.0, &format!("{}: {q}''", s.method));
        }
    }
}

#[test]
fn torque_free_body_keeps_its_angular_momentum_and_energy() {
    let (columns, rows) = simulate("torque-free-body", &[]);
    let qs = ["a1", "a2", "a3"].map(|c| column(&columns, c));
    let rs = ["a1'", "a2'", "a3'"].map(|c| column(&columns, c));
    let [x, xd] = ["x", "x'"].map(|c| column(&columns, c));
    // H = R I R^t w in N's axes, and the kinetic energy w . H / 2.
    let invariants = |row: &Vec<f64>| {
        let q = qs.map(|i| row[i]);
        let w = xyz_angular_velocity(q, rs.map(|i| row[i]));
        let rr = xyz_rotation(q);
        let h = mul(matmul(matmul(rr, SATELLITE), transpose(rr)), w);
        (h, 0.5 * dot(w, h))
    };
    let (h0, e0) = invariants(&rows[0]);
    let size = dot(h0, h0).sqrt();
    for row in &rows {
        let (h, energy) = invariants(row);
        for k in 0..3 {
            assert_close(
                h[k],
                h0[k],
                1e-6,
                size,
                &format!("H[{k}] at t = {}", row[0]),
            );
        }
        assert_close(energy, e0, 1e-6, e0, &format!("energy at t = {}", row[0]));
        // Newton's first law for the mass center: x = x0 + v t.
        assert_close(
            row[x],
            rows[0][x] + rows[0][xd] * row[0],
            1e-6,
            1.0,
            &format!("x at t = {}", row[0]),
        );
    }
}
