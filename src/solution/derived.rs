//! Steps 2 to 6 of the worked solution: what the derivation and the simulation give,
//! turned into the strings and tables of [`Solution`].

use super::long::LONG_EQUATION;
use super::tex::{action_components, bodies_tex, initial_sign, unknowns_tex, uses_shown};
use crate::equations::{Derivation, Method};
use crate::plan::Sum;
use crate::problem::BodyId;
use crate::render::context::{
    InitialValue, Named, Plan, PlanRow, Reaction, Rejected as RejectedView, Solution,
};
use crate::render::text::{MarkupLine, Math};
use crate::symbolic::{
    as_shown, fixed, fixed_or_zero, latex, latex_unit_vector, latex_with_squares,
    named_definitions, roots_of_squares, simplify, Definition, Expr,
};
use crate::Worked;

/// Fills steps 2 to 6 of `solution` from what the stages gave (see [`Worked`]).
pub fn fill(solution: &mut Solution, worked: &Worked) {
    let derivation = &worked.derivation;
    let problem = derivation.model.problem;
    let model = &derivation.model;
    solution.plan = plan(derivation);
    // The constraints of step 1 and steps 2 to 5 write sines and cosines of the angles as
    // s_1, c_12, listed once where they are first used.
    let style = coordinates_style(problem);
    // A contact sliding at the start: the sliding law in place of its no-slip row.
    let sliding = super::sliding_rows::sliding_rows(derivation, &worked.initial.friction);
    let (_, abbreviations) = crate::symbolic::with_style(style, || {
        let constraint_notes;
        (solution.constraints, constraint_notes) = super::constrained::constraints(derivation);
        solution.constraint_notes = MarkupLine::all(constraint_notes);
        solution.closure_loops = Math::all(super::closure_loops::loops(derivation));
        let contacts = super::contact_loops::loops(derivation);
        solution.contact_leads = contacts.iter().map(|(lead, _)| lead.clone()).collect();
        solution.contact_loops = Math::all(contacts.into_iter().map(|(_, l)| l).collect());
        solution.solve_notes = MarkupLine::all(super::solve_words::notes(derivation));
        solution.free_bodies = super::free_bodies::free_bodies(derivation);
        solution.lagrange = super::lagrange::view(derivation);
        solution.force_definitions =
            crate::render::grouped_definitions(force_definitions(derivation));
        let by_partials;
        (solution.kinematics, by_partials) = super::kinematics::kinematics(derivation);
        solution.spin_frames = super::spin_frames::spin_frames(derivation);
        for spin in &mut solution.spin_frames {
            // A body named by a word is called by its letter, as everywhere in the math.
            spin.body = super::force_labels::shown_name(&spin.body, &solution.shown_names);
        }
        solution.equations = derivation
            .rows
            .iter()
            .map(|row| super::row_view::equation_view(derivation, row))
            .collect();
        super::long::refer_to_repeated_vector_forms(derivation, &mut solution.equations);
        super::loops::refer_to_repeated_loops(&mut solution.equations);
        super::written_out::drop_repeated(&mut solution.equations);
        super::long::refer_to_the_first_auxiliary_row(&mut solution.equations);
        // The matrix is listed entry by entry whenever an equation refers to its entries.
        let by_name: Vec<bool> = solution.equations.iter().map(|e| e.by_name).collect();
        let use_shown = uses_shown(derivation);
        let sign = initial_sign(&derivation.model);
        let shown = |e: &Expr| {
            let e = simplify(e);
            let e = if use_shown { as_shown(&e) } else { e };
            roots_of_squares(&e, &sign)
        };
        let at_start = model.values_at(0.0, &worked.q0, &worked.rates0);
        let initial = |e: &Expr| crate::symbolic::eval(e, &at_start);
        solution.in_numbers =
            super::in_numbers::in_numbers(worked, &shown, &initial, !sliding.is_empty());
        super::in_numbers::said_once(&mut solution.solve_notes, derivation, &solution.in_numbers);
        solution.matrix = super::matrix::matrix(derivation, &by_name, shown, initial, &sliding);
        solution.partial_velocities = super::kane::partial_velocities(derivation);
        solution.kane_theory = super::kane_theory::theory(derivation);
        let mut definitions = kinematic_definitions(derivation);
        if by_partials != super::kinematics::ByPartials::None {
            let rule = super::kinematics::partial_velocity_definition(derivation, by_partials);
            definitions.insert(0, rule);
        }
        solution.kinematic_definitions = crate::render::grouped_definitions(definitions);
        solution.speeds = super::speeds::speeds(derivation);
        // Written with the same abbreviations as the rows it stands beside.
        solution.dependent_speeds =
            super::constrained::dependent_speeds(derivation, &worked.q0, &worked.rates0);
    });
    // Each row as step 5 simplified it, before the sliding law takes a no-slip row's place.
    let stick_rows: Vec<String> = (solution.equations.iter())
        .map(|e| e.simplified_tex.as_str().to_string())
        .collect();
    super::sliding_rows::replace_rows(solution, derivation, &sliding);
    // After the sliding law has taken its no-slip row's place: "the constraint rows after
    // it" only where one is.
    super::long::say_the_acceleration_level_once(&mut solution.equations);
    // Only those the solution prints: a text formed and then given up (an entry given by
    // value, a row too long to write whole) records its abbreviations too.
    let printed = serde_json::to_string(&*solution).unwrap_or_default();
    let in_print = |name: &str| {
        let quoted = serde_json::to_string(name).unwrap_or_default();
        printed.contains(quoted.trim_matches('"'))
    };
    let printed: Vec<Named> = abbreviations
        .into_iter()
        .filter(|a| in_print(&a.name))
        .map(|a| Named {
            definition_tex: Math::from(format!("{} = {}", a.name, a.value)),
            note: String::new(),
        })
        .collect();
    (solution.abbreviations, solution.abbreviations_by_rule) = abbreviation_examples(printed);
    said_axes_only_where_used(solution);
    let (q0, rates0, initial) = (&worked.q0, &worked.rates0, &worked.initial);
    let marks = super::initial_state::assembled(
        &mut solution.coordinates,
        problem,
        (q0, rates0),
        &model.constraints.dependent_rates,
    );
    if let Some(note) = marks {
        solution.constraint_notes.insert(0, MarkupLine::from(note));
    }
    let points = super::shown_names::point_notes(model, &solution.shown_names);
    (solution.constraint_notes).extend(MarkupLine::all(points));
    (solution.constraint_notes).extend(MarkupLine::all(super::initial_state::branches(
        model, q0, rates0,
    )));
    solution.initial_values = initial_accelerations(problem, &initial.accelerations);
    if solution.in_numbers.gives_accelerations {
        // Step 5's solution in numbers gives them already.
        solution.initial_values.clear();
    }
    solution
        .initial_values
        .extend(tensions(derivation, q0, rates0, &initial.reactions));
    solution.friction = super::friction::views(derivation, &initial.friction, &stick_rows);
    super::sliding_solve::replace_order(&mut solution.solve_notes, derivation, &initial.friction);
    solution.reactions = reactions(derivation, (q0, rates0), &initial.reactions);
    (solution.solve_notes).extend(MarkupLine::all(super::normal_sense::notes(
        &derivation.model,
        (q0, rates0),
        &initial.reactions,
    )));
    pictures(solution, derivation, (q0, rates0), &initial.accelerations);
    if let Some(simulated) = &worked.simulation {
        super::simulation::simulation(solution, problem, simulated);
    }
}

