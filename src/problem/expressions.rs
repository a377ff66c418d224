//! What names mean inside the expressions of a problem, and where each kind is allowed.
//!
//! Constants are `Symbol::Const` (so is `pi`), coordinates and their rates
//! `Symbol::Coord(name, order)`, time `Symbol::Time`, and unit vectors
//! `Symbol::UnitVector(frame, axis)`, which vector expressions split off as their terms.

use super::json::{kind, Diagnostics};
use super::model::{BodyId, VectorExpr};
use super::names::{suggest, Kind, Names};
use crate::symbolic::{eval, linear_split, parse, Expr, ParseError, Resolve, Symbol, Values};
use serde_json::Value;
use std::cell::RefCell;
use std::collections::HashSet;

/// Where an expression stands, which decides what it may use.
#[derive(Clone, Copy, Debug)]
pub struct Context {
    /// Loads: coordinates, their first rates and `t` are allowed; otherwise constants only.
    pub dynamic: bool,
    /// What the expression is, for messages: "a mass", "a position".
    pub what: &'static str,
    /// Questions: second rates `q1''` are allowed too.
    pub second_rates: bool,
}

impl Context {
    /// Constants only.
    pub fn constant(what: &'static str) -> Context {
        Context {
            dynamic: false,
            what,
            second_rates: false,
        }
    }

    /// A load: constants, coordinates, first rates and time.
    pub fn load(what: &'static str) -> Context {
        Context {
            dynamic: true,
            what,
            second_rates: false,
        }
    }

    /// A question's value: constants, coordinates, first and second rates, and time.
    pub fn question(what: &'static str) -> Context {
        Context {
            dynamic: true,
            what,
            second_rates: true,
        }
    }
}

/// Resolves names for one expression and remembers the unit vectors in the order written.
pub struct Scope<'a> {
    names: &'a Names,
    context: Context,
    vectors: bool,
    seen: RefCell<Vec<(BodyId, u8)>>,
}

impl<'a> Scope<'a> {
    fn new(names: &'a Names, context: Context, vectors: bool) -> Scope<'a> {
        Scope {
            names,
            context,
            vectors,
            seen: RefCell::new(Vec::new()),
        }
    }

    fn allowed_names(&self) -> Vec<&'a str> {
        let mut out: Vec<&str> = self.names.constants.iter().map(String::as_str).collect();
        if self.context.dynamic {
            out.extend(self.names.coordinates.iter().map(String::as_str));
            out.push("t");
        }
        out.push("pi");
        out
    }

    fn only_constants(&self, column: usize, message: String) -> ParseError {
        ParseError::new(column, message).with_hint(format!(
            "{} may use constants only; coordinates, rates and `t` belong in loads",
            self.context.what
        ))
    }
}

impl Resolve for Scope<'_> {
    fn name(&self, name: &str, primes: u8, column: usize) -> Result<Expr, ParseError> {
        let written = format!("{name}{}", "'".repeat(primes as usize));
        let no_rate = |what: &str| {
            ParseError::new(column, format!("`{written}`: {what} has no rate"))
                .with_hint("only coordinates have rates, written `q1'`")
        };
        match (name, self.names.kind_of(name)) {
            ("pi", _) => {
                return if primes == 0 {
                    Ok(Expr::constant("pi"))
                } else {
                    Err(no_rate("`pi`"))
                }
            }
            ("t", _) if primes > 0 => return Err(no_rate("time")),
            ("t", _) if self.context.dynamic => return Ok(Expr::time()),
            ("t", _) => {
                return Err(self.only_constants(column, "time `t` is not allowed here".into()))
            }
            ("N", _) => {
                return Err(
                    ParseError::new(column, "`N` is the Newtonian frame, not a number")
                        .with_hint("its unit vectors are N.x, N.y, N.z"),
                )
            }
            (_, Some(Kind::Constant)) if primes > 0 => {
                return Err(no_rate(&format!("the constant `{name}`")))
            }
            (_, Some(Kind::Constant)) => return Ok(Expr::constant(name)),
            (_, Some(Kind::Coordinate)) => {}
            (_, Some(other)) => {
                let hint = match other {
                    Kind::Body => format!("its unit vectors are {name}.x, {name}.y, {name}.z"),
                    _ => "expressions use numbers, constants, coordinates and `t`".into(),
                };
                return Err(ParseError::new(
                    column,
                    format!("`{name}` is {}, not a number", other.noun()),
                )
                .with_hint(hint));
            }
            (_, None) => {
                return Err(ParseError::new(column, format!("unknown name `{name}`"))
                    .with_hint(suggest(name, &self.allowed_names(), "names allowed here")))
            }
        }
        // A coordinate.
        if !self.context.dynamic {
            let what = if primes == 0 {
                "a coordinate"
            } else {
                "a rate"
            };
            return Err(
                self.only_constants(column, format!("`{written}` is {what}, not allowed here"))
            );
        }
        match primes {
            0 | 1 => Ok(Expr::coord(name, primes)),
            2 if self.context.second_rates => Ok(Expr::coord(name, 2)),
            2 => Err(ParseError::new(
                column,
                format!("`{written}` is a second rate, not allowed here"),
            )
            .with_hint("loads may use coordinates and their first rates only")),
            _ => Err(
                ParseError::new(column, format!("`{written}`: too many primes"))
                    .with_hint("write `q1'` for a rate"),
            ),
        }
    }

    fn unit_vector(&self, frame: &str, axis: &str, column: usize) -> Result<Expr, ParseError> {
        let Some(body) = self.names.body(frame) else {
            let message = match self.names.kind_of(frame) {
                Some(kind) => format!("`{frame}` is {}, not a frame", kind.noun()),
                None => format!("unknown frame `{frame}`"),
            };
            return Err(ParseError::new(column, message).with_hint(suggest(
                frame,
                &self.names.frames(),
                "frames",
            )));
        };
        let index = axis_index(frame, axis, column)?;
        if !self.vectors {
            return Err(ParseError::new(
                column,
                format!("the unit vector `{frame}.{axis}` is not allowed here"),
            )
            .with_hint(format!("{} is a scalar", self.context.what)));
        }
        self.seen.borrow_mut().push((body, index));
        Ok(Expr::sym(Symbol::UnitVector(frame.into(), index)))
    }
}

