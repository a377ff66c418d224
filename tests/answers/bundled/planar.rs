//! Answers of the planar bundled problems against closed forms written here.

use super::*;

#[test]
fn every_bundled_statement_that_asks_declares_its_questions() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("problems");
    let mut asked = 0;
    for entry in std::fs::read_dir(&dir).expect("problems/") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|e| e != "json") {
            continue;
        }
        let json: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&path).expect("readable")).expect("JSON");
        let statement = json["statement"].as_str().unwrap_or("");
        if ["Find", "find", "How", "What", "?"]
            .iter()
            .any(|w| statement.contains(w))
        {
            let questions = json["find"]["questions"].as_array().map_or(0, Vec::len);
            assert!(
                questions > 0,
                "{}: the statement asks, but find.questions is empty",
                path.display()
            );
            asked += 1;
        }
    }
    assert!(asked >= 28, "only {asked} statements ask anything");
}

#[test]
fn the_collar_on_the_driven_rod() {
    let a = bundled_answers("collar-on-driven-rod");
    let (m, w, r, rd) = (0.3, 3.0, 0.2, 0.1);
    // No force along the frictionless rod: r'' - r w^2 = 0.
    close(v(&a, 0), r * w * w, 1e-9, "r''");
    // Across the rod the collar needs m (r theta'' + 2 r' w) = 2 m r' w; no couple (theta'' = 0).
    close(part(&a[1], "slide.force.x"), 0.0, 1e-9, "along the rod");
    close(
        part(&a[1], "slide.force.y"),
        2.0 * m * rd * w,
        1e-9,
        "normal force",
    );
    close(part(&a[1], "slide.moment.z"), 0.0, 1e-9, "couple");
    // The motor supplies dH_O/dt, H_O = (M L^2/3 + Ic + m r^2) w: 2 m r r' w.
    close(v(&a, 2), 2.0 * m * r * rd * w, 1e-9, "motor torque");
}

#[test]
fn the_cylinder_rolling_down_the_incline() {
    let a = bundled_answers("cylinder-on-incline");
    let (m, r, g, alpha) = (2.0, 0.1, 9.81, PI / 6.0);
    // m x'' = m g sin(alpha) + F, (m R^2/2) theta'' = R F... with x' = -R theta': x'' = 2/3 g sin(alpha).
    let xdd = 2.0 / 3.0 * g * alpha.sin();
    close(v(&a, 0), xdd, 1e-9, "x''");
    close(v(&a, 1), -xdd / r, 1e-9, "theta''");
    close(
        part(&a[2], "contact.force.x"),
        -m * g * alpha.sin() / 3.0,
        1e-9,
        "friction",
    );
    close(
        part(&a[2], "contact.force.y"),
        m * g * alpha.cos(),
        1e-9,
        "normal force",
    );
}

