//! Machines in three dimensions: the RRP arm, the unbalanced disk on its shaft and the
//! collar on a spinning shaft.

use super::v3::{mul, rot};
use crate::support::{assert_close, column, simulate, solve_all};

const G: f64 = 9.81;

/// The RRP arm: turret (about N.z), upper arm (elevation q2 about -T.y, so its axis is
/// e = cos q2 T.x + sin q2 T.z), telescoping link E along e with its center at
/// r = q3 + LE/2 from the shoulder S, which lies on the turret's axis and so is fixed.
struct Arm {
    mt: f64,
    rt: f64,
    mu: f64,
    lu: f64,
    me: f64,
    le: f64,
}

const ARM: Arm = Arm {
    mt: 4.0,
    rt: 0.1,
    mu: 2.0,
    lu: 0.5,
    me: 1.0,
    le: 0.4,
};

#[test]
fn arm_extension_feels_centrifugal_force_and_gravity_only() {
    // E's center is at r e from the fixed S, and e turns at w = q1' N.z - q2' T.y, so
    // a_G . e = r'' - r |w x e|^2 (the Euler and Coriolis terms are normal to e), with
    // |w x e|^2 = q1'^2 cos^2 q2 + q2'^2. Along e: mE a_G . e = F3 - mE g sin q2.
    let Arm { me, le, .. } = ARM;
    let (q2, q3, q1d, q2d, q3d) = (0.4_f64, 0.15, 0.8, 0.3, 0.1);
    // The actuator's controller: F3 = f3 + kp3 (r3 - q3) - kd3 q3'.
    let f3 = 4.7 + 400.0 * (0.2 - q3) - 40.0 * q3d;
    let r = q3 + le / 2.0;
    let q3dd = r * (q1d * q1d * q2.cos().powi(2) + q2d * q2d) - G * q2.sin() + f3 / me;
    for s in solve_all("arm-3d-rrp", &[]) {
        assert_close(s.acc("q3"), q3dd, 1e-9, G, &format!("{}: q3''", s.method));
    }
}

#[test]
fn arm_turret_acceleration_with_the_arm_fixed_in_the_turret() {
    // With q2' = q3' = 0 the angular momentum about the vertical is I_eff q1' with I_eff
    // constant, and only the turret motor has a moment about the vertical: q1'' = tau1/I_eff.
    // N.z = sin q2 U.x + cos q2 U.z, so each arm part adds Ixx sin^2 + Izz cos^2 + m d^2
    // with d its center's distance from the vertical.
    let Arm {
        mt,
        rt,
        mu,
        lu,
        me,
        le,
        ..
    } = ARM;
    let (q2, q3, tau1) = (0.4_f64, 0.15, 0.5);
    let (s2, c2) = (q2.sin().powi(2), q2.cos().powi(2));
    let r = q3 + le / 2.0;
    let turret = mt * rt * rt / 2.0;
    let upper = 2.0e-3 * s2 + mu * lu * lu / 12.0 * c2 + mu * (lu / 2.0).powi(2) * c2;
    let link = 5.0e-4 * s2 + me * le * le / 12.0 * c2 + me * r * r * c2;
    let q1dd = tau1 / (turret + upper + link);
    for s in solve_all("arm-3d-rrp", &["--state", "q2'=0,q3'=0"]) {
        assert_close(s.acc("q1"), q1dd, 1e-9, 1.0, &format!("{}: q1''", s.method));
    }
}

