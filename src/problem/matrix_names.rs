//! Names for the handout's matrices that no body, frame, point or constant of the problem
//! uses: the system matrix and right-hand side `A x = b`, and the matrix of the dependent
//! rates `q̇_D = C q̇_I`. A double pendulum's bodies A and B, or a four-bar's lengths b and
//! c, would otherwise read as the matrix's name.

use super::Problem;
use serde::Serialize;

/// The system matrix's names in order of preference: the first free one is taken. None is
/// a letter the handout itself gives a meaning: the energy E, the angular momentum H, the
/// kinetic and potential energies T and V, the work W, the frame N, a contact point U.
const SYSTEM: [&str; 5] = ["A", "S", "D", "G", "Z"];

/// The right-hand side's names in order of preference (none the handout's own, as above).
const RIGHT_SIDE: [&str; 4] = ["b", "f", "d", "z"];

/// The names of the column of unknowns (`A x = b`) and of the state of the small motions
/// (`ż = A z`), in order of preference: a letter no coordinate or name of the problem uses
/// (a cart's `x`), never `q` or `u`, a handout's coordinates and speeds.
const UNKNOWNS: [&str; 6] = ["x", "z", "w", "y", "s", "p"];

/// The dependent rates' matrix's names in order of preference.
const DEPENDENT: [&str; 5] = ["C", "D", "G", "Y", "Z"];

/// The names of the three matrices, as LaTeX letters.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct MatrixNames {
    /// The system matrix, `A` unless the problem uses it.
    pub a: String,
    /// The right-hand side, `b` unless the problem uses it.
    pub b: String,
    /// The matrix of the dependent rates, `C` unless the problem uses it.
    pub c: String,
    /// The column of unknowns, `x` unless the problem uses it.
    pub x: String,
    /// The state of the small motions, `z` unless the problem uses it.
    pub z: String,
}

impl Default for MatrixNames {
    fn default() -> Self {
        MatrixNames {
            a: SYSTEM[0].into(),
            b: RIGHT_SIDE[0].into(),
            c: DEPENDENT[0].into(),
            x: UNKNOWNS[0].into(),
            z: UNKNOWNS[1].into(),
        }
    }
}

impl MatrixNames {
    /// The first names of each list that no one-letter name of `problem` uses, letters
    /// compared without case (body B's unit vectors are b̂): the last of a list when all
    /// are taken.
    pub fn of(problem: &Problem) -> MatrixNames {
        let used = used_letters(problem);
        // Each the first free name of its list: A x = b, or A z = f beside a body B, as a
        // course keeps A for the matrix wherever it can.
        let (a, b) = (first_free(&used, &SYSTEM), first_free(&used, &RIGHT_SIDE));
        // The column of unknowns also differs from the coordinates, the matrices and the
        // right-hand side; the state of the small motions from all of those too.
        let mut vectors = used.clone();
        vectors.extend(problem.coordinates.iter().filter_map(|c| {
            let stem: Vec<char> = c
                .name
                .chars()
                .take_while(char::is_ascii_alphabetic)
                .collect();
            (stem.len() == 1).then(|| stem[0].to_ascii_lowercase())
        }));
        vectors.extend([&a, &b].iter().filter_map(|n| n.chars().next()));
        vectors = vectors.iter().map(char::to_ascii_lowercase).collect();
        let x = first_free(&vectors, &UNKNOWNS);
        vectors.extend(x.chars().next());
        let z = first_free(&vectors, &UNKNOWNS);
        MatrixNames {
            a,
            b,
            c: first_free(&used, &DEPENDENT),
            x,
            z,
        }
    }
}

/// The first of `letters` that no one-letter name of `problem` uses, letters compared
/// without case (body B's unit vectors are b̂): the last of the list when all are taken.
/// A general symbol of a formula (the point of Kane's `R_P`) is named so too.
pub fn free_letter(problem: &Problem, letters: &[&str]) -> String {
    first_free(&used_letters(problem), letters)
}

/// The first of `letters` whose letter (small) is not in `used`; the last when all are.
fn first_free(used: &[char], letters: &[&str]) -> String {
    let first = letters.iter().find(|name| {
        let letter = name.chars().next().unwrap_or(' ').to_ascii_lowercase();
        !used.contains(&letter)
    });
    first
        .or(letters.last())
        .copied()
        .unwrap_or_default()
        .to_string()
}

/// The letters (small) the handout prints as names: a name prints as one letter (with any
/// index, `B`, `b1`, `m_2`) or as a word (`bob`, upright), and only a letter can be read as
/// a matrix's or a formula's symbol; the spin frame a handout adds counts too.
fn used_letters(problem: &Problem) -> Vec<char> {
    let mut used: Vec<char> = used_names(problem)
        .filter_map(|n| {
            let stem: Vec<char> = n.chars().take_while(char::is_ascii_alphabetic).collect();
            (stem.len() == 1).then(|| stem[0].to_ascii_lowercase())
        })
        .collect();
    used.extend(spin_frame_letter(problem));
    used
}

/// The letter (small) of the frame a handout adds for a body spinning about its symmetry
/// axis on a joint of several turns (Resal's frame): the first capital that names no body,
/// as the kinematics takes it. Only in space, where a joint turns about more than one axis.
fn spin_frame_letter(problem: &Problem) -> Option<char> {
    use super::JointKind;
    let turns = problem.joints.iter().any(|j| {
        matches!(
            j.kind,
            JointKind::Spherical | JointKind::Universal | JointKind::Free
        )
    });
    if problem.dimension != super::Dimension::Three || !turns {
        return None;
    }
    let taken =
        |c: char| (problem.bodies.iter()).any(|b| b.name.eq_ignore_ascii_case(&c.to_string()));
    ('A'..='Z')
        .find(|&c| c != 'N' && !taken(c))
        .map(|c| c.to_ascii_lowercase())
}

/// Every name a handout prints for the problem: bodies (and their frames), joints and
/// closures (their points), declared points, constraints and constants.
fn used_names(problem: &Problem) -> impl Iterator<Item = &str> {
    let bodies = problem.bodies.iter().map(|b| b.name.as_str());
    let joints = problem.joints.iter().map(|j| j.name.as_str());
    let closures = problem.closures.iter().map(|j| j.name.as_str());
    let points = problem.points.iter().map(|p| p.name.as_str());
    let constants = problem.constants.iter().map(|c| c.name.as_str());
    let constraints = problem.constraints.iter().map(|c| c.name.as_str());
    bodies
        .chain(joints)
        .chain(closures)
        .chain(points)
        .chain(constants)
        .chain(constraints)
}
