//! The validated problem as a whole ([`Problem`]): its parts, from [`model`](super::model),
//! and the questions asked of it by index (a body's name, a reaction site's name and path,
//! a coordinate's symbol, the generalized speeds).

use super::impact::Impact;
use super::model::{
    Body, BodyId, Constant, Constraint, Coordinate, Dimension, Joint, Load, PointDef,
    SimulateSettings, Speed, VectorExpr,
};
use super::question_model::Question;
use crate::symbolic::{Expr, Symbol};

/// A validated problem.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    /// The title, as the handout's heading.
    pub title: String,
    /// The statement, as written for the student, if given.
    pub statement: Option<String>,
    /// Planar or spatial.
    pub dimension: Dimension,
    /// The named constants, in file order.
    pub constants: Vec<Constant>,
    /// The generalized coordinates, in the order the joints first name them.
    pub coordinates: Vec<Coordinate>,
    /// The acceleration of gravity, if any.
    pub gravity: Option<VectorExpr>,
    /// The declared bodies; `BodyId(i + 1)` is `bodies[i]`.
    pub bodies: Vec<Body>,
    /// The joints of the tree, one per declared body.
    pub joints: Vec<Joint>,
    /// The declared points.
    pub points: Vec<PointDef>,
    /// The applied loads, in file order.
    pub loads: Vec<Load>,
    /// Loop-closing joints: they add no coordinates and remove the motion their type forbids.
    pub closures: Vec<Joint>,
    /// Rolling contacts and general position and velocity constraints.
    pub constraints: Vec<Constraint>,
    /// Reactions requested, as site indices (see [`Problem::site_name`]).
    pub find_reactions: Vec<usize>,
    /// The questions of `find.questions`, answered in the handout's "Answers".
    pub questions: Vec<Question>,
    /// How long and how finely to simulate.
    pub simulate: SimulateSettings,
    /// The declared generalized speeds, as many as the coordinates; empty when the speeds
    /// are the coordinates' rates (the default).
    pub speeds: Vec<Speed>,
    /// The fractions the expressions write as decimals, with the decimal (`2/5`, `0.4`):
    /// the worked solution prints them as written; the arithmetic stays exact.
    pub decimals: Vec<(crate::symbolic::Number, String)>,
    /// An impact at the initial state (`impact`), if any.
    pub impact: Option<Impact>,
}

impl Problem {
    /// The coordinates' initial values `q(0)`, as written, in coordinate order.
    pub fn initial_coordinates(&self) -> Vec<f64> {
        self.initial_state().q
    }

    /// The name of a body, `N` for the ground.
    pub fn body_name(&self, id: BodyId) -> &str {
        if id == BodyId::GROUND {
            "N"
        } else {
            &self.bodies[id.0 - 1].name
        }
    }

    /// The body ids of the declared bodies, in file order.
    pub fn body_ids(&self) -> impl Iterator<Item = BodyId> {
        (1..=self.bodies.len()).map(BodyId)
    }

    /// The declared body behind `id` (not `N`).
    pub fn body(&self, id: BodyId) -> &Body {
        &self.bodies[id.0 - 1]
    }

    /// The joint whose child is `body`, if any (every declared body has exactly one).
    pub fn joint_of(&self, body: BodyId) -> Option<usize> {
        self.joints.iter().position(|j| j.child == body)
    }

    /// The name of reaction site `site`: the joints first, then the closures, then the
    /// constraints (the indices of [`Problem::find_reactions`]).
    pub fn site_name(&self, site: usize) -> &str {
        self.site_name_and_path(site).0
    }

    /// The JSON path of reaction site `site`'s entry, e.g. `closures[0]`.
    pub fn site_path(&self, site: usize) -> &str {
        self.site_name_and_path(site).1
    }

    fn site_name_and_path(&self, site: usize) -> (&str, &str) {
        let (j, c) = (self.joints.len(), self.closures.len());
        if site < j {
            (&self.joints[site].name, &self.joints[site].path)
        } else if site < j + c {
            let closure = &self.closures[site - j];
            (&closure.name, &closure.path)
        } else {
            let constraint = &self.constraints[site - j - c];
            (&constraint.name, &constraint.path)
        }
    }

    /// Whether reaction site `site` has Coulomb friction (a rough slider, closure or contact).
    pub fn site_is_rough(&self, site: usize) -> bool {
        let (j, c) = (self.joints.len(), self.closures.len());
        if site < j {
            self.joints[site].friction.is_some()
        } else if site < j + c {
            self.closures[site - j].friction.is_some()
        } else {
            self.constraints[site - j - c].friction.is_some()
        }
    }

    /// Whether the problem has closures, constraints or prescribed coordinates.
    pub fn is_constrained(&self) -> bool {
        !self.closures.is_empty()
            || !self.constraints.is_empty()
            || self.coordinates.iter().any(|c| c.motion.is_some())
    }

    /// The symbol of coordinate `index` differentiated `order` times.
    pub fn coordinate_symbol(&self, index: usize, order: u8) -> Symbol {
        Symbol::Coord(self.coordinates[index].name.as_str().into(), order)
    }

    /// The generalized speed `r` (`order` 1) or its rate (`order` 2): the declared speed
    /// when the problem has `speeds`, the coordinate's rate otherwise.
    pub fn speed_symbol(&self, r: usize, order: u8) -> Symbol {
        match self.speeds.get(r) {
            Some(speed) => Symbol::Speed(speed.name.as_str().into(), order.saturating_sub(1)),
            None => self.coordinate_symbol(r, order),
        }
    }

    /// Every generalized speed (`order` 1) or every speed's rate (`order` 2), in order.
    pub fn speed_symbols(&self, order: u8) -> Vec<Symbol> {
        (0..self.coordinates.len())
            .map(|r| self.speed_symbol(r, order))
            .collect()
    }

    /// The same problem with the coordinates' rates as its speeds: the same motion, derived
    /// in `q''` (the state matrix of `linearize` is about `q` and `q'` either way).
    pub fn without_speeds(&self) -> Problem {
        Problem {
            speeds: Vec::new(),
            ..self.clone()
        }
    }

    /// Whether the problem declares its own generalized speeds.
    pub fn has_speeds(&self) -> bool {
        !self.speeds.is_empty()
    }

    /// The expression of coordinate `index` differentiated `order` times.
    pub fn coordinate_expr(&self, index: usize, order: u8) -> Expr {
        Expr::sym(self.coordinate_symbol(index, order))
    }

    /// Whether some motion is prescribed: a coordinate driven by a motion of time (not held at
    /// a constant), or a position or velocity constraint written with `t`.
    pub fn moves_with_time(&self) -> bool {
        use crate::problem::ConstraintKind;
        let time = crate::symbolic::Symbol::Time;
        let driven =
            (self.coordinates.iter()).any(|c| c.motion.as_ref().is_some_and(|m| m.contains(&time)));
        let written = self.constraints.iter().any(|c| match &c.kind {
            ConstraintKind::Position { expression } | ConstraintKind::Velocity { expression } => {
                expression.contains(&time)
            }
            _ => false,
        });
        driven || written
    }
}
