//! A worked solution written by hand, for testing the templates without the pipeline.
//!
//! It is the double pendulum of the problem-format example (two uniform rods of mass `m`,
//! length `L`, `q1` from the downward vertical, `q2` of rod B relative to rod A), solved with
//! the Motion Law and derived on paper: mass matrix
//! `m L^2 [[5/3 + cos q2, 1/3 + cos q2 / 2], [1/3 + cos q2 / 2, 1/3]]`, gravity terms
//! `m g L / 2 (3 sin q1 + sin(q1 + q2), sin(q1 + q2))`. The numbers are for `m = 1 kg`,
//! `L = 0.5 m`, `g = 9.81 m/s^2`, released from rest at `q1 = 0.5`, `q2 = 0`.

use super::context::*;
use super::text::{FileName, LatexCode, Markup, MarkupLine, Math, SvgDocument};

fn s(text: &str) -> String {
    text.to_string()
}

const N: &str = "\\hat{\\mathbf{n}}";
const A: &str = "\\hat{\\mathbf{a}}";
const B: &str = "\\hat{\\mathbf{b}}";

/// The hand-written double pendulum; see the module documentation.
pub fn sample() -> Solution {
    Solution {
        title: s("Double pendulum of two uniform rods"),
        shown_names: Vec::new(),
        statement: Some(Markup::from(s("Two uniform rods A and B, each of mass m and length L, are pinned together at P; \
            rod A hangs from a fixed pin at O. The system is released from rest with q1 = 0.5 rad and q2 = 0.\n\n\
            Find the angular accelerations of the rods and the reaction at O at the instant of release."))),
        dimension: s("planar"),
        method: s("the Motion Law"),
        student: false,
        frames: frames(),
        spin_frames: vec![SpinFrame {
            frame: Frame {
                name: "C".into(),
                frame_tex: "\\hat{\\mathbf{c}}_{x}, \\hat{\\mathbf{c}}_{y}, \\hat{\\mathbf{c}}_{z}".into(),
                fixed_in: String::new(),
                parent: "N".into(),
                orientation_tex: "\\text{body-fixed rotations by } \\psi, \\theta \\text{ about } z, x"
                    .into(),
            },
            body: "B".into(),
            axis_tex: "\\hat{\\mathbf{b}}_{z}".into(),
            spin_tex: "\\phi".into(),
            parents: false,
        }],
        axes: Vec::new(),
        // The sample is hand-written: no pictures, so its renderings stay as they were.
        configuration: Figure::default(),
        coordinates: vec![
            coordinate("q_{1}", "\\dot{q}_{1}", "angle of rod A from the downward vertical", "O (revolute)", "0.5"),
            coordinate("q_{2}", "\\dot{q}_{2}", "angle of rod B relative to rod A", "P (revolute)", "0"),
        ],
        constants: vec![
            constant("m", "1", "\\mathrm{kg}", "mass of each rod"),
            constant("L", "0.5", "\\mathrm{m}", "length of each rod"),
            constant("g", "9.81", "\\mathrm{m/s^{2}}", "gravitational acceleration"),
        ],
        speeds: None,
        constraints: Vec::new(),
        constraint_notes: Vec::new(),
        closure_loops: Vec::new(),
        contact_loops: Vec::new(),
        contact_leads: Vec::new(),
        solve_notes: Vec::new(),
        matrix_names: Default::default(),
        free_bodies: free_bodies(),
        free_body_legend: String::new(),
        force_definitions: Vec::new(),
        kinematic_definitions: Vec::new(),
        abbreviations: Vec::new(),
        abbreviations_by_rule: Vec::new(),
        plan: plan(),
        kinematics: kinematics(),
        equations: equations(),
        dependent_speeds: None,
        partial_velocities: Vec::new(),
        kane_theory: None,
        lagrange: None,
        matrix: matrix(),
        in_numbers: Default::default(),
        initial_values: vec![
            value("\\ddot{q}_{1}", "-12.0939", "\\mathrm{rad/s^{2}}"),
            value("\\ddot{q}_{2}", "16.1251", "\\mathrm{rad/s^{2}}"),
            value("F^{O}_{x}", "-7.07557", "\\mathrm{N}"),
            value("F^{O}_{y}", "15.7546", "\\mathrm{N}"),
        ],
        friction: Vec::new(),
        reactions: vec![Reaction {
            joint: s("O"),
            force: s("(-7.07557, 15.7546, 0) N"),
            moment: s("(0, 0, 0) N m"),
            force_tex: Math::from(format!("\\left(-7.07557 {N}_{{x}} + 15.7546 {N}_{{y}}\\right) \\mathrm{{N}}")),
            moment_tex: Math::from(s("\\mathbf{0} \\; \\mathrm{N\\,m}")),
        }],
        impact: None,
        simulation: simulation(),
        linearization: None,
        answers: vec![super::sections::AnswerView {
            question: MarkupLine::from(s("Find the angular acceleration of rod A at the instant of release.")),
            at_tex: Math::from(s("t = 0\\ \\mathrm{s}")),
            at_note: s("the initial state"),
            values_tex: vec![Math::from(s("\\ddot{q}_{1} = -12.0939\\ \\mathrm{rad}/\\mathrm{s}^{2}"))],
            note: String::new(),
            label: s("1"),
            steps: Vec::new(),
            blank_lines: 0,
            same_state: false,
        }],
        statics: None,
    }
}

