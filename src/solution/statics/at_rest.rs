//! The dynamic worked solution brought to rest: the rows at rest (the stages brought them
//! there), no inertia forces on the free bodies, no kinetic diagrams, the kinematics
//! reduced to positions, no matrix of q'' and no simulation.

use crate::equations::{Derivation, Method};
use crate::problem::Problem;
use crate::render::context::{Kinematics, Simulation, StaticsView};
use crate::render::draw::View;
use crate::render::text::{MarkupLine, Math};
use crate::render::Solution;
use crate::symbolic::Symbol;
use crate::Worked;

/// Leaves out of step 3 and step 5 the rows that are identically zero at rest, and counts
/// what the rest find.
fn keep_rows(solution: &mut Solution, derivation: &Derivation, zero: &[bool]) {
    let keep = |i: usize| !zero.get(i).copied().unwrap_or(false);
    let mut i = 0;
    solution.plan.rows.retain(|_| {
        i += 1;
        keep(i - 1)
    });
    let mut i = 0;
    solution.equations.retain(|_| {
        i += 1;
        keep(i - 1)
    });
    let mut unknowns: Vec<&Symbol> = Vec::new();
    for (k, row) in derivation.rows.iter().enumerate() {
        for u in row.unknowns.iter().filter(|_| keep(k)) {
            if !unknowns.contains(&u) {
                unknowns.push(u);
            }
        }
    }
    solution.plan.equations_count = solution.plan.rows.len();
    solution.plan.unknowns_count = unknowns.len();
}

/// Whether a line of math speaks of motion: a rate, a second derivative, an acceleration,
/// an angular velocity or acceleration, a kinetic energy.
pub fn speaks_of_motion(tex: &str) -> bool {
    [
        "\\dot",
        "\\ddot",
        "\\mathbf{a}",
        "\\boldsymbol{\\alpha}",
        "\\mathbf{v}^{",
        "\\omega",
    ]
    .iter()
    .any(|word| tex.contains(word))
}

/// Takes out of `solution` what a body at rest does not have: inertia forces, velocities
/// and accelerations, the q'' and their matrix, Kane's generalized inertia forces,
/// Lagrange's kinetic energy and its derivatives, the simulation.
pub fn strip(solution: &mut Solution, derivation: &Derivation, zero: &[bool]) {
    keep_rows(solution, derivation, zero);
    for row in &mut solution.plan.rows {
        row.equation_tex = Math::from(label_at_rest(row.equation_tex.as_str()));
    }
    for equation in &mut solution.equations {
        equation.label_tex = Math::from(label_at_rest(equation.label_tex.as_str()));
        if equation
            .simplified_note
            .contains("collected by the second derivatives")
        {
            equation.simplified_note = "At rest, with the kinetic energy zero:".into();
        }
    }
    for body in &mut solution.free_bodies {
        body.inertia.clear();
    }
    solution.kinematics = std::mem::take(&mut solution.kinematics)
        .into_iter()
        .filter(|k| !k.position_tex.is_empty())
        .map(|k| Kinematics {
            body: k.body,
            particle: k.particle,
            light: k.light,
            position_tex: k.position_tex,
            ..Kinematics::default()
        })
        .collect();
    solution
        .kinematic_definitions
        .retain(|d| !d.definitions_tex.iter().any(|x| speaks_of_motion(x)));
    for equation in &mut solution.equations {
        equation.inertia_tex = Math::default();
        equation.lagrange_tex.clear();
    }
    if let Some(lagrange) = &mut solution.lagrange {
        lagrange.energy_tex.retain(|x| x.as_str().starts_with('V'));
    }
    solution.initial_values.clear();
    solution.matrix = Default::default();
    // The solve in two stages is of accelerations and reactions; at rest step 5 says its own.
    solution.solve_notes.clear();
    // No inertia term to write out at rest.
    for equation in &mut solution.equations {
        equation.written_tex = Default::default();
    }
    solution.dependent_speeds = None;
    solution.friction.clear();
    solution.simulation = Simulation::default();
    solution.plan.note = MarkupLine::from(plan_note(derivation));
    solution.linearization = None;
}

