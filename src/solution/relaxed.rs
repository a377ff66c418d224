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

/// The row of a relaxed joint (`row`, of Lagrange's rows) derived with its auxiliary
/// coordinate; `None` for any other row. Each expression is written as `shown` gives it.
pub fn relaxed(
    derivation: &Derivation,
    row: &Equation,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Option<Relaxed> {
    let model = &derivation.model;
    let (site, reaction) = relaxed_reaction(derivation, row)?;
    let index = derivation.rows.iter().position(|r| std::ptr::eq(r, row))?;
    let xi = format!("\\xi_{{{}}}", index + 1);
    let xi_dot = format!("\\dot{{\\xi}}_{{{}}}", index + 1);
    let unknown = latex(&Expr::sym(reaction.unknown(site)));
    let bodies = bodies_tex(derivation, &row.free_body);
    let point = latex_name(site);
    let d = vector_tex(model, &reaction.direction);
    // A direction of several terms in parentheses where it is multiplied.
    let dp = super::tex::factor_of_product(&d);
    let (motion, inertia_sum) = match reaction.kind {
        ComponentKind::Force => (
            format!(
                "Let ${point}$ give way along ${d}$ by an auxiliary coordinate ${xi}$, zero in the motion: every point of ${bodies}$ gains the velocity ${xi_dot}\\, {dp}$, so that $\\partial \\mathbf{{v}}^{{k^*}} / \\partial {xi_dot} = {d}$ and $\\partial \\boldsymbol{{\\omega}}^{{k}} / \\partial {xi_dot} = \\mathbf{{0}}$ for each body $k$ of ${bodies}$."
            ),
            format!("\\sum_{{k}} m_{{k}}\\, \\mathbf{{a}}^{{k^*}} \\cdot {d}"),
        ),
        ComponentKind::Moment => (
            format!(
                "Let ${bodies}$ turn about ${point}$ by an auxiliary angle ${xi}$ about ${d}$, zero in the motion: each of its bodies gains the angular velocity ${xi_dot}\\, {dp}$, so that $\\partial \\boldsymbol{{\\omega}}^{{k}} / \\partial {xi_dot} = {d}$ and $\\partial \\mathbf{{v}}^{{k^*}} / \\partial {xi_dot} = {dp} \\times \\mathbf{{r}}^{{{point} k^*}}$."
            ),
            format!("\\sum_{{k}} \\left( \\mathbf{{r}}^{{{point} k^*}} \\times m_{{k}} \\mathbf{{a}}^{{k^*}} + \\mathbf{{I}}^{{k}} \\cdot \\boldsymbol{{\\alpha}}^{{k}} + \\boldsymbol{{\\omega}}^{{k}} \\times \\mathbf{{I}}^{{k}} \\cdot \\boldsymbol{{\\omega}}^{{k}} \\right) \\cdot {d}"),
        ),
    };
    let intro = format!(
        "{motion} The joint no longer holds along ${xi}$, so ${unknown}$ does work as ${xi}$ changes and enters its generalized force $Q_{{{xi}}}$, with the other forces on ${bodies}$ from outside. At ${xi} = {xi_dot} = 0$ the velocities and accelerations are those of step 4."
    );
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
