//! A compiled program laid out for running: its instructions cut into runs of one kind,
//! each run's operands in one flat array. The schedule already puts like instructions
//! together (see [`super::schedule`]); here a run decides what it is once and then loops
//! over plain operand arrays, where one [`Instr`] at a time decides it per instruction and
//! a sum reads its pairs through a pointer of its own. Every instruction computes what
//! [`Instr::execute`] does, in the same order, so the results are the same to the bit.

use super::eval::{apply, power};
use super::expr::Func;
use super::instr::Instr;

/// What every instruction of a run does.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Mul,
    Neg,
    Recip,
    Square,
    Pow,
    Func(Func),
    /// Each instruction's operands: the count of added pairs, the count of all pairs, then
    /// the pairs.
    Dot,
}

/// The instructions of a program as runs (see the module documentation).
#[derive(Clone, Debug, Default)]
pub(super) struct Runs {
    /// Each run: its kind and how many instructions it holds.
    runs: Vec<(Kind, u32)>,
    operands: Vec<u32>,
}

impl Runs {
    /// The runs of `instructions`, whose results go to the slots from `first` on. A run also
    /// ends where an instruction reads a result of the same run, so that a run reads only
    /// slots below its own.
    pub(super) fn new(instructions: &[Instr], first: usize) -> Runs {
        let mut runs = Runs::default();
        let mut run_start = first;
        for (i, instr) in instructions.iter().enumerate() {
            let slot = first + i;
            let kind = match instr {
                Instr::Const(_) => unreachable!("the constants are a table of their own"),
                Instr::Mul(..) => Kind::Mul,
                Instr::Neg(_) => Kind::Neg,
                Instr::Recip(_) => Kind::Recip,
                Instr::Square(_) => Kind::Square,
                Instr::Pow(..) => Kind::Pow,
                Instr::Func(f, ..) => Kind::Func(*f),
                Instr::Dot { .. } => Kind::Dot,
            };
            let reads_run = instr.reads_any(|s| s as usize >= run_start);
            match runs.runs.last_mut() {
                Some((last, count)) if *last == kind && !reads_run => *count += 1,
                _ => {
                    runs.runs.push((kind, 1));
                    run_start = slot;
                }
            }
            match instr {
                Instr::Const(_) => {}
                Instr::Neg(a) | Instr::Recip(a) | Instr::Square(a) => runs.operands.push(*a),
                Instr::Mul(a, b) | Instr::Pow(a, b) | Instr::Func(_, a, b) => {
                    runs.operands.extend([*a, *b]);
                }
                Instr::Dot { pairs, positive } => {
                    runs.operands.extend([*positive, pairs.len() as u32]);
                    runs.operands.extend(pairs.iter().flatten());
                }
            }
        }
        runs
    }

    /// Runs every instruction, writing slot `first + i` from the slots below it in `s`.
    pub(super) fn execute(&self, s: &mut [f64], first: usize) {
        let mut slot = first;
        let mut operands = &self.operands[..];
        for &(kind, count) in &self.runs {
            let count = count as usize;
            let (done, rest) = s.split_at_mut(slot);
            let out = &mut rest[..count];
            let v = |a: &u32| done[*a as usize];
            let used = match kind {
                Kind::Mul => binary(out, operands, |a, b| v(a) * v(b)),
                Kind::Pow => binary(out, operands, |a, b| power(v(a), v(b))),
                Kind::Func(f) => binary(out, operands, |a, b| apply(f, v(a), v(b))),
                Kind::Neg => unary(out, operands, |a| -v(a)),
                Kind::Recip => unary(out, operands, |a| 1.0 / v(a)),
                Kind::Square => unary(out, operands, |a| v(a) * v(a)),
                Kind::Dot => {
                    let mut at = 0;
                    for o in out.iter_mut() {
                        let (positive, len) = (operands[at] as usize, operands[at + 1] as usize);
                        let pairs = &operands[at + 2..at + 2 + 2 * len];
                        let (plus, minus) = pairs.split_at(2 * positive);
                        let sum = |pairs: &[u32]| -> f64 {
                            pairs.chunks_exact(2).map(|p| v(&p[0]) * v(&p[1])).sum()
                        };
                        *o = sum(plus) - sum(minus);
                        at += 2 + 2 * len;
                    }
                    at
                }
            };
            operands = &operands[used..];
            slot += count;
        }
    }
}

/// Each of `out` from two operands; the number of operands read.
#[inline]
fn binary(out: &mut [f64], operands: &[u32], f: impl Fn(&u32, &u32) -> f64) -> usize {
    for (o, pair) in out.iter_mut().zip(operands.chunks_exact(2)) {
        *o = f(&pair[0], &pair[1]);
    }
    2 * out.len()
}

/// Each of `out` from one operand; the number of operands read.
#[inline]
fn unary(out: &mut [f64], operands: &[u32], f: impl Fn(&u32) -> f64) -> usize {
    for (o, a) in out.iter_mut().zip(operands) {
        *o = f(a);
    }
    out.len()
}

#[cfg(test)]
mod tests {
    use crate::symbolic::build::{cos, pow, sin};
    use crate::symbolic::compile::Program;
    use crate::symbolic::{Expr, Symbol};

    /// The program one instruction at a time, as [`super::Instr::execute`] computes it.
    fn one_at_a_time(program: &Program, inputs: &[f64]) -> Vec<f64> {
        let mut s: Vec<f64> = inputs.to_vec();
        s.extend(&program.constants);
        for instr in &program.instructions {
            let value = instr.execute(&s);
            s.push(value);
        }
        program.outputs.iter().map(|&slot| s[slot]).collect()
    }

    #[test]
    fn runs_compute_what_each_instruction_does_to_the_bit() {
        let (q1, q2) = (Expr::coord("q1", 0), Expr::coord("q2", 0));
        let (u, l) = (Expr::coord("q1", 1), Expr::constant("L"));
        let shared = sin(q1.clone()) * l.clone() + cos(q2.clone()) * u.clone();
        let outputs = [
            shared.clone() * shared.clone() - Expr::ratio(1, 3) * l.clone() * u.clone(),
            Expr::int(1) / (Expr::int(2) + cos(q1.clone() + q2.clone())),
            -(shared.clone() * sin(q2.clone()) + l.clone() * cos(q1.clone()) * u.clone()),
            pow(shared, Expr::ratio(3, 2)) + q1.clone() * q2.clone() * u.clone() * l.clone(),
        ];
        let inputs = [
            Symbol::Coord("q1".into(), 0),
            Symbol::Coord("q2".into(), 0),
            Symbol::Coord("q1".into(), 1),
            Symbol::Const("L".into()),
        ];
        let program = Program::compile(&inputs, &outputs);
        for state in [[0.3, -1.1, 0.7, 2.0], [2.9, 0.4, -3.0, 0.5]] {
            let expected = one_at_a_time(&program, &state);
            let got = program.eval(&state);
            for (e, g) in expected.iter().zip(&got) {
                assert_eq!(e.to_bits(), g.to_bits(), "{e} against {g}");
            }
        }
    }
}