/// What step 3's plan does at rest, method by method.
fn plan_note(derivation: &Derivation) -> String {
    match derivation.method {
        Method::MotionLaw => "At rest the inertia forces are zero, so each row is a sum of the contact and distance forces alone. Rows are chosen so that no unwanted reaction appears: moments about the point where the reactions not sought meet, sums of forces along a direction they are perpendicular to; the fewest new unknowns at a time.",
        Method::NewtonEuler => "Every body is a free body, its forces and its moments about its mass centre summing to zero; the unknowns are every reaction component and the equilibrium configuration.",
        Method::Kane => "At rest every generalized inertia force is zero: one row per generalized speed, its generalized active force equal to zero, and one per reaction asked for, through an auxiliary speed.",
        Method::Lagrange => "At rest the kinetic energy and its derivatives vanish: for each coordinate, $\\partial V / \\partial q_r = Q_r$ (the generalized forces of the loads without a potential and of the multipliers).",
    }
    .to_string()
}

/// Step 2's free bodies drawn without kinetic diagrams, and the configuration, at the
/// equilibrium.
pub fn draw(solution: &mut Solution, worked: &Worked) {
    let drawings = crate::solution::pictures::draw_at_rest(
        &worked.derivation,
        &worked.q0,
        &worked.rates0,
        View::Isometric,
    );
    for drawing in &drawings {
        if drawing.free_body.is_empty() {
            solution.configuration = drawing.figure();
        } else if let Some(body) = solution
            .free_bodies
            .iter_mut()
            .find(|b| b.name == drawing.free_body)
        {
            body.figure = if crate::solution::free_bodies::table_is_narrow(body) {
                drawing.figure_beside_a_table()
            } else {
                drawing.figure_above_a_table()
            };
        }
    }
}

/// The student's statics handout: the set-up, the system drawn at its initial
/// configuration (from `initial`, its equations there), and as many blank rows as the
/// worked solution has free bodies and equations.
pub fn student(
    problem: &Problem,
    method: Method,
    initial: Option<&Derivation>,
    full: &Solution,
) -> Solution {
    let mut setup = crate::solution::setup(problem, method);
    if let Some(drawing) = initial.and_then(crate::solution::pictures::initial_configuration) {
        setup.configuration = drawing.figure();
    }
    setup.free_bodies = vec![Default::default(); full.free_bodies.len()];
    setup.plan.rows = vec![Default::default(); full.plan.rows.len()];
    setup.lagrange = full.lagrange.clone().map(crate::solution::lagrange::blank);
    setup.statics = full.statics.as_ref().map(|s| StaticsView {
        sought: s.sought.clone(),
        kinematics_note: s.kinematics_note.clone(),
        rest_note: s.rest_note.clone(),
        ..StaticsView::default()
    });
    setup
}

/// A row's name at rest: Kane's `F_{r} + F^{*}_{r}` as `F_{r} = 0`, Lagrange's
/// `d/dt ∂L/∂q̇ − ∂L/∂q = Q` as `∂V/∂q = Q`.
pub fn label_at_rest(tex: &str) -> String {
    let mut out = tex.to_string();
    for inertia in [" + \\tilde{F}^{*}_{", " + F^{*}_{"] {
        if let Some(start) = out.find(inertia) {
            let end = out[start + inertia.len()..]
                .find('}')
                .map_or(out.len(), |e| start + inertia.len() + e + 1);
            out.replace_range(start..end, " = 0");
        }
    }
    const D_DT: &str = "\\frac{\\mathrm{d}}{\\mathrm{d}t} \\frac{\\partial L}{\\partial \\dot{";
    while let Some(start) = out.find(D_DT) {
        let rest = &out[start + D_DT.len()..];
        let Some(close) = matching_brace(rest) else {
            break;
        };
        let q = rest[..close].to_string();
        let tail = format!("}}}} - \\frac{{\\partial L}}{{\\partial {q}}}");
        if !rest[close..].starts_with(&tail) {
            break;
        }
        let end = start + D_DT.len() + close + tail.len();
        out.replace_range(
            start..end,
            &format!("\\frac{{\\partial V}}{{\\partial {q}}}"),
        );
    }
    out
}

/// Where the brace closes that was opened just before `text`.
fn matching_brace(text: &str) -> Option<usize> {
    let mut depth = 1;
    for (i, c) in text.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
    }
    None
}