fn frames() -> Vec<Frame> {
    let triad = |u: &str| format!("{u}_{{x}}, {u}_{{y}}, {u}_{{z}}");
    vec![
        Frame {
            name: s("N"),
            frame_tex: Math::from(triad(N)),
            fixed_in: s("N"),
            parent: s(""),
            orientation_tex: Math::from(s("")),
        },
        Frame {
            name: s("A"),
            frame_tex: Math::from(triad(A)),
            fixed_in: s("A"),
            parent: s("N"),
            orientation_tex: Math::from(format!(
                "\\text{{rotated by }} q_{{1}} \\text{{ about }} {N}_{{z}}"
            )),
        },
        Frame {
            name: s("B"),
            frame_tex: Math::from(triad(B)),
            fixed_in: s("B"),
            parent: s("A"),
            orientation_tex: Math::from(format!(
                "\\text{{rotated by }} q_{{2}} \\text{{ about }} {A}_{{z}}"
            )),
        },
    ]
}

fn coordinate(name: &str, rate: &str, description: &str, joint: &str, initial: &str) -> Coordinate {
    Coordinate {
        name_tex: Math::from(s(name)),
        rate_tex: Math::from(s(rate)),
        description: MarkupLine::from(s(description)),
        joint: MarkupLine::from(s(joint)),
        unit_tex: Math::from(s("\\mathrm{rad}")),
        initial: s(initial),
        initial_rate: s("0"),
    }
}

fn constant(name: &str, value: &str, unit: &str, description: &str) -> Constant {
    Constant {
        name_tex: Math::from(s(name)),
        value: s(value),
        unit_tex: Math::from(s(unit)),
        description: MarkupLine::from(s(description)),
    }
}

fn value(name: &str, value: &str, unit: &str) -> InitialValue {
    InitialValue {
        name_tex: Math::from(s(name)),
        value: s(value),
        unit_tex: Math::from(s(unit)),
    }
}

fn force(label: &str, vector: String, point: &str) -> Force {
    Force {
        label: MarkupLine::from(label),
        vector_tex: Math::from(vector),
        point_tex: Math::from(s(point)),
    }
}

