use super::*;
use crate::numeric::simulate::test_systems::{MassSpringDamper, Pendulum, TwoOscillators};
use crate::numeric::system::{Evaluation, ReactionColumn};

/// Another system's equations with q'' multiplied by `factor` (−1: every sign wrong), its
/// energies untouched: equations that no longer follow from the energies.
struct Broken<'a> {
    inner: &'a dyn System,
    factor: f64,
}

impl System for Broken<'_> {
    fn coordinate_names(&self) -> Vec<String> {
        self.inner.coordinate_names()
    }
    fn reaction_columns(&self) -> Vec<ReactionColumn> {
        self.inner.reaction_columns()
    }
    fn evaluate(&self, t: f64, q: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError> {
        let mut e = self.inner.evaluate(t, q, rates)?;
        for a in &mut e.accelerations {
            *a *= self.factor;
        }
        Ok(e)
    }
    fn is_conservative(&self) -> bool {
        self.inner.is_conservative()
    }
    fn has_dissipation_only(&self) -> bool {
        self.inner.has_dissipation_only()
    }
}

/// Two masses m between three springs k (wall–m–m–wall), with a sign error possible in
/// the coupling of the equations: ω² = k/m and 3k/m by hand.
struct Chain {
    m: f64,
    k: f64,
    coupling_sign: f64,
}

