//! The validation problems of version 3 against closed forms worked by hand, by every
//! method: two rough contacts on one body (a box pushed on its two edges, a ladder on a
//! rough floor and a rough wall), a block on a rough cart, a pendulum on a light slider,
//! a planetary gear train and an Atwood machine with a massive pulley.

use crate::support::{assert_close, column, friction_site, number, problem, run, solve_all};

const G: f64 = 9.81;

// ---- a box pushed across a rough floor on its two bottom edges ----

#[test]
fn a_box_pushed_on_two_rough_edges_slides_with_a_equal_to_p_minus_mu_m_g_over_m() {
    let (m, b, c, d, p, mu) = (20.0, 0.4, 0.3, 0.1, 120.0, 0.4);
    // Sliding: m a = P − μ(N_A + N_B), N_A + N_B = m g; no turning, so about the centre
    // b (N_B − N_A) = μ c (N_A + N_B) + P d.
    let a = (p - mu * m * G) / m;
    let difference = (mu * c * m * G + p * d) / b;
    let (back, front) = ((m * G - difference) / 2.0, (m * G + difference) / 2.0);
    // From rest too: P > μ m g, so it starts to slide at once.
    for rate in ["x'=1.2", "x'=0"] {
        for s in solve_all("validation/box-on-two-rough-edges", &["--state", rate]) {
            let what = |q: &str| format!("{} at {rate}: {q}", s.method);
            assert_close(s.acc("x"), a, 1e-9, 1.0, &what("x''"));
            assert_close(s.acc("th"), 0.0, 1e-9, 1.0, &what("th''"));
            for (edge, normal) in [("back", back), ("front", front)] {
                assert_eq!(
                    friction_site(&s.json, edge)["mode"],
                    "slip",
                    "{}",
                    what(edge)
                );
                assert_close(s.force(edge)[1], normal, 1e-9, 1.0, &what(edge));
                assert_close(s.force(edge)[0], -mu * normal, 1e-9, 1.0, &what(edge));
            }
        }
    }
}

#[test]
fn a_box_pushed_less_than_mu_m_g_stays_at_rest_on_both_edges() {
    let (m, b, c, d, p, mu) = (20.0, 0.4, 0.3, 0.1, 50.0, 0.4);
    assert!(p < mu * m * G, "the case holds");
    // Both edges stick: statics fixes N_A + N_B = m g, F_A + F_B = −P and, about the
    // centre, b (N_B − N_A) = (c + d) P, but not how the friction is shared; the tool
    // shares it so that both edges are equally far from slipping: |F|/N = P/(m g).
    let difference = (c + d) * p / b;
    let (back, front) = ((m * G - difference) / 2.0, (m * G + difference) / 2.0);
    for s in solve_all(
        "validation/box-on-two-rough-edges",
        &["--set", "P=50", "--state", "x'=0"],
    ) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("x"), 0.0, 1e-9, 1.0, &what("x''"));
        assert_close(
            s.force("back")[0] + s.force("front")[0],
            -p,
            1e-9,
            1.0,
            &what("ΣF"),
        );
        for (edge, normal) in [("back", back), ("front", front)] {
            let site = friction_site(&s.json, edge);
            assert_eq!(site["mode"], "stick", "{}", what(edge));
            assert_close(number(site, "normal"), normal, 1e-9, 1.0, &what(edge));
            assert_close(number(site, "ratio"), p / (m * G), 1e-9, 1.0, &what(edge));
        }
    }
}

#[test]
fn the_handout_says_that_statics_leaves_the_split_between_the_edges_free() {
    let text = crate::support::explain(
        "validation/box-on-two-rough-edges",
        &["--set", "P=50,v=0", "--method", "kane"],
    );
    assert!(text.contains("the equations are one short"), "{text}");
    assert!(text.contains("The check holds"), "{text}");
}

