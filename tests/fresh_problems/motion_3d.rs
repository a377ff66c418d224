//! Spatial problems in motion: a cylindrical joint on a skew shaft, a universal joint and a
//! ball joint, by every method against closed forms (Euler's equations, Lagrange's) and
//! the energy of the simulated motion.

use super::{at, close, command, solve_each, triple};
use crate::support::{column, table};

type M3 = [[f64; 3]; 3];

fn mat_vec(a: &M3, v: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| (0..3).map(|k| a[i][k] * v[k]).sum())
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Rodrigues: the rotation by `phi` about the unit vector `u`.
fn rotation(u: [f64; 3], phi: f64) -> M3 {
    let (c, s) = (phi.cos(), phi.sin());
    let skew = [[0.0, -u[2], u[1]], [u[2], 0.0, -u[0]], [-u[1], u[0], 0.0]];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let id = if i == j { 1.0 } else { 0.0 };
            id * c + s * skew[i][j] + (1.0 - c) * u[i] * u[j]
        })
    })
}

/// The body on the skew shaft u = (n̂_x + n̂_z)/√2: its centre on the axis, so
/// m s̈ = −k s − m g (n̂_z·u) and (A + C)/2 φ̈ = τ (u·I·u with I = diag(A, B, C)); the
/// shaft pushes the weight's part across the axis, m g (n̂_z − (n̂_z·u) u), and its couple
/// is dH/dt less the actuator's τ u: I_N α + ω × I_N ω − τ u, I_N = R I Rᵀ.
#[test]
fn a_body_slides_and_turns_on_a_skew_shaft() {
    let (m, g, k, a, b, c, tau) = (3.0, 9.81, 40.0, 0.2, 0.3, 0.5, 1.5);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let u = [h, 0.0, h];
    for (s0, phi, phi_rate) in [(0.1, 0.7, 2.0), (-0.2, 2.1, -5.0)] {
        let state = format!("s={s0},phi={phi},phi'={phi_rate},s'=0.4");
        for sol in solve_each("spinning-slider-on-skew-shaft", &["--state", &state]) {
            let what = format!("{} at {state}", sol["method"]);
            close(
                at(&sol, &["accelerations", "s"]),
                (-k * s0 - m * g * h) / m,
                &what,
            );
            let phi_acc = tau / ((a + c) / 2.0);
            close(at(&sol, &["accelerations", "phi"]), phi_acc, &what);
            let force = triple(&sol["reactions"]["S"]["force"]);
            let want = [-m * g / 2.0, 0.0, m * g / 2.0];
            (0..3).for_each(|i| close(force[i], want[i], &format!("{what}: force {i}")));
            let r = rotation(u, phi);
            let body = [[a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, c]];
            let inertia: M3 = std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    (0..3)
                        .map(|p| (0..3).map(|q| r[i][p] * body[p][q] * r[j][q]).sum::<f64>())
                        .sum()
                })
            });
            let omega = u.map(|x| x * phi_rate);
            let alpha = u.map(|x| x * phi_acc);
            let spin = cross(omega, mat_vec(&inertia, omega));
            let turn = mat_vec(&inertia, alpha);
            let moment = triple(&sol["reactions"]["S"]["moment"]);
            for i in 0..3 {
                close(
                    moment[i],
                    turn[i] + spin[i] - tau * u[i],
                    &format!("{what}: moment {i}"),
                );
            }
        }
    }
}

/// The universal joint's angles a (about n̂_x) and b (about the next ŷ); the centre at
/// −L along the body's ẑ. Lagrange's equations (T = ½ m L² (ḃ² + cos²b ȧ²) + ½ (A ȧ² cos²b +
/// A ḃ² + C ȧ² sin²b), V = −m g L cos a cos b), solved for ä and b̈.
fn universal(q: [f64; 4]) -> [f64; 2] {
    let (m, g, l, a_, c_) = (1.2, 9.81, 0.7, 0.02, 0.005);
    let [a, b, ad, bd] = q;
    let (sb, cb) = (b.sin(), b.cos());
    let j = a_ + l * l * m;
    let add =
        (2.0 * (j - c_) * ad * bd * sb - l * g * m * a.sin()) * cb / ((j - c_) * cb * cb + c_);
    let bdd = ((c_ - j) * ad * ad * cb - l * g * m * a.cos()) * sb / j;
    [add, bdd]
}

/// The centre's position, R_x(a) R_y(b) (0, 0, −L).
fn universal_centre(a: f64, b: f64) -> [f64; 3] {
    let l = 0.7;
    [-l * b.sin(), l * b.cos() * a.sin(), -l * b.cos() * a.cos()]
}

