//! Derivatives: the time derivative by the chain rule, and partial derivatives.
//!
//! Plain recursion with one derivative rule per function, since rewrite tables
//! cannot express the chain rule.

use super::build::{add, cos, func, mul, pow, sin};
use super::expr::{Expr, Func, Node, Symbol};
use super::fast_hash::FastMap;
use std::fmt;

/// A derivative that cannot be taken.
#[derive(Clone, Debug, PartialEq)]
pub struct DiffError {
    /// The expression whose derivative was asked for.
    pub expression: String,
    /// Why it cannot be differentiated.
    pub reason: String,
}

impl fmt::Display for DiffError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "cannot differentiate `{}`: {}",
            self.expression, self.reason
        )
    }
}

/// The total time derivative: `d/dt q = q'`, `d/dt q' = q''`, `d/dt t = 1`.
///
/// # Errors
/// When the expression holds a function without a derivative (`sign`, `min`, `max`) of
/// something that changes, or a second rate.
pub fn time_derivative(e: &Expr) -> Result<Expr, DiffError> {
    derivative(e, true, &|s| match s {
        Symbol::Coord(name, order) if *order < 2 => {
            Ok(Expr::sym(Symbol::Coord(name.clone(), order + 1)))
        }
        Symbol::Coord(name, _) => Err(format!("`{name}''` has no derivative here")),
        Symbol::Speed(name, 0) => Ok(Expr::sym(Symbol::Speed(name.clone(), 1))),
        Symbol::Speed(name, _) => Err(format!("`{name}'` has no derivative here")),
        Symbol::Time => Ok(Expr::one()),
        _ => Ok(Expr::zero()),
    })
}

/// The partial derivative with respect to `symbol`.
///
/// # Errors
/// As for [`time_derivative`].
pub fn partial(e: &Expr, symbol: &Symbol) -> Result<Expr, DiffError> {
    derivative(e, false, &|s| {
        Ok(if s == symbol {
            Expr::one()
        } else {
            Expr::zero()
        })
    })
}

/// `in_time`: a defined symbol with a named rate differentiates to that rate.
fn derivative(
    e: &Expr,
    in_time: bool,
    of_symbol: &dyn Fn(&Symbol) -> Result<Expr, String>,
) -> Result<Expr, DiffError> {
    Derivative {
        in_time,
        of_symbol,
        done: FastMap::default(),
    }
    .of(e)
}

/// One derivative taken through an expression, each shared part once: the same
/// subexpression (a sine of a coordinate in many monomials, a named quantity's value at
/// each of its uses) is one node reached by many parents, and its derivative is the same
/// at each.
struct Derivative<'a> {
    in_time: bool,
    of_symbol: &'a dyn Fn(&Symbol) -> Result<Expr, String>,
    /// The derivatives of the shared nodes met so far, by node; every node is alive for
    /// the whole call (`e` holds it), so an address names one node throughout.
    done: FastMap<*const Node, Expr>,
}