impl System for Chain {
    fn coordinate_names(&self) -> Vec<String> {
        vec!["x1".into(), "x2".into()]
    }
    fn reaction_columns(&self) -> Vec<ReactionColumn> {
        Vec::new()
    }
    fn evaluate(&self, _: f64, q: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError> {
        let (m, k, s) = (self.m, self.k, self.coupling_sign);
        let (x1, x2) = (q[0], q[1]);
        Ok(Evaluation {
            accelerations: vec![
                (-2.0 * k * x1 + s * k * x2) / m,
                (s * k * x1 - 2.0 * k * x2) / m,
            ],
            reactions: Vec::new(),
            kinetic: 0.5 * m * (rates[0] * rates[0] + rates[1] * rates[1]),
            potential: 0.5 * k * (x1 * x1 + (x2 - x1) * (x2 - x1) + x2 * x2),
        })
    }
    fn is_conservative(&self) -> bool {
        true
    }
    fn has_dissipation_only(&self) -> bool {
        false
    }
}

/// A mass free to slide: no potential, so no stable equilibrium.
struct Free;

impl System for Free {
    fn coordinate_names(&self) -> Vec<String> {
        vec!["x".into()]
    }
    fn reaction_columns(&self) -> Vec<ReactionColumn> {
        Vec::new()
    }
    fn evaluate(&self, _: f64, _: &[f64], rates: &[f64]) -> Result<Evaluation, SolveError> {
        Ok(Evaluation {
            accelerations: vec![0.0],
            reactions: Vec::new(),
            kinetic: 0.5 * rates[0] * rates[0],
            potential: 0.0,
        })
    }
    fn is_conservative(&self) -> bool {
        true
    }
    fn has_dissipation_only(&self) -> bool {
        false
    }
}

fn close(a: f64, b: f64, tolerance: f64) -> bool {
    (a - b).abs() <= tolerance * b.abs().max(1.0)
}

#[test]
fn crossings_of_a_sampled_cosine() {
    let times: Vec<f64> = (0..=200).map(|i| i as f64 * 0.05).collect();
    let x: Vec<f64> = times.iter().map(|t| (2.0 * t).cos()).collect();
    let v: Vec<f64> = times.iter().map(|t| -2.0 * (2.0 * t).sin()).collect();
    let found = downward_crossings(&times, &x, &v);
    // cos(2t) falls through zero at t = π/4 + kπ, three times before t = 10.
    let expected: Vec<f64> = (0..3).map(|k| PI * (0.25 + k as f64)).collect();
    assert_eq!(found.len(), expected.len());
    for (a, b) in found.iter().zip(&expected) {
        assert!((a - b).abs() < 1e-6, "{a} vs {b}");
    }
}

#[test]
fn modes_from_the_energies_match_closed_forms() {
    // Pendulum (m = 2): T = ½ m l² θ'², V = −m g l cos θ, so M = m l², K = m g l at θ = 0.
    let (l, g) = (0.5, 9.81);
    let pendulum = modes(&Pendulum::new(l, g), &[0.4]).unwrap();
    assert!(pendulum.equilibrium[0].abs() < 1e-7, "{pendulum:?}");
    assert!(
        close(pendulum.mass[(0, 0)], 2.0 * l * l, 1e-12),
        "{pendulum:?}"
    );
    assert!(
        close(pendulum.stiffness[(0, 0)], 2.0 * g * l, 1e-6),
        "{pendulum:?}"
    );
    assert!(
        close(pendulum.omegas[0], (g / l).sqrt(), 1e-7),
        "{pendulum:?}"
    );
    // From past the top's side it still finds the bottom, not the top.
    let far = modes(&Pendulum::new(l, g), &[2.5]).unwrap();
    assert!(far.equilibrium[0].abs() < 1e-7, "{far:?}");
    // The undamped natural frequency, whatever the damper.
    let (m, c, k) = (2.0, 0.6, 50.0);
    let spring = modes(&MassSpringDamper { m, c, k }, &[0.1]).unwrap();
    assert!(close(spring.omegas[0], (k / m).sqrt(), 1e-7), "{spring:?}");
    // Two coordinates: ω² = k/m and 3k/m.
    let chain = modes(
        &Chain {
            m: 2.0,
            k: 8.0,
            coupling_sign: 1.0,
        },
        &[0.3, -0.1],
    )
    .unwrap();
    assert!(close(chain.omegas[0], 2.0, 1e-7), "{chain:?}");
    assert!(close(chain.omegas[1], 12f64.sqrt(), 1e-7), "{chain:?}");
    let two = modes(&TwoOscillators, &[0.1, 0.2]).unwrap();
    assert!(close(two.omegas[0], 1.0, 1e-7) && close(two.omegas[1], 2.0, 1e-7));
    // Gravity upward: the bottom is a maximum of V; no potential: neutral. Nothing oscillates.
    assert!(modes(&Pendulum::new(l, -g), &[0.0]).is_none());
    assert!(modes(&Free, &[0.0]).is_none());
}

#[test]
fn correct_equations_pass() {
    let pendulum = small_oscillation(&Pendulum::new(0.5, 9.81), &[0.4]).unwrap();
    assert!(pendulum.passed, "{pendulum:?}");
    assert!(pendulum.value < 1e-6, "{pendulum:?}");
    let expected = 2.0 * PI * (0.5f64 / 9.81).sqrt();
    assert!(
        pendulum
            .detail()
            .contains(&format!("T = 2π/ω = {} s", fixed(expected))),
        "{}",
        pendulum.detail()
    );
    let damped = small_oscillation(
        &MassSpringDamper {
            m: 2.0,
            c: 0.6,
            k: 50.0,
        },
        &[0.1],
    )
    .unwrap();
    assert!(damped.passed, "{damped:?}");
    // σ = c / 2m = 0.15 1/s, measured on the motion.
    assert!(
        damped.detail().contains("σ = 0.15 1/s"),
        "{}",
        damped.detail()
    );
    let chain = Chain {
        m: 2.0,
        k: 8.0,
        coupling_sign: 1.0,
    };
    let both = small_oscillation(&chain, &[0.0, 0.0]).unwrap();
    assert!(both.passed, "{both:?}");
    assert!(both.detail().contains("2 modes"), "{}", both.detail());
}

#[test]
fn wrong_equations_fail() {
    let pendulum = Pendulum::new(0.5, 9.81);
    // Every sign of q'' wrong: the bottom repels, and the motion never comes back.
    let flipped = Broken {
        inner: &pendulum,
        factor: -1.0,
    };
    let check = small_oscillation(&flipped, &[0.4]).unwrap();
    assert!(!check.passed, "{check:?}");
    assert!(check.value.is_infinite(), "{check:?}");
    // A wrong factor (a rod's m L²/3 where m L²/2 belongs, say): the period is off by
    // 1 − 1/√1.5.
    let scaled = Broken {
        inner: &pendulum,
        factor: 1.5,
    };
    let check = small_oscillation(&scaled, &[0.4]).unwrap();
    assert!(!check.passed, "{check:?}");
    assert!(
        close(check.value, 1.0 - 1.5f64.sqrt().recip(), 1e-5),
        "{check:?}"
    );
    // The kinetic energy wrong instead (twice the true one): now the reference is off, its
    // period √2 times too long.
    let heavy = Pendulum {
        kinetic_factor: 1.0,
        ..Pendulum::new(0.5, 9.81)
    };
    let check = small_oscillation(&heavy, &[0.4]).unwrap();
    assert!(!check.passed, "{check:?}");
    assert!(
        close(check.value, 1.0 - 2f64.sqrt().recip(), 1e-5),
        "{check:?}"
    );
    // A sign error in one coupling term of two coordinates: each mode's period is wrong.
    let chain = Chain {
        m: 2.0,
        k: 8.0,
        coupling_sign: -1.0,
    };
    let check = small_oscillation(&chain, &[0.0, 0.0]).unwrap();
    assert!(!check.passed, "{check:?}");
    // Damped equations with their stiffness off by 10 %.
    let damper = MassSpringDamper {
        m: 2.0,
        c: 0.6,
        k: 50.0,
    };
    let stiff = Broken {
        inner: &damper,
        factor: 1.1,
    };
    let check = small_oscillation(&stiff, &[0.1]).unwrap();
    assert!(!check.passed, "{check:?}");
}

#[test]
fn checks_that_do_not_apply() {
    // More than one coordinate with dampers, a system that gains energy, too much damping.
    let pumping = MassSpringDamper {
        m: 1.0,
        c: -0.1,
        k: 1.0,
    };
    assert!(small_oscillation(&pumping, &[0.1]).is_none());
    let overdamped = MassSpringDamper {
        m: 1.0,
        c: 30.0,
        k: 1.0,
    };
    assert!(small_oscillation(&overdamped, &[0.1]).is_none());
    assert!(small_oscillation(&Free, &[0.0]).is_none());
    assert!(small_oscillation(&Pendulum::new(0.5, -9.81), &[0.0]).is_none());
}
