//! Step 5's friction: at each friction site, the textbook's process in words and numbers.
//! Where the site slides, the sliding law in place of the no-slip row; where it is at rest,
//! the assumption that it sticks, the solution, the check that the friction force is at most μ times the normal force and, when the check
//! fails, the solution again with sliding friction.

use crate::equations::Derivation;
use crate::numeric::{FrictionMode as Mode, SiteState};
use crate::plan::Sum;
use crate::render::context::{FrictionStep, FrictionView};
use crate::render::text::Math;
use crate::symbolic::{fixed, latex, Expr};

/// One view per friction site of `derivation`, from its state in `friction` (the solution
/// at the initial state).
///
/// `stick_rows` holds step 5's simplified row for each row of the derivation as it was
/// before the sliding law took a no-slip row's place: the no-slip condition written out
/// where the assumption that the contact sticks uses it.
pub fn views(
    derivation: &Derivation,
    friction: &[SiteState],
    stick_rows: &[String],
) -> Vec<FrictionView> {
    let model = &derivation.model;
    model
        .constraints
        .friction
        .iter()
        .zip(friction)
        .map(|(site, state)| {
            let names: Vec<String> = site
                .stick
                .iter()
                .map(|r| latex(&Expr::sym(r.unknown.clone())))
                .collect();
            // A rough slider in 3D has two normal components: |N| is their root sum of squares.
            let normal_names: Vec<String> = site
                .normal
                .iter()
                .map(|n| latex(&Expr::sym(n.clone())))
                .collect();
            let (normal, size) = match &normal_names[..] {
                [one] => (one.clone(), format!("\\left|{one}\\right|")),
                many => (magnitude_tex(many), magnitude_tex(many)),
            };
            let slider = site.site < model.problem.joints.len() + model.problem.closures.len();
            // A slider is called by its body's word where it has one (the collar).
            let child = model.sites[site.site].child;
            let words = super::joint_words::body_words(model.problem, child);
            let noun = match words.strip_prefix("the ") {
                Some(word) if slider && !word.contains(' ') => word,
                _ if slider => "slider",
                _ => "contact",
            };
            // Only a disc rolls: a point that touches a plane (a ladder's foot) sticks.
            let disc = match model.sites[site.site].kind {
                crate::mechanics::SiteKind::Contact(k) => matches!(
                    model.problem.constraints.get(k).map(|c| &c.kind),
                    Some(crate::problem::ConstraintKind::Rolling { .. })
                ),
                _ => false,
            };
            let rows: Vec<String> = site
                .stick
                .iter()
                .filter_map(|r| {
                    derivation
                        .rows
                        .iter()
                        .position(
                            |row| matches!(&row.sum, Sum::Constraint { name } if *name == r.name),
                        )
                        .map(|i| format!("({})", i + 1))
                })
                .collect();
            let rows = rows.join(" and ");
            let mu = latex(&site.coefficient);
            // In the plane, a sliding contact's no-slip row gave way to the sliding law in
            // step 5 (`super::sliding_rows`): the condition is written here where it is used.
            let replaced =
                state.mode == Mode::Slip && site.normal.len() == 1 && state.friction() > 0.0;
            let written = site
                .stick
                .iter()
                .filter_map(|r| {
                    let i = derivation.rows.iter().position(
                        |row| matches!(&row.sum, Sum::Constraint { name } if *name == r.name),
                    )?;
                    stick_rows.get(i).filter(|t| !t.is_empty()).cloned()
                })
                .collect::<Vec<_>>()
                .join(", \\qquad ");
            let (tangential, n) = state
                .failed_stick
                .as_ref()
                .map_or((&state.tangential[..], state.normal), |f| {
                    (&f.tangential[..], f.normal)
                });
            let stick = Stick {
                row_tex: written,
                replaced,
                needed: super::friction_needed::needed(derivation, site, tangential, n),
            };
            let steps = steps(
                state,
                &names,
                (&normal, &size, noun),
                &rows,
                (&mu, disc),
                &stick,
            );
            FrictionView {
                site: super::force_labels::place(&site.name),
                coefficient: fixed(state.coefficient),
                steps,
            }
        })
        .collect()
}

fn step(text: impl Into<String>, math_tex: impl Into<String>) -> FrictionStep {
    FrictionStep {
        text: text.into(),
        math_tex: Math::from(math_tex.into()),
    }
}

/// The forces as equations, `F_x = -13.734\ \mathrm{N}, \quad F_y = 68.67\ \mathrm{N}`.
fn forces(names: &[String], tangential: &[f64], normal_name: &str, normal: f64) -> String {
    let mut parts: Vec<String> = names
        .iter()
        .zip(tangential)
        .map(|(n, v)| format!("{n} = {}\\ \\mathrm{{N}}", fixed(*v)))
        .collect();
    parts.push(format!("{normal_name} = {}\\ \\mathrm{{N}}", fixed(normal)));
    parts.join(", \\quad ")
}

/// `|F|`: the component's absolute value in 2D, the root of the squares in 3D.
fn magnitude_tex(names: &[String]) -> String {
    match names {
        [one] => format!("\\left|{one}\\right|"),
        _ => format!(
            "\\sqrt{{{}}}",
            names
                .iter()
                .map(|n| format!("{{{n}}}^{{2}}"))
                .collect::<Vec<_>>()
                .join(" + ")
        ),
    }
}

