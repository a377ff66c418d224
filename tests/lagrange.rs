//! Lagrange's equations against a hand derivation (the double pendulum of rods: T, V, each
//! ∂L/∂q̇ and the two equations), its multipliers against the reactions Newton–Euler finds
//! (the four-bar's closure, the rolling coin's floor), and its q'' against the other three
//! methods at random states of the validation problems.

use mbd_tutor::equations::{
    coordinate_terms, energy_terms, inertia_terms, lagrange_potential, Method,
};
use mbd_tutor::numeric::{Compiled, StateSolution, System};
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::problem::{load_file, Problem};
use mbd_tutor::symbolic::{eval, Symbol, Values};

use crate::support::Lcg;

/// The double pendulum's constants as its file gives them.
const M1: f64 = 1.2;
const L1: f64 = 0.6;
const M2: f64 = 0.8;
const L2: f64 = 0.4;
const G: f64 = 9.81;

/// The double pendulum by hand. A's centre is L1/2 from O, B's is L1 â + (L2/2) b̂ with
/// b̂ at q1 + q2, so
/// v_A*² = (L1/2)² q̇1², v_B*² = L1² q̇1² + (L2/2)² w² + L1 L2 q̇1 w cos q2 (w = q̇1 + q̇2),
/// T = ½ m1 v_A*² + ½ (m1 L1²/12) q̇1² + ½ m2 v_B*² + ½ (m2 L2²/12) w²,
/// V = −m1 g (L1/2) cos q1 − m2 g (L1 cos q1 + (L2/2) cos(q1 + q2)).
#[derive(Clone, Copy)]
struct ByHand {
    q: [f64; 2],
    u: [f64; 2],
    a: [f64; 2],
}

impl ByHand {
    fn kinetic(&self) -> f64 {
        let ([_, q2], [u1, u2]) = (self.q, self.u);
        let w = u1 + u2;
        let va2 = (L1 / 2.0).powi(2) * u1 * u1;
        let vb2 = L1 * L1 * u1 * u1 + (L2 / 2.0).powi(2) * w * w + L1 * L2 * u1 * w * q2.cos();
        0.5 * M1 * va2
            + 0.5 * (M1 * L1 * L1 / 12.0) * u1 * u1
            + 0.5 * M2 * vb2
            + 0.5 * (M2 * L2 * L2 / 12.0) * w * w
    }

    fn potential(&self) -> f64 {
        let [q1, q2] = self.q;
        -M1 * G * L1 / 2.0 * q1.cos() - M2 * G * (L1 * q1.cos() + L2 / 2.0 * (q1 + q2).cos())
    }

    /// ∂T/∂q̇1 and ∂T/∂q̇2 (L2²/4 + L2²/12 = L2²/3).
    fn momenta(&self) -> [f64; 2] {
        let ([_, q2], [u1, u2]) = (self.q, self.u);
        let w = u1 + u2;
        let c = L1 * L2 / 2.0 * q2.cos();
        [
            M1 * L1 * L1 / 3.0 * u1 + M2 * (L1 * L1 * u1 + L2 * L2 / 3.0 * w + c * (2.0 * u1 + u2)),
            M2 * (L2 * L2 / 3.0 * w + c * u1),
        ]
    }

    /// d/dt of the momenta.
    fn momentum_rates(&self) -> [f64; 2] {
        let ([_, q2], [u1, u2], [a1, a2]) = (self.q, self.u, self.a);
        let (c, s) = (L1 * L2 / 2.0 * q2.cos(), L1 * L2 / 2.0 * q2.sin());
        [
            M1 * L1 * L1 / 3.0 * a1
                + M2 * (L1 * L1 * a1 + L2 * L2 / 3.0 * (a1 + a2) + c * (2.0 * a1 + a2)
                    - s * (2.0 * u1 + u2) * u2),
            M2 * (L2 * L2 / 3.0 * (a1 + a2) + c * a1 - s * u1 * u2),
        ]
    }

