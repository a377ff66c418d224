//! Planar problems with sliding joints, springs and a floating body: the cart-pole, the
//! bead on a rotating rod, the two-mass spring-damper, the block on a wedge and the plate
//! hung from springs.

use super::solve_linear;
use crate::support::{assert_close, column, simulate, solve_all};

const G: f64 = 9.81;

#[test]
fn cart_pole_accelerations_and_reactions() {
    let (cart, m, l, h, push) = (1.0, 0.2, 0.8, 0.1, 2.0);
    // x' = 0.2 m/s enters nowhere: the track is smooth and level.
    let (th, thd) = (0.3_f64, -0.4_f64);
    // The pole's center: G = (x - L/2 sin th, h + L/2 cos th). Lagrange with
    // T = (M + m) x'^2/2 - m L/2 cos th x' th' + m L^2/3 th'^2/2, V = m g L/2 cos th:
    //   (M + m) x'' - m L/2 cos th th'' = F - m L/2 sin th th'^2
    //   -m L/2 cos th x'' + m L^2/3 th'' = m g L/2 sin th
    let k = m * l / 2.0;
    let acc = solve_linear(
        vec![
            vec![cart + m, -k * th.cos()],
            vec![-k * th.cos(), m * l * l / 3.0],
        ],
        vec![push - k * th.sin() * thd * thd, m * G * l / 2.0 * th.sin()],
    );
    let (xdd, thdd) = (acc[0], acc[1]);
    // Newton on the pole: F_pin = m a_G + m g (0, 1).
    let a_g = [
        xdd - l / 2.0 * (th.cos() * thdd - th.sin() * thd * thd),
        -l / 2.0 * (th.sin() * thdd + th.cos() * thd * thd),
    ];
    let pin = [m * a_g[0], m * a_g[1] + m * G];
    // The cart does not rise or turn: N - M g - pin_y = 0, and about its center
    // M_track + (h (0, 1)) x (-pin) = 0, so M_track = -h pin_x.
    let normal = cart * G + pin[1];
    let tipping = -h * pin[0];
    for s in solve_all("cart-pole", &[]) {
        let what = |w: &str| format!("{}: {w}", s.method);
        assert_close(s.acc("x"), xdd, 1e-9, G, &what("x''"));
        assert_close(s.acc("theta"), thdd, 1e-9, G / l, &what("theta''"));
        let f = s.force("pin");
        assert_close(f[0], pin[0], 1e-9, m * G, &what("pin force x"));
        assert_close(f[1], pin[1], 1e-9, m * G, &what("pin force y"));
        let track = s.force("track");
        assert_close(
            track[0],
            0.0,
            1e-9,
            cart * G,
            &what("track force x (free direction)"),
        );
        assert_close(
            track[1],
            normal,
            1e-9,
            cart * G,
            &what("track normal force"),
        );
        assert_close(
            s.moment("track")[2],
            tipping,
            1e-9,
            m * G * h,
            &what("track couple"),
        );
    }
}

/// The bead: in the rotating rod's axes the bead's acceleration is
/// (r'' - r th'^2, r th'' + 2 r' th'); along the rod only the spring acts:
/// m (r'' - r th'^2) = -k (r - r0). Moments about the axle for rod and bead together,
/// d/dt[(I + m r^2) th'] = 0, give th'' = -2 m r r' th' / (I + m r^2).
struct Bead {
    rod_inertia: f64,
    m: f64,
    k: f64,
    r0: f64,
}

const BEAD: Bead = Bead {
    rod_inertia: 0.5 * 1.0 * 1.0 / 12.0,
    m: 0.1,
    k: 20.0,
    r0: 0.2,
};