/// The table of the second derivatives at the initial state, each with its unit.
fn initial_accelerations(
    problem: &crate::problem::Problem,
    accelerations: &[f64],
) -> Vec<InitialValue> {
    problem
        .coordinates
        .iter()
        .enumerate()
        .map(|(i, c)| InitialValue {
            name_tex: Math::from(latex(&problem.coordinate_expr(i, 2))),
            value: fixed_or_zero(accelerations[i]),
            unit_tex: match c.kind {
                crate::problem::CoordinateKind::Angle => {
                    Math::from(crate::render::unit_tex("rad/s^2"))
                }
                crate::problem::CoordinateKind::Distance => {
                    Math::from(crate::render::unit_tex("m/s^2"))
                }
            },
        })
        .collect()
}

/// A joint's axis is said in step 1 only where something else printed uses it.
fn said_axes_only_where_used(solution: &mut Solution) {
    let axes = std::mem::take(&mut solution.axes);
    let printed = serde_json::to_string(&*solution).unwrap_or_default();
    solution.axes = (axes.into_iter())
        .filter(|a| {
            let unit = a
                .definition_tex
                .as_str()
                .split(' ')
                .next()
                .unwrap_or_default();
            let quoted = serde_json::to_string(unit).unwrap_or_default();
            printed.contains(quoted.trim_matches('"'))
        })
        .collect();
}

