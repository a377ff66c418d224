//! Kane's generalized inertia force of an independent speed as a student forms it with the
//! constrained partial velocities: body by body,
//! `F̃^*_{r,B} = ṽ^{B*}_r · R^*_B + ω̃^B_r · T^*_B`, each dot product multiplied out in one
//! frame's unit vectors, then the dependent accelerations it holds replaced by the
//! constraints differentiated, `q̈_D = C q̈_I + Ċ q̇_I` (each written where it first enters),
//! then the body's term in the independent speeds alone, then their sum.

use super::kane_dots::{candidate_frames, products_lines, DotProduct, WIDEST_LINE};
use super::tex::centre_tex;
use crate::equations::{partials, Derivation};
use crate::mechanics::{is_particle, DependentSpeeds, Model, Vector};
use crate::plan::Groups;
use crate::problem::BodyId;
use crate::render::symbols;
use crate::symbolic::{
    add, eval, latex, latex_collected, latex_name, simplify, substitute, Expr, Symbol, Values,
};

/// The most bodies whose dot products are written out, as for the rates as speeds (see
/// [`super::kane_dots`]).
const MOST_BODIES: usize = 3;

/// The most characters of LaTeX one body's term may take, broken over lines: a longer one
/// is read in the row's sum.
const LONGEST_TERM: usize = 600;

/// The most characters of LaTeX a part may take and still be repeated in the whole sum
/// that ends the display.
const LONGEST_REPEATED: usize = 250;

/// The dependent rates and accelerations written with the independent ones, and whether
/// the row was formed with them replaced (a row whose inertia force would grow too long
/// keeps them, and the differentiated constraints are solved with it).
struct Elimination<'a> {
    model: &'a Model<'a>,
    speeds: &'a DependentSpeeds,
    rates: Vec<Expr>,
    accelerations: Vec<Expr>,
    applies: bool,
}

impl<'a> Elimination<'a> {
    fn new(
        model: &'a Model<'a>,
        speeds: &'a DependentSpeeds,
        groups: &Groups,
    ) -> Option<Elimination<'a>> {
        let accelerations = speeds.dependent_accelerations(model).ok()?;
        let rates = speeds.dependent_rates(model);
        let inertia = add([groups.inertia_force.clone(), groups.inertia_torque.clone()]);
        let problem = model.problem;
        let applies = !speeds.dependent.iter().any(|&d| {
            inertia.contains(&problem.coordinate_symbol(d, 2))
                || inertia.contains(&problem.coordinate_symbol(d, 1))
        });
        Some(Elimination {
            model,
            speeds,
            rates,
            accelerations,
            applies,
        })
    }

    /// `e` with the dependent rates and accelerations replaced, if the row was so formed.
    fn apply(&self, e: &Expr) -> Expr {
        if !self.applies {
            return e.clone();
        }
        let problem = self.model.problem;
        let with_rates = self
            .speeds
            .with_independent_rates(self.model, &self.rates, e);
        substitute(&with_rates, &|symbol| {
            self.speeds
                .dependent
                .iter()
                .position(|&d| problem.coordinate_symbol(d, 2) == *symbol)
                .map(|s| self.accelerations[s].clone())
        })
    }

    /// The dependent accelerations (indices into `speeds.dependent`) that `e` holds.
    fn entering(&self, e: &Expr) -> Vec<usize> {
        let problem = self.model.problem;
        (0..self.speeds.dependent.len())
            .filter(|&s| e.contains(&problem.coordinate_symbol(self.speeds.dependent[s], 2)))
            .collect()
    }
}

/// One body's part of `F̃^*_r`: its dot products, the term as they give it and the term in
/// the independent speeds.
struct Part {
    body: BodyId,
    dots: Vec<DotProduct>,
    formed: Expr,
    term: Expr,
}