#[test]
fn bead_on_rotating_rod_centripetal_and_coriolis_terms() {
    let Bead {
        rod_inertia,
        m,
        k,
        r0,
    } = BEAD;
    let (r, rd, thd) = (0.3, 0.4, 6.0);
    let rdd = r * thd * thd - k / m * (r - r0);
    let thdd = -2.0 * m * r * rd * thd / (rod_inertia + m * r * r);
    // Across the rod the rod itself pushes the bead: N = m (r th'' + 2 r' th').
    let normal = m * (r * thdd + 2.0 * rd * thd);
    for s in solve_all("bead-on-rotating-rod", &[]) {
        let what = |w: &str| format!("{}: {w}", s.method);
        assert_close(s.acc("r"), rdd, 1e-9, r * thd * thd, &what("r''"));
        assert_close(s.acc("theta"), thdd, 1e-9, thd * thd, &what("theta''"));
        let f = s.force("slide");
        assert_close(
            f[0],
            0.0,
            1e-9,
            normal.abs(),
            &what("force along the rod (free)"),
        );
        assert_close(f[1], normal, 1e-9, normal.abs(), &what("normal force"));
    }
}

#[test]
fn bead_on_rotating_rod_conserves_angular_momentum_and_energy() {
    let Bead {
        rod_inertia,
        m,
        k,
        r0,
    } = BEAD;
    let (columns, rows) = simulate("bead-on-rotating-rod", &[]);
    let [r, rd, thd] = ["r", "r'", "theta'"].map(|c| column(&columns, c));
    let momentum = |row: &Vec<f64>| (rod_inertia + m * row[r] * row[r]) * row[thd];
    let energy = |row: &Vec<f64>| {
        0.5 * (rod_inertia + m * row[r] * row[r]) * row[thd] * row[thd]
            + 0.5 * m * row[rd] * row[rd]
            + 0.5 * k * (row[r] - r0).powi(2)
    };
    let (h0, e0) = (momentum(&rows[0]), energy(&rows[0]));
    for row in &rows {
        assert_close(
            momentum(row),
            h0,
            1e-7,
            h0,
            &format!("angular momentum at t = {}", row[0]),
        );
        assert_close(
            energy(row),
            e0,
            1e-7,
            e0,
            &format!("energy at t = {}", row[0]),
        );
    }
}

/// The two carts: springs and dashpots act along the track between the wall, A and B:
///   m1 x1'' = -k1 x1 - c1 x1' + k2 (x2 - x1) + c2 (x2' - x1')
///   m2 x2'' = -k2 (x2 - x1) - c2 (x2' - x1') + F0 cos(w t)
#[test]
fn two_mass_spring_damper_matrix_equations() {
    let (m1, m2, k1, k2, c1, c2, f0, w) = (2.0, 1.0, 200.0, 100.0, 2.0, 1.0, 5.0, 8.0_f64);
    let (t, x1, x2, v1, v2) = (0.3_f64, 0.02, -0.01, 0.1, 0.0);
    let a1 = (-k1 * x1 - c1 * v1 + k2 * (x2 - x1) + c2 * (v2 - v1)) / m1;
    let a2 = (-k2 * (x2 - x1) - c2 * (v2 - v1) + f0 * (w * t).cos()) / m2;
    for s in solve_all("two-mass-spring-damper", &["--time", "0.3"]) {
        let what = |w: &str| format!("{}: {w}", s.method);
        assert_close(s.acc("x1"), a1, 1e-9, k1 * 0.01 / m1, &what("x1''"));
        assert_close(s.acc("x2"), a2, 1e-9, k1 * 0.01 / m1, &what("x2''"));
        // The track holds cart A up against its weight; along the track it is free.
        let f = s.force("trackA");
        assert_close(f[0], 0.0, 1e-9, m1 * G, &what("track force along x"));
        assert_close(f[1], m1 * G, 1e-9, m1 * G, &what("track normal force"));
        assert_close(
            s.moment("trackA")[2],
            0.0,
            1e-9,
            m1 * G * 0.1,
            &what("track couple"),
        );
    }
}

