//! Compiling expressions once into a flat program: every shared subexpression is
//! computed once, and one evaluation costs about the arithmetic it contains.

use super::expr::{Expr, Func, Node, Symbol};
use super::fast_hash::FastMap;
use super::instr::Instr;
use super::runs::Runs;
use super::simplify::key::{Key, KeyMap};
use std::ops::Neg;

/// A straight-line program that evaluates a list of expressions.
///
/// Slots: the inputs, then the constants, then one per instruction.
#[derive(Clone, Debug)]
pub struct Program {
    pub(super) inputs: Vec<Symbol>,
    pub(super) constants: Vec<f64>,
    pub(super) instructions: Vec<Instr>,
    pub(super) outputs: Vec<usize>,
    /// The instructions as [`Runs`], the form `run` executes.
    runs: Runs,
}

struct Compiler {
    program: Program,
    by_pointer: FastMap<*const Node, usize>,
    /// Keyed by a bounded prefix of each tree and compared pointer-first: a node met for
    /// the first time costs a lookup, not a walk of everything under it.
    by_value: KeyMap<Key, usize>,
    constant_slots: FastMap<u64, usize>,
    constant_values: Vec<f64>,
    // Keeps every compiled node alive so that pointers stay unique.
    alive: Vec<Expr>,
}

impl Program {
    /// Compiles `outputs`, reading the symbols in `inputs` (in that order) when run.
    ///
    /// Symbols not among the inputs evaluate to NaN, except `pi`.
    pub fn compile(inputs: &[Symbol], outputs: &[Expr]) -> Program {
        let mut c = Compiler {
            program: Program {
                inputs: inputs.to_vec(),
                constants: Vec::new(),
                instructions: Vec::new(),
                outputs: Vec::new(),
                runs: Runs::default(),
            },
            by_pointer: FastMap::default(),
            by_value: KeyMap::default(),
            constant_slots: FastMap::default(),
            constant_values: Vec::new(),
            alive: Vec::new(),
        };
        let slots: Vec<usize> = outputs.iter().map(|e| c.slot(e)).collect();
        let (mut instructions, outputs) =
            super::schedule::schedule(inputs.len(), &c.program.instructions, &slots);
        // The schedule puts the constants first; they become a table copied in each run.
        let count = instructions
            .iter()
            .take_while(|i| matches!(i, Instr::Const(_)))
            .count();
        c.program.constants = instructions
            .drain(..count)
            .map(|i| match i {
                Instr::Const(index) => c.constant_values[index as usize],
                _ => f64::NAN,
            })
            .collect();
        let first = inputs.len() + c.program.constants.len();
        c.program.runs = Runs::new(&instructions, first);
        c.program.instructions = instructions;
        c.program.outputs = outputs;
        c.program
    }

    /// The number of arithmetic operations and function calls in one run.
    pub fn operation_count(&self) -> usize {
        self.instructions.iter().map(Instr::operation_count).sum()
    }

    /// The input symbols, in the order `run` reads them.
    pub fn inputs(&self) -> &[Symbol] {
        &self.inputs
    }

    /// Evaluates every output; `scratch` is reused between calls to avoid allocation.
    pub fn run(&self, inputs: &[f64], scratch: &mut Vec<f64>, outputs: &mut [f64]) {
        let (count, constants) = (self.inputs.len(), self.constants.len());
        let start = count + constants;
        // Every slot is written before it is read, so a buffer of the right length from an
        // earlier run is reused as it is.
        scratch.resize(start + self.instructions.len(), 0.0);
        scratch[..count].copy_from_slice(&inputs[..count]);
        scratch[count..start].copy_from_slice(&self.constants);
        self.runs.execute(scratch, start);
        for (out, slot) in outputs.iter_mut().zip(&self.outputs) {
            *out = scratch[*slot];
        }
    }

    /// Evaluates every output into a new vector.
    pub fn eval(&self, inputs: &[f64]) -> Vec<f64> {
        let mut scratch = Vec::new();
        let mut outputs = vec![0.0; self.outputs.len()];
        self.run(inputs, &mut scratch, &mut outputs);
        outputs
    }
}

