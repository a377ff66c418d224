//! Grading: a student's work on a problem checked item by item against the worked
//! solution, and the mistake named in the problem's notation.
//!
//! [`Reference::new`] derives the worked solution once (the chosen method's rows,
//! Newton–Euler's for every reaction, the answers) and samples the motion at a few random
//! states; [`grade`] compares every item of a [`Submission`] there:
//! - answers within 0.5 % (or 1e-6 near zero), a vector's components in the frame named;
//! - equations as a set (they must hold for the motion and determine every q''), each
//!   wrong one matched to the worked row it was meant to be, after scaling, and diagnosed
//!   part by part (the coefficient of each q'' and reaction, the terms without rates, the
//!   terms with rates) and by contribution (a weight's moment, an inertia force, an
//!   inertia torque);
//! - the q'', the kinematics, the partial velocities and the generalized forces by their
//!   values at the sampled states, vectors compared in N.
//!
//! [`grade_batch`] grades a class's submissions, each against its own variant, into a gradebook.

mod answers;
mod batch;
mod contributions;
mod diagnose;
mod equations;
mod names;
mod numbers;
mod parts;
mod reference;
mod report;
mod scalars;
mod submission;
mod vectors;

pub use batch::grade_batch;
pub use reference::{Reference, Sample};
pub use report::{Item, Report, Verdict};
pub use submission::{read, Submission};

/// The questions that `submissions` answer, by their index in `find.questions` (a key
/// that is no index names none), in order: those a reference for them must work out.
pub fn asked_questions<'s>(submissions: impl IntoIterator<Item = &'s Submission>) -> Vec<usize> {
    let mut asked: Vec<usize> = (submissions.into_iter())
        .filter_map(|s| s.answers.as_ref())
        .flatten()
        .filter_map(|(key, _)| key.parse::<usize>().ok())
        .collect();
    asked.sort_unstable();
    asked.dedup();
    asked
}

/// Grades `submission` against the worked solution `reference`: its answers, q'',
/// equations, kinematics, partial velocities and generalized forces, in that order.
pub fn grade(reference: &Reference, submission: &Submission) -> Report {
    let mut items = Vec::new();
    if let Some(given) = &submission.answers {
        items.extend(answers::grade(reference, given));
    }
    if let Some(given) = &submission.accelerations {
        items.extend(scalars::accelerations(reference, given));
    }
    if let Some(given) = &submission.equations {
        items.extend(equations::grade(reference, given));
    }
    if let Some(given) = &submission.kinematics {
        items.extend(vectors::kinematics(reference, given));
    }
    if let Some(given) = &submission.partial_velocities {
        items.extend(vectors::partial_velocities(reference, given));
    }
    if let Some(given) = &submission.generalized_forces {
        items.extend(scalars::generalized(reference, given));
    }
    Report {
        student: submission.student.clone(),
        items,
    }
}
