//! A Motion Law row's inertia terms written out as a student writes them between the row as
//! formed and its simplified form: for each body of the free body the position of its mass
//! centre from the moment point and `m a*` in one frame's unit vectors (the frame that writes
//! them shortest), the cross product's component along the row's direction, the inertia
//! torque in the body's own unit vectors, and the dot products of unit vectors the row uses;
//! in a force row `m a*` dotted with the direction term by term.

use super::tex::centre_tex;
use crate::equations::{Derivation, Method};
use crate::mechanics::cross3;
use crate::mechanics::Vector;
use crate::plan::{Direction, Equation, Sum};
use crate::problem::BodyId;
use crate::render::context::Equation as EquationView;
use crate::render::symbols;
use crate::render::text::Math;
use crate::symbolic::latex_collected;
use crate::symbolic::simplify;
use crate::symbolic::{add, Expr};
use crate::symbolic::{latex, latex_name, latex_unit_vector};

/// The most bodies of a free body whose terms are written out.
const MOST_BODIES: usize = 3;

/// The most characters of LaTeX one quantity of the display may take, broken over lines:
/// a longer one is read by the names of step 4 instead.
const LONGEST_LINE: usize = 600;

/// How many symbols (see [`symbols`]) a line holding both `r` and `m a*` may print.
const ONE_LINE: f64 = 56.0;

/// How many symbols one printed line of the display may take: the page's line.
const WIDEST_LINE: f64 = 66.0;

/// A row's inertia terms written out.
#[derive(Clone, Debug)]
pub struct WrittenOut {
    /// The terms as the row has them, body by body (each inertia force's part, then each
    /// inertia torque's, with the row's sign): their sum is the row's inertia groups.
    pub terms: Vec<Expr>,
    /// One `aligned` display, a line per quantity.
    pub tex: String,
}

/// The inertia terms of a Motion Law row of forces or moments (or of a Newton–Euler row of
/// moments), written out; `None` for another method or row, a free body of more than three
/// bodies, a body whose acceleration
/// step 4 writes by named parts, or a line too long for the page.
pub fn written_out(derivation: &Derivation, row: &Equation) -> Option<WrittenOut> {
    written_out_shown(derivation, row, &|e: &Expr| e.clone())
}

