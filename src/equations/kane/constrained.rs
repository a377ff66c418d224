//! Kane's method for a constrained system, as Kane and Levinson teach it: one equation
//! `F̃_r + F̃*_r = 0` per independent speed, formed with the constrained partial velocities
//! `ṽ_r = v_r + Σ_s C_sr v_s`, in which no constraint or contact force appears; one row per
//! prescribed coordinate for its drive; one per requested reaction component, through an
//! auxiliary speed along it (ch. 4). The differentiated constraints give the dependent q''.
//!
//! Since `F̃_r = Σ F · ṽ_r = F_r + Σ_s C_sr F_s`, each row is the combination of the rows of
//! the coordinates' rates that the motion of its speed weighs them by, formed without the
//! constraint forces; the one unknown force a row is for is added with its unit weight.

use super::{auxiliary_rows, generalized_groups, generalized_row, Workless};
use crate::equations::on_motion;
use crate::mechanics::{drive_symbol, DependentSpeeds, Model, RowOrigin};
use crate::plan::{Action, Equation, Groups, Inertia};
use crate::symbolic::{add, linear_split, substitute, Expr, Symbol};

/// What the constrained rows are formed for.
pub struct Request<'a> {
    /// The dependent speeds.
    pub speeds: &'a DependentSpeeds,
    /// The sites whose reactions are asked for (tree joints, closures and contacts).
    pub reactions: &'a [usize],
    /// Forces that must stay unknowns though not asked for: at a site with friction, the
    /// normal force, which the friction force is written with, gets its auxiliary row as
    /// a requested reaction component does; the friction force does work with the slip
    /// rates (speeds) and is found by the site's stick row or sliding law.
    pub kept: &'a [Symbol],
    /// The unknowns of the system, for each row's list of those it holds.
    pub unknowns: &'a [Symbol],
}

/// The name of the auxiliary speed along a constraint's reaction or drive, e.g. `u(floor.Fx)`.
fn auxiliary_name(what: &str) -> String {
    format!("u({what})")
}

/// Kane's rows with independent speeds: one per independent speed, one per prescribed
/// coordinate (its drive), one per requested reaction component.
pub fn equations(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    request: &Request,
) -> Vec<Equation> {
    let n = model.problem.coordinates.len();
    let speeds = request.speeds;
    let raw = generalized_groups(model, actions, inertia, Workless::EveryConstraintForce);
    let written = Written::new(model, speeds);
    let row = |name: String, groups: Groups| {
        generalized_row(
            model,
            name,
            on_motion::groups(model, groups),
            request.unknowns,
        )
    };
    let mut rows = Vec::new();
    for (r, &i) in speeds.independent.iter().enumerate() {
        // The rows an auxiliary speed adds are solved with every q'' known: they keep the
        // dependent ones.
        let groups = written.apply(combined(&raw, &speeds.independent_weights(r, n)));
        rows.push(row(
            model.problem.coordinate_symbol(i, 1).to_string(),
            groups,
        ));
    }
    for (p, &i) in speeds.prescribed.iter().enumerate() {
        // The drive does work only with its own coordinate's rate, by a unit weight.
        let name = &model.problem.coordinates[i].name;
        let mut groups = combined(&raw, &speeds.prescribed_weights(p, n));
        groups.contact = &groups.contact + &Expr::sym(drive_symbol(model.problem, i));
        rows.push(row(auxiliary_name(&format!("{name} drive")), groups));
    }
    let tree = model.problem.joints.len();
    let kept_joints = super::kept_joints(model, request.reactions, request.kept);
    let whole = request.reactions.iter().map(|&j| (j, None));
    let kept_components = kept_joints.iter().map(|&j| (j, Some(request.kept)));
    for (j, only) in whole.chain(kept_components) {
        if j < tree {
            for aux in auxiliary_rows(model, actions, inertia, request.unknowns, (j, only)) {
                let name = aux_speed(&aux);
                let groups = without_constraint_forces(model, speeds, &raw, aux.groups);
                rows.push(row(name, groups));
            }
            continue;
        }
        // Closures and contacts come whole: `kept_joints` holds tree joints alone.
        let site = &model.sites[j];
        for component in &site.reactions {
            let unknown = component.unknown(&site.name);
            let Some(k) = speeds.row_of(model, &unknown) else {
                continue;
            };
            let weights = speeds.violation_weights(k, n);
            let mut groups = combined(&raw, &weights);
            groups.contact = &groups.contact + &Expr::sym(unknown);
            let what = format!("{}.{}", site.name, component.component());
            rows.push(on_moved(
                row(auxiliary_name(&what), groups),
                model,
                &weights,
            ));
        }
    }
    for unknown in request.kept {
        if let Some(k) = speeds.row_of(model, unknown) {
            let weights = speeds.violation_weights(k, n);
            let mut groups = combined(&raw, &weights);
            groups.contact = &groups.contact + &Expr::sym(unknown.clone());
            let name = auxiliary_name(&model.constraints.rows[k].name);
            rows.push(on_moved(row(name, groups), model, &weights));
        }
    }
    rows
}

