//! Forward-mode differentiation of a compiled [`Program`]: every slot carries its value and
//! its derivatives along some of the inputs (a dual number with one tangent per input
//! differentiated), so one run gives the outputs and their exact partial derivatives, to
//! rounding, for a few times the cost of a plain run.
//!
//! The tangents of all slots live in one block, `directions` numbers per slot, written in
//! place; a slot that reads nothing that varies keeps a zero tangent and costs nothing.

use super::compile::Program;
use super::eval::{apply, power};
use super::expr::Func;
use super::instr::Instr;

/// The outputs of one run and their partial derivatives.
#[derive(Clone, Debug)]
pub struct Derivatives {
    /// The outputs' values, in order.
    pub values: Vec<f64>,
    /// `∂output_i/∂input_{directions[j]}` at `i * directions + j`.
    pub partials: Vec<f64>,
    /// The number of inputs differentiated.
    pub directions: usize,
}

impl Derivatives {
    /// The partial derivatives of output `i`, one per direction.
    pub fn of(&self, i: usize) -> &[f64] {
        &self.partials[i * self.directions..(i + 1) * self.directions]
    }
}

impl Program {
    /// Runs the program and differentiates every output with respect to the inputs at the
    /// positions `directions` (indices into the inputs), by forward-mode differentiation.
    ///
    /// `min` and `max` take the derivative of the argument they pick; where the two
    /// arguments are equal and change differently there is none, and it is NaN.
    pub fn run_with_derivatives(&self, inputs: &[f64], directions: &[usize]) -> Derivatives {
        let m = directions.len();
        let (count, constants) = (self.inputs.len(), self.constants.len());
        let start = count + constants;
        let slots = start + self.instructions.len();
        let mut value = vec![0.0; slots];
        value[..count].copy_from_slice(&inputs[..count]);
        value[count..start].copy_from_slice(&self.constants);
        let mut tangent = vec![0.0; slots * m];
        let mut varies = vec![false; slots];
        for (j, &input) in directions.iter().enumerate() {
            tangent[input * m + j] = 1.0;
            varies[input] = true;
        }
        for (i, instr) in self.instructions.iter().enumerate() {
            let slot = start + i;
            value[slot] = instr.execute(&value);
            if instr.reads_any(|s| varies[s as usize]) {
                varies[slot] = true;
                let (before, after) = tangent.split_at_mut(slot * m);
                let local = Local {
                    value: &value,
                    tangent: before,
                    varies: &varies,
                    m,
                };
                local.differentiate(instr, value[slot], &mut after[..m]);
            }
        }
        let mut partials = Vec::with_capacity(self.outputs.len() * m);
        for &slot in &self.outputs {
            partials.extend_from_slice(&tangent[slot * m..(slot + 1) * m]);
        }
        Derivatives {
            values: self.outputs.iter().map(|&s| value[s]).collect(),
            partials,
            directions: m,
        }
    }
}

/// The slots computed so far, for the tangent of the next.
struct Local<'a> {
    value: &'a [f64],
    tangent: &'a [f64],
    varies: &'a [bool],
    m: usize,
}

impl Local<'_> {
    fn v(&self, slot: u32) -> f64 {
        self.value[slot as usize]
    }

    fn t(&self, slot: u32) -> &[f64] {
        let s = slot as usize;
        &self.tangent[s * self.m..(s + 1) * self.m]
    }

    /// `out += factor · tangent(slot)`, skipped for a slot that does not vary (whose factor
    /// may be infinite: `0 ^ (1/2 − 1)` multiplies a zero tangent).
    fn add_scaled(&self, out: &mut [f64], factor: f64, slot: u32) {
        if self.varies[slot as usize] {
            for (o, t) in out.iter_mut().zip(self.t(slot)) {
                *o += factor * t;
            }
        }
    }

    /// Writes the tangent of `instr`, whose value is `result`, into `out` (zero on entry).
    fn differentiate(&self, instr: &Instr, result: f64, out: &mut [f64]) {
        match instr {
            Instr::Const(_) => {}
            Instr::Mul(a, b) => {
                self.add_scaled(out, self.v(*b), *a);
                self.add_scaled(out, self.v(*a), *b);
            }
            Instr::Neg(a) => self.add_scaled(out, -1.0, *a),
            Instr::Recip(a) => self.add_scaled(out, -result * result, *a),
            Instr::Square(a) => self.add_scaled(out, 2.0 * self.v(*a), *a),
            Instr::Pow(a, b) => {
                let (base, exponent) = (self.v(*a), self.v(*b));
                self.add_scaled(out, exponent * power(base, exponent - 1.0), *a);
                self.add_scaled(out, result * base.ln(), *b);
            }
            Instr::Func(f, a, b) => self.function(*f, *a, *b, result, out),
            Instr::Dot { pairs, positive } => {
                for (k, [a, b]) in pairs.iter().enumerate() {
                    let sign = if k < *positive as usize { 1.0 } else { -1.0 };
                    self.add_scaled(out, sign * self.v(*b), *a);
                    self.add_scaled(out, sign * self.v(*a), *b);
                }
            }
        }
    }

    fn function(&self, f: Func, a: u32, b: u32, result: f64, out: &mut [f64]) {
        let x = self.v(a);
        let slope = match f {
            Func::Sin => x.cos(),
            Func::Cos => -x.sin(),
            Func::Tan => 1.0 + result * result,
            Func::Asin => power(1.0 - x * x, -0.5),
            Func::Acos => -power(1.0 - x * x, -0.5),
            Func::Atan => 1.0 / (1.0 + x * x),
            Func::Exp => result,
            Func::Ln => 1.0 / x,
            Func::Abs => apply(Func::Sign, x, x),
            Func::Sqrt => 0.5 * power(x, -0.5),
            Func::Sign => 0.0,
            Func::Atan2 => {
                // d atan2(y, x) = (x dy − y dx) / (x² + y²)
                let (y, x) = (self.v(a), self.v(b));
                let r2 = x * x + y * y;
                self.add_scaled(out, x / r2, a);
                self.add_scaled(out, -y / r2, b);
                return;
            }
            Func::Min | Func::Max => {
                let y = self.v(b);
                let picked = match (x == y, (x < y) == (f == Func::Min)) {
                    (false, true) => a,
                    (false, false) => b,
                    // Where the arguments cross, a derivative only if they move alike.
                    (true, _) if self.t(a) == self.t(b) => a,
                    (true, _) => {
                        out.fill(f64::NAN);
                        return;
                    }
                };
                self.add_scaled(out, 1.0, picked);
                return;
            }
        };
        self.add_scaled(out, slope, a);
    }
}

