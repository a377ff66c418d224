//! Lagrange's equations as a course teaches them: the kinetic energy of every body, the
//! potential energy and the Lagrangian; the generalized forces of the loads without a
//! potential by virtual work; then per coordinate ∂L/∂q̇_r, its time derivative and ∂L/∂q_r
//! before the collected equation, and the multipliers with the reactions they are.

use super::long::LONG_EQUATION;
use crate::equations::{
    energy_derivative, energy_terms, joint_generalized_forces, lagrange_generalized_forces,
    lagrange_potential, partial_velocities, role, virtual_work, Derivation, Method, Role,
};
use crate::mechanics::{Model, Vector};
use crate::plan::{constraint_generalized_forces, ActionKind, Equation, Sum};
use crate::render::context::{GeneralizedForceRow, LagrangeView};
use crate::render::text::{MarkupLine, Math};
use crate::symbolic::{latex, latex_collected, simplify, Expr};

/// The plan's note: what the rows are and where the reactions come from.
pub fn plan_note(derivation: &Derivation) -> String {
    let model = &derivation.model;
    let mut note = "One equation per coordinate, Lagrange's equation, with the Lagrangian and the generalized forces of step 2.".to_string();
    if !model.constraints.rows.is_empty() {
        note.push_str(" Each constraint row brings a multiplier into every coordinate's equation; the multiplier is the reaction component that enforces the row, and the constraint rows, differentiated, close the system.");
    }
    if derivation
        .reaction_joints
        .iter()
        .any(|&j| j < model.problem.joints.len())
    {
        note.push_str(" A reaction at a joint does no work as the coordinates change: each component asked for is found by letting the joint give way along it by an auxiliary coordinate, zero in the motion, whose Lagrange equation gives the component.");
    }
    note
}

/// The coordinate whose equation `row` is (by Lagrange's equations), if it is one.
fn coordinate_of(model: &Model, row: &Equation) -> Option<usize> {
    let Sum::Generalized { speed } = &row.sum else {
        return None;
    };
    let problem = model.problem;
    (0..problem.coordinates.len()).find(|&r| problem.coordinate_symbol(r, 1).to_string() == *speed)
}

/// `\dot{q}_{1}` and `q_{1}` of coordinate `r`.
fn names(model: &Model, r: usize) -> (String, String) {
    let problem = model.problem;
    (
        latex(&problem.coordinate_expr(r, 1)),
        latex(&problem.coordinate_expr(r, 0)),
    )
}

/// The plan table's equation of a coordinate's row, `d/dt(∂L/∂q̇_r) − ∂L/∂q_r = Q_r`; of a
/// relaxed joint's row, the component it brings in.
pub fn equation_tex(derivation: &Derivation, sum: &Sum) -> Option<String> {
    if derivation.method != Method::Lagrange {
        return None;
    }
    let row = derivation.rows.iter().find(|row| row.sum == *sum)?;
    let model = &derivation.model;
    match coordinate_of(model, row) {
        Some(r) => Some(lagrange_tex(model, r)),
        None => Some(relaxed_tex(row)),
    }
}

/// The plan table's direction of one of Lagrange's rows: the coordinate whose equation it
/// is (`\delta q_{1}`, the variation the virtual work is taken along), or for a relaxed
/// joint's row the direction the joint is let give way (or turn) along.
pub fn direction_tex(derivation: &Derivation, row: &Equation) -> String {
    let model = &derivation.model;
    if let Some(r) = coordinate_of(model, row) {
        let (_, q) = names(model, r);
        return format!("\\delta {q}");
    }
    relaxed_direction(derivation, row).unwrap_or_default()
}

/// `\text{along } \hat{x}` (a force) or `\text{about } \hat{z}` (a moment) of the
/// reaction component a relaxed joint's row brings in.
fn relaxed_direction(derivation: &Derivation, row: &Equation) -> Option<String> {
    use crate::symbolic::ComponentKind;
    let model = &derivation.model;
    let (_, reaction) = super::relaxed::relaxed_reaction(derivation, row)?;
    let d = super::tex::vector_tex(model, &reaction.direction);
    Some(match reaction.kind {
        ComponentKind::Force => format!("\\text{{along }} {d}"),
        ComponentKind::Moment => format!("\\text{{about }} {d}"),
    })
}