/// The rows written with the independent speeds alone, as Kane and Levinson write them:
/// each dependent rate and q'' replaced by its expression in the independent ones, where
/// that does not make a group much longer (then the group keeps them, and the
/// differentiated constraints give them).
struct Written<'m> {
    model: &'m Model<'m>,
    speeds: &'m DependentSpeeds,
    rates: Vec<Expr>,
    accelerations: Option<Vec<Expr>>,
}

/// How many times longer a group may grow when its dependent rates are written out.
const LONGEST_GROWTH: usize = 6;

impl<'m> Written<'m> {
    fn new(model: &'m Model<'m>, speeds: &'m DependentSpeeds) -> Written<'m> {
        Written {
            model,
            speeds,
            rates: speeds.dependent_rates(model),
            // A `C` evaluated at each state has no derivative a reader could follow: the
            // rows keep the dependent rates and q''.
            accelerations: if speeds.at_each_state {
                None
            } else {
                speeds.dependent_accelerations(model).ok()
            },
        }
    }

    fn apply(&self, groups: Groups) -> Groups {
        let Some(accelerations) = &self.accelerations else {
            return groups;
        };
        let problem = self.model.problem;
        let one = |e: &Expr| -> Expr {
            let with_rates = self
                .speeds
                .with_independent_rates(self.model, &self.rates, e);
            let out = substitute(&with_rates, &|symbol| {
                self.speeds
                    .dependent
                    .iter()
                    .position(|&d| problem.coordinate_symbol(d, 2) == *symbol)
                    .map(|s| accelerations[s].clone())
            });
            if out.operation_count() > LONGEST_GROWTH * e.operation_count().max(40) {
                e.clone()
            } else {
                out
            }
        };
        Groups {
            contact: one(&groups.contact),
            distance: one(&groups.distance),
            inertia_force: one(&groups.inertia_force),
            inertia_torque: one(&groups.inertia_torque),
        }
    }
}

/// `row` with the free body of the bodies its auxiliary speed moves (see [`super::moved`]).
fn on_moved(row: Equation, model: &Model, weights: &[Expr]) -> Equation {
    Equation {
        free_body: super::moved::moved_bodies(model, weights),
        ..row
    }
}

fn aux_speed(row: &Equation) -> String {
    match &row.sum {
        crate::plan::Sum::Generalized { speed } => speed.clone(),
        _ => String::new(),
    }
}

/// `Σ_c w_c G_c`, group by group.
fn combined(groups: &[Groups], weights: &[Expr]) -> Groups {
    let part = |of: fn(&Groups) -> &Expr| {
        add(groups
            .iter()
            .zip(weights)
            .filter(|(_, w)| !w.is_zero())
            .map(|(g, w)| if w.is_one() { of(g).clone() } else { of(g) * w }))
    };
    Groups {
        contact: part(|g| &g.contact),
        distance: part(|g| &g.distance),
        inertia_force: part(|g| &g.inertia_force),
        inertia_torque: part(|g| &g.inertia_torque),
    }
}

/// The auxiliary row of a tree joint's reaction component, whose rigid motion of the
/// subtree may violate the constraints: the dependent rates that restore them are added
/// to the motion, so that the constraint forces it brought in drop out. With `c_k` the
/// coefficient of the force of constraint `k` in the row, the motion gains `−c_k` times
/// the motion that violates `k` by a unit.
fn without_constraint_forces(
    model: &Model,
    speeds: &DependentSpeeds,
    raw: &[Groups],
    groups: Groups,
) -> Groups {
    let n = model.problem.coordinates.len();
    let enforcing: Vec<Symbol> = speeds
        .rows
        .iter()
        .map(|&k| model.constraints.rows[k].unknown.clone())
        .collect();
    let Ok((coefficients, contact)) = linear_split(&groups.contact, &enforcing) else {
        return groups;
    };
    let mut out = Groups { contact, ..groups };
    for (k, c) in coefficients.iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        let restoring = combined(raw, &speeds.violation_weights(k, n));
        let minus = -c.clone();
        out = Groups {
            contact: &out.contact + &(&restoring.contact * &minus),
            distance: &out.distance + &(&restoring.distance * &minus),
            inertia_force: &out.inertia_force + &(&restoring.inertia_force * &minus),
            inertia_torque: &out.inertia_torque + &(&restoring.inertia_torque * &minus),
        };
    }
    out
}

/// The unknowns of Kane's system with independent speeds: every q'', the components of the
/// requested reactions, and the drives of the prescribed coordinates. No multiplier and no
/// reaction that is not asked for, but those `kept` (see [`Request::kept`]).
pub fn unknowns(
    model: &Model,
    accelerations: &[Symbol],
    reactions: &[usize],
    kept: &[Symbol],
) -> Vec<Symbol> {
    let drives = model
        .constraints
        .rows
        .iter()
        .filter(|r| matches!(r.origin, RowOrigin::Prescribed(_)))
        .map(|r| r.unknown.clone());
    accelerations
        .iter()
        .cloned()
        .chain(crate::mechanics::reaction_unknowns(model, reactions))
        .chain(drives)
        .chain(kept.iter().cloned())
        .collect()
}
