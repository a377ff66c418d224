//! The expression grammar of the problem format, with the column of every error.
//!
//! ```text
//! sum     = product (("+" | "-") product)*
//! product = unary (("*" | "/") unary)*
//! unary   = ("-" | "+") unary | power
//! power   = primary ("^" unary)?          right associative, tighter than unary minus
//! primary = number | name primes? | name "(" sum ("," sum)* ")" | frame "." axis | "(" sum ")"
//! ```

use super::build::{add, func, mul, pow};
use super::expr::{Expr, Func};
use super::number::Number;
use std::fmt;

/// The deepest nesting of parentheses, powers and signs that is accepted.
pub const MAX_DEPTH: usize = 200;
/// The longest expression text that is accepted, in bytes.
pub const MAX_LENGTH: usize = 100_000;

/// A syntax or name error inside one expression.
#[derive(Clone, Debug, PartialEq)]
pub struct ParseError {
    /// The 1-based character column where the problem starts.
    pub column: usize,
    /// What is wrong.
    pub message: String,
    /// What to do about it, when there is something useful to say.
    pub hint: Option<String>,
}

impl ParseError {
    /// An error at `column` without a hint.
    pub fn new(column: usize, message: impl Into<String>) -> ParseError {
        ParseError {
            column,
            message: message.into(),
            hint: None,
        }
    }

    /// The same error with a hint.
    pub fn with_hint(mut self, hint: impl Into<String>) -> ParseError {
        self.hint = Some(hint.into());
        self
    }
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "column {}: {}", self.column, self.message)
    }
}

/// What the names in an expression mean; the caller decides what is allowed where.
pub trait Resolve {
    /// The expression for `name` followed by `primes` apostrophes, found at `column`.
    ///
    /// # Errors
    /// When the name is unknown or not allowed here.
    fn name(&self, name: &str, primes: u8, column: usize) -> Result<Expr, ParseError>;

    /// The unit vector `frame.axis`, found at `column`.
    ///
    /// # Errors
    /// When unit vectors are not allowed here, or the frame or axis is unknown.
    fn unit_vector(&self, frame: &str, axis: &str, column: usize) -> Result<Expr, ParseError>;
}

#[derive(Clone, Debug, PartialEq)]
enum Token {
    Number(Number),
    Name { name: String, primes: u8 },
    UnitVector { frame: String, axis: String },
    Op(char),
}

fn tokenize(text: &str) -> Result<Vec<(Token, usize)>, ParseError> {
    let chars: Vec<char> = text.chars().collect();
    let mut tokens = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let column = i + 1;
        if c.is_whitespace() {
            i += 1;
        } else if c.is_ascii_digit()
            || (c == '.' && chars.get(i + 1).is_some_and(|d| d.is_ascii_digit()))
        {
            let start = i;
            i = number_literal_end(&chars, i);
            let literal: String = chars[start..i].iter().collect();
            let number = Number::parse_decimal(&literal).ok_or_else(|| {
                ParseError::new(column, format!("`{literal}` is not a finite number"))
            })?;
            tokens.push((Token::Number(number), column));
        } else if c.is_ascii_alphabetic() {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            let name: String = chars[start..i].iter().collect();
            if i + 1 < chars.len() && chars[i] == '.' && chars[i + 1].is_ascii_alphabetic() {
                let axis_start = i + 1;
                i += 1;
                while i < chars.len() && chars[i].is_ascii_alphanumeric() {
                    i += 1;
                }
                let axis: String = chars[axis_start..i].iter().collect();
                tokens.push((Token::UnitVector { frame: name, axis }, column));
                continue;
            }
            let mut primes = 0u8;
            while i < chars.len() && chars[i] == '\'' {
                primes = primes.saturating_add(1);
                i += 1;
            }
            tokens.push((Token::Name { name, primes }, column));
        } else if "+-*/^(),".contains(c) {
            tokens.push((Token::Op(c), column));
            i += 1;
        } else {
            return Err(ParseError::new(column, format!("unexpected character `{c}`"))
                .with_hint("expressions use numbers, names, + - * / ^, parentheses and functions such as sin(q1)"));
        }
    }
    Ok(tokens)
}

struct Parser<'a> {
    tokens: Vec<(Token, usize)>,
    position: usize,
    end_column: usize,
    depth: usize,
    resolver: &'a dyn Resolve,
}