    /// ∂T/∂q1 and ∂T/∂q2.
    fn kinetic_partials(&self) -> [f64; 2] {
        let ([_, q2], [u1, u2]) = (self.q, self.u);
        [0.0, -M2 * L1 * L2 / 2.0 * u1 * (u1 + u2) * q2.sin()]
    }

    /// ∂V/∂q1 and ∂V/∂q2.
    fn potential_partials(&self) -> [f64; 2] {
        let [q1, q2] = self.q;
        [
            M1 * G * L1 / 2.0 * q1.sin() + M2 * G * (L1 * q1.sin() + L2 / 2.0 * (q1 + q2).sin()),
            M2 * G * L2 / 2.0 * (q1 + q2).sin(),
        ]
    }

    /// The q'' of d/dt(∂T/∂q̇) − ∂T/∂q + ∂V/∂q = 0, by Cramer's rule on the mass matrix.
    fn accelerations(&self) -> [f64; 2] {
        let at = |a: [f64; 2]| {
            let by_hand = ByHand { a, ..*self };
            let (p, t, v) = (
                by_hand.momentum_rates(),
                by_hand.kinetic_partials(),
                by_hand.potential_partials(),
            );
            [p[0] - t[0] + v[0], p[1] - t[1] + v[1]]
        };
        let rest = at([0.0, 0.0]);
        let (c1, c2) = (at([1.0, 0.0]), at([0.0, 1.0]));
        let m = [
            [c1[0] - rest[0], c2[0] - rest[0]],
            [c1[1] - rest[1], c2[1] - rest[1]],
        ];
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        [
            (-rest[0] * m[1][1] + rest[1] * m[0][1]) / det,
            (-rest[1] * m[0][0] + rest[0] * m[1][0]) / det,
        ]
    }
}

fn values_of(problem: &Problem, hand: &ByHand) -> Values {
    let mut values = Values::new();
    for c in &problem.constants {
        values.set(Symbol::Const(c.name.as_str().into()), c.value);
    }
    for i in 0..2 {
        values.set(problem.coordinate_symbol(i, 0), hand.q[i]);
        values.set(problem.coordinate_symbol(i, 1), hand.u[i]);
        values.set(problem.coordinate_symbol(i, 2), hand.a[i]);
    }
    values
}

fn near(got: f64, want: f64, what: &str) {
    assert!(
        (got - want).abs() <= 1e-10 * want.abs().max(1.0),
        "{what}: {got} against {want} by hand"
    );
}

#[test]
fn the_double_pendulums_energies_derivatives_and_equations_are_the_hand_derivations() {
    let problem = load_file(&crate::support::problem("double-pendulum-rods")).expect("problem");
    let derivation = derive(&problem, Method::Lagrange, Purpose::Handout).expect("derives");
    let model = &derivation.model;
    let terms = coordinate_terms(model, &derivation.actions, true).expect("terms");
    let kinetic = mbd_tutor::symbolic::add(energy_terms(model).iter().map(|b| b.kinetic()));
    let potential = lagrange_potential(model);
    let compiled = Compiled::new(&derive(&problem, Method::Lagrange, Purpose::Rows).expect("rows"));
    let mut random = Lcg(59);
    for _ in 0..25 {
        let mut next = || 2.0 * random.next();
        let hand = ByHand {
            q: [next(), next()],
            u: [next(), next()],
            a: [next(), next()],
        };
        let values = values_of(&problem, &hand);
        near(eval(&kinetic, &values), hand.kinetic(), "T");
        near(eval(&potential, &values), hand.potential(), "V");
        for (r, t) in terms.iter().enumerate() {
            near(eval(&t.momentum, &values), hand.momenta()[r], "∂T/∂q̇");
            near(
                eval(&t.momentum_rate, &values),
                hand.momentum_rates()[r],
                "d/dt ∂T/∂q̇",
            );
            near(
                eval(&t.kinetic_partial, &values),
                hand.kinetic_partials()[r],
                "∂T/∂q",
            );
            near(
                eval(&t.potential_partial, &values),
                hand.potential_partials()[r],
                "∂V/∂q",
            );
            near(eval(&t.generalized_force, &values), 0.0, "Q");
        }
        // The rows as written for the worked solution: d/dt(∂L/∂q̇) − ∂L/∂q = 0 by hand.
        for (r, row) in derivation.rows.iter().take(2).enumerate() {
            let by_hand = hand.momentum_rates()[r] - hand.kinetic_partials()[r]
                + hand.potential_partials()[r];
            near(-eval(&row.expression, &values), by_hand, "equation");
        }
        let solved = compiled.solve(0.0, &hand.q, &hand.u).expect("solves");
        let want = hand.accelerations();
        near(solved.accelerations[0], want[0], "q1''");
        near(solved.accelerations[1], want[1], "q2''");
    }
}

