//! Pendulums and arms in a vertical plane: the simple and compound pendulums, the double
//! pendulum of rods, the five-link chain and the two-link robot arm.
//!
//! Positions are `p = l (sin th, -cos th)` for a rod hanging at angle `th` from the
//! downward vertical, so `p'' = l th'' (cos th, sin th) + l th'^2 (-sin th, cos th)`.

use super::solve_linear;
use crate::support::{assert_close, column, simulate, solve_all};

const G: f64 = 9.81;

/// The acceleration of the point `l (sin th, -cos th)`.
fn swing(l: f64, th: f64, thd: f64, thdd: f64) -> [f64; 2] {
    [
        l * (thdd * th.cos() - thd * thd * th.sin()),
        l * (thdd * th.sin() + thd * thd * th.cos()),
    ]
}

#[test]
fn simple_pendulum_acceleration_and_rod_tension() {
    let (m, l) = (0.5, 0.8);
    let (th, thd) = (0.6_f64, 0.5_f64);
    // Moments about the pivot: m L^2 th'' = -m g L sin th.
    let thdd = -G / l * th.sin();
    // Newton on the bob: F + m g (0, -1) = m a, so F = m a + m g (0, 1).
    let a = swing(l, th, thd, thdd);
    let force = [m * a[0], m * a[1] + m * G, 0.0];
    // Along the rod, toward the pivot: the tension m (g cos th + L th'^2).
    let tension = m * (G * th.cos() + l * thd * thd);
    for s in solve_all("simple-pendulum", &[]) {
        assert_close(
            s.acc("theta"),
            thdd,
            1e-9,
            G / l,
            &format!("{}: theta''", s.method),
        );
        let f = s.force("O");
        for i in 0..3 {
            assert_close(
                f[i],
                force[i],
                1e-9,
                m * G,
                &format!("{}: O force[{i}]", s.method),
            );
        }
        let along = -f[0] * th.sin() + f[1] * th.cos();
        assert_close(
            along,
            tension,
            1e-9,
            m * G,
            &format!("{}: tension", s.method),
        );
        assert_close(
            s.moment("O")[2],
            0.0,
            1e-9,
            m * G * l,
            &format!("{}: O moment", s.method),
        );
    }
}

