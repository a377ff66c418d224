//! The answers of the problems answered so far in this run, kept for the stage that asks
//! for them again: `variants` answers every variant for its key, then writes each one's
//! worked solution, which answers the same problem by the same method.

use crate::equations::Method;
use crate::error::Error;
use crate::numeric::Answer;
use crate::problem::Problem;
use std::cell::RefCell;

/// How many problems' answers are kept: a class's variants and more; the oldest go first.
const KEEP: usize = 1000;

type Kept = Vec<(Problem, Method, Vec<Answer>)>;

thread_local! {
    static KEPT: RefCell<Kept> = const { RefCell::new(Vec::new()) };
}

/// The answers of `problem` by `method`: those kept from an earlier call where the problem
/// and the method are the same (every constant, body and question equal), else
/// `compute`'s, kept when found.
///
/// # Errors
/// `compute`'s error; an error is not kept.
pub fn answers(
    problem: &Problem,
    method: Method,
    compute: impl FnOnce() -> Result<Vec<Answer>, Error>,
) -> Result<Vec<Answer>, Error> {
    let kept = KEPT.with(|kept| {
        (kept.borrow().iter())
            .find(|(p, m, _)| *m == method && p == problem)
            .map(|(_, _, answers)| answers.clone())
    });
    if let Some(answers) = kept {
        return Ok(answers);
    }
    let answers = compute()?;
    KEPT.with(|kept| {
        let mut kept = kept.borrow_mut();
        if kept.len() >= KEEP {
            kept.remove(0);
        }
        kept.push((problem.clone(), method, answers.clone()));
    });
    Ok(answers)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    /// The simple pendulum with the bob's mass `mass`.
    fn pendulum(mass: &str) -> Problem {
        let text = include_str!("../../problems/simple-pendulum.json")
            .replace("\"value\": 0.5,", &format!("\"value\": {mass},"));
        let Ok(problem) = crate::problem::load(&text) else {
            panic!("the pendulum loads");
        };
        problem
    }

    #[test]
    fn the_same_problem_is_answered_once_and_another_afresh() {
        let calls = Cell::new(0);
        let count = || {
            calls.set(calls.get() + 1);
            Ok(Vec::new())
        };
        let failing = || Err(Error::Usage("no answers".into()));
        assert!(answers(&pendulum("0.5"), Method::Kane, count).is_ok());
        // Read again from its text: equal, so kept.
        assert!(answers(&pendulum("0.5"), Method::Kane, count).is_ok());
        assert_eq!(calls.get(), 1);
        // Another mass, another method: answered afresh.
        assert!(answers(&pendulum("0.7"), Method::Kane, count).is_ok());
        assert!(answers(&pendulum("0.5"), Method::MotionLaw, count).is_ok());
        assert_eq!(calls.get(), 3);
        // An error is not kept.
        assert!(answers(&pendulum("0.9"), Method::Kane, failing).is_err());
        assert!(answers(&pendulum("0.9"), Method::Kane, count).is_ok());
        assert_eq!(calls.get(), 4);
    }
}