/// The index (0, 1, 2 for x, y, z) of the unit vector `frame.axis`, or an error a student
/// can act on: `frame.o` is a point, any other axis unknown.
///
/// # Errors
/// An axis other than `x`, `y`, `z`, at `column`.
pub fn axis_index(frame: &str, axis: &str, column: usize) -> Result<u8, ParseError> {
    let hint = || format!("the unit vectors are {frame}.x, {frame}.y, {frame}.z");
    match axis {
        "x" => Ok(0),
        "y" => Ok(1),
        "z" => Ok(2),
        "o" => Err(
            ParseError::new(column, format!("`{frame}.o` is a point, not a unit vector"))
                .with_hint(hint()),
        ),
        _ => Err(
            ParseError::new(column, format!("`{frame}.{axis}`: unknown axis `{axis}`"))
                .with_hint(hint()),
        ),
    }
}

/// The text of an expression value: a string, or a JSON number written out.
fn text_of(value: &Value, path: &str, vector: bool, diag: &mut Diagnostics) -> Option<String> {
    match value {
        Value::String(s) => Some(s.clone()),
        Value::Number(n) => Some(n.to_string()),
        other => {
            let example = if vector { "\"-g*N.y\"" } else { "\"m*g\"" };
            diag.hint(
                path,
                format!("expected an expression, found {}", kind(other)),
                format!("write it as a string such as {example}"),
            );
            None
        }
    }
}

fn report(diag: &mut Diagnostics, path: &str, e: ParseError) {
    diag.push(path, Some(e.column), e.message, e.hint);
}

/// Parses a scalar expression at `path`.
pub fn scalar(
    value: &Value,
    path: &str,
    names: &Names,
    context: Context,
    diag: &mut Diagnostics,
) -> Option<Expr> {
    let text = text_of(value, path, false, diag)?;
    let scope = Scope::new(names, context, false);
    parse(&text, &scope).map_err(|e| report(diag, path, e)).ok()
}

/// Parses a vector expression at `path` into its unit-vector terms.
pub fn vector(
    value: &Value,
    path: &str,
    names: &Names,
    context: Context,
    diag: &mut Diagnostics,
) -> Option<VectorExpr> {
    let text = text_of(value, path, true, diag)?;
    let scope = Scope::new(names, context, true);
    let expr = parse(&text, &scope)
        .map_err(|e| report(diag, path, e))
        .ok()?;
    let mut order: Vec<(BodyId, u8)> = Vec::new();
    for seen in scope.seen.into_inner() {
        if !order.contains(&seen) {
            order.push(seen);
        }
    }
    let symbols: Vec<Symbol> = order
        .iter()
        .map(|(b, a)| Symbol::UnitVector(names.body_name(*b).into(), *a))
        .collect();
    let (coefficients, rest) =
        match linear_split(&expr, &symbols) {
            Ok(split) => split,
            Err(e) => {
                diag.hint(
                path,
                format!("not a vector: `{}` does not appear linearly in `{}`", e.symbol, e.term),
                "write a sum of terms, each a scalar times one unit vector, e.g. `L/2*A.x - h*A.y`",
            );
                return None;
            }
        };
    if !rest.is_zero() {
        diag.hint(
            path,
            format!("`{rest}` has no unit vector; {} is a vector", context.what),
            "multiply by a unit vector such as N.x, or write 0 for the zero vector",
        );
        return None;
    }
    let terms = order
        .into_iter()
        .zip(coefficients)
        .filter(|(_, c)| !c.is_zero())
        .map(|((body, axis), c)| (body, axis, c))
        .collect();
    Some(VectorExpr { terms })
}

/// The constants' values, for the checks that need numbers.
#[derive(Clone, Debug, Default)]
pub struct ConstantValues {
    values: Values,
    known: HashSet<String>,
}

impl ConstantValues {
    /// Records the value of a constant.
    pub fn set(&mut self, name: &str, value: f64) {
        self.values.set(Symbol::Const(name.into()), value);
        self.known.insert(name.to_string());
    }

