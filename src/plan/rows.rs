//! One scalar equation of motion: a free body, a sum of forces or of moments about a point,
//! dotted with a direction, its terms grouped as the Motion Law groups them.

pub use crate::mechanics::Form;
use crate::mechanics::{
    angular, apply, center, named_components, sample_states, size, Built, Components, DotSum,
    Frames, Kind, Quantity, MAX_EXPANDED_TERMS,
};
use crate::mechanics::{Model, Vector};
use crate::plan::forces::{Action, ActionKind, Category};
use crate::problem::BodyId;
use crate::symbolic::{add, Expr, Node, Symbol};
use std::cell::RefCell;

/// The inertia force `-m a*` and inertia torque `-I·α - ω×I·ω` of every body.
#[derive(Clone, Debug)]
pub struct Inertia {
    /// Indexed by body id (`N` first, zero).
    pub force: Vec<Vector>,
    /// Indexed by body id, in the body's own unit vectors.
    pub torque: Vec<Vector>,
    /// The mass centres' accelerations as the inertia forces use them: a long one in the
    /// body's unit vectors with named parts (`Σ v_r q̈_r + ã`), for step 4. Indexed by body id.
    pub acceleration: Vec<Vector>,
    /// The angular accelerations likewise, in the body's unit vectors.
    pub alpha: Vec<Vector>,
    /// Whether a body's mass-centre acceleration is written with named parts. Indexed by
    /// body id.
    pub compact: Vec<bool>,
    /// The form it is written for.
    pub form: Form,
    /// Inertia torques dotted with a direction so far: a torque is long, and every free
    /// body that holds its body dots it with the same directions again.
    torque_along: RefCell<Vec<(BodyId, Vector, Expr)>>,
}

impl Inertia {
    /// The inertia forces and torques of every body of `model`, written for `form`.
    pub fn of(model: &Model, form: Form) -> Inertia {
        let mut force = Vec::with_capacity(model.bodies.len());
        let mut torque = Vec::with_capacity(model.bodies.len());
        let accelerations: Vec<Symbol> = model.problem.speed_symbols(2);
        // Long accelerations in the body's own unit vectors with named parts; short ones stay
        // as the student writes them. The states check the parts built on the parent's.
        let states = sample_states(model);
        let named = |body: BodyId, vector: &Vector, kind: Kind, built: Option<&Built>| {
            let frame = model.bodies[body.0].frame;
            let components = vector.components_in(frame, &model.frames);
            if body == BodyId::GROUND {
                return components;
            }
            let body_name = model.frames.name(body);
            let quantity = Quantity {
                body: body_name,
                kind,
            };
            named_components(&components, &accelerations, &quantity, built, &states)
        };
        // Angular accelerations parents first, so that a body's partial angular velocities
        // can be built on its parent's named ones: ω_r^k = C ω_r^(k-1) + the joint's own.
        let mut alphas: Vec<Components> =
            vec![std::array::from_fn(|_| Expr::zero()); model.bodies.len()];
        for &body in &model.order {
            let built = angular(model, body, &alphas);
            alphas[body.0] = named(
                body,
                &model.bodies[body.0].alpha,
                Kind::AngularAcceleration,
                built.as_ref(),
            );
        }
        // A short acceleration keeps the unit vectors it was written in (`ẍ n_x`). A handout
        // writes a planar one whole, as the student does: a five-link chain's outer link
        // (−L m (1/3 + cos q5 / 2 + …) q̈1) reads better so than by names, and a ten-link
        // chain's takes no fewer pages by names.
        let whole = model.is_planar() && form == Form::Handout;
        let longest = if whole {
            usize::MAX
        } else {
            3 * MAX_EXPANDED_TERMS
        };
        let is_long = |vector: &Vector| {
            let terms: usize = vector.parts().iter().map(|(_, c)| size(c)).sum();
            terms > longest
        };
        // Mass centres parents first too: v_r^k* = v_r^(k-1)* + ω_r^(k-1) × r + ω_r^k × r'.
        let mut centers: Vec<Vector> = model
            .bodies
            .iter()
            .map(|b| b.center.acceleration.clone())
            .collect();
        let mut compact = vec![false; model.bodies.len()];
        for &body in &model.order {
            let state = &model.bodies[body.0];
            if !is_long(&state.center.acceleration) {
                continue;
            }
            compact[body.0] = true;
            let built = center(model, body, &centers, &alphas);
            centers[body.0] = Vector::new(
                state.frame,
                named(
                    body,
                    &state.center.acceleration,
                    Kind::CenterAcceleration,
                    built.as_ref(),
                ),
            );
        }
        let mut acceleration = Vec::with_capacity(model.bodies.len());
        let mut alpha = Vec::with_capacity(model.bodies.len());
        for (index, state) in model.bodies.iter().enumerate() {
            let body = BodyId(index);
            let center = centers[index].clone();
            force.push(center.scaled(&-state.mass.clone()));
            acceleration.push(center);
            let w = state.omega_named.components_in(state.frame, &model.frames);
            let a = alphas[index].clone();
            let iw = apply(&state.inertia, &w);
            let gyro = crate::mechanics::cross3(&w, &iw);
            let t: Components = if form == Form::Numeric && !model.is_planar() {
                torque_with_named_rest(
                    &state.inertia,
                    &a,
                    &gyro,
                    &accelerations,
                    model.frames.name(body),
                )
            } else {
                torque_whole(&state.inertia, &a, &gyro)
            };
            torque.push(Vector::new(state.frame, t));
            alpha.push(Vector::new(state.frame, a));
        }
        Inertia {
            force,
            torque,
            acceleration,
            alpha,
            compact,
            form,
            torque_along: RefCell::default(),
        }
    }