/// A relaxed joint's row: the reaction component it brings in, `u \to F^{O}_{x}`.
fn relaxed_tex(row: &Equation) -> String {
    // The row of `u(O.Fx)` brings in the joint's own component; the multipliers of the
    // closures and contacts it also holds are not what it is written for.
    let joint = match &row.sum {
        Sum::Generalized { speed } => speed
            .strip_prefix("u(")
            .and_then(|s| s.split('.').next())
            .unwrap_or_default(),
        _ => "",
    };
    let reactions: Vec<crate::symbolic::Symbol> = row
        .unknowns
        .iter()
        .filter(|u| matches!(u, crate::symbolic::Symbol::Unknown(k) if k.site() == Some(joint)))
        .cloned()
        .collect();
    format!(
        "\\text{{relaxed along }} {}",
        super::tex::unknowns_tex(&reactions)
    )
}

/// `\frac{d}{dt} \frac{∂L}{∂\dot{q}_r} - \frac{∂L}{∂q_r} = Q_r`.
fn lagrange_tex(model: &Model, r: usize) -> String {
    let (rate, q) = names(model, r);
    format!(
        "\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}} \\frac{{\\partial L}}{{\\partial {rate}}} - \\frac{{\\partial L}}{{\\partial {q}}} = Q_{{{}}}",
        r + 1
    )
}

/// What step 5 writes of one of Lagrange's rows.
pub struct RowText {
    /// The heading.
    pub label_tex: String,
    /// Plain words after it.
    pub label: String,
    /// For a relaxed joint's row, its auxiliary coordinate in words (markup; empty for a
    /// coordinate's row).
    pub intro: String,
    /// The derivatives, one equation each, before the collected equation.
    pub lines: Vec<String>,
    /// What introduces the collected equation.
    pub note: String,
}

