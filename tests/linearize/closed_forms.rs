//! Linearization against closed forms derived by hand: pendulums, a two-mass chain, the sleeping top, the torque-free body.

use super::*;

#[test]
fn simple_pendulum_swings_at_root_g_over_l() {
    let path = problem("simple-pendulum");
    let path = path.to_str().unwrap();
    for (method, length) in [("motion-law", 0.8f64), ("newton-euler", 0.8), ("kane", 2.5)] {
        let set = format!("L={length}");
        let l = linearize(&[
            path,
            "--state",
            "theta=0,theta'=0",
            "--method",
            method,
            "--set",
            &set,
        ]);
        // A bob on a light rod: ω = √(g/L).
        let omega = (9.81 / length).sqrt();
        let lambda = eigenvalues(&l);
        assert_eq!(lambda.len(), 2);
        assert!(
            lambda[0].0.abs() < 1e-12 && close(lambda[0].1, -omega, 1e-12),
            "{method}: {lambda:?}"
        );
        assert!(
            lambda[1].0.abs() < 1e-12 && close(lambda[1].1, omega, 1e-12),
            "{method}: {lambda:?}"
        );
        let mode = &l["modes"][0];
        assert!(close(
            number(&mode["natural_frequency_hz"]),
            omega / TAU,
            1e-12
        ));
        assert!(close(
            number(&mode["damped_frequency_hz"]),
            omega / TAU,
            1e-12
        ));
        assert_eq!(number(&mode["damping_ratio"]), 0.0);
        assert_eq!(mode["shape"], serde_json::json!({ "theta": 1.0 }));
        // A = [[0, 1], [-g/L, 0]]; M = m L², K = m g L.
        let a = matrix(&l["A"]);
        assert_eq!(a[0], vec![0.0, 1.0]);
        assert!(
            close(a[1][0], -9.81 / length, 1e-12) && a[1][1] == 0.0,
            "{a:?}"
        );
        assert!(close(matrix(&l["M"])[0][0], 0.5 * length * length, 1e-12));
        assert!(close(matrix(&l["K"])[0][0], 0.5 * 9.81 * length, 1e-12));
    }
}

#[test]
fn compound_pendulum_with_pivot_friction() {
    // A uniform bar of mass m, length L on a pin at one end, a joint damper c:
    // I_O θ'' + c θ' + m g (L/2) θ = 0 with I_O = m L²/3.
    let text = r#"{
      "title": "Bar on a pin", "dimension": 2,
      "constants": { "m": 2.0, "L": 1.2, "g": 9.81, "c": 0.3 },
      "gravity": "-g*N.y",
      "bodies": { "B": { "mass": "m", "center": "-L/2*B.y", "inertia": "m*L^2/12" } },
      "joints": [ { "name": "O", "type": "revolute", "parent": "N", "child": "B", "coordinates": ["q"] } ],
      "loads": [ { "name": "friction", "type": "joint_damper", "joint": "O", "coordinate": "q", "coefficient": "c" } ]
    }"#;
    let path = temporary_problem("compound", text);
    let l = linearize(&[path.to_str().unwrap()]);
    let (m, length, g, c): (f64, f64, f64, f64) = (2.0, 1.2, 9.81, 0.3);
    let inertia = m * length * length / 3.0;
    let k = m * g * length / 2.0;
    let omega_n = (k / inertia).sqrt();
    let zeta = c / (2.0 * (k * inertia).sqrt());
    let mode = &l["modes"][0];
    assert!(
        close(number(&mode["natural_frequency_hz"]), omega_n / TAU, 1e-10),
        "{mode}"
    );
    assert!(close(number(&mode["damping_ratio"]), zeta, 1e-10), "{mode}");
    assert!(close(
        number(&mode["damped_frequency_hz"]),
        omega_n * (1.0 - zeta * zeta).sqrt() / TAU,
        1e-10
    ));
    assert!(close(matrix(&l["C"])[0][0], c, 1e-12));
}