/// The reactions at the joints at the initial state, each in the simplest frame to write
/// it in.
fn reactions(
    derivation: &Derivation,
    (q0, rates0): (&[f64], &[f64]),
    reactions: &[(String, [f64; 3], [f64; 3])],
) -> Vec<Reaction> {
    let problem = derivation.model.problem;
    reactions
        .iter()
        .map(|(joint, f, m)| {
            let (parent, child) = (derivation.model.sites.iter())
                .find(|j| &j.name == joint)
                .map_or((BodyId::GROUND, BodyId::GROUND), |j| (j.parent, j.child));
            let written =
                super::reaction_frames::simplest(problem, (parent, child), (*f, *m), (q0, rates0));
            let frame = problem.body_name(written.frame);
            Reaction {
                joint: joint.clone(),
                force: triple(&written.force),
                moment: triple(&written.moment),
                force_tex: Math::from(numeric_vector_tex(frame, &written.force, "N")),
                moment_tex: Math::from(numeric_vector_tex(frame, &written.moment, "N\\,m")),
            }
        })
        .collect()
}

/// The pictures at the initial state, the configuration first, each free body's beside or
/// above its table.
fn pictures(
    solution: &mut Solution,
    derivation: &Derivation,
    (q0, rates0): (&[f64], &[f64]),
    accelerations: &[f64],
) {
    // The pictures at the initial state, the configuration first.
    let drawings =
        crate::solution::pictures::draw_in_handout(derivation, (q0, rates0), Some(accelerations));
    if drawings.len() > 1 {
        solution.free_body_legend = crate::solution::pictures::free_body_legend(&drawings);
    }
    for drawing in &drawings {
        if drawing.free_body.is_empty() {
            solution.configuration = drawing.figure();
        } else if let Some(body) = solution
            .free_bodies
            .iter_mut()
            .find(|b| b.name == drawing.free_body)
        {
            body.figure = if super::free_bodies::table_is_narrow(body) {
                drawing.figure_beside_a_table()
            } else {
                drawing.figure_above_a_table()
            };
            // Drawn, the free body equals its kinetic diagram (m a and I α on the right);
            // the table's inertia force and torque are those turned round, among the
            // forces: said so, that the two read as one statement.
            for force in &mut body.inertia {
                if force.label.starts_with("inertia ") {
                    (force.label.0).push_str(", opposite to its arrow in the kinetic diagram");
                }
            }
        }
    }
}

/// What the student's blank tables count: the free bodies and the rows of step 5 of the
/// worked solution, and Lagrange's energies and generalized forces (written in the same
/// style as the worked solution writes them, for the blank to keep their left sides).
pub fn blanks(
    derivation: &Derivation,
) -> (usize, usize, Option<crate::render::context::LagrangeView>) {
    let problem = derivation.model.problem;
    let rows = plan(derivation).rows.len();
    let style = coordinates_style(problem);
    let ((free_bodies, lagrange), _) = crate::symbolic::with_style(style, || {
        let free_bodies = super::free_bodies::free_bodies(derivation).len();
        (free_bodies, super::lagrange::view(derivation))
    });
    (free_bodies, rows, lagrange)
}

/// The style of steps 1 to 5: sines and cosines of the angles written `s_1`, `c_12`.
fn coordinates_style(problem: &crate::problem::Problem) -> crate::symbolic::Style {
    // Only angles are indexed, so that a slider's distance `x` beside the angles `q1`,
    // `q2` leaves them `s_1`, `c_12`.
    let names: Vec<&str> = problem
        .coordinates
        .iter()
        .filter(|c| c.kind == crate::problem::CoordinateKind::Angle)
        .map(|c| c.name.as_str())
        .collect();
    super::tex::style_of(problem).with_coordinates(&names)
}

