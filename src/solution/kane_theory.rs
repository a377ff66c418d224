//! Kane's method said once, where step 5 first uses it, and only what applies to the
//! problem: the generalized active and inertia forces, with a body's inertia torque only
//! where some body has rotational inertia. Its letters for "a point" and "a body" are
//! letters the problem does not print, so that a body named B is never read into the sums.

use crate::equations::{Derivation, Method};
use crate::mechanics::is_particle;
use crate::render::context::KaneTheory;
use crate::render::text::{MarkupLine, Math};
use crate::symbolic::Expr;

/// The letters the formula's point may take, in order of preference.
const POINT_LETTERS: [&str; 4] = ["P", "Q", "K", "X"];

/// The letters the formula's body may take, in order of preference: none of the letters
/// its terms are written with (`R`, `T`, `I`, `N`, `m`, `v`), nor the total energy `E` of
/// step 6.
const BODY_LETTERS: [&str; 5] = ["B", "D", "H", "W", "J"];

/// The bold letters of a force and of a couple in Kane's sums, `R` and `T` in Kane and
/// Levinson, unless the handout prints them for something else: a point or a radius `R`,
/// and always `T`, the kinetic energy of step 6. Then `f`, and `M`, `τ` or `Γ`.
pub struct Letters {
    /// A force's, `\mathbf{R}` or `\mathbf{f}`.
    pub force: String,
    /// A couple's, `\mathbf{M}`, `\boldsymbol{\Gamma}` or `\boldsymbol{\tau}`.
    pub couple: String,
}

/// The letters of [`Letters`] for `derivation`'s handout.
pub fn letters(derivation: &Derivation) -> Letters {
    let model = &derivation.model;
    let problem = model.problem;
    let shown = super::shown_names::shown_names(model);
    // Every name printed as a letter, as the handout sets it in math.
    let mut printed: Vec<String> = (problem.bodies.iter().map(|b| b.name.as_str()))
        .chain(problem.joints.iter().map(|j| j.name.as_str()))
        .chain(problem.closures.iter().map(|j| j.name.as_str()))
        .chain(problem.points.iter().map(|p| p.name.as_str()))
        .chain(problem.constants.iter().map(|c| c.name.as_str()))
        .map(crate::symbolic::latex_name)
        .chain(shown.into_iter().map(|(_, letter)| letter))
        .collect();
    printed.extend(
        (derivation.system.unknowns.iter()).map(|u| crate::symbolic::latex(&Expr::sym(u.clone()))),
    );
    let period = (problem.questions.iter())
        .any(|q| matches!(q.kind, crate::problem::QuestionKind::Period { .. }));
    // A name is the letter itself, or the letter with an index or a superscript.
    let taken = |letter: &str| {
        printed.iter().any(|name| {
            name.strip_prefix(letter)
                .is_some_and(|rest| rest.is_empty() || rest.starts_with(['_', '^']))
        })
    };
    let force = if taken("R") {
        "\\mathbf{f}"
    } else {
        "\\mathbf{R}"
    };
    let couple = if !taken("M") {
        "\\mathbf{M}"
    } else if !taken("\\Gamma") || taken("\\tau") || period {
        // Γ before τ: τ is what a statement most often calls a drive's torque, and a
        // period.
        "\\boldsymbol{\\Gamma}"
    } else {
        "\\boldsymbol{\\tau}"
    };
    Letters {
        force: force.to_string(),
        couple: couple.to_string(),
    }
}

/// The definitions of `F_r` and `F^*_r` for Kane's handout (`None` for the other methods):
/// a problem of particles alone has no couples on bodies and no inertia torques, so their
/// terms are left out.
pub fn theory(derivation: &Derivation) -> Option<KaneTheory> {
    if derivation.method != Method::Kane {
        return None;
    }
    let model = &derivation.model;
    let rigid = model.order.iter().any(|&body| !is_particle(model, body));
    // The point's letter is one the problem does not use (a double pendulum's pin is P),
    // nor a letter the handout prints for a point named by a word (a contact's P).
    let shown = super::shown_names::shown_names(model);
    let free = |candidates: &[&'static str], taken: &str| -> String {
        let letters: Vec<&str> = (candidates.iter().copied())
            .filter(|l| *l != taken && shown.iter().all(|(_, letter)| letter != l))
            .collect();
        crate::problem::free_letter(model.problem, &letters)
    };
    let x = free(&POINT_LETTERS, "");
    let b = free(&BODY_LETTERS, &x);
    let Letters {
        force: f,
        couple: t,
    } = letters(derivation);
    let couples = match rigid {
        true => format!(" + \\sum_{{{b}}} \\boldsymbol{{\\omega}}^{{{b}}}_r \\cdot {t}_{{{b}}}"),
        false => String::new(),
    };
    let couple_words = match rigid {
        true => format!(" and ${t}_{b}$ a couple on body ${b}$"),
        false => String::new(),
    };
    let active = format!("F_r = \\sum_{{{x}}} \\mathbf{{v}}^{{{x}}}_r \\cdot {f}_{{{x}}}{couples}");
    let (forces_tex, note) = if rigid {
        (
            format!("{active}, \\qquad F^{{*}}_r = \\sum_{{{b}}} \\left(\\mathbf{{v}}^{{{b}^*}}_r \\cdot {f}^{{*}}_{{{b}}} + \\boldsymbol{{\\omega}}^{{{b}}}_r \\cdot {t}^{{*}}_{{{b}}}\\right),"),
            format!("with ${f}_{x}$ a force applied at the point ${x}$, ${t}_{b}$ a couple on body ${b}$, ${f}^{{*}}_{{{b}}} = -m_{b}\\,\\mathbf{{a}}^{{{b}^*}}$ and ${t}^{{*}}_{{{b}}} = -\\mathbf{{I}}^{{{b}}} \\cdot \\boldsymbol{{\\alpha}}^{{{b}}} - \\boldsymbol{{\\omega}}^{{{b}}} \\times \\mathbf{{I}}^{{{b}}} \\cdot \\boldsymbol{{\\omega}}^{{{b}}}$."),
        )
    } else {
        (
            format!("F_r = \\sum_{{{x}}} \\mathbf{{v}}^{{{x}}}_r \\cdot {f}_{{{x}}}, \\qquad F^{{*}}_r = \\sum_{{{b}}} \\mathbf{{v}}^{{{b}^*}}_r \\cdot {f}^{{*}}_{{{b}}},"),
            format!("with ${f}_{x}$ a force applied at the point ${x}$ and ${f}^{{*}}_{{{b}}} = -m_{b}\\,\\mathbf{{a}}^{{{b}^*}}$ the inertia force of particle ${b}$ (a particle has no inertia torque)."),
        )
    };
    Some(KaneTheory {
        forces_tex: Math::from(forces_tex),
        note: MarkupLine::from(note),
        velocity_partial_tex: Math::from(format!(
            "\\mathbf{{v}}^{{{b}^*}}_r = \\partial\\,{{}}^{{N}}\\mathbf{{v}}^{{{b}^*}} / \\partial u_r"
        )),
        omega_partial_tex: Math::from(format!(
            "\\boldsymbol{{\\omega}}^{{{b}}}_r = \\partial\\,{{}}^{{N}}\\boldsymbol{{\\omega}}^{{{b}}} / \\partial u_r"
        )),
        active_tex: Math::from(format!("{active},")),
        active_note: MarkupLine::from(format!(
            "where ${f}_{x}$ is a force applied at the point ${x}${couple_words}"
        )),
    })
}