/// [`written_out`] with each component as `shown` prints it (the row's printing: a root of
/// a square taken by the initial sign, `√(c²)` as `c`), so that the lines read as the row.
pub fn written_out_shown(
    derivation: &Derivation,
    row: &Equation,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Option<WrittenOut> {
    // Newton–Euler's moment rows likewise: a reaction's r × F, the inertia torque.
    let moment_row = matches!(row.sum, Sum::Moment { .. });
    let method = derivation.method == Method::MotionLaw
        || (derivation.method == Method::NewtonEuler && moment_row);
    if !method || row.free_body.len() > MOST_BODIES {
        return None;
    }
    let inertia = derivation.inertia();
    if row.free_body.iter().any(|b| inertia.compact[b.0]) {
        return None;
    }
    let direction = row.direction.as_ref()?;
    let mut lines = Vec::new();
    let mut terms = Vec::new();
    let mut dots = Dots::default();
    for &body in &row.free_body {
        let written = match &row.sum {
            Sum::Force => force_lines(derivation, body, direction, &mut dots, shown),
            Sum::Moment { point, position } => moment_lines(
                derivation,
                body,
                (point, position),
                direction,
                (&mut dots, shown),
            ),
            _ => return None,
        };
        let Some((body_lines, body_terms)) = written else {
            continue;
        };
        lines.extend(body_lines);
        terms.extend(body_terms);
    }
    if let Sum::Moment { point, position } = &row.sum {
        // The reactions' moments first, each where it fits a line of the page.
        let point = super::moment_point::shown_point(&derivation.model, point, position);
        let point = super::tex::point_tex(&point);
        let at = (point.as_str(), position);
        let forces = super::force_moments::lines(derivation, &row.free_body, at, direction, shown);
        let fits = |l: &String| symbols(l) <= WIDEST_LINE && l.len() <= LONGEST_LINE;
        let forces: Vec<String> = forces.into_iter().filter(fits).collect();
        lines.splice(0..0, forces);
    }
    if lines.is_empty() {
        return None;
    }
    if let Some(line) = dots.line(direction) {
        lines.push(line);
    }
    // Every printed line within the page (a fraction too wide to break would stick out):
    // otherwise the row keeps the names of step 4 alone.
    let too_wide = lines
        .iter()
        .flat_map(|l| l.split(" \\\\ "))
        .any(|l| symbols(l) > WIDEST_LINE);
    if too_wide || lines.iter().any(|l| l.len() > LONGEST_LINE) {
        return None;
    }
    Some(WrittenOut {
        terms,
        tex: super::aligned::display(&lines),
    })
}

/// The dot products of unit vectors with the row's direction a row uses, in the order met.
#[derive(Default)]
struct Dots {
    used: Vec<(String, Expr)>,
}

impl Dots {
    /// `f̂_i · d̂` for a unit vector of `frame`, remembered when it is neither 0 nor 1.
    fn of(&mut self, derivation: &Derivation, frame: BodyId, axis: usize, d: &Direction) -> Expr {
        let frames = &derivation.model.frames;
        let value = simplify(&Vector::unit(frame, axis).dot(&d.vector, frames));
        let unit = latex_unit_vector(frames.name(frame), axis as u8);
        let trivial = value.is_zero() || value.is_one() || unit == d.latex;
        if !trivial && !self.used.iter().any(|(u, _)| *u == unit) {
            self.used.push((unit, value.clone()));
        }
        value
    }

    /// The line that lists them, `â_x · n̂_x = c_1, …` (none when there are none).
    fn line(&self, d: &Direction) -> Option<String> {
        if self.used.is_empty() {
            return None;
        }
        let items: Vec<String> = self
            .used
            .iter()
            .map(|(unit, value)| format!("{unit} \\cdot {} = {}", d.latex, latex(value)))
            .collect();
        let lines: Vec<String> = items.chunks(3).map(|c| c.join(",\\quad ")).collect();
        Some(format!(
            "&\\text{{with }} {}",
            lines.join(", \\\\ &\\quad ")
        ))
    }
}

/// A sum of written terms, `a + b - c`.
fn joined(terms: &[String]) -> String {
    let mut out = String::new();
    for t in terms {
        match (out.is_empty(), t.strip_prefix('-')) {
            (true, _) => out.push_str(t),
            (false, Some(rest)) => out.push_str(&format!(" - {rest}")),
            (false, None) => out.push_str(&format!(" + {t}")),
        }
    }
    if out.is_empty() {
        "0".into()
    } else {
        out
    }
}

/// A mass as a factor: in brackets when it is a sum.
fn mass_tex(mass: &Expr) -> String {
    if mass.terms().len() > 1 {
        format!("\\left({}\\right)", latex(mass))
    } else {
        latex(mass)
    }
}

/// `m_k a^{k*} · d̂` term by term: each of step 4's components times its unit vector's dot
/// product with the direction. The term the row has is minus it.
fn force_lines(
    derivation: &Derivation,
    body: BodyId,
    direction: &Direction,
    dots: &mut Dots,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Option<(Vec<String>, Vec<Expr>)> {
    let model = &derivation.model;
    let mass = &model.bodies[body.0].mass;
    if mass.is_zero() {
        return None;
    }
    let acceleration = &derivation.inertia().acceleration[body.0];
    let mut parts = Vec::new();
    let mut total: Vec<Expr> = Vec::new();
    for (frame, components) in acceleration.parts() {
        for (axis, c) in components.iter().enumerate() {
            if c.is_zero() {
                continue;
            }
            let dot = dots.of(derivation, *frame, axis, direction);
            total.push(c * &dot);
        }
    }
    // Simplified as one sum, not term by term: the terms of two components may cancel, or
    // meet in sin² + cos² (a top's s_ψ s_θ c²_θ + s_ψ s³_θ is s_ψ s_θ).
    let sum = shown(&simplify(&add(total)));
    parts.extend(sum.terms().iter().map(latex));
    let m = mass_tex(mass);
    let inside = joined(&parts);
    let value = if parts.len() > 1 {
        format!("{m} \\left( {inside} \\right)")
    } else {
        latex(&simplify(&(mass * &sum)))
    };
    let name = format!(
        "{m}\\, {{}}^{{N}}\\mathbf{{a}}^{{{}}} \\cdot {}",
        centre_tex(model, body),
        direction.latex
    );
    let line = super::aligned::line(&name, "=", &value);
    Some((vec![line], vec![-(mass * &sum)]))
}

/// The frames a vector may be written in: `N` and every frame of the problem.
fn candidate_frames(derivation: &Derivation) -> Vec<BodyId> {
    (0..derivation.model.frames.len()).map(BodyId).collect()
}

/// The frame in which `vectors` are written shortest, preferring one of whose unit vectors
/// the direction is one (the cross product's component is then a row of the determinant).
fn shortest_frame(derivation: &Derivation, vectors: &[&Vector], direction: &Direction) -> BodyId {
    let frames = &derivation.model.frames;
    let length = |frame: BodyId| -> usize {
        vectors
            .iter()
            .map(|v| {
                v.expressed_in(frame, frames)
                    .map(simplify)
                    .operation_count()
            })
            .sum()
    };
    let along = |frame: BodyId| axis_of(derivation, frame, direction).is_some();
    let candidates = candidate_frames(derivation);
    let preferred: Vec<BodyId> = candidates.iter().copied().filter(|f| along(*f)).collect();
    let pool = if preferred.is_empty() {
        candidates
    } else {
        preferred
    };
    pool.into_iter()
        .min_by_key(|f| (length(*f), f.0))
        .unwrap_or(BodyId::GROUND)
}

/// The axis of `frame` the direction is (as `(axis, sign)`), if it is one.
fn axis_of(derivation: &Derivation, frame: BodyId, direction: &Direction) -> Option<usize> {
    let frames = &derivation.model.frames;
    let components = direction
        .vector
        .components_in(frame, frames)
        .map(|c| simplify(&c));
    let ones: Vec<usize> = (0..3).filter(|&i| components[i].is_one()).collect();
    let zeros = components.iter().filter(|c| c.is_zero()).count();
    match ones.as_slice() {
        [axis] if zeros == 2 => Some(*axis),
        _ => None,
    }
}

/// Components in one frame written with their unit vectors, `a â_x + b â_y`.
fn components_tex(derivation: &Derivation, frame: BodyId, components: &[Expr; 3]) -> String {
    let v = Vector::new(frame, components.clone());
    super::tex::vector_tex(&derivation.model, &v)
}

/// A moment row's lines for one body: `r` and `m a*` in one frame, the cross product's
/// component along the direction, then the inertia torque's.
fn moment_lines(
    derivation: &Derivation,
    body: BodyId,
    (point, position): (&String, &Vector),
    direction: &Direction,
    (dots, shown): (&mut Dots, &dyn Fn(&Expr) -> Expr),
) -> Option<(Vec<String>, Vec<Expr>)> {
    let model = &derivation.model;
    let frames = &model.frames;
    let state = &model.bodies[body.0];
    let mut lines = Vec::new();
    let mut terms = Vec::new();
    let centre = centre_tex(model, body);
    let r = state.center.position.minus(position);
    let m_a = derivation.inertia().acceleration[body.0].scaled(&state.mass);
    let about_centre =
        (0..3).all(|i| simplify(&r.components_in(BodyId::GROUND, frames)[i]).is_zero());
    if !state.mass.is_zero() && !about_centre {
        let frame = shortest_frame(derivation, &[&r, &m_a], direction);
        let r_f = r.components_in(frame, frames).map(|c| shown(&simplify(&c)));
        let a_f = m_a
            .components_in(frame, frames)
            .map(|c| shown(&simplify(&c)));
        let point = super::moment_point::shown_point(model, point, position);
        let point = super::tex::point_tex(&point);
        let frame_name = frames.name(frame);
        let units = [0u8, 1, 2]
            .iter()
            .filter(|&&i| !(model.is_planar() && i == 2))
            .map(|&i| latex_unit_vector(frame_name, i))
            .collect::<Vec<_>>()
            .join(", ");
        let r_name = format!("\\mathbf{{r}}^{{{point} {centre}}}");
        let r_tex = components_tex(derivation, frame, &r_f);
        let m = mass_tex(&state.mass);
        let ma_name = format!("{m}\\, {{}}^{{N}}\\mathbf{{a}}^{{{centre}}}");
        let a_tex = components_tex(derivation, frame, &a_f);
        let in_frame = format!("\\quad \\text{{(in }} {units}\\text{{)}}");
        // Both on one line where they fit it, as a student writes two short vectors.
        let together = format!("{r_tex}, \\quad {ma_name} = {a_tex}");
        if symbols(&r_name) + symbols(&together) + symbols(&in_frame) <= ONE_LINE {
            lines.push(format!("{r_name} &= {together} {in_frame}"));
        } else {
            lines.push(format!(
                "{} {in_frame}",
                super::aligned::line(&r_name, "=", &r_tex)
            ));
            lines.push(super::aligned::line(&ma_name, "=", &a_tex));
        }
        let cross = cross3(&r_f, &a_f);
        let (pattern, value) = match axis_of(derivation, frame, direction) {
            Some(axis) => (determinant_row(axis), shown(&simplify(&cross[axis]))),
            None => {
                let value =
                    add((0..3).map(|i| &cross[i] * &dots.of(derivation, frame, i, direction)));
                ("".to_string(), shown(&simplify(&value)))
            }
        };
        // The row holds the inertia force −m a, so its moment is written with that sign: a
        // student who reads r × m a beside the row's opposite term sees a sign error.
        let left = format!("({r_name} \\times (-{ma_name})) \\cdot {}", direction.latex);
        let term = -value;
        let right = format!("{pattern}{}", latex_collected(&simplify(&term)));
        lines.push(super::aligned::line(&left, "=", &right));
        terms.push(term);
    }
    if let Some((line, term)) = torque_line(derivation, body, direction, (dots, shown)) {
        lines.push(line);
        terms.push(term);
    }
    (!lines.is_empty()).then_some((lines, terms))
}

/// `-(r_x (m a)_y - r_y (m a)_x) = ` for the component along axis `axis` (the determinant's
/// row, of the inertia force −m a).
fn determinant_row(axis: usize) -> String {
    let names = ["x", "y", "z"];
    let (j, k) = ((axis + 1) % 3, (axis + 2) % 3);
    format!(
        "-\\left(r_{{{}}}\\, (m a)_{{{}}} - r_{{{}}}\\, (m a)_{{{}}}\\right) = ",
        names[j], names[k], names[k], names[j]
    )
}

/// The inertia torque `−I·α − ω×I·ω` of `body` in its own unit vectors, dotted with the
/// direction; `None` for a particle.
fn torque_line(
    derivation: &Derivation,
    body: BodyId,
    direction: &Direction,
    (dots, shown): (&mut Dots, &dyn Fn(&Expr) -> Expr),
) -> Option<(String, Expr)> {
    let model = &derivation.model;
    let torque = &derivation.inertia().torque[body.0];
    let mut value = Vec::new();
    let mut parts = Vec::new();
    let mut along_one = false;
    for (frame, components) in torque.parts() {
        for (axis, c) in components.iter().enumerate() {
            let c = shown(&simplify(c));
            if c.is_zero() {
                continue;
            }
            let dot = dots.of(derivation, *frame, axis, direction);
            if dot.is_zero() {
                continue;
            }
            along_one = dot.is_one();
            parts.push((frame, axis, c.clone()));
            value.push(&c * &dot);
        }
    }
    if value.is_empty() {
        return None;
    }
    let value = shown(&simplify(&add(value)));
    let k = latex_name(model.problem.body_name(body));
    let named = super::long::inertia_torque_terms(&k, model.is_planar())
        .iter()
        .map(|t| format!("- {t}"))
        .collect::<Vec<_>>()
        .join(" ");
    // Its components in the body's unit vectors, each named, before the dot product.
    let components: Vec<String> = parts
        .iter()
        .map(|(frame, axis, c)| {
            super::tex::component_term(
                c,
                &latex_unit_vector(model.frames.name(**frame), *axis as u8),
            )
        })
        .collect();
    let whole = joined(&components);
    let dotted = if parts.len() == 1 && along_one {
        String::new()
    } else {
        format!("\\left( {whole} \\right) \\cdot {} = ", direction.latex)
    };
    let left = format!("\\left( {named} \\right) \\cdot {}", direction.latex);
    let right = format!("{dotted}{}", latex_collected(&value));
    let line = super::aligned::line(&left, "=", &right);
    Some((line, value))
}

/// A mass centre's `m a*` written once: a later row that would write the same line again
/// (a body in several free bodies, its acceleration in the same unit vectors) leaves it
/// out, since its cross product names it.
pub fn drop_repeated(views: &mut [EquationView]) {
    const OPEN: &str = "\\begin{aligned} ";
    const CLOSE: &str = " \\end{aligned}";
    let mut seen: Vec<String> = Vec::new();
    for view in views.iter_mut() {
        let Some(inner) = view
            .written_tex
            .strip_prefix(OPEN)
            .and_then(|t| t.strip_suffix(CLOSE))
        else {
            continue;
        };
        // Each quantity with the lines it continues on.
        let mut groups: Vec<Vec<&str>> = Vec::new();
        for line in inner.split(" \\\\ ") {
            match groups.last_mut() {
                Some(group) if line.starts_with("&\\quad") => group.push(line),
                _ => groups.push(vec![line]),
            }
        }
        let is_acceleration = |first: &str| {
            first.contains("\\mathbf{a}^{")
                && !first.contains("\\cdot")
                && !first.contains("\\times")
                && !first.contains("\\mathbf{r}^{")
        };
        let mut kept: Vec<String> = Vec::new();
        for group in groups {
            let text = group.join(" \\\\ ");
            if is_acceleration(group[0]) {
                if seen.contains(&text) {
                    continue;
                }
                seen.push(text.clone());
            }
            kept.push(text);
        }
        view.written_tex = Math::from(super::aligned::display(&kept));
    }
}
