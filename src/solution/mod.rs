//! The worked solution's content (step by step, as a textbook prints it), prepared from what
//! the stages before gave: the problem, the model, the plan, the equations, the solution at
//! the initial state, the simulation and its checks ([`crate::Worked`]): a pure function of
//! them, deriving, solving and simulating nothing.
//!
//! [`worked`] fills a [`Solution`](crate::render::Solution): each step's rows as formed and simplified with their
//! headings, the where-lists, the rejections chosen to show, the tables, the pictures'
//! scenes (laid out, [`draw_pictures`]), the answers and the checks. [`crate::render`] only writes
//! it; this stage is the last one that reads the derivation.

mod abbreviations;
mod absent_constants;
mod aligned;
mod answer_leads;
mod answer_lines;
mod answer_numbers;
mod answer_sheet;
mod answers;
mod asked_bodies;
mod auxiliary;
mod auxiliary_partials;
mod build;
mod closed_form;
mod closure_loops;
mod concise;
mod confirmation;
mod constancy;
mod constrained;
mod contact_loops;
mod derived;
mod describe_words;
mod direction;
mod drawn_on;
mod eigen_plot;
mod elimination;
mod energy_datum;
mod force_labels;
mod force_moments;
mod force_words;
mod frames;
mod free_bodies;
mod friction;
mod friction_needed;
mod handout;
mod impact;
mod in_numbers;
mod independent;
mod initial_state;
mod joint_words;
mod kane;
mod kane_bodies;
mod kane_delta;
mod kane_dots;
mod kane_loop;
mod kane_system;
mod kane_theory;
mod kane_tilde;
mod kinematics;
mod lagrange;
mod light_rods;
mod linearization;
mod long;
mod loop_relations;
mod loops;
mod matrix;
mod matrix_by_value;
mod mode_shape;
mod moment_point;
mod moving_axes;
mod named_identity;
mod normal_sense;
mod on_constraint;
mod partial_rows;
mod period_contrast;
mod pictures;
mod plot_titles;
mod polar_units;
mod potential_tex;
mod question_answers;
mod question_steps;
mod reaction_forms;
mod reaction_frames;
mod reduced;
mod rejected;
mod relations;
mod relaxed;
mod row_names;
mod row_view;
mod sense_words;
mod settled;
mod show_conditions;
mod shown_names;
mod simulation;
mod sliding_rows;
mod sliding_solve;
mod solve_words;
mod speeds;
mod spin_frames;
mod stability_answers;
mod static_answers;
mod statics;
mod steady_check;
mod steady_force;
mod switch_steps;
mod tex;
mod vector_answers;
mod written_out;

pub use answer_numbers::labels as answer_labels;
pub use answer_sheet::{
    csv_cell, full as full_digits, json as answer_sheet_json, key_columns,
    text as answer_sheet_text,
};
pub use answers::section as answers_section;
pub use build::{setup, solution as worked};
pub use derived::plan as plan_view;
pub use eigen_plot::sweep_plot;
pub use handout::{handout, student, Handout};
pub use pictures::motion::motion as motion_picture;
pub use pictures::{
    draw as draw_pictures, free_body_sets, point_id, FREE_BODY_LEGEND, FREE_BODY_LEGEND_THIRD_LAW,
    SLIDING_FRICTION,
};
pub use row_view::equation_view;
pub use shown_names::shown_names;
pub use solve_words::constraint_block;
pub use statics::handout as statics_handout;
pub use tex::style_of;
pub use written_out::written_out;