/// The chain of five links in absolute angles: M theta'' + C + G = Q (Lagrange's equations,
/// with M as the statement gives it).
#[test]
fn the_five_link_chain_by_lagranges_equations_in_absolute_angles() {
    let a = bundled_answers("five-link-chain");
    let (m, l, c, g) = (0.2, 0.3, 0.002, 9.81);
    let n = 5;
    let q = [0.6, -0.3, 0.2, -0.1, 0.15];
    let qd = [0.5, 0.0, -0.4, 0.3, 0.0];
    let cum = |x: &[f64]| {
        x.iter()
            .scan(0.0, |s, v| {
                *s += v;
                Some(*s)
            })
            .collect::<Vec<f64>>()
    };
    let (th, thd) = (cum(&q), cum(&qd));
    // Coefficient of link i and j (1-based): n - max(i, j) + 1/2, or n - i + 1/3 on the diagonal.
    let coef = |i: usize, j: usize| {
        if i == j {
            (n - i) as f64 + 1.0 / 3.0
        } else {
            (n - i.max(j)) as f64 + 0.5
        }
    };
    let mut mm = nalgebra::DMatrix::zeros(n, n);
    let mut rhs = nalgebra::DVector::zeros(n);
    for i in 0..n {
        for j in 0..n {
            let cij = coef(i + 1, j + 1);
            mm[(i, j)] = m * l * l * cij * (th[i] - th[j]).cos();
            // The velocity terms: sum_j m L^2 c_ij sin(theta_i - theta_j) theta_j'^2.
            if i != j {
                rhs[i] -= m * l * l * cij * (th[i] - th[j]).sin() * thd[j] * thd[j];
            }
        }
        // Gravity: dV/dtheta_i = m g L (n - i + 1/2) sin(theta_i).
        rhs[i] -= m * g * l * ((n - i - 1) as f64 + 0.5) * th[i].sin();
        // The pins' friction -c q_k' on the relative angles: Q_i = -c q_i' + c q_(i+1)'.
        rhs[i] += -c * qd[i] + if i + 1 < n { c * qd[i + 1] } else { 0.0 };
    }
    let thdd = mm.clone().lu().solve(&rhs).expect("regular");
    for i in 0..n {
        let want = thdd[i] - if i > 0 { thdd[i - 1] } else { 0.0 };
        close(v(&a, i), want, 1e-8, &format!("q{}''", i + 1));
    }
    // The energy changes at theta'^T (M theta'' + C + G) = theta'^T Q = -c sum q_i'^2.
    let rate: f64 = (0..n)
        .map(|i| {
            let mut row = m * g * l * ((n - i - 1) as f64 + 0.5) * th[i].sin();
            for j in 0..n {
                row += mm[(i, j)] * thdd[j];
                if i != j {
                    row += m * l * l * coef(i + 1, j + 1) * (th[i] - th[j]).sin() * thd[j] * thd[j];
                }
            }
            thd[i] * row
        })
        .sum();
    close(v(&a, 5), -rate, 1e-8, "dissipation");
    close(
        v(&a, 5),
        c * qd.iter().map(|x| x * x).sum::<f64>(),
        1e-12,
        "c sum q'^2",
    );
}

/// The four-bar from rest: the loop's kinematic coefficients, Lagrange's equation in q1, then
/// Newton–Euler body by body for the pin forces.
#[test]
fn the_four_bar_released_from_rest() {
    let a = bundled_answers("four-bar");
    let (la, lb, lc, d, m, g) = (0.1, 0.3, 0.25, 0.3, 1.0, 9.81);
    let q1 = 1.2f64;
    let p = la * along(q1);
    let qpin = Vector2::new(d, 0.0);
    // R on the rocker's circle at the coupler's length from P (Newton from the problem's guess).
    let mut q3 = 1.6f64;
    for _ in 0..50 {
        let rr = qpin + lc * along(q3) - p;
        let f = rr.norm_squared() - lb * lb;
        let df = 2.0 * rr.dot(&(lc * perp(q3)));
        q3 -= f / df;
    }
    let r = qpin + lc * along(q3);
    let phib = (r - p).y.atan2((r - p).x);
    // a eA' + b phiB' eB' = c q3' eC' (the loop's velocity, per unit q1').
    let k = Matrix2::from_columns(&[lb * perp(phib), -lc * perp(q3)]);
    let s = k.lu().solve(&(-la * perp(q1))).expect("regular");
    let (dphib, dq3) = (s.x, s.y);
    let dga = la / 2.0 * perp(q1);
    let dgb = la * perp(q1) + lb / 2.0 * dphib * perp(phib);
    let dgc = lc / 2.0 * dq3 * perp(q3);
    let (ia, ib, ic) = (m * la * la / 12.0, m * lb * lb / 12.0, m * lc * lc / 12.0);
    let j = m * (dga.norm_squared() + dgb.norm_squared() + dgc.norm_squared())
        + ia
        + ib * dphib * dphib
        + ic * dq3 * dq3;
    let qg = -m * g * (dga.y + dgb.y + dgc.y);
    // From rest the velocity terms vanish: J q1'' = Q.
    let q1dd = qg / j;
    let (phibdd, q3dd) = (dphib * q1dd, dq3 * q1dd);
    close(v(&a, 0), q1dd, 1e-7, "q1''");
    close(v(&a, 1), phibdd - q1dd, 1e-7, "q2''");
    close(v(&a, 2), q3dd, 1e-7, "q3''");
    // Accelerations of the mass centers of A and B (no centripetal terms from rest); the
    // rocker turns about the fixed Q.
    let aa = dga * q1dd;
    let ab = la * perp(q1) * q1dd + lb / 2.0 * perp(phib) * phibdd;
    let (ga, gb, gc) = (
        la / 2.0 * along(q1),
        p + lb / 2.0 * along(phib),
        qpin + lc / 2.0 * along(q3),
    );
    let weight = Vector2::new(0.0, -m * g);
    // Rocker about Q: (R - Q) x F_R + (G_C - Q) x W = (m c^2/3) q3''.
    // Coupler about P: (R - P) x (-F_R) + (G_B - P) x W = I_B phiB'' + (G_B - P) x m a_B.
    let (u, w) = (r - qpin, r - p);
    let k = Matrix2::new(-u.y, u.x, w.y, -w.x);
    let rhs = Vector2::new(
        m * lc * lc / 3.0 * q3dd - cross2(gc - qpin, weight),
        ib * phibdd + cross2(gb - p, m * ab) - cross2(gb - p, weight),
    );
    let f_r = k.lu().solve(&rhs).expect("regular");
    let f_p = m * ab + f_r - weight;
    let f_o = m * aa + f_p - weight;
    // The crank about O closes the check: -P x F_P + G_A x W = (m a^2/3) q1''.
    close(
        -cross2(p, f_p) + cross2(ga, weight),
        m * la * la / 3.0 * q1dd,
        1e-9,
        "crank moments",
    );
    close(part(&a[3], "O.force.x"), f_o.x, 1e-7, "O x");
    close(part(&a[3], "O.force.y"), f_o.y, 1e-7, "O y");
    // R is reported in the coupler's unit vectors.
    close(
        part(&a[4], "R.force.x"),
        f_r.dot(&along(phib)),
        1e-7,
        "R along B",
    );
    close(
        part(&a[4], "R.force.y"),
        f_r.dot(&perp(phib)),
        1e-7,
        "R across B",
    );
}

