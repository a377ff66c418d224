//! Kane's generalized inertia force of one speed as a student multiplies it out: body by
//! body, `F^*_{r,B} = v^{B*}_r · R^*_B + ω^B_r · T^*_B`, each dot product written as the
//! products of its components in one frame's unit vectors, then the body's term simplified,
//! then their sum.

use super::tex::centre_tex;
use crate::equations::partials;
use crate::equations::Derivation;
use crate::mechanics::is_particle;
use crate::mechanics::{Model, Vector};
use crate::problem::BodyId;
use crate::render::symbols;
use crate::symbolic::latex_collected;
use crate::symbolic::simplify;
use crate::symbolic::{add, Expr, Node, Symbol};
use crate::symbolic::{latex, latex_name};

/// The most bodies whose dot products are written out: past three, the products of a
/// chain's outer bodies run over several lines each, and its rows are read by step 4's
/// names instead.
const MOST_BODIES: usize = 3;

/// The most characters of LaTeX one line of products may take: a longer one would stick
/// out of the page's margin, and the body's term is then written without its products.
const LONGEST_PRODUCTS: usize = 300;

/// The most symbols one printed line may take: the page's line, as
/// [`crate::render::symbols`] counts them.
pub(super) const WIDEST_LINE: f64 = 66.0;

/// One dot product `a · b` written in one frame: the pairs of components that multiply,
/// in axis order.
pub(super) struct DotProduct {
    /// `(a_i, b_i)` for each axis where neither is zero.
    pub(super) pairs: Vec<(Expr, Expr)>,
    /// The frame the components are in, and the axis of each pair.
    frame: BodyId,
    axes: Vec<u8>,
}

impl DotProduct {
    /// `a · b` in whichever of `frames` writes both the shortest.
    pub(super) fn shortest(a: &Vector, b: &Vector, frames: &[BodyId], model: &Model) -> DotProduct {
        let written = |frame: BodyId| {
            let a = a.components_in(frame, &model.frames).map(|c| simplify(&c));
            let b = b.components_in(frame, &model.frames).map(|c| simplify(&c));
            let cost: usize = a.iter().chain(&b).map(|c| latex(c).len()).sum();
            (cost, frame, a, b)
        };
        let (_, frame, a, b) = frames
            .iter()
            .map(|&f| written(f))
            .min_by_key(|(cost, ..)| *cost)
            .unwrap_or_else(|| written(BodyId::GROUND));
        let axes: Vec<u8> = (0..3u8)
            .filter(|&axis| !a[axis as usize].is_zero() && !b[axis as usize].is_zero())
            .collect();
        let pairs = (axes.iter())
            .map(|&axis| (a[axis as usize].clone(), b[axis as usize].clone()))
            .collect();
        DotProduct { pairs, frame, axes }
    }

    /// Each pair as the partial velocity's component times the inertia force's named by
    /// its unit vector, `a_x\,(\mathbf{f}^{*}_{B} \cdot \hat{\mathbf{b}}_{x})`, where
    /// `named` is the inertia force's (or torque's) name.
    pub(super) fn named_terms(&self, model: &Model, named: &str) -> Vec<String> {
        let frame = model.frames.name(self.frame);
        (self.pairs.iter().zip(&self.axes))
            .map(|((a, _), &axis)| {
                let unit = crate::symbolic::latex_unit_vector(frame, axis);
                let b = format!("\\left({named} \\cdot {unit}\\right)");
                match a {
                    a if a.is_one() => b,
                    a if (-a).is_one() => format!("-{b}"),
                    _ => format!("{}\\, {b}", factor_tex(a)),
                }
            })
            .collect()
    }

    /// `Σ a_i b_i` as an expression.
    pub(super) fn value(&self) -> Expr {
        add(self.pairs.iter().map(|(a, b)| a * b))
    }
}

/// A factor of a product: in brackets when it is a sum or starts with a sign.
fn factor_tex(e: &Expr) -> String {
    let text = latex(e);
    if matches!(e.node(), Node::Add(_)) || text.starts_with('-') {
        format!("\\left({text}\\right)")
    } else {
        text
    }
}

