//! The frame step 5's table of reactions writes each reaction in: of the body the joint is
//! mounted on, `N` and the body it carries, the one whose unit vectors give the force and
//! the moment the fewest components (the mounting body's when none gives fewer). A gear's
//! tooth force, tangential to the pitch circles, is then 15 n̂_y, as the Answers give it,
//! not 4.43 â_x + 14.33 â_y along the turning pinion's axes.

use crate::numeric::answer_frame_rotation;
use crate::problem::{BodyId, Problem};

/// A reaction's force and moment at the initial state, with the frame they are along.
pub(super) struct Written {
    /// The frame whose unit vectors the components are along.
    pub frame: BodyId,
    /// The force's components.
    pub force: [f64; 3],
    /// The moment's components.
    pub moment: [f64; 3],
}

/// Below this fraction of the largest component a component is round-off of zero.
const ROUND_OFF: f64 = 1e-9;

fn cleaned(v: [f64; 3]) -> [f64; 3] {
    let largest = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    v.map(|x| {
        if x.abs() <= ROUND_OFF * largest {
            0.0
        } else {
            x
        }
    })
}

fn count(v: &[f64; 3]) -> usize {
    v.iter().filter(|x| **x != 0.0).count()
}

/// The simplest of the mounting body `parent`, `N` and the carried body `child` to write
/// force `f` and moment `m` (given along `parent`'s unit vectors) in, at the state `q`,
/// `rates`.
pub(super) fn simplest(
    problem: &Problem,
    (parent, child): (BodyId, BodyId),
    (f, m): ([f64; 3], [f64; 3]),
    (q, rates): (&[f64], &[f64]),
) -> Written {
    let mut best = Written {
        frame: parent,
        force: cleaned(f),
        moment: cleaned(m),
    };
    for frame in [BodyId::GROUND, child] {
        if frame == best.frame {
            continue;
        }
        let Ok(turn) = answer_frame_rotation(problem, (frame, parent), 0.0, q, rates) else {
            continue;
        };
        let rotate = |v: [f64; 3]| -> [f64; 3] {
            std::array::from_fn(|i| (0..3).map(|k| turn[i][k] * v[k]).sum())
        };
        let (force, moment) = (cleaned(rotate(f)), cleaned(rotate(m)));
        if count(&force) + count(&moment) < count(&best.force) + count(&best.moment) {
            best = Written {
                frame,
                force,
                moment,
            };
        }
    }
    best
}