/// The sliding law for each tangential component: `F_x = -\mu F_y`.
fn law_tex(names: &[String], normal: &str, mu: &str, state: &SiteState) -> String {
    let force = state.friction().max(f64::MIN_POSITIVE);
    let sign = if state.normal < 0.0 { -1.0 } else { 1.0 };
    if let ([name], [t]) = (names, &state.tangential[..]) {
        if !normal.contains("\\sqrt") && state.friction() > 0.0 {
            // In the plane: the sizes, then the signs at this state, then the signed law.
            return super::sliding_rows::sized_law_tex(name, normal, mu, (t.signum(), sign));
        }
    }
    names
        .iter()
        .zip(&state.tangential)
        .map(|(name, t)| {
            let factor = sign * t / force;
            let factor_tex = match factor {
                f if (f - 1.0).abs() < 1e-12 => String::new(),
                f if (f + 1.0).abs() < 1e-12 => "-".to_string(),
                f => format!("{} \\, ", fixed(f)),
            };
            format!("{name} = {factor_tex}{mu} \\, {normal}")
        })
        .collect::<Vec<_>>()
        .join(", \\qquad ")
}

/// What the assumption that a contact sticks uses: its no-slip condition, whether step 5
/// printed the sliding law in its place, and the friction it needs in symbols.
struct Stick {
    /// The no-slip row, simplified, `… = 0`.
    row_tex: String,
    /// Whether step 5's row is the sliding law in its place.
    replaced: bool,
    /// The sticking solution in symbols, where it comes out short.
    needed: Option<super::friction_needed::Needed>,
}

fn steps(
    state: &SiteState,
    names: &[String],
    (normal, size, noun): (&str, &str, &str),
    rows: &str,
    (mu, disc): (&str, bool),
    stick: &Stick,
) -> Vec<FrictionStep> {
    let magnitude = magnitude_tex(names);
    let wheel = if disc {
        " (a wheel: that it rolls without slipping)"
    } else {
        ""
    };
    let check = |tangential: &[f64], n: f64, holds: bool| {
        let force: f64 = tangential.iter().map(|t| t * t).sum::<f64>().sqrt();
        format!(
            "{magnitude} = {}\\ \\mathrm{{N}} {} {mu} {size} = {} \\times {}\\ \\mathrm{{N}} = {}\\ \\mathrm{{N}}",
            fixed(force),
            if holds { "\\le" } else { ">" },
            fixed(state.coefficient),
            fixed(n.abs()),
            fixed(state.coefficient * n.abs())
        )
    };
    let solved = forces(names, &state.tangential, normal, state.normal);
    let slip_speed: f64 = state.slip.iter().map(|v| v * v).sum::<f64>().sqrt();
    let mut out = Vec::new();
    if state.mode == Mode::Slip && state.failed_stick.is_none() {
        let head = format!(
            "The {noun} slides at this state: its slip velocity, relative to the surface, is {} m/s, so the no-slip condition does not hold;",
            fixed(slip_speed),
        );
        // Where step 5 printed the sliding law as its row, it is referred to, not said again.
        match normal.contains("\\sqrt") {
            false => out.push(step(
                format!("{head} row {rows} above, the sliding law, stands in its place. Solved with it:"),
                solved,
            )),
            true => {
                out.push(step(
                    format!("{head} in place of row {rows} above, the sliding law:"),
                    law_tex(names, normal, mu, state),
                ));
                out.push(step("Solved with it:", solved));
            }
        }
        return out;
    }
    let first = state.failed_stick.as_ref();
    let (tangential, n) = first.map_or((&state.tangential[..], state.normal), |f| {
        (&f.tangential[..], f.normal)
    });
    if stick.replaced && !stick.row_tex.is_empty() {
        // Step 5 printed the sliding law as row (k): the no-slip condition is written here.
        out.push(step(
            format!("The {noun} is at rest relative to the surface at this state. Assume that it sticks{wheel}: its slip velocity then stays zero, and so does its derivative, the no-slip condition, which stands in place of row {rows} (the sliding law):"),
            stick.row_tex.clone(),
        ));
        out.push(step(
            "Solved with it and the other rows of step 5:",
            forces(names, tangential, normal, n),
        ));
    } else {
        out.push(step(
            format!("The {noun} is at rest relative to the surface at this state. Assume that it sticks{wheel}, so that the no-slip condition {rows} holds. Solved with it:"),
            forces(names, tangential, normal, n),
        ));
    }
    if let Some(needed) = &stick.needed {
        out.push(step(
            "In symbols, the same rows with every rate zero (at rest) give",
            needed.forces.clone(),
        ));
    }
    if state.shared {
        out.push(step(
            format!("Sticking here, the equations are one short: statics fixes only what the sticking contacts carry together, not how they share it. The split taken is the one that keeps every {noun} as far from slipping (the ratio of its friction force to μ times its normal force) as the others, so that the {noun}s stick if any split could hold them."),
            "",
        ));
    }
    if let Some(needed) = &stick.needed {
        out.push(step(
            "Friction can give that much only if it is at most μ times the normal force; in symbols:",
            needed.condition.clone(),
        ));
    }
    let check_words = match stick.needed {
        Some(_) => "In numbers:",
        None => "Check that friction can give that much, at most μ times the normal force:",
    };
    match first {
        None => {
            out.push(step(check_words, check(tangential, n, true)));
            out.push(step(
                format!("The check holds: the {noun} sticks, and the solution stands."),
                "",
            ));
        }
        Some(_) => {
            out.push(step(check_words, check(tangential, n, false)));
            let law = match stick.replaced && !stick.row_tex.is_empty() {
                true => {
                    format!("the sliding law, row {rows}, stands in place of the no-slip condition")
                }
                false => format!("row {rows} is replaced by the sliding law"),
            };
            out.push(step(
                format!("The check fails: friction cannot hold the {noun}, and it slips. Solve again with sliding friction, μ times the normal force, opposing the motion that would start (along the force that sticking needed): {law}"),
                law_tex(names, normal, mu, state),
            ));
            out.push(step("Solved with it (the values below):", solved));
        }
    }
    out
}
