//! Step 2's table of generalized forces by Lagrange's equations: what loads a coordinate
//! directly, named as the problem names it.

use crate::mechanics::Model;
use crate::plan::joint_load_value;
use crate::problem::LoadKind;
use crate::symbolic::{simplify, Expr};

/// What acts on coordinate `r` directly, as step 2 names it: the joint loads (`motor`, a
/// damper), and friction where the rough sliders add to `q`, the coordinate's share.
pub(super) fn direct_load_label(model: &Model, r: usize, q: &Expr) -> String {
    let problem = model.problem;
    let mut joint_sum = Expr::zero();
    let mut names: Vec<String> = Vec::new();
    for load in &problem.loads {
        if matches!(load.kind, LoadKind::JointSpring { .. }) {
            continue;
        }
        let Some((_, _, value)) = joint_load_value(problem, &load.kind).filter(|v| v.1 == r) else {
            continue;
        };
        joint_sum = &joint_sum + &value;
        names.push(load.name.clone().unwrap_or_else(|| match load.kind {
            LoadKind::JointDamper { .. } => "damper".to_string(),
            _ => "actuator".to_string(),
        }));
    }
    if !simplify(&(q - &joint_sum)).is_zero() {
        names.push("friction".to_string());
    }
    let coordinate = crate::symbolic::latex_name(&problem.coordinates[r].name);
    format!("{} (on ${coordinate}$)", names.join(" and "))
}