/// Parses `text` into a canonical expression, resolving names through `resolver`.
///
/// # Errors
/// The first syntax or name error, with its column.
pub fn parse(text: &str, resolver: &dyn Resolve) -> Result<Expr, ParseError> {
    if text.len() > MAX_LENGTH {
        return Err(
            ParseError::new(1, format!("the expression is {} bytes long", text.len()))
                .with_hint(format!("expressions are limited to {MAX_LENGTH} bytes")),
        );
    }
    let tokens = tokenize(text)?;
    if tokens.is_empty() {
        return Err(ParseError::new(1, "the expression is empty").with_hint("write 0 for zero"));
    }
    let mut parser = Parser {
        tokens,
        position: 0,
        end_column: text.chars().count() + 1,
        depth: 0,
        resolver,
    };
    let expr = parser.sum()?;
    if let Some((token, column)) = parser.tokens.get(parser.position) {
        let hint = match token {
            Token::Op(')') => "this parenthesis closes nothing",
            _ => "an operator such as * may be missing",
        };
        return Err(
            ParseError::new(*column, format!("unexpected {}", describe(token))).with_hint(hint),
        );
    }
    if super::build::is_refused_power(&expr) {
        return Err(ParseError::new(1, "the expression expands to too many terms").with_hint(format!(
            "a power of a sum may expand to at most {} terms; write it with fewer terms or a smaller power",
            super::build::MAX_EXPANDED_TERMS
        )));
    }
    Ok(expr)
}

fn describe(token: &Token) -> String {
    match token {
        Token::Number(n) => format!("number `{n}`"),
        Token::Name { name, .. } => format!("name `{name}`"),
        Token::UnitVector { frame, axis } => format!("unit vector `{frame}.{axis}`"),
        Token::Op(c) => format!("`{c}`"),
    }
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.position).map(|(t, _)| t)
    }

    fn column(&self) -> usize {
        self.tokens
            .get(self.position)
            .map_or(self.end_column, |(_, c)| *c)
    }

    fn eat(&mut self, op: char) -> bool {
        if self.peek() == Some(&Token::Op(op)) {
            self.position += 1;
            true
        } else {
            false
        }
    }

    fn enter(&mut self) -> Result<(), ParseError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(
                ParseError::new(self.column(), "the expression is nested too deeply").with_hint(
                    format!("at most {MAX_DEPTH} levels of parentheses, powers and signs"),
                ),
            );
        }
        Ok(())
    }

    fn sum(&mut self) -> Result<Expr, ParseError> {
        self.enter()?;
        let mut terms = vec![self.product()?];
        loop {
            if self.eat('+') {
                terms.push(self.product()?);
            } else if self.eat('-') {
                terms.push(-self.product()?);
            } else {
                break;
            }
        }
        self.depth -= 1;
        Ok(add(terms))
    }

    fn product(&mut self) -> Result<Expr, ParseError> {
        let column = self.column();
        let mut factors = vec![self.unary()?];
        loop {
            if self.eat('*') {
                factors.push(self.unary()?);
            } else if self.eat('/') {
                factors.push(pow(self.unary()?, Expr::int(-1)));
            } else {
                break;
            }
        }
        // Multiplying out sums multiplies their term counts: refuse before doing the work.
        let terms = factors
            .iter()
            .fold(1u64, |n, f| n.saturating_mul(f.terms().len() as u64));
        if terms > super::build::MAX_EXPANDED_TERMS {
            return Err(
                ParseError::new(column, "the product expands to too many terms").with_hint(
                    format!(
                        "a product of sums may expand to at most {} terms",
                        super::build::MAX_EXPANDED_TERMS
                    ),
                ),
            );
        }
        Ok(mul(factors))
    }

    fn unary(&mut self) -> Result<Expr, ParseError> {
        self.enter()?;
        let result = if self.eat('-') {
            self.unary().map(|e| -e)
        } else if self.eat('+') {
            self.unary()
        } else {
            self.power()
        };
        self.depth -= 1;
        result
    }

    fn power(&mut self) -> Result<Expr, ParseError> {
        let base = self.primary()?;
        if self.eat('^') {
            let exponent = self.unary()?;
            return Ok(pow(base, exponent));
        }
        Ok(base)
    }

    fn primary(&mut self) -> Result<Expr, ParseError> {
        let column = self.column();
        let Some((token, _)) = self.tokens.get(self.position).cloned() else {
            return Err(ParseError::new(column, "the expression ends too early")
                .with_hint("a number, a name or `(` should follow"));
        };
        self.position += 1;
        match token {
            Token::Number(n) => Ok(Expr::num(n)),
            Token::UnitVector { frame, axis } => self.resolver.unit_vector(&frame, &axis, column),
            Token::Op('(') => {
                let inner = self.sum()?;
                if !self.eat(')') {
                    return Err(ParseError::new(self.column(), "missing `)`")
                        .with_hint(format!("the `(` at column {column} is never closed")));
                }
                Ok(inner)
            }
            Token::Name { name, primes } if self.peek() == Some(&Token::Op('(')) => {
                self.position += 1;
                self.call(&name, primes, column)
            }
            Token::Name { name, primes } => self.resolver.name(&name, primes, column),
            Token::Op(c) => Err(ParseError::new(column, format!("unexpected `{c}`"))
                .with_hint("a number, a name or `(` should stand here")),
        }
    }

    fn call(&mut self, name: &str, primes: u8, column: usize) -> Result<Expr, ParseError> {
        let Some(f) = Func::from_name(name).filter(|_| primes == 0) else {
            let known: Vec<&str> = Func::ALL.iter().map(|(_, n)| *n).collect();
            let hint = match super::hint::closest(name, known.iter().copied()) {
                Some(close) => format!("did you mean `{close}`?"),
                None => format!("the functions are {}", known.join(", ")),
            };
            return Err(
                ParseError::new(column, format!("unknown function `{name}`")).with_hint(hint),
            );
        };
        let mut args = vec![self.sum()?];
        while self.eat(',') {
            args.push(self.sum()?);
        }
        if !self.eat(')') {
            return Err(
                ParseError::new(self.column(), "missing `)`").with_hint(format!(
                    "the call of `{name}` at column {column} is never closed"
                )),
            );
        }
        if args.len() != f.arity() {
            let wanted = if f.arity() == 1 {
                "one argument"
            } else {
                "two arguments"
            };
            return Err(ParseError::new(
                column,
                format!("`{name}` takes {wanted}, not {}", args.len()),
            ));
        }
        Ok(func(f, args))
    }
}

