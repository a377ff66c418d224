//! The energies of Lagrange's equations and their derivatives: `T` of every body from the
//! velocities of step 4, `V` of gravity and springs, and per coordinate ∂T/∂q̇_r, its time
//! derivative, ∂T/∂q_r and ∂V/∂q_r.

use crate::mechanics::{apply, dot3, Components, Frames, MechanicsError, Model, Vector};
use crate::problem::BodyId;
use crate::symbolic::{
    add, partial, simplify, substitute, time_derivative, DiffError, Expr, Symbol,
};

/// One body's velocity of its mass centre and angular velocity (in its own unit vectors),
/// with the coordinates' rates, and its mass and central inertia.
pub struct BodyMotion<'m> {
    /// The body.
    pub body: BodyId,
    /// `v*`, each part in its own frame.
    pub velocity: Vector,
    /// `ω` in the body's unit vectors.
    pub omega: Components,
    /// The mass.
    pub mass: Expr,
    /// The central inertia matrix, in the body's unit vectors.
    pub inertia: crate::mechanics::Matrix,
    frames: &'m Frames,
}

impl BodyMotion<'_> {
    /// `v*·v*`, each pair of parts in the frame of the longer.
    pub fn speed_squared(&self) -> Expr {
        self.velocity.dot(&self.velocity, self.frames)
    }

    /// The body's kinetic energy `½ m v*·v* + ½ ω·I·ω`.
    pub fn kinetic(&self) -> Expr {
        let half = Expr::ratio(1, 2);
        let translation = &self.mass * &self.speed_squared();
        &half * &(&translation + &self.rotation())
    }

    /// `ω·I·ω`.
    pub fn rotation(&self) -> Expr {
        dot3(&self.omega, &apply(&self.inertia, &self.omega))
    }

    /// `∂T/∂q̇_r = m v*·∂v*/∂q̇_r + ω·I·∂ω/∂q̇_r` (the frames do not depend on the rates;
    /// I symmetric).
    fn partial_rate(&self, rate: &Symbol) -> Result<Expr, DiffError> {
        let dv = self.velocity.try_map(|c| partial(c, rate))?;
        let dw = try_components(&self.omega, |c| partial(c, rate))?;
        let translation = &self.mass * &self.velocity.dot(&dv, self.frames);
        Ok(&translation + &dot3(&self.omega, &apply(&self.inertia, &dw)))
    }

    /// `∂T/∂q_r = ½ m ∂(v*·v*)/∂q_r + ω·I·∂ω/∂q_r`.
    fn partial_coordinate(&self, q: &Symbol) -> Result<Expr, DiffError> {
        let half = Expr::ratio(1, 2);
        let dw = try_components(&self.omega, |c| partial(c, q))?;
        let translation = &half * &(&self.mass * &partial(&self.speed_squared(), q)?);
        Ok(&translation + &dot3(&self.omega, &apply(&self.inertia, &dw)))
    }
}

fn try_components(
    c: &Components,
    f: impl Fn(&Expr) -> Result<Expr, DiffError>,
) -> Result<Components, DiffError> {
    Ok([f(&c[0])?, f(&c[1])?, f(&c[2])?])
}

/// Every body with mass or inertia, in the tree's order.
pub fn bodies<'m>(model: &'m Model<'m>) -> Vec<BodyMotion<'m>> {
    let rates = rates_of(model);
    model
        .order
        .iter()
        .map(|&body| {
            let state = &model.bodies[body.0];
            let w = state.omega.components_in(state.frame, &model.frames);
            BodyMotion {
                body,
                velocity: state.center.velocity.map(&rates),
                omega: w.map(|c| rates(&c)),
                mass: state.mass.clone(),
                inertia: state.inertia.clone(),
                frames: &model.frames,
            }
        })
        .filter(|b| !(b.mass.is_zero() && b.inertia.iter().flatten().all(Expr::is_zero)))
        .collect()
}

/// Rewrites declared speeds as the coordinates' rates, `u_s = Σ_r W[s][r] q̇_r`: Lagrange's
/// equations differentiate with respect to the rates. The identity without declared speeds.
pub fn rates_of<'a>(model: &'a Model<'a>) -> impl Fn(&Expr) -> Expr + 'a {
    move |e: &Expr| match &model.speeds {
        None => e.clone(),
        Some(speeds) => substitute(e, &|s| {
            let i = speeds.speeds.iter().position(|u| u == s)?;
            Some(add(speeds.w[i]
                .iter()
                .zip(&speeds.rates)
                .map(|(w, q)| w * &Expr::sym(q.clone()))))
        }),
    }
}

