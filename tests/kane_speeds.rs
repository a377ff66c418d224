//! Kane's method with independent speeds: for every constrained bundled problem, one row
//! per independent speed (and per drive, and per requested reaction component), no
//! constraint force among the unknowns unless asked for, and the q'' of Newton–Euler; the
//! rolling coin's three equations against a derivation by hand.

use mbd_tutor::equations::{friction_forces, normal_forces, Derivation, Method};
use mbd_tutor::numeric::{Compiled, System};
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::plan::Sum;
use mbd_tutor::problem::{load_file, Problem};
use mbd_tutor::symbolic::{eval, Symbol};

use crate::support::Lcg;

/// Whether a problem has a contact with Coulomb friction: there the friction forces work
/// with the slip rates and stay in the rows, and each normal force gets an auxiliary row.
fn has_friction(problem: &Problem) -> bool {
    problem.constraints.iter().any(|c| c.friction.is_some())
        || (problem.joints.iter())
            .chain(&problem.closures)
            .any(|j| j.friction.is_some())
}

/// Every bundled problem (and validation problem) with a closure, a constraint or a
/// prescribed coordinate.
fn constrained() -> Vec<(String, Problem)> {
    let mut paths: Vec<_> = ["problems", "problems/validation"]
        .iter()
        .flat_map(|dir| std::fs::read_dir(dir).expect("problems/").flatten())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    paths.sort();
    let list: Vec<(String, Problem)> = paths
        .iter()
        .map(|p| (p.display().to_string(), load_file(p).expect("valid")))
        .filter(|(_, problem)| {
            !problem.closures.is_empty()
                || !problem.constraints.is_empty()
                || problem.coordinates.iter().any(|c| c.motion.is_some())
        })
        .collect();
    assert!(list.len() >= 11, "only {} constrained problems", list.len());
    assert!(
        list.iter().filter(|(_, p)| has_friction(p)).count() >= 6,
        "too few constrained problems with friction"
    );
    list
}

fn generalized_rows(derivation: &Derivation) -> usize {
    derivation
        .rows
        .iter()
        .filter(|r| matches!(r.sum, Sum::Generalized { .. }))
        .count()
}

/// The reaction components of the requested sites that an auxiliary speed brings in: every
/// one but a friction force (its stick row or sliding law gives it).
fn requested_components(derivation: &Derivation) -> Vec<Symbol> {
    let model = &derivation.model;
    let friction = friction_forces(model);
    let sites = &model.problem.find_reactions;
    let asked = mbd_tutor::mechanics::reaction_unknowns(model, sites);
    asked
        .into_iter()
        .filter(|u| !friction.contains(u))
        .collect()
}

/// Kane's plan: a row per independent speed, per drive, per requested component and per
/// normal force at a rough contact; no unknown but the q'', those components and forces,
/// the friction forces and the drives; and in the rows of the independent speeds no force
/// but friction.
fn check_plan(name: &str, kane: &Derivation) {
    let speeds = kane
        .dependent_speeds
        .as_ref()
        .unwrap_or_else(|| panic!("{name}: no independent speeds"));
    let n = kane.model.problem.coordinates.len();
    let drives = speeds.prescribed.len();
    let mut forces = requested_components(kane);
    for normal in normal_forces(&kane.model) {
        if !forces.contains(&normal) {
            forces.push(normal);
        }
    }
    let friction = friction_forces(&kane.model);
    assert_eq!(
        generalized_rows(kane),
        speeds.independent.len() + drives + forces.len(),
        "{name}: Kane's rows"
    );
    assert_eq!(
        kane.system.unknowns.len(),
        n + drives + forces.len() + friction.len(),
        "{name}: unknowns {:?}",
        kane.system.unknowns
    );
    for row in kane.rows.iter().take(speeds.independent.len()) {
        assert!(
            row.unknowns
                .iter()
                .all(|u| matches!(u, Symbol::Coord(_, 2)) || friction.contains(u)),
            "{name}: a constraint force in {:?}: {:?}",
            row.sum,
            row.unknowns
        );
    }
}

