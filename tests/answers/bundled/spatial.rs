//! Answers of the spatial and rolling bundled problems against closed forms written here.

use super::*;

#[test]
fn the_wheel_pendulum_released_from_rest() {
    let a = bundled_answers("wheel-pendulum");
    let (big_m, r, m, lp, g, psi) = (3.0, 0.2, 1.0, 0.6, 9.81, 0.8f64);
    // Rolling: x' = -R theta'. With psi = theta + phi the rod's angle,
    // T = (3M/2 + m) x'^2/2 + m Lp cos(psi) x' psi'/2 + m Lp^2 psi'^2/6,
    // V = -m g Lp cos(psi)/2; from rest the velocity terms vanish.
    let mm = Matrix2::new(
        1.5 * big_m + m,
        m * lp / 2.0 * psi.cos(),
        m * lp / 2.0 * psi.cos(),
        m * lp * lp / 3.0,
    );
    let s = mm
        .lu()
        .solve(&Vector2::new(0.0, -m * g * lp / 2.0 * psi.sin()))
        .expect("regular");
    let (xdd, psidd) = (s.x, s.y);
    let thdd = -xdd / r;
    close(v(&a, 0), xdd, 1e-9, "x''");
    close(v(&a, 1), thdd, 1e-9, "theta''");
    close(v(&a, 2), psidd - thdd, 1e-9, "phi''");
    // Newton for the rod and for the whole: the rod's center accelerates at a_P.
    let ap = Vector2::new(
        xdd + lp / 2.0 * psi.cos() * psidd,
        lp / 2.0 * psi.sin() * psidd,
    );
    close(
        part(&a[3], "ground.force.x"),
        big_m * xdd + m * ap.x,
        1e-9,
        "ground x",
    );
    close(
        part(&a[3], "ground.force.y"),
        m * ap.y + (big_m + m) * g,
        1e-9,
        "ground y",
    );
    close(part(&a[4], "pin.force.x"), m * ap.x, 1e-9, "pin x");
    close(part(&a[4], "pin.force.y"), m * ap.y + m * g, 1e-9, "pin y");
    // At rest the energy is the potential alone; it stays so.
    let e0 = big_m * g * r + m * g * (r - lp / 2.0 * psi.cos());
    close(v(&a, 5), e0, 1e-9, "energy at the release");
    close(v(&a, 6), e0, SIMULATED, "energy after 4 s");
}

/// The rotation of the body-fixed sequence `axes` by `angles`.
fn rotation(axes: [Vector3<f64>; 3], angles: [f64; 3]) -> Matrix3<f64> {
    let mut r = Matrix3::identity();
    for (axis, angle) in axes.iter().zip(angles) {
        r *= Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(*axis), angle).matrix();
    }
    r
}

