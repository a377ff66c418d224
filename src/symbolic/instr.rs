//! The instructions of a compiled [`Program`](super::compile::Program): what each reads,
//! and what it computes.

use super::eval::{apply, power};
use super::expr::Func;

/// One step of a program. Slots are u32, so a program of millions of steps still fits.
#[derive(Clone, Debug)]
pub(super) enum Instr {
    /// Entry `i` of the constant table; only while compiling (a run copies the table).
    Const(u32),
    Mul(u32, u32),
    Neg(u32),
    Recip(u32),
    Square(u32),
    Pow(u32, u32),
    Func(Func, u32, u32),
    /// `Σ a·b` over the first `positive` pairs minus `Σ a·b` over the rest: a whole sum in
    /// one step, added up in a register, instead of a load, an add and a store per term.
    Dot {
        pairs: Box<[[u32; 2]]>,
        positive: u32,
    },
}

impl Instr {
    /// The slots it reads.
    pub(super) fn operands(&self) -> Vec<u32> {
        match self {
            Instr::Const(_) => vec![],
            Instr::Neg(a) | Instr::Recip(a) | Instr::Square(a) => vec![*a],
            Instr::Mul(a, b) | Instr::Pow(a, b) | Instr::Func(_, a, b) => vec![*a, *b],
            Instr::Dot { pairs, .. } => pairs.iter().flatten().copied().collect(),
        }
    }

    /// Whether it reads a slot for which `test` holds; unlike [`Instr::operands`], with no
    /// list built, for a test run once per instruction per evaluation.
    pub(super) fn reads_any(&self, test: impl Fn(u32) -> bool) -> bool {
        match self {
            Instr::Const(_) => false,
            Instr::Neg(a) | Instr::Recip(a) | Instr::Square(a) => test(*a),
            Instr::Mul(a, b) | Instr::Pow(a, b) | Instr::Func(_, a, b) => test(*a) || test(*b),
            Instr::Dot { pairs, .. } => pairs.iter().flatten().any(|&s| test(s)),
        }
    }

    /// What it does, as a number: equal for instructions that run the same code.
    pub(super) fn kind(&self) -> u8 {
        match self {
            Instr::Const(_) => 0,
            Instr::Mul(..) => 1,
            Instr::Neg(_) => 2,
            Instr::Recip(_) => 3,
            Instr::Square(_) => 4,
            Instr::Pow(..) => 5,
            Instr::Dot { .. } => 6,
            Instr::Func(f, ..) => 7 + *f as u8,
        }
    }

    /// The number of arithmetic operations and function calls it does.
    pub(super) fn operation_count(&self) -> usize {
        match self {
            Instr::Const(_) => 0,
            // A product per pair whose second factor is not one, and the additions.
            Instr::Dot { pairs, .. } => 2 * pairs.len() - 1,
            _ => 1,
        }
    }

    /// The same instruction reading `renumber(slot)` for each slot.
    pub(super) fn renumbered(&self, renumber: impl Fn(u32) -> u32) -> Instr {
        match self {
            Instr::Const(i) => Instr::Const(*i),
            Instr::Mul(a, b) => Instr::Mul(renumber(*a), renumber(*b)),
            Instr::Neg(a) => Instr::Neg(renumber(*a)),
            Instr::Recip(a) => Instr::Recip(renumber(*a)),
            Instr::Square(a) => Instr::Square(renumber(*a)),
            Instr::Pow(a, b) => Instr::Pow(renumber(*a), renumber(*b)),
            Instr::Func(f, a, b) => Instr::Func(*f, renumber(*a), renumber(*b)),
            Instr::Dot { pairs, positive } => Instr::Dot {
                pairs: pairs
                    .iter()
                    .map(|[a, b]| [renumber(*a), renumber(*b)])
                    .collect(),
                positive: *positive,
            },
        }
    }

    /// Its value, reading the slots in `s`.
    #[inline]
    pub(super) fn execute(&self, s: &[f64]) -> f64 {
        match self {
            // Never in a finished program: the constants are a table of their own.
            Instr::Const(_) => f64::NAN,
            Instr::Mul(a, b) => s[*a as usize] * s[*b as usize],
            Instr::Neg(a) => -s[*a as usize],
            Instr::Recip(a) => 1.0 / s[*a as usize],
            Instr::Square(a) => s[*a as usize] * s[*a as usize],
            Instr::Pow(a, b) => power(s[*a as usize], s[*b as usize]),
            Instr::Func(f, a, b) => apply(*f, s[*a as usize], s[*b as usize]),
            Instr::Dot { pairs, positive } => {
                let (plus, minus) = pairs.split_at(*positive as usize);
                let sum = |pairs: &[[u32; 2]]| -> f64 {
                    pairs
                        .iter()
                        .map(|[a, b]| s[*a as usize] * s[*b as usize])
                        .sum()
                };
                sum(plus) - sum(minus)
            }
        }
    }
}
