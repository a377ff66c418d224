//! The line of a spring or damper: its length ℓ, the unit vector û from its first point to
//! its second, and the rate ℓ̇ at which it stretches, each named once.
//!
//! A spring's force is then `k (ℓ − ℓ0) û` and a damper's `c ℓ̇ û`, as a textbook writes
//! them, instead of `√((x − a)² + (y − b)²)` multiplied through every term. When the two
//! points only ever differ along one unit vector, the length is that coordinate
//! expression itself, with the sign it has at the initial state (`x₁`, not `√(x₁²)`).

use crate::mechanics::{dot3, Components, MechanicsError, Model, Vector};
use crate::problem::{BodyId, PointRef, Problem};
use crate::symbolic::{add, eval, func, simplify, sqrt, time_derivative, Expr, Func};

/// The geometry of one spring or damper.
#[derive(Clone, Debug)]
pub struct Line {
    /// The two points, first to second.
    pub points: [PointRef; 2],
    /// The vector from the first point to the second.
    pub delta: Vector,
    /// Its length `ℓ` (a named symbol, or a coordinate expression along one unit vector).
    pub length: Expr,
    /// The unit vector `û` from the first point toward the second.
    pub unit: Vector,
    /// The rate of stretch `ℓ̇`.
    pub rate: Expr,
}

/// The lines met so far, so that a spring and a damper between the same points share
/// `ℓ₁`, `û₁` and `ℓ̇₁`.
#[derive(Debug, Default)]
pub struct Lines {
    lines: Vec<Line>,
}

const AXES: [&str; 3] = ["x", "y", "z"];

/// The most terms a component of the ends' relative velocity may have and still be written
/// into ℓ̇ = û·Δv; a longer one (an end on a long chain) is named, so that ℓ̇ reads as three
/// products instead of every rate times every direction cosine.
const MAX_INLINE_RATE_TERMS: usize = 2;

/// A point's name as the problem writes it.
fn point_name(problem: &Problem, point: PointRef) -> String {
    match point {
        PointRef::Named(i) => problem.points[i].name.clone(),
        PointRef::MassCenter(b) => format!("{}*", problem.body_name(b)),
        PointRef::Origin(b) => format!("{}.o", problem.body_name(b)),
        PointRef::Joint(j) => problem.joints[j].name.clone(),
    }
}

impl Lines {
    /// The line between `between`, built the first time it is asked for.
    ///
    /// # Errors
    /// When both points are on one body, or a rate cannot be differentiated.
    pub fn get(
        &mut self,
        model: &Model,
        between: &[PointRef; 2],
        path: &str,
    ) -> Result<&Line, MechanicsError> {
        let index = match self.lines.iter().position(|l| l.points == *between) {
            Some(index) => index,
            None => {
                let line = build(model, between, path, self.lines.len() + 1)?;
                self.lines.push(line);
                self.lines.len() - 1
            }
        };
        Ok(&self.lines[index])
    }
}

/// The frames a line is tried in: `N`, the two bodies and their parents.
fn candidate_frames(model: &Model, bodies: [BodyId; 2]) -> Vec<BodyId> {
    let mut frames = vec![BodyId::GROUND];
    for body in bodies {
        let parent = model.frames.info(body).parent;
        for frame in std::iter::once(body).chain(parent) {
            if !frames.contains(&frame) {
                frames.push(frame);
            }
        }
    }
    frames
}

fn build(
    model: &Model,
    between: &[PointRef; 2],
    path: &str,
    number: usize,
) -> Result<Line, MechanicsError> {
    let problem = model.problem;
    let ends = [model.locate(between[0]), model.locate(between[1])];
    if ends[0].0 == ends[1].0 {
        return Err(MechanicsError {
            path: format!("{path}.between"),
            message: format!(
                "both points are on `{}`, so the element can never stretch",
                problem.body_name(ends[0].0)
            ),
            hint: Some("connect points of two different bodies".into()),
        });
    }
    let first = model.point_on(ends[0].0, &ends[0].1);
    let second = model.point_on(ends[1].0, &ends[1].1);
    let delta = second.position.minus(&first.position);
    let delta_rate = second.velocity.minus(&first.velocity);
    // The frame in which the vector between the points has the fewest, then the shortest,
    // components.
    let (frame, components) = candidate_frames(model, [ends[0].0, ends[1].0])
        .into_iter()
        .map(|frame| {
            let c = delta
                .components_in(frame, &model.frames)
                .map(|e| simplify(&e));
            (frame, c)
        })
        .min_by_key(|(_, c)| {
            let nonzero = c.iter().filter(|e| !e.is_zero()).count();
            let length: usize = c.iter().map(Expr::operation_count).sum();
            (nonzero, length)
        })
        .unwrap_or((
            BodyId::GROUND,
            delta.components_in(BodyId::GROUND, &model.frames),
        ));
    let (from, to) = (
        point_name(problem, between[0]),
        point_name(problem, between[1]),
    );
    let nonzero: Vec<usize> = (0..3).filter(|&i| !components[i].is_zero()).collect();
    let (length, unit, rate) = if let [axis] = nonzero[..] {
        along_one_axis(
            model,
            frame,
            axis,
            &components[axis],
            path,
            (number, &from, &to),
        )?
    } else {
        named_line(model, frame, &components, &delta_rate, number, &from, &to)
    };
    Ok(Line {
        points: *between,
        delta: Vector::new(frame, components),
        length,
        unit,
        rate,
    })
}

