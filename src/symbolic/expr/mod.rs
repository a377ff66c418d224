//! The expression type: an owned tree kept in one canonical form.
//!
//! Sums and products are n-ary and sorted, like terms are collected, and products
//! are expanded over sums, so every expression is a sum of monomials over atoms
//! (symbols, functions, non-integer powers). Two equal expressions therefore
//! compare equal and print the same every time.

use super::number::Number;
use std::cmp::Ordering;
use std::rc::Rc;

mod definition;
mod unknown;
pub use definition::Definition;
pub use unknown::{Axis, Component, ComponentKind, Unknown};

/// A name shared cheaply between expressions.
pub type Name = Rc<str>;

/// A symbol: what an expression can refer to.
///
/// Symbols are ordered by kind in the order below, then by name as a reader counts
/// (`q2` before `q10`, see `natural_cmp`), so that sums print
/// `q1 + q2 + … + q10`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Symbol {
    /// A named constant (`m`, `L`, `g`).
    Const(Name),
    /// A generalized coordinate or one of its time derivatives (`order` 0, 1 or 2).
    Coord(Name, u8),
    /// Time `t`.
    Time,
    /// A declared generalized speed (`order` 0) or its time derivative (`order` 1), when a
    /// problem's `speeds` replace the coordinates' rates.
    Speed(Name, u8),
    /// An unknown of the linear system other than a `q''`: a reaction component, a drive
    /// or a multiplier (see [`Unknown`]).
    Unknown(Unknown),
    /// A unit vector `frame.axis` (axis 0, 1, 2 for x, y, z); only inside vector expressions.
    UnitVector(Name, u8),
    /// A quantity named once and used in many places (see [`Definition`]).
    Defined(Definition),
}

/// A quantity named once and used in many places, such as a component of a body's angular
/// velocity: products of it stay products instead of being multiplied out, which keeps
/// `(q1' + … + qk')^2` one term instead of k² terms. It evaluates and differentiates as its
/// definition. Two definitions are the same when their names are.
///
impl Symbol {
    fn kind(&self) -> u8 {
        match self {
            Symbol::Const(_) => 0,
            Symbol::Coord(..) => 1,
            Symbol::Time => 2,
            Symbol::Speed(..) => 3,
            Symbol::Unknown(_) => 4,
            Symbol::UnitVector(..) => 5,
            Symbol::Defined(_) => 6,
        }
    }
}

impl Ord for Symbol {
    fn cmp(&self, other: &Self) -> Ordering {
        use super::natural::natural_cmp;
        match (self, other) {
            (Symbol::Const(a), Symbol::Const(b)) => natural_cmp(a, b).then_with(|| a.cmp(b)),
            (Symbol::Unknown(a), Symbol::Unknown(b)) => a.cmp(b),
            (Symbol::Coord(a, i), Symbol::Coord(b, j))
            | (Symbol::Speed(a, i), Symbol::Speed(b, j))
            | (Symbol::UnitVector(a, i), Symbol::UnitVector(b, j)) => natural_cmp(a, b)
                .then_with(|| a.cmp(b))
                .then_with(|| i.cmp(j)),
            (Symbol::Defined(a), Symbol::Defined(b)) => a.cmp(b),
            _ => self.kind().cmp(&other.kind()),
        }
    }
}

impl PartialOrd for Symbol {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// The functions of the problem format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Func {
    /// sin x.
    Sin,
    /// cos x.
    Cos,
    /// tan x.
    Tan,
    /// `asin x`, in `[−π/2, π/2]`.
    Asin,
    /// `acos x`, in `[0, π]`.
    Acos,
    /// atan x, in (−π/2, π/2).
    Atan,
    /// `atan2(y, x)`, the angle of the point (x, y), in `[−π, π]`.
    Atan2,
    /// The square root.
    Sqrt,
    /// e to the power x.
    Exp,
    /// The natural logarithm.
    Ln,
    /// |x|.
    Abs,
    /// The sign of x: −1, 0 or 1.
    Sign,
    /// The smaller of two.
    Min,
    /// The larger of two.
    Max,
}

