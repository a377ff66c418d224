//! The impact, as its own step after step 5: the rows of the chosen method integrated over
//! the instant of the impact (the impulse–momentum equations), the collision's law, the
//! rates just after, the impulses and the kinetic energy lost.

use super::row_names::row_heading_tex;
use crate::equations::{Derivation, Method};
use crate::numeric::ImpactMode as Mode;
use crate::problem::Problem;
use crate::render::text::Math;
use crate::render::{ImpactSection, ImpactStep};
use crate::symbolic::{
    eval, fixed, latex, latex_collected, latex_name, substitute, Expr, Symbol, Values,
};
use crate::{ImpactSolution, Worked};

/// The impact's section of the worked solution, or `None` without an impact.
pub fn section(worked: &Worked) -> Option<ImpactSection> {
    let impact = worked.impact.as_ref()?;
    let solution = &impact.solution;
    let problem = worked.derivation.model.problem;
    let method = worked.derivation.method;
    let mut steps = vec![text(intro(method, &worked.derivation.model))];
    match impact.equations.as_ref()? {
        Ok(derivation) => steps.extend(rows(derivation)),
        Err(e) => steps.push(text(format!(
            "The impulse–momentum equations could not be written out: {}",
            e.one_line()
        ))),
    }
    steps.extend(collision(
        problem,
        solution,
        &worked.derivation.model.values,
    ));
    steps.push(rates(problem, solution));
    steps.extend(reactions(solution));
    steps.push(text(energy(solution)));
    Some(ImpactSection { steps })
}

fn text(sentence: String) -> ImpactStep {
    ImpactStep {
        text: sentence,
        ..ImpactStep::default()
    }
}

/// What the chosen method's rows become over the impact, naming only what the problem has:
/// its finite forces, its reactions, its blows and its collision.
fn intro(method: Method, model: &crate::mechanics::Model) -> String {
    use crate::problem::{JointKind, LoadKind};
    let problem = model.problem;
    let mut finite = Vec::new();
    if problem.gravity.is_some() {
        finite.push(if problem.bodies.len() > 1 {
            "the weights"
        } else {
            "the weight"
        });
    }
    let loads = |f: fn(&LoadKind) -> bool| problem.loads.iter().any(|l| f(&l.kind));
    if loads(|k| matches!(k, LoadKind::Spring { .. } | LoadKind::JointSpring { .. })) {
        finite.push("the springs");
    }
    if loads(|k| matches!(k, LoadKind::Damper { .. } | LoadKind::JointDamper { .. })) {
        finite.push("the dampers");
    }
    if loads(|k| matches!(k, LoadKind::Force { .. } | LoadKind::Torque { .. })) {
        finite.push("the applied loads");
    }
    let finite = match finite.as_slice() {
        [] => "the finite forces give no impulse".to_string(),
        list => format!("the finite forces ({}) give no impulse", and_list(list)),
    };
    let impact = problem.impact.as_ref();
    let blows = impact.map_or(0, |i| i.impulses.len());
    let collision = impact.is_some_and(|i| i.collision.is_some());
    let mut sources = Vec::new();
    match blows {
        0 => {}
        1 => sources.push("the blow"),
        _ => sources.push("the blows"),
    }
    if collision {
        sources.push("the collision");
    }
    let sources = and_list(&sources);
    let reactions = model.sites.iter().any(|s| !s.reactions.is_empty());
    let each = if blows + usize::from(collision) == 1 {
        format!("{sources} its impulse")
    } else {
        format!("{sources} their impulses")
    };
    let reaction = if reactions {
        " each reaction its impulse (a hat marks an impulse),"
    } else {
        ""
    };
    let common = format!("The impact lasts an instant: the configuration does not change and {finite}. Integrated over that instant, each row of step 5 becomes an impulse–momentum equation: each second derivative becomes the jump Δ of its rate (after less before),{reaction} {each}, and the velocity terms drop out.");
    let pin = problem
        .joints
        .iter()
        .any(|j| j.kind == JointKind::Revolute && j.parent == crate::problem::BodyId::GROUND);
    let own = match method {
        Method::MotionLaw if !reactions => format!(" By the Motion Law, the angular impulse about a point equals the jump of the angular momentum about it; no reaction acts, so the jumps come from {sources} alone."),
        Method::MotionLaw => format!(" By the Motion Law, the angular impulse about a point equals the jump of the angular momentum about it; about a point where the impulsive reactions meet{} no reaction appears, and the jumps come from {sources} alone.", if pin { " (the fixed pin)" } else { "" }),
        Method::NewtonEuler => " By Newton–Euler, the linear impulse on every body equals the jump m Δv* of its momentum, and the angular impulse about its mass centre the jump of its angular momentum.".to_string(),
        Method::Kane => " By Kane's method, each generalized impulse (every impulse dotted with its partial velocity) equals the jump of the generalized momentum, the generalized inertia forces with each second derivative read as the jump of its rate.".to_string(),
        Method::Lagrange => format!(" By Lagrange's equations, the jump of each generalized momentum (the derivative of L with respect to a coordinate's rate) equals the generalized impulse of {sources} (each impulse dotted with its partial velocity){}.", if reactions { ", the multipliers read as the constraints' impulses" } else { "" }),
    };
    format!("{common}{own}")
}

