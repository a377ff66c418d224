//! Bodies spinning about their symmetry axis are written in the frame that does not spin
//! (Resal's): the heavy top's gyroscopic equations as a textbook derives them, checked
//! against the hand derivation written here, and no sine or cosine of a spin angle in any
//! of its handouts.

use mbd_tutor::equations::Method;
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::problem::load_file;
use mbd_tutor::symbolic::{eval, Symbol, Values};

/// The heavy top about its tip O in the frame A after precession ψ and nutation θ, with
/// I₁ = I_t + m h² (the transverse moment about O) and ω₃ = φ̇ + ψ̇ cos θ:
/// - â_x: I₁ θ̈ = m g h sin θ + (I₁ − I₃) ψ̇² sin θ cos θ − I₃ φ̇ ψ̇ sin θ;
/// - â_y: I₁ (ψ̈ sin θ + 2 ψ̇ θ̇ cos θ) = I₃ θ̇ (φ̇ + ψ̇ cos θ);
/// - â_z: I₃ (φ̈ + ψ̈ cos θ − ψ̇ θ̇ sin θ) = 0.
fn by_hand(v: &Values) -> [f64; 3] {
    let c = |n: &str| v.get(&Symbol::Const(n.into()));
    let q = |n: &str, order: u8| v.get(&Symbol::Coord(n.into(), order));
    let (m, h, g, i3, it) = (c("m"), c("h"), c("g"), c("I3"), c("It"));
    let i1 = it + m * h * h;
    let (theta, dpsi, dtheta, dphi) = (q("theta", 0), q("psi", 1), q("theta", 1), q("phi", 1));
    let (ddpsi, ddtheta, ddphi) = (q("psi", 2), q("theta", 2), q("phi", 2));
    let (s, co) = theta.sin_cos();
    [
        m * g * h * s + (i1 - i3) * dpsi * dpsi * s * co - i3 * dphi * dpsi * s - i1 * ddtheta,
        i3 * dtheta * (dphi + dpsi * co) - i1 * (ddpsi * s + 2.0 * dpsi * dtheta * co),
        -i3 * (ddphi + ddpsi * co - dpsi * dtheta * s),
    ]
}

#[test]
fn the_heavy_tops_moments_about_its_tip_are_eulers_in_the_frame_that_does_not_spin() {
    let problem = load_file(&crate::support::problem("heavy-symmetric-top")).expect("problem");
    let derivation = derive(&problem, Method::MotionLaw, Purpose::Handout).expect("derivation");
    let rows = ["A.x", "A.y", "A.z"].map(|name| {
        derivation
            .rows
            .iter()
            .find(|row| {
                row.direction.as_ref().is_some_and(|d| d.name == name)
                    && row
                        .unknowns
                        .iter()
                        .all(|u| !matches!(u, Symbol::Unknown(_)))
            })
            .unwrap_or_else(|| panic!("no moment row along {name}"))
            .expression
            .clone()
    });
    let mut random = crate::support::Lcg(7);
    for _ in 0..20 {
        let mut values = Values::new();
        for c in &problem.constants {
            values.set(Symbol::Const(c.name.as_str().into()), c.value);
        }
        for (i, _) in problem.coordinates.iter().enumerate() {
            for order in 0..3 {
                values.set(problem.coordinate_symbol(i, order), 2.0 * random.next());
            }
        }
        let hand = by_hand(&values);
        for (k, row) in rows.iter().enumerate() {
            let got = eval(row, &values);
            // A row is written `… = 0` with either sign.
            let err = (got - hand[k]).abs().min((got + hand[k]).abs());
            assert!(
                err <= 1e-12 * (1.0 + hand[k].abs()),
                "row along A.{k}: {got} against {} by hand",
                hand[k]
            );
        }
    }
}

#[test]
fn no_handout_of_the_heavy_top_has_a_sine_or_cosine_of_its_spin() {
    for method in ["motion-law", "newton-euler", "kane"] {
        let markdown = crate::support::explain("heavy-symmetric-top", &["--method", method]);
        for spin in ["s_{\\phi}", "c_{\\phi}", "\\sin(\\phi)", "\\cos(\\phi)"] {
            assert!(!markdown.contains(spin), "{method}: {spin} in the handout");
        }
        assert!(
            markdown.contains("Resal's frame"),
            "{method}: step 1 does not say which frame"
        );
    }
}