/// Whether `e` is a sum of two or more coordinates, the angles of a chain. (Only these: in
/// `sin(1e308 + q)` the sum rounds to the large term, and the identity would not.)
fn is_angle_sum(e: &Expr) -> bool {
    let is_angle = |t: &Expr| matches!(t.node(), Node::Sym(Symbol::Coord(_, 0)));
    matches!(e.node(), Node::Add(terms) if terms.len() >= 2 && terms.iter().all(is_angle))
}

/// A value a factoring plan produced: in a slot, or a product not yet emitted, so that a
/// sum can take it with its addition in one instruction.
#[derive(Clone, Copy, Debug)]
enum Value {
    Slot(usize),
    Product(usize, usize),
}

impl Compiler {
    fn constant_slot(&mut self, value: f64) -> usize {
        if let Some(slot) = self.constant_slots.get(&value.to_bits()) {
            return *slot;
        }
        let slot = self.emit(Instr::Const(self.constant_values.len() as u32));
        self.constant_values.push(value);
        self.constant_slots.insert(value.to_bits(), slot);
        slot
    }

    fn emit(&mut self, instr: Instr) -> usize {
        self.program.instructions.push(instr);
        self.program.inputs.len() + self.program.instructions.len() - 1
    }

    fn slot(&mut self, e: &Expr) -> usize {
        let pointer = std::rc::Rc::as_ptr(&e.0);
        if let Some(slot) = self.by_pointer.get(&pointer) {
            return *slot;
        }
        let slot = match self.by_value.get(&Key(e.clone())) {
            Some(slot) => *slot,
            None => {
                let slot = self.build(e);
                self.by_value.insert(Key(e.clone()), slot);
                slot
            }
        };
        self.by_pointer.insert(pointer, slot);
        self.alive.push(e.clone());
        slot
    }

    fn build(&mut self, e: &Expr) -> usize {
        match e.node() {
            Node::Num(n) => self.constant_slot(n.to_f64()),
            Node::Sym(s) => match (self.program.inputs.iter().position(|i| i == s), s) {
                (Some(index), _) => index,
                // Computed once however many terms use it: `slot` remembers it.
                (None, Symbol::Defined(d)) => self.slot(d.value()),
                (None, Symbol::Const(n)) if &**n == "pi" => {
                    self.constant_slot(std::f64::consts::PI)
                }
                (None, _) => self.constant_slot(f64::NAN),
            },
            Node::Add(terms) => {
                let plan =
                    super::horner::factor(terms.iter().map(super::horner::monomial).collect());
                let (negative, value) = self.plan(&plan);
                let slot = self.materialize(value);
                if negative {
                    self.emit(Instr::Neg(slot as u32))
                } else {
                    slot
                }
            }
            Node::Mul(factors) => {
                let slots: Vec<usize> = factors.iter().map(|f| self.slot(f)).collect();
                let mut acc = slots[0];
                for &slot in &slots[1..] {
                    acc = self.emit(Instr::Mul(acc as u32, slot as u32));
                }
                acc
            }
            Node::Pow(base, exponent) => {
                let b = self.slot(base);
                match exponent.as_number().and_then(|n| n.as_integer()) {
                    Some(-1) => self.emit(Instr::Recip(b as u32)),
                    Some(2) => self.emit(Instr::Square(b as u32)),
                    _ => {
                        let x = self.slot(exponent);
                        self.emit(Instr::Pow(b as u32, x as u32))
                    }
                }
            }
            Node::Func(f @ (Func::Sin | Func::Cos), args) if is_angle_sum(&args[0]) => {
                self.angle_sum(*f, args[0].terms())
            }
            Node::Func(f, args) => {
                let a = self.slot(&args[0]);
                let b = match args.get(1) {
                    Some(arg) => self.slot(arg),
                    None => a,
                };
                self.emit(Instr::Func(*f, a as u32, b as u32))
            }
        }
    }