#[test]
fn a_box_thrown_along_the_floor_stops_at_v_squared_over_two_a_and_stays() {
    // Pushed with P = 50 N < μ m g while sliding at 1.2 m/s: it slows at (μ m g − P)/m,
    // stops at t = v/a having gone v²/(2a), and both edges stick from then on.
    let (m, mu, p, v) = (20.0, 0.4, 50.0, 1.2);
    let a = (mu * m * G - p) / m;
    for method in crate::support::METHODS {
        let (columns, rows) = crate::support::simulate(
            "validation/box-on-two-rough-edges",
            &[
                "--set",
                "P=50",
                "--method",
                method,
                "--duration",
                "1.5",
                "--no-checks",
            ],
        );
        let (x, rate) = (column(&columns, "x"), column(&columns, "x'"));
        let last = rows.last().expect("rows");
        assert_close(
            last[x],
            v * v / (2.0 * a),
            1e-8,
            1.0,
            &format!("{method}: x"),
        );
        assert_close(last[rate], 0.0, 1e-8, 1.0, &format!("{method}: x'"));
    }
}

// ---- a ladder on a rough floor against a rough wall ----

/// By hand, the ladder sliding (θ from the vertical, foot away from the wall, top down):
/// floor N₁ up and μ₁N₁ toward the wall, wall N₂ out and μ₂N₂ up, the mid-point at
/// (l sin θ, l cos θ):
///   m (l cos θ θ'' − l sin θ θ'²) = N₂ − μ₁N₁,
///   m (−l sin θ θ'' − l cos θ θ'²) = N₁ + μ₂N₂ − m g,
///   m l²/3 θ'' = l N₁ (sin θ − μ₁ cos θ) − l N₂ (cos θ + μ₂ sin θ),
/// solved by Cramer's rule for (θ'', N₁, N₂).
fn ladder(theta: f64, rate: f64) -> [f64; 3] {
    let (m, l, mu1, mu2) = (12.0, 1.25, 0.25, 0.2);
    let (s, c) = theta.sin_cos();
    let a = [
        [m * l * c, mu1, -1.0],
        [-m * l * s, -1.0, -mu2],
        [m * l * l / 3.0, -l * (s - mu1 * c), l * (c + mu2 * s)],
    ];
    let b = [
        m * l * s * rate * rate,
        m * l * c * rate * rate - m * G,
        0.0,
    ];
    let det = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
            - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let whole = det(a);
    let mut x = [0.0; 3];
    for (k, x) in x.iter_mut().enumerate() {
        let mut replaced = a;
        for (row, b) in replaced.iter_mut().zip(b) {
            row[k] = b;
        }
        *x = det(replaced) / whole;
    }
    x
}

#[test]
fn a_ladder_sliding_on_a_rough_floor_and_wall_follows_the_hand_solution() {
    let (theta, rate) = (0.6_f64, 0.5);
    let [alpha, floor, wall] = ladder(theta, rate);
    for s in solve_all("validation/ladder-on-rough-wall-and-floor", &[]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("theta"), alpha, 1e-9, 1.0, &what("theta''"));
        let x = 1.25 * (theta.cos() * alpha - theta.sin() * rate * rate);
        assert_close(s.acc("x"), x, 1e-9, 1.0, &what("x''"));
        assert_close(s.force("floor")[1], floor, 1e-9, 1.0, &what("floor N"));
        assert_close(
            s.force("floor")[0],
            -0.25 * floor,
            1e-9,
            1.0,
            &what("floor F"),
        );
        assert_close(s.force("wall")[0], wall, 1e-9, 1.0, &what("wall N"));
        assert_close(s.force("wall")[1], 0.2 * wall, 1e-9, 1.0, &what("wall F"));
        for site in ["floor", "wall"] {
            assert_eq!(
                friction_site(&s.json, site)["mode"],
                "slip",
                "{}",
                what(site)
            );
        }
    }
}

