//! The expression parser on arbitrary text, with a small scope of names: it never panics,
//! hangs or aborts, every error has a column inside the text, and every result prints.

#![no_main]

use libfuzzer_sys::fuzz_target;
use mbd_tutor::symbolic::parse::{parse, ParseError, Resolve};
use mbd_tutor::symbolic::{print, Expr, Symbol};

struct Scope;

impl Resolve for Scope {
    fn name(&self, name: &str, primes: u8, column: usize) -> Result<Expr, ParseError> {
        match (name, primes) {
            ("m" | "L" | "g" | "pi", 0) => Ok(Expr::constant(name)),
            ("q1" | "q2", 0..=2) => Ok(Expr::coord(name, primes)),
            ("t", 0) => Ok(Expr::time()),
            _ => Err(ParseError::new(column, format!("unknown name `{name}`"))),
        }
    }

    fn unit_vector(&self, frame: &str, axis: &str, column: usize) -> Result<Expr, ParseError> {
        let index = ["x", "y", "z"].iter().position(|a| *a == axis);
        match (frame, index) {
            ("N" | "A", Some(i)) => Ok(Expr::sym(Symbol::UnitVector(frame.into(), i as u8))),
            _ => Err(ParseError::new(column, format!("no unit vector `{frame}.{axis}`"))),
        }
    }
}

fuzz_target!(|text: &str| {
    match parse(text, &Scope) {
        Ok(e) => {
            let _ = print::latex(&e);
            let _ = print::plain(&e);
        }
        Err(e) => {
            assert!(e.column >= 1 && e.column <= text.chars().count() + 1);
            assert!(!e.message.is_empty());
        }
    }
});