#[test]
fn arm_held_still_by_its_motors() {
    // At rest on its targets the controllers give only their feedforward parts. With tau1 = 0,
    // the shoulder carrying gravity's moment, tau2 = g cos q2 (mU LU/2 + mE r), and the actuator
    // the link's weight along the arm, f3 = mE g sin q2, every q'' = 0,
    // and the slide holds the rest of the weight: in U's axes, with N.z = sin q2 U.x + cos q2 U.z,
    // F = mE g cos q2 U.z, and about E's origin M = (LE/2 U.x) x (mE g N.z) = -LE/2 mE g cos q2 U.y.
    let Arm { mu, lu, me, le, .. } = ARM;
    let (q2, q3) = (0.5_f64, 0.2);
    let r = q3 + le / 2.0;
    let tau2 = G * q2.cos() * (mu * lu / 2.0 + me * r);
    let f3 = me * G * q2.sin();
    let set = format!("tau1=0,tau2={tau2:.17e},f3={f3:.17e}");
    for s in solve_all(
        "arm-3d-rrp",
        &["--set", &set, "--state", "q2=0.5,q3=0.2,q1'=0,q2'=0,q3'=0"],
    ) {
        for q in ["q1", "q2", "q3"] {
            assert_close(s.acc(q), 0.0, 1e-9, G, &format!("{}: {q}''", s.method));
        }
        let (f, m) = (s.force("slide"), s.moment("slide"));
        let want_f = [0.0, 0.0, me * G * q2.cos()];
        let want_m = [0.0, -le / 2.0 * me * G * q2.cos(), 0.0];
        for k in 0..3 {
            assert_close(
                f[k],
                want_f[k],
                1e-9,
                me * G,
                &format!("{}: slide force[{k}]", s.method),
            );
            assert_close(
                m[k],
                want_m[k],
                1e-9,
                me * G * le,
                &format!("{}: slide moment[{k}]", s.method),
            );
        }
    }
}

#[test]
fn unbalanced_disk_weld_and_bearing_loads() {
    let (ms, rs, m, rd, h, e, tau) = (2.0, 0.01, 5.0, 0.15, 0.4, 0.002, 0.8);
    let (theta, w) = (0.3_f64, 150.0);
    let (shaft_zz, disk_zz) = (ms * rs * rs / 2.0, m * rd * rd / 2.0);
    // Moments about the axis: (Is + Id + m e^2) alpha = tau (gravity is parallel to it).
    let alpha = tau / (shaft_zz + disk_zz + m * e * e);
    // The disk's center e S.x turns with the shaft: a_G = -e w^2 S.x + e alpha S.y. The weld
    // supplies F = m a_G + m g S.z: its radial part is the rotating unbalance load m e w^2.
    // About the weld point, M + (e S.x) x (-m g S.z) = dH_G/dt + (e S.x) x m a_G, with
    // dH_G/dt = Id alpha S.z, so M = -m g e S.y + (Id + m e^2) alpha S.z.
    let weld_force = [-m * e * w * w, m * e * alpha, m * G];
    let weld_moment = [0.0, -m * G * e, (disk_zz + m * e * e) * alpha];
    // The bearing, about O: the disk's r x m a with r = e S.x + h S.z gives
    // m (e^2 alpha S.z - h e w^2 S.y - h e alpha S.x); gravity's moment is m g e S.y; the motor's
    // tau S.z is a joint load, not part of the reaction. So in the shaft's axes
    // M = (-m h e alpha, -m h e w^2 - m g e, 0), then turned by theta into N's axes.
    let turn = rot(2, theta);
    let bearing_force = {
        let f = mul(turn, [-m * e * w * w, m * e * alpha, 0.0]);
        [f[0], f[1], (m + ms) * G]
    };
    let bearing_moment = mul(
        turn,
        [-m * h * e * alpha, -m * h * e * w * w - m * G * e, 0.0],
    );
    assert_close(
        weld_force[0].abs(),
        225.0,
        1e-12,
        1.0,
        "m e w^2 = 225 N, over four times the disk's weight",
    );
    for s in solve_all("unbalanced-disk-shaft", &[]) {
        let what = |w: &str| format!("{}: {w}", s.method);
        assert_close(s.acc("theta"), alpha, 1e-9, alpha, &what("theta''"));
        for k in 0..3 {
            assert_close(
                s.force("weld")[k],
                weld_force[k],
                1e-9,
                225.0,
                &what(&format!("weld force[{k}]")),
            );
            assert_close(
                s.moment("weld")[k],
                weld_moment[k],
                1e-9,
                225.0 * h,
                &what(&format!("weld moment[{k}]")),
            );
            assert_close(
                s.force("bearing")[k],
                bearing_force[k],
                1e-9,
                225.0,
                &what(&format!("bearing force[{k}]")),
            );
            let got = s.moment("bearing")[k];
            assert_close(
                got,
                bearing_moment[k],
                1e-9,
                225.0 * h,
                &what(&format!("bearing moment[{k}]")),
            );
        }
    }
}