impl Func {
    /// Every function with its name as written in a problem.
    pub const ALL: [(Func, &'static str); 14] = [
        (Func::Sin, "sin"),
        (Func::Cos, "cos"),
        (Func::Tan, "tan"),
        (Func::Asin, "asin"),
        (Func::Acos, "acos"),
        (Func::Atan, "atan"),
        (Func::Atan2, "atan2"),
        (Func::Sqrt, "sqrt"),
        (Func::Exp, "exp"),
        (Func::Ln, "ln"),
        (Func::Abs, "abs"),
        (Func::Sign, "sign"),
        (Func::Min, "min"),
        (Func::Max, "max"),
    ];

    /// The name as written in a problem.
    pub fn name(self) -> &'static str {
        Func::ALL
            .iter()
            .find(|(f, _)| *f == self)
            .map(|(_, n)| *n)
            .unwrap_or("?")
    }

    /// Looks a function up by name.
    pub fn from_name(name: &str) -> Option<Func> {
        Func::ALL.iter().find(|(_, n)| *n == name).map(|(f, _)| *f)
    }

    /// How many arguments the function takes.
    pub fn arity(self) -> usize {
        match self {
            Func::Atan2 | Func::Min | Func::Max => 2,
            _ => 1,
        }
    }
}

/// One node of an expression.
#[derive(Debug, PartialEq)]
pub enum Node {
    /// A number.
    Num(Number),
    /// A symbol: a constant, a coordinate or its rate, an unknown, a named quantity.
    Sym(Symbol),
    /// Two or more terms, sorted, like terms collected, a number term first if any.
    Add(Vec<Expr>),
    /// Two or more factors, sorted, a numeric coefficient first if not one.
    Mul(Vec<Expr>),
    /// A power that could not be folded: base and exponent.
    Pow(Expr, Expr),
    /// A function applied to its arguments.
    Func(Func, Vec<Expr>),
}

/// A symbolic expression, cheap to clone.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr(pub(crate) Rc<Node>);

impl Eq for Expr {}

impl Expr {
    /// The node behind the expression.
    pub fn node(&self) -> &Node {
        &self.0
    }

    pub(crate) fn from_node(node: Node) -> Expr {
        crate::symbolic::budget::charge(1);
        Expr(Rc::new(node))
    }

    /// A number.
    pub fn num(n: Number) -> Expr {
        Expr::from_node(Node::Num(n))
    }

    /// An integer.
    pub fn int(n: i64) -> Expr {
        Expr::num(Number::int(n))
    }

    /// The fraction `n/d`.
    pub fn ratio(n: i64, d: i64) -> Expr {
        Expr::num(Number::ratio(n as i128, d as i128))
    }

    /// Zero.
    pub fn zero() -> Expr {
        Expr::int(0)
    }

    /// One.
    pub fn one() -> Expr {
        Expr::int(1)
    }

    /// A real number.
    pub fn real(x: f64) -> Expr {
        Expr::num(Number::Real(x))
    }

    /// A symbol.
    pub fn sym(s: Symbol) -> Expr {
        Expr::from_node(Node::Sym(s))
    }

    /// The constant named `name`.
    pub fn constant(name: &str) -> Expr {
        Expr::sym(Symbol::Const(name.into()))
    }

    /// The coordinate `name` differentiated `order` times.
    pub fn coord(name: &str, order: u8) -> Expr {
        Expr::sym(Symbol::Coord(name.into(), order))
    }

    /// `value` named `name` when it is a sum (see [`Definition`]); `value` itself otherwise.
    pub fn defined(name: &str, value: Expr) -> Expr {
        if matches!(value.node(), Node::Add(_)) {
            Expr::sym(Symbol::Defined(Definition::new(
                name, value, None, "", None,
            )))
        } else {
            value
        }
    }

    /// `value` under the name `name`, printed in LaTeX as `latex` and described by `note`
    /// (see [`Definition`]); a number or a single symbol is returned as it is.
    pub fn named(name: &str, latex: &str, note: &str, value: Expr) -> Expr {
        Expr::named_with(name, latex, note, value, None)
    }

