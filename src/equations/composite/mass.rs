//! The mass matrix by composite bodies.
//!
//! For speeds `r` of joint `i` and `s` of a joint `j` at or outboard of `i`, the entry
//! `M_rs = Σ_k m_k v^k_r · v^k_s + ω^k_r · I_k ω^k_s` over the bodies outboard of `j` is
//! (see [`super`])
//!
//! ```text
//! M_rs = ω_r · H_s(O_i) + u_r · L_s,
//! ```
//!
//! with `L_s` and `H_s(P)` the linear momentum and the angular momentum about `P` of the
//! bodies outboard of `j` per unit of `s`. At `j` they are one rigid body's, the composite
//! of the subtree (its mass, first moment and inertia about `O_j`, built from the leaves
//! in); towards the root, `H_s(O_p) = H_s(O_i) + (O_i − O_p) × L_s`, one shift per joint.
//! An entry is one dot product, where the rows sum over the bodies.

use super::tree::{
    apply, carried_by, carried_in, leaves_first, named, named_components, named_dcm, named_vector,
    SpeedMotion, AXES,
};
use crate::mechanics::{cross3, dot3, Components, Matrix, Model, Vector};
use crate::problem::BodyId;
use crate::symbolic::{add, latex_name, Expr};

/// The bodies outboard of a joint as one rigid body, about the child's point at the joint,
/// in the child's unit vectors.
pub struct Composite {
    /// The mass.
    pub mass: Expr,
    /// `Σ m (p − O)`.
    pub first_moment: Components,
    /// About the joint's point; symmetric.
    pub inertia: Matrix,
}

impl Composite {
    /// The linear momentum and the angular momentum about the joint's point of the
    /// composite moving with angular velocity `omega` (in the child's unit vectors) and its
    /// point at the joint with `velocity`: `m v + ω × h` and `h × v + I ω`.
    pub fn momentum(
        &self,
        body: BodyId,
        omega: &Components,
        velocity: &Vector,
        model: &Model,
    ) -> (Vector, Vector) {
        let h = Vector::new(body, self.first_moment.clone());
        let linear = velocity
            .scaled(&self.mass)
            .plus(&Vector::new(body, cross3(omega, &self.first_moment)));
        let angular = h
            .cross(velocity, &model.frames)
            .plus(&Vector::new(body, apply(&self.inertia, omega)));
        (linear, angular)
    }
}

/// The linear momentum and the angular momentum about a joint's point, per unit of one
/// speed, of the bodies outboard of the joint the speed belongs to.
pub struct Momentum {
    /// The speed.
    pub speed: usize,
    /// Linear momentum.
    pub linear: Vector,
    /// Angular momentum about the joint's point.
    pub angular: Vector,
}

/// Every joint's composite, and at every joint the momenta of the speeds of its own and of
/// the joints outboard, about its point.
pub struct Momenta {
    /// Indexed by joint.
    pub composites: Vec<Composite>,
    /// Indexed by joint.
    pub at: Vec<Vec<Momentum>>,
}

/// The composites from the leaves in, then each speed's momentum at its own joint and
/// carried in to the root, one shift per joint.
pub fn momenta(model: &Model, speeds: &[Vec<SpeedMotion>]) -> Option<Momenta> {
    let problem = model.problem;
    let count = problem.joints.len();
    let mut composites: Vec<Option<Composite>> = (0..count).map(|_| None).collect();
    for j in leaves_first(model) {
        composites[j] = Some(composite(model, j, &composites));
    }
    let composites: Vec<Composite> = composites.into_iter().collect::<Option<_>>()?;
    let mut at: Vec<Vec<Momentum>> = (0..count).map(|_| Vec::new()).collect();
    for (j, own) in speeds.iter().enumerate() {
        for s in own {
            let body = problem.joints[j].child;
            let moving = composites[j].momentum(body, &s.omega, &s.velocity, model);
            let (mut linear, mut angular) = named_momenta(model, body, s.speed, moving);
            let mut here = j;
            loop {
                at[here].push(Momentum {
                    speed: s.speed,
                    linear: linear.clone(),
                    angular: angular.clone(),
                });
                let Some(inner) = problem.joint_of(problem.joints[here].parent) else {
                    break;
                };
                let point = &model.joints[inner].child_at;
                let (l, h) = carried_in(model, here, point, (&linear, &angular));
                let body = problem.joints[inner].child;
                let carried = (Vector::new(body, l), Vector::new(body, h));
                (linear, angular) = named_momenta(model, body, s.speed, carried);
                here = inner;
            }
        }
    }
    Some(Momenta { composites, at })
}

/// The mass matrix `M` (Kane's rows hold `−M q''`), entry `[r][s]` for speeds `r`, `s`: at
/// every joint, its speeds against the momenta there.
pub fn mass_matrix(
    model: &Model,
    speeds: &[Vec<SpeedMotion>],
    momenta: &Momenta,
) -> Vec<Vec<Expr>> {
    let problem = model.problem;
    let n = problem.coordinates.len();
    let mut m = vec![vec![Expr::zero(); n]; n];
    for (j, own) in speeds.iter().enumerate() {
        let body = problem.joints[j].child;
        for momentum in &momenta.at[j] {
            let s = momentum.speed;
            for r in own {
                if problem.coordinates[s].joint == j && r.speed > s {
                    // Taken from the other speed's side.
                    continue;
                }
                let entry = r.dot(model, body, (&momentum.linear, &momentum.angular));
                m[r.speed][s] = entry.clone();
                m[s][r.speed] = entry;
            }
        }
    }
    m
}