/// Kane's q'' (and reactions and drives) against Newton–Euler's at assembled states near
/// the initial one.
fn check_numbers(name: &str, problem: &Problem, kane: &Derivation) {
    let newton =
        Compiled::new(&derive(problem, Method::NewtonEuler, Purpose::Rows).expect("derives"));
    let kane = Compiled::new(kane);
    let mut random = Lcg(11);
    let mut checked = 0;
    for _ in 0..6 {
        let (mut q, mut rates) = random.state_near(problem, 0.2);
        let t = 0.3 * (random.next() + 1.0);
        if newton.assemble(t, &mut q, &mut rates).is_err() {
            continue;
        }
        let Ok(reference) = newton.solve(t, &q, &rates) else {
            continue;
        };
        let ours = kane
            .solve(t, &q, &rates)
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        let close = |a: f64, b: f64, scale: f64| (a - b).abs() <= 1e-9 * scale.max(1.0);
        let scale = reference
            .accelerations
            .iter()
            .fold(0.0f64, |m, x| m.max(x.abs()));
        for (a, b) in reference.accelerations.iter().zip(&ours.accelerations) {
            assert!(close(*a, *b, scale), "{name}: q'' {b}, Newton–Euler {a}");
        }
        for ((joint, f1, m1), (_, f2, m2)) in reference.reactions.iter().zip(&ours.reactions) {
            let scale = f1.iter().chain(m1).fold(0.0f64, |m, x| m.max(x.abs()));
            for (a, b) in f1.iter().chain(m1).zip(f2.iter().chain(m2)) {
                assert!(
                    close(*a, *b, scale),
                    "{name}: reaction at {joint}: {b}, {a}"
                );
            }
        }
        for ((coordinate, a), (_, b)) in reference.drives.iter().zip(&ours.drives) {
            assert!(
                close(*a, *b, a.abs()),
                "{name}: drive {coordinate}: {b}, {a}"
            );
        }
        checked += 1;
    }
    assert!(checked >= 3, "{name}: too few assembled states");
}

#[test]
fn kane_has_one_row_per_independent_speed_and_per_requested_component() {
    for (name, problem) in constrained() {
        let kane =
            derive(&problem, Method::Kane, Purpose::Rows).unwrap_or_else(|e| panic!("{name}: {e}"));
        check_plan(&name, &kane);
        check_numbers(&name, &problem, &kane);
    }
}

#[test]
fn kane_without_requested_reactions_has_only_the_accelerations_and_drives_as_unknowns() {
    for (name, mut problem) in constrained() {
        problem.find_reactions.clear();
        let kane =
            derive(&problem, Method::Kane, Purpose::Rows).unwrap_or_else(|e| panic!("{name}: {e}"));
        check_plan(&name, &kane);
        let speeds = kane.dependent_speeds.as_ref().expect("speeds");
        let n = problem.coordinates.len();
        let rough = friction_forces(&kane.model).len() + normal_forces(&kane.model).len();
        assert_eq!(
            kane.system.unknowns.len(),
            n + speeds.prescribed.len() + rough
        );
        check_numbers(&name, &problem, &kane);
    }
}