/// Where the number literal starting at `start` ends: digits and points, then an optional
/// exponent (`e`, an optional sign, digits). Shared with the scan for written decimals.
pub(crate) fn number_literal_end(chars: &[char], start: usize) -> usize {
    let mut i = start;
    while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
        i += 1;
    }
    if i < chars.len() && (chars[i] == 'e' || chars[i] == 'E') {
        let mut j = i + 1;
        if j < chars.len() && (chars[j] == '+' || chars[j] == '-') {
            j += 1;
        }
        if j < chars.len() && chars[j].is_ascii_digit() {
            i = j;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
            }
        }
    }
    i
}

/// For tests of the algebra: `text` parsed with the names `coordinate` accepts (and any
/// name with primes) as coordinates, every other name a constant, and no unit vectors.
#[cfg(test)]
pub(crate) fn parse_scalar(text: &str, coordinate: fn(&str) -> bool) -> Expr {
    struct Scalars(fn(&str) -> bool);
    impl Resolve for Scalars {
        fn name(&self, name: &str, primes: u8, _: usize) -> Result<Expr, ParseError> {
            Ok(if (self.0)(name) || primes > 0 {
                Expr::coord(name, primes)
            } else {
                Expr::constant(name)
            })
        }
        fn unit_vector(&self, _: &str, _: &str, column: usize) -> Result<Expr, ParseError> {
            Err(ParseError::new(column, "no vectors here"))
        }
    }
    parse(text, &Scalars(coordinate)).unwrap_or_else(|e| panic!("`{text}`: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::expr::Symbol;

    struct Names;
    impl Resolve for Names {
        fn name(&self, name: &str, primes: u8, column: usize) -> Result<Expr, ParseError> {
            match (name, primes) {
                ("q1" | "q2", p) => Ok(Expr::coord(name, p)),
                (_, 0) if name.len() == 1 => Ok(Expr::constant(name)),
                _ => Err(ParseError::new(column, format!("unknown name `{name}`"))),
            }
        }
        fn unit_vector(&self, frame: &str, axis: &str, _: usize) -> Result<Expr, ParseError> {
            let index = "xyz".find(axis).unwrap_or(0) as u8;
            Ok(Expr::sym(Symbol::UnitVector(frame.into(), index)))
        }
    }

    fn same(a: &str, b: &str) {
        assert_eq!(
            parse(a, &Names).unwrap(),
            parse(b, &Names).unwrap(),
            "{a} vs {b}"
        );
    }

    fn error_column(text: &str) -> usize {
        parse(text, &Names).unwrap_err().column
    }

    #[test]
    fn precedence() {
        same("-x^2", "-(x^2)");
        same("x^y^z", "x^(y^z)");
        same("a*b/c", "(a*b)/c");
        same("a-b-c", "a-(b+c)");
        same("2^-1", "0.5");
        same("q1'*L", "L*q1'");
    }

    #[test]
    fn errors_have_columns() {
        assert_eq!(error_column("x + * y"), 5);
        assert_eq!(error_column("sin(x"), 6);
        assert_eq!(error_column("x + foo"), 5);
        assert_eq!(error_column("snn(x)"), 1);
        assert_eq!(error_column("x $ y"), 3);
        assert_eq!(error_column("(x))"), 4);
    }

    #[test]
    fn deep_nesting_is_refused_not_overflowed() {
        let deep = format!("{}x{}", "(".repeat(10_000), ")".repeat(10_000));
        assert!(parse(&deep, &Names).is_err());
        let signs = format!("{}x", "-".repeat(10_000));
        assert!(parse(&signs, &Names).is_err());
    }

    #[test]
    fn powers_that_would_expand_past_the_bound_are_refused() {
        assert!(parse("((m+L+g+p)^8)^8", &Names).is_err());
        assert!(parse("(m+L+g+p)^8", &Names).is_ok());
        assert!(parse("2^(-9223372036854775807-1)", &Names).is_ok());
    }

    #[test]
    fn long_sums_parse_in_linear_time() {
        let long = vec!["x"; 20_000].join("+");
        assert_eq!(
            parse(&long, &Names).unwrap(),
            parse("20000*x", &Names).unwrap()
        );
    }
}