/// Step 5's text of `row` when it is a coordinate's (by Lagrange's equations), each
/// expression written as `shown` gives it; `None` for any other row.
pub fn row_text(
    derivation: &Derivation,
    row: &Equation,
    shown: &dyn Fn(&Expr) -> Expr,
) -> Option<RowText> {
    if derivation.method != Method::Lagrange {
        return None;
    }
    let model = &derivation.model;
    let Some(r) = coordinate_of(model, row) else {
        // A constraint row (no slip, a closure) is written as every method writes it.
        if !matches!(row.sum, Sum::Generalized { .. }) {
            return None;
        }
        // The auxiliary coordinate that lets the joint give way, its kinetic terms and its
        // generalized force, then its equation at zero coordinate and rate.
        let relaxed = super::relaxed::relaxed(derivation, row, shown);
        let (intro, lines) = relaxed.map_or_else(Default::default, |r| (r.intro, r.lines));
        // Said in full for the first reaction; the others are found as it was.
        let first = (derivation.rows.iter())
            .find(|r| super::relaxed::relaxed_reaction(derivation, r).is_some())
            .is_some_and(|r| std::ptr::eq(r, row));
        let note = match first {
            true => "Its equation at zero auxiliary coordinate and rate:",
            false => "Likewise:",
        };
        return Some(RowText {
            label_tex: relaxed_tex(row),
            label: String::new(),
            intro,
            lines,
            note: note.into(),
        });
    };
    let written = derivation.lagrange_terms.get(r).is_none_or(|t| t.written);
    let (momentum, momentum_rate, kinetic_partial, potential_partial, q_r, multipliers) =
        match derivation.lagrange_terms.get(r) {
            // The derivation's own, formed once.
            Some(t) => (
                t.momentum.clone(),
                t.momentum_rate.clone(),
                t.kinetic_partial.clone(),
                t.potential_partial.clone(),
                t.generalized_force.clone(),
                t.multipliers.clone(),
            ),
            None => {
                let bodies = energy_terms(model);
                let v = lagrange_potential(model);
                let terms = energy_derivative(model, (&bodies, &v), r, true).ok()?;
                let (q_r, multipliers) = lagrange_generalized_forces(model, &derivation.actions)
                    .into_iter()
                    .nth(r)?;
                (
                    terms.momentum,
                    terms.momentum_rate,
                    terms.kinetic_partial,
                    terms.potential_partial,
                    q_r,
                    multipliers,
                )
            }
        };
    let (rate, q) = names(model, r);
    let tex = |e: &Expr| latex_collected(&shown(&simplify(e)));
    let fits = |definition: String, value: String| {
        if value.len() > LONG_EQUATION {
            definition
        } else {
            format!("{definition} = {value}")
        }
    };
    // Derivatives of T too long to write out were not formed: named only.
    let kinetic = |definition: String, value: &Expr| {
        if written {
            fits(definition, tex(value))
        } else {
            definition
        }
    };
    let partial_l_rate = format!("\\frac{{\\partial L}}{{\\partial {rate}}}");
    let mut lines = vec![
        kinetic(
            format!("{partial_l_rate} = \\frac{{\\partial T}}{{\\partial {rate}}}"),
            &momentum,
        ),
        kinetic(
            format!("\\frac{{\\mathrm{{d}}}}{{\\mathrm{{d}}t}} {partial_l_rate}"),
            &momentum_rate,
        ),
        kinetic(
            format!(
                "\\frac{{\\partial L}}{{\\partial {q}}} = \\frac{{\\partial T}}{{\\partial {q}}} - \\frac{{\\partial V}}{{\\partial {q}}}"
            ),
            &(&kinetic_partial - &potential_partial),
        ),
    ];
    // Q_r of step 2 holds the constraint forces' terms, the multipliers, with the loads'.
    let q_name = format!("Q_{{{}}}", r + 1);
    let sum = format!(
        "\\sum_{{k}} \\lambda_{{k}} \\frac{{\\partial \\dot{{f}}_{{k}}}}{{\\partial {rate}}}"
    );
    let on_motion = |e: &Expr| tex(&on_the_motion(model, e));
    lines.push(match (multipliers.is_zero(), q_r.is_zero()) {
        (true, _) => fits(q_name, on_motion(&q_r)),
        (false, true) => fits(format!("{q_name} = {sum}"), on_motion(&multipliers)),
        (false, false) => fits(
            format!("{q_name} = {} + {sum}", on_motion(&q_r)),
            on_motion(&(&q_r + &multipliers)),
        ),
    });
    let note = "Lagrange's equation, collected by the second derivatives:";
    Some(RowText {
        label_tex: format!("{q}\\colon\\; {}", lagrange_tex(model, r)),
        label: "(Lagrange's equation of the coordinate)".into(),
        intro: String::new(),
        lines,
        note: note.to_string(),
    })
}

/// Step 2 by Lagrange's equations: every body's kinetic energy, `T`, `V` and `L`; the
/// generalized forces of the loads without a potential; the multipliers.
pub fn view(derivation: &Derivation) -> Option<LagrangeView> {
    if derivation.method != Method::Lagrange {
        return None;
    }
    let model = &derivation.model;
    Some(LagrangeView {
        energy_tex: Math::all(energies(model)),
        forces: force_rows(derivation),
        forces_note: MarkupLine::from(forces_note(derivation)),
        multipliers_note: MarkupLine::from(multipliers_note(derivation)),
    })
}