#[test]
fn the_rolling_coin_keeps_its_energy_and_obeys_newton_and_euler() {
    let a = bundled_answers("rolling-coin");
    let (m, r, g, th) = (0.5, 0.1, 9.81, 0.3f64);
    let (psid, phid) = (1.0, 8.0);
    let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
    // Orientation z-x-y (heading, lean, spin); the axle is D.y.
    let rot = rotation([z, x, y], [0.0, th, 0.0]);
    let axle = rot * y;
    let inertia =
        rot * Matrix3::from_diagonal(&Vector3::new(
            m * r * r / 4.0,
            m * r * r / 2.0,
            m * r * r / 4.0,
        )) * rot.transpose();
    let omega = psid * z + phid * axle;
    // The contact point is the rim's lowest point: from the centre, R (0, sin, -cos).
    let to_contact = r * Vector3::new(0.0, th.sin(), -th.cos());
    let vel = omega.cross(&(-to_contact));
    let e0 =
        m * vel.norm_squared() / 2.0 + omega.dot(&(inertia * omega)) / 2.0 + m * g * r * th.cos();
    close(v(&a, 4), e0, 1e-9, "energy at the start");
    close(v(&a, 5), e0, SIMULATED, "energy after 5 s");
    // Newton: the floor's force is m (a_G + g z). Euler about the centre:
    // (C - G) x F = I alpha + omega x I omega, with (theta' = 0)
    // alpha = psi'' z + theta'' x + phi'' axle + phi' psi' (z x axle).
    let state = &a[3];
    let p = mbd_tutor::problem::load(
        &std::fs::read_to_string(crate::support::problem("rolling-coin")).expect("readable"),
    )
    .expect("valid");
    let derivation = mbd_tutor::pipeline::derive(
        &p,
        mbd_tutor::equations::Method::MotionLaw,
        mbd_tutor::pipeline::Purpose::Numbers,
    )
    .expect("derives");
    let solver = mbd_tutor::pipeline::Solver::new(&p, &derivation);
    use mbd_tutor::numeric::System;
    let qdd = solver
        .evaluate(0.0, &state.q, &state.rates)
        .expect("solves")
        .accelerations;
    let (ag, psidd, thdd, phidd) = (Vector3::new(qdd[0], qdd[1], qdd[2]), qdd[3], qdd[4], qdd[5]);
    close(psidd, v(&a, 0), 1e-12, "psi''");
    close(thdd, v(&a, 1), 1e-12, "theta''");
    close(phidd, v(&a, 2), 1e-12, "phi''");
    let force = m * (ag + g * z);
    for (k, axis) in ["x", "y", "z"].into_iter().enumerate() {
        close(
            part(&a[3], &format!("floor.force.{axis}")),
            force[k],
            1e-9,
            "floor force",
        );
    }
    let alpha = psidd * z + thdd * x + phidd * axle + phid * psid * z.cross(&axle);
    let residual = to_contact.cross(&force) - inertia * alpha - omega.cross(&(inertia * omega));
    assert!(residual.norm() < 1e-9, "Euler's equations: {residual}");
}

#[test]
fn the_two_wheeled_cart_under_equal_torques() {
    let a = bundled_answers("two-wheeled-cart");
    let (mc, iyy, mw, r, tau) = (6.0, 0.1, 1.0, 0.15, 0.6);
    // With equal torques it goes straight: theta_w = phi + q the wheels' angle, x = R theta_w.
    // T = ((mC + 2 mW) R^2 + mW R^2) theta_w'^2/2 + Iyy phi'^2/2; the motors do work
    // 2 tau (d theta_w - d phi).
    let thwdd = 2.0 * tau / ((mc + 3.0 * mw) * r * r);
    let phidd = -2.0 * tau / iyy;
    close(v(&a, 0), r * thwdd, 1e-9, "x''");
    close(v(&a, 1), phidd, 1e-9, "phi''");
    close(v(&a, 2), thwdd - phidd, 1e-9, "qL''");
    close(v(&a, 3), thwdd - phidd, 1e-9, "qR''");
    assert!(v(&a, 4).abs() < 1e-9, "psi'' = {}", v(&a, 4));
}

#[test]
fn the_spherical_pendulum_keeps_its_angular_momentum_about_the_vertical_and_its_energy() {
    let a = bundled_answers("spherical-pendulum");
    let (m, rb, l, g) = (1.0, 0.05, 1.0, 9.81);
    let (q, qd) = ([0.5, 0.3, 0.0], [0.2, 1.0, 0.3]);
    let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
    let rot = rotation([x, y, z], q);
    // omega = q1' x + q2' (Rx y) + q3' (Rx Ry z); the ball's center is -L along the body's z.
    let omega = qd[0] * x
        + qd[1] * (rotation([x, y, z], [q[0], 0.0, 0.0]) * y)
        + qd[2] * (rotation([x, y, z], [q[0], q[1], 0.0]) * z);
    let axis = rot * z;
    let i_o = (2.0 / 5.0 * m * rb * rb) * Matrix3::identity()
        + m * l * l * (Matrix3::identity() - axis * axis.transpose());
    let h = (i_o * omega).z;
    let e = omega.dot(&(i_o * omega)) / 2.0 - m * g * l * axis.z;
    close(v(&a, 4), h, 1e-12, "H at the start");
    close(v(&a, 5), h, SIMULATED, "H after 4 s");
    close(v(&a, 6), e, 1e-12, "energy at the start");
    close(v(&a, 7), e, SIMULATED, "energy after 4 s");
}