#[test]
fn a_ladder_on_a_rough_floor_and_wall_holds_while_tan_theta_is_at_most_the_limit() {
    // At rest both ends stick, and statics leaves the forces one short (four for three
    // equations); the ladder holds if some split keeps both within μN, that is for
    // tan θ ≤ 2μ₁/(1 − μ₁μ₂) (θ from the vertical).
    let (mu1, mu2) = (0.25_f64, 0.2_f64);
    let limit = (2.0 * mu1 / (1.0 - mu1 * mu2)).atan();
    for (theta, mode) in [(limit - 1e-4, "stick"), (limit + 1e-4, "slip")] {
        let state = format!("theta={theta},theta'=0");
        for s in solve_all(
            "validation/ladder-on-rough-wall-and-floor",
            &["--state", &state],
        ) {
            let what = |q: &str| format!("{} at θ = {theta}: {q}", s.method);
            let want = if mode == "stick" {
                0.0
            } else {
                ladder(theta, 0.0)[0]
            };
            assert_close(s.acc("theta"), want, 1e-9, 1.0, &what("theta''"));
            for site in ["floor", "wall"] {
                assert_eq!(friction_site(&s.json, site)["mode"], mode, "{}", what(site));
            }
        }
    }
}

#[test]
fn the_motion_law_explains_two_rough_contacts_of_one_body() {
    for name in [
        "validation/box-on-two-rough-edges",
        "validation/ladder-on-rough-wall-and-floor",
    ] {
        let text = crate::support::explain(name, &["--method", "motion-law"]);
        assert!(
            // A contact sticking at the start has its no-slip row; one sliding has the
            // sliding law in its place, said beside it.
            text.contains("while it sticks")
                || (text.contains("in place of the no-slip condition") && text.contains("sticks")),
            "{name}: no stick rows"
        );
    }
}

// ---- a block on a rough cart pulled by a force ----

#[test]
fn a_block_on_a_rough_cart_rides_along_or_slips_back_by_every_method() {
    let (cart, block, mu) = (4.0, 1.5, 0.3);
    for p in [10.0, 30.0] {
        // Together while the block's m a needs no more than μ m g: P ≤ μ g (M + m).
        let (x, s, friction) = if p <= mu * G * (cart + block) {
            let a = p / (cart + block);
            (a, 0.0, block * a)
        } else {
            let a = (p - mu * block * G) / cart;
            (a, mu * G - a, mu * block * G)
        };
        let set = format!("P={p}");
        for sol in solve_all("validation/block-on-rough-cart", &["--set", &set]) {
            let what = |q: &str| format!("{} with P = {p}: {q}", sol.method);
            assert_close(sol.acc("x"), x, 1e-9, 1.0, &what("x''"));
            assert_close(sol.acc("s"), s, 1e-9, 1.0, &what("s''"));
            assert_close(sol.force("top")[0], friction, 1e-9, 1.0, &what("friction"));
            assert_close(sol.force("top")[1], block * G, 1e-9, 1.0, &what("normal"));
            // The rail carries both weights; the light slider carries nothing across.
            let rail = sol.force("rail");
            assert_close(rail[1], (cart + block) * G, 1e-9, 1.0, &what("rail"));
        }
    }
}

// ---- a pendulum hung from a light slider held by a spring ----

#[test]
fn a_pendulum_on_a_light_slider_follows_the_hand_solution() {
    let (m, l, k) = (0.8, 0.6, 50.0);
    let (x, theta, theta_rate) = (0.05_f64, 0.4_f64, -0.7_f64);
    // The slider has no mass: the spring's −k x reaches the bob through the rod alone, so
    // m X'' = −k x for the bob's X = x + L sin θ, and the rod (no mass either) pushes along
    // itself: sin θ (Y'' + g) + cos θ X'' = 0 with Y = −L cos θ.
    let bob_x = -k * x / m;
    let (s, c) = theta.sin_cos();
    let alpha = -(l * s * c * theta_rate.powi(2) + G * s + c * bob_x) / (l * s * s);
    let slider = bob_x - l * c * alpha + l * s * theta_rate.powi(2);
    let bob_y = l * s * alpha + l * c * theta_rate.powi(2);
    for sol in solve_all("validation/pendulum-on-light-slider", &[]) {
        let what = |q: &str| format!("{}: {q}", sol.method);
        assert_close(sol.acc("theta"), alpha, 1e-9, 1.0, &what("theta''"));
        assert_close(sol.acc("x"), slider, 1e-9, 1.0, &what("x''"));
        assert_close(sol.force("pin")[0], -k * x, 1e-9, 1.0, &what("pin x"));
        assert_close(
            sol.force("pin")[1],
            m * (bob_y + G),
            1e-9,
            1.0,
            &what("pin y"),
        );
    }
}