/// The composite of the bodies outboard of joint `j`: its child's own mass and inertia,
/// and the composites of the joints the child carries (`outer`, filled for those).
fn composite(model: &Model, j: usize, outer: &[Option<Composite>]) -> Composite {
    let problem = model.problem;
    let child = problem.joints[j].child;
    let state = &model.bodies[child.0];
    let joint_point = &model.joints[j].child_at;
    // The child itself: its mass centre from the joint point, and the parallel-axis terms.
    let to_center: Components = std::array::from_fn(|i| &state.center_offset[i] - &joint_point[i]);
    let mut masses = vec![state.mass.clone()];
    let mut first_moments = vec![to_center.clone().map(|x| &state.mass * &x)];
    let mut inertias = vec![
        state.inertia.clone(),
        point_inertia(&state.mass, &to_center),
    ];
    for c in carried_by(model, child) {
        let Some(carried) = &outer[c] else {
            continue;
        };
        let grandchild = problem.joints[c].child;
        let turn = named_dcm(model, child, grandchild);
        // The carried joint's point from this one's, in the child's unit vectors.
        let offset = super::tree::joint_offset(model, c, joint_point);
        let moment = apply(&turn, &carried.first_moment);
        masses.push(carried.mass.clone());
        first_moments.push(moment.clone());
        first_moments.push(offset.clone().map(|x| &carried.mass * &x));
        inertias.push(rotated(model, (child, grandchild), &turn, &carried.inertia));
        inertias.push(point_inertia(&carried.mass, &offset));
        inertias.push(cross_terms(&moment, &offset));
    }
    let name = model.frames.name(child);
    let mass = named(
        format!("{name}.crb.m"),
        format!("m^{{{}}}_{{c}}", latex_name(name)),
        format!("mass of {name} and the bodies it carries"),
        add(masses),
    );
    let what = format!("first moment of mass of {name} and the bodies it carries about its joint");
    let first_moment = named_components(
        model,
        child,
        ("h", "h", &what),
        std::array::from_fn(|axis| add(first_moments.iter().map(|c| c[axis].clone()))),
    );
    let inertia = symmetric(|a, b| {
        let value = add(inertias.iter().map(|m| m[a][b].clone()));
        let axes = format!("{}{}", AXES[a], AXES[b]);
        named(
            format!("{name}.crb.I.{axes}"),
            format!("I^{{{}}}_{{c,{axes}}}", latex_name(name)),
            format!("inertia of {name} and the bodies it carries about its joint, {axes}"),
            value,
        )
    });
    Composite {
        mass,
        first_moment,
        inertia,
    }
}

/// The momenta of speed `s`, each component named, at the joint whose child is `body`.
fn named_momenta(
    model: &Model,
    body: BodyId,
    s: usize,
    (linear, angular): (Vector, Vector),
) -> (Vector, Vector) {
    let name = model.frames.name(body);
    let speed = &model.problem.coordinates[s].name;
    let what = |momentum: &str| {
        format!("{momentum} per unit {speed}' of the bodies it moves, at the joint of {name}")
    };
    (
        named_vector(
            model,
            body,
            (&format!("L.{speed}"), "L", &what("linear momentum")),
            &linear,
        ),
        named_vector(
            model,
            body,
            (&format!("H.{speed}"), "H", &what("angular momentum")),
            &angular,
        ),
    )
}

/// `C I Cᵀ`: an inertia given in the frame `from` in the unit vectors of `to`, through the
/// named product `I Cᵀ`.
fn rotated(model: &Model, (to, from): (BodyId, BodyId), turn: &Matrix, inertia: &Matrix) -> Matrix {
    let (to_name, from_name) = (model.frames.name(to), model.frames.name(from));
    let half: Matrix = std::array::from_fn(|a| {
        std::array::from_fn(|k| {
            let value = add((0..3).map(|b| &inertia[a][b] * &turn[k][b]));
            named(
                format!("{to_name}.crb.IC.{from_name}.{}{}", a + 1, k + 1),
                format!(
                    "(I C^{{T}})^{{{}}}_{{{}{}}}",
                    latex_name(from_name),
                    a + 1,
                    k + 1
                ),
                format!("the inertia carried by {from_name} times the direction cosines"),
                value,
            )
        })
    });
    symmetric(|i, k| add((0..3).map(|a| &turn[i][a] * &half[a][k])))
}

/// The inertia of a point of mass `m` at `r`: `m (r·r 1 − r rᵀ)`.
fn point_inertia(m: &Expr, r: &Components) -> Matrix {
    let squared = dot3(r, r);
    symmetric(|a, b| {
        let diagonal = if a == b {
            squared.clone()
        } else {
            Expr::zero()
        };
        m * &(&diagonal - &(&r[a] * &r[b]))
    })
}

/// What a composite's inertia gains, beyond the point-mass term, when its reference point
/// moves by `−d`: `2 (g·d) 1 − g dᵀ − d gᵀ`, with `g` its first moment.
fn cross_terms(g: &Components, d: &Components) -> Matrix {
    let both = dot3(g, d);
    symmetric(|a, b| {
        let diagonal = if a == b {
            &Expr::int(2) * &both
        } else {
            Expr::zero()
        };
        &diagonal - &(&(&g[a] * &d[b]) + &(&d[a] * &g[b]))
    })
}

/// A symmetric matrix from its entries on and above the diagonal.
fn symmetric(entry: impl Fn(usize, usize) -> Expr) -> Matrix {
    let upper: [[Option<Expr>; 3]; 3] =
        std::array::from_fn(|a| std::array::from_fn(|b| (a <= b).then(|| entry(a, b))));
    std::array::from_fn(|a| {
        std::array::from_fn(|b| {
            let (i, k) = if a <= b { (a, b) } else { (b, a) };
            upper[i][k].clone().unwrap_or_else(Expr::zero)
        })
    })
}