fn energies(model: &Model) -> Vec<String> {
    let sign = super::tex::initial_sign(model);
    let tex = |e: &Expr| latex_collected(&crate::symbolic::roots_of_squares(&simplify(e), &sign));
    let mut lines = Vec::new();
    let mut names = Vec::new();
    for body in energy_terms(model) {
        let name = crate::symbolic::latex_name(model.problem.body_name(body.body));
        let centre = super::tex::centre_tex(model, body.body);
        let v = format!("{{}}^{{N}}\\mathbf{{v}}^{{{centre}}}");
        let w = format!("{{}}^{{N}}\\boldsymbol{{\\omega}}^{{{name}}}");
        let moves = !body.velocity.map(simplify).is_zero();
        let turns = !body.omega.iter().all(|c| simplify(c).is_zero());
        let mut terms = Vec::new();
        if moves && !body.mass.is_zero() {
            terms.push(format!(
                "\\frac{{1}}{{2}} {} \\, {v} \\cdot {v}",
                latex(&body.mass)
            ));
        }
        if turns && !body.inertia.iter().flatten().all(Expr::is_zero) {
            terms.push(format!(
                "\\frac{{1}}{{2}} {w} \\cdot \\mathbf{{I}}^{{{name}}} \\cdot {w}"
            ));
        }
        if terms.is_empty() {
            continue;
        }
        let definition = format!("T_{{{name}}} = {}", terms.join(" + "));
        let value = tex(&body.kinetic());
        lines.push(if value.len() > LONG_EQUATION {
            definition
        } else {
            format!("{definition} = {value}")
        });
        names.push(format!("T_{{{name}}}"));
    }
    // One body's kinetic energy is the system's: named T at once, not T_D and then T = T_D.
    if let [name] = names.as_slice() {
        let last = lines.len() - 1;
        if let Some(rest) = lines[last].strip_prefix(name.as_str()) {
            lines[last] = format!("T{rest}");
        }
    } else if !names.is_empty() {
        lines.push(format!("T = {}", names.join(" + ")));
    }
    lines.push(format!(
        "V = {}",
        super::potential_tex::potential_tex(model)
    ));
    lines.push("L = T - V".into());
    lines
}

fn forces_note(derivation: &Derivation) -> String {
    let (names, plural) = super::potential_tex::sources(derivation);
    let listed = super::potential_tex::listed(&names);
    if force_rows(derivation).is_empty() {
        let what = match (names.is_empty(), plural) {
            (true, _) => "No load has a potential ($V = 0$)".to_string(),
            (false, true) => format!(
                "{} have a potential, in $V$",
                super::potential_tex::capitalized(&listed)
            ),
            (false, false) => format!(
                "{} has a potential, in $V$",
                super::potential_tex::capitalized(&listed)
            ),
        };
        return format!("{what}; no other load does work: $Q_r = 0$ for every coordinate.");
    }
    let model = &derivation.model;
    let constrained = derivation
        .actions
        .iter()
        .any(|a| role(model, a) == Role::Multiplier)
        || !constraint_generalized_forces(model)
            .iter()
            .all(|(c, _)| c.is_empty());
    let multipliers = if constrained {
        " (and of the constraint forces, whose components are the multipliers)"
    } else {
        ""
    };
    let in_v = match (names.is_empty(), plural) {
        (true, _) => String::new(),
        (false, true) => format!("; {listed} are in $V$"),
        (false, false) => format!("; {listed} is in $V$"),
    };
    format!(
        "The generalized forces of the loads without a potential{multipliers}, by virtual work:{}{in_v}.",
        " a force $\\mathbf{F}$ at a point $P$ adds $\\mathbf{F} \\cdot \\partial \\mathbf{v}^{P} / \\partial \\dot{q}_r$ to $Q_r$, a couple $\\mathbf{T}$ on a body $B$ adds $\\mathbf{T} \\cdot \\partial \\boldsymbol{\\omega}^{B} / \\partial \\dot{q}_r$"
    )
}

/// `e` simplified and written with what holds on the motion where that is shorter: a disc
/// in a cylinder's `r (x² + y²)/(R − r)² F_t` is `r F_t`, since `x² + y² = (R − r)²` there.
fn on_the_motion(model: &crate::mechanics::Model, e: &Expr) -> Expr {
    let simplified = simplify(e);
    let written = (model.constraints.relations.iter())
        .fold(simplified.clone(), |e, (_, relation)| relation.reduce(&e));
    match written.operation_count() < simplified.operation_count() {
        true => written,
        false => simplified,
    }
}