#[test]
fn with_the_rod_hanging_straight_down_every_method_names_the_light_slider() {
    let path = problem("validation/pendulum-on-light-slider");
    for method in crate::support::METHODS {
        let out = run(&[
            "solve".as_ref(),
            path.as_os_str(),
            "--method".as_ref(),
            method.as_ref(),
            "--state".as_ref(),
            "theta=0".as_ref(),
        ]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{method}: {stderr}");
        assert!(
            stderr.contains("`x''` is undetermined: body S has no mass"),
            "{method}: {stderr}"
        );
    }
}

// ---- a planetary gear train with a fixed ring ----

#[test]
fn a_planetary_train_turns_with_the_reflected_inertia_and_its_tooth_forces() {
    let (rs, rp, is, ic, ip, mp, t) = (0.06_f64, 0.03_f64, 0.004, 0.01, 0.0006, 1.2, 2.5);
    // The ring fixed: ω_c = r_s ω_s / (2 (r_s + r_p)), ω_p = −r_s ω_s / (2 r_p) (absolute).
    let carrier = rs / (2.0 * (rs + rp));
    let planet = -rs / (2.0 * rp);
    let inertia = is + (ic + mp * (rs + rp).powi(2)) * carrier.powi(2) + ip * planet.powi(2);
    let alpha = t / inertia;
    // The sun: I_s α = T − r_s F; the planet about its centre: I_p ω_p' = r_p (G − F).
    let sun_tooth = (t - is * alpha) / rs;
    let ring_tooth = sun_tooth + ip * planet * alpha / rp;
    let (qs, qc) = (0.7_f64, 0.3_f64);
    let state = format!("qs={qs},qc={qc},qp=1.1");
    for s in solve_all("validation/planetary-gear-train", &["--state", &state]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("qs"), alpha, 1e-9, 1.0, &what("qs''"));
        assert_close(s.acc("qc"), carrier * alpha, 1e-9, 1.0, &what("qc''"));
        assert_close(
            s.acc("qp"),
            (planet - carrier) * alpha,
            1e-9,
            1.0,
            &what("qp''"),
        );
        // Both tooth forces on the planet lie along the tangent (−sin qc, cos qc); the sun's
        // in the sun's unit vectors, the ring's in N's.
        let sun = s.force("sunmesh");
        let (tx, ty) = (-sun_tooth * qc.sin(), sun_tooth * qc.cos());
        let (c, sn) = (qs.cos(), qs.sin());
        assert_close(sun[0], c * tx + sn * ty, 1e-9, 1.0, &what("sun tooth x"));
        assert_close(sun[1], -sn * tx + c * ty, 1e-9, 1.0, &what("sun tooth y"));
        let ring = s.force("ringmesh");
        assert_close(ring[0], -ring_tooth * qc.sin(), 1e-9, 1.0, &what("ring x"));
        assert_close(ring[1], ring_tooth * qc.cos(), 1e-9, 1.0, &what("ring y"));
    }
}

// ---- an Atwood machine with a massive pulley ----