#[test]
fn the_knife_edge_runs_on_a_circle() {
    let a = bundled_answers("knife-edge");
    // No force along the blade and no moment: the speed v and the turning rate w stay
    // constant, so the blade's point runs on a circle of radius v/w.
    let (th0, w) = (0.3f64, 1.0);
    let vel = 1.2 / th0.cos();
    close(v(&a, 0), -vel * th0.sin() * w, 1e-9, "x''");
    close(v(&a, 1), vel * th0.cos() * w, 1e-9, "y''");
    close(v(&a, 2), 0.0, 1e-9, "theta''");
    let th = th0 + w * 1.0;
    close(
        v(&a, 3),
        vel / w * (th.sin() - th0.sin()),
        SIMULATED,
        "x(1)",
    );
    close(
        v(&a, 4),
        -vel / w * (th.cos() - th0.cos()),
        SIMULATED,
        "y(1)",
    );
    close(v(&a, 5), th, SIMULATED, "theta(1)");
}

#[test]
fn the_cartesian_pendulum_against_lagranges_equation_in_the_angle() {
    let a = bundled_answers("pendulum-cartesian");
    let (m, mx, l, g) = (1.0, 0.05, 0.5, 9.81);
    // x = L sin(phi), y = -L cos(phi); the carriage moves with x only:
    // T = m L^2 phi'^2/2 + mX (L cos(phi) phi')^2/2, V = -m g L cos(phi), so
    // (m + mX cos^2) L phi'' = mX L cos sin phi'^2 - m g sin.
    let (s, c) = (0.6, 0.8);
    let pd = 0.6 / (l * c);
    let pdd = (mx * l * c * s * pd * pd - m * g * s) / ((m + mx * c * c) * l);
    close(v(&a, 0), l * (c * pdd - s * pd * pd), 1e-9, "x''");
    close(v(&a, 1), l * (s * pdd + c * pd * pd), 1e-9, "y''");
    close(v(&a, 2), l * pdd, 1e-9, "along the path");
}

