//! The parts of the worked solution that constrained systems add: the constraint rows as
//! equations (step 1), the dependent rates as a map of the independent ones, Kane's
//! equations with dependent speeds and the reduced partial velocities (step 5).

use super::row_names::{constraint_label_tex, constraint_what_tex};
use crate::equations::Derivation;
use crate::mechanics::{Model, RowOrigin, Vector};
use crate::problem::BodyId;
use crate::render::context::{ConstraintView, DependentSpeeds};
use crate::render::text::{MarkupLine, Math};
use crate::symbolic::{
    fixed, fixed_or_zero, latex, latex_collected, latex_name, roots_of_squares, simplify, Expr,
    Node, Symbol,
};

/// The longest equation (LaTeX characters) the constraint table's narrow column holds;
/// a longer one, lines of a few terms each, would run over pages.
const LONGEST_IN_TABLE: usize = 600;

/// A row `= 0` whose terms are all negative with their signs turned: `r_A q̇_A + r_B q̇_B
/// = 0`, as a textbook writes it, never `−r_A q̇_A − r_B q̇_B = 0`.
pub(super) fn signs_turned(row: Expr) -> Expr {
    let negative = |t: &Expr| t.split_coefficient().0.is_negative();
    let all_negative = match row.node() {
        Node::Add(terms) => terms.iter().all(negative),
        _ => negative(&row),
    };
    match all_negative {
        true => -row,
        false => row,
    }
}

/// The angle `q` where `e` is `sin q` and `q` starts at zero: the row holds it at zero.
fn held_angle(problem: &crate::problem::Problem, e: &Expr) -> Option<String> {
    (0..problem.coordinates.len())
        .find(|&i| {
            problem.coordinates[i].initial.abs() < 1e-12
                && *e == crate::symbolic::sin(problem.coordinate_expr(i, 0))
        })
        .map(|i| latex(&problem.coordinate_expr(i, 0)))
}

/// Step 1: every constraint row as an equation (position level when it has one), and the
/// notes on what the constraints solve for.
pub fn constraints(derivation: &Derivation) -> (Vec<ConstraintView>, Vec<String>) {
    let model = &derivation.model;
    let constraints = &model.constraints;
    let sign = super::tex::initial_sign(model);
    // The contact points whose velocity a long row is written with, each defined once.
    let mut velocities: Vec<usize> = Vec::new();
    let mut views: Vec<ConstraintView> = constraints
        .rows
        .iter()
        .map(|row| {
            let (level, expression) = match &row.position {
                Some(p) => ("position", p),
                None => ("velocity", &row.velocity),
            };
            let shown = signs_turned(roots_of_squares(&simplify(expression), &sign));
            // A velocity constraint collected by the rates, as Σ (coefficient) q̇_j = 0.
            let mut equation_tex = format!("{} = 0", latex_collected(&shown));
            // sin q = 0 with q at zero: the angle held at zero, as a course writes it.
            if let Some(q) = held_angle(model.problem, &shown) {
                equation_tex = format!("{q} = 0");
            }
            // A position constraint holds a distance, not a component: it has no direction;
            // a loop's closure holds a point in two directions, each row named by its own.
            let closure = matches!(row.origin, RowOrigin::Site { site, .. }
                if matches!(model.sites[site].kind, crate::mechanics::SiteKind::Closure(_)));
            let name_tex = match row.position {
                Some(_) if !closure => constraint_what_tex(model, &row.name),
                _ => constraint_label_tex(model, &row.name),
            };
            if let (true, None, RowOrigin::Site { site, component }) = (
                equation_tex.len() > LONGEST_IN_TABLE,
                &row.position,
                &row.origin,
            ) {
                // Multiplied out, a contact's velocity across a chain of frames is long;
                // as the contact point's velocity along the reaction's direction it reads
                // as a textbook writes the constraint.
                if let Some(direction) = model.sites[*site].row_direction(*component) {
                    equation_tex = format!(
                        "{} \\cdot {} = 0",
                        point_velocity_tex(model, *site),
                        super::tex::vector_tex(model, direction)
                    );
                    if !velocities.contains(site) {
                        velocities.push(*site);
                    }
                }
            }
            ConstraintView {
                name_tex: Math::from(name_tex),
                level: level.into(),
                below: equation_tex.len() > LONGEST_IN_TABLE,
                equation_tex: Math::from(equation_tex),
            }
        })
        .collect();
    for site in velocities {
        let equation_tex = contact_velocity_tex(model, site);
        views.push(ConstraintView {
            name_tex: Math::from(format!(
                "\\text{{the velocity of the contact point at {}}}",
                crate::render::escape_latex(&model.sites[site].name, crate::render::Lines::One)
            )),
            level: "definition".into(),
            below: equation_tex.len() > LONGEST_IN_TABLE,
            equation_tex: Math::from(equation_tex),
        });
    }
    // Notes are written for the terminal, with `code` quotes; a handout shows the quoted
    // coordinates and rates as symbols (the notes are markup, see `markup`).
    let problem = derivation.model.problem;
    let mut notes: Vec<String> = constraints
        .notes
        .iter()
        .map(|n| quoted_as_math(problem, n))
        .collect();
    notes.extend(constraints.dropped.iter().map(|(row, why)| {
        // `teeth.height`: the height constraint of the contact teeth.
        let (site, what) = row.split_once('.').unwrap_or((row.as_str(), "position"));
        match dropped_in_words(&derivation.model, site, what) {
            Some(words) => words,
            None => {
                format!("The {what} constraint at {site} is not needed: {why}.").replace('`', "")
            }
        }
    }));
    notes.extend(constraints.relations.iter().map(|(name, relation)| {
        let tangent = super::polar_units::tangent_definition(&derivation.model);
        let unit = match (line_of_centres(problem, relation), tangent) {
            (Some(tex), Some(t)) => format!(
                "${tex}$ is a unit vector, and so is ${t}$, along the common tangent"
            ),
            (Some(tex), None) => format!("${tex}$ is a unit vector"),
            (None, _) => "the line of centres, divided by the distance the constraint keeps, is a unit vector".into(),
        };
        let root_of = crate::symbolic::latex(&relation.square);
        let root = crate::symbolic::latex(&relation.root);
        format!(
            "Wherever the distance constraint of {} holds, ${}$: {unit}. From here on $\\sqrt{{{root_of}}}$ is replaced by ${root}$, the value the constraint gives it.",
            super::force_labels::place(name),
            relation.latex()
        )
    }));
    (views, notes)
}

