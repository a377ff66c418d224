//! The unknowns of the linear system other than the q'': what each one is, as a type.
//!
//! Every printed form derives from the type: the plain name (`O.Fx`, `Q_q1`,
//! `lambda_loop`), the LaTeX (`F^{O}_{x}`, `\tau`, `\lambda_{\mathrm{loop}}`)
//! and, through the site or coordinate it names, the keys of the commands' output.

use super::Name;
use std::cmp::Ordering;
use std::fmt;

/// Whether a reaction component is a force or a moment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ComponentKind {
    /// A force through the site's point.
    Force,
    /// A moment (a couple).
    Moment,
}

impl ComponentKind {
    /// `F` or `M`.
    pub fn letter(self) -> &'static str {
        match self {
            ComponentKind::Force => "F",
            ComponentKind::Moment => "M",
        }
    }
}

/// Which way a reaction component acts, as its name tells it. Declared in the order the
/// names sort in (`F1 < Fn < Ft1 < Fx`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Axis {
    /// One of the directions chosen perpendicular to a joint's axis, counted from 1.
    Numbered(u8),
    /// A rolling contact's normal.
    Normal,
    /// The one tangent of a contact in a plane, or a rough slider's axis when it is not a
    /// unit vector: printed `t`, named `t1` in the commands' output (as the first of
    /// several would be).
    SoleTangent,
    /// One of a rolling contact's tangents in space, counted from 1.
    Tangent(u8),
    /// A unit vector of the frame the reaction is given in: 0, 1, 2 for x, y, z.
    Unit(u8),
    /// Along a two-force member, toward its joint: the member's tension.
    Member,
}

impl Axis {
    /// The subscript as printed: `x`, `2`, `n`, `t` (the one tangent), `t1`.
    pub fn subscript(self) -> String {
        match self {
            Axis::SoleTangent => "t".into(),
            other => other.plain(),
        }
    }

    /// The subscript in a plain name (`O.Fx`, `floor.Ft1`): a sole tangent is `t1`.
    pub fn plain(self) -> String {
        match self {
            Axis::Numbered(i) => i.to_string(),
            Axis::Normal => "n".into(),
            Axis::SoleTangent => "t1".into(),
            Axis::Tangent(i) => format!("t{i}"),
            Axis::Unit(i) => ["x", "y", "z"]
                .get(i as usize)
                .copied()
                .unwrap_or("?")
                .into(),
            Axis::Member => String::new(),
        }
    }
}

/// One reaction component's kind and axis: `Fx`, `M1`, `Fn`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Component {
    /// Force or moment.
    pub kind: ComponentKind,
    /// Which way it acts.
    pub axis: Axis,
}

impl fmt::Display for Component {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.axis == Axis::Member {
            return write!(f, "T");
        }
        write!(f, "{}{}", self.kind.letter(), self.axis.plain())
    }
}

/// An unknown of the linear system other than a q'' (those are `Symbol::Coord(_, 2)`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Unknown {
    /// A reaction component at a site: a joint, a closure or a rolling contact (whose
    /// contact forces are its reaction components).
    Reaction {
        /// The site's name.
        site: Name,
        /// Which component.
        component: Component,
    },
    /// The generalized force that drives a prescribed coordinate.
    Drive {
        /// The coordinate's name.
        coordinate: Name,
        /// How it is written: the statement's symbol, or `\\tau` for an angle and `F` for
        /// a distance (see `mechanics::constraints::drive_symbol`).
        tex: Name,
    },
    /// The multiplier of a `position` or `velocity` constraint entry.
    Multiplier {
        /// The entry's name.
        constraint: Name,
    },
}

impl Unknown {
    /// The site whose reaction this is, if it is one.
    pub fn site(&self) -> Option<&str> {
        match self {
            Unknown::Reaction { site, .. } => Some(site),
            _ => None,
        }
    }

    /// The name in LaTeX: `F^{O}_{x}`, `\tau`, `\lambda_{\mathrm{loop}}`.
    pub fn latex(&self) -> String {
        use crate::symbolic::tex_name::{latex_name, latex_name_plain};
        match self {
            Unknown::Reaction { site, component } if component.axis == Axis::Member => {
                format!("T^{{{}}}", latex_name(site))
            }
            Unknown::Reaction { site, component } => format!(
                "{}^{{{}}}_{{{}}}",
                component.kind.letter(),
                latex_name(site),
                component.axis.subscript()
            ),
            Unknown::Drive { tex, .. } => tex.to_string(),
            Unknown::Multiplier { constraint } => {
                format!("\\lambda_{{{}}}", latex_name_plain(constraint))
            }
        }
    }
}

