//! Springs and dampers that share both ends (a spring and a damper in parallel) drawn side
//! by side, each in its lane (see [`crate::render::draw::in_lane`]).

/// Per load of `loads`, its lane: 0 for a spring or damper alone between its two points,
/// and for those that share both ends (a spring and a damper in parallel), steps of one
/// either side of the line, as a textbook draws them side by side.
pub fn lanes(loads: &[crate::problem::Load]) -> Vec<f64> {
    use crate::problem::LoadKind;
    let ends: Vec<Option<[crate::problem::PointRef; 2]>> = loads
        .iter()
        .map(|load| match &load.kind {
            LoadKind::Spring { between, .. } | LoadKind::Damper { between, .. } => Some(*between),
            _ => None,
        })
        .collect();
    let same = |x: &Option<[crate::problem::PointRef; 2]>,
                [a, b]: [crate::problem::PointRef; 2]| {
        matches!(x, Some([c, d]) if (*c == a && *d == b) || (*c == b && *d == a))
    };
    ends.iter()
        .enumerate()
        .map(|(i, pair)| {
            let Some(pair) = *pair else { return 0.0 };
            let sharing = ends.iter().filter(|x| same(x, pair)).count();
            let before = ends[..i].iter().filter(|x| same(x, pair)).count();
            before as f64 - (sharing - 1) as f64 / 2.0
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::problem::{BodyId, Load, LoadKind, PointRef};
    use crate::symbolic::Expr;

    fn element(spring: bool, between: [PointRef; 2]) -> Load {
        let zero = Expr::zero();
        let kind = if spring {
            LoadKind::Spring {
                between,
                stiffness: zero.clone(),
                free_length: zero,
            }
        } else {
            LoadKind::Damper {
                between,
                coefficient: zero,
            }
        };
        Load {
            name: None,
            kind,
            path: String::new(),
        }
    }

    #[test]
    fn a_spring_and_a_damper_between_the_same_points_go_side_by_side() {
        let (wall, a, b) = (
            PointRef::Origin(BodyId::GROUND),
            PointRef::MassCenter(BodyId(1)),
            PointRef::MassCenter(BodyId(2)),
        );
        let loads = [
            element(true, [wall, a]),
            element(false, [a, wall]),
            element(true, [a, b]),
        ];
        assert_eq!(lanes(&loads), [-0.5, 0.5, 0.0]);
    }
}