/// A contact's constraint that its joints already hold, named by the bodies it would hold:
/// "the joints already keep the pinion on the rack"; `None` for another kind of row.
fn dropped_in_words(model: &Model, site: &str, what: &str) -> Option<String> {
    let found = model.sites.iter().find(|s| s.name == site)?;
    let words = |b| super::joint_words::body_words(model.problem, b);
    let (body, on) = (words(found.child), words(found.parent));
    match what {
        "height" => Some(format!(
            "The joints keep {body} on {on}, so the two stay in contact without an equation for it; the joints carry the normal load."
        )),
        "distance" => Some(format!(
            "The joints hold the centres of {body} and {on} at the distance at which their pitch circles touch, so the teeth stay in mesh without an equation for it; the joints carry the push along the line of centres."
        )),
        _ => None,
    }
}

/// `ê_r = (x n̂_x + y n̂_y)/(R − r)`: the line of centres as a unit vector, where the
/// relation's square is `x² + y²` of the coordinates along `N`'s axes of a planar joint on
/// the ground; `None` otherwise.
fn line_of_centres(
    problem: &crate::problem::Problem,
    relation: &crate::symbolic::Relation,
) -> Option<String> {
    let parts: Vec<String> = (super::polar_units::planar_squares(problem, relation)?.iter())
        .map(|&(i, axis)| {
            format!(
                "{} {}",
                latex(&problem.coordinate_expr(i, 0)),
                crate::symbolic::latex_unit_vector("N", axis as u8)
            )
        })
        .collect();
    (parts.len() == 2).then(|| {
        format!(
            "\\hat{{\\mathbf{{e}}}}_{{r}} = \\frac{{{}}}{{{}}}",
            parts.join(" + "),
            latex(&relation.root)
        )
    })
}