/// The rolling disc of Kane and Levinson (Dynamics: Theory and Applications, 1985), by
/// hand: with `b₁` along the disc's plane horizontally, `b₂` its axle and `b₃` from the
/// contact P to the centre C, `ω = w₁ b₁ + w₂ b₂ + w₃ b₃` with `w₁ = θ'`,
/// `w₂ = φ' + ψ' sin θ`, `w₃ = ψ' cos θ`; the frame B of b turns with
/// `Ω = w₁ b₁ + w₃ tan θ b₂ + w₃ b₃`; rolling gives `v^C = R (w₂ b₁ − w₁ b₂)`. The moment of
/// momentum about the contact point, `Ḣ_C + r^{PC} × m a^C = r^{PC} × m g`, in B's unit
/// vectors is three equations in `w'`, from which `ψ''`, `θ''`, `φ''`.
fn rolling_disc_by_hand(m: f64, r: f64, g: f64, theta: f64, rates: [f64; 3]) -> [f64; 3] {
    let [psi_d, theta_d, phi_d] = rates;
    let (s, c) = theta.sin_cos();
    let (i, j) = (m * r * r / 4.0, m * r * r / 2.0);
    let w = [theta_d, phi_d + psi_d * s, psi_d * c];
    let big_omega = [w[0], w[2] * s / c, w[2]];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    // Each equation is linear in w': its coefficients (a column per w'_k) and the rest.
    // v^C = R (w₂ b₁ − w₁ b₂): a^C = R (w₂' b₁ − w₁' b₂) + Ω × v^C.
    let v = [r * w[1], -r * w[0], 0.0];
    let a_rest = cross(big_omega, v);
    let h = [i * w[0], j * w[1], i * w[2]];
    let h_rest = cross(big_omega, h);
    let arm = [0.0, 0.0, r];
    // Gravity: −m g N.z with N.z = sin θ b₂ + cos θ b₃.
    let weight = [0.0, -m * g * s, -m * g * c];
    let moment = cross(arm, weight);
    let rest_of = |k: usize| h_rest[k] + m * cross(arm, a_rest)[k] - moment[k];
    // Columns: ∂/∂w'_k of Ḣ + r × m a.
    let column = |k: usize| {
        let dh = match k {
            0 => [i, 0.0, 0.0],
            1 => [0.0, j, 0.0],
            _ => [0.0, 0.0, i],
        };
        let da = match k {
            0 => [0.0, -r, 0.0],
            1 => [r, 0.0, 0.0],
            _ => [0.0, 0.0, 0.0],
        };
        let ra = cross(arm, da);
        [dh[0] + m * ra[0], dh[1] + m * ra[1], dh[2] + m * ra[2]]
    };
    let a = nalgebra::Matrix3::from_columns(&[
        nalgebra::Vector3::from(column(0)),
        nalgebra::Vector3::from(column(1)),
        nalgebra::Vector3::from(column(2)),
    ]);
    let b = -nalgebra::Vector3::new(rest_of(0), rest_of(1), rest_of(2));
    let w_dot = a.lu().solve(&b).expect("regular");
    // w₁' = θ'', w₂' = φ'' + ψ'' sin θ + ψ' θ' cos θ, w₃' = ψ'' cos θ − ψ' θ' sin θ.
    let theta_dd = w_dot[0];
    let psi_dd = (w_dot[2] + psi_d * theta_d * s) / c;
    let phi_dd = w_dot[1] - psi_dd * s - psi_d * theta_d * c;
    [psi_dd, theta_dd, phi_dd]
}