fn free_bodies() -> Vec<FreeBody> {
    let gravity = |body: &str| {
        force(
            &format!("gravity on {body}"),
            format!("-m g {N}_{{y}}"),
            &format!("{body}^{{*}}"),
        )
    };
    let inertia = |body: &str, alpha: &str| {
        vec![
            force(
                &format!("inertia force of {body}"),
                format!("-m\\,{{}}^{{N}}\\mathbf{{a}}^{{{body}^{{*}}}}"),
                &format!("{body}^{{*}}"),
            ),
            force(
                &format!("inertia couple of {body}"),
                format!("-\\frac{{m L^{{2}}}}{{12}} {alpha} {N}_{{z}}"),
                "",
            ),
        ]
    };
    vec![
        FreeBody {
            name: s("A+B"),
            name_tex: Math::from(s("A + B")),
            bodies: s("A, B"),
            contact: vec![force(
                "pin O",
                format!("F^{{O}}_{{x}} {N}_{{x}} + F^{{O}}_{{y}} {N}_{{y}}"),
                "O",
            )],
            distance: vec![gravity("A"), gravity("B")],
            inertia: [
                inertia("A", "\\ddot{q}_{1}"),
                inertia("B", "\\left(\\ddot{q}_{1} + \\ddot{q}_{2}\\right)"),
            ]
            .concat(),
            figure: Figure::default(),
        },
        FreeBody {
            name: s("B"),
            name_tex: Math::from(s("B")),
            bodies: s("B"),
            contact: vec![force(
                "pin P",
                format!("F^{{P}}_{{x}} {A}_{{x}} + F^{{P}}_{{y}} {A}_{{y}}"),
                "P",
            )],
            distance: vec![gravity("B")],
            inertia: inertia("B", "\\left(\\ddot{q}_{1} + \\ddot{q}_{2}\\right)"),
            figure: Figure::default(),
        },
    ]
}

fn plan() -> Plan {
    let row = |free_body: &str, equation: &str, direction: String, unknowns: &str| PlanRow {
        free_body_tex: Math::from(s(free_body)),
        equation_tex: Math::from(s(equation)),
        direction_tex: Math::from(direction),
        unknowns_tex: Math::from(s(unknowns)),
    };
    let accelerations = "\\ddot{q}_{1}, \\ddot{q}_{2}";
    let rows = vec![
        row(
            "A + B",
            "\\sum \\mathbf{M}_{O}",
            format!("{N}_{{z}}"),
            accelerations,
        ),
        row(
            "B",
            "\\sum \\mathbf{M}_{P}",
            format!("{A}_{{z}}"),
            accelerations,
        ),
        row(
            "A + B",
            "\\sum \\mathbf{F}",
            format!("{N}_{{x}}"),
            "\\ddot{q}_{1}, \\ddot{q}_{2}, F^{O}_{x}",
        ),
        row(
            "A + B",
            "\\sum \\mathbf{F}",
            format!("{N}_{{y}}"),
            "\\ddot{q}_{1}, \\ddot{q}_{2}, F^{O}_{y}",
        ),
    ];
    Plan {
        columns: super::plan_table::columns(&rows),
        directions: true,
        rows,
        rejected: vec![Rejected {
            free_body_tex: Math::from(s("A")),
            equation_tex: Math::from(s("\\sum \\mathbf{M}_{O}")),
            direction_tex: Math::from(format!("{N}_{{z}}")),
            reason: s("brings in the reaction at P"),
            reason_tex: Math::from(s("F^{P}_{x}, F^{P}_{y}")),
            reason_after: s(", which is not asked for"),
        }],
        rejected_total: 1,
        rejected_all: vec![],
        equations_count: 4,
        unknowns_count: 4,
        note: MarkupLine::from("The system is square: one equation for each unknown."),
    }
}