    /// The inertia torque of `body` dotted with `direction`, written out once for each.
    pub fn torque_along(&self, body: BodyId, direction: &Vector, frames: &Frames) -> Expr {
        let known = self
            .torque_along
            .borrow()
            .iter()
            .find(|(b, d, _)| *b == body && d == direction)
            .map(|(.., e)| e.clone());
        known.unwrap_or_else(|| {
            let e = self.torque[body.0].dot(direction, frames);
            let entry = (body, direction.clone(), e.clone());
            self.torque_along.borrow_mut().push(entry);
            e
        })
    }
}

/// Step 2's inertia forces and torques, written the first time they are read: a system by
/// composite bodies (the numbers of a large tree) never reads them, and for a long chain in
/// space naming their parts is most of the derivation's time.
#[derive(Debug)]
pub struct LazyInertia {
    form: Form,
    written: std::cell::OnceCell<Inertia>,
}

impl LazyInertia {
    /// Not yet written; to be written for `form`.
    pub fn new(form: Form) -> LazyInertia {
        LazyInertia {
            form,
            written: std::cell::OnceCell::new(),
        }
    }

    /// Already written.
    pub fn written(inertia: Inertia) -> LazyInertia {
        LazyInertia {
            form: inertia.form,
            written: std::cell::OnceCell::from(inertia),
        }
    }

    /// The inertia forces and torques of `model`, written now if they were not.
    pub fn get(&self, model: &Model) -> &Inertia {
        self.written.get_or_init(|| Inertia::of(model, self.form))
    }

    /// As [`Self::get`], owned.
    pub fn into_written(self, model: &Model) -> Inertia {
        let form = self.form;
        self.written
            .into_inner()
            .unwrap_or_else(|| Inertia::of(model, form))
    }
}

/// The Motion Law's groups of one scalar equation; their sum is zero.
#[derive(Clone, Debug, PartialEq)]
pub struct Groups {
    /// Contact forces (and couples): reactions, springs, dampers, applied loads.
    pub contact: Expr,
    /// Distance forces: gravity.
    pub distance: Expr,
    /// Inertia forces `-m a*` (their moments, in a moment equation).
    pub inertia_force: Expr,
    /// Inertia torques.
    pub inertia_torque: Expr,
}

impl Groups {
    /// The whole left-hand side.
    pub fn total(&self) -> Expr {
        add([
            self.contact.clone(),
            self.distance.clone(),
            self.inertia_force.clone(),
            self.inertia_torque.clone(),
        ])
    }
}

/// What an equation sums.
#[derive(Clone, Debug, PartialEq)]
pub enum Sum {
    /// Forces.
    Force,
    /// Moments about a point.
    Moment {
        /// The point's name as a student writes it (`O`, `A*`).
        point: String,
        /// Its position from `N.o`.
        position: Vector,
    },
    /// A constraint differentiated to the acceleration level (a closure, a rolling
    /// contact, a `position` or `velocity` entry, a prescribed coordinate).
    Constraint {
        /// The constraint row's name, e.g. `R.Fx`, `q1 prescribed`.
        name: String,
    },
    /// Kane's generalized forces for a generalized speed (or an auxiliary one).
    Generalized {
        /// The speed, e.g. `q1'` or `u(O.Fx)`.
        speed: String,
    },
}