fn triple(v: &[f64; 3]) -> String {
    format!("({}, {}, {})", fixed(v[0]), fixed(v[1]), fixed(v[2]))
}

fn numeric_vector_tex(frame: &str, v: &[f64; 3], unit: &str) -> String {
    let terms: Vec<String> = (0..3)
        .filter(|&k| fixed(v[k]) != "0")
        .map(|k| format!("{} {}", fixed(v[k]), latex_unit_vector(frame, k as u8)))
        .collect();
    if terms.is_empty() {
        return "\\mathbf{0}".into();
    }
    format!(
        "({})\\,\\mathrm{{{unit}}}",
        terms.join(" + ").replace("+ -", "- ")
    )
}

/// The named quantities the forces use, each with what it stands for.
pub fn force_definitions(derivation: &Derivation) -> Vec<Named> {
    let components: Vec<Expr> = action_components(derivation).map(as_shown).collect();
    let (speeds, plain) = speed_indices(derivation);
    crate::render::merged_by_speed(named_list(named_definitions(&components)), &speeds, &plain)
}

/// The speeds as a name's index writes them (`q_{1}`, `\\phi`) and as a note does (`q1`).
fn speed_indices(derivation: &Derivation) -> (Vec<String>, Vec<String>) {
    let problem = derivation.model.problem;
    let coordinates = 0..problem.coordinates.len();
    let speeds: Vec<String> = coordinates
        .clone()
        .map(|i| latex(&problem.coordinate_expr(i, 0)))
        .collect();
    let plain: Vec<String> = coordinates
        .map(|i| problem.coordinates[i].name.clone())
        .collect();
    (speeds, plain)
}

/// Each definition as `name = value`, with its note.
pub fn named_list(definitions: Vec<Definition>) -> Vec<Named> {
    definitions
        .iter()
        .map(|d| Named {
            definition_tex: Math::from(format!(
                "{} = {}",
                d.latex().unwrap_or_default(),
                latex_with_squares(&simplify(d.value()))
            )),
            note: d.note().to_string(),
        })
        .collect()
}

/// What Kane's rows are, without friction: one per speed, and only what the problem has
/// besides: the auxiliary speeds of the reactions asked for, the constraints differentiated.
fn kane_rows_note(derivation: &Derivation, speeds: &str) -> String {
    let auxiliary = (derivation.rows.iter())
        .filter(|row| matches!(row.sum, Sum::Generalized { .. }))
        .count()
        > super::kane::speed_rows(derivation);
    let constraints = (derivation.rows.iter()).any(|row| matches!(row.sum, Sum::Constraint { .. }));
    let mut parts = vec![format!("One row per {speeds}")];
    if auxiliary {
        parts.push("one per requested reaction component through an auxiliary speed".into());
    }
    if constraints {
        parts.push("one per scalar constraint, differentiated".into());
    }
    let last = parts.pop().unwrap_or_default();
    if parts.is_empty() {
        format!("{last}.")
    } else {
        format!("{}, and {last}.", parts.join(", "))
    }
}