/// The table of generalized forces: a line per load and coordinate it does work with.
fn force_rows(derivation: &Derivation) -> Vec<GeneralizedForceRow> {
    let model = &derivation.model;
    let problem = model.problem;
    let tex = |e: &Expr| latex_collected(&on_the_motion(model, e));
    let mut rows = Vec::new();
    for action in &derivation.actions {
        if !matches!(role(model, action), Role::Load | Role::Multiplier) {
            continue;
        }
        let partials = partial_velocities(model, action);
        let work = virtual_work(model, action);
        let (point, of) = match &action.kind {
            ActionKind::Force { offset, .. } => {
                let at = Vector::new(action.body, offset.clone());
                let point = super::free_bodies::acts_at(model, action, &at);
                // The point by its name where the table has one: `\mathbf{v}^{B^*}`.
                let named = point
                    .strip_prefix("\\text{at } ")
                    .filter(|p| !p.contains("\\text") && !p.contains("\\hat"))
                    .unwrap_or("P");
                (point.clone(), format!("\\mathbf{{v}}^{{{named}}}"))
            }
            ActionKind::Couple { .. } => (
                super::free_bodies::anywhere_on(
                    model,
                    action.body,
                    &super::shown_names::shown_names(model),
                ),
                format!(
                    "\\boldsymbol{{\\omega}}^{{{}}}",
                    crate::symbolic::latex_name(problem.body_name(action.body))
                ),
            ),
        };
        let label = load_label(derivation, action);
        let mut first = true;
        for (r, (partial, work)) in partials.iter().zip(&work).enumerate() {
            if simplify(work).is_zero() {
                continue;
            }
            let (rate, _) = names(model, r);
            rows.push(GeneralizedForceRow {
                load: match std::mem::take(&mut first) {
                    true => label.clone(),
                    false => String::new(),
                }
                .into(),
                point_tex: Math::from(point.clone()),
                partial_tex: Math::from(format!(
                    "\\frac{{\\partial {of}}}{{\\partial {rate}}} = {}",
                    super::tex::shortest_tex(model, partial, action.body)
                )),
                q_tex: Math::from(format!("Q_{{{}}}\\colon\\; {}", r + 1, tex(work))),
            });
        }
    }
    // On the coordinates directly: joint dampers and actuators, a rough slider's friction,
    // and the multipliers of the rows without a site.
    let joint = joint_generalized_forces(model);
    for (r, q) in joint.iter().enumerate() {
        if simplify(q).is_zero() {
            continue;
        }
        rows.push(GeneralizedForceRow {
            load: super::lagrange_loads::direct_load_label(model, r, q).into(),
            point_tex: Math::from("\\text{joint}".to_string()),
            partial_tex: Math::from(String::new()),
            q_tex: Math::from(format!("Q_{{{}}}\\colon\\; {}", r + 1, tex(q))),
        });
    }
    for (row, (coordinates, values)) in model
        .constraints
        .rows
        .iter()
        .zip(constraint_generalized_forces(model))
    {
        for (c, value) in coordinates.into_iter().zip(values) {
            rows.push(GeneralizedForceRow {
                load: format!("multiplier of {}", row.name).into(),
                point_tex: Math::from("\\text{joint}".to_string()),
                partial_tex: Math::from(String::new()),
                q_tex: Math::from(format!("Q_{{{}}}\\colon\\; {}", c + 1, tex(&value))),
            });
        }
    }
    rows
}

/// A load's name in the table of generalized forces, as step 2's table of forces names it
/// (the contact force at P, the reaction force at O); where a reaction acts on two bodies of
/// the table, each is named with its body.
fn load_label(derivation: &Derivation, action: &crate::plan::Action) -> String {
    let model = &derivation.model;
    if role(model, action) != Role::Multiplier {
        return action.label.clone();
    }
    let shown = super::shown_names::shown_names(model);
    let label = super::force_labels::table_label(model, action, &shown);
    let shared = (derivation.actions.iter())
        .filter(|a| a.source == action.source && role(model, a) == Role::Multiplier)
        .any(|a| a.body != action.body);
    if !shared {
        return label;
    }
    let body = super::force_labels::shown_name(model.problem.body_name(action.body), &shown);
    format!("{label} on {body}")
}

