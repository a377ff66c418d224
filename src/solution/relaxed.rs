//! A reaction asked of a joint by Lagrange's equations, derived as a course derives it: the
//! joint is let give way (or turn) along the component by an auxiliary coordinate that
//! violates the joint, zero in the motion; the reaction does work with it, and Lagrange's
//! equation of that coordinate, at zero coordinate and rate, gives the component.

use super::long::LONG_EQUATION;
use super::tex::{bodies_tex, vector_tex};
use crate::equations::Derivation;
use crate::mechanics::ReactionComponent;
use crate::plan::{Equation, Sum};
use crate::symbolic::{latex, latex_collected, latex_name, simplify, ComponentKind, Expr};
use crate::symbolic::{Symbol, Unknown};

/// What step 5 writes before a relaxed joint's row: the auxiliary coordinate in words
/// (markup), then its equation's terms, one line each.
pub struct Relaxed {
    /// The auxiliary coordinate, how the bodies move with it, and which force works.
    pub intro: String,
    /// The kinetic terms and the generalized force of the auxiliary coordinate.
    pub lines: Vec<String>,
}

/// The joint's name and the reaction component a relaxed joint's row (`u(O.Fx)`) brings
/// in; the multipliers of the closures and contacts it also holds are not what it is
/// written for. `None` for any other row.
pub(super) fn relaxed_reaction<'a>(
    derivation: &'a Derivation,
    row: &'a Equation,
) -> Option<(&'a str, &'a ReactionComponent)> {
    let model = &derivation.model;
    let Sum::Generalized { speed } = &row.sum else {
        return None;
    };
    let joint = speed.strip_prefix("u(")?.split('.').next()?;
    let (site, component) = row.unknowns.iter().find_map(|u| match u {
        Symbol::Unknown(Unknown::Reaction { site, component }) if &**site == joint => {
            Some((site, component))
        }
        _ => None,
    })?;
    let j = (model.problem.joints.iter()).position(|joint| joint.name.as_str() == &**site)?;
    let reaction = (model.sites[j].reactions.iter()).find(|c| c.component() == *component)?;
    Some((&**site, reaction))
}

/// The relaxed rows said in one paragraph with `row`: those of the same joint, the same
/// kind of component (forces or moments) and the same bodies, in the rows' order, each
/// with its row's index.
fn group<'a>(derivation: &'a Derivation, row: &Equation) -> Vec<(usize, &'a ReactionComponent)> {
    let Some((site, reaction)) = relaxed_reaction(derivation, row) else {
        return Vec::new();
    };
    let kind = reaction.kind;
    (derivation.rows.iter().enumerate())
        .filter(|(_, other)| other.free_body == row.free_body)
        .filter_map(|(i, other)| {
            let (s, c) = relaxed_reaction(derivation, other)?;
            (s == site && c.kind == kind).then_some((i, c))
        })
        .collect()
}