/// The double pendulum of two uniform rods hanging straight down, in absolute angles
/// θ1 = q1, θ2 = q1 + q2: M_abs and K_abs by hand, then M = Tᵀ M_abs T, K = Tᵀ K_abs T.
#[test]
fn double_pendulum_has_the_two_frequencies_of_its_characteristic_equation() {
    let (m1, l1, m2, l2, g): (f64, f64, f64, f64, f64) = (1.2, 0.6, 0.8, 0.4, 9.81);
    let m_abs = [
        [m1 * l1 * l1 / 3.0 + m2 * l1 * l1, m2 * l1 * l2 / 2.0],
        [m2 * l1 * l2 / 2.0, m2 * l2 * l2 / 3.0],
    ];
    let k_abs = [[(m1 / 2.0 + m2) * g * l1, 0.0], [0.0, m2 * g * l2 / 2.0]];
    // det(K − ω² M) = 0: a ω⁴ − b ω² + c = 0.
    let a = m_abs[0][0] * m_abs[1][1] - m_abs[0][1] * m_abs[1][0];
    let b = m_abs[0][0] * k_abs[1][1] + m_abs[1][1] * k_abs[0][0];
    let c = k_abs[0][0] * k_abs[1][1];
    let root = (b * b - 4.0 * a * c).sqrt();
    let expected = [
        ((b - root) / (2.0 * a)).sqrt() / TAU,
        ((b + root) / (2.0 * a)).sqrt() / TAU,
    ];
    // T = [[1, 0], [1, 1]] maps (q1, q2) to (θ1, θ2).
    let congruent = |x: [[f64; 2]; 2]| {
        [
            [x[0][0] + 2.0 * x[0][1] + x[1][1], x[0][1] + x[1][1]],
            [x[0][1] + x[1][1], x[1][1]],
        ]
    };
    let path = problem("double-pendulum-rods");
    for method in ["motion-law", "newton-euler", "kane"] {
        let l = linearize(&[
            path.to_str().unwrap(),
            "--state",
            "q1=0,q2=0,q1'=0,q2'=0",
            "--method",
            method,
        ]);
        let found = natural_frequencies(&l);
        assert_eq!(found.len(), 2, "{method}");
        for (f, e) in found.iter().zip(expected) {
            assert!(
                close(*f, e, 1e-10),
                "{method}: {found:?} against {expected:?}"
            );
        }
        for (name, by_hand) in [("M", congruent(m_abs)), ("K", congruent(k_abs))] {
            let got = matrix(&l[name]);
            for i in 0..2 {
                for j in 0..2 {
                    assert!(
                        close(got[i][j], by_hand[i][j], 1e-12),
                        "{method} {name}: {got:?}"
                    );
                }
            }
        }
        assert!(l["eigenvalues"]
            .as_array()
            .unwrap()
            .iter()
            .all(|e| number(&e["re"]) == 0.0));
    }
}