/// The collar: symmetric about the shaft and centered on it, so only the axial and spin
/// equations couple it to the shaft:
///   mc z'' = -mc g - k (z - zr),   Cz (th'' + phi'') = -c phi',   Sz th'' = tau + c phi'.
struct Collar {
    ms: f64,
    sz: f64,
    mc: f64,
    cz: f64,
    k: f64,
    c: f64,
}

const COLLAR: Collar = Collar {
    ms: 3.0,
    sz: 3.0 * 0.025 * 0.025 / 2.0,
    mc: 0.8,
    cz: 0.8 * (0.025 * 0.025 + 0.04 * 0.04) / 2.0,
    k: 500.0,
    c: 0.02,
};

#[test]
fn collar_spin_up_and_spring_support() {
    let Collar {
        ms,
        sz,
        mc,
        cz,
        k,
        c,
    } = COLLAR;
    let (z, phid, tau) = (0.02, -20.0, 0.1);
    let thdd = (tau + c * phid) / sz;
    let phidd = -c * phid / cz - thdd;
    let zdd = -G - k / mc * z;
    // The bearing holds both weights and the collar's acceleration: F_z = (ms + mc) g + mc z''
    // = ms g - k (z - zr): it feels the spring, not the collar's weight.
    let axial = (ms + mc) * G + mc * zdd;
    assert_close(
        axial,
        ms * G - k * z,
        1e-12,
        ms * G,
        "the bearing feels the spring",
    );
    for s in solve_all("collar-on-spinning-shaft", &[]) {
        let what = |w: &str| format!("{}: {w}", s.method);
        assert_close(s.acc("theta"), thdd, 1e-9, thdd.abs(), &what("theta''"));
        assert_close(s.acc("phi"), phidd, 1e-9, thdd.abs(), &what("phi''"));
        assert_close(s.acc("z"), zdd, 1e-9, G, &what("z''"));
        let f = s.force("bearing");
        for (k, want) in [0.0, 0.0, axial].iter().enumerate() {
            assert_close(
                f[k],
                *want,
                1e-9,
                ms * G,
                &what(&format!("bearing force[{k}]")),
            );
            assert_close(
                s.moment("bearing")[k],
                0.0,
                1e-9,
                ms * G,
                &what(&format!("bearing moment[{k}]")),
            );
        }
    }
}

#[test]
fn collar_relative_spin_decays_exponentially_and_momentum_is_kept() {
    // Motor off: Sz th' + Cz (th' + phi') is conserved, and phi'' = -c phi' (1/Cz + 1/Sz),
    // so phi'(t) = phi'(0) exp(-c (1/Cz + 1/Sz) t).
    let Collar { sz, cz, c, .. } = COLLAR;
    let rate = c * (1.0 / cz + 1.0 / sz);
    let (columns, rows) = simulate("collar-on-spinning-shaft", &["--set", "tau=0"]);
    let [t, thd, phid] = ["t", "theta'", "phi'"].map(|n| column(&columns, n));
    let momentum = |r: &Vec<f64>| sz * r[thd] + cz * (r[thd] + r[phid]);
    let (h0, p0) = (momentum(&rows[0]), rows[0][phid]);
    for r in &rows {
        assert_close(
            momentum(r),
            h0,
            1e-7,
            h0.abs(),
            &format!("angular momentum at t = {}", r[t]),
        );
        let want = p0 * (-rate * r[t]).exp();
        assert_close(
            r[phid],
            want,
            1e-6,
            p0.abs(),
            &format!("relative spin at t = {}", r[t]),
        );
    }
}
