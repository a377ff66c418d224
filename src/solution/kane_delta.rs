//! The common denominator `Δ` of the dependent rates in step 5 and the one step 1 finds
//! them with, linked: the four-bar's `Δ = a sin(q₁ − q₃) + d sin q₃` is, on the loop,
//! `−b sin(q₁ + q₂ − q₃)`, since the loop dotted with `ĉ_y` is zero. So the student reads
//! the two forms of `q̇₂` and `q̇₃` as one, and the singular configuration once.

use crate::mechanics::{same_at, sample_states, DependentSpeeds, Model, SiteKind, Vector};
use crate::problem::BodyId;
use crate::symbolic::{latex, named_definitions, simplify, Expr, Node, Symbol};

/// What `Δ` equals on the loop, in LaTeX, and the factor of it that holds the coordinates
/// (`\sin(q_1 + q_2 - q_3)`), zero where `Δ` is; `None` where the rates have no `Δ`, the
/// loop is not one plane closure of step 1, or no denominator of step 1 matches.
pub struct OnTheLoop {
    /// `-b \sin(q_{1} + q_{2} - q_{3})`.
    pub equal_tex: String,
    /// The unit vector the loop is dotted with, `\hat{\mathbf{c}}_{y}`.
    pub along_tex: String,
    /// `\sin(q_{1} + q_{2} - q_{3})`.
    pub zero_tex: String,
}

/// See [`OnTheLoop`].
pub fn on_the_loop(model: &Model, speeds: &DependentSpeeds) -> Option<OnTheLoop> {
    let definitions = named_definitions(speeds.c.iter().flatten());
    let mut deltas = (definitions.iter())
        .filter(|d| d.note() == "the common denominator of the dependent rates");
    let delta = deltas.next()?;
    if deltas.next().is_some() {
        return None;
    }
    let rates = super::closure_loops::loop_rates(model)?;
    let mut candidates: Vec<Expr> = Vec::new();
    for (_, value) in &rates {
        denominators(value, &mut candidates);
    }
    let mut closures = (model.sites.iter()).filter(|s| matches!(s.kind, SiteKind::Closure(_)));
    let site = closures.next()?;
    let on_parent = model.point_on(site.parent, &site.parent_offset);
    let gap = on_parent.position.minus(&site.point.position);
    let states = sample_states(model);
    let frames = (std::iter::once(BodyId::GROUND)).chain(model.order.iter().copied());
    let units: Vec<Vector> = frames
        .flat_map(|f| {
            let axis = |k: usize| {
                let parts: [Expr; 3] =
                    std::array::from_fn(|i| if i == k { Expr::one() } else { Expr::zero() });
                Vector::new(f, parts)
            };
            [axis(0), axis(1)]
        })
        .collect();
    for den in &candidates {
        for sign in [Expr::one(), Expr::int(-1)] {
            let equal = simplify(&(den * &sign));
            let residual = delta.value() - &equal;
            for unit in &units {
                let along = gap.dot(unit, &model.frames);
                if same_at(&residual, &along, &states) || same_at(&residual, &-along, &states) {
                    return Some(OnTheLoop {
                        equal_tex: latex(&equal),
                        along_tex: super::tex::vector_tex(model, unit),
                        zero_tex: latex(&with_coordinates(&equal)),
                    });
                }
            }
        }
    }
    None
}

/// Each product of the factors of a term of `e` that divide it, once.
fn denominators(e: &Expr, out: &mut Vec<Expr>) {
    match e.node() {
        Node::Mul(items) => {
            let under: Vec<Expr> = (items.iter())
                .filter_map(|x| match x.node() {
                    Node::Pow(base, exponent) => match exponent.node() {
                        Node::Num(n) if n.is_negative() => {
                            Some(crate::symbolic::pow(base.clone(), -exponent.clone()))
                        }
                        _ => None,
                    },
                    _ => None,
                })
                .collect();
            if !under.is_empty() {
                push_once(out, simplify(&crate::symbolic::mul(under)));
            }
            items.iter().for_each(|x| denominators(x, out));
        }
        Node::Pow(base, exponent) => {
            if matches!(exponent.node(), Node::Num(n) if n.is_negative()) {
                push_once(
                    out,
                    simplify(&crate::symbolic::pow(base.clone(), -exponent.clone())),
                );
            }
            denominators(base, out);
        }
        Node::Add(items) | Node::Func(_, items) => items.iter().for_each(|x| denominators(x, out)),
        Node::Num(_) | Node::Sym(_) => {}
    }
}

fn push_once(out: &mut Vec<Expr>, e: Expr) {
    let of_coordinates = e.any_symbol(&|s| matches!(s, Symbol::Coord(..)));
    if of_coordinates && !out.contains(&e) {
        out.push(e);
    }
}

/// The factors of `e` that hold a coordinate: `\sin(q_1 + q_2 - q_3)` of `-b \sin(…)`.
fn with_coordinates(e: &Expr) -> Expr {
    let holds = |x: &Expr| x.any_symbol(&|s| matches!(s, Symbol::Coord(..)));
    match e.node() {
        Node::Mul(items) => crate::symbolic::mul(
            items
                .iter()
                .filter(|x| holds(x))
                .cloned()
                .collect::<Vec<_>>(),
        ),
        _ => e.clone(),
    }
}