#[test]
fn a_pendulum_on_a_universal_joint_by_lagranges_equations() {
    let (m, g) = (1.2, 9.81);
    for q in [[0.5, -0.3, 0.8, 1.1], [-1.0, 0.9, -2.0, 0.4]] {
        let state = format!("a={},b={},a'={},b'={}", q[0], q[1], q[2], q[3]);
        let want = universal(q);
        for s in solve_each("universal-pendulum", &["--state", &state]) {
            let what = format!("{} at {state}", s["method"]);
            close(at(&s, &["accelerations", "a"]), want[0], &what);
            close(at(&s, &["accelerations", "b"]), want[1], &what);
            // The joint's force: m a* + m g n̂_z, a* from the centre's position by central
            // differences (its second derivatives along the motion).
            let e = 1e-4;
            let r = |da: f64, db: f64| universal_centre(q[0] + da, q[1] + db);
            let acc: [f64; 3] = std::array::from_fn(|i| {
                let raa = (r(e, 0.0)[i] - 2.0 * r(0.0, 0.0)[i] + r(-e, 0.0)[i]) / (e * e);
                let rbb = (r(0.0, e)[i] - 2.0 * r(0.0, 0.0)[i] + r(0.0, -e)[i]) / (e * e);
                let rab = (r(e, e)[i] - r(e, -e)[i] - r(-e, e)[i] + r(-e, -e)[i]) / (4.0 * e * e);
                let ra = (r(e, 0.0)[i] - r(-e, 0.0)[i]) / (2.0 * e);
                let rb = (r(0.0, e)[i] - r(0.0, -e)[i]) / (2.0 * e);
                ra * want[0]
                    + rb * want[1]
                    + raa * q[2] * q[2]
                    + 2.0 * rab * q[2] * q[3]
                    + rbb * q[3] * q[3]
            });
            let force = triple(&s["reactions"]["U"]["force"]);
            let pull = [m * acc[0], m * acc[1], m * acc[2] + m * g];
            for i in 0..3 {
                crate::support::assert_close(force[i], pull[i], 1e-5, 10.0, &what);
            }
        }
    }
}

/// A body with a product of inertia on a ball joint: the four methods give the same q̈ at
/// two states, and the simulated motion keeps its energy.
#[test]
fn an_unsymmetrical_body_on_a_ball_joint_keeps_its_energy() {
    for state in [
        "q1=0.3,q2=-0.4,q3=0.2",
        "q1=-1,q2=0.8,q3=2,q1'=-2,q2'=0.3,q3'=-4",
    ] {
        let all = solve_each("asymmetric-body-on-ball-joint", &["--state", state]);
        for q in ["q1", "q2", "q3"] {
            let first = at(&all[0], &["accelerations", q]);
            for s in &all[1..] {
                close(
                    at(s, &["accelerations", q]),
                    first,
                    &format!("{} {q}", s["method"]),
                );
            }
        }
    }
    let json = command("simulate", "asymmetric-body-on-ball-joint", "kane", &[]);
    let (columns, rows) = table(&json);
    let total = column(&columns, "total");
    let start = rows[0][total];
    let kinetic = rows[0][column(&columns, "kinetic")];
    for row in &rows {
        crate::support::assert_close(row[total], start, 1e-6, kinetic, "energy kept");
    }
}

/// The skew shaft's vectors in the body's frame: ω = φ̇ u and v* = ṡ u have the same
/// components in D as in N (u is fixed in D), α = φ̈ u in N, and the shaft's force turns
/// into D by Rᵀ.
#[test]
fn the_skew_shafts_vectors_in_the_bodys_frame() {
    let (m, g, a, c, tau) = (3.0, 9.81, 0.2, 0.5, 1.5);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let u = [h, 0.0, h];
    let (phi, phi_rate, s_rate) = (0.7, 2.0, 0.2);
    for method in crate::support::METHODS {
        let found = command("answer", "spinning-slider-on-skew-shaft", method, &[]);
        let list = found["answers"].as_array().expect("answers");
        let parts = |k: usize| -> [f64; 3] {
            ["x", "y", "z"].map(|axis| at(&list[k], &["components", axis]))
        };
        let frames = list.iter().map(|a| a["frame"].clone()).collect::<Vec<_>>();
        assert_eq!(frames, ["D", "N", "D", "D"], "{method}");
        let phi_acc = tau / ((a + c) / 2.0);
        let (omega, alpha, speed) = (parts(0), parts(1), parts(2));
        for (i, along) in u.iter().enumerate() {
            close(omega[i], phi_rate * along, &format!("{method}: ω in D"));
            close(alpha[i], phi_acc * along, &format!("{method}: α in N"));
            close(speed[i], s_rate * along, &format!("{method}: v* in D"));
        }
        let r = rotation(u, phi);
        let force = [-m * g / 2.0, 0.0, m * g / 2.0];
        let in_d: [f64; 3] = std::array::from_fn(|i| (0..3).map(|k| r[k][i] * force[k]).sum());
        for (got, want) in parts(3).iter().zip(in_d) {
            close(*got, want, &format!("{method}: the shaft's force in D"));
        }
    }
}