/// Two points that differ along one unit vector only, by `c`: `ℓ = |c|` and `û = σ e`
/// with `σ = sgn c`, with no square root. The worked solution shows them with the sign `c`
/// has at the initial state (`ℓ₁ = a₁ + x₁`, `σ₁ = 1`), which holds as long as the points
/// do not cross; the numbers keep `|c|` and `sgn c`, which hold everywhere.
fn along_one_axis(
    model: &Model,
    frame: BodyId,
    axis: usize,
    c: &Expr,
    path: &str,
    (number, from, to): (usize, &str, &str),
) -> Result<(Expr, Vector, Expr), MechanicsError> {
    let problem = model.problem;
    let state = problem.initial_state();
    let initial = eval(c, &model.values_at(state.t, &state.q, &state.rates));
    let c_rate = time_derivative(c).map_err(|e| MechanicsError {
        path: path.to_string(),
        message: e.to_string(),
        hint: None,
    })?;
    let sign = if initial > 0.0 {
        Some(1)
    } else if initial < 0.0 {
        Some(-1)
    } else {
        None
    };
    let named = |name: &str, latex: String, note: String, value: Expr, shown: Option<Expr>| {
        let name = format!("line{number}.{name}");
        match shown {
            Some(shown) => Expr::named_shown(&name, &latex, &note, value, shown),
            None => Expr::named(&name, &latex, &note, value),
        }
    };
    let length = named(
        "l",
        format!("\\ell_{{{number}}}"),
        format!("distance from {from} to {to}"),
        func(Func::Abs, vec![c.clone()]),
        sign.map(|s| &Expr::int(s) * c),
    );
    let frame_name = model.frames.name(frame);
    let direction = named(
        "s",
        format!("\\sigma_{{{number}}}"),
        format!(
            "the sign of the unit vector from {from} toward {to} along {frame_name}.{}",
            AXES[axis]
        ),
        func(Func::Sign, vec![c.clone()]),
        sign.map(Expr::int),
    );
    let rate = &direction * &c_rate;
    Ok((length, Vector::unit(frame, axis).scaled(&direction), rate))
}

/// The general case: the components of `Δ` from the first point to the second, `ℓ = √(Δ·Δ)`,
/// `û = Δ/ℓ` and `ℓ̇ = û·Δ̇`, each a named symbol.
fn named_line(
    model: &Model,
    frame: BodyId,
    components: &Components,
    delta_rate: &Vector,
    number: usize,
    from: &str,
    to: &str,
) -> (Expr, Vector, Expr) {
    let frame_name = model.frames.name(frame).to_string();
    // "the x component, in frame N," as a textbook says it, not the internal `N.x`.
    let along = |axis: usize| format!("{} component, in frame {frame_name},", AXES[axis]);
    // A vector of the line by its components, each named `symbol` with the line's number
    // and the axis as its index: Δ₁ₓ, û₁ₓ, Δv₁ₓ.
    let component = |key: &str, symbol: &str, of: &str, axis: usize, value: Expr| {
        Expr::named(
            &format!("line{number}.{key}.{}", AXES[axis]),
            &format!("{symbol}_{{{number}{}}}", AXES[axis]),
            &format!("the {} of {of}", along(axis)),
            value,
        )
    };
    let delta: Components = std::array::from_fn(|axis| {
        let of = format!("the vector from {from} to {to}");
        component("d", "\\Delta", &of, axis, components[axis].clone())
    });
    let length = Expr::named(
        &format!("line{number}.l"),
        &format!("\\ell_{{{number}}}"),
        &format!("distance from {from} to {to}"),
        sqrt(dot3(&delta, &delta)),
    );
    let unit: Components = std::array::from_fn(|axis| {
        if components[axis].is_zero() {
            return Expr::zero();
        }
        let of = format!("the unit vector from {from} toward {to}");
        component("u", "\\hat{u}", &of, axis, &delta[axis] / &length)
    });
    let rates = delta_rate
        .components_in(frame, &model.frames)
        .map(|e| simplify(&e));
    let rates: Components = std::array::from_fn(|axis| {
        let rate = &rates[axis];
        if rate.terms().len() <= MAX_INLINE_RATE_TERMS {
            return rate.clone();
        }
        let of = format!("the velocity of {to} relative to {from}");
        component("dv", "\\Delta v", &of, axis, rate.clone())
    });
    let rate = Expr::named(
        &format!("line{number}.v"),
        &format!("\\dot{{\\ell}}_{{{number}}}"),
        &format!("rate at which the distance from {from} to {to} grows"),
        add((0..3).map(|i| &unit[i] * &rates[i])),
    );
    if let Some(d) = length.as_definition() {
        d.set_rate(&rate);
    }
    (length, Vector::new(frame, unit), rate)
}
