//! Steps 3 and 5 for one method: the unknowns ([`Setup`]), the method's own rows from its
//! module, then the rows checked against the unknowns and assembled into `A x = b`.

use super::method::Method;
use super::system::{Derivation, LinearSystem, Request, Rows};
use super::unknowns::{kane_reaction_joints, Inputs, MethodRows, Setup};
use crate::mechanics::Form;
use crate::mechanics::{MechanicsError, Model};
use crate::plan::{coefficient_rows, Action};
use crate::plan::{Equation, FreeBodies, Inertia, LazyInertia};
use crate::symbolic::{budget, linear_split, Symbol};

/// Steps 3 and 5: the equations of motion of `model` by `method`, from its free bodies
/// (step 2): the method's rows (for the Motion Law, the rows its planner chooses),
/// assembled into `A x = b`.
///
/// # Errors
/// When the planner finds no complete set of rows, or an unknown appears nonlinearly.
pub(super) fn write_equations<'p>(
    model: Model<'p>,
    free_bodies: FreeBodies,
    method: Method,
    request: Request<'_>,
) -> Result<Derivation<'p>, MechanicsError> {
    let FreeBodies { actions, inertia } = free_bodies;
    budget::step(match method {
        Method::MotionLaw => "writing the Motion Law's candidate rows (step 3)",
        Method::NewtonEuler => "writing the Newton–Euler rows (step 3)",
        Method::Kane => "writing Kane's generalized forces (step 3)",
        Method::Lagrange => "writing Lagrange's equations (step 3)",
    });
    let setup = Setup::new(&model, method)?;
    if let Some((system, reaction_joints)) =
        composite_alone(&model, &actions, &setup, method, request)
    {
        return Ok(Derivation {
            model,
            method,
            actions,
            lazy_inertia: inertia,
            rows: Vec::new(),
            rejected: Vec::new(),
            system,
            system_method: Method::Kane,
            composite_system: None,
            reaction_joints,
            dependent_speeds: None,
            kept_forces: None,
            lagrange_terms: Vec::new(),
        });
    }
    let inertia = inertia.into_written(&model);
    let inputs = Inputs {
        model: &model,
        actions: &actions,
        inertia: &inertia,
        states: request.states,
    };
    let mut lagrange_terms = Vec::new();
    let rows = match method {
        Method::NewtonEuler => super::newton_euler::rows(&inputs, setup),
        Method::Kane => super::kane::rows(&inputs, setup)?,
        Method::Lagrange => {
            let (rows, terms) = super::lagrange::rows(&inputs, setup)?;
            lagrange_terms = terms;
            rows
        }
        Method::MotionLaw => super::motion_law::rows(&inputs, setup),
    };
    let mut derivation = finish(model, method, actions, inertia, rows, request.form)?;
    derivation.lagrange_terms = lagrange_terms;
    Ok(derivation)
}

/// Kane's system by composite bodies, built alone for numbers where it stands in for the
/// method's rows ([`Rows::Fastest`], or Kane's own with [`Rows::Compiled`]), with the
/// sites whose reactions it solves for.
fn composite_alone(
    model: &Model,
    actions: &[Action],
    setup: &Setup,
    method: Method,
    request: Request<'_>,
) -> Option<(LinearSystem, Vec<usize>)> {
    match (method, request.form, request.rows) {
        (_, Form::Numeric, Rows::Fastest) | (Method::Kane, Form::Numeric, Rows::Compiled) => {
            // Kane's reactions: the requested ones, where every other method's are too
            // (`system_alone` applies to trees alone, without closures or contacts).
            let joints = kane_reaction_joints(model.problem, &setup.loop_sites);
            let kane_unknowns = setup.unknowns_of(model, &joints);
            super::composite::system_alone(model, actions, &kane_unknowns, &joints)
                .map(|system| (system, joints))
        }
        _ => None,
    }
}