/// A direction for the dot product, with its name.
#[derive(Clone, Debug, PartialEq)]
pub struct Direction {
    /// Plain name, e.g. `N.x`, `axis of O`.
    pub name: String,
    /// LaTeX, e.g. `\hat{\mathbf{n}}_{x}`.
    pub latex: String,
    /// The unit vector.
    pub vector: Vector,
}

/// One scalar equation of motion.
#[derive(Clone, Debug)]
pub struct Equation {
    /// The bodies of the free body.
    pub free_body: Vec<BodyId>,
    /// Forces or moments.
    pub sum: Sum,
    /// The direction of the dot product (none for Kane's rows).
    pub direction: Option<Direction>,
    /// The terms grouped as the Motion Law groups them, before simplification.
    pub groups: Groups,
    /// The whole equation, `expression = 0`.
    pub expression: Expr,
    /// The unknowns it contains (q'' and reaction components), in system order.
    pub unknowns: Vec<Symbol>,
}

impl Equation {
    /// The same equation with `f` applied to its groups and its whole expression.
    pub fn map_expressions(self, f: impl Fn(&Expr) -> Expr) -> Equation {
        Equation {
            groups: Groups {
                contact: f(&self.groups.contact),
                distance: f(&self.groups.distance),
                inertia_force: f(&self.groups.inertia_force),
                inertia_torque: f(&self.groups.inertia_torque),
            },
            expression: f(&self.expression),
            ..self
        }
    }
}

/// Whether an action acts on the free body from outside it.
pub fn is_external(action: &Action, free_body: &[BodyId]) -> bool {
    free_body.contains(&action.body) && !action.partner.is_some_and(|p| free_body.contains(&p))
}

/// The groups of `(Σ forces) · u` or `(Σ moments about P) · u` for a free body.
pub fn resultant(
    model: &Model,
    actions: &[Action],
    inertia: &Inertia,
    free_body: &[BodyId],
    about: Option<&Vector>,
    direction: &Vector,
) -> Groups {
    let (contact, distance) = action_terms(model, actions, free_body, about, direction);
    let (inertia_force, inertia_torque) =
        inertia_terms(model, inertia, free_body, about, direction);
    Groups {
        contact,
        distance,
        inertia_force,
        inertia_torque,
    }
}

/// The contact and distance terms: the external actions on the free body.
pub fn action_terms(
    model: &Model,
    actions: &[Action],
    free_body: &[BodyId],
    about: Option<&Vector>,
    direction: &Vector,
) -> (Expr, Expr) {
    let frames = &model.frames;
    let (mut contact, mut distance) = (Vec::new(), Vec::new());
    for action in actions.iter().filter(|a| is_external(a, free_body)) {
        let term = match (&action.kind, about) {
            (ActionKind::Force { force, .. }, None) => force.dot(direction, frames),
            (ActionKind::Couple { .. }, None) => continue,
            (ActionKind::Force { offset, force }, Some(point)) => {
                let at = model.position_on(action.body, offset).minus(point);
                let mut moment = MomentSum::new(frames, direction);
                moment.add(&at, force);
                moment.total()
            }
            (ActionKind::Couple { torque }, Some(_)) => torque.dot(direction, frames),
        };
        match action.category {
            Category::Contact => contact.push(term),
            Category::Distance => distance.push(term),
        }
    }
    (add(contact), add(distance))
}

/// The inertia-force and inertia-torque terms of the bodies of the free body.
pub fn inertia_terms(
    model: &Model,
    inertia: &Inertia,
    free_body: &[BodyId],
    about: Option<&Vector>,
    direction: &Vector,
) -> (Expr, Expr) {
    let frames = &model.frames;
    let Some(point) = about else {
        // The forces summed first: one dot product instead of one per body.
        let force = Vector::sum(free_body.iter().map(|b| inertia.force[b.0].clone()));
        return (force.dot(direction, frames), Expr::zero());
    };
    let mut moments = MomentSum::new(frames, direction);
    let mut inertia_torque = Vec::new();
    for &body in free_body {
        let at = model.bodies[body.0].center.position.minus(point);
        moments.add(&at, &inertia.force[body.0]);
        inertia_torque.push(inertia.torque_along(body, direction, frames));
    }
    (moments.total(), add(inertia_torque))
}