/// `a`, `a and b`, `a, b and c`.
fn listed(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// The words that let the joint of `members` give way, said once for all of them (the
/// first row of the group): the auxiliary coordinates, how the bodies move with them, and
/// which reactions then do work.
fn intro(
    derivation: &Derivation,
    row: &Equation,
    members: &[(usize, &ReactionComponent)],
) -> String {
    let model = &derivation.model;
    let Some((site, reaction)) = relaxed_reaction(derivation, row) else {
        return String::new();
    };
    let bodies = bodies_tex(derivation, &row.free_body);
    let point = latex_name(site);
    let xi = |i: usize| format!("\\xi_{{{}}}", i + 1);
    let xi_dot = |i: usize| format!("\\dot{{\\xi}}_{{{}}}", i + 1);
    let dirs: Vec<String> = (members.iter())
        .map(|(_, c)| vector_tex(model, &c.direction))
        .collect();
    let math = |items: Vec<String>| {
        listed(
            &items
                .into_iter()
                .map(|x| format!("${x}$"))
                .collect::<Vec<_>>(),
        )
    };
    let xis = math(members.iter().map(|&(i, _)| xi(i)).collect());
    let unknowns = math(
        members
            .iter()
            .map(|(_, c)| latex(&Expr::sym(c.unknown(site))))
            .collect(),
    );
    // The bodies' velocity: each rate along (or about) its direction.
    let gained = (members.iter().zip(&dirs))
        .map(|(&(i, _), d)| format!("{}\\, {}", xi_dot(i), super::tex::factor_of_product(d)))
        .collect::<Vec<_>>()
        .join(" + ");
    let [(first, _), ..] = members else {
        return String::new();
    };
    let one = members.len() == 1;
    let motion = match (reaction.kind, one) {
        (ComponentKind::Force, true) => {
            let (x, xd, d) = (xi(*first), xi_dot(*first), &dirs[0]);
            format!(
                "Let ${point}$ give way along ${d}$ by an auxiliary coordinate ${x}$, zero in the motion: every point of ${bodies}$ gains the velocity ${gained}$, so that $\\partial \\mathbf{{v}}^{{k^*}} / \\partial {xd} = {d}$ and $\\partial \\boldsymbol{{\\omega}}^{{k}} / \\partial {xd} = \\mathbf{{0}}$ for each body $k$ of ${bodies}$."
            )
        }
        (ComponentKind::Force, false) => format!(
            "Let ${point}$ give way along {} by auxiliary coordinates {xis}, zero in the motion: every point of ${bodies}$ gains the velocity ${gained}$, so that, for each $\\xi_{{i}}$ along its direction $\\hat{{\\mathbf{{e}}}}_{{i}}$, $\\partial \\mathbf{{v}}^{{k^*}} / \\partial \\dot{{\\xi}}_{{i}} = \\hat{{\\mathbf{{e}}}}_{{i}}$ and $\\partial \\boldsymbol{{\\omega}}^{{k}} / \\partial \\dot{{\\xi}}_{{i}} = \\mathbf{{0}}$ for each body $k$ of ${bodies}$.",
            math(dirs.clone())
        ),
        (ComponentKind::Moment, true) => {
            let (x, xd, d) = (xi(*first), xi_dot(*first), &dirs[0]);
            let dp = super::tex::factor_of_product(d);
            format!(
                "Let ${bodies}$ turn about ${point}$ by an auxiliary angle ${x}$ about ${d}$, zero in the motion: each of its bodies gains the angular velocity ${gained}$, so that $\\partial \\boldsymbol{{\\omega}}^{{k}} / \\partial {xd} = {d}$ and $\\partial \\mathbf{{v}}^{{k^*}} / \\partial {xd} = {dp} \\times \\mathbf{{r}}^{{{point} k^*}}$."
            )
        }
        (ComponentKind::Moment, false) => format!(
            "Let ${bodies}$ turn about ${point}$ by auxiliary angles {xis} about {}, zero in the motion: each of its bodies gains the angular velocity ${gained}$, so that, for each $\\xi_{{i}}$ about its axis $\\hat{{\\mathbf{{e}}}}_{{i}}$, $\\partial \\boldsymbol{{\\omega}}^{{k}} / \\partial \\dot{{\\xi}}_{{i}} = \\hat{{\\mathbf{{e}}}}_{{i}}$ and $\\partial \\mathbf{{v}}^{{k^*}} / \\partial \\dot{{\\xi}}_{{i}} = \\hat{{\\mathbf{{e}}}}_{{i}} \\times \\mathbf{{r}}^{{{point} k^*}}$.",
            math(dirs.clone())
        ),
    };
    let works = if one {
        let x = xi(*first);
        format!("The joint no longer holds along ${x}$, so {unknowns} does work as ${x}$ changes and enters its generalized force $Q_{{{x}}}$, with the other forces on ${bodies}$ from outside.")
    } else {
        format!("The joint no longer holds along them, so {unknowns} do work as they change, each in the generalized force $Q_{{\\xi_{{i}}}}$ of its own coordinate, with the other forces on ${bodies}$ from outside.")
    };
    // Where the motion is taken: said once, in the first of the relaxed rows' words.
    let relaxed_rows: Vec<usize> = (derivation.rows.iter().enumerate())
        .filter(|(_, r)| relaxed_reaction(derivation, r).is_some())
        .map(|(i, _)| i)
        .collect();
    let at = match (relaxed_rows.as_slice(), one) {
        ([_], true) => format!(
            " At ${} = {} = 0$ the velocities and accelerations are those of step 4.",
            xi(*first),
            xi_dot(*first)
        ),
        ([head, ..], _) if head == first => " At zero auxiliary coordinates and rates, here and in the rows below, the velocities and accelerations are those of step 4.".to_string(),
        _ => String::new(),
    };
    format!("{motion} {works}{at}")
}

/// The row of a relaxed joint (`row`, of Lagrange's rows) derived with its auxiliary
/// coordinate; `None` for any other row. The words that let the joint give way are said
/// in the first row of those of the same joint and kind (see `group`), for them all.
/// Each expression is written as `shown` gives it.
pub fn relaxed(
    derivation: &Derivation,
    row: &Equation,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Option<Relaxed> {
    let model = &derivation.model;
    let (_, reaction) = relaxed_reaction(derivation, row)?;
    let index = derivation.rows.iter().position(|r| std::ptr::eq(r, row))?;
    let members = group(derivation, row);
    let first = members.first().is_some_and(|&(i, _)| i == index);
    let intro = if first {
        intro(derivation, row, &members)
    } else {
        String::new()
    };
    let xi = format!("\\xi_{{{}}}", index + 1);
    let xi_dot = format!("\\dot{{\\xi}}_{{{}}}", index + 1);
    let d = vector_tex(model, &reaction.direction);
    let point = latex_name(relaxed_reaction(derivation, row)?.0);
    let inertia_sum = match reaction.kind {
        ComponentKind::Force => format!("\\sum_{{k}} m_{{k}}\\, \\mathbf{{a}}^{{k^*}} \\cdot {d}"),
        ComponentKind::Moment => format!("\\sum_{{k}} \\left( \\mathbf{{r}}^{{{point} k^*}} \\times m_{{k}} \\mathbf{{a}}^{{k^*}} + \\mathbf{{I}}^{{k}} \\cdot \\boldsymbol{{\\alpha}}^{{k}} + \\boldsymbol{{\\omega}}^{{k}} \\times \\mathbf{{I}}^{{k}} \\cdot \\boldsymbol{{\\omega}}^{{k}} \\right) \\cdot {d}"),
    };
    let g = &row.groups;
    let tex = |e: &Expr| latex_collected(&shown(&simplify(e)));
    // A value too long for its line is left to the collected equation below.
    let fits = |definition: String, value: String| match value.len() > LONG_EQUATION {
        true => definition,
        false => format!("{definition} = {value}"),
    };
    let kinetic = -(&g.inertia_force + &g.inertia_torque);
    let forces = &g.contact + &g.distance;
    let lines = vec![
        fits(
            format!("\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}} \\frac{{\\partial T}}{{\\partial {xi_dot}}} - \\frac{{\\partial T}}{{\\partial {xi}}} = {inertia_sum}"),
            tex(&kinetic),
        ),
        fits(
            format!("Q_{{{xi}}} - \\frac{{\\partial V}}{{\\partial {xi}}}"),
            tex(&forces),
        ),
    ];
    Some(Relaxed { intro, lines })
}