    /// As [`Expr::named`], shown in the worked solution as `shown`, which equals `value`
    /// near the initial state only: `a₁ + x₁` for `|a₁ + x₁|`. The numbers keep `value`.
    pub fn named_shown(name: &str, latex: &str, note: &str, value: Expr, shown: Expr) -> Expr {
        Expr::named_with(name, latex, note, value, Some(shown))
    }

    /// `value` under the name `name`, printed in LaTeX as `latex`, for the numbers alone:
    /// the worked solution never writes the value out (see [`Definition::is_evaluated`]).
    pub fn evaluated(name: &str, latex: &str, note: &str, value: Expr) -> Expr {
        if matches!(value.node(), Node::Num(_)) {
            return value;
        }
        Expr::sym(Symbol::Defined(Definition::evaluated(
            name, value, latex, note,
        )))
    }

    fn named_with(name: &str, latex: &str, note: &str, value: Expr, shown: Option<Expr>) -> Expr {
        if matches!(value.node(), Node::Num(_) | Node::Sym(_)) {
            return value;
        }
        Expr::sym(Symbol::Defined(Definition::new(
            name,
            value,
            Some(latex),
            note,
            shown,
        )))
    }

    /// The definition, if this is a defined symbol.
    pub fn as_definition(&self) -> Option<&Definition> {
        match self.node() {
            Node::Sym(Symbol::Defined(d)) => Some(d),
            _ => None,
        }
    }

    /// Time.
    pub fn time() -> Expr {
        Expr::sym(Symbol::Time)
    }

    /// The number, if this is one.
    pub fn as_number(&self) -> Option<Number> {
        match self.node() {
            Node::Num(n) => Some(*n),
            _ => None,
        }
    }

    /// The symbol, if this is one.
    pub fn as_symbol(&self) -> Option<&Symbol> {
        match self.node() {
            Node::Sym(s) => Some(s),
            _ => None,
        }
    }

    /// Whether this is exactly zero.
    pub fn is_zero(&self) -> bool {
        self.as_number().is_some_and(Number::is_zero)
    }

    /// Whether this is exactly one.
    pub fn is_one(&self) -> bool {
        self.as_number().is_some_and(Number::is_one)
    }

    /// The terms of a sum (a single term otherwise).
    pub fn terms(&self) -> &[Expr] {
        match self.node() {
            Node::Add(terms) => terms,
            _ => std::slice::from_ref(self),
        }
    }

    /// The factors of a product (a single factor otherwise).
    pub fn factors(&self) -> &[Expr] {
        match self.node() {
            Node::Mul(factors) => factors,
            _ => std::slice::from_ref(self),
        }
    }

    /// Splits a term into its numeric coefficient and the rest.
    pub fn split_coefficient(&self) -> (Number, Expr) {
        match self.node() {
            Node::Num(n) => (*n, Expr::one()),
            Node::Mul(factors) => match factors[0].as_number() {
                Some(c) => {
                    let rest = &factors[1..];
                    let rest = if rest.len() == 1 {
                        rest[0].clone()
                    } else {
                        Expr::from_node(Node::Mul(rest.to_vec()))
                    };
                    (c, rest)
                }
                None => (Number::ONE, self.clone()),
            },
            _ => (Number::ONE, self.clone()),
        }
    }

    /// Calls `visit` on every symbol in the expression, inside definitions too.
    pub fn for_each_symbol(&self, visit: &mut impl FnMut(&Symbol)) {
        match self.node() {
            Node::Num(_) => {}
            Node::Sym(s) => {
                visit(s);
                if let Symbol::Defined(d) = s {
                    d.value().for_each_symbol(visit);
                }
            }
            Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => {
                items.iter().for_each(|e| e.for_each_symbol(visit))
            }
            Node::Pow(b, e) => {
                b.for_each_symbol(visit);
                e.for_each_symbol(visit);
            }
        }
    }

    /// Whether any symbol satisfies `pred`, inside definitions too.
    pub fn any_symbol(&self, pred: &impl Fn(&Symbol) -> bool) -> bool {
        match self.node() {
            Node::Num(_) => false,
            Node::Sym(Symbol::Defined(d)) => {
                pred(&Symbol::Defined(d.clone())) || d.inside().iter().any(pred)
            }
            Node::Sym(s) => pred(s),
            Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => {
                items.iter().any(|e| e.any_symbol(pred))
            }
            Node::Pow(b, e) => b.any_symbol(pred) || e.any_symbol(pred),
        }
    }