/// Euler's equations I w' + w x I w = 0 in body axes, with w and w' from the x-y-z angles:
/// w = (c2 c3 a1' + s3 a2', -c2 s3 a1' + c3 a2', s2 a1' + a3') and its derivative.
fn euler_residual(inertia: Matrix3<f64>, q: [f64; 3], qd: [f64; 3], qdd: [f64; 3]) -> Vector3<f64> {
    let (s2, c2, s3, c3) = (q[1].sin(), q[1].cos(), q[2].sin(), q[2].cos());
    let w = Vector3::new(
        c2 * c3 * qd[0] + s3 * qd[1],
        -c2 * s3 * qd[0] + c3 * qd[1],
        s2 * qd[0] + qd[2],
    );
    let wd = Vector3::new(
        c2 * c3 * qdd[0] + s3 * qdd[1] - s2 * c3 * qd[1] * qd[0] - c2 * s3 * qd[2] * qd[0]
            + c3 * qd[2] * qd[1],
        -c2 * s3 * qdd[0] + c3 * qdd[1] + s2 * s3 * qd[1] * qd[0]
            - c2 * c3 * qd[2] * qd[0]
            - s3 * qd[2] * qd[1],
        s2 * qdd[0] + qdd[2] + c2 * qd[1] * qd[0],
    );
    inertia * wd + w.cross(&(inertia * w))
}

#[test]
fn the_torque_free_bodies_obey_eulers_equations_and_keep_their_energy() {
    let a = bundled_answers("torque-free-body");
    for i in 0..3 {
        assert!(
            v(&a, i).abs() < 1e-12,
            "the mass center accelerates: {}",
            v(&a, i)
        );
    }
    let inertia = Matrix3::new(4.0, -0.5, 0.2, -0.5, 6.0, 0.3, 0.2, 0.3, 8.0);
    let r = euler_residual(
        inertia,
        [0.0; 3],
        [0.2, -0.1, 2.0],
        [v(&a, 3), v(&a, 4), v(&a, 5)],
    );
    assert!(r.norm() < 1e-9, "Euler's equations: {r}");

    let a = bundled_answers("torque-free-body-speeds");
    let inertia = Matrix3::from_diagonal(&Vector3::new(4.0, 6.0, 8.0));
    let (q, qd) = ([0.3, -0.2, 0.5], [0.2, -0.1, 2.0]);
    let r = euler_residual(inertia, q, qd, [v(&a, 0), v(&a, 1), v(&a, 2)]);
    assert!(r.norm() < 1e-9, "Euler's equations: {r}");
    // The kinetic energy from the angular velocity in N, turned into body axes.
    let (x, y, z) = (Vector3::x(), Vector3::y(), Vector3::z());
    let omega_n = qd[0] * x
        + qd[1] * (rotation([x, y, z], [q[0], 0.0, 0.0]) * y)
        + qd[2] * (rotation([x, y, z], [q[0], q[1], 0.0]) * z);
    let omega_b = rotation([x, y, z], q).transpose() * omega_n;
    let t = omega_b.dot(&(inertia * omega_b)) / 2.0;
    close(v(&a, 3), t, 1e-12, "T at the start");
    close(v(&a, 4), t, SIMULATED, "T after 10 s");
}

