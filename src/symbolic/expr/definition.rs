//! A named quantity: a value under a name, printed by the name and defined once in the
//! worked solution's "where" lists.

use super::{Expr, Name, Node, Symbol};
use crate::symbolic::fast_hash::FastHasher;
use std::cell::OnceCell;
use std::cmp::Ordering;
use std::hash::BuildHasherDefault;
use std::rc::{Rc, Weak};

/// A definition with a printed name (a spring's length `ℓ₁`) prints as that name, and the
/// worked solution lists what it stands for once; one without prints as its definition in
/// parentheses (the angular velocity components).
#[derive(Clone, Debug)]
pub struct Definition(Rc<DefinitionData>);

#[derive(Debug)]
struct DefinitionData {
    name: Name,
    value: Expr,
    /// How LaTeX prints it, e.g. `\ell_{1}`; `None` prints the value.
    latex: Option<Name>,
    /// What it is, in words, for the "where" list (may be empty).
    note: Name,
    /// What the worked solution shows instead, when that holds only near the initial
    /// state (`a₁ + x₁` for `|a₁ + x₁|` while `a₁ + x₁ > 0`); the numbers use `value`.
    shown: Option<Expr>,
    /// Computed at each state and never written out (see [`Definition::is_evaluated`]).
    evaluated: bool,
    /// Its time derivative when that has a name of its own (`ℓ̇₁` for `ℓ₁`). Weak, since
    /// the rate's definition may refer back to this one; once the rate is gone d/dt falls
    /// back to differentiating the value.
    rate: OnceCell<Weak<Node>>,
    /// Every symbol inside the value, nested definitions and what is inside them included,
    /// each once: found on first use, so that a search through definitions built on
    /// definitions (direction cosines of a long chain) visits each once, not once per path.
    inside: OnceCell<Rc<[Symbol]>>,
}

impl Definition {
    /// `value` under `name`, printed as `latex` (its value when `None`), described by `note`,
    /// shown in the worked solution as `shown` if given.
    pub(super) fn new(
        name: &str,
        value: Expr,
        latex: Option<&str>,
        note: &str,
        shown: Option<Expr>,
    ) -> Definition {
        Definition(Rc::new(DefinitionData {
            name: name.into(),
            value,
            latex: latex.map(Into::into),
            note: note.into(),
            shown,
            evaluated: false,
            rate: OnceCell::new(),
            inside: OnceCell::new(),
        }))
    }

    /// As [`Definition::new`], for a quantity the worked solution names but does not write
    /// out: its value (an entry of a matrix inverse, formed through named minors) is only
    /// for the numbers, and what it is is said in words beside it.
    pub(super) fn evaluated(name: &str, value: Expr, latex: &str, note: &str) -> Definition {
        Definition(Rc::new(DefinitionData {
            name: name.into(),
            value,
            latex: Some(latex.into()),
            note: note.into(),
            shown: None,
            evaluated: true,
            rate: OnceCell::new(),
            inside: OnceCell::new(),
        }))
    }

    /// Whether the value is for the numbers alone: no "where" list writes it out.
    pub fn is_evaluated(&self) -> bool {
        self.0.evaluated
    }

    /// The unique name, e.g. `B.w.z`.
    pub fn name(&self) -> &str {
        &self.0.name
    }

    /// What the symbol stands for.
    pub fn value(&self) -> &Expr {
        &self.0.value
    }

    /// The printed LaTeX name, when it prints as a name.
    pub fn latex(&self) -> Option<&str> {
        self.0.latex.as_deref()
    }

    /// What it is, in words (may be empty), e.g. `length of the left spring`.
    pub fn note(&self) -> &str {
        &self.0.note
    }

    /// What the worked solution shows instead of the symbol, if anything (see
    /// [`Expr::named_shown`]).
    pub fn shown(&self) -> Option<&Expr> {
        self.0.shown.as_ref()
    }

    /// Whether it prints as its name (and the solution lists its value in a "where" list).
    pub fn is_named(&self) -> bool {
        self.0.latex.is_some()
    }

    /// Its time derivative by name, when one was given with [`Definition::set_rate`] and is
    /// still alive.
    pub fn rate(&self) -> Option<Expr> {
        self.0.rate.get().and_then(Weak::upgrade).map(Expr)
    }

    /// Every symbol inside the value, nested definitions included, each once.
    pub(super) fn inside(&self) -> &[Symbol] {
        self.0.inside.get_or_init(|| {
            let mut found: Vec<Symbol> = Vec::new();
            let mut seen = Seen::default();
            collect_inside(self.value(), &mut found, &mut seen);
            found.into()
        })
    }

    /// Gives the symbol a named time derivative: d/dt of this symbol is then `rate`
    /// (which must equal the derivative of the value). A second call is ignored.
    pub fn set_rate(&self, rate: &Expr) {
        let _ = self.0.rate.set(Rc::downgrade(&rate.0));
    }
}

/// The symbols met so far: only asked whether one is new, never listed.
type Seen = std::collections::HashSet<Symbol, BuildHasherDefault<FastHasher>>;

fn collect_inside(e: &Expr, found: &mut Vec<Symbol>, seen: &mut Seen) {
    match e.node() {
        Node::Num(_) => {}
        Node::Sym(s) => {
            if seen.insert(s.clone()) {
                found.push(s.clone());
                if let Symbol::Defined(d) = s {
                    for inner in d.inside() {
                        if seen.insert(inner.clone()) {
                            found.push(inner.clone());
                        }
                    }
                }
            }
        }
        Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => {
            items.iter().for_each(|x| collect_inside(x, found, seen))
        }
        Node::Pow(b, x) => {
            collect_inside(b, found, seen);
            collect_inside(x, found, seen);
        }
    }
}

impl PartialEq for Definition {
    fn eq(&self, other: &Self) -> bool {
        Rc::ptr_eq(&self.0, &other.0) || self.name() == other.name()
    }
}

impl Eq for Definition {}

impl PartialOrd for Definition {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Definition {
    fn cmp(&self, other: &Self) -> Ordering {
        crate::symbolic::natural::natural_cmp(self.name(), other.name())
            .then_with(|| self.name().cmp(other.name()))
    }
}

impl std::hash::Hash for Definition {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.name().hash(state)
    }
}