    /// Whether the expression contains `symbol`.
    pub fn contains(&self, symbol: &Symbol) -> bool {
        self.any_symbol(&|s| s == symbol)
    }

    /// Whether the expression depends only on constants and numbers.
    pub fn is_constant(&self) -> bool {
        !self.any_symbol(&|s| !matches!(s, Symbol::Const(_)))
    }

    /// The number of arithmetic operations a direct evaluation would take.
    pub fn operation_count(&self) -> usize {
        match self.node() {
            Node::Num(_) | Node::Sym(_) => 0,
            Node::Add(items) | Node::Mul(items) => {
                items.len() - 1 + items.iter().map(Expr::operation_count).sum::<usize>()
            }
            Node::Pow(b, e) => 1 + b.operation_count() + e.operation_count(),
            Node::Func(_, args) => 1 + args.iter().map(Expr::operation_count).sum::<usize>(),
        }
    }

    /// As [`Self::operation_count`], but the count stops once past `cap`: a subexpression
    /// shared in many places is counted at each, so the whole count of a large shared tree
    /// can take exponential time where the question is only "more than `cap`?".
    pub fn operation_count_capped(&self, cap: usize) -> usize {
        fn walk(e: &Expr, count: &mut usize, cap: usize) {
            let children: &[Expr] = match e.node() {
                Node::Num(_) | Node::Sym(_) => return,
                Node::Add(items) | Node::Mul(items) => {
                    *count += items.len() - 1;
                    items
                }
                Node::Pow(b, x) => {
                    *count += 1;
                    for child in [b, x] {
                        if *count > cap {
                            return;
                        }
                        walk(child, count, cap);
                    }
                    return;
                }
                Node::Func(_, args) => {
                    *count += 1;
                    args
                }
            };
            for child in children {
                if *count > cap {
                    return;
                }
                walk(child, count, cap);
            }
        }
        let mut count = 0;
        walk(self, &mut count, cap);
        count.min(cap.saturating_add(1))
    }

    /// The rank of a product among node kinds (see `rank`).
    pub(crate) const MUL_RANK: u8 = 4;

    /// The order of node kinds when two expressions of different kinds are compared.
    pub(crate) fn rank(&self) -> u8 {
        match self.node() {
            Node::Num(_) => 0,
            Node::Sym(_) => 1,
            Node::Func(..) => 2,
            Node::Pow(..) => 3,
            Node::Mul(_) => 4,
            Node::Add(_) => 5,
        }
    }
}

impl Ord for Expr {
    fn cmp(&self, other: &Self) -> Ordering {
        if Rc::ptr_eq(&self.0, &other.0) {
            return Ordering::Equal;
        }
        match (self.node(), other.node()) {
            (Node::Num(a), Node::Num(b)) => a.total_cmp(b),
            (Node::Sym(a), Node::Sym(b)) => a.cmp(b),
            (Node::Add(a), Node::Add(b)) | (Node::Mul(a), Node::Mul(b)) => {
                a.len().cmp(&b.len()).then_with(|| a.cmp(b))
            }
            (Node::Pow(a, b), Node::Pow(c, d)) => a.cmp(c).then_with(|| b.cmp(d)),
            (Node::Func(f, a), Node::Func(g, b)) => f.cmp(g).then_with(|| a.cmp(b)),
            _ => self.rank().cmp(&other.rank()),
        }
    }
}

impl PartialOrd for Expr {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl std::hash::Hash for Expr {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        match self.node() {
            Node::Num(n) => n.to_f64().to_bits().hash(state),
            Node::Sym(s) => s.hash(state),
            Node::Add(items) => {
                1u8.hash(state);
                items.hash(state)
            }
            Node::Mul(items) => {
                2u8.hash(state);
                items.hash(state)
            }
            Node::Pow(b, e) => {
                3u8.hash(state);
                b.hash(state);
                e.hash(state)
            }
            Node::Func(f, args) => {
                f.hash(state);
                args.hash(state)
            }
        }
    }
}

#[cfg(test)]
mod tests;