/// Which reaction component each multiplier is, row by row of step 1, and its sign.
fn multipliers_note(derivation: &Derivation) -> String {
    let model = &derivation.model;
    let rows = &model.constraints.rows;
    if rows.is_empty() {
        return String::new();
    }
    let parts: Vec<String> = (rows.iter().enumerate())
        .map(|(k, row)| {
            // The row in words, as step 1's table names it, its direction as math.
            let what = super::row_names::constraint_what_tex(model, &row.name);
            let words = text_and_math(&what);
            let along = super::row_names::constraint_direction_tex(model, &row.name)
                .map(|d| format!(", along ${d}$"))
                .unwrap_or_default();
            format!(
                "$\\lambda_{{{}}} = {}$ ({words}{along}{})",
                k + 1,
                latex(&Expr::sym(row.unknown.clone())),
                row_rate(model, k + 1, &row.velocity)
            )
        })
        .collect();
    let multipliers = match parts.len() {
        1 => "Its multiplier is".to_string(),
        _ => "Their multipliers are".to_string(),
    };
    format!(
        "Each constraint row of step 1 enters with a multiplier $\\lambda_k$, the reaction \
         component that enforces it, positive along the arrow step 2 draws for it, and \
         $\\dot{{f}}_k$ is that row written as a velocity along the same arrow. \
         {multipliers} {}. The terms \
         $\\sum_k \\lambda_k\\, \\partial \\dot{{f}}_k / \\partial \\dot{{q}}_r$ of each \
         equation are the virtual work of those components; the constraint rows, differentiated, close the \
         system, and the reactions asked for are these multipliers.",
        parts.join(", ")
    )
}

/// A row's name as step 1 writes it in math, `\text{no slip at } P` or
/// `q_{1} \text{ held by its support}`, as prose: the words plain, the rest as math.
fn text_and_math(what: &str) -> String {
    let mut out = String::new();
    let mut rest = what;
    while let Some(at) = rest.find("\\text{") {
        let math = rest[..at].trim();
        if !math.is_empty() {
            out.push_str(&format!("${math}$"));
        }
        let after = &rest[at + "\\text{".len()..];
        let Some(end) = after.find('}') else {
            return format!("${what}$");
        };
        out.push_str(&after[..end]);
        rest = &after[end + 1..];
    }
    let math = rest.trim();
    if !math.is_empty() {
        out.push_str(&format!(" ${math}$"));
    }
    match out.contains('\\') && !out.contains('$') {
        true => format!("${what}$"),
        false => out.replace("  ", " ").trim().to_string(),
    }
}

/// `; ḟ_k = …`, the row as the velocity along its reaction's arrow, whose partials the
/// rows of step 5 take: step 1 may print the row with the other sign (a distance row as
/// `√(x² + y²) − R + r`, a row of negative terms turned), and only this one makes
/// `λ_k = F` true. Left out where it would not fit a line.
fn row_rate(model: &Model, k: usize, velocity: &Expr) -> String {
    let sign = super::tex::initial_sign(model);
    let rate = crate::symbolic::roots_of_squares(&on_the_motion(model, velocity), &sign);
    let written = latex_collected(&rate);
    match written.len() <= ROW_RATE_LONGEST {
        true => format!("; $\\dot{{f}}_{{{k}}} = {written}$"),
        false => String::new(),
    }
}

/// The longest `ḟ_k` written beside its multiplier, in LaTeX characters.
const ROW_RATE_LONGEST: usize = 160;

/// The student's handout: the energies' left sides and the loads of the table, the rest
/// left blank.
pub fn blank(view: LagrangeView) -> LagrangeView {
    let left = |x: &Math| {
        Math::from(
            x.as_str()
                .split(" = ")
                .next()
                .unwrap_or_default()
                .to_string(),
        )
    };
    LagrangeView {
        energy_tex: view.energy_tex.iter().map(left).collect(),
        forces: view
            .forces
            .into_iter()
            .map(|f| GeneralizedForceRow {
                partial_tex: Math::default(),
                q_tex: Math::default(),
                ..f
            })
            .collect(),
        forces_note: MarkupLine::default(),
        multipliers_note: MarkupLine::default(),
    }
}