fn kinematics() -> Vec<Kinematics> {
    let rates = "\\left(\\dot{q}_{1} + \\dot{q}_{2}\\right)";
    let accelerations = "\\left(\\ddot{q}_{1} + \\ddot{q}_{2}\\right)";
    vec![
        Kinematics {
            body: s("A"),
            particle: false,
            light: false,
            position_tex: Math::from(format!("\\mathbf{{r}}^{{O A^{{*}}}} = -\\frac{{L}}{{2}} {A}_{{y}}")),
            omega_tex: Math::from(format!("{{}}^{{N}}\\boldsymbol{{\\omega}}^{{A}} = \\dot{{q}}_{{1}} {N}_{{z}}")),
            alpha_tex: Math::from(format!("{{}}^{{N}}\\boldsymbol{{\\alpha}}^{{A}} = \\ddot{{q}}_{{1}} {N}_{{z}}")),
            pin_velocity_tex: Math::from(String::new()),
            pin_acceleration_tex: Math::from(String::new()),
            velocity_tex: Math::from(format!("{{}}^{{N}}\\mathbf{{v}}^{{A^{{*}}}} = \\frac{{L}}{{2}} \\dot{{q}}_{{1}} {A}_{{x}}")),
            acceleration_tex: Math::from(format!(
                "{{}}^{{N}}\\mathbf{{a}}^{{A^{{*}}}} = \\frac{{L}}{{2}} \\ddot{{q}}_{{1}} {A}_{{x}} + \\frac{{L}}{{2}} \\dot{{q}}_{{1}}^{{2}} {A}_{{y}}"
            )),
        },
        Kinematics {
            body: s("B"),
            particle: false,
            light: false,
            position_tex: Math::from(format!("\\mathbf{{r}}^{{P B^{{*}}}} = -\\frac{{L}}{{2}} {B}_{{y}}")),
            omega_tex: Math::from(format!("{{}}^{{N}}\\boldsymbol{{\\omega}}^{{B}} = {rates} {N}_{{z}}")),
            alpha_tex: Math::from(format!("{{}}^{{N}}\\boldsymbol{{\\alpha}}^{{B}} = {accelerations} {N}_{{z}}")),
            pin_velocity_tex: Math::from(format!(
                "{{}}^{{N}}\\mathbf{{v}}^{{P}} = L \\dot{{q}}_{{1}} {A}_{{x}}, \\qquad {{}}^{{N}}\\mathbf{{a}}^{{P}} = L \\ddot{{q}}_{{1}} {A}_{{x}} + L \\dot{{q}}_{{1}}^{{2}} {A}_{{y}}"
            )),
            pin_acceleration_tex: Math::from(String::new()),
            velocity_tex: Math::from(format!(
                "{{}}^{{N}}\\mathbf{{v}}^{{B^{{*}}}} = {{}}^{{N}}\\mathbf{{v}}^{{P}} + \\frac{{L}}{{2}} {rates} {B}_{{x}}"
            )),
            acceleration_tex: Math::from(format!(
                "{{}}^{{N}}\\mathbf{{a}}^{{B^{{*}}}} = {{}}^{{N}}\\mathbf{{a}}^{{P}} + \\frac{{L}}{{2}} {accelerations} {B}_{{x}} + \\frac{{L}}{{2}} {rates}^{{2}} {B}_{{y}}"
            )),
        },
    ]
}