#[test]
fn two_mass_spring_damper_static_deflection_under_a_steady_push() {
    // With w = 0 the push is F0: the wall spring carries F0, and so does the coupling spring.
    let (k1, k2, f0) = (200.0, 100.0, 5.0);
    let (x1, x2) = (f0 / k1, f0 / k1 + f0 / k2);
    let state = format!("x1={x1:.17e},x2={x2:.17e},x1'=0,x2'=0");
    for s in solve_all(
        "two-mass-spring-damper",
        &["--set", "w=0", "--state", &state],
    ) {
        assert_close(s.acc("x1"), 0.0, 1e-9, f0, &format!("{}: x1''", s.method));
        assert_close(s.acc("x2"), 0.0, 1e-9, f0, &format!("{}: x2''", s.method));
    }
}

#[test]
fn block_on_wedge_matches_the_closed_forms() {
    let (big, m, alpha, height, b) = (5.0, 1.0, std::f64::consts::PI / 6.0, 0.5, 0.1);
    let (sa, ca) = (alpha.sin(), alpha.cos());
    // Lagrange with T = (M + m) x'^2/2 + m x' s' cos a + m s'^2/2, V = -m g s sin a:
    //   (M + m) x'' + m cos a s'' = 0,  cos a x'' + s'' = g sin a, so
    let d = big + m * sa * sa;
    let sdd = (big + m) * G * sa / d;
    let xdd = -m * G * sa * ca / d;
    // The block: m a_B = N n - m g (0, 1) with n = (sin a, cos a) normal to the incline,
    // a_B = (x'' + s'' cos a, -s'' sin a); this gives N = M m g cos a / (M + m sin^2 a).
    let normal = big * m * G * ca / d;
    let block = [m * (xdd + sdd * ca), m * (-sdd * sa) + m * G];
    assert_close(
        block[0],
        normal * sa,
        1e-12,
        normal,
        "closed forms agree with each other (x)",
    );
    assert_close(
        block[1],
        normal * ca,
        1e-12,
        normal,
        "closed forms agree with each other (y)",
    );
    // The floor on the wedge: vertically for both bodies, F_y = (M + m) g + m a_By. About the
    // wedge's origin O (the wedge does not turn), with its center c = (B/3, H/3), B = H/tan a:
    //   M_f - M g c_x + (P x (-N n))_z = (c x M a_W)_z = -c_y M x''
    // where P = at + s u is where the block's reaction acts, u = (cos a, -sin a).
    let s_now = 0.1;
    let base = height / alpha.tan();
    let (cx, cy) = (base / 3.0, height / 3.0);
    let p = [
        b / 2.0 * sa + 0.1 + s_now * ca,
        height - 0.1 * alpha.tan() + b / 2.0 * ca - s_now * sa,
    ];
    let p_cross_n = p[0] * normal * ca - p[1] * normal * sa;
    let floor_couple = big * G * cx + p_cross_n - cy * big * xdd;
    let floor_normal = (big + m) * G - m * sdd * sa;
    for s in solve_all("block-on-wedge", &["--state", "s=0.1"]) {
        let what = |w: &str| format!("{}: {w}", s.method);
        assert_close(s.acc("x"), xdd, 1e-9, G, &what("x''"));
        assert_close(s.acc("s"), sdd, 1e-9, G, &what("s''"));
        let f = s.force("incline");
        assert_close(f[0], normal * sa, 1e-9, normal, &what("incline force x"));
        assert_close(f[1], normal * ca, 1e-9, normal, &what("incline force y"));
        assert_close(
            s.moment("incline")[2],
            0.0,
            1e-9,
            normal * b,
            &what("incline couple"),
        );
        let floor = s.force("floor");
        assert_close(floor[0], 0.0, 1e-9, big * G, &what("floor force x (free)"));
        assert_close(
            floor[1],
            floor_normal,
            1e-9,
            big * G,
            &what("floor normal force"),
        );
        assert_close(
            s.moment("floor")[2],
            floor_couple,
            1e-9,
            big * G * base,
            &what("floor couple"),
        );
    }
}