/// The plain name: `O.Fx`, `Q_q1`, `lambda_loop`.
impl fmt::Display for Unknown {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Unknown::Reaction { site, component } => write!(f, "{site}.{component}"),
            Unknown::Drive { coordinate, .. } => write!(f, "Q_{coordinate}"),
            Unknown::Multiplier { constraint } => write!(f, "lambda_{constraint}"),
        }
    }
}

/// Unknowns sort as their plain names do, read as a reader counts (`A.Fx < A.Fy < B.Fx`,
/// `Q_q2 < Q_q10`), so expressions print in the same order whatever the kind of unknown.
impl Ord for Unknown {
    fn cmp(&self, other: &Self) -> Ordering {
        use super::super::natural::natural_cmp;
        match (self, other) {
            // The common cases need no name written out: with one site, the names differ
            // in the component alone, whose order is that of its name.
            (
                Unknown::Reaction {
                    site: a,
                    component: x,
                },
                Unknown::Reaction {
                    site: b,
                    component: y,
                },
            ) if a == b => x.cmp(y),
            (Unknown::Drive { coordinate: a, .. }, Unknown::Drive { coordinate: b, .. })
            | (Unknown::Multiplier { constraint: a }, Unknown::Multiplier { constraint: b }) => {
                natural_cmp(a, b).then_with(|| a.cmp(b))
            }
            _ => {
                let (a, b) = (self.to_string(), other.to_string());
                natural_cmp(&a, &b).then_with(|| a.cmp(&b))
            }
        }
    }
}

impl PartialOrd for Unknown {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::symbolic::natural::natural_cmp;

    fn reaction(site: &str, kind: ComponentKind, axis: Axis) -> Unknown {
        Unknown::Reaction {
            site: site.into(),
            component: Component { kind, axis },
        }
    }

    #[test]
    fn names_and_latex_come_from_the_type() {
        use Axis::*;
        use ComponentKind::*;
        let check = |u: Unknown, plain: &str, latex: &str| {
            assert_eq!(u.to_string(), plain);
            assert_eq!(u.latex(), latex);
        };
        check(reaction("O", Force, Unit(0)), "O.Fx", "F^{O}_{x}");
        check(
            reaction("P2", Moment, Numbered(1)),
            "P2.M1",
            "M^{P_{2}}_{1}",
        );
        check(
            reaction("floor", Force, Normal),
            "floor.Fn",
            "F^{\\mathrm{floor}}_{n}",
        );
        check(
            reaction("floor", Force, SoleTangent),
            "floor.Ft1",
            "F^{\\mathrm{floor}}_{t}",
        );
        check(
            reaction("floor", Force, Tangent(2)),
            "floor.Ft2",
            "F^{\\mathrm{floor}}_{t2}",
        );
        check(
            Unknown::Drive {
                coordinate: "q1".into(),
                tex: "\\tau".into(),
            },
            "Q_q1",
            "\\tau",
        );
        check(
            Unknown::Multiplier {
                constraint: "loop".into(),
            },
            "lambda_loop",
            "\\lambda_{\\mathrm{loop}}",
        );
        // The coordinate as it prints everywhere else, as the subscript.
        check(
            Unknown::Drive {
                coordinate: "q_1".into(),
                tex: "F_{q_{1}}".into(),
            },
            "Q_q_1",
            "F_{q_{1}}",
        );
        check(
            Unknown::Multiplier {
                constraint: "2".into(),
            },
            "lambda_2",
            "\\lambda_{2}",
        );
    }

    #[test]
    fn unknowns_sort_as_their_names() {
        use Axis::*;
        use ComponentKind::*;
        let mut all = Vec::new();
        for site in ["A", "A1", "A10", "A2", "B", "Q", "a", "lambda"] {
            for kind in [Force, Moment] {
                for axis in [
                    Unit(2),
                    Unit(0),
                    Numbered(2),
                    Numbered(1),
                    Normal,
                    Tangent(1),
                ] {
                    all.push(reaction(site, kind, axis));
                }
            }
        }
        for name in ["q1", "q10", "q2", "x"] {
            all.push(Unknown::Drive {
                coordinate: name.into(),
                tex: "\\tau".into(),
            });
            all.push(Unknown::Multiplier {
                constraint: name.into(),
            });
        }
        let mut by_type = all.clone();
        by_type.sort();
        let mut by_name = all;
        by_name.sort_by(|a, b| {
            let (a, b) = (a.to_string(), b.to_string());
            natural_cmp(&a, &b).then_with(|| a.cmp(&b))
        });
        assert_eq!(by_type, by_name);
    }
}
