//! The power of friction along a run, for the energy balance with the applied loads: at
//! each rough site, each friction component times the slip velocity along it. The friction
//! component is the site's reaction, as the run's columns give it in the unit vectors of the
//! site's parent, dotted with the component's direction; between two rows of the run it is
//! taken linearly in time, the state as `work_along` gives it. A sticking site does no work
//! (its slip is zero), nor does a normal force (it has no slip along it).

use super::inputs::state_symbols;
use super::simulate::Trajectory;
use crate::mechanics::Model;
use crate::problem::Problem;
use crate::symbolic::{ComponentKind, Expr, Program};

/// The power of friction at a time and a state (each coordinate's `(q, q')`), W; zero
/// without friction. `None` where the problem has friction the model has no site for, or
/// the run lacks a rough site's reaction columns: its work is then not known.
#[allow(clippy::type_complexity)] // a closure over (time, state) pairs; named, it hides the shape
pub(super) fn friction_power<'a>(
    problem: &'a Problem,
    trajectory: &'a Trajectory,
) -> Option<impl FnMut(f64, &[(f64, f64)]) -> Option<f64> + 'a> {
    let rough = (problem.constraints.iter().map(|c| &c.friction))
        .chain(problem.joints.iter().map(|j| &j.friction))
        .chain(problem.closures.iter().map(|j| &j.friction))
        .filter(|f| f.is_some())
        .count();
    // Per slip row: the run's three columns of its reaction, and four outputs of the
    // program: the component's direction in the parent's unit vectors, then the slip.
    let mut columns: Vec<[usize; 3]> = Vec::new();
    let mut outputs: Vec<Expr> = Vec::new();
    if rough > 0 {
        let model = Model::build(problem).ok()?;
        if model.constraints.friction.len() != rough {
            return None;
        }
        for friction in &model.constraints.friction {
            let site = &model.sites[friction.site];
            for row in &friction.stick {
                let c = (site.reactions.iter()).find(|c| c.unknown(&site.name) == row.unknown)?;
                let kind = match c.kind {
                    ComponentKind::Force => "force",
                    ComponentKind::Moment => "moment",
                };
                let column =
                    |axis: &str| trajectory.column(&format!("{}.{kind}.{axis}", site.name));
                columns.push([column("x")?, column("y")?, column("z")?]);
                outputs.extend(c.direction.components_in(site.parent, &model.frames));
                outputs.push(row.velocity.clone());
            }
        }
    }
    let program = Program::compile(&state_symbols(problem), &outputs);
    let constants: Vec<f64> = problem.constants.iter().map(|c| c.value).collect();
    let rows = &trajectory.rows;
    let (mut scratch, mut out) = (Vec::new(), vec![0.0; outputs.len()]);
    Some(move |t: f64, state: &[(f64, f64)]| {
        if columns.is_empty() || rows.len() < 2 {
            return Some(0.0);
        }
        let mut inputs = constants.clone();
        inputs.extend(state.iter().map(|s| s.0));
        inputs.extend(state.iter().map(|s| s.1));
        inputs.push(t);
        program.run(&inputs, &mut scratch, &mut out);
        // The two rows about t, and the reaction between them.
        let i = rows.partition_point(|r| r[0] <= t).clamp(1, rows.len() - 1);
        let (a, b) = (&rows[i - 1], &rows[i]);
        let s = (t - a[0]) / (b[0] - a[0]);
        let at = |k: usize| a[k] + s * (b[k] - a[k]);
        let power: f64 = (columns.iter().enumerate())
            .map(|(r, c)| {
                let d = &out[4 * r..4 * r + 4];
                (at(c[0]) * d[0] + at(c[1]) * d[1] + at(c[2]) * d[2]) * d[3]
            })
            .sum();
        power.is_finite().then_some(power)
    })
}