/// The solution of `problem` by `method` at a state near the initial one, on the constraints.
fn solve_near(problem: &Problem, method: Method, random: &mut Lcg) -> Option<StateSolution> {
    let compiled = Compiled::new(&derive(problem, method, Purpose::Rows).expect("derives"));
    let (mut q, mut rates) = random.state_near(problem, 0.2);
    compiled.assemble(0.0, &mut q, &mut rates).ok()?;
    Some(compiled.solve(0.0, &q, &rates).expect("solves"))
}

/// Lagrange's multipliers at `site` against the reaction Newton–Euler finds there.
fn multipliers_are_reactions(name: &str, site: &str) {
    let problem = load_file(&crate::support::problem(name)).expect("problem");
    let mut checked = 0;
    for seed in 1..8 {
        let (mut a, mut b) = (Lcg(seed), Lcg(seed));
        let (Some(lagrange), Some(newton)) = (
            solve_near(&problem, Method::Lagrange, &mut a),
            solve_near(&problem, Method::NewtonEuler, &mut b),
        ) else {
            continue;
        };
        let find = |s: &StateSolution| {
            s.reactions
                .iter()
                .find(|(n, _, _)| n == site)
                .map(|(_, f, m)| (*f, *m))
                .unwrap_or_else(|| panic!("{name}: no reaction at {site}"))
        };
        let ((f1, m1), (f2, m2)) = (find(&lagrange), find(&newton));
        let scale = f2.iter().chain(&m2).fold(1.0f64, |s, x| s.max(x.abs()));
        for (x, y) in f1.iter().chain(&m1).zip(f2.iter().chain(&m2)) {
            assert!(
                (x - y).abs() <= 1e-9 * scale,
                "{name} at {site}: {x} against {y}"
            );
        }
        checked += 1;
    }
    assert!(checked >= 3, "{name}: only {checked} states");
}

#[test]
fn the_four_bars_multipliers_are_its_closure_reaction_by_newton_euler() {
    multipliers_are_reactions("four-bar", "R");
}

#[test]
fn the_rolling_coins_multipliers_are_the_floors_contact_force_by_newton_euler() {
    multipliers_are_reactions("rolling-coin", "floor");
}