/// Springs pull with k (l - l0) toward their anchors; Newton's and Euler's laws for the plate.
fn plate_accelerations(
    (m, i, g): (f64, f64, f64),
    (pos, th, vel, w): (Vector2<f64>, f64, Vector2<f64>, f64),
    springs: &[(Vector2<f64>, Vector2<f64>, f64, f64)],
    dashpot: Option<(Vector2<f64>, Vector2<f64>, f64)>,
    couple: f64,
) -> (Vector3<f64>, Vec<f64>) {
    let rot = nalgebra::Rotation2::new(th);
    let mut force = Vector2::new(0.0, -m * g);
    let mut moment = couple;
    let mut tensions = Vec::new();
    for &(anchor, corner, k, l0) in springs {
        let r = rot * corner;
        let d = anchor - (pos + r);
        let t = k * (d.norm() - l0);
        tensions.push(t);
        force += t * d / d.norm();
        moment += cross2(r, t * d / d.norm());
    }
    if let Some((anchor, corner, c)) = dashpot {
        let r = rot * corner;
        let d = pos + r - anchor;
        let vd = vel + w * Vector2::new(-r.y, r.x);
        let rate = d.dot(&vd) / d.norm();
        tensions.push(c * rate);
        let f = -c * rate * d / d.norm();
        force += f;
        moment += cross2(r, f);
    }
    (Vector3::new(force.x / m, force.y / m, moment / i), tensions)
}

#[test]
fn the_plate_on_two_springs_by_newton_and_euler() {
    let a = bundled_answers("plate-on-two-springs");
    let (ha, b, d, e) = (0.25, 0.1, 0.5, 0.8);
    let (acc, _) = plate_accelerations(
        (2.0, 0.05, 9.81),
        (Vector2::new(0.05, 0.0), 0.2, Vector2::new(0.2, -0.1), 0.3),
        &[
            (Vector2::new(-d, e), Vector2::new(-ha, b), 150.0, 0.4),
            (Vector2::new(d, e), Vector2::new(ha, b), 120.0, 0.45),
        ],
        None,
        0.0,
    );
    for (i, name) in ["x''", "y''", "theta''"].into_iter().enumerate() {
        close(v(&a, i), acc[i], 1e-9, name);
    }
}

#[test]
fn the_floating_plate_s_spring_and_dashpot_forces() {
    let a = bundled_answers("floating-plate-springs");
    let (m, w, h) = (4.0, 0.6, 0.3);
    let (acc, forces) = plate_accelerations(
        (m, m * (w * w + h * h) / 12.0, 9.81),
        (Vector2::new(0.02, 0.1), 0.1, Vector2::new(0.1, -0.2), 0.5),
        &[
            (
                Vector2::new(-0.4, 1.0),
                Vector2::new(-w / 2.0, h / 2.0),
                200.0,
                0.75,
            ),
            (
                Vector2::new(0.4, 1.0),
                Vector2::new(w / 2.0, h / 2.0),
                200.0,
                0.75,
            ),
        ],
        Some((Vector2::new(0.0, -0.8), Vector2::new(0.0, -h / 2.0), 3.0)),
        0.5,
    );
    close(v(&a, 0), forces[0], 1e-9, "left spring");
    close(v(&a, 1), forces[1], 1e-9, "right spring");
    close(v(&a, 2), forces[2], 1e-9, "dashpot");
    for (i, name) in ["x''", "y''", "theta''"].into_iter().enumerate() {
        close(v(&a, 3 + i), acc[i], 1e-9, name);
    }
}

