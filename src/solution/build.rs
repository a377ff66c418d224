//! Building the [`Solution`] from a problem and what the pipeline derives from it.
//!
//! What the problem alone gives (title, statement, step 1) is filled here; the steps that
//! come from the equations and the simulation start empty, and the templates leave out
//! what is empty.

use super::tex::style_of;
use crate::equations::Method;
use crate::problem::{Dimension, JointKind, Problem};
use crate::render::context::{Constant, Coordinate, Named, Plan, Simulation, Solution};
use crate::render::text::{Markup, MarkupLine, Math};
use crate::symbolic::{fixed, latex, latex_name};

/// The whole worked solution from what the stages gave (their run, [`crate::Worked`]):
/// step 1 from the problem, steps 2 to 6 from the derivation, the solution at the initial
/// state and the simulation.
pub fn solution(worked: &crate::Worked) -> Solution {
    let derivation = &worked.derivation;
    let problem = derivation.model.problem;
    let mut solution = crate::symbolic::with_style(style_of(problem), || {
        // The letters a word-named body, point or joint is printed by, from step 1 on.
        let shown = super::shown_names::shown_names(&derivation.model);
        let mut solution = setup_styled(problem, derivation.method, &shown);
        super::shown_names::name_in_step_one(&mut solution, &shown);
        solution.shown_names = shown;
        solution
    })
    .0;
    crate::symbolic::with_style(style_of(problem), || {
        super::derived::fill(&mut solution, worked);
        solution.impact = super::impact::section(worked);
    });
    solution
}

/// What the problem alone gives: title, statement and step 1, for the student's handout,
/// which names its bodies, points and joints by the letters the worked solution prints
/// (by the problem's words where its kinematics cannot be built).
pub fn setup(problem: &Problem, method: Method) -> Solution {
    crate::symbolic::with_style(style_of(problem), || {
        let shown = crate::mechanics::Model::build(problem)
            .map(|model| super::shown_names::shown_names(&model))
            .unwrap_or_default();
        let mut solution = setup_styled(problem, method, &shown);
        super::shown_names::name_in_step_one(&mut solution, &shown);
        solution.shown_names = shown;
        solution
    })
    .0
}

/// Title, statement and step 1, a word-named joint called by its letter in `shown`.
fn setup_styled(problem: &Problem, method: Method, shown: &[(String, String)]) -> Solution {
    Solution {
        title: problem.title.clone(),
        statement: problem.statement.clone().map(Markup::from),
        dimension: match problem.dimension {
            Dimension::Two => "planar",
            Dimension::Three => "spatial",
        }
        .to_string(),
        method: method.title().to_string(),
        student: false,
        frames: super::frames::frames(problem),
        coordinates: coordinates(problem, shown),
        axes: axes(problem),
        constants: constants(problem),
        plan: Plan::default(),
        matrix_names: {
            let names = crate::problem::MatrixNames::of(problem);
            crate::render::context::MatrixLetters {
                a: names.a,
                b: names.b,
                c: names.c,
                x: names.x,
                z: names.z,
            }
        },
        simulation: Simulation {
            settings: MarkupLine::from(super::confirmation::integration(
                problem,
                &problem.simulate,
            )),
            ..Simulation::default()
        },
        ..Solution::default()
    }
}

/// The unit vector along each joint axis that a sum may be taken along (a prismatic or
/// cylindrical joint's; a revolute joint's in 3D), as step 3 names it: `ê_slide`.
fn axes(problem: &Problem) -> Vec<Named> {
    problem
        .joints
        .iter()
        .filter(|j| match j.kind {
            JointKind::Prismatic | JointKind::Cylindrical => true,
            JointKind::Revolute => problem.dimension == Dimension::Three,
            _ => false,
        })
        .filter_map(|j| {
            let axis = j.axis.as_ref()?;
            let unit = format!("\\hat{{\\mathbf{{e}}}}_{{{}}}", latex_name(&j.name));
            // A unit vector as written is the axis; any other vector gives its direction.
            let plain = axis.terms.len() == 1 && axis.terms[0].2.is_one();
            let relation = if plain { "=" } else { "\\parallel" };
            // The subscript names the joint: no note.
            Some(Named::new(
                format!(
                    "{unit} {relation} {}",
                    super::frames::vector_tex(problem, axis)
                ),
                "",
            ))
        })
        .collect()
}

/// Step 1's coordinates; `shown` the letters of word-named points (a joint's among them).
fn coordinates(problem: &Problem, shown: &[(String, String)]) -> Vec<Coordinate> {
    problem
        .coordinates
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let unit = crate::numeric::coordinate_unit(problem, i, 0);
            let rate_unit = crate::numeric::coordinate_unit(problem, i, 1);
            let with_unit = super::initial_state::with_unit;
            Coordinate {
                name_tex: Math::from(latex(&problem.coordinate_expr(i, 0))),
                rate_tex: Math::from(latex(&problem.coordinate_expr(i, 1))),
                description: MarkupLine::from(c.description.clone().unwrap_or_default()),
                // One line per joint, said at its first coordinate; the joint's other
                // coordinates point back to it.
                joint: match (problem.coordinates[..i].iter()).position(|b| b.joint == c.joint) {
                    Some(first) => MarkupLine::from(
                        super::joint_words::later_coordinate_words(problem, i, first)
                            .unwrap_or_else(|| {
                                format!("as for ${}$", latex(&problem.coordinate_expr(first, 0)))
                            }),
                    ),
                    None => {
                        MarkupLine::from(super::joint_words::joint_words(problem, c.joint, shown))
                    }
                },
                unit_tex: Math::from(crate::render::unit_tex(&unit)),
                initial: with_unit(&fixed(c.initial), &unit),
                initial_rate: with_unit(&fixed(c.rate), &rate_unit),
            }
        })
        .collect()
}

/// A constant's value; an angle in radians that is a whole number of degrees (as a
/// statement gives it) also in degrees: `0.698132 (40°)`.
fn with_degrees(value: f64, unit: Option<&str>) -> String {
    let degrees = value.to_degrees();
    let whole = degrees.round();
    if unit == Some("rad") && whole != 0.0 && (degrees - whole).abs() < 1e-9 {
        format!("{} ({whole}°)", fixed(value))
    } else {
        fixed(value)
    }
}

fn constants(problem: &Problem) -> Vec<Constant> {
    problem
        .constants
        .iter()
        .map(|c| Constant {
            name_tex: Math::from(latex_name(&c.name)),
            value: with_degrees(c.value, c.unit.as_deref()),
            unit_tex: Math::from(crate::render::unit_tex(
                c.unit.as_deref().unwrap_or_default(),
            )),
            description: MarkupLine::from(c.description.clone().unwrap_or_default()),
        })
        .collect()
}
