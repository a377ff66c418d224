//! Long acceleration components of spatial problems as named quantities, linear in the q''.
//!
//! Multiplied out, the mass-centre acceleration of the k-th body of a spatial chain has
//! hundreds of terms, and every equation that dots it with a partial velocity or crosses it
//! with a lever arm multiplies them out again. Written as `Σ v_r q̈_r + ã`, with each long
//! coefficient (a partial velocity component) and the rest `ã` a named quantity, it is n + 1
//! terms, the q'' stay visible for the linear system, and the numbers are unchanged.

use crate::mechanics::vector::Components;
use crate::symbolic::{add, eval, latex, latex_name, linear_split, Expr, Symbol, Values};

/// Components with more terms than this are written with named parts; shorter ones are
/// printed as they are.
pub const MAX_EXPANDED_TERMS: usize = 8;

/// What a component is, for the names of its parts.
pub struct Quantity<'a> {
    /// The body's name (`B3`).
    pub body: &'a str,
    /// `a` for the mass centre's acceleration, `alpha` for the angular acceleration.
    pub kind: Kind,
}

/// The two accelerations that get named parts.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// The mass centre's acceleration; the q'' coefficients are partial velocities.
    CenterAcceleration,
    /// The angular acceleration; the q'' coefficients are partial angular velocities.
    AngularAcceleration,
}

/// One acceleration built on the parent's: the coefficient of each q̈ (a partial velocity)
/// and the rest, each in the body's own unit vectors.
pub struct Built {
    /// Indexed like the accelerations.
    pub partials: Vec<Components>,
    /// The part without the q''.
    pub rest: Components,
}

/// The names of the axes, for the names of the parts.
pub const AXES: [&str; 3] = ["x", "y", "z"];

/// `components` (in the body's own unit vectors) with every long one rewritten as
/// `Σ c_r q̈_r + rest`, each long `c_r` and `rest` a named quantity. A part of `built` (the
/// same acceleration built on the parent's) is used where it is shorter and has the same
/// value at every one of `states`, where an identity holds and a slip would not.
pub fn named_components(
    components: &Components,
    accelerations: &[Symbol],
    quantity: &Quantity,
    built: Option<&Built>,
    states: &[Values],
) -> Components {
    let shorter = |direct: Expr, candidate: Option<&Expr>| match candidate {
        Some(c) if c.terms().len() < direct.terms().len() && same_value(c, &direct, states) => {
            c.clone()
        }
        _ => direct,
    };
    std::array::from_fn(|axis| {
        let value = &components[axis];
        if value.terms().len() <= MAX_EXPANDED_TERMS {
            return value.clone();
        }
        let Ok((coefficients, rest)) = linear_split(value, accelerations) else {
            return value.clone();
        };
        let mut terms = Vec::with_capacity(accelerations.len() + 1);
        for (r, (coefficient, acceleration)) in
            coefficients.into_iter().zip(accelerations).enumerate()
        {
            if coefficient.is_zero() {
                continue;
            }
            let coefficient = shorter(coefficient, built.map(|b| &b.partials[r][axis]));
            let named = name_part(&coefficient, quantity, axis, Some(acceleration));
            terms.push(&named * &Expr::sym(acceleration.clone()));
        }
        let rest = shorter(rest, built.map(|b| &b.rest[axis]));
        terms.push(name_part(&rest, quantity, axis, None));
        add(terms)
    })
}

/// Whether `a` and `b` agree at every state, to rounding.
fn same_value(a: &Expr, b: &Expr, states: &[Values]) -> bool {
    states.iter().all(|state| {
        let (x, y) = (eval(a, state), eval(b, state));
        (x - y).abs() <= 1e-9 * (1.0 + y.abs())
    })
}

/// `value` (a component of `quantity` along `axis`, or with `rate` its part for that
/// speed) under a name when it has two terms or more, itself otherwise.
pub fn name_part(value: &Expr, quantity: &Quantity, axis: usize, rate: Option<&Symbol>) -> Expr {
    if value.terms().len() < 2 {
        return value.clone();
    }
    let body = quantity.body;
    let body_tex = latex_name(body);
    let axis_name = AXES[axis];
    let (name, tex, note) = match (quantity.kind, rate) {
        (Kind::CenterAcceleration, Some(s)) => {
            let speed = coordinate_of(s);
            (
                format!("{body}*.v.{speed}.{axis_name}"),
                format!("v^{{{body_tex}^{{*}}}}_{{{},{axis_name}}}", speed_tex(s)),
                format!("partial velocity of {body}* for {speed}', along {body}.{axis_name}"),
            )
        }
        (Kind::CenterAcceleration, None) => (
            format!("{body}*.a.{axis_name}"),
            format!("\\tilde{{a}}^{{{body_tex}^{{*}}}}_{{{axis_name}}}"),
            format!("acceleration of {body}* along {body}.{axis_name} without the q''"),
        ),
        (Kind::AngularAcceleration, Some(s)) => {
            let speed = coordinate_of(s);
            (
                format!("{body}.w.{speed}.{axis_name}"),
                format!("\\omega^{{{body_tex}}}_{{{},{axis_name}}}", speed_tex(s)),
                format!(
                    "partial angular velocity of {body} for {speed}', along {body}.{axis_name}"
                ),
            )
        }
        (Kind::AngularAcceleration, None) => (
            format!("{body}.alpha.{axis_name}"),
            format!("\\tilde{{\\alpha}}^{{{body_tex}}}_{{{axis_name}}}"),
            format!("angular acceleration of {body} along {body}.{axis_name} without the q''"),
        ),
    };
    Expr::named(&name, &tex, &note, value.clone())
}

/// The coordinate's name of a q'' symbol.
fn coordinate_of(s: &Symbol) -> String {
    match s {
        Symbol::Coord(name, _) => name.to_string(),
        other => other.to_string(),
    }
}

/// The coordinate as LaTeX (`q_{3}`, `\theta`), the index of a partial velocity.
fn speed_tex(s: &Symbol) -> String {
    match s {
        Symbol::Coord(name, _) => latex(&Expr::coord(name, 0)),
        other => latex(&Expr::sym(other.clone())),
    }
}
