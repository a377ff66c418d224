//! The period of the disc rolling inside the cylinder: the equation of the one coordinate
//! left derived in the answer, not asserted.
//!
//! By hand: the no-slip row and the distance row give ẏ = −x ẋ/y and
//! r θ̇ = ẋ (x² + y²)/(y (R − r)) = (R − r) ẋ/y on x² + y² = (R − r)². Then
//! T = ½ m (ẋ² + ẏ²) + ½ (m r²/2) θ̇² = ½ m ẋ² (R − r)²/y² + ¼ m (R − r)² ẋ²/y²
//!   = (3m/4) (R − r)² ẋ²/y², so M = (3m/2) (R − r)²/y²; V = m g y.
//! Along the motion dy/dx = −x/y: dM/dx = −3m (R − r)²/y³ · (−x/y) = 3m (R − r)² x/y⁴,
//! dV/dx = −m g x/y. Lagrange's equation M ẍ + ½ (dM/dx) ẋ² + dV/dx = 0 gives
//! (3m/(2y²)) (R − r)² ẍ = −(3m x/(2y⁴)) (R − r)² ẋ² + m g x/y.
//! At the bottom, x = 0, y = −(R − r): M = 3m/2, K = d²V/dx² = −m g/y = m g/(R − r),
//! ω² = 2g/(3(R − r)), τ = 2π √(3(R − r)/(2g)).

use crate::support::{explain, problem};
use mbd_tutor::equations::Method;
use std::f64::consts::PI;

const M: f64 = 1.0;
const R_DISC: f64 = 0.1;
const R_CYL: f64 = 0.5;
const G: f64 = 9.81;

/// The answers of `answer --format json` by `method`.
fn answers(method: Method) -> Vec<serde_json::Value> {
    crate::support::answers_json(&problem("disc-in-cylinder"), method.name())
}

/// Answer 2 of the handout by `method`, in Markdown.
fn period_answer(method: Method) -> String {
    let text = explain(
        "disc-in-cylinder",
        &["--format", "markdown", "--method", method.name()],
    );
    let answers = &text[text.find("## Answers").expect("Answers")..];
    let start = answers.find("2. At $x = 0").expect("answer 2");
    let rest = &answers[start..];
    rest[..rest.find("\n## ").unwrap_or(rest.len())].to_string()
}

#[test]
fn every_method_gives_the_closed_form_period() {
    let expected = 2.0 * PI * (3.0 * (R_CYL - R_DISC) / (2.0 * G)).sqrt();
    for method in Method::ALL {
        let found = answers(method);
        let period = found[3]["value"].as_f64().expect("period");
        assert!(
            (period - expected).abs() <= 1e-6 * expected,
            "{}: {period} against {expected}",
            method.name()
        );
    }
}

/// The equation derived by hand (above) gives the first answer's ẍ at the start, released
/// from rest at x = 0.05 m: ẍ = (m g x/y)/M.
#[test]
fn the_derived_equation_gives_the_first_answer() {
    let x = 0.05f64;
    let y = -((R_CYL - R_DISC).powi(2) - x * x).sqrt();
    let mass = 1.5 * M * (R_CYL - R_DISC).powi(2) / (y * y);
    let xdd = M * G * x / y / mass;
    for method in Method::ALL {
        let found = answers(method)[0]["value"].as_f64().expect("x''");
        assert!(
            (found - xdd).abs() <= 1e-6 * xdd.abs(),
            "{}: {found} against {xdd}",
            method.name()
        );
    }
}

#[test]
fn the_energies_give_the_reduced_equation_line_by_line() {
    for method in [Method::Lagrange, Method::NewtonEuler, Method::MotionLaw] {
        let text = period_answer(method);
        for line in [
            // The dependent rates through ẋ.
            "\\dot{y} = -\\frac{x}{y} \\dot{x}",
            "\\dot{\\theta} = \\frac{1}{r y} (R - r) \\dot{x}",
            // T on the motion, x² + y² = (R − r)², and V.
            "x^{2} + y^{2} = \\left(R - r\\right)^{2}",
            "= \\frac{3 m}{4 y^{2}} (R - r)^{2} \\, \\dot{x}^{2}",
            "V = m g y",
            // y follows x, and the chain rule.
            "\\mathrm{d}y/\\mathrm{d}x = \\dot{y}/\\dot{x} = -\\frac{x}{y}",
            "3 m (R - r)^{2} \\frac{x}{y^{4}}",
            "-\\frac{m g x}{y}",
            // Lagrange's equation in x alone, then the equation free of the reactions.
            "M \\ddot{x} + \\frac{1}{2} \\frac{\\mathrm{d} M}{\\mathrm{d} x} \\, \\dot{x}^{2} + \\frac{\\mathrm{d} V}{\\mathrm{d} x} = 0",
            "\\frac{3 m}{2 y^{2}} (R - r)^{2} \\, \\ddot{x} = -\\frac{3 m x}{2 y^{4}} (R - r)^{2} \\dot{x}^{2} + \\frac{m g x}{y}",
            // Where the forms are singular.
            "wherever $y \\neq 0$",
            // ω² = V''/M at the bottom.
            "K = \\mathrm{d}^{2} V/\\mathrm{d} x^{2}",
            "M = \\frac{3 m}{2}, \\qquad K = \\frac{m g}{(R - r)}",
            "\\frac{2 g}{3 (R - r)} = 16.35",
            "\\tau = \\frac{2\\pi}{\\omega} = 1.55389",
        ] {
            assert!(text.contains(line), "{}: {line}\n{text}", method.name());
        }
        // Not asserted without the working.
        assert!(!text.contains("accelerations eliminated)"), "{text}");
    }
}

#[test]
fn kanes_row_for_the_independent_speed_is_the_reduced_equation() {
    let text = period_answer(Method::Kane);
    assert!(text.contains("is already row (1) of step 5"), "{text}");
    assert!(
        text.contains("\\frac{3 m}{2 y^{2}} (R - r)^{2} \\, \\ddot{x} = -\\frac{3 m x}{2 y^{4}} (R - r)^{2} \\dot{x}^{2} + \\frac{m g x}{y}"),
        "{text}"
    );
    // Row (1) of step 5 puts in the dependent accelerations, as the answer says.
    let all = explain(
        "disc-in-cylinder",
        &["--format", "markdown", "--method", "kane"],
    );
    assert!(
        all.contains("with the relations of the dependent rates differentiated"),
        "{all}"
    );
    assert!(!text.contains("\\frac{\\mathrm{d} M}"), "{text}");
}