fn equations() -> Vec<Equation> {
    let loads = |body: &str| {
        format!("\\left(-m g {N}_{{y}} - m\\,{{}}^{{N}}\\mathbf{{a}}^{{{body}^{{*}}}}\\right)")
    };
    let sum_forces = format!(
        "F^{{O}}_{{x}} {N}_{{x}} + F^{{O}}_{{y}} {N}_{{y}} + {} + {}",
        loads("A"),
        loads("B")
    );
    let c1 = "\\cos(q_{1})";
    let s1 = "\\sin(q_{1})";
    let c12 = "\\cos\\left(q_{1} + q_{2}\\right)";
    let s12 = "\\sin\\left(q_{1} + q_{2}\\right)";
    let rates = "\\left(\\dot{q}_{1} + \\dot{q}_{2}\\right)";
    let accelerations = "\\left(\\ddot{q}_{1} + \\ddot{q}_{2}\\right)";
    vec![
        Equation {
            label_tex: Math::from(format!("A + B\\colon \\sum \\mathbf{{M}}_{{O}} \\cdot {N}_{{z}}")),
            label: String::new(),
            augmented_note: MarkupLine::default(),
            grouped_tex: Math::from(format!(
                "{N}_{{z}} \\cdot \\left(\\mathbf{{r}}^{{A^{{*}}/O}} \\times {} - \\frac{{m L^{{2}}}}{{12}} \\ddot{{q}}_{{1}} {N}_{{z}} \
                 + \\mathbf{{r}}^{{B^{{*}}/O}} \\times {} - \\frac{{m L^{{2}}}}{{12}} {accelerations} {N}_{{z}}\\right) = 0",
                loads("A"),
                loads("B")
            )),
            written_tex: Math::default(),
            simplified_tex: Math::from(format!(
                "m L^{{2}} \\left(\\frac{{5}}{{3}} + \\cos(q_{{2}})\\right) \\ddot{{q}}_{{1}} + m L^{{2}} \\left(\\frac{{1}}{{3}} + \\frac{{\\cos(q_{{2}})}}{{2}}\\right) \\ddot{{q}}_{{2}} \
                 - \\frac{{m L^{{2}}}}{{2}} \\sin(q_{{2}}) \\left(2 \\dot{{q}}_{{1}} \\dot{{q}}_{{2}} + \\dot{{q}}_{{2}}^{{2}}\\right) \
                 + \\frac{{m g L}}{{2}} \\left(3 {s1} + {s12}\\right) = 0"
            )),
            simplified_note: String::new(),
            bare: false,
            by_name: false,
            active_tex: Math::from(String::new()),
            inertia_tex: Math::from(String::new()),
            solved_tex: Math::from(String::new()),
            lagrange_tex: Vec::new(),
        },
        Equation {
            label_tex: Math::from(format!("B\\colon \\sum \\mathbf{{M}}_{{P}} \\cdot {A}_{{z}}")),
            label: String::new(),
            augmented_note: MarkupLine::default(),
            grouped_tex: Math::from(format!(
                "{A}_{{z}} \\cdot \\left(\\mathbf{{r}}^{{B^{{*}}/P}} \\times {} - \\frac{{m L^{{2}}}}{{12}} {accelerations} {N}_{{z}}\\right) = 0",
                loads("B")
            )),
            written_tex: Math::default(),
            simplified_tex: Math::from(format!(
                "m L^{{2}} \\left(\\frac{{1}}{{3}} + \\frac{{\\cos(q_{{2}})}}{{2}}\\right) \\ddot{{q}}_{{1}} + \\frac{{m L^{{2}}}}{{3}} \\ddot{{q}}_{{2}} \
                 + \\frac{{m L^{{2}}}}{{2}} \\sin(q_{{2}}) \\dot{{q}}_{{1}}^{{2}} + \\frac{{m g L}}{{2}} {s12} = 0"
            )),
            simplified_note: String::new(),
            bare: false,
            by_name: false,
            active_tex: Math::from(String::new()),
            inertia_tex: Math::from(String::new()),
            solved_tex: Math::from(String::new()),
            lagrange_tex: Vec::new(),
        },
        Equation {
            label_tex: Math::from(format!("A + B\\colon \\sum \\mathbf{{F}} \\cdot {N}_{{x}}")),
            label: String::new(),
            augmented_note: MarkupLine::default(),
            grouped_tex: Math::from(format!("{N}_{{x}} \\cdot \\left({sum_forces}\\right) = 0")),
            written_tex: Math::default(),
            simplified_tex: Math::from(format!(
                "F^{{O}}_{{x}} - m L \\left(\\frac{{3}}{{2}} \\left({c1} \\ddot{{q}}_{{1}} - {s1} \\dot{{q}}_{{1}}^{{2}}\\right) \
                 + \\frac{{1}}{{2}} \\left({c12} {accelerations} - {s12} {rates}^{{2}}\\right)\\right) = 0"
            )),
            simplified_note: String::new(),
            bare: false,
            by_name: false,
            active_tex: Math::from(String::new()),
            inertia_tex: Math::from(String::new()),
            solved_tex: Math::from(String::new()),
            lagrange_tex: Vec::new(),
        },
        Equation {
            label_tex: Math::from(format!("A + B\\colon \\sum \\mathbf{{F}} \\cdot {N}_{{y}}")),
            label: String::new(),
            augmented_note: MarkupLine::default(),
            grouped_tex: Math::from(format!("{N}_{{y}} \\cdot \\left({sum_forces}\\right) = 0")),
            written_tex: Math::default(),
            simplified_tex: Math::from(format!(
                "F^{{O}}_{{y}} - 2 m g - m L \\left(\\frac{{3}}{{2}} \\left({s1} \\ddot{{q}}_{{1}} + {c1} \\dot{{q}}_{{1}}^{{2}}\\right) \
                 + \\frac{{1}}{{2}} \\left({s12} {accelerations} + {c12} {rates}^{{2}}\\right)\\right) = 0"
            )),
            simplified_note: String::new(),
            bare: false,
            by_name: false,
            active_tex: Math::from(String::new()),
            inertia_tex: Math::from(String::new()),
            solved_tex: Math::from(String::new()),
            lagrange_tex: Vec::new(),
        },
    ]
}