#[test]
fn two_mass_chain_has_its_hand_written_m_c_k_and_modes() {
    let (m1, m2, k1, k2, c1, c2) = (2.0, 1.0, 200.0, 100.0, 2.0, 1.0);
    let m = [[m1, 0.0], [0.0, m2]];
    let c = [[c1 + c2, -c2], [-c2, c2]];
    let k = [[k1 + k2, -k2], [-k2, k2]];
    let path = problem("two-mass-spring-damper");
    // The system is linear: any state gives the same matrices.
    let l = linearize(&[path.to_str().unwrap(), "--time", "0.3"]);
    for (name, by_hand) in [("M", m), ("C", c), ("K", k)] {
        let got = matrix(&l[name]);
        for i in 0..2 {
            for j in 0..2 {
                assert!(close(got[i][j], by_hand[i][j], 1e-12), "{name}: {got:?}");
            }
        }
    }
    // A = [[0, I], [−M⁻¹K, −M⁻¹C]].
    let a = matrix(&l["A"]);
    for i in 0..2 {
        for j in 0..2 {
            assert!(close(a[2 + i][j], -k[i][j] / m[i][i], 1e-12), "{a:?}");
            assert!(close(a[2 + i][2 + j], -c[i][j] / m[i][i], 1e-12), "{a:?}");
        }
    }
    // Every eigenvalue is a root of det(λ² M + λ C + K).
    for (re, im) in eigenvalues(&l) {
        let lambda = num_complex(re, im);
        let entry = |i: usize, j: usize| {
            let l2 = mul(lambda, lambda);
            add(
                add(scale(l2, m[i][j]), scale(lambda, c[i][j])),
                (k[i][j], 0.0),
            )
        };
        let det = sub(mul(entry(0, 0), entry(1, 1)), mul(entry(0, 1), entry(1, 0)));
        assert!(
            norm(det) < 1e-8 * k1 * k2,
            "det = {det:?} at λ = {lambda:?}"
        );
        assert!(re < 0.0, "damped: {re}");
    }
    // C = K/100: proportional damping, so the shapes are real, those of K − ω² M = 0.
    for mode in l["modes"].as_array().unwrap() {
        let omega = number(&mode["natural_frequency_hz"]) * TAU;
        let shape = [number(&mode["shape"]["x1"]), number(&mode["shape"]["x2"])];
        for i in 0..2 {
            let residual: f64 = (0..2)
                .map(|j| (k[i][j] - omega * omega * m[i][j]) * shape[j])
                .sum();
            assert!(residual.abs() < 1e-8 * k1, "{mode}");
        }
        assert!(shape.contains(&1.0) && shape.iter().all(|x| x.abs() <= 1.0));
        assert!(
            close(number(&mode["damping_ratio"]), 0.01 * omega / 2.0, 1e-9),
            "{mode}"
        );
    }
}

type C64 = (f64, f64);
fn num_complex(re: f64, im: f64) -> C64 {
    (re, im)
}
fn add(a: C64, b: C64) -> C64 {
    (a.0 + b.0, a.1 + b.1)
}
fn sub(a: C64, b: C64) -> C64 {
    (a.0 - b.0, a.1 - b.1)
}
fn mul(a: C64, b: C64) -> C64 {
    (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0)
}
fn scale(a: C64, s: f64) -> C64 {
    (a.0 * s, a.1 * s)
}
fn norm(a: C64) -> f64 {
    a.0.hypot(a.1)
}

/// A heavy symmetric top on its tip, its spin (the last angle of an x-y-z sequence, so that
/// upright is not a gimbal lock) set by the constant `w` through an expression-valued rate.

#[test]
fn sleeping_top_is_stable_above_its_threshold_spin() {
    let (m, l, i3, it, g): (f64, f64, f64, f64, f64) = (0.5, 0.04, 4.0e-4, 2.5e-4, 9.81);
    let i1 = it + m * l * l; // about a transverse axis through the tip
                             // Stable iff (I3 ω)² > 4 I1' m g l.
    let threshold = 2.0 * (i1 * m * g * l).sqrt() / i3;
    let path = temporary_problem("top", TOP);
    let sweep = format!("w={}:{}:9", 0.8 * threshold, 1.2 * threshold);
    let results = linearize(&[path.to_str().unwrap(), "--sweep", &sweep]);
    let results = results.as_array().expect("a sweep gives an array");
    assert_eq!(results.len(), 9);
    for l_at in results {
        let w = number(&l_at["sweep"]["w"]);
        assert!(
            close(number(&l_at["state"]["a3'"]), w, 1e-15),
            "the rate follows w"
        );
        let largest = eigenvalues(l_at)
            .iter()
            .map(|e| e.0)
            .fold(f64::MIN, f64::max);
        if w < 0.99 * threshold {
            assert!(largest > 1e-3, "w = {w} below {threshold}: {largest}");
            assert_eq!(l_at["stable"], false);
        } else if w > 1.01 * threshold {
            assert!(largest <= 0.0, "w = {w} above {threshold}: {largest}");
            assert_eq!(l_at["stable"], true);
        }
        // s⁴ + (p² − 2k) s² + k² = 0, p = I3 ω / I1', k = m g l / I1'; s = 0 twice (spin).
        let (p, k) = (i3 * w / i1, m * g * l / i1);
        for (re, im) in eigenvalues(l_at) {
            let s = num_complex(re, im);
            let s2 = mul(s, s);
            let value = add(add(mul(s2, s2), scale(s2, p * p - 2.0 * k)), (k * k, 0.0));
            let at_zero = norm(s) < 1e-6;
            assert!(
                at_zero || norm(value) < 1e-8 * k * k,
                "w = {w}: s = {s:?} gives {value:?}"
            );
        }
    }
    // The text report names the stable range.
    let out = run(&["linearize", path.to_str().unwrap(), "--sweep", &sweep]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("stable (every Re λ ≤ 0) for w from"),
        "{text}"
    );
}

