//! A limit on the symbolic work of one derivation, so that a problem too large to multiply
//! out is refused in seconds rather than after minutes and gigabytes.
//!
//! The work is the number of expression nodes built plus the terms that sums and products
//! sort: deterministic, and roughly proportional to the time a derivation takes. Once
//! the limit is passed, the builders ([`add`](super::add), [`mul`](super::mul), …) return
//! zero at once, so the derivation runs out quickly; its caller then asks [`settle`] and
//! reports the overrun instead of whatever the zeros led to. Nothing built after the limit
//! is ever shown or evaluated.

use std::cell::Cell;
use std::fmt;

thread_local! {
    static SPENT: Cell<u64> = const { Cell::new(0) };
    static LIMIT: Cell<u64> = const { Cell::new(u64::MAX) };
    static STEP: Cell<&'static str> = const { Cell::new("deriving the equations") };
    static OVERRUN_STEP: Cell<Option<&'static str>> = const { Cell::new(None) };
    static ARMED: Cell<bool> = const { Cell::new(false) };
}

/// The default limit of the command line, in units of work: about 20 s of symbolic work
/// on a laptop. `--max-work` changes it.
pub const DEFAULT_LIMIT: u64 = 150_000_000;

/// The work a derivation was refused for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Overrun {
    /// The step that was being worked on when the limit was passed.
    pub step: &'static str,
    /// The limit, in units of work.
    pub limit: u64,
}

impl fmt::Display for Overrun {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the symbolic work passed its limit of {} million units (terms built or sorted) while {}: \
             multiplied out, this problem's equations are too large to derive in reasonable \
             time and memory",
            self.limit / 1_000_000,
            self.step
        )
    }
}

impl std::error::Error for Overrun {}

/// Sets the limit for the derivations that follow on this thread (`u64::MAX`: none, the
/// library's default).
pub fn set_limit(limit: u64) {
    LIMIT.with(|l| l.set(limit));
}

/// The limit now in force.
pub fn limit() -> u64 {
    LIMIT.with(Cell::get)
}

/// Starts counting a new derivation from zero, against the limit, until [`settle`]. Work
/// outside such a span is counted but never limited, so that no caller can be handed the
/// zeros of an overrun it does not ask about.
pub fn start() {
    SPENT.with(|s| s.set(0));
    OVERRUN_STEP.with(|o| o.set(None));
    ARMED.with(|a| a.set(true));
}

/// Names the step the work now goes to, for the message if the limit is passed there.
pub fn step(name: &'static str) {
    STEP.with(|s| s.set(name));
}

/// Counts `units` of work: a node built, or a term a sum or product sorts.
#[inline]
pub(crate) fn charge(units: u64) {
    SPENT.with(|s| {
        let spent = s.get().saturating_add(units);
        s.set(spent);
        if spent >= LIMIT.with(Cell::get) && ARMED.with(Cell::get) && !exhausted() {
            OVERRUN_STEP.with(|o| o.set(Some(STEP.with(Cell::get))));
        }
    });
}

/// Whether the limit has been passed: the builders then return zero at once.
#[inline]
pub fn exhausted() -> bool {
    OVERRUN_STEP.with(|o| o.get().is_some())
}

/// The work counted since [`start`].
pub fn spent() -> u64 {
    SPENT.with(Cell::get)
}

/// The overrun, if the limit was passed since [`start`].
///
/// # Errors
/// [`Overrun`] naming the step where the limit was passed.
pub fn settle() -> Result<(), Overrun> {
    ARMED.with(|a| a.set(false));
    match OVERRUN_STEP.with(|o| o.replace(None)) {
        Some(step) => Err(Overrun {
            step,
            limit: limit(),
        }),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::Expr;

    #[test]
    fn passing_the_limit_names_the_step_and_makes_builders_return_zero() {
        set_limit(50);
        start();
        step("testing");
        let x = Expr::constant("x");
        let mut sum = Expr::zero();
        for i in 0..100 {
            sum = &sum + &(&x * &Expr::int(i));
        }
        assert!(exhausted());
        assert!(sum.is_zero(), "built after the limit: {sum}");
        let overrun = settle().unwrap_err();
        assert_eq!(overrun.step, "testing");
        // Settled: builders work again, and work outside start..settle is never limited.
        assert!(!exhausted());
        for i in 0..100 {
            sum = &sum + &(&x * &Expr::int(i));
        }
        assert!(!sum.is_zero());
        assert!(settle().is_ok());
        set_limit(u64::MAX);
    }
}