fn matrix() -> MatrixForm {
    let a = [
        [
            "m L^{2} \\left(\\frac{5}{3} + \\cos(q_{2})\\right)",
            "m L^{2} \\left(\\frac{1}{3} + \\frac{\\cos(q_{2})}{2}\\right)",
            "0",
            "0",
        ],
        [
            "m L^{2} \\left(\\frac{1}{3} + \\frac{\\cos(q_{2})}{2}\\right)",
            "\\frac{m L^{2}}{3}",
            "0",
            "0",
        ],
        [
            "-\\frac{m L}{2} \\left(3 \\cos(q_{1}) + \\cos\\left(q_{1} + q_{2}\\right)\\right)",
            "-\\frac{m L}{2} \\cos\\left(q_{1} + q_{2}\\right)",
            "1",
            "0",
        ],
        [
            "-\\frac{m L}{2} \\left(3 \\sin(q_{1}) + \\sin\\left(q_{1} + q_{2}\\right)\\right)",
            "-\\frac{m L}{2} \\sin\\left(q_{1} + q_{2}\\right)",
            "0",
            "1",
        ],
    ];
    let b = [
        "\\frac{m L^{2}}{2} \\sin(q_{2}) \\left(2 \\dot{q}_{1} \\dot{q}_{2} + \\dot{q}_{2}^{2}\\right) - \\frac{m g L}{2} \\left(3 \\sin(q_{1}) + \\sin\\left(q_{1} + q_{2}\\right)\\right)",
        "-\\frac{m L^{2}}{2} \\sin(q_{2}) \\dot{q}_{1}^{2} - \\frac{m g L}{2} \\sin\\left(q_{1} + q_{2}\\right)",
        "-\\frac{m L}{2} \\left(3 \\sin(q_{1}) \\dot{q}_{1}^{2} + \\sin\\left(q_{1} + q_{2}\\right) \\left(\\dot{q}_{1} + \\dot{q}_{2}\\right)^{2}\\right)",
        "2 m g + \\frac{m L}{2} \\left(3 \\cos(q_{1}) \\dot{q}_{1}^{2} + \\cos\\left(q_{1} + q_{2}\\right) \\left(\\dot{q}_{1} + \\dot{q}_{2}\\right)^{2}\\right)",
    ];
    let rows: Vec<String> = a.iter().map(|row| row.join(" & ")).collect();
    MatrixForm {
        whole: Some(WholeMatrix {
            a_tex: Math::from(format!("\\begin{{bmatrix}} {} \\end{{bmatrix}}", rows.join(" \\\\ "))),
            x_tex: Math::from(s("\\begin{bmatrix} \\ddot{q}_{1} \\\\ \\ddot{q}_{2} \\\\ F^{O}_{x} \\\\ F^{O}_{y} \\end{bmatrix}")),
            b_tex: Math::from(format!("\\begin{{bmatrix}} {} \\end{{bmatrix}}", b.join(" \\\\ "))),
            // Too wide for one table on the page: the templates show A, x and b.
            table_tex: Math::from(String::new()),
        }),
        ..MatrixForm::default()
    }
}

