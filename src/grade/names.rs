//! What the names in a student's expression mean: the problem format's grammar (constants,
//! coordinates with up to two primes, `t`, `pi`, unit vectors `B.y`), and the reaction
//! components as the worked solution names them in plain text (`O.Fx`, `P.My`).

use crate::problem::Problem;
use crate::symbolic::{parse, Expr, ParseError, Resolve, Symbol};

/// Resolves the names of one student expression.
pub(super) struct Names<'a> {
    problem: &'a Problem,
    /// Every reaction component of every site, as unknowns.
    reactions: &'a [Symbol],
    /// Whether unit vectors are allowed (a vector expression).
    vectors: bool,
}

impl<'a> Names<'a> {
    /// Names for a scalar (`vectors` false) or a vector expression.
    pub(super) fn new(problem: &'a Problem, reactions: &'a [Symbol], vectors: bool) -> Names<'a> {
        Names {
            problem,
            reactions,
            vectors,
        }
    }

    /// Parses `text` with these names.
    pub(super) fn parse(&self, text: &str) -> Result<Expr, ParseError> {
        parse(text, self)
    }

    fn allowed(&self) -> Vec<&'a str> {
        let constants = self.problem.constants.iter().map(|c| c.name.as_str());
        let coordinates = self.problem.coordinates.iter().map(|c| c.name.as_str());
        constants.chain(coordinates).chain(["t", "pi"]).collect()
    }

    fn is_frame(&self, name: &str) -> bool {
        name == "N" || self.problem.bodies.iter().any(|b| b.name == name)
    }

    fn reaction(&self, frame: &str, axis: &str) -> Option<&'a Symbol> {
        let written = format!("{frame}.{axis}");
        self.reactions
            .iter()
            .find(|s| matches!(s, Symbol::Unknown(u) if u.to_string() == written))
    }
}

impl Resolve for Names<'_> {
    fn name(&self, name: &str, primes: u8, column: usize) -> Result<Expr, ParseError> {
        let written = format!("{name}{}", "'".repeat(primes as usize));
        if name == "pi" && primes == 0 {
            return Ok(Expr::constant("pi"));
        }
        if name == "t" && primes == 0 {
            return Ok(Expr::time());
        }
        if self.problem.constants.iter().any(|c| c.name == name) {
            if primes == 0 {
                return Ok(Expr::constant(name));
            }
            return Err(ParseError::new(
                column,
                format!("`{written}`: the constant `{name}` has no rate"),
            )
            .with_hint("only coordinates have rates, written `q1'`"));
        }
        if self.problem.coordinates.iter().any(|c| c.name == name) {
            if primes <= 2 {
                return Ok(Expr::coord(name, primes));
            }
            return Err(
                ParseError::new(column, format!("`{written}`: too many primes"))
                    .with_hint("write `q1'` for a rate and `q1''` for a second rate"),
            );
        }
        let hint = match crate::symbolic::closest(name, self.allowed()) {
            Some(c) => format!("did you mean `{c}`?"),
            None if self.is_frame(name) => {
                format!("`{name}` is a frame: its unit vectors are {name}.x, {name}.y, {name}.z")
            }
            None => format!("the names are {}", self.allowed().join(", ")),
        };
        Err(ParseError::new(column, format!("unknown name `{written}`")).with_hint(hint))
    }

    fn unit_vector(&self, frame: &str, axis: &str, column: usize) -> Result<Expr, ParseError> {
        if let Some(reaction) = self.reaction(frame, axis) {
            return Ok(Expr::sym(reaction.clone()));
        }
        if !self.is_frame(frame) {
            let sites: Vec<String> = self
                .reactions
                .iter()
                .filter_map(|s| match s {
                    Symbol::Unknown(u) => Some(u.to_string()),
                    _ => None,
                })
                .collect();
            let hint = if sites.is_empty() {
                "a unit vector is written FRAME.x, with a body's name or N".to_string()
            } else {
                format!(
                    "unit vectors are FRAME.x (a body or N); reaction components are {}",
                    sites.join(", ")
                )
            };
            return Err(ParseError::new(
                column,
                format!("unknown frame or reaction `{frame}.{axis}`"),
            )
            .with_hint(hint));
        }
        let index = crate::problem::axis_index(frame, axis, column)?;
        if !self.vectors {
            return Err(ParseError::new(
                column,
                format!("the unit vector `{frame}.{axis}` is not allowed here"),
            )
            .with_hint("this answer is a scalar"));
        }
        Ok(Expr::sym(Symbol::UnitVector(frame.into(), index)))
    }
}