/// The parts of every body that moves with independent speed `r` (1-based).
fn parts(
    derivation: &Derivation,
    speeds: &DependentSpeeds,
    r: usize,
    elimination: &Elimination,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Vec<Part> {
    let model = &derivation.model;
    let problem = model.problem;
    let n = problem.coordinates.len();
    let rates: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
    let (weights, rigid) = if r <= speeds.independent.len() {
        (speeds.independent_weights(r - 1, n), None)
    } else {
        // An auxiliary speed's: only its constraint gives way, or its joint of the tree
        // with the loop kept closed.
        match super::auxiliary_partials::motion(derivation, r) {
            Some(motion) => (motion.weights, motion.rigid),
            None => (vec![Expr::zero(); n], None),
        }
    };
    let combined = |list: &[Vector], own: Vector| -> Vector {
        Vector::sum(
            list.iter()
                .zip(&weights)
                .filter(|(_, w)| !w.is_zero())
                .map(|(v, w)| v.scaled(w)),
        )
        .plus(&own)
        .map(|e| shown(&simplify(e)))
    };
    let inertia = derivation.inertia();
    let mut out = Vec::new();
    for &body in &model.order {
        let state = &model.bodies[body.0];
        let own = rigid
            .as_ref()
            .map(|m| (m.centre(model, body), m.omega(body)));
        let (own_v, own_w) = own.unwrap_or((Vector::zero(), Vector::zero()));
        let v = combined(&partials(&state.center.velocity, &rates), own_v);
        let frames = candidate_frames(model, body);
        let mut dots = vec![DotProduct::shortest(
            &v,
            &inertia.force[body.0],
            &frames,
            model,
        )];
        if !is_particle(model, body) {
            let w = combined(&partials(&state.omega, &rates), own_w);
            dots.push(DotProduct::shortest(
                &w,
                &inertia.torque[body.0],
                &frames,
                model,
            ));
        }
        let formed = shown(&simplify(&add(dots.iter().map(DotProduct::value))));
        let term = shown(&simplify(&elimination.apply(&formed)));
        if !formed.is_zero() {
            out.push(Part {
                body,
                dots,
                formed,
                term,
            });
        }
    }
    out
}

/// Whether the parts add up to the row's inertia groups at the initial state, every
/// second derivative given a value: what is printed is what the row sums.
fn add_up(derivation: &Derivation, parts: &[Part], groups: &Groups) -> bool {
    let model = &derivation.model;
    // On the loop where the parts are finished with its constraints.
    let on_loop = super::kane_loop::OnTheLoop::of(derivation);
    let start = on_loop.as_ref().and_then(|l| l.states().first().cloned());
    let mut values: Values = start
        .or_else(|| crate::mechanics::sample_states(model).into_iter().next())
        .unwrap_or_default();
    let problem = model.problem;
    for i in 0..problem.coordinates.len() {
        values.set(problem.coordinate_symbol(i, 2), 0.37 + 0.61 * i as f64);
    }
    let row = eval(&groups.inertia_force, &values) + eval(&groups.inertia_torque, &values);
    let sum: f64 = parts.iter().map(|p| eval(&p.term, &values)).sum();
    let tolerance = if on_loop.is_some() { 1e-7 } else { 1e-9 };
    row.is_finite() && (row - sum).abs() <= tolerance * (1.0 + row.abs())
}

/// `q̈_D = …` of each dependent acceleration in `entering` not yet written, as lines of
/// the display, after the words that say where they come from (once in the handout).
fn acceleration_lines(
    derivation: &Derivation,
    elimination: &Elimination,
    entering: &[usize],
    written: &mut Vec<usize>,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Vec<String> {
    let problem = derivation.model.problem;
    let mut lines = Vec::new();
    for &s in entering {
        if written.contains(&s) {
            continue;
        }
        if written.is_empty() && lines.is_empty() {
            lines.push(
                "&\\text{with the relations of the dependent rates differentiated:}".to_string(),
            );
        }
        let d = elimination.speeds.dependent[s];
        let value = shown(&simplify(&elimination.accelerations[s]));
        lines.push(super::aligned::line(
            &latex(&problem.coordinate_expr(d, 2)),
            "=",
            &latex_collected(&value),
        ));
    }
    for &s in entering {
        if !written.contains(&s) {
            written.push(s);
        }
    }
    lines
}

/// One body's lines: the definition, the products, the term as formed, then (where
/// dependent accelerations enter and are replaced) them and the term in the independent
/// speeds. `None` where a term is too long to read.
fn part_lines(
    derivation: &Derivation,
    r: usize,
    part: &Part,
    elimination: &Elimination,
    written: &mut Vec<usize>,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Option<(String, Vec<String>)> {
    let model = &derivation.model;
    let symbol = latex_name(model.problem.body_name(part.body));
    let name = format!("\\tilde{{F}}^{{*}}_{{{r},{symbol}}}");
    let letters = super::kane_theory::letters(derivation);
    let mut definition = format!(
        "\\tilde{{\\mathbf{{v}}}}^{{{}}}_{{{r}}} \\cdot {}^{{*}}_{{{symbol}}}",
        centre_tex(model, part.body),
        letters.force
    );
    if part.dots.len() > 1 {
        definition.push_str(&format!(
            " + \\tilde{{\\boldsymbol{{\\omega}}}}^{{{symbol}}}_{{{r}}} \\cdot {}^{{*}}_{{{symbol}}}",
            letters.couple
        ));
    }
    // The definition is written in the first row and in the first auxiliary row, whose
    // partial velocities are those of another motion; the rows after them start from the
    // products, as a textbook writes a second row like the first.
    let first_of_its_kind = derivation
        .dependent_speeds
        .as_ref()
        .map_or(r == 1, |s| r == 1 || r == s.independent.len() + 1);
    let mut lines = if first_of_its_kind {
        vec![format!("{name} &= {definition}")]
    } else {
        Vec::new()
    };
    let dots: Vec<&DotProduct> = part.dots.iter().collect();
    let mut products = products_lines(&dots);
    // One product by a unit vector's unit component is the term as formed: said once.
    let one = part.dots.iter().map(|d| d.pairs.len()).sum::<usize>() == 1
        && part
            .dots
            .iter()
            .flat_map(|d| &d.pairs)
            .all(|(a, _)| a.is_one());
    // An auxiliary speed's long products are the table's partial velocities times step
    // 4's accelerations: its terms alone keep the row short.
    let auxiliary = derivation
        .dependent_speeds
        .as_ref()
        .is_some_and(|s| r > s.independent.len());
    let many = products.iter().map(|l| l.len()).sum::<usize>() > LONGEST_AUXILIARY_PRODUCTS;
    let long = (auxiliary && many) || products.iter().any(|l| symbols(l) > WIDEST_LINE);
    if one || long {
        products.clear();
    }
    if long && !one {
        // Products too long to write out: each partial velocity's component times the
        // inertia force's by name, the step between the definition and the term.
        products = named_products(model, part, &symbol, &letters);
    }
    lines.extend(products);
    let formed = latex_collected(&part.formed);
    let term = latex_collected(&part.term);
    let longest = if auxiliary {
        LONGEST_AUXILIARY_TERM
    } else {
        LONGEST_TERM
    };
    if formed.len() > longest || term.len() > longest {
        return None;
    }
    lines.push(super::aligned::line_within("", "=", &formed, PART_SYMBOLS));
    if let Some(first) = lines
        .first_mut()
        .filter(|l| l.trim_start().starts_with('&'))
    {
        *first = format!("{name} {}", first.trim_start());
    }
    if part.term != part.formed {
        let entering = elimination.entering(&part.formed);
        lines.extend(acceleration_lines(
            derivation,
            elimination,
            &entering,
            written,
            shown,
        ));
        lines.push(super::aligned::line_within(&name, "=", &term, PART_SYMBOLS));
    }
    Some((name, lines))
}

/// One body's dot products as its partial velocities' components times the inertia
/// force's and torque's components by name, `a_x\,(\mathbf{f}^{*}_{B} \cdot
/// \hat{\mathbf{b}}_{x}) + …`, as a line of an aligned display (broken where long);
/// nothing where even that would not be short.
fn named_products(
    model: &Model,
    part: &Part,
    symbol: &str,
    letters: &super::kane_theory::Letters,
) -> Vec<String> {
    let names = [&letters.force, &letters.couple].map(|l| format!("{l}^{{*}}_{{{symbol}}}"));
    let terms: Vec<String> = (part.dots.iter().zip(&names))
        .flat_map(|(dot, name)| dot.named_terms(model, name))
        .collect();
    let mut sum = String::new();
    for term in &terms {
        match (sum.is_empty(), term.strip_prefix('-')) {
            (true, _) => sum.push_str(term),
            (false, Some(rest)) => sum.push_str(&format!(" - {rest}")),
            (false, None) => sum.push_str(&format!(" + {term}")),
        }
    }
    if terms.is_empty() || sum.len() > LONGEST_NAMED {
        return Vec::new();
    }
    vec![super::aligned::line_within("", "=", &sum, PART_SYMBOLS)]
}

/// How many symbols the right side of a line of a body's part takes: the display is set
/// on lines of its own, under the words that name it, and its left sides (`\tilde{F}^{*}_{3,B}`)
/// are short, so a term of a sum fits whole where a line of 46 would split its bracket.
const PART_SYMBOLS: f64 = 60.0;

/// The most characters of LaTeX a body's products by name may take.
const LONGEST_NAMED: usize = 400;

/// `F̃^*_r` of Kane's independent or auxiliary speed `r` (1-based) with each body's dot products
/// multiplied out and the dependent accelerations replaced, as an `aligned` block ending in
/// `whole`'s formula (the row's `F̃^*_r = …`); `None` without dependent speeds written in
/// symbols, for more than three bodies, where a part is too long, or where the parts do not
/// add up to the row's `groups` (then [`super::kane_bodies::inertia_by_body`] writes it).
pub fn inertia_dot_products(
    derivation: &Derivation,
    r: usize,
    groups: &Groups,
    whole: &str,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Option<String> {
    let model = &derivation.model;
    let speeds = derivation
        .dependent_speeds
        .as_ref()
        .filter(|s| !s.at_each_state)?;
    let auxiliary = r > speeds.independent.len();
    if model.order.len() > MOST_BODIES
        || r == 0
        || (auxiliary && super::auxiliary_partials::motion(derivation, r).is_none())
    {
        return None;
    }
    let mut elimination = Elimination::new(model, speeds, groups)?;
    // An auxiliary row is solved with every q̈ known: it keeps the dependent ones.
    elimination.applies &= !auxiliary;
    let this = parts(derivation, speeds, r, &elimination, shown);
    if this.is_empty() || !add_up(derivation, &this, groups) {
        return None;
    }
    // The dependent accelerations the rows before this one wrote already.
    let mut written: Vec<usize> = Vec::new();
    if elimination.applies {
        for earlier in 1..r {
            for part in parts(derivation, speeds, earlier, &elimination, shown) {
                if part.term != part.formed {
                    written.extend(elimination.entering(&part.formed));
                }
            }
        }
        written.sort_unstable();
        written.dedup();
    }
    let mut names = Vec::new();
    let mut lines = Vec::new();
    for part in &this {
        let (name, part_lines) =
            part_lines(derivation, r, part, &elimination, &mut written, shown)?;
        names.push(name);
        lines.extend(part_lines);
    }
    lines.extend(kept_note(derivation, &elimination, &this, r));
    // A long part is written once: the whole, which would repeat it, is read in the sum;
    // an auxiliary row's whole is the reaction solved for just below, with its sign turned.
    let long = this
        .iter()
        .any(|p| latex_collected(&p.term).len() > LONGEST_REPEATED);
    let whole = if long || auxiliary { "" } else { whole };
    let block = super::aligned::sum_of_parts(
        &format!("\\tilde{{F}}^{{*}}_{{{r}}}"),
        &names,
        lines,
        whole,
        model.order.len() == 1,
    )?;
    // An auxiliary speed's F̃*_r body by body only where that is short: a long one is formed
    // from the table as the rows before it show, and printed whole.
    (!auxiliary || block.len() <= LONGEST_AUXILIARY).then_some(block)
}

/// The most characters of LaTeX an auxiliary speed's `F̃*_r` written body by body may take:
/// the four-bar's rows of the pins O and R, three bodies' terms each.
const LONGEST_AUXILIARY: usize = 2400;

/// The most characters of LaTeX an auxiliary speed's products of one body may take: longer,
/// they are the table's partial velocities times step 4's accelerations, and the term alone
/// is written.
const LONGEST_AUXILIARY_PRODUCTS: usize = 300;

/// The most characters of LaTeX one body's term of an auxiliary speed's `F̃*_r` may take.
const LONGEST_AUXILIARY_TERM: usize = 900;

/// Where the row keeps the dependent accelerations (replaced, they would make it too long
/// to read), the words that say where they are found, on the first row that has them.
fn kept_note(
    derivation: &Derivation,
    elimination: &Elimination,
    parts: &[Part],
    r: usize,
) -> Option<String> {
    if elimination.applies || r != 1 {
        return None;
    }
    let mut kept: Vec<usize> = parts
        .iter()
        .flat_map(|p| elimination.entering(&p.formed))
        .collect();
    kept.sort_unstable();
    kept.dedup();
    let problem = derivation.model.problem;
    let names: Vec<String> = kept
        .iter()
        .map(|&s| latex(&problem.coordinate_expr(elimination.speeds.dependent[s], 2)))
        .collect();
    let (list, are) = match names.as_slice() {
        [] => return None,
        [one] => (one.clone(), "is"),
        [rest @ .., last] => (format!("{}\\text{{ and }}{last}", rest.join(", ")), "are"),
    };
    Some(format!(
        "&\\text{{(}}{list}\\text{{ {are} kept: the constraints differentiated give them)}}"
    ))
}

#[cfg(test)]
mod tests;
