//! Direct evaluation by walking the tree: for planning and tests, not for the hot path
//! (see `compile` for that).

use super::expr::{Expr, Func, Node, Symbol};
use super::fast_hash::FastMap;
use std::cell::RefCell;

/// Values of the symbols an expression may hold.
#[derive(Clone, Debug, Default)]
pub struct Values {
    values: FastMap<Symbol, f64>,
    /// The values of the definitions met so far, by name, with these values: definitions
    /// built on definitions (the direction cosines of a chain) are then evaluated once each,
    /// not once per path through them.
    defined: RefCell<FastMap<std::rc::Rc<str>, f64>>,
    /// The values of the symbols met so far, by the address of their name and their kind:
    /// one word hashed instead of the name's characters. The symbol is kept so that the
    /// address stays its own.
    met: RefCell<FastMap<(usize, u16), (Symbol, f64)>>,
}

impl Values {
    /// No values yet.
    pub fn new() -> Values {
        Values::default()
    }

    /// Sets the value of `symbol`.
    pub fn set(&mut self, symbol: Symbol, value: f64) {
        self.values.insert(symbol, value);
        self.defined.get_mut().clear();
        self.met.get_mut().clear();
    }

    /// The value of `symbol`; `pi` is built in, an unset symbol is NaN.
    pub fn get(&self, symbol: &Symbol) -> f64 {
        match self.values.get(symbol) {
            Some(v) => *v,
            None if matches!(symbol, Symbol::Const(n) if &**n == "pi") => std::f64::consts::PI,
            None => f64::NAN,
        }
    }

    /// The value of `symbol` in an evaluation: a definition's is its value's.
    fn of(&self, symbol: &Symbol) -> f64 {
        let address = |name: &str| name.as_ptr() as usize;
        let key = match symbol {
            Symbol::Const(n) => (address(n), 0),
            Symbol::Coord(n, order) => (address(n), 0x100 | u16::from(*order)),
            Symbol::Speed(n, order) => (address(n), 0x200 | u16::from(*order)),
            Symbol::Defined(d) => (address(d.name()), 0x300),
            _ => return self.get(symbol),
        };
        if let Some((_, v)) = self.met.borrow().get(&key) {
            return *v;
        }
        let v = match symbol {
            Symbol::Defined(d) => self.definition(d),
            _ => self.get(symbol),
        };
        self.met.borrow_mut().insert(key, (symbol.clone(), v));
        v
    }

    fn definition(&self, d: &super::Definition) -> f64 {
        if let Some(v) = self.defined.borrow().get(d.name()) {
            return *v;
        }
        let v = eval(d.value(), self);
        self.defined.borrow_mut().insert(d.name().into(), v);
        v
    }
}

/// Applies a function of the problem format to numbers.
pub fn apply(f: Func, a: f64, b: f64) -> f64 {
    match f {
        Func::Sin => a.sin(),
        Func::Cos => a.cos(),
        Func::Tan => a.tan(),
        Func::Asin => a.asin(),
        Func::Acos => a.acos(),
        Func::Atan => a.atan(),
        Func::Atan2 => a.atan2(b),
        Func::Sqrt => a.sqrt(),
        Func::Exp => a.exp(),
        Func::Ln => a.ln(),
        Func::Abs => a.abs(),
        Func::Sign => {
            if a > 0.0 {
                1.0
            } else if a < 0.0 {
                -1.0
            } else {
                0.0
            }
        }
        Func::Min => a.min(b),
        Func::Max => a.max(b),
    }
}

/// `base^exponent`, with integer exponents multiplied out for accuracy.
pub fn power(base: f64, exponent: f64) -> f64 {
    if exponent == exponent.trunc() && exponent.abs() <= 16.0 {
        base.powi(exponent as i32)
    } else if exponent == 0.5 {
        base.sqrt()
    } else {
        base.powf(exponent)
    }
}

/// The value of `e` with `values`.
pub fn eval(e: &Expr, values: &Values) -> f64 {
    match e.node() {
        Node::Num(n) => n.to_f64(),
        Node::Sym(s) => values.of(s),
        Node::Add(terms) => terms.iter().map(|t| eval(t, values)).sum(),
        Node::Mul(factors) => factors.iter().map(|f| eval(f, values)).product(),
        Node::Pow(b, x) => power(eval(b, values), eval(x, values)),
        Node::Func(f, args) => {
            let a = eval(&args[0], values);
            let b = args.get(1).map_or(0.0, |x| eval(x, values));
            apply(*f, a, b)
        }
    }
}