/// The velocity of the child's material point at a contact as a textbook forms it, from
/// the body's mass centre: ᴺv^P = ᴺv^{F*} + ᴺω^F × r^{F*P}, both named in step 4, with the
/// arm r^{F*P} written out. Multiplied out across the chain of frames it would fill lines.
fn contact_velocity_tex(model: &Model, site: usize) -> String {
    let contact = &model.sites[site];
    let body = contact.child;
    let center = &model.bodies[body.0].center_offset;
    let arm = Vector::sum((0..3).map(|axis| {
        Vector::unit(body, axis).scaled(&(&contact.child_offset[axis] - &center[axis]))
    }));
    let name = latex_name(model.problem.body_name(body));
    let centre = super::tex::centre_tex(model, body);
    let point = latex_name(&contact.name);
    format!(
        "{} = {{}}^{{N}}\\mathbf{{v}}^{{{centre}}} + {{}}^{{N}}\\boldsymbol{{\\omega}}^{{{name}}} \\times \\mathbf{{r}}^{{{centre} {point}}}, \\quad \\mathbf{{r}}^{{{centre} {point}}} = {}",
        point_velocity_tex(model, site),
        super::tex::vector_tex(model, &arm)
    )
}

/// `{}^{N}\mathbf{v}^{P}` for the contact point of site `site`.
fn point_velocity_tex(model: &Model, site: usize) -> String {
    format!(
        "{{}}^{{N}}\\mathbf{{v}}^{{{}}}",
        latex_name(&model.sites[site].name)
    )
}

/// The dependent rates as a linear map of the independent ones at the (assembled) initial
/// state, and Kane's equations with dependent speeds, which eliminate the constraint forces.
pub fn dependent_speeds(
    derivation: &Derivation,
    q: &[f64],
    rates: &[f64],
) -> Option<DependentSpeeds> {
    if let Some(speeds) = &derivation.dependent_speeds {
        return Some(super::independent::dependent_speeds(
            derivation, speeds, q, rates,
        ));
    }
    let model = &derivation.model;
    let problem = model.problem;
    let reducer = crate::numeric::Reducer::new(model);
    let inputs = crate::numeric::input_values(problem, 0.0, q, rates);
    let (dependent, c) = reducer.dependent_rate_map(&inputs);
    if dependent.is_empty() || reducer.rates.is_empty() {
        return None;
    }
    // Rates the constraints hold at zero (a contact's ẏ = 0) depend on no independent rate:
    // the constraint rows say so already, and "the dependent rates from the independent
    // ones" would not be true of them.
    if c.iter().all(|x| *x == 0.0) && !problem.moves_with_time() {
        return None;
    }
    let rate = |i: usize| latex(&problem.coordinate_expr(i, 1));
    let column = |list: &[usize]| {
        format!(
            "\\begin{{bmatrix}} {} \\end{{bmatrix}}",
            list.iter()
                .map(|&i| rate(i))
                .collect::<Vec<_>>()
                .join(" \\\\ ")
        )
    };
    let rows: Vec<String> = (0..c.nrows())
        .map(|r| {
            (0..c.ncols())
                .map(|k| fixed(if c[(r, k)] == 0.0 { 0.0 } else { c[(r, k)] }))
                .collect::<Vec<_>>()
                .join(" & ")
        })
        .collect();
    let relation_tex = format!(
        "{} = \\begin{{bmatrix}} {} \\end{{bmatrix}} {}",
        column(&dependent),
        rows.join(" \\\\ "),
        column(&reducer.rates)
    );
    // The same map as equations, in symbols where they are short (θ̇ = ẋ/r), else in
    // numbers, ẋ = −0.3 θ̇_R, for the handouts that need no C by name.
    let values = model.values_at(0.0, q, rates);
    let symbolic = super::relations::in_symbols(model, &dependent, &reducer.rates, &c, &values)
        .or_else(|| {
            super::loop_relations::written(model, (&dependent, &reducer.rates), &c, &values)
        });
    let relations_tex = dependent
        .iter()
        .enumerate()
        .map(|(d, &s)| {
            let terms = reducer
                .rates
                .iter()
                .enumerate()
                .map(|(k, &r)| (c[(d, k)], rate(r)));
            format!(
                "{} = {}",
                rate(s),
                super::tex::numeric_sum(terms, 0.0).unwrap_or("0".into())
            )
        })
        .map(Math::from)
        .collect();
    // Relations in symbols hold at every state: the values at the start are said apart.
    let start_tex = start_values(problem, &dependent, rates, symbolic.as_deref());
    let relations_tex = match symbolic {
        Some(written) => written.into_iter().map(Math::from).collect(),
        None => relations_tex,
    };
    let kane_tex = "\\left(F_r + F_r^*\\right) + \\sum_{s} C_{sr} \\left(F_s + F_s^*\\right) = 0, \\quad r \\text{ independent}, \\; s \\text{ dependent}".to_string();
    let reduced = reduced_partials(model, (&dependent, &reducer.rates), &c, &values);
    Some(DependentSpeeds {
        relation_tex: Math::from(relation_tex),
        relations_tex,
        kane_tex: Math::from(kane_tex),
        reduced_tex: Math::all(reduced),
        kane_kept_note: MarkupLine::from(
            derivation
                .kept_forces
                .map(|why| {
                    format!(
                    "Kane's rows here keep the forces that enforce the constraints as unknowns, \
                     rather than take the independent speeds alone: {}.",
                    why.reason()
                )
                })
                .unwrap_or_default(),
        ),
        time_terms: problem.moves_with_time(),
        start_tex,
        ..DependentSpeeds::default()
    })
}