/// A sum of moments `(at × force) · direction`, written `-Σ (at × direction) · force`: the
/// short vectors are crossed, and the long forces are multiplied out once, in dot products
/// that share work between bodies (see [`DotSum`]).
struct MomentSum<'a> {
    frames: &'a Frames,
    direction: &'a Vector,
    sum: DotSum<'a>,
}

impl<'a> MomentSum<'a> {
    fn new(frames: &'a Frames, direction: &'a Vector) -> Self {
        MomentSum {
            frames,
            direction,
            sum: DotSum::new(frames),
        }
    }

    fn add(&mut self, at: &Vector, force: &Vector) {
        self.sum.add(&at.cross(self.direction, self.frames), force);
    }

    fn total(self) -> Expr {
        -self.sum.total()
    }
}

/// The unknowns among `all` that appear in `e`, in the order of `all`.
pub fn unknowns_in(e: &Expr, all: &[Symbol]) -> Vec<Symbol> {
    // One walk of the expression, not one per unknown. Definitions are not entered: they
    // hold rates, never an unknown (`linear_split` refuses one that would).
    fn walk(e: &Expr, present: &mut std::collections::HashSet<Symbol>) {
        match e.node() {
            Node::Sym(s @ (Symbol::Coord(_, 2) | Symbol::Speed(_, 1) | Symbol::Unknown(_))) => {
                present.insert(s.clone());
            }
            Node::Num(_) | Node::Sym(_) => {}
            Node::Add(items) | Node::Mul(items) | Node::Func(_, items) => {
                items.iter().for_each(|i| walk(i, present))
            }
            Node::Pow(b, x) => {
                walk(b, present);
                walk(x, present);
            }
        }
    }
    let mut present = std::collections::HashSet::new();
    walk(e, &mut present);
    all.iter()
        .filter(|s| present.contains(*s))
        .cloned()
        .collect()
}

/// The LaTeX of a unit vector direction `frame.axis`.
pub fn unit_direction(model: &Model, frame: BodyId, axis: usize) -> Direction {
    let name = model.frames.name(frame);
    Direction {
        name: format!("{name}.{}", ["x", "y", "z"][axis]),
        latex: crate::symbolic::latex_unit_vector(name, axis as u8),
        vector: Vector::unit(frame, axis),
    }
}

/// The inertia torque −(I·α + ω × I·ω), as the student writes it.
fn torque_whole(
    inertia: &crate::mechanics::Matrix,
    alpha: &Components,
    gyro: &Components,
) -> Components {
    let ia = apply(inertia, alpha);
    std::array::from_fn(|i| -(&ia[i] + &gyro[i]))
}

/// The inertia torque −(I·α + ω × I·ω) with what does not multiply a q̈ named, component by
/// component: T^k = I·α̃ + ω × I·ω. Every Kane row and every moment then takes it as three
/// products, ω_r · T, where multiplied out against ω_r the gyroscopic part alone is some
/// thirty monomials of the ω components for each body and row. For the numbers only.
fn torque_with_named_rest(
    inertia: &crate::mechanics::Matrix,
    alpha: &Components,
    gyro: &Components,
    accelerations: &[Symbol],
    body: &str,
) -> Components {
    let split: Option<Vec<(Vec<Expr>, Expr)>> = alpha
        .iter()
        .map(|c| crate::symbolic::linear_split(c, accelerations).ok())
        .collect();
    let Some(split) = split else {
        return torque_whole(inertia, alpha, gyro);
    };
    let rest: Components = std::array::from_fn(|i| split[i].1.clone());
    let with_q: Components = std::array::from_fn(|i| {
        add(split[i]
            .0
            .iter()
            .zip(accelerations)
            .map(|(c, q)| c * &Expr::sym(q.clone())))
    });
    let (i_with_q, i_rest) = (apply(inertia, &with_q), apply(inertia, &rest));
    std::array::from_fn(|axis| {
        let value = &i_rest[axis] + &gyro[axis];
        let axis_name = ["x", "y", "z"][axis];
        let named = if value.terms().len() < 2 {
            value
        } else {
            Expr::named(
                &format!("{body}.T.{axis_name}"),
                &format!(
                    "T^{{{}}}_{{{axis_name}}}",
                    crate::symbolic::latex_name(body)
                ),
                &format!("inertia torque of {body} without the q'', along {body}.{axis_name}"),
                value,
            )
        };
        -(&i_with_q[axis] + &named)
    })
}