    /// sin or cos of `a + t` from those of `a` and `t`, four products where a function call
    /// costs tens: a chain's relative angles need the sine and cosine of every run
    /// `q_i + … + q_j`, and each is the previous run's and one angle's.
    fn angle_sum(&mut self, f: Func, terms: &[Expr]) -> usize {
        let (last, head) = terms.split_last().unwrap_or((&terms[0], &[]));
        let head = super::build::add(head.to_vec());
        let [sin_head, cos_head, sin_last, cos_last] = [
            super::build::sin(head.clone()),
            super::build::cos(head),
            super::build::sin(last.clone()),
            super::build::cos(last.clone()),
        ]
        .map(|e| self.slot(&e) as u32);
        let (pairs, positive) = match f {
            Func::Sin => ([[sin_head, cos_last], [cos_head, sin_last]], 2),
            _ => ([[cos_head, cos_last], [sin_head, sin_last]], 1),
        };
        self.emit(Instr::Dot {
            pairs: Box::new(pairs),
            positive,
        })
    }

    /// The slot of a value, emitting its last product if it is still pending.
    fn materialize(&mut self, value: Value) -> usize {
        match value {
            Value::Slot(slot) => slot,
            Value::Product(a, b) => self.emit(Instr::Mul(a as u32, b as u32)),
        }
    }