    /// The constants' values, for evaluating expressions that hold more than constants.
    pub fn values(&self) -> Values {
        self.values.clone()
    }

    /// The value of `e`, when it holds only constants whose values are known
    /// (an expression naming a constant that had its own error is not judged again).
    pub fn eval(&self, e: &Expr) -> Option<f64> {
        let known = !e.any_symbol(&|s| match s {
            Symbol::Const(name) => &**name != "pi" && !self.known.contains(&**name),
            _ => true,
        });
        known.then(|| eval(e, &self.values))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names() -> Names {
        let mut names = Names::default();
        let mut diag = Diagnostics::default();
        for c in ["m", "L", "g"] {
            names.declare(c, Kind::Constant, "c", &mut diag);
        }
        names.bodies = vec!["A".into(), "B".into()];
        for b in ["A", "B"] {
            names.declare(b, Kind::Body, "b", &mut diag);
        }
        names.declare("q1", Kind::Coordinate, "q", &mut diag);
        assert!(diag.is_empty());
        names
    }

    fn scalar_of(text: &str, context: Context) -> Result<Expr, (Option<usize>, String)> {
        let mut diag = Diagnostics::default();
        scalar(&Value::from(text), "x", &names(), context, &mut diag).ok_or_else(|| {
            let e = diag.errors.remove(0);
            (e.column, e.message)
        })
    }

    fn vector_of(text: &str) -> Result<VectorExpr, String> {
        let mut diag = Diagnostics::default();
        vector(
            &Value::from(text),
            "x",
            &names(),
            Context::load("a force"),
            &mut diag,
        )
        .ok_or_else(|| diag.errors.remove(0).message)
    }

    fn term(body: usize, axis: u8, coefficient: Expr) -> (BodyId, u8, Expr) {
        (BodyId(body), axis, coefficient)
    }

    #[test]
    fn symbols_of_each_kind() {
        let load = Context::load("a load");
        assert_eq!(scalar_of("m", load).unwrap(), Expr::constant("m"));
        assert_eq!(scalar_of("pi", load).unwrap(), Expr::constant("pi"));
        assert_eq!(scalar_of("t", load).unwrap(), Expr::time());
        assert_eq!(scalar_of("q1'", load).unwrap(), Expr::coord("q1", 1));
    }

    #[test]
    fn what_is_not_allowed_has_a_column() {
        let mass = Context::constant("a mass");
        assert_eq!(scalar_of("m*q1", mass).unwrap_err().0, Some(3));
        assert_eq!(scalar_of("2 + t", mass).unwrap_err().0, Some(5));
        let load = Context::load("a load");
        assert!(scalar_of("q1''", load)
            .unwrap_err()
            .1
            .contains("second rate"));
        assert!(scalar_of("m'", load).unwrap_err().1.contains("no rate"));
        assert!(scalar_of("A", load).unwrap_err().1.contains("is a body"));
        assert!(scalar_of("m*N.x", load)
            .unwrap_err()
            .1
            .contains("not allowed"));
        assert!(scalar_of("mm", load)
            .unwrap_err()
            .1
            .contains("unknown name"));
    }

    #[test]
    fn vectors_split_into_terms_in_the_order_written() {
        let v = vector_of("L/2*B.y - m*g*N.x + L*B.y").unwrap();
        let three_halves_l = Expr::ratio(3, 2) * Expr::constant("L");
        let mg = -(Expr::constant("m") * Expr::constant("g"));
        assert_eq!(v.terms, vec![term(2, 1, three_halves_l), term(0, 0, mg)]);
        assert!(vector_of("0").unwrap().terms.is_empty());
        assert!(vector_of("A.x - A.x").unwrap().terms.is_empty());
        let grouped = vector_of("(m + L)*(A.x + A.y)").unwrap();
        assert_eq!(grouped.terms.len(), 2);
    }

    #[test]
    fn not_vectors() {
        assert!(vector_of("A.x*A.y").unwrap_err().contains("linearly"));
        assert!(vector_of("3").unwrap_err().contains("has no unit vector"));
        assert!(vector_of("A.x + 1")
            .unwrap_err()
            .contains("has no unit vector"));
        assert!(vector_of("sin(A.x)").unwrap_err().contains("linearly"));
        assert!(vector_of("C.x").unwrap_err().contains("unknown frame"));
        assert!(vector_of("A.o").unwrap_err().contains("is a point"));
        assert!(vector_of("A.w").unwrap_err().contains("unknown axis"));
    }

    #[test]
    fn constant_values() {
        let mut values = ConstantValues::default();
        values.set("m", 2.0);
        let m = Expr::constant("m");
        assert_eq!(
            values.eval(&(&m * &Expr::constant("pi"))),
            Some(2.0 * std::f64::consts::PI)
        );
        assert_eq!(values.eval(&Expr::constant("L")), None);
        assert_eq!(values.eval(&Expr::coord("q1", 0)), None);
        let over_zero = crate::symbolic::pow(Expr::zero(), Expr::int(-1));
        assert!(!values.eval(&(m * over_zero)).unwrap().is_finite());
    }
}