/// The reduced partial velocities of every mass centre at the initial state,
/// ṽ_r = v_r + Σ_s C_sr v_s, for each independent rate of `rates` (dependent, independent).
fn reduced_partials(
    model: &Model,
    (dependent, independent): (&[usize], &[usize]),
    c: &nalgebra::DMatrix<f64>,
    values: &crate::symbolic::Values,
) -> Vec<String> {
    let problem = model.problem;
    let rate = |i: usize| latex(&problem.coordinate_expr(i, 1));
    let all_rates: Vec<Symbol> = (0..problem.coordinates.len())
        .map(|i| problem.coordinate_symbol(i, 1))
        .collect();
    let mut reduced = Vec::new();
    for body in problem.body_ids() {
        let partials =
            crate::equations::partials(&model.bodies[body.0].center.velocity, &all_rates);
        let numbers: Vec<[f64; 3]> = partials
            .iter()
            .map(|v| {
                let c = v.components_in(BodyId::GROUND, &model.frames);
                std::array::from_fn(|k| crate::symbolic::eval(&c[k], values))
            })
            .collect();
        let centre = super::tex::centre_tex(model, body);
        for (k, &r) in independent.iter().enumerate() {
            let mut v = numbers[r];
            for (d, &s) in dependent.iter().enumerate() {
                for (i, x) in v.iter_mut().enumerate() {
                    *x += c[(d, k)] * numbers[s][i];
                }
            }
            let units = ["x", "y", "z"]
                .iter()
                .zip(v)
                .map(|(axis, x)| (x, format!("\\hat{{\\mathbf{{n}}}}_{{{axis}}}")));
            let terms = super::tex::numeric_sum(units, 1e-13).unwrap_or("\\mathbf{0}".into());
            reduced.push(format!(
                "\\tilde{{\\mathbf{{v}}}}^{{{centre}}}_{{{}}} = {terms}",
                rate(r)
            ));
        }
    }
    reduced
}

/// Where the relations are written in symbols (they hold in general), each dependent
/// rate's value at the start, unless the relations are those values already (ẏ = 0).
fn start_values(
    problem: &crate::problem::Problem,
    dependent: &[usize],
    rates: &[f64],
    symbolic: Option<&[String]>,
) -> Vec<Math> {
    let rate = |i: usize| latex(&problem.coordinate_expr(i, 1));
    let start: Vec<String> = (dependent.iter())
        .map(|&s| format!("{} = {}", rate(s), fixed_or_zero(rates[s])))
        .collect();
    // Said with their units, unless the relations are those values already.
    let with_units = (dependent.iter()).zip(&start).map(|(&s, value)| {
        let unit = crate::numeric::coordinate_unit(problem, s, 1);
        format!("{value}{}", super::answer_numbers::unit_tex(&unit))
    });
    match symbolic {
        Some(written) if written != start.as_slice() => Math::all(with_units.collect()),
        _ => Vec::new(),
    }
}

/// `text` with each `q1` or `x'` between backquotes written as the math of that coordinate
/// or rate, `$q_{1}$`, `$\dot{x}$`; any other quoted text plain.
fn quoted_as_math(problem: &crate::problem::Problem, text: &str) -> String {
    let mut out = String::new();
    for (i, part) in text.split('`').enumerate() {
        if i % 2 == 0 {
            out.push_str(part);
            continue;
        }
        let order = part.chars().rev().take_while(|c| *c == '\'').count();
        let name = &part[..part.len() - order];
        match problem.coordinates.iter().position(|c| c.name == name) {
            Some(c) if order <= 2 => {
                let symbol = crate::symbolic::latex(&problem.coordinate_expr(c, order as u8));
                out.push_str(&format!("${symbol}$"));
            }
            _ => out.push_str(part),
        }
    }
    out
}