/// Step 3: the planner's table, the rejected candidates and the counts.
pub fn plan(derivation: &Derivation) -> Plan {
    let problem = derivation.model.problem;
    let rows: Vec<PlanRow> = derivation
        .rows
        .iter()
        .map(|row| PlanRow {
            // A constraint row is no free body's equation.
            free_body_tex: if matches!(row.sum, Sum::Constraint { .. }) {
                Math::from(String::new())
            } else {
                // An auxiliary row's force inside its bodies: the bodies cut where it acts
                // (its pair of forces is drawn on the free bodies either side).
                let bodies = bodies_tex(derivation, &row.free_body);
                Math::from(match super::auxiliary::cut_at(derivation, row) {
                    Some(site) => format!("{bodies}\\text{{, cut at }}{site}"),
                    None => bodies,
                })
            },
            equation_tex: Math::from(match row.sum {
                // Kane's row is an equation: F_r + F*_r = 0.
                Sum::Generalized { .. } if derivation.method == Method::Kane => {
                    format!("{} = 0", super::row_names::sum_tex(derivation, &row.sum))
                }
                _ => super::row_names::sum_tex(derivation, &row.sum),
            }),
            direction_tex: match (&row.direction, &row.sum) {
                (Some(d), _) => Math::from(d.latex.clone()),
                // A contact's or a closure's row: along its reaction component; any other
                // constraint differentiated in time, short enough for the table's column.
                (None, Sum::Constraint { name }) => Math::from(
                    super::row_names::constraint_direction_tex(&derivation.model, name)
                        .unwrap_or_else(|| "\\frac{\\mathrm{d}}{\\mathrm{d}t}".into()),
                ),
                (None, _) if derivation.method == Method::Lagrange => {
                    Math::from(super::lagrange::direction_tex(derivation, row))
                }
                // Kane's row dots the forces with the partial velocities of its speed.
                (None, Sum::Generalized { .. }) if derivation.method == Method::Kane => {
                    Math::from(super::row_names::kane_direction_tex(derivation, row))
                }
                (None, _) => Math::from(String::new()),
            },
            unknowns_tex: Math::from(unknowns_tex(&row.unknowns)),
        })
        .collect();
    // A candidate about the very point of a chosen row (ΣM_J where J is D*) is that row.
    let views: Vec<Option<RejectedView>> = (derivation.rejected.iter())
        .map(|r| {
            (!super::rejected::repeats_the_same_point(derivation, r))
                .then(|| super::rejected::view(derivation, r))
        })
        .collect();
    let rejected = crate::plan::highlights(&derivation.model, &derivation.rejected)
        .into_iter()
        .filter_map(|i| views[i].clone())
        .collect();
    let rejected_all: Vec<RejectedView> = views.into_iter().flatten().collect();
    let note = match derivation.method {
        Method::NewtonEuler => format!(
            "Newton–Euler takes every body as a free body, with its force rows and its moment rows: {} equations per body; the unknowns are every second derivative and every reaction component.",
            if problem.dimension == crate::problem::Dimension::Two { 3 } else { 6 }
        ),
        Method::MotionLaw => {
            let order = super::rejected::order_note(derivation);
            // What this plan's rows do, not how every plan is made.
            let moments = super::rejected::moment_note(derivation);
            let note = [moments, order]
                .into_iter()
                .filter(|s| !s.is_empty())
                .collect::<Vec<_>>()
                .join(" ");
            // Why a light rod's closure carries one unknown, before the rows that use it.
            let mut sentences = super::light_rods::notes(derivation);
            sentences.push(note);
            sentences.retain(|s| !s.is_empty());
            sentences.join(" ")
        }
        Method::Kane => {
            let speeds = if derivation.dependent_speeds.is_some() {
                "independent speed"
            } else {
                "generalized speed"
            };
            let mut note = if derivation.model.constraints.friction.is_empty() {
                kane_rows_note(derivation, speeds)
            } else {
                let asked = match problem.find_reactions.is_empty() {
                    true => "",
                    false => ", and each other reaction component asked for",
                };
                format!("One row per {speeds}; one per auxiliary speed (each normal force the sliding law needs{asked}); the constraints, differentiated; and one per rough contact for its friction force: its no-slip condition while it sticks, the sliding law while it slips.")
            };
            if let Some(order) = super::kane::solve_order_note(derivation) {
                note = format!("{note} {order}");
            }
            note
        }
        Method::Lagrange => super::lagrange::plan_note(derivation),
    };
    Plan {
        columns: crate::render::plan_columns(&rows),
        directions: rows.iter().any(|r| !r.direction_tex.is_empty()),
        rows,
        rejected_total: rejected_all.len(),
        rejected,
        rejected_all,
        equations_count: derivation.rows.len(),
        unknowns_count: derivation.system.unknowns.len(),
        note: MarkupLine::from(note),
    }
}