/// The products of dot products, `(a_x)(b_x) + (a_y)(b_y)`: on one line, or one product a
/// line where that is too long.
/// Empty where a product alone would stick out of the margin.
pub(super) fn products_lines(dots: &[&DotProduct]) -> Vec<String> {
    let terms: Vec<String> = dots
        .iter()
        .flat_map(|d| d.pairs.iter())
        .map(|(a, b)| match a {
            a if a.is_one() => factor_tex(b),
            _ => format!("{}\\, {}", factor_tex(a), factor_tex(b)),
        })
        .collect();
    let one_line = format!("&= {}", terms.join(" + "));
    if one_line.len() <= LONGEST_PRODUCTS {
        return vec![one_line];
    }
    if terms.iter().any(|t| t.len() > LONGEST_PRODUCTS) {
        return Vec::new();
    }
    terms
        .iter()
        .enumerate()
        .map(|(i, t)| match i {
            0 => format!("&= {t}"),
            _ => format!("&\\quad + {t}"),
        })
        .collect()
}

/// The frames a body's products may be written in: its own, its parent's and `N`.
pub(super) fn candidate_frames(model: &Model, body: BodyId) -> Vec<BodyId> {
    let mut frames = vec![model.bodies[body.0].frame, body, BodyId::GROUND];
    if let Some(parent) = model.frames.info(body).parent {
        frames.push(parent);
    }
    frames.dedup();
    frames
}

/// The lines of one body's term of `F^*_r`: its definition with the products written
/// out, then the term simplified. `None` when the body's partials are both zero.
fn body_lines(
    derivation: &Derivation,
    body: BodyId,
    r: usize,
    rates: &[Symbol],
    shown: &dyn Fn(&Expr) -> Expr,
) -> Option<(String, Vec<String>)> {
    let model = &derivation.model;
    let state = &model.bodies[body.0];
    let v = partials(&state.center.velocity, rates).swap_remove(r - 1);
    let w = partials(&state.omega, rates).swap_remove(r - 1);
    let inertia = derivation.inertia();
    let particle = is_particle(model, body);
    let frames = candidate_frames(model, body);
    let translation = DotProduct::shortest(&v, &inertia.force[body.0], &frames, model);
    let rotation =
        (!particle).then(|| DotProduct::shortest(&w, &inertia.torque[body.0], &frames, model));
    let dots: Vec<&DotProduct> = std::iter::once(&translation).chain(&rotation).collect();
    let term = shown(&simplify(&add(dots.iter().map(|d| d.value()))));
    if term.is_zero() {
        return None;
    }
    let symbol = latex_name(model.problem.body_name(body));
    let name = format!("F^{{*}}_{{{r},{symbol}}}");
    let letters = super::kane_theory::letters(derivation);
    let mut definition = format!(
        "\\mathbf{{v}}^{{{}}}_{{{r}}} \\cdot {}^{{*}}_{{{symbol}}}",
        centre_tex(model, body),
        letters.force
    );
    if !particle {
        definition.push_str(&format!(
            " + \\boldsymbol{{\\omega}}^{{{symbol}}}_{{{r}}} \\cdot {}^{{*}}_{{{symbol}}}",
            letters.couple
        ));
    }
    let mut lines = vec![format!("{name} &= {definition}")];
    lines.extend(products_lines(&dots));
    lines.push(format!("&= {}", latex_collected(&term)));
    // Products that print wider than the page go; a term that does makes the block go.
    let (term_line, products) = lines.split_last()?;
    if symbols(term_line) > WIDEST_LINE {
        return Some((name, Vec::new()));
    }
    let mut kept: Vec<String> = products.to_vec();
    if kept.iter().any(|l| symbols(l) > WIDEST_LINE) {
        kept.truncate(1);
    }
    kept.push(term_line.clone());
    Some((name, kept))
}