/// The complete elliptic integral of the first kind, by the arithmetic-geometric mean:
/// K(k) = pi / (2 agm(1, sqrt(1 - k^2))).
fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0_f64, (1.0 - k * k).sqrt());
    while (a - b).abs() > 1e-15 {
        (a, b) = ((a + b) / 2.0, (a * b).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

#[test]
fn simple_pendulum_period_matches_the_large_amplitude_formula() {
    let (m, l) = (0.5, 0.8);
    let (th0, thd0) = (0.6_f64, 0.5_f64);
    // Energy: m L^2 th'^2 / 2 - m g L cos th = -m g L cos th_max.
    let cos_max = th0.cos() - l * thd0 * thd0 / (2.0 * G);
    let k = ((1.0 - cos_max) / 2.0).sqrt(); // sin(th_max / 2)
    let period = 4.0 * (l / G).sqrt() * elliptic_k(k);

    let (columns, rows) = simulate("simple-pendulum", &[]);
    let (t, q, qd) = (
        column(&columns, "t"),
        column(&columns, "theta"),
        column(&columns, "theta'"),
    );
    let energy = |r: &Vec<f64>| 0.5 * m * l * l * r[qd] * r[qd] - m * G * l * r[q].cos();
    let e0 = energy(&rows[0]);
    for r in &rows {
        assert_close(
            energy(r),
            e0,
            1e-7,
            m * G * l,
            &format!("energy at t = {}", r[t]),
        );
    }
    // Upward zero crossings, by linear interpolation: the path is straight there (th'' = 0).
    let crossings: Vec<f64> = rows
        .windows(2)
        .filter(|w| w[0][q] < 0.0 && w[1][q] >= 0.0)
        .map(|w| w[0][t] + (w[1][t] - w[0][t]) * -w[0][q] / (w[1][q] - w[0][q]))
        .collect();
    assert!(
        crossings.len() >= 2,
        "at least one whole swing in the simulation"
    );
    let measured = (crossings[crossings.len() - 1] - crossings[0]) / (crossings.len() - 1) as f64;
    assert_close(measured, period, 1e-5, period, "period");
}

/// `simulate` reports its confirmation on standard error, the small-oscillation period
/// among them: sqrt(g/L) = 3.50179 rad/s for L = 0.8 m, by hand.
#[test]
fn simulate_reports_its_checks() {
    let out = crate::support::run(&[
        "simulate",
        crate::support::problem("simple-pendulum")
            .to_str()
            .expect("a UTF-8 path"),
    ]);
    assert!(out.status.success());
    let report = String::from_utf8_lossy(&out.stderr);
    for line in [
        "energy conservation",
        "agreement between methods",
        "small-oscillation period",
        "ω = 3.50179 rad/s",
    ] {
        assert!(report.contains(line), "{line:?} missing from:\n{report}");
    }
    assert!(!report.contains("FAIL"), "{report}");
    assert!(report.matches("(pass)").count() == 3, "{report}");
}

#[test]
fn compound_pendulum_with_pin_friction() {
    let (m, l, c) = (2.0, 1.0, 0.05);
    let (th, thd) = (1.0_f64, -0.5_f64);
    // Moments about the pin O: (m L^2 / 3) th'' = -m g (L/2) sin th - c th'.
    let thdd = -(m * G * l / 2.0 * th.sin() + c * thd) / (m * l * l / 3.0);
    // Newton on the bar: F = m a_G + m g (0, 1), with G at L/2 down the bar. The pin's
    // friction couple acts at the joint and is not part of the reaction.
    let a = swing(l / 2.0, th, thd, thdd);
    let force = [m * a[0], m * a[1] + m * G];
    for s in solve_all("compound-pendulum", &[]) {
        assert_close(
            s.acc("theta"),
            thdd,
            1e-9,
            G / l,
            &format!("{}: theta''", s.method),
        );
        let f = s.force("O");
        for i in 0..2 {
            assert_close(
                f[i],
                force[i],
                1e-9,
                m * G,
                &format!("{}: O force[{i}]", s.method),
            );
        }
    }
}

#[test]
fn compound_pendulum_swings_like_a_simple_pendulum_of_two_thirds_its_length() {
    // Without friction and for small swings th'' = -(3 g / 2 L) th = -g / (2 L / 3) th.
    let (l, th) = (1.0, 1e-6);
    let want = -G / (2.0 * l / 3.0) * th;
    for s in solve_all(
        "compound-pendulum",
        &["--set", "c=0", "--state", "theta=1e-6,theta'=0"],
    ) {
        assert_close(
            s.acc("theta"),
            want,
            1e-9,
            0.0,
            &format!("{}: theta''", s.method),
        );
    }
}

/// The double pendulum in absolute angles t1 = q1, t2 = q1 + q2, by Lagrange:
/// T = (M11 t1'^2 + 2 M12 t1' t2' + M22 t2'^2) / 2 with M11 = m1 L1^2/3 + m2 L1^2,
/// M12 = m2 L1 L2/2 cos(t1 - t2), M22 = m2 L2^2/3, and
/// V = -(m1/2 + m2) g L1 cos t1 - m2 g L2/2 cos t2. The equations are
/// M11 t1'' + M12 t2'' + k sin(t1 - t2) t2'^2 + (m1/2 + m2) g L1 sin t1 = 0,
/// M12 t1'' + M22 t2'' - k sin(t1 - t2) t1'^2 + m2 g L2/2 sin t2 = 0, with k = m2 L1 L2/2.
struct DoublePendulum {
    m1: f64,
    l1: f64,
    m2: f64,
    l2: f64,
}

impl DoublePendulum {
    const LIBRARY: DoublePendulum = DoublePendulum {
        m1: 1.2,
        l1: 0.6,
        m2: 0.8,
        l2: 0.4,
    };

    /// (t1'', t2'') at absolute angles and rates.
    fn accelerations(&self, t1: f64, t2: f64, w1: f64, w2: f64) -> [f64; 2] {
        let DoublePendulum { m1, l1, m2, l2 } = *self;
        let k = m2 * l1 * l2 / 2.0;
        let m11 = m1 * l1 * l1 / 3.0 + m2 * l1 * l1;
        let m12 = k * (t1 - t2).cos();
        let m22 = m2 * l2 * l2 / 3.0;
        let f1 = -k * (t1 - t2).sin() * w2 * w2 - (m1 / 2.0 + m2) * G * l1 * t1.sin();
        let f2 = k * (t1 - t2).sin() * w1 * w1 - m2 * G * l2 / 2.0 * t2.sin();
        let x = solve_linear(vec![vec![m11, m12], vec![m12, m22]], vec![f1, f2]);
        [x[0], x[1]]
    }

    fn energy(&self, t1: f64, t2: f64, w1: f64, w2: f64) -> f64 {
        let DoublePendulum { m1, l1, m2, l2 } = *self;
        let m11 = m1 * l1 * l1 / 3.0 + m2 * l1 * l1;
        let m12 = m2 * l1 * l2 / 2.0 * (t1 - t2).cos();
        let m22 = m2 * l2 * l2 / 3.0;
        0.5 * (m11 * w1 * w1 + 2.0 * m12 * w1 * w2 + m22 * w2 * w2)
            - (m1 / 2.0 + m2) * G * l1 * t1.cos()
            - m2 * G * l2 / 2.0 * t2.cos()
    }
}

#[test]
fn double_pendulum_accelerations_and_ground_pin_reaction() {
    let p = DoublePendulum::LIBRARY;
    let (q1, q2, q1d, q2d) = (0.7_f64, -0.4_f64, 1.0, -0.5);
    let (t1, t2, w1, w2) = (q1, q1 + q2, q1d, q1d + q2d);
    let [a1, a2] = p.accelerations(t1, t2, w1, w2);
    // Newton on both rods together: F_O = m1 a_G1 + m2 a_G2 + (m1 + m2) g (0, 1).
    let g1 = swing(p.l1 / 2.0, t1, w1, a1);
    let e = swing(p.l1, t1, w1, a1);
    let g2 = swing(p.l2 / 2.0, t2, w2, a2);
    let force = [
        p.m1 * g1[0] + p.m2 * (e[0] + g2[0]),
        p.m1 * g1[1] + p.m2 * (e[1] + g2[1]) + (p.m1 + p.m2) * G,
    ];
    for s in solve_all("double-pendulum-rods", &[]) {
        assert_close(
            s.acc("q1"),
            a1,
            1e-9,
            G / p.l1,
            &format!("{}: q1''", s.method),
        );
        assert_close(
            s.acc("q2"),
            a2 - a1,
            1e-9,
            G / p.l1,
            &format!("{}: q2''", s.method),
        );
        let f = s.force("O");
        for i in 0..2 {
            assert_close(
                f[i],
                force[i],
                1e-9,
                (p.m1 + p.m2) * G,
                &format!("{}: O force[{i}]", s.method),
            );
        }
    }
}

#[test]
fn double_pendulum_conserves_energy() {
    let p = DoublePendulum::LIBRARY;
    let (columns, rows) = simulate("double-pendulum-rods", &[]);
    let [q1, q2, w1, w2] = ["q1", "q2", "q1'", "q2'"].map(|c| column(&columns, c));
    let energy = |r: &Vec<f64>| p.energy(r[q1], r[q1] + r[q2], r[w1], r[w1] + r[w2]);
    let e0 = energy(&rows[0]);
    let scale = (p.m1 + p.m2) * G * p.l1;
    for r in &rows {
        assert_close(
            energy(r),
            e0,
            1e-7,
            scale,
            &format!("energy at t = {}", r[0]),
        );
    }
}

/// The chain of n equal rods in absolute angles th_i (link 1 at the top): by Lagrange,
/// M_ij = m L^2 (n - max(i, j) + 1/2) cos(th_i - th_j) for i != j (the links below both
/// carry the full L of each, link max(i, j) carries L/2 of its own), M_ii = m L^2 (n - i + 1/3);
/// equation i has the velocity terms sum_j m L^2 (n - max(i, j) + 1/2) sin(th_i - th_j) th_j'^2
/// and gravity's m g L (n - i + 1/2) sin th_i. With relative angles th = T q (T lower-triangular
/// ones), M_q = T^t M T, and the pins' friction adds -c q_i' on each q_i.
struct Chain {
    m: f64,
    l: f64,
    c: f64,
}

impl Chain {
    const LIBRARY: Chain = Chain {
        m: 0.2,
        l: 0.3,
        c: 0.002,
    };
    const N: usize = 5;

    fn absolute(q: &[f64]) -> Vec<f64> {
        q.iter()
            .scan(0.0, |s, x| {
                *s += x;
                Some(*s)
            })
            .collect()
    }

    fn mass_matrix(&self, th: &[f64]) -> Vec<Vec<f64>> {
        let n = Self::N;
        let ml2 = self.m * self.l * self.l;
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        // 1-based link numbers: links below link k number n - k.
                        let below = (n - 1 - i.max(j)) as f64;
                        if i == j {
                            ml2 * (below + 1.0 / 3.0)
                        } else {
                            ml2 * (below + 0.5) * (th[i] - th[j]).cos()
                        }
                    })
                    .collect()
            })
            .collect()
    }

    fn accelerations(&self, q: &[f64], qd: &[f64]) -> Vec<f64> {
        let n = Self::N;
        let (th, w) = (Self::absolute(q), Self::absolute(qd));
        let ml2 = self.m * self.l * self.l;
        let mth = self.mass_matrix(&th);
        // Generalized forces in absolute angles (everything but q''-terms, moved right).
        let f_th: Vec<f64> = (0..n)
            .map(|i| {
                let velocity: f64 = (0..n)
                    .filter(|&j| j != i)
                    .map(|j| {
                        ml2 * ((n - 1 - i.max(j)) as f64 + 0.5)
                            * (th[i] - th[j]).sin()
                            * w[j]
                            * w[j]
                    })
                    .sum();
                -velocity - self.m * G * self.l * ((n - 1 - i) as f64 + 0.5) * th[i].sin()
            })
            .collect();
        // T^t: row i sums the entries from i down; the friction acts on each q_i.
        let mq: Vec<Vec<f64>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        (i..n)
                            .flat_map(|a| (j..n).map(move |b| (a, b)))
                            .map(|(a, b)| mth[a][b])
                            .sum()
                    })
                    .collect()
            })
            .collect();
        let fq: Vec<f64> = (0..n)
            .map(|i| (i..n).map(|a| f_th[a]).sum::<f64>() - self.c * qd[i])
            .collect();
        solve_linear(mq, fq)
    }

    fn energy(&self, q: &[f64], qd: &[f64]) -> f64 {
        let n = Self::N;
        let (th, w) = (Self::absolute(q), Self::absolute(qd));
        let mth = self.mass_matrix(&th);
        let kinetic: f64 = (0..n)
            .flat_map(|i| (0..n).map(move |j| (i, j)))
            .map(|(i, j)| 0.5 * mth[i][j] * w[i] * w[j])
            .sum();
        let potential: f64 = (0..n)
            .map(|i| -self.m * G * self.l * ((n - 1 - i) as f64 + 0.5) * th[i].cos())
            .sum();
        kinetic + potential
    }
}