/// A torque-free body on a spherical joint at its mass center, spinning about one
/// principal axis; the spin is the first angle of the sequence, so that the equations do
/// not depend on it and the linearization holds for all time.
fn torque_free(sequence: &str) -> String {
    format!(
        r#"{{
  "title": "Torque-free body", "dimension": 3,
  "constants": {{ "I1": 2.0, "I2": 3.0, "I3": 5.0, "w": 1.5 }},
  "coordinates": {{ "a1": {{ "rate": "w" }} }},
  "bodies": {{ "B": {{ "mass": 1, "inertia": {{ "xx": "I1", "yy": "I2", "zz": "I3" }} }} }},
  "joints": [ {{ "name": "C", "type": "spherical", "parent": "N", "child": "B", "sequence": "{sequence}", "coordinates": ["a1", "a2", "a3"] }} ]
}}"#
    )
}

#[test]
fn torque_free_body_is_unstable_about_its_intermediate_axis_only() {
    let (i1, i2, i3, w): (f64, f64, f64, f64) = (2.0, 3.0, 5.0, 1.5);
    // About y (intermediate): growth rate ω √((I2 − I1)(I3 − I2)/(I1 I3)).
    let path = temporary_problem("torque-free-y", &torque_free("yzx"));
    let l = linearize(&[path.to_str().unwrap()]);
    let sigma = w * ((i2 - i1) * (i3 - i2) / (i1 * i3)).sqrt();
    let lambda = eigenvalues(&l);
    let positive: Vec<_> = lambda.iter().filter(|e| e.0 > 0.0).collect();
    assert_eq!(positive.len(), 1, "{lambda:?}");
    assert!(
        close(positive[0].0, sigma, 1e-10) && positive[0].1 == 0.0,
        "{lambda:?}"
    );
    assert!(
        lambda.iter().any(|e| close(e.0, -sigma, 1e-10)),
        "{lambda:?}"
    );
    let marginal = lambda.iter().filter(|e| e.0 == 0.0).count();
    assert_eq!(
        marginal,
        lambda.len() - 2,
        "the others are marginal: {lambda:?}"
    );
    assert_eq!(l["stable"], false);
    // About z (largest) and x (smallest): stable, wobbling at ω √((I3 − I1)(I3 − I2)/(I1 I2))
    // and ω √((I2 − I1)(I3 − I1)/(I2 I3)).
    for (sequence, wobble) in [
        ("zxy", w * ((i3 - i1) * (i3 - i2) / (i1 * i2)).sqrt()),
        ("xyz", w * ((i2 - i1) * (i3 - i1) / (i2 * i3)).sqrt()),
    ] {
        let path = temporary_problem(&format!("torque-free-{sequence}"), &torque_free(sequence));
        let l = linearize(&[path.to_str().unwrap()]);
        let lambda = eigenvalues(&l);
        assert!(lambda.iter().all(|e| e.0 == 0.0), "{sequence}: {lambda:?}");
        assert_eq!(l["stable"], true);
        let found = natural_frequencies(&l);
        assert!(
            found.iter().any(|f| close(*f, wobble / TAU, 1e-10)),
            "{sequence}: {found:?}, expected {}",
            wobble / TAU
        );
    }
}