/// The named quantities of steps 4 and 5 that the forces do not already define: each
/// body's named acceleration parts and what the rows use.
fn kinematic_definitions(derivation: &Derivation) -> Vec<Named> {
    let inertia = derivation.inertia();
    let parts = inertia
        .acceleration
        .iter()
        .chain(&inertia.alpha)
        .chain(derivation.model.bodies.iter().map(|b| &b.omega_named))
        .flat_map(|v| v.parts())
        .flat_map(|(_, c)| c.iter());
    let rows = derivation.rows.iter().map(|r| &r.expression);
    let forces: Vec<Definition> = named_definitions(action_components(derivation));
    // Kane's step 5 defines the dependent rates' denominator where it first writes it.
    let in_step_5 = super::kane_delta::defined_in_step_5(derivation);
    let used: Vec<Definition> = named_definitions(parts.chain(rows))
        .into_iter()
        .filter(|d| !forces.contains(d))
        .filter(|d| !(in_step_5 && d.note() == super::kane_delta::DELTA_NOTE))
        .collect();
    let (speeds, plain) = speed_indices(derivation);
    let merged = crate::render::merged_by_speed(named_list(used), &speeds, &plain);
    // A definition too long to read is given by what it is; the numbers use the formula.
    merged
        .into_iter()
        .map(|named| {
            if named.definition_tex.len() <= LONG_EQUATION {
                return named;
            }
            let name = named.definition_tex.split(" = ").next().unwrap_or_default();
            Named {
                definition_tex: Math::from(name.to_string()),
                note: format!("{}; a long expression, not written out", named.note),
            }
        })
        .collect()
}

/// The most abbreviations listed one by one; more are stated by their rule, which every one
/// follows (`s_{12} = \sin(q_1 + q_2)`), with a few examples.
const MOST_ABBREVIATIONS_LISTED: usize = 12;

/// The abbreviations to list and whether they are examples of the rule: the first, the first
/// of a sum and the last (the longest sum), in the list's order.
fn abbreviation_examples(all: Vec<Named>) -> (Vec<Named>, Vec<String>) {
    // The rule's sentence names the letters, s and c or S and C: others are listed one by one.
    let starts = |n: &Named, letter: &str| n.definition_tex.starts_with(letter);
    let letters = [["s", "c"], ["S", "C"]]
        .into_iter()
        .find(|[s, c]| all.iter().all(|n| starts(n, s) || starts(n, c)));
    let Some(letters) = letters.filter(|_| all.len() > MOST_ABBREVIATIONS_LISTED) else {
        return (all, Vec::new());
    };
    let of_sum = |n: &Named| n.definition_tex.contains(" + ");
    let picks = [
        Some(0),
        all.iter().position(of_sum),
        all.len().checked_sub(1),
    ];
    let mut keep: Vec<usize> = picks.into_iter().flatten().collect();
    keep.dedup();
    let examples = all
        .into_iter()
        .enumerate()
        .filter(|(i, _)| keep.contains(i))
        .map(|(_, n)| n)
        .collect();
    (examples, letters.map(String::from).to_vec())
}

/// The tension of each two-force member at the initial state, from its joint's force:
/// T = F · ê, ê the member's direction toward the joint.
fn tensions(
    derivation: &Derivation,
    q0: &[f64],
    rates0: &[f64],
    reactions: &[(String, [f64; 3], [f64; 3])],
) -> Vec<InitialValue> {
    let model = &derivation.model;
    let values = model.values_at(0.0, q0, rates0);
    let mut out = Vec::new();
    for site in &model.sites {
        let Some(member) = site
            .reactions
            .iter()
            .find(|c| c.axis == crate::symbolic::Axis::Member)
        else {
            continue;
        };
        let Some((_, force, _)) = reactions.iter().find(|(joint, _, _)| *joint == site.name) else {
            continue;
        };
        let along = member.direction.components_in(site.parent, &model.frames);
        let tension: f64 = (0..3)
            .map(|k| force[k] * crate::symbolic::eval(&along[k], &values))
            .sum();
        out.push(InitialValue {
            name_tex: Math::from(latex(&Expr::sym(member.unknown(&site.name)))),
            value: fixed_or_zero(tension),
            unit_tex: Math::from(crate::render::unit_tex("N")),
        });
    }
    out
}