#[test]
fn block_on_wedge_limit_of_a_very_heavy_wedge_is_a_fixed_incline() {
    // M -> infinity: the wedge stays put and s'' -> g sin a; at M = 1e6 m the closed form
    // differs from the limit by a factor 1 + (m/M) cos^2 a, under 1e-6.
    let alpha = std::f64::consts::PI / 6.0;
    for s in solve_all("block-on-wedge", &["--set", "M=1e6"]) {
        assert_close(
            s.acc("s"),
            G * alpha.sin(),
            1e-5,
            G,
            &format!("{}: s''", s.method),
        );
        assert_close(s.acc("x"), 0.0, 1e-5, G, &format!("{}: x''", s.method));
    }
}

#[test]
fn floating_plate_spring_and_dashpot_forces() {
    let (m, w, h, k, l0, c, couple) = (4.0, 0.6, 0.3, 200.0, 0.75, 3.0, 0.5);
    let inertia = m * (w * w + h * h) / 12.0;
    let (x, y, th, xd, yd, thd) = (0.02, 0.1, 0.1_f64, 0.1, -0.2, 0.5);
    // A plate point p (in plate axes) is at c + R p and moves at v_c + th' k x (R p).
    let arm = |p: [f64; 2]| {
        [
            th.cos() * p[0] - th.sin() * p[1],
            th.sin() * p[0] + th.cos() * p[1],
        ]
    };
    let place = |p: [f64; 2]| {
        let r = arm(p);
        ([x + r[0], y + r[1]], [xd - thd * r[1], yd + thd * r[0]])
    };
    let unit = |from: [f64; 2], to: [f64; 2]| {
        let d = [to[0] - from[0], to[1] - from[1]];
        let len = d[0].hypot(d[1]);
        ([d[0] / len, d[1] / len], len)
    };
    // Each force on the plate, with the plate point it acts at.
    let mut forces: Vec<([f64; 2], [f64; 2])> = Vec::new();
    for (anchor, corner) in [
        ([-0.4, 1.0], [-w / 2.0, h / 2.0]),
        ([0.4, 1.0], [w / 2.0, h / 2.0]),
    ] {
        // A spring longer than its free length pulls the corner toward the anchor.
        let (at, _) = place(corner);
        let (e, len) = unit(anchor, at);
        let tension = k * (len - l0);
        forces.push((corner, [-tension * e[0], -tension * e[1]]));
    }
    {
        // The dashpot resists the rate at which D moves away from F.
        let (at, v) = place([0.0, -h / 2.0]);
        let (e, _) = unit([0.0, -0.8], at);
        let rate = v[0] * e[0] + v[1] * e[1];
        forces.push(([0.0, -h / 2.0], [-c * rate * e[0], -c * rate * e[1]]));
    }
    let fx: f64 = forces.iter().map(|(_, f)| f[0]).sum();
    let fy: f64 = forces.iter().map(|(_, f)| f[1]).sum::<f64>() - m * G;
    let mz: f64 = forces
        .iter()
        .map(|(p, f)| {
            let r = arm(*p);
            r[0] * f[1] - r[1] * f[0]
        })
        .sum::<f64>()
        + couple;
    // Newton and Euler for a free plate: m x'' = F_x, m y'' = F_y, I th'' = M_z.
    for s in solve_all("floating-plate-springs", &[]) {
        let what = |w: &str| format!("{}: {w}", s.method);
        assert_close(s.acc("x"), fx / m, 1e-9, G, &what("x''"));
        assert_close(s.acc("y"), fy / m, 1e-9, G, &what("y''"));
        assert_close(s.acc("theta"), mz / inertia, 1e-9, G / w, &what("theta''"));
    }
}