#[test]
fn the_driven_slider_crank_s_motor_torque_and_pin_forces() {
    let a = bundled_answers("slider-crank-driven");
    let (r, l, ma, mb, mc, w, g) = (0.1, 0.35, 1.2, 1.5, 2.0, 4.0 * PI, 9.81);
    // At the dead centre (q1 = 0) the rod lies along x and turns at -r w/l with no angular
    // acceleration; the slider accelerates at -r w^2 (1 + r/l), the rod's center at
    // -r w^2 (1 + r/(2 l)), the crank's at -r w^2/2, all along x.
    let a_c = -r * w * w * (1.0 + r / l);
    let a_b = -r * w * w * (1.0 + r / (2.0 * l));
    let a_a = -r * w * w / 2.0;
    // Rod about the crank pin: -l Q_y - (l/2) mB g = 0; slider along x: Q_x = mC a_C.
    let (qx, qy) = (mc * a_c, -mb * g / 2.0);
    // Rod: P - Q - mB g y = mB a_B; crank: F_O - P - mA g y = mA a_A.
    let (px, py) = (mb * a_b + qx, qy + mb * g);
    let (ox, oy) = (ma * a_a + px, py + ma * g);
    // Crank about O: tau - r P_y - (r/2) mA g = 0.
    close(
        v(&a, 0),
        r * py + r / 2.0 * ma * g,
        1e-9,
        "motor torque at t = 0",
    );
    close(
        v(&a, 0),
        r * g * (ma + mb) / 2.0,
        1e-9,
        "by the power of gravity",
    );
    close(part(&a[1], "O.force.x"), ox, 1e-9, "O x");
    close(part(&a[1], "O.force.y"), oy, 1e-9, "O y");
    close(part(&a[2], "Q.force.x"), qx, 1e-9, "Q along the rod");
    close(part(&a[2], "Q.force.y"), qy, 1e-9, "Q across the rod");
    // At any instant the motor's power is the rate of the energy, tau w = dE/dt = w dE/dq:
    // E(q) = w^2 J(q)/2 + V(q), J the inertia reduced to the crank.
    let sc = SliderCrank { r, l };
    let energy = |q: f64| {
        let (_, dphi, _, dx, gb, dgb) = sc.at(q);
        let j = ma * r * r / 3.0
            + mb * dgb.norm_squared()
            + mb * l * l / 12.0 * dphi * dphi
            + mc * dx * dx;
        w * w * j / 2.0 + g * (ma * r / 2.0 * q.sin() + mb * gb.y)
    };
    let q = w * 0.1;
    let h = 1e-5;
    close(
        v(&a, 3),
        (energy(q + h) - energy(q - h)) / (2.0 * h),
        1e-6,
        "motor torque at 0.1 s",
    );
}

#[test]
fn the_engine_s_crank_and_its_energy() {
    let a = bundled_answers("slider-crank-flywheel");
    let (r, l, ia, mb, mc, f0, e, h, g) = (0.1, 0.35, 0.05, 1.5, 2.0, 100.0, 0.03f64, 0.48, 9.81);
    let sc = SliderCrank { r, l };
    // One degree of freedom: E = J(q) q'^2/2 + V(q), the gas's potential
    // F0 e^1.4 (h - x)^-0.4/0.4; Lagrange: J q'' + J'(q) q'^2/2 + V'(q) = 0.
    let j = |q: f64| {
        let (_, dphi, _, dx, _, dgb) = sc.at(q);
        ia + mb * dgb.norm_squared() + mb * l * l / 12.0 * dphi * dphi + mc * dx * dx
    };
    let pot = |q: f64| {
        let (_, _, x, _, gb, _) = sc.at(q);
        mb * g * gb.y + f0 * e.powf(1.4) * (h - x).powf(-0.4) / 0.4
    };
    let (q, qd, step) = (0.4, 20.0, 1e-5);
    let dj = (j(q + step) - j(q - step)) / (2.0 * step);
    let dv = (pot(q + step) - pot(q - step)) / (2.0 * step);
    close(v(&a, 0), -(dj * qd * qd / 2.0 + dv) / j(q), 1e-6, "q1''");
    let e0 = j(q) * qd * qd / 2.0 + pot(q);
    close(v(&a, 1), e0, 1e-9, "energy at the start");
    close(v(&a, 2), e0, SIMULATED, "energy after 2 s");
}

#[test]
fn the_simple_pendulum_comes_back_after_the_large_amplitude_period() {
    let a = bundled_answers("simple-pendulum");
    let (l, g, th, thd) = (0.8, 9.81, 0.6f64, 0.5);
    // Energy: cos(theta_max) = cos(theta) - L theta'^2/(2 g).
    let th_max = (th.cos() - l * thd * thd / (2.0 * g)).acos();
    close(v(&a, 3), th_max, 1e-12, "theta_max");
    // T = 4 sqrt(L/g) K(k), k = sin(theta_max/2), K by the arithmetic-geometric mean.
    let k = (th_max / 2.0).sin();
    let (mut p, mut q) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..8 {
        (p, q) = ((p + q) / 2.0, (p * q).sqrt());
    }
    let period = 4.0 * (l / g).sqrt() * PI / (2.0 * p);
    assert!(
        (a[4].time - period).abs() < 1e-9,
        "asked at {} s, T = {period}",
        a[4].time
    );
    // After one period the bob is back where it started, moving as it started.
    close(v(&a, 4), th, SIMULATED, "theta(T)");
    close(v(&a, 5), thd, 1e-6, "theta'(T)");
}