/// The rows checked against the unknowns and assembled into the system.
fn finish<'p>(
    model: Model<'p>,
    method: Method,
    actions: Vec<Action>,
    inertia: Inertia,
    written: MethodRows,
    form: Form,
) -> Result<Derivation<'p>, MechanicsError> {
    let MethodRows {
        rows,
        rejected,
        unknowns,
        reaction_joints,
        dependent_speeds,
        kept_forces,
    } = written;
    // Loads that use rates (dampers) are written with the speeds too.
    let rows = match &model.speeds {
        Some(speeds) => rows
            .into_iter()
            .map(|row| row.map_expressions(|e| speeds.to_speeds(e)))
            .collect(),
        None => rows,
    };
    // Written with what holds on the motion (a gear's unit line of centres), where the
    // rows are evaluated.
    let rows: Vec<Equation> = rows
        .into_iter()
        .map(|row| super::on_motion::row(&model, row, &unknowns))
        .collect();
    if rows.len() != unknowns.len() {
        return Err(too_few_rows(
            &model,
            method,
            &actions,
            &inertia,
            (rows.len(), unknowns.len()),
        ));
    }
    budget::step("assembling the linear system (step 5)");
    let system = assemble(&rows, &unknowns)?;
    let composite_system = match (method, form) {
        (Method::Kane, Form::Numeric) => {
            super::composite::system(&model, &actions, &system, &reaction_joints)
        }
        _ => None,
    };
    Ok(Derivation {
        model,
        method,
        actions,
        lazy_inertia: LazyInertia::written(inertia),
        rows,
        rejected,
        system,
        system_method: method,
        composite_system,
        reaction_joints,
        dependent_speeds,
        kept_forces,
        lagrange_terms: Vec::new(),
    })
}

/// The error of a method that found fewer independent rows than unknowns, naming the
/// massless body or coordinate behind it where there is one.
fn too_few_rows(
    model: &Model,
    method: Method,
    actions: &[Action],
    inertia: &Inertia,
    (rows, unknowns): (usize, usize),
) -> MechanicsError {
    let accelerations: Vec<Symbol> = model.problem.speed_symbols(2);
    let mut message = format!(
        "{} found {rows} independent equations for {unknowns} unknowns",
        method.title(),
    );
    let mut path = "joints".to_string();
    if let Some(i) = massless_coordinate(model, actions, inertia, &accelerations) {
        let name = &model.problem.coordinates[i].name;
        match crate::mechanics::massless_body_moved_by(model, i) {
            Some(body) => {
                let body = model.problem.body(body);
                path = format!("{}.mass", body.path);
                message.push_str(": ");
                message.push_str(&crate::mechanics::undetermined(name, &body.name));
            }
            None => message.push_str(&format!(
                ": the coordinate `{name}` moves nothing with mass or inertia, so `{name}''` is undetermined"
            )),
        }
    }
    MechanicsError {
        path,
        message,
        hint: Some(
            "a coordinate may move nothing with mass, or a reaction may be undetermined".into(),
        ),
    }
}

/// A coordinate whose q'' has a zero coefficient in every one of Kane's rows (its column
/// of the mass matrix is zero), at generic states: the usual reason a plan falls short.
fn massless_coordinate(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    accelerations: &[Symbol],
) -> Option<usize> {
    let rows = super::kane::equations(model, actions, inertia, accelerations, (&[], &[]));
    let states = crate::mechanics::sample_states(model);
    let coefficients: Vec<Vec<f64>> = rows
        .iter()
        .flat_map(|row| coefficient_rows(row, accelerations, &states))
        .collect();
    (0..accelerations.len()).find(|&i| coefficients.iter().all(|row| row[i].abs() < 1e-12))
}

/// `A x = b` from rows linear in the unknowns.
fn assemble(rows: &[Equation], unknowns: &[Symbol]) -> Result<LinearSystem, MechanicsError> {
    let mut a = Vec::with_capacity(rows.len());
    let mut b = Vec::with_capacity(rows.len());
    for row in rows {
        let (coefficients, rest) =
            linear_split(&row.expression, unknowns).map_err(|e| MechanicsError {
                path: "loads".into(),
                message: e.to_string(),
                hint: Some("loads may not depend on second rates".into()),
            })?;
        a.push(coefficients);
        b.push(-rest);
    }
    Ok(LinearSystem {
        unknowns: unknowns.to_vec(),
        a,
        b,
    })
}