#[test]
fn five_link_chain_accelerations() {
    let chain = Chain::LIBRARY;
    let q = [0.6, -0.3, 0.2, -0.1, 0.15];
    let qd = [0.5, 0.0, -0.4, 0.3, 0.0];
    let want = chain.accelerations(&q, &qd);
    for s in solve_all("five-link-chain", &[]) {
        for (i, w) in want.iter().enumerate() {
            let name = format!("q{}", i + 1);
            assert_close(
                s.acc(&name),
                *w,
                1e-9,
                G / chain.l,
                &format!("{}: {name}''", s.method),
            );
        }
    }
}

#[test]
fn five_link_chain_loses_the_energy_its_pins_dissipate() {
    // dE/dt = -c sum q_i'^2: integrate the right side by Simpson's rule over the rows.
    let chain = Chain::LIBRARY;
    let (columns, rows) = simulate("five-link-chain", &[]);
    let qs: Vec<usize> = (1..=5)
        .map(|i| column(&columns, &format!("q{i}")))
        .collect();
    let ws: Vec<usize> = (1..=5)
        .map(|i| column(&columns, &format!("q{i}'")))
        .collect();
    let state = |r: &Vec<f64>| {
        (
            qs.iter().map(|&i| r[i]).collect::<Vec<_>>(),
            ws.iter().map(|&i| r[i]).collect::<Vec<_>>(),
        )
    };
    let power = |r: &Vec<f64>| -chain.c * ws.iter().map(|&i| r[i] * r[i]).sum::<f64>();
    let n = if rows.len() % 2 == 1 {
        rows.len()
    } else {
        rows.len() - 1
    };
    let h = rows[1][0] - rows[0][0];
    let simpson: f64 = (0..n)
        .map(|i| {
            let weight = if i == 0 || i == n - 1 {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            weight * power(&rows[i])
        })
        .sum::<f64>()
        * h
        / 3.0;
    let (q0, w0) = state(&rows[0]);
    let (q1, w1) = state(&rows[n - 1]);
    let lost = chain.energy(&q1, &w1) - chain.energy(&q0, &w0);
    assert!(simpson < 0.0);
    assert_close(
        lost,
        simpson,
        1e-5,
        simpson.abs(),
        "energy lost = work of the pins' friction",
    );
}

/// The two-link arm, angles from the horizontal, absolute t1 = q1, t2 = q1 + q2. As for the
/// double pendulum with gravity's lever arms cos instead of sin:
/// M11 t1'' + M12 t2'' + k sin(t1 - t2) t2'^2 + (m1/2 + m2) g L1 cos t1 = tau1 - tau2,
/// M12 t1'' + M22 t2'' - k sin(t1 - t2) t1'^2 + m2 g L2/2 cos t2 = tau2
/// (the elbow motor turns B forward and A back).
fn robot_arm(tau1: f64, tau2: f64, q: [f64; 2], qd: [f64; 2]) -> [f64; 2] {
    let (m1, l1, m2, l2) = (3.0, 0.5, 2.0, 0.4);
    let (t1, t2, w1, w2) = (q[0], q[0] + q[1], qd[0], qd[0] + qd[1]);
    let k = m2 * l1 * l2 / 2.0;
    let m11 = m1 * l1 * l1 / 3.0 + m2 * l1 * l1;
    let m12 = k * (t1 - t2).cos();
    let m22 = m2 * l2 * l2 / 3.0;
    let f1 = tau1 - tau2 - k * (t1 - t2).sin() * w2 * w2 - (m1 / 2.0 + m2) * G * l1 * t1.cos();
    let f2 = tau2 + k * (t1 - t2).sin() * w1 * w1 - m2 * G * l2 / 2.0 * t2.cos();
    let x = solve_linear(vec![vec![m11, m12], vec![m12, m22]], vec![f1, f2]);
    [x[0], x[1] - x[0]]
}

#[test]
fn robot_arm_accelerations_and_elbow_force() {
    let (l1, m2, l2) = (0.5, 2.0, 0.4);
    let (q, qd) = ([0.4_f64, 0.8_f64], [0.5, -0.3]);
    // The controllers: T = tau + kp (r - q) - kd q'.
    let shoulder = 15.95 + 60.0 * (0.6 - q[0]) - 8.0 * qd[0];
    let elbow = 1.78 + 20.0 * (0.5 - q[1]) - 3.0 * qd[1];
    let [a1, a2] = robot_arm(shoulder, elbow, q, qd);
    // Newton on the forearm: F = m2 a_G2 + m2 g (0, 1), with
    // G2 = L1 (cos t1, sin t1) + L2/2 (cos t2, sin t2); then into A's axes (rotate by -t1).
    let (t1, t2, w1, w2, e1, e2) = (q[0], q[0] + q[1], qd[0], qd[0] + qd[1], a1, a1 + a2);
    let circle = |l: f64, t: f64, w: f64, e: f64| {
        [
            l * (-e * t.sin() - w * w * t.cos()),
            l * (e * t.cos() - w * w * t.sin()),
        ]
    };
    let (p, r) = (circle(l1, t1, w1, e1), circle(l2 / 2.0, t2, w2, e2));
    let f = [m2 * (p[0] + r[0]), m2 * (p[1] + r[1]) + m2 * G];
    let in_a = [
        f[0] * t1.cos() + f[1] * t1.sin(),
        -f[0] * t1.sin() + f[1] * t1.cos(),
    ];
    for s in solve_all("two-link-robot-arm", &[]) {
        assert_close(
            s.acc("q1"),
            a1,
            1e-9,
            G / l1,
            &format!("{}: q1''", s.method),
        );
        assert_close(
            s.acc("q2"),
            a2,
            1e-9,
            G / l1,
            &format!("{}: q2''", s.method),
        );
        let got = s.force("elbow");
        for i in 0..2 {
            assert_close(
                got[i],
                in_a[i],
                1e-9,
                m2 * G,
                &format!("{}: elbow force[{i}]", s.method),
            );
        }
    }
}

#[test]
fn robot_arm_holding_torques_keep_it_still() {
    // At rest on target the controllers give only their feedforward torques, and q'' = 0 needs
    // tau2 = m2 g L2/2 cos t2 and tau1 - tau2 = (m1/2 + m2) g L1 cos t1.
    let (m1, l1, m2, l2) = (3.0, 0.5, 2.0, 0.4);
    let (t1, t2) = (0.6_f64, 1.1_f64);
    let tau2 = m2 * G * l2 / 2.0 * t2.cos();
    let tau1 = tau2 + (m1 / 2.0 + m2) * G * l1 * t1.cos();
    let set = format!("tau1={tau1:.17e},tau2={tau2:.17e}");
    for s in solve_all(
        "two-link-robot-arm",
        &["--set", &set, "--state", "q1=0.6,q2=0.5,q1'=0,q2'=0"],
    ) {
        assert_close(
            s.acc("q1"),
            0.0,
            1e-9,
            G / l1,
            &format!("{}: q1''", s.method),
        );
        assert_close(
            s.acc("q2"),
            0.0,
            1e-9,
            G / l1,
            &format!("{}: q2''", s.method),
        );
    }
}