#[test]
fn the_rolling_coin_has_kane_and_levinsons_three_equations() {
    let problem = load_file(std::path::Path::new("problems/rolling-coin.json")).expect("valid");
    let kane = derive(&problem, Method::Kane, Purpose::Rows).expect("derives");
    let speeds = kane.dependent_speeds.as_ref().expect("independent speeds");
    let names = |list: &[usize]| -> Vec<String> {
        let mut names: Vec<String> = list
            .iter()
            .map(|&i| problem.coordinates[i].name.clone())
            .collect();
        names.sort();
        names
    };
    assert_eq!(names(&speeds.independent), ["phi", "psi", "theta"]);
    assert_eq!(names(&speeds.dependent), ["x", "y", "z"]);
    let mut plain = problem.clone();
    plain.find_reactions.clear();
    let reduced = derive(&plain, Method::Kane, Purpose::Rows).expect("derives");
    assert_eq!(generalized_rows(&reduced), 3);
    let compiled = Compiled::new(&reduced);
    let index = |name: &str| {
        problem
            .coordinates
            .iter()
            .position(|c| c.name == name)
            .expect("coordinate")
    };
    let (m, r, g) = (0.5, 0.1, 9.81);
    let mut random = Lcg(3);
    for _ in 0..8 {
        let mut q: Vec<f64> = problem.initial_coordinates();
        let mut rates = vec![0.0; q.len()];
        q[index("theta")] = 0.3 + 0.8 * random.next();
        q[index("psi")] = 2.0 * random.next();
        q[index("phi")] = 2.0 * random.next();
        for name in ["psi", "theta", "phi"] {
            rates[index(name)] = 5.0 * random.next();
        }
        compiled
            .assemble(0.0, &mut q, &mut rates)
            .expect("assembles");
        let ours = compiled.solve(0.0, &q, &rates).expect("solves");
        let theirs = rolling_disc_by_hand(
            m,
            r,
            g,
            q[index("theta")],
            [
                rates[index("psi")],
                rates[index("theta")],
                rates[index("phi")],
            ],
        );
        for (name, expected) in ["psi", "theta", "phi"].iter().zip(theirs) {
            let got = ours.accelerations[index(name)];
            assert!(
                (got - expected).abs() <= 1e-9 * expected.abs().max(1.0),
                "{name}'' = {got}, by hand {expected}"
            );
        }
        // Each of the three rows holds at the hand's accelerations: the same equations.
        let mut values = reduced.model.values_at(0.0, &q, &rates);
        for (k, name) in ["psi", "theta", "phi"].iter().enumerate() {
            values.set(Symbol::Coord((*name).into(), 2), theirs[k]);
        }
        for (name, value) in ["x", "y", "z"]
            .iter()
            .map(|n| (n, ours.accelerations[index(n)]))
        {
            values.set(Symbol::Coord((*name).into(), 2), value);
        }
        for row in reduced.rows.iter().take(3) {
            let residual = eval(&row.expression, &values);
            assert!(residual.abs() < 1e-9, "{:?}: residual {residual}", row.sum);
        }
    }
}

/// With friction, Kane's rows are those of the independent speeds (the friction forces work
/// in them) and one auxiliary row per normal force; no reason to keep the constraint forces
/// is given. The bowling ball: ẋ and θ' give m ẍ = F and (2/5) m R² θ̈ = R F, the normal
/// force's row N − m g − m ÿ = 0, three rows.
#[test]
fn with_friction_kane_takes_the_independent_speeds_and_an_auxiliary_row_per_normal_force() {
    let mut seen = 0;
    for (name, problem) in constrained() {
        if !has_friction(&problem) {
            continue;
        }
        seen += 1;
        let kane =
            derive(&problem, Method::Kane, Purpose::Rows).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(kane.kept_forces.is_none(), "{name}: {:?}", kane.kept_forces);
        for normal in normal_forces(&kane.model) {
            assert!(
                kane.rows
                    .iter()
                    .skip(
                        kane.dependent_speeds
                            .as_ref()
                            .expect("speeds")
                            .independent
                            .len()
                    )
                    .any(|r| matches!(r.sum, Sum::Generalized { .. })
                        && r.unknowns.contains(&normal)),
                "{name}: no auxiliary row brings in {normal:?}"
            );
        }
    }
    assert!(seen >= 6, "only {seen} constrained problems with friction");
    let ball = load_file(std::path::Path::new("problems/bowling-ball.json")).expect("valid");
    let kane = derive(&ball, Method::Kane, Purpose::Rows).expect("derives");
    assert_eq!(generalized_rows(&kane), 3);
}