/// `a`, `a and b`, `a, b and c`.
fn and_list(items: &[&str]) -> String {
    match items {
        [] => String::new(),
        [one] => (*one).to_string(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// `\hat{F}^{O}_{x}` from `F^{O}_{x}`: a hat on the leading letter or command.
fn hat(tex: &str) -> String {
    let end = match tex.strip_prefix('\\') {
        Some(rest) => {
            1 + rest
                .find(|c: char| !c.is_ascii_alphabetic())
                .unwrap_or(rest.len())
        }
        None => tex.chars().next().map_or(0, char::len_utf8),
    };
    format!("\\hat{{{}}}{}", &tex[..end], &tex[end..])
}

/// How an unknown of step 5 is written over the impact: a rate's jump (`\Delta \dot{q}`
/// for `\ddot{q}`), or an impulse (`\hat{F}^{O}_{x}` for `F^{O}_{x}`).
fn impulsive_tex(symbol: &Symbol) -> (String, String) {
    let shown = latex(&Expr::sym(symbol.clone()));
    let jump = match symbol {
        Symbol::Coord(name, 2) => format!("\\Delta {}", latex(&Expr::coord(name, 1))),
        Symbol::Speed(name, 1) => format!(
            "\\Delta {}",
            latex(&Expr::sym(Symbol::Speed(name.clone(), 0)))
        ),
        _ => hat(&shown),
    };
    (shown, jump)
}

/// Each row of the method's equations of the impulsive problem, rates zero, written in the
/// jumps and the impulses, `… = 0` as step 5 writes its rows.
fn rows(derivation: &Derivation) -> Vec<ImpactStep> {
    let system = &derivation.system;
    let mut names: Vec<(String, String)> = system.unknowns.iter().map(impulsive_tex).collect();
    // Longest first, so that no name is replaced inside a longer one.
    names.sort_by_key(|(shown, _)| std::cmp::Reverse(shown.len()));
    // The configuration does not change over the impact: a coordinate that is zero there
    // is zero in the rows (cos θ = 1 at θ = 0), as a course evaluates them.
    let problem = derivation.model.problem;
    let zero_at_impact = |name: &str| {
        (problem.coordinates.iter()).any(|c| c.name == name && c.initial == 0.0 && !c.dependent)
    };
    let still = |s: &Symbol| match s {
        Symbol::Coord(_, 1) | Symbol::Speed(_, 0) => Some(Expr::zero()),
        Symbol::Coord(name, 0) if zero_at_impact(name) => Some(Expr::zero()),
        _ => None,
    };
    let mut steps = Vec::new();
    let mut solved: Vec<String> = Vec::new();
    for (i, (a, b)) in system.a.iter().zip(&system.b).enumerate() {
        let mut row = -b.clone();
        let mut present = Vec::new();
        for (coefficient, symbol) in a.iter().zip(&system.unknowns) {
            let c = crate::symbolic::simplify(&substitute(coefficient, &still));
            if !c.is_zero() {
                present.push((c.clone(), symbol));
            }
            row = row + coefficient.clone() * Expr::sym(symbol.clone());
        }
        let row = crate::symbolic::simplify(&substitute(&row, &still));
        if row.is_zero() {
            continue;
        }
        if let [(c, symbol)] = present.as_slice() {
            // One jump in the row: solved for it in symbols.
            if matches!(symbol, Symbol::Coord(_, 2) | Symbol::Speed(_, 1)) {
                let rest = row.clone() - c.clone() * Expr::sym((*symbol).clone());
                let value = crate::symbolic::simplify(&(-rest / c.clone()));
                solved.push(format!("{} = {}", impulsive_tex(symbol).1, latex(&value)));
            }
        }
        let mut tex = latex_collected(&row);
        for (shown, jump) in &names {
            tex = tex.replace(shown.as_str(), jump);
        }
        let heading_tex = if i < derivation.rows.len() {
            Math(row_heading_tex(derivation, i))
        } else {
            Math::default()
        };
        steps.push(ImpactStep {
            text: format!("Row {},", i + 1),
            heading_tex,
            math_tex: Math(format!("{tex} = 0")),
        });
    }
    if !solved.is_empty() {
        steps.push(ImpactStep {
            text: "Each row with one jump, solved for it in symbols:".into(),
            heading_tex: Math::default(),
            math_tex: Math(solved.join(", \\qquad ")),
        });
    }
    steps
}

/// A number as the handout prints it, rounding-level values (against `scale`) as 0.
fn shown(x: f64, scale: f64) -> String {
    if x.abs() <= 1e-12 * scale.max(1.0) {
        "0".into()
    } else {
        fixed(x)
    }
}

fn vector_tex(v: &[f64; 3], planar: bool) -> String {
    let n = if planar { 2 } else { 3 };
    let scale = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let parts: Vec<String> = v[..n].iter().map(|x| shown(*x, scale)).collect();
    format!("\\left({}\\right)", parts.join(",\\ "))
}

/// The collision's law: restitution along the normal, then sticking or sliding.
fn collision(problem: &Problem, s: &ImpactSolution, values: &Values) -> Vec<ImpactStep> {
    let Some((name, p)) = &s.collision else {
        return Vec::new();
    };
    let Some(c) = problem.impact.as_ref().and_then(|i| i.collision.as_ref()) else {
        return Vec::new();
    };
    let on = problem.body_name(c.on);
    let planar = problem.dimension == crate::problem::Dimension::Two;
    let mut steps = vec![ImpactStep {
        text: format!(
            "The collision at {name}: along the normal, Newton's law of restitution makes the struck point's velocity relative to {on} after the impact −e times the one before (e = {}), which fixes the normal impulse.",
            fixed(eval(&c.restitution, values))
        ),
        math_tex: Math("v_{n}^{+} = -e\\, v_{n}^{-}".into()),
        ..ImpactStep::default()
    }];
    let law = match p.mode {
        Mode::Smooth => "The surface is smooth: the impulse has no tangential part.".to_string(),
        Mode::Stick => format!(
            "Stopping the point's slip needs a tangential impulse of {} N s, within μ times the normal impulse, {} N s: the point sticks, and leaves the impact without slipping.",
            fixed(p.tangential),
            fixed(c.friction.as_ref().map_or(0.0, |mu| eval(mu, values) * p.normal))
        ),
        Mode::Slide => format!(
            "Stopping the point's slip would need more than μ times the normal impulse: the point slides through the impact, and the tangential impulse is μ times the normal one, {} N s, against the slip.",
            fixed(p.tangential)
        ),
        Mode::Separate => "The blows carry the point off the surface: the collision gives no impulse.".to_string(),
    };
    steps.push(ImpactStep {
        text: format!(
            "{law} The collision's impulse on {}, in {on}'s unit vectors (N s):",
            problem.body_name(c.body)
        ),
        math_tex: Math(format!(
            "\\hat{{\\mathbf{{P}}}} = {},\\quad P_{{n}} = {}",
            vector_tex(&p.components, planar),
            fixed(p.normal)
        )),
        ..ImpactStep::default()
    });
    steps
}

fn rates(problem: &Problem, s: &ImpactSolution) -> ImpactStep {
    let parts: Vec<String> = (0..problem.coordinates.len())
        .map(|i| {
            let rate = latex(&problem.coordinate_expr(i, 1));
            format!(
                "{rate}^{{-}} = {},\\ {rate}^{{+}} = {}",
                shown(s.before[i], s.before[i].abs()),
                shown(s.after[i], s.before[i].abs())
            )
        })
        .collect();
    ImpactStep {
        text: "The rates just before (−) and just after (+) the impact; step 6 starts from those after it:".into(),
        math_tex: Math(parts.join(";\\quad ")),
        ..ImpactStep::default()
    }
}

fn reactions(s: &ImpactSolution) -> Vec<ImpactStep> {
    s.reactions
        .iter()
        .map(|(site, f, m)| {
            let name = latex_name(site);
            ImpactStep {
                text: format!("The impulse of the reaction at {site} (on the body the joint carries, in the unit vectors of the body it is mounted on; N s and N m s):"),
                math_tex: Math(format!(
                    "\\hat{{\\mathbf{{F}}}}^{{{name}}} = {},\\quad \\hat{{\\mathbf{{M}}}}^{{{name}}} = {}",
                    vector_tex(f, false),
                    vector_tex(m, false)
                )),
                ..ImpactStep::default()
            }
        })
        .collect()
}

fn energy(s: &ImpactSolution) -> String {
    let [before, after] = s.energy;
    let lost = before - after;
    let scale = before.abs().max(after.abs()).max(f64::MIN_POSITIVE);
    let change = if lost.abs() <= 1e-9 * scale {
        "the impact keeps it".to_string()
    } else if lost > 0.0 {
        format!("the impact takes {} J", fixed(lost))
    } else {
        format!("the blows give {} J", fixed(-lost))
    };
    format!(
        "The kinetic energy is {} J just before and {} J just after: {change}.",
        fixed(before),
        fixed(after)
    )
}