#[test]
fn lagrange_agrees_with_the_other_methods_on_the_validation_problems() {
    for name in [
        "all-joints-3d",
        "atwood-massive-pulley",
        "block-on-rough-cart",
        "box-on-two-rough-edges",
        "double-pendulum-particles-absolute",
        "ladder-on-rough-wall-and-floor",
        "pendulum-on-light-slider",
        "planetary-gear-train",
        "sleeping-top",
    ] {
        let path = std::path::Path::new("problems/validation").join(format!("{name}.json"));
        let problem = load_file(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
        for method in [Method::Kane, Method::NewtonEuler, Method::MotionLaw] {
            let mut checked = 0;
            for seed in 1..6 {
                let (mut a, mut b) = (Lcg(seed), Lcg(seed));
                let (Some(lagrange), Some(other)) = (
                    solve_near(&problem, Method::Lagrange, &mut a),
                    solve_near(&problem, method, &mut b),
                ) else {
                    continue;
                };
                let scale = other
                    .accelerations
                    .iter()
                    .fold(1.0f64, |s, x| s.max(x.abs()));
                for (x, y) in lagrange.accelerations.iter().zip(&other.accelerations) {
                    assert!(
                        (x - y).abs() <= 1e-9 * scale,
                        "{name}: {x} by Lagrange, {y} by {}",
                        method.name()
                    );
                }
                checked += 1;
            }
            assert!(checked > 0, "{name}: no state solved by {}", method.name());
        }
    }
}

/// For the numbers, `d/dt(∂T/∂q̇_r) − ∂T/∂q_r` is formed from the accelerations of step 4
/// (`Σ m a*·∂v*/∂q̇_r + (I·α + ω×I·ω)·∂ω/∂q̇_r`); the worked solution differentiates `T`.
/// The two must be the same function of q, q̇ and q̈ at every state, for planar and spatial
/// problems, trees and closed loops.
#[test]
fn the_kinetic_terms_for_the_numbers_are_those_of_differentiating_t() {
    for name in [
        "problems/double-pendulum-rods.json",
        "problems/four-bar.json",
        "problems/rolling-coin.json",
        "problems/validation/all-joints-3d.json",
        "problems/validation/sleeping-top.json",
        "problems/validation/spherical-chain-3.json",
    ] {
        let problem = load_file(std::path::Path::new(name)).unwrap_or_else(|e| panic!("{e}"));
        let derivation = derive(&problem, Method::Lagrange, Purpose::Rows).expect("derives");
        let model = &derivation.model;
        assert!(model.speeds.is_none(), "{name}: declared speeds");
        let fast = inertia_terms(model, derivation.inertia());
        let by_differentiating =
            coordinate_terms(model, &derivation.actions, false).expect("terms");
        let mut random = Lcg(7);
        for _ in 0..5 {
            let mut values = Values::new();
            for c in &problem.constants {
                values.set(Symbol::Const(c.name.as_str().into()), c.value);
            }
            for i in 0..problem.coordinates.len() {
                for order in 0..3 {
                    values.set(problem.coordinate_symbol(i, order), random.next());
                }
            }
            for (r, ((translation, rotation), t)) in
                fast.iter().zip(&by_differentiating).enumerate()
            {
                let got = -(eval(translation, &values) + eval(rotation, &values));
                let want = eval(&t.momentum_rate, &values) - eval(&t.kinetic_partial, &values);
                assert!(
                    (got - want).abs() <= 1e-9 * want.abs().max(1.0),
                    "{name}, coordinate {r}: {got} from the accelerations, {want} by differentiating T"
                );
            }
        }
    }
}

/// The spherical chain's derivatives of `T` are too long to write out, so the worked
/// solution names them and writes its rows from the accelerations of step 4. Those rows,
/// solved, must give the q'' of Kane's method and of Lagrange's own rows for the numbers
/// at states near the initial one.
#[test]
fn the_spherical_chains_worked_rows_give_the_other_methods_accelerations() {
    let path = std::path::Path::new("problems/validation/spherical-chain-3.json");
    let problem = load_file(path).unwrap_or_else(|e| panic!("{e}"));
    let handout = derive(&problem, Method::Lagrange, Purpose::Handout).expect("derives");
    assert!(
        !handout.lagrange_terms.is_empty() && handout.lagrange_terms.iter().all(|t| !t.written),
        "the derivatives of T were formed"
    );
    let worked = Compiled::new(&handout);
    for method in [Method::Kane, Method::Lagrange] {
        let other = Compiled::new(&derive(&problem, method, Purpose::Rows).expect("derives"));
        let mut random = Lcg(11);
        for _ in 0..4 {
            let (q, rates) = random.state_near(&problem, 0.3);
            let got = worked.solve(0.0, &q, &rates).expect("solves");
            let want = other.solve(0.0, &q, &rates).expect("solves");
            let scale = want
                .accelerations
                .iter()
                .fold(1.0f64, |s, x| s.max(x.abs()));
            for (x, y) in got.accelerations.iter().zip(&want.accelerations) {
                assert!(
                    (x - y).abs() <= 1e-9 * scale,
                    "{x} by the worked rows, {y} by {}",
                    method.name()
                );
            }
        }
    }
}