    /// Emits a factoring plan; returns (negated, value of the magnitude). A sum's parts are
    /// signed inside its Dot instruction, so only a single term or product comes back negated.
    fn plan(&mut self, plan: &super::horner::Plan) -> (bool, Value) {
        use super::horner::Plan;
        match plan {
            Plan::Term((coefficient, factors)) => {
                let negative = coefficient.is_negative();
                let magnitude = if negative {
                    coefficient.neg()
                } else {
                    *coefficient
                };
                let power = |(base, k): &(Expr, i64)| {
                    if *k == 1 {
                        base.clone()
                    } else {
                        super::build::pow(base.clone(), Expr::int(*k))
                    }
                };
                // The constant part (coefficient and constants) as one product, so that the
                // same `m L^2 / 12` is computed once for the whole program.
                let (constant, varying): (Vec<_>, Vec<_>) =
                    factors.iter().partition(|(base, _)| base.is_constant());
                let mut constant_part: Vec<Expr> = constant.into_iter().map(power).collect();
                constant_part.push(Expr::num(magnitude));
                let constant_part = super::build::mul(constant_part);
                let mut slots: Vec<usize> = Vec::new();
                if !constant_part.is_one() || varying.is_empty() {
                    slots.push(self.slot(&constant_part));
                }
                for factor in varying {
                    slots.push(self.slot(&power(factor)));
                }
                let Some((&last, rest)) = slots.split_last() else {
                    return (negative, Value::Slot(self.constant_slot(f64::NAN)));
                };
                let Some((&first, middle)) = rest.split_first() else {
                    return (negative, Value::Slot(last));
                };
                let mut acc = first;
                for &s in middle {
                    acc = self.emit(Instr::Mul(acc as u32, s as u32));
                }
                (negative, Value::Product(acc, last))
            }
            Plan::Product(base, inner) => {
                let b = self.slot(base);
                let (negative, value) = self.plan(inner);
                let s = self.materialize(value);
                (negative, Value::Product(b, s))
            }
            Plan::Sum(parts) => {
                let signed: Vec<(bool, Value)> = parts.iter().map(|p| self.plan(p)).collect();
                let one = self.constant_slot(1.0);
                let pair = |value: &Value| match *value {
                    Value::Product(a, b) => [a as u32, b as u32],
                    Value::Slot(s) => [s as u32, one as u32],
                };
                let plus = signed.iter().filter(|(negative, _)| !negative);
                let minus = signed.iter().filter(|(negative, _)| *negative);
                let pairs: Box<[[u32; 2]]> =
                    plus.clone().chain(minus).map(|(_, v)| pair(v)).collect();
                let positive = plus.count() as u32;
                (
                    false,
                    Value::Slot(self.emit(Instr::Dot { pairs, positive })),
                )
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::build::{cos, sin};
    use crate::symbolic::eval::{eval, Values};
    use crate::symbolic::Func;

    #[test]
    fn matches_the_tree_walk_and_shares_subexpressions() {
        let q = Expr::coord("q", 0);
        let l = Expr::constant("L");
        let shared = sin(q.clone()) * l.clone();
        let outputs = [
            shared.clone() + cos(q.clone()),
            shared.clone() * Expr::int(3) - Expr::ratio(1, 2),
            pow_test(&q),
        ];
        let inputs = [Symbol::Coord("q".into(), 0), Symbol::Const("L".into())];
        let program = Program::compile(&inputs, &outputs);
        let mut values = Values::new();
        values.set(inputs[0].clone(), 0.3);
        values.set(inputs[1].clone(), 2.0);
        let got = program.eval(&[0.3, 2.0]);
        for (e, g) in outputs.iter().zip(&got) {
            assert!((eval(e, &values) - g).abs() < 1e-14);
        }
        let sins = program
            .instructions
            .iter()
            .filter(|i| matches!(i, Instr::Func(Func::Sin, ..)))
            .count();
        assert_eq!(sins, 1);
    }

    #[test]
    fn sines_of_angle_sums_come_from_the_angles_by_the_addition_formulas() {
        let angles: Vec<Expr> = (1..=4).map(|i| Expr::coord(&format!("q{i}"), 0)).collect();
        let run = |k: usize| crate::symbolic::build::add(angles[..k].to_vec());
        // A chain's runs: q1 + q2, q1 + q2 + q3, q1 + … + q4.
        let outputs: Vec<Expr> = (2..=4).flat_map(|k| [sin(run(k)), cos(run(k))]).collect();
        let inputs: Vec<Symbol> = (1..=4)
            .map(|i| Symbol::Coord(format!("q{i}").into(), 0))
            .collect();
        let program = Program::compile(&inputs, &outputs);
        let q = [0.3, -1.2, 2.5, 0.8];
        let got = program.eval(&q);
        for (k, pair) in (2..=4).zip(got.chunks(2)) {
            let angle: f64 = q[..k].iter().sum();
            assert!((pair[0] - angle.sin()).abs() < 1e-14);
            assert!((pair[1] - angle.cos()).abs() < 1e-14);
        }
        // One sine and one cosine per angle; the sums' are products of these.
        let calls = program
            .instructions
            .iter()
            .filter(|i| matches!(i, Instr::Func(..)))
            .count();
        assert_eq!(calls, 8);
    }

    #[test]
    fn equal_trees_built_apart_are_computed_once_and_long_common_prefixes_kept_apart() {
        // Sums of 40 terms L_i sin(q + i), the second with its last term changed: the two
        // agree on far more nodes than a key looks at, and must stay two values.
        let q = Expr::coord("q", 0);
        let sum = |last: i64| {
            crate::symbolic::build::add((1..=40).map(|i| {
                let shift = if i == 40 { last } else { i };
                Expr::constant(&format!("L{i}")) * sin(q.clone() + Expr::int(shift))
            }))
        };
        let (a, b, again) = (sum(40), sum(41), sum(40));
        assert!(!std::rc::Rc::ptr_eq(&a.0, &again.0));
        let mut inputs = vec![Symbol::Coord("q".into(), 0)];
        inputs.extend((1..=40).map(|i| Symbol::Const(format!("L{i}").into())));
        let x: Vec<f64> = (0..inputs.len()).map(|k| 0.1 + 0.07 * k as f64).collect();
        let mut values = Values::new();
        for (s, v) in inputs.iter().zip(&x) {
            values.set(s.clone(), *v);
        }
        let twice = Program::compile(&inputs, &[a.clone(), b.clone(), again]);
        let got = twice.eval(&x);
        // Checked against the tree walk: the last terms differ by L40 (sin(q+41) − sin(q+40)).
        assert!((got[0] - eval(&a, &values)).abs() < 1e-12);
        assert!((got[1] - eval(&b, &values)).abs() < 1e-12);
        assert!((got[0] - got[1]).abs() > 1e-3);
        assert_eq!(got[2], got[0]);
        // The copy built apart costs no instruction of its own.
        let once = Program::compile(&inputs, &[a, b]);
        assert_eq!(twice.operation_count(), once.operation_count());
    }

    fn pow_test(q: &Expr) -> Expr {
        crate::symbolic::build::pow(q.clone() + Expr::int(2), Expr::ratio(-1, 2))
    }
}