#[test]
fn an_atwood_machine_with_a_massive_or_a_light_pulley() {
    let (r, m1, m2) = (0.2, 3.0, 1.5);
    for mass in [4.0, 0.0] {
        // T = (M R²/2 + (m₁ + m₂) R²) θ'²/2, V = g R θ (m₂ − m₁).
        let alpha = G * r * (m1 - m2) / (mass * r * r / 2.0 + (m1 + m2) * r * r);
        let (left, right) = (m1 * (G - r * alpha), m2 * (G + r * alpha));
        let set = format!("M={mass}");
        for s in solve_all("validation/atwood-massive-pulley", &["--set", &set]) {
            let what = |q: &str| format!("{} with M = {mass}: {q}", s.method);
            assert_close(s.acc("th"), alpha, 1e-9, 1.0, &what("th''"));
            assert_close(s.acc("y1"), -r * alpha, 1e-9, 1.0, &what("y1''"));
            assert_close(s.acc("y2"), r * alpha, 1e-9, 1.0, &what("y2''"));
            assert_close(s.force("left")[1], -left, 1e-9, 1.0, &what("left"));
            assert_close(s.force("right")[1], -right, 1e-9, 1.0, &what("right"));
            let bearing = mass * G + left + right;
            assert_close(s.force("O")[1], bearing, 1e-9, 1.0, &what("bearing"));
            assert_close(
                number(&s.json["state"], "y1'"),
                -r * 1.5,
                1e-9,
                1.0,
                &what("y1'"),
            );
        }
    }
}

// ---- a double pendulum of two particles, both angles measured from the vertical ----

#[test]
fn a_double_pendulum_with_absolute_angles_follows_the_textbook_equations_and_its_rods_pull_along_themselves(
) {
    let (m1, m2, l1, l2) = (1.0, 0.5, 0.6, 0.4);
    let (q1, q2, u1, u2): (f64, f64, f64, f64) = (0.7, 0.3, 1.0, 0.5);
    let d = q1 - q2;
    // Lagrange's equations in the absolute angles, by hand:
    // (m1 + m2) L1 q̈1 + m2 L2 cos(q1 − q2) q̈2 = −m2 L2 sin(q1 − q2) q̇2² − (m1 + m2) g sin q1,
    // L1 cos(q1 − q2) q̈1 + L2 q̈2 = L1 sin(q1 − q2) q̇1² − g sin q2.
    let (a11, a12, b1) = (
        (m1 + m2) * l1,
        m2 * l2 * d.cos(),
        -m2 * l2 * d.sin() * u2 * u2 - (m1 + m2) * G * q1.sin(),
    );
    let (a21, a22, b2) = (l1 * d.cos(), l2, l1 * d.sin() * u1 * u1 - G * q2.sin());
    let det = a11 * a22 - a12 * a21;
    let acc1 = (b1 * a22 - a12 * b2) / det;
    let acc2 = (a11 * b2 - a21 * b1) / det;
    // Each rod is a two-force member: it pulls its bob toward its pivot with a tension.
    // Along rod 2 (e₂ = (−sin q2, cos q2), from P2 toward Q) for bob 2, then along rod 1.
    let e = |q: f64| [-q.sin(), q.cos()];
    let t2 = m2 * (G * q2.cos() + l2 * u2 * u2 + l1 * u1 * u1 * d.cos() + l1 * acc1 * d.sin());
    let t1 = m1 * (G * q1.cos() + l1 * u1 * u1) + t2 * d.cos();
    for s in solve_all("validation/double-pendulum-particles-absolute", &[]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("q1"), acc1, 1e-9, 1.0, &what("q1''"));
        assert_close(s.acc("q2"), acc2, 1e-9, 1.0, &what("q2''"));
        // O's force in N's unit vectors; Q's in rod 1's, turned by q1 into N's.
        let o = s.force("O");
        let q = s.force("Q");
        let q_in_n = [
            q[0] * q1.cos() - q[1] * q1.sin(),
            q[0] * q1.sin() + q[1] * q1.cos(),
        ];
        for k in 0..2 {
            assert_close(o[k], t1 * e(q1)[k], 1e-9, 1.0, &what("O along rod 1"));
            assert_close(q_in_n[k], t2 * e(q2)[k], 1e-9, 1.0, &what("Q along rod 2"));
        }
    }
}
