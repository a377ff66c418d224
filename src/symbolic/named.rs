//! Finding the named quantities an expression uses, for the worked solution's "where"
//! lists, and ordering names as a reader counts (`q2` before `q10`).

use super::expr::{Definition, Expr, Node, Symbol};
pub use super::natural::natural_cmp;

/// Every named definition (one that prints as its name) that `exprs` use, also inside other
/// definitions, each once, in `natural_cmp` order of their names.
pub fn named_definitions<'a>(exprs: impl IntoIterator<Item = &'a Expr>) -> Vec<Definition> {
    let mut found: Vec<Definition> = Vec::new();
    let mut seen_nodes = std::collections::HashSet::new();
    for e in exprs {
        collect(e, &mut found, &mut seen_nodes);
    }
    found.sort_by(|a, b| natural_cmp(a.name(), b.name()));
    found
}

fn collect(
    e: &Expr,
    found: &mut Vec<Definition>,
    seen: &mut std::collections::HashSet<*const Node>,
) {
    // Shared subtrees are visited once: expressions are DAGs.
    if !seen.insert(std::rc::Rc::as_ptr(&e.0)) {
        return;
    }
    match e.node() {
        Node::Num(_) => {}
        // Said in words where it is used, never written out.
        Node::Sym(Symbol::Defined(d)) if d.is_evaluated() => {}
        Node::Sym(Symbol::Defined(d)) => {
            if d.is_named() && !found.contains(d) {
                found.push(d.clone());
            }
            collect(d.value(), found, seen);
        }
        Node::Sym(_) => {}
        Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => {
            items.iter().for_each(|x| collect(x, found, seen))
        }
        Node::Pow(b, x) => {
            collect(b, found, seen);
            collect(x, found, seen);
        }
    }
}

/// `e` as the worked solution shows it: every definition with a shown form (see
/// [`Expr::named_shown`]) replaced by that form, and simplified again where it changed.
/// `e` itself, untouched, when it uses none.
pub fn as_shown(e: &Expr) -> Expr {
    let uses = e.any_symbol(&|s| matches!(s, Symbol::Defined(d) if d.shown().is_some()));
    if !uses {
        return e.clone();
    }
    let replaced = super::subst::substitute(e, &|s| match s {
        Symbol::Defined(d) => d.shown().cloned(),
        _ => None,
    });
    super::simplify::simplify(&replaced)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn named_symbols_are_found_inside_other_definitions_once() {
        let l = Expr::named(
            "line1.l",
            "\\ell_{1}",
            "",
            Expr::constant("a") + Expr::constant("b"),
        );
        let u = Expr::named(
            "line1.u.x",
            "\\hat{u}_{1x}",
            "",
            Expr::constant("c") / l.clone(),
        );
        let hidden = Expr::defined("load0.stretch", l.clone() - Expr::constant("l0"));
        let e = &u * &hidden;
        let names: Vec<String> = named_definitions([&e, &l])
            .iter()
            .map(|d| d.name().to_string())
            .collect();
        assert_eq!(names, ["line1.l", "line1.u.x"]);
    }
}

#[cfg(test)]
mod rate_tests {
    use crate::symbolic::diff::time_derivative;
    use crate::symbolic::{sqrt, Expr};

    #[test]
    fn a_named_length_differentiates_to_its_named_rate() {
        let x = Expr::coord("x", 0);
        let length = Expr::named("line1.l", "\\ell_{1}", "", sqrt(&x * &x + Expr::one()));
        let rate = Expr::named(
            "line1.v",
            "\\dot{\\ell}_{1}",
            "",
            &(&x / &length) * &Expr::coord("x", 1),
        );
        length.as_definition().unwrap().set_rate(&rate);
        assert_eq!(
            time_derivative(&(&length * &Expr::constant("k"))).unwrap(),
            &rate * &Expr::constant("k")
        );
        // Without a named rate, d/dt goes through the value.
        let plain = Expr::named("line2.l", "\\ell_{2}", "", sqrt(&x * &x + Expr::one()));
        assert_ne!(time_derivative(&plain).unwrap(), rate);
    }
}