/// `F^*_r` of Kane's speed row `r` (1-based) with each body's dot products multiplied out,
/// as an `aligned` block ending in `whole`'s formula; `None` for more than three bodies,
/// for speeds combined by dependent-speed weights (written by
/// [`super::kane_bodies::inertia_by_body`]) and where no body contributes.
pub fn inertia_dot_products(
    derivation: &Derivation,
    r: usize,
    whole: &str,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Option<String> {
    let model = &derivation.model;
    if model.order.len() > MOST_BODIES || derivation.dependent_speeds.is_some() {
        return None;
    }
    let rates = model.problem.speed_symbols(1);
    if r == 0 || r > rates.len() {
        return None;
    }
    let mut names = Vec::new();
    let mut lines = Vec::new();
    for &body in &model.order {
        if let Some((name, body_lines)) = body_lines(derivation, body, r, &rates, shown) {
            if body_lines.is_empty() {
                return None;
            }
            names.push(name);
            lines.extend(body_lines);
        }
    }
    if names.is_empty() {
        return None;
    }
    super::aligned::sum_of_parts(
        &format!("F^{{*}}_{{{r}}}"),
        &names,
        lines,
        whole,
        model.order.len() == 1,
    )
}

#[cfg(test)]
mod tests {
    use super::DotProduct;
    use crate::equations::partials;
    use crate::equations::{derive, Method, Request, Rows};
    use crate::mechanics::Form;
    use crate::symbolic::eval;
    use crate::symbolic::{add, Expr};

    /// The double pendulum of two uniform rods: body B's part of `F^*_1`, written out by
    /// hand from `v^{B*}_1 = (L₂/2 + L₁ c₂) b̂_x − L₁ s₂ b̂_y`, `ω^B_1 = b̂_z` and Lagrange's
    /// `∂T/∂q̇₁` of B alone, equals the sum of the products the handout writes.
    #[test]
    fn the_second_rods_products_sum_to_its_term_written_by_hand() {
        let text = std::fs::read_to_string("problems/double-pendulum-rods.json").unwrap();
        let problem = crate::problem::load(&text).unwrap();
        let request = Request {
            form: Form::Handout,
            rows: Rows::Formed,
            states: &[],
        };
        let derivation = derive(&problem, Method::Kane, request).unwrap();
        let model = &derivation.model;
        let body = model.order[1];
        let rates = problem.speed_symbols(1);
        let v = partials(&model.bodies[body.0].center.velocity, &rates).swap_remove(0);
        let w = partials(&model.bodies[body.0].omega, &rates).swap_remove(0);
        let inertia = derivation.inertia();
        let frames = super::candidate_frames(model, body);
        let sum = add(vec![
            DotProduct::shortest(&v, &inertia.force[body.0], &frames, model).value(),
            DotProduct::shortest(&w, &inertia.torque[body.0], &frames, model).value(),
        ]);
        let (q2, u1, u2, a1, a2) = (0.4_f64, 1.1, -0.6, 2.0, -3.0);
        let mut values = model.values_at(0.0, &[0.3, q2], &[u1, u2]);
        values.set(problem.coordinate_symbol(0, 2), a1);
        values.set(problem.coordinate_symbol(1, 2), a2);
        // The problem's L₁, L₂ and m₂.
        let (l1, l2, m2) = (0.6, 0.4, 0.8);
        // −∂/∂q̇₁ of B's kinetic energy, differentiated in time, plus ∂T_B/∂q₁ (zero).
        let (c2, s2) = (q2.cos(), q2.sin());
        let by_hand = -m2 * (l1 * l1 + l2 * l2 / 3.0 + l1 * l2 * c2) * a1
            - m2 * (l2 * l2 / 3.0 + l1 * l2 * c2 / 2.0) * a2
            + m2 * l1 * l2 * s2 * (2.0 * u1 * u2 + u2 * u2) / 2.0;
        let value = eval(&sum, &values);
        assert!((value - by_hand).abs() < 1e-12, "{value} vs {by_hand}");
        assert!(!Expr::is_zero(&sum));
    }
}