/// A disc inside a cylinder with its contact written by hand as constraint entries, the
/// spin's coefficient `r (x² + y²)²/(R − r)⁴` (which is r only on the motion, a relation
/// no entry states): θ' = C x' would be a fraction within fractions, so C is named and
/// evaluated at each state; Kane's rows are still one per independent speed, and agree.
#[test]
fn where_c_would_not_read_well_it_is_evaluated_at_each_state_and_agrees() {
    let name = "tests/kane_speeds/disc-by-constraint-entries.json";
    let problem = load_file(std::path::Path::new(name)).expect("valid");
    let kane =
        derive(&problem, Method::Kane, Purpose::Rows).unwrap_or_else(|e| panic!("{name}: {e}"));
    let speeds = kane.dependent_speeds.as_ref().expect("u_D = C u_I");
    assert!(speeds.at_each_state, "{name}: C written out");
    assert_eq!(kane.kept_forces, None);
    assert_eq!(generalized_rows(&kane), speeds.independent.len());
    check_numbers(name, &problem, &kane);
}

/// The Whipple bicycle: six dependent rates coupled through both contacts, C evaluated at
/// each state; three rows, for the lean, the rear wheel and the steer, and their q'' those
/// of Newton–Euler's rows, which keep every contact force.
#[test]
fn the_bicycle_takes_its_three_independent_speeds() {
    let name = "problems/validation/whipple-bicycle.json";
    let problem = load_file(std::path::Path::new(name)).expect("valid");
    let kane =
        derive(&problem, Method::Kane, Purpose::Rows).unwrap_or_else(|e| panic!("{name}: {e}"));
    let speeds = kane.dependent_speeds.as_ref().expect("u_D = C u_I");
    assert!(speeds.at_each_state);
    let names: Vec<&str> = (speeds.independent.iter())
        .map(|&i| problem.coordinates[i].name.as_str())
        .collect();
    assert_eq!(names, ["phi", "thetaR", "delta"]);
    assert_eq!(generalized_rows(&kane), 3);
    check_numbers(name, &problem, &kane);
}

/// The slider-crank's light connecting rod is a two-force member: Kane's rows bring in the
/// force at its closure Q as one unknown along the rod, the tension T^Q, through one
/// auxiliary speed; the crank pin P's two components asked for come as before.
#[test]
fn a_light_rod_s_closure_carries_its_tension_alone() {
    let name = "problems/slider-crank-light-rod.json";
    let problem = load_file(std::path::Path::new(name)).expect("valid");
    let kane =
        derive(&problem, Method::Kane, Purpose::Rows).unwrap_or_else(|e| panic!("{name}: {e}"));
    let unknowns = unknowns_tex(&kane);
    assert!(unknowns.contains(&"T^{Q}".to_string()), "{unknowns:?}");
    assert!(
        !unknowns.iter().any(|u| u.starts_with("F^{Q}")),
        "{unknowns:?}"
    );
    // q̈₁'s row, the tension's, and P's two components.
    assert_eq!(generalized_rows(&kane), 4);
    check_numbers(name, &problem, &kane);
    // The Motion Law takes the tension as the unknown too: the crank and rod about O, the
    // piston along its slide, the loop's two rows and the rod's two for P, and no row
    // of the rod's moments, which would say only that nothing acts across it.
    let motion_law =
        derive(&problem, Method::MotionLaw, Purpose::Rows).unwrap_or_else(|e| panic!("{e}"));
    let unknowns = unknowns_tex(&motion_law);
    assert_eq!(
        unknowns,
        [
            "\\ddot{q}_{1}",
            "\\ddot{q}_{2}",
            "\\ddot{x}",
            "T^{Q}",
            "F^{P}_{x}",
            "F^{P}_{y}"
        ],
        "{unknowns:?}"
    );
}

/// The unknowns of `derivation`'s system as the handout writes them: `T^{Q}`, `F^{P}_{x}`.
fn unknowns_tex(derivation: &Derivation) -> Vec<String> {
    (derivation.system.unknowns.iter())
        .map(|u| mbd_tutor::symbolic::latex(&mbd_tutor::symbolic::Expr::sym(u.clone())))
        .collect()
}