impl Derivative<'_> {
    fn of(&mut self, e: &Expr) -> Result<Expr, DiffError> {
        // A node held once is reached through its one parent only: nothing to keep.
        let shared = std::rc::Rc::strong_count(&e.0) > 1
            && !matches!(
                e.node(),
                Node::Num(_) | Node::Sym(Symbol::Const(_) | Symbol::Coord(..))
            );
        let key = std::rc::Rc::as_ptr(&e.0);
        if shared {
            if let Some(done) = self.done.get(&key) {
                return Ok(done.clone());
            }
        }
        let d = self.taken(e)?;
        if shared {
            self.done.insert(key, d.clone());
        }
        Ok(d)
    }

    fn taken(&mut self, e: &Expr) -> Result<Expr, DiffError> {
        let fail = |reason: String| DiffError {
            expression: e.to_string(),
            reason,
        };
        let in_time = self.in_time;
        Ok(match e.node() {
            Node::Num(_) => Expr::zero(),
            Node::Sym(Symbol::Defined(d)) => match d.rate().filter(|_| in_time) {
                Some(rate) => rate,
                None => self.of(d.value())?,
            },
            Node::Sym(s) => (self.of_symbol)(s).map_err(fail)?,
            Node::Add(terms) => add(terms
                .iter()
                .map(|t| self.of(t))
                .collect::<Result<Vec<_>, _>>()?),
            Node::Mul(factors) => {
                let mut terms = Vec::with_capacity(factors.len());
                for (i, factor) in factors.iter().enumerate() {
                    let d = self.of(factor)?;
                    if d.is_zero() {
                        continue;
                    }
                    let mut product: Vec<Expr> = factors.to_vec();
                    product[i] = d;
                    terms.push(mul(product));
                }
                add(terms)
            }
            Node::Pow(base, exponent) => {
                let db = self.of(base)?;
                let de = self.of(exponent)?;
                let power_rule = mul([
                    exponent.clone(),
                    pow(base.clone(), exponent - &Expr::one()),
                    db,
                ]);
                if de.is_zero() {
                    power_rule
                } else {
                    let log_rule = mul([e.clone(), func(Func::Ln, vec![base.clone()]), de]);
                    power_rule + log_rule
                }
            }
            Node::Func(f, args) => {
                let x = &args[0];
                let dx = self.of(x)?;
                let outer = match f {
                    _ if dx.is_zero() && args.len() == 1 => return Ok(Expr::zero()),
                    Func::Sin => cos(x.clone()),
                    Func::Cos => -sin(x.clone()),
                    Func::Tan => Expr::one() + pow(func(Func::Tan, vec![x.clone()]), Expr::int(2)),
                    Func::Asin => pow(Expr::one() - x * x, Expr::ratio(-1, 2)),
                    Func::Acos => -pow(Expr::one() - x * x, Expr::ratio(-1, 2)),
                    Func::Atan => pow(Expr::one() + x * x, Expr::int(-1)),
                    Func::Exp => e.clone(),
                    Func::Ln => pow(x.clone(), Expr::int(-1)),
                    Func::Abs => func(Func::Sign, vec![x.clone()]),
                    Func::Sqrt => Expr::ratio(1, 2) * pow(x.clone(), Expr::ratio(-1, 2)),
                    Func::Atan2 => {
                        // d atan2(y, x) = (x dy - y dx) / (x^2 + y^2)
                        let (y, xx) = (&args[0], &args[1]);
                        let dxx = self.of(xx)?;
                        return Ok((xx * &dx - y * &dxx) / (xx * xx + y * y));
                    }
                    Func::Sign => return Ok(Expr::zero()),
                    Func::Min | Func::Max => {
                        return Err(fail(format!(
                            "`{}` has no derivative where its arguments cross",
                            f.name()
                        )))
                    }
                };
                outer * dx
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::parse::{parse, ParseError, Resolve};

    struct Names;
    impl Resolve for Names {
        fn name(&self, name: &str, primes: u8, _: usize) -> Result<Expr, ParseError> {
            Ok(if name.starts_with('q') {
                Expr::coord(name, primes)
            } else {
                Expr::constant(name)
            })
        }
        fn unit_vector(&self, _: &str, _: &str, c: usize) -> Result<Expr, ParseError> {
            Err(ParseError::new(c, "no vectors"))
        }
    }

    fn check(expression: &str, expected: &str) {
        let e = parse(expression, &Names).unwrap();
        assert_eq!(
            time_derivative(&e).unwrap(),
            parse(expected, &Names).unwrap(),
            "d/dt {expression}"
        );
    }

    #[test]
    fn chain_rule() {
        check("sin(q1)", "cos(q1)*q1'");
        check("cos(q1)", "-sin(q1)*q1'");
        check("q1'", "q1''");
        check("L*q1^2", "2*L*q1*q1'");
        check("sin(q1+q2)", "cos(q1+q2)*(q1'+q2')");
        check("q1*q1'", "q1'^2 + q1*q1''");
        check("sqrt(q1)", "q1'/(2*sqrt(q1))");
        check("m*g", "0");
        check("exp(q1)", "exp(q1)*q1'");
        check("ln(q1)", "q1'/q1");
        check("atan2(q1, q2)", "(q2*q1' - q1*q2')/(q1^2+q2^2)");
    }

    /// A sine and a named rate each one node under several parents (as the kinematics
    /// builds them): each use differentiated alike, as by hand. With s = sin q1 and
    /// w = q1' + q2' (named), d/dt (L s w + m s q2 + s w)
    /// = L (c q1' w + s (q1'' + q2'')) + m (c q1' q2 + s q2') + c q1' w + s (q1'' + q2'').
    #[test]
    fn shared_parts_differentiate_as_each_use_alone() {
        let q = |n: &str, k: u8| Expr::coord(n, k);
        let (l, m) = (Expr::constant("L"), Expr::constant("m"));
        let s = sin(q("q1", 0));
        let c = cos(q("q1", 0));
        let w = Expr::defined("w", &q("q1", 1) + &q("q2", 1));
        let e = add([
            mul([l.clone(), s.clone(), w.clone()]),
            mul([m.clone(), s.clone(), q("q2", 0)]),
            mul([s.clone(), w.clone()]),
        ]);
        let dw = &q("q1", 2) + &q("q2", 2);
        let ds = mul([c, q("q1", 1)]);
        let d_sw = &mul([ds.clone(), w]) + &mul([s.clone(), dw]);
        let by_hand = add([
            mul([l, d_sw.clone()]),
            mul([m, &mul([ds, q("q2", 0)]) + &mul([s, q("q2", 1)])]),
            d_sw,
        ]);
        assert_eq!(time_derivative(&e).unwrap(), by_hand);
    }
}