fn simulation() -> Simulation {
    Simulation {
        settings: MarkupLine::from(s("The equations of step 5 are integrated in time from the initial state of step 1 for 5 s by a fifth-order Runge–Kutta method; the plots show the state every 0.01 s.")),
        checks: vec![
            Check {
                name: s("energy drift (relative)"),
                value: s("3.1e-10"),
                tolerance: s("1e-6"),
                passed: true,
                detail: MarkupLine::from(super::markup::literal_with_numbers("Every force that does work has a potential, so the total energy stays constant: E(t) − E(0) stays below 1e-9 J while 0.74 J is traded between T and V.")),
            },
            Check {
                name: s("agreement with Kane's method"),
                value: s("4.4e-15"),
                tolerance: s("1e-9"),
                passed: true,
                detail: MarkupLine::from(super::markup::literal_with_numbers("Newton–Euler and Kane's method give the same second derivatives at every state compared along the motion.")),
            },
            Check {
                name: s("small-oscillation period, slow mode (s)"),
                value: s("1.65772"),
                tolerance: s("1.65772 ± 0.1%"),
                passed: true,
                detail: MarkupLine::from(super::markup::literal_with_numbers("Started a little away from its equilibrium, the motion oscillates with the period 2π/ω = 1.65772 s that the linearized equations give.")),
            },
        ],
        plots_in_row: 3,
        plots: vec![
            plot(
                "coordinates",
                "The coordinates against time",
                "q_{1}",
                "q_{2}",
                "rad",
            ),
            plot(
                "energy",
                "Kinetic, potential and total energy against time",
                "T",
                "V",
                "J",
            ),
        ],
        note: s(
            "Every check passed: the equations conserve energy and agree with the second method.",
        ),
        ..Simulation::default()
    }
}

fn plot(kind: &str, title: &str, first: &str, second: &str, unit: &str) -> Plot {
    let svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"320\" height=\"120\" viewBox=\"0 0 320 120\">\
        <polyline fill=\"none\" stroke=\"#1f77b4\" points=\"0,40 40,80 80,100 120,70 160,30 200,20 240,50 280,90 320,100\"/>\
        <polyline fill=\"none\" stroke=\"#d62728\" points=\"0,60 40,30 80,50 120,90 160,80 200,40 240,30 280,60 320,70\"/>\
        </svg>";
    let pgfplots = format!(
        "\\begin{{tikzpicture}}\n\\begin{{axis}}[width=0.9\\linewidth, height=5cm, xlabel={{$t$ (s)}}, ylabel={{{unit}}}]\n\
         \\addplot[blue, no marks] coordinates {{(0,0.5) (0.5,-0.1) (1,-0.4) (1.5,0.2) (2,0.5)}};\n\\addlegendentry{{${first}$}}\n\
         \\addplot[red, no marks] coordinates {{(0,0) (0.5,0.3) (1,-0.2) (1.5,-0.3) (2,0.1)}};\n\\addlegendentry{{${second}$}}\n\
         \\end{{axis}}\n\\end{{tikzpicture}}"
    );
    Plot {
        kind: s(kind),
        title: s(title),
        svg_file: FileName::from(format!("{kind}.svg")),
        image_svg: SvgDocument::from(s(svg)),
        image_latex: LatexCode::from(pgfplots),
        data: None,
    }
}