/// With declared speeds, the rewriting of the second rates `q̈_s = d/dt(Σ_r W⁻¹[s][r] u_r)`,
/// so that the rows are linear in the `u̇` the system solves for; `None` without.
pub fn second_rates_as_speeds<'a>(model: &'a Model<'a>) -> Option<impl Fn(&Expr) -> Expr + 'a> {
    let speeds = model.speeds.as_ref()?;
    let problem = model.problem;
    let second: Vec<(Symbol, Expr)> = speeds
        .rates_as_speeds()
        .iter()
        .enumerate()
        .map(|(s, rate)| {
            let derivative = time_derivative(rate).unwrap_or_else(|_| Expr::zero());
            (
                problem.coordinate_symbol(s, 2),
                speeds.to_speeds(&derivative),
            )
        })
        .collect();
    Some(move |e: &Expr| {
        substitute(e, &|s| {
            second
                .iter()
                .find(|(q, _)| q == s)
                .map(|(_, value)| value.clone())
        })
    })
}

/// `∂T/∂q̇_r` of `bodies` for coordinate `r`, as formed (not simplified).
///
/// # Errors
/// When a velocity holds a function without a derivative.
pub fn raw_momentum(
    model: &Model,
    bodies: &[BodyMotion],
    r: usize,
) -> Result<Expr, MechanicsError> {
    let rate = model.problem.coordinate_symbol(r, 1);
    let terms: Result<Vec<Expr>, DiffError> =
        bodies.iter().map(|b| b.partial_rate(&rate)).collect();
    terms.map(add).map_err(|e| MechanicsError {
        path: "bodies".into(),
        message: e.to_string(),
        hint: Some(
            "Lagrange's equations differentiate the energies: use functions that have a derivative"
                .into(),
        ),
    })
}

/// The derivatives of `T` and `V` for one coordinate.
pub struct EnergyTerms {
    /// ∂T/∂q̇_r.
    pub momentum: Expr,
    /// d/dt(∂T/∂q̇_r).
    pub momentum_rate: Expr,
    /// ∂T/∂q_r.
    pub kinetic_partial: Expr,
    /// ∂V/∂q_r.
    pub potential_partial: Expr,
}

/// The potential energy `V`: gravity, springs and joint springs.
pub fn potential(model: &Model) -> Expr {
    crate::equations::energy::potential(model)
}

/// Per coordinate, ∂T/∂q̇_r, d/dt(∂T/∂q̇_r), ∂T/∂q_r and ∂V/∂q_r; each simplified when
/// `simplified` (for the worked solution; the numbers take them as formed).
///
/// # Errors
/// When a velocity or a spring holds a function without a derivative.
pub fn derivatives(model: &Model, simplified: bool) -> Result<Vec<EnergyTerms>, MechanicsError> {
    let bodies = bodies(model);
    let v = potential(model);
    (0..model.problem.coordinates.len())
        .map(|r| derivative(model, (&bodies, &v), r, simplified))
        .collect()
}

/// The derivatives of `T` (of `bodies`) and `V` for coordinate `r` (see `derivatives`).
///
/// # Errors
/// As for `derivatives`.
pub fn derivative(
    model: &Model,
    (bodies, v): (&[BodyMotion], &Expr),
    r: usize,
    simplified: bool,
) -> Result<EnergyTerms, MechanicsError> {
    let problem = model.problem;
    let failed = |e: DiffError| MechanicsError {
        path: "bodies".into(),
        message: e.to_string(),
        hint: Some(
            "Lagrange's equations differentiate the energies: use functions that have a derivative"
                .into(),
        ),
    };
    let tidy = |e: Expr| if simplified { simplify(&e) } else { e };
    let q = problem.coordinate_symbol(r, 0);
    let rate = problem.coordinate_symbol(r, 1);
    let sum = |f: &dyn Fn(&BodyMotion) -> Result<Expr, DiffError>| {
        let terms: Result<Vec<Expr>, DiffError> = bodies.iter().map(f).collect();
        terms.map(|t| tidy(add(t))).map_err(failed)
    };
    let momentum = sum(&|b| b.partial_rate(&rate))?;
    let momentum_rate = tidy(time_derivative(&momentum).map_err(failed)?);
    let kinetic_partial = sum(&|b| b.partial_coordinate(&q))?;
    let potential_partial = tidy(partial(v, &q).map_err(failed)?);
    Ok(EnergyTerms {
        momentum,
        momentum_rate,
        kinetic_partial,
        potential_partial,
    })
}