#[cfg(test)]
mod tests {
    use crate::symbolic::build::{cos, func, pow, sin, sqrt};
    use crate::symbolic::compile::Program;
    use crate::symbolic::diff::partial;
    use crate::symbolic::{Expr, Func, Symbol};

    /// The forward derivatives of `e` in x and y at (x, y) against its symbolic partials.
    fn check(e: Expr, x: f64, y: f64) {
        let symbols = [Symbol::Coord("x".into(), 0), Symbol::Coord("y".into(), 0)];
        let d = Program::compile(&symbols, std::slice::from_ref(&e))
            .run_with_derivatives(&[x, y], &[0, 1]);
        for (j, s) in symbols.iter().enumerate() {
            let symbolic = partial(&e, s).expect("differentiable");
            let want = Program::compile(&symbols, &[symbolic]).eval(&[x, y])[0];
            let got = d.of(0)[j];
            assert!(
                (got - want).abs() <= 1e-13 * want.abs().max(1.0),
                "∂({e})/∂{s:?}: {got} against {want}"
            );
        }
    }

    #[test]
    fn forward_derivatives_equal_the_symbolic_ones() {
        let (x, y) = (Expr::coord("x", 0), Expr::coord("y", 0));
        check(sin(x.clone() + y.clone()) * cos(x.clone()), 0.3, -1.1);
        check(
            pow(x.clone() + Expr::int(2), Expr::ratio(-1, 2)) * y.clone(),
            0.7,
            2.0,
        );
        check(pow(x.clone(), y.clone()), 1.7, 0.4);
        check(sqrt(x.clone() * x.clone() + y.clone()), 0.5, 3.0);
        check(
            Expr::int(3) / (x.clone() * y.clone() - Expr::int(5)),
            0.5,
            3.0,
        );
        check(func(Func::Atan2, vec![y.clone(), x.clone()]), -0.4, 0.9);
        for f in [
            Func::Tan,
            Func::Asin,
            Func::Acos,
            Func::Atan,
            Func::Exp,
            Func::Abs,
        ] {
            check(func(f, vec![x.clone() * y.clone()]), 0.3, -0.8);
        }
        check(func(Func::Ln, vec![x.clone() + y.clone()]), 0.3, 0.8);
    }

    #[test]
    fn min_picks_its_argument_and_has_no_derivative_where_they_cross() {
        let (x, y) = (Expr::coord("x", 0), Expr::coord("y", 0));
        let inputs = [Symbol::Coord("x".into(), 0), Symbol::Coord("y".into(), 0)];
        let program = Program::compile(&inputs, &[func(Func::Min, vec![x, y * Expr::int(2)])]);
        assert_eq!(
            program.run_with_derivatives(&[1.0, 3.0], &[0, 1]).of(0),
            [1.0, 0.0]
        );
        assert_eq!(
            program.run_with_derivatives(&[7.0, 3.0], &[0, 1]).of(0),
            [0.0, 2.0]
        );
        let crossing = program.run_with_derivatives(&[6.0, 3.0], &[0, 1]);
        assert!(crossing.of(0).iter().all(|d| d.is_nan()));
    }
}