#[test]
fn the_two_link_arm_held_at_its_target() {
    let a = bundled_answers("two-link-robot-arm");
    let (m1, l1, m2, l2, g) = (3.0, 0.5, 2.0, 0.4, 9.81);
    let (tau1, tau2, r1, r2, kp1, kp2) = (15.95, 1.78, 0.6f64, 0.5f64, 60.0, 20.0);
    // Lagrange at rest: M(q) q'' = T - G(q), with
    // M11 = m1 L1^2/3 + m2 (L1^2 + L2^2/3 + L1 L2 cos q2), M12 = m2 (L2^2/3 + L1 L2 cos q2/2),
    // M22 = m2 L2^2/3, G1 = g ((m1/2 + m2) L1 cos q1 + m2 L2/2 cos(q1 + q2)),
    // G2 = g m2 L2/2 cos(q1 + q2).
    let gravity = |q1: f64, q2: f64| {
        Vector2::new(
            g * ((m1 / 2.0 + m2) * l1 * q1.cos() + m2 * l2 / 2.0 * (q1 + q2).cos()),
            g * m2 * l2 / 2.0 * (q1 + q2).cos(),
        )
    };
    let c2 = r2.cos();
    let mm = Matrix2::new(
        m1 * l1 * l1 / 3.0 + m2 * (l1 * l1 + l2 * l2 / 3.0 + l1 * l2 * c2),
        m2 * (l2 * l2 / 3.0 + l1 * l2 * c2 / 2.0),
        m2 * (l2 * l2 / 3.0 + l1 * l2 * c2 / 2.0),
        m2 * l2 * l2 / 3.0,
    );
    let qdd = mm
        .lu()
        .solve(&(Vector2::new(tau1, tau2) - gravity(r1, r2)))
        .expect("regular");
    close(v(&a, 5), qdd.x, 1e-8, "q1'' at the target");
    close(v(&a, 6), qdd.y, 1e-8, "q2'' at the target");
    // Where it comes to rest the torques balance gravity: tau + kp (r - q) = G(q).
    let rest = &a[7].values;
    let (q1, q2) = (rest[0].1, rest[1].1);
    let left = Vector2::new(tau1 + kp1 * (r1 - q1), tau2 + kp2 * (r2 - q2)) - gravity(q1, q2);
    assert!(left.norm() < 1e-9, "statics: {left}");
}

/// The bar about its end: I_O θ̈ = −m g (L/2) sin θ at rest, I_O = m L²/3, so the equivalent
/// simple pendulum −g sin θ/θ̈ is 2L/3 at any angle (the statement's third part).
#[test]
fn the_compound_pendulum_swings_like_a_simple_pendulum_of_two_thirds_its_length() {
    let a = bundled_answers("compound-pendulum");
    let l = 1.0;
    close(v(&a, 2), 2.0 * l / 3.0, 1e-12, "ℓ_e");
}

/// The block on the smooth wedge: N = M m g cos α / (M + m sin² α), the statement's
/// closed form, from the program's ẍ through the block's motion normal to the incline.
#[test]
fn the_wedges_normal_force_is_the_closed_form() {
    let a = bundled_answers("block-on-wedge");
    let (big_m, m, g, alpha) = (5.0, 1.0, 9.81, std::f64::consts::PI / 6.0);
    let n = big_m * m * g * alpha.cos() / (big_m + m * alpha.sin().powi(2));
    close(v(&a, 4), n, 1e-12, "N");
}

/// A slider-crank with the crank at angle q: the rod's absolute angle, the slider's
/// position, and their derivatives by q, in closed form.
struct SliderCrank {
    r: f64,
    l: f64,
}

impl SliderCrank {
    /// (phi, dphi/dq, x, dx/dq, G_B, dG_B/dq).
    fn at(&self, q: f64) -> (f64, f64, f64, f64, Vector2<f64>, Vector2<f64>) {
        let (r, l) = (self.r, self.l);
        let phi = (-r * q.sin() / l).asin();
        let dphi = -r * q.cos() / (l * phi.cos());
        let x = r * q.cos() + l * phi.cos();
        let dx = -r * q.sin() - l * phi.sin() * dphi;
        let gb = r * along(q) + l / 2.0 * along(phi);
        let dgb = r * perp(q) + l / 2.0 * dphi * perp(phi);
        (phi, dphi, x, dx, gb, dgb)
    }
}