#[test]
fn the_rrp_arm_s_extension_and_the_slide_held_at_the_targets() {
    let a = bundled_answers("arm-3d-rrp");
    let (mt, rt, mu, lu, me, le, g) = (4.0, 0.1, 2.0, 0.5, 1.0, 0.4, 9.81);
    let (tau1, tau2, f3, r2, r3) = (0.5, 7.75, 4.7, 0.5f64, 0.2);
    close(v(&a, 0), tau1, 1e-12, "turret torque");
    // Part 2: the right-hand side equals q3'' from the whole dynamics.
    close(v(&a, 6), v(&a, 5), 1e-9, "the extension's equation");
    // Held at rest at the targets: E's center at r = r3 + LE/2 from S on the turret's axis.
    // Along the arm: mE q3'' = f3 - mE g sin q2. About the shoulder (no coupling with the
    // turret, the arm's plane holding the vertical): (mU LU^2/3 + mE LE^2/12 + mE r^2) q2''
    // = tau2 - g cos q2 (mU LU/2 + mE r). About the vertical: I_v q1'' = tau1.
    let (s, c, r) = (r2.sin(), r2.cos(), r3 + le / 2.0);
    let q3dd = f3 / me - g * s;
    let q2dd = (tau2 - g * c * (mu * lu / 2.0 + me * r))
        / (mu * lu * lu / 3.0 + me * le * le / 12.0 + me * r * r);
    close(v(&a, 8), q2dd, 1e-8, "q2'' held");
    close(v(&a, 9), q3dd, 1e-8, "q3'' held");
    let (iux, iuz, iex, iez) = (2e-3, mu * lu * lu / 12.0, 5e-4, me * le * le / 12.0);
    let i_v = mt * rt * rt / 2.0
        + iux * s * s
        + iuz * c * c
        + mu * (lu / 2.0 * c).powi(2)
        + iex * s * s
        + iez * c * c
        + me * (r * c).powi(2);
    let q1dd = tau1 / i_v;
    // The slide's force on E in U's axes (x along the arm, y horizontal, z up across it):
    // E's center accelerates at (q3'', r cos q2 q1'', r q2''); gravity is -g (sin, 0, cos).
    let held = &a[10];
    close(part(held, "slide.force.x"), 0.0, 1e-9, "along the slide");
    close(
        part(held, "slide.force.y"),
        me * r * c * q1dd,
        1e-8,
        "sideways",
    );
    close(
        part(held, "slide.force.z"),
        me * (r * q2dd + g * c),
        1e-8,
        "across",
    );
    // Its couple about E's inner end: I alpha + r_c x mE (a - g), alpha = (q1'' s, -q2'', q1'' c).
    let (iey, rc) = (me * le * le / 12.0, le / 2.0);
    close(
        part(held, "slide.moment.x"),
        iex * q1dd * s,
        1e-8,
        "couple x",
    );
    close(
        part(held, "slide.moment.y"),
        -iey * q2dd - rc * me * (r * q2dd + g * c),
        1e-8,
        "couple y",
    );
    close(
        part(held, "slide.moment.z"),
        iez * q1dd * c + rc * me * r * c * q1dd,
        1e-8,
        "couple z",
    );
}

#[test]
fn spins_and_angular_momenta_about_an_axis() {
    // The gyroscope at its steady state: with the axle horizontal and theta' = 0 the rotor's
    // spin equation is Is phi'' = tau - c phi', the motor's torque in it alone; off, -c s/Is.
    let a = bundled_answers("gyroscope-gimbal");
    close(v(&a, 4), -1e-5 * 300.0 / 2e-4, 1e-9, "the rotor slows down");
    // The shaft and collar: about the vertical only the motor acts (the oil film and the
    // spring are internal, the bearing carries no axial couple), so dH/dt = tau, and with the
    // motor off both end at H/(Is + Ic).
    let a = bundled_answers("collar-on-spinning-shaft");
    let is = 3.0 * 0.025f64.powi(2) / 2.0;
    let ic = 0.8 * (0.025f64.powi(2) + 0.04f64.powi(2)) / 2.0;
    close(v(&a, 3), 0.1, 1e-9, "dH/dt");
    close(
        v(&a, 4),
        (is * 20.0 + ic * 0.0) / (is + ic),
        1e-12,
        "common final spin",
    );
    // The bead: r'' = r theta'^2 - k (r - r0)/m; H = (I_O + m r^2) theta' is kept, so
    // theta'' = -2 m r r' theta'/(I_O + m r^2); across the rod the bead needs
    // m (r theta'' + 2 r' theta').
    let a = bundled_answers("bead-on-rotating-rod");
    let (big_m, ha, m, k, r0, r, rd, w) = (0.5, 0.5, 0.1, 20.0, 0.2, 0.3, 0.4, 6.0);
    let i_o = big_m * (2.0 * ha) * (2.0 * ha) / 12.0;
    let thdd = -2.0 * m * r * rd * w / (i_o + m * r * r);
    close(v(&a, 0), r * w * w - k * (r - r0) / m, 1e-9, "r''");
    close(v(&a, 1), thdd, 1e-9, "theta''");
    close(v(&a, 2), r * w * w, 1e-12, "centripetal");
    close(v(&a, 3), 2.0 * m * rd * w, 1e-12, "Coriolis");
    close(
        part(&a[4], "slide.force.y"),
        m * (r * thdd + 2.0 * rd * w),
        1e-9,
        "normal force",
    );
}
