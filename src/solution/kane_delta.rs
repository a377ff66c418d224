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
    /// The other identities the loop gives that step 5's rates need to be step 1's, each
    /// with the unit vector the loop is dotted with: `c \sin(q_1 - q_3) + d \sin q_1 =
    /// -b \sin q_2` along `\hat{\mathbf{a}}_{y}`, for `q̇₃`.
    pub also: Vec<(String, String)>,
    /// The dependent rates those identities simplify, each by its index among the
    /// dependent speeds with its coefficient of the free rate in step 1's form over `Δ`
    /// (`−a b sin q₂/(c Δ)` for `q̇₃`): what step 5 prints, the simplest form.
    pub simplest: Vec<(usize, Expr)>,
    /// `Δ`, the named denominator.
    pub delta: Expr,
    /// What `Δ` equals on the loop, `-b \sin(q_1 + q_2 - q_3)`.
    pub equal: Expr,
}

/// What the dependent rates' common denominator is named for.
pub const DELTA_NOTE: &str = "the common denominator of the dependent rates";

/// Whether step 5 defines `Δ` beside the dependent rates (Kane's method with the rates
/// written in symbols), so that step 4 does not.
pub fn defined_in_step_5(derivation: &crate::equations::Derivation) -> bool {
    derivation.method == crate::equations::Method::Kane
        && (derivation.dependent_speeds.as_ref()).is_some_and(|s| !s.at_each_state)
}

/// `\Delta = a \sin(q_1 - q_3) + d \sin(q_3)`: the dependent rates' common denominator
/// defined, for the sentence that first writes the rates with it; `None` without one.
pub fn definition_tex(speeds: &DependentSpeeds) -> Option<String> {
    let definitions = named_definitions(speeds.c.iter().flatten());
    let delta = (definitions.iter()).find(|d| d.note() == DELTA_NOTE)?;
    let name = delta.latex()?;
    Some(format!(
        "{name} = {}",
        crate::symbolic::latex_collected(delta.value())
    ))
}

/// See [`OnTheLoop`].
pub fn on_the_loop(model: &Model, speeds: &DependentSpeeds) -> Option<OnTheLoop> {
    let definitions = named_definitions(speeds.c.iter().flatten());
    let mut deltas = (definitions.iter()).filter(|d| d.note() == DELTA_NOTE);
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
                    let delta =
                        (speeds.c.iter().flatten()).find_map(|c| named_delta(c, delta.note()))?;
                    let links = rate_links(model, speeds, (&delta, &equal), &gap, &units);
                    let (also, simplest) = links.into_iter().unzip();
                    return Some(OnTheLoop {
                        also,
                        simplest,
                        delta,
                        equal: equal.clone(),
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

/// For each dependent rate whose form in step 5 is not yet step 1's once `Δ` is written
/// as on the loop (`delta`, `equal`), the identity of the loop that makes it so: the
/// numerators over `Δ` equal, as the loop's `gap` dotted with one of `units` shows; with
/// the rate's index and its coefficient so simplified.
fn rate_links(
    model: &Model,
    speeds: &DependentSpeeds,
    (delta, equal): (&Expr, &Expr),
    gap: &Vector,
    units: &[Vector],
) -> Vec<((String, String), (usize, Expr))> {
    let problem = model.problem;
    let Some(rates) = super::closure_loops::loop_rates(model) else {
        return Vec::new();
    };
    if speeds.independent.len() != 1 || !speeds.prescribed.is_empty() {
        return Vec::new();
    }
    let free = problem.coordinate_expr(speeds.independent[0], 1);
    let states = sample_states(model);
    let mut out = Vec::new();
    for (s, &d) in speeds.dependent.iter().enumerate() {
        let Some((_, first)) = rates.iter().find(|(i, _)| *i == d) else {
            continue;
        };
        // Step 5's numerator over Δ and step 1's rate times what Δ is on the loop.
        let over = simplify(&(&speeds.c[s][0] * delta));
        let step_1 = simplify(&(&(first / &free) * equal));
        let difference = &over - &step_1;
        // Equal already, or by what step 5 says of Δ alone.
        let said = delta.as_definition().map(|d| d.value() - equal);
        if same_at(&difference, &Expr::zero(), &states)
            || said.is_some_and(|said| proportional(&difference, &said, &states))
        {
            continue;
        }
        let along = (units.iter())
            .find(|unit| proportional(&difference, &gap.dot(unit, &model.frames), &states));
        let Some(along) = along else {
            continue;
        };
        let (common, inner) = crate::symbolic::pull_common_factor(&over);
        let other = simplify(&(&step_1 / &common));
        let simplest = simplify(&(&(&common * &other) / delta));
        out.push((
            (
                format!("{} = {}", latex(&inner), latex(&other)),
                super::tex::vector_tex(model, along),
            ),
            (s, simplest),
        ));
    }
    out
}

/// Whether `a` is a constant non-zero multiple of `b` at `states`.
fn proportional(a: &Expr, b: &Expr, states: &[crate::symbolic::Values]) -> bool {
    let ratio =
        |v: &crate::symbolic::Values| crate::symbolic::eval(a, v) / crate::symbolic::eval(b, v);
    let first = states.first().map(ratio).unwrap_or(f64::NAN);
    first.is_finite()
        && first.abs() > 1e-12
        && (states.iter()).all(|v| (ratio(v) - first).abs() <= 1e-9 * first.abs())
}

/// The named denominator in `e` whose note is `note`, as the symbol it is written with.
fn named_delta(e: &Expr, note: &str) -> Option<Expr> {
    if e.as_definition().is_some_and(|d| d.note() == note) {
        return Some(e.clone());
    }
    match e.node() {
        Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => {
            items.iter().find_map(|x| named_delta(x, note))
        }
        Node::Pow(base, exponent) => {
            named_delta(base, note).or_else(|| named_delta(exponent, note))
        }
        Node::Num(_) | Node::Sym(_) => None,
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
