//! The parts of `F̃^*_r` against the method's numbers and a hand derivation.

use super::{inertia_dot_products, parts, Elimination, Part};
use crate::equations::{Derivation, Method, Request, Rows};
use crate::mechanics::Form;
use crate::numeric::{Compiled, System};
use crate::plan::{Groups, Sum};
use crate::symbolic::{eval, roots_of_squares, Expr, Values};
use nalgebra::{DMatrix, DVector};

/// Kane's rows as the handout writes them, from the equations' own entry.
fn derivation_of(problem: &crate::problem::Problem) -> Option<Derivation<'_>> {
    let request = Request {
        form: Form::Handout,
        rows: Rows::Formed,
        states: &[],
    };
    crate::equations::derive(problem, Method::Kane, request).ok()
}

/// Kane's row of independent speed `r` (1-based).
fn row_groups<'d>(derivation: &'d Derivation, r: usize) -> &'d Groups {
    let row = derivation
        .rows
        .iter()
        .filter(|row| matches!(row.sum, Sum::Generalized { .. }))
        .nth(r - 1)
        .expect("the row of the speed");
    &row.groups
}

/// The initial state with the dependent rates that the constraints give and every q̈ and
/// unknown force as the method's system gives them there.
fn solved_state(derivation: &Derivation) -> Values {
    let model = &derivation.model;
    let problem = model.problem;
    let mut q0: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
    let mut rates0: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    Compiled::new(derivation)
        .assemble(0.0, &mut q0, &mut rates0)
        .expect("the constraints are met at the start");
    let mut values = model.values_at(0.0, &q0, &rates0);
    let speeds = derivation
        .dependent_speeds
        .as_ref()
        .expect("dependent speeds");
    let rates = speeds.dependent_rates(model);
    for (s, &d) in speeds.dependent.iter().enumerate() {
        let value = eval(&rates[s], &values);
        values.set(problem.coordinate_symbol(d, 1), value);
    }
    let system = &derivation.system;
    let n = system.unknowns.len();
    let a = DMatrix::from_fn(n, n, |i, j| eval(&system.a[i][j], &values));
    let b = DVector::from_fn(n, |i, _| eval(&system.b[i], &values));
    let x = a
        .lu()
        .solve(&b)
        .expect("the system is regular at the start");
    for (unknown, value) in system.unknowns.iter().zip(x.iter()) {
        values.set(unknown.clone(), *value);
    }
    values
}

fn sum(parts: &[Part], of: impl Fn(&Part) -> &Expr, values: &Values) -> f64 {
    parts.iter().map(|p| eval(of(p), values)).sum()
}

/// Every bundled problem with dependent speeds written in symbols: at the initial state,
/// with the q̈ the method's system gives, each row's `F̃_r` plus its bodies' parts of
/// `F̃^*_r` is zero, both as formed (the dependent q̈ in them) and with the dependent q̈
/// replaced; and the parts are printed for the problems a course works by hand.
#[test]
fn the_parts_satisfy_the_rows_at_the_methods_accelerations() {
    let mut checked = Vec::new();
    let mut paths: Vec<_> = std::fs::read_dir("problems")
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    paths.sort();
    for path in paths {
        let text = std::fs::read_to_string(&path).unwrap();
        let problem = crate::problem::load(&text).unwrap();
        let Some(derivation) = derivation_of(&problem) else {
            continue;
        };
        let model = &derivation.model;
        let Some(speeds) = derivation
            .dependent_speeds
            .as_ref()
            .filter(|s| !s.at_each_state && model.order.len() <= super::MOST_BODIES)
        else {
            continue;
        };
        let sign = crate::solution::tex::initial_sign(model);
        let shown = |e: &Expr| roots_of_squares(e, &sign);
        let values = solved_state(&derivation);
        for r in 1..=speeds.independent.len() {
            let groups = row_groups(&derivation, r);
            let elimination = Elimination::new(model, speeds, groups).unwrap();
            let parts = parts(&derivation, speeds, r, &elimination, &shown);
            let active = eval(&groups.contact, &values) + eval(&groups.distance, &values);
            let scale = 1.0 + active.abs();
            let formed = active + sum(&parts, |p| &p.formed, &values);
            let term = active + sum(&parts, |p| &p.term, &values);
            let name = path.display();
            assert!(formed.abs() < 1e-6 * scale, "{name} r = {r}: {formed}");
            assert!(term.abs() < 1e-6 * scale, "{name} r = {r}: {term}");
            let block = inertia_dot_products(&derivation, r, groups, "", &shown);
            checked.push((path.file_stem().unwrap().to_owned(), r, block.is_some()));
        }
    }
    for name in [
        "disc-on-cart",
        "rolling-coin",
        "slider-crank-light-rod",
        "four-bar",
    ] {
        let rows: Vec<_> = checked.iter().filter(|(n, ..)| n == name).collect();
        assert!(!rows.is_empty(), "{name} has dependent speeds");
        assert!(
            rows.iter().all(|(.., shown)| *shown),
            "{name} printed: {rows:?}"
        );
    }
}

/// The disc on the cart (problems/disc-on-cart.json), by hand: with u₂ = ṡ, θ̇ = −ṡ/R, so
/// `ṽ^{D*}_2 = n̂_x`, `ω̃^D_2 = −(1/R) d̂_z`; `a^{D*} = (ẍ + s̈) n̂_x`, `α^D = θ̈ d̂_z` and
/// `I = m R²/2`, so `F̃^*_{2,D} = −m (ẍ + s̈) + (m R/2) θ̈`, and with `θ̈ = −s̈/R`,
/// `−m ẍ − (3m/2) s̈`. The cart does not move with u₂.
#[test]
fn the_discs_part_of_the_second_row_is_as_by_hand() {
    let text = std::fs::read_to_string("problems/disc-on-cart.json").unwrap();
    let problem = crate::problem::load(&text).unwrap();
    let derivation = derivation_of(&problem).unwrap();
    let model = &derivation.model;
    let speeds = derivation.dependent_speeds.as_ref().unwrap();
    let groups = row_groups(&derivation, 2);
    let elimination = Elimination::new(model, speeds, groups).unwrap();
    let parts = parts(&derivation, speeds, 2, &elimination, &|e: &Expr| e.clone());
    assert_eq!(parts.len(), 1, "the disc alone moves with ṡ");
    let (m, r) = (2.0, 0.1);
    let (xdd, sdd, thdd) = (0.7, -1.3, 4.1);
    let mut values = crate::mechanics::sample_states(model).swap_remove(0);
    let index = |name: &str| {
        problem
            .coordinates
            .iter()
            .position(|c| c.name == name)
            .unwrap()
    };
    values.set(problem.coordinate_symbol(index("x"), 2), xdd);
    values.set(problem.coordinate_symbol(index("s"), 2), sdd);
    values.set(problem.coordinate_symbol(index("theta"), 2), thdd);
    values.set(problem.coordinate_symbol(index("h"), 2), 0.0);
    let formed = eval(&parts[0].formed, &values);
    let by_hand = -m * (xdd + sdd) + m * r / 2.0 * thdd;
    assert!((formed - by_hand).abs() < 1e-12, "{formed} vs {by_hand}");
    let term = eval(&parts[0].term, &values);
    let by_hand = -m * xdd - 1.5 * m * sdd;
    assert!((term - by_hand).abs() < 1e-12, "{term} vs {by_hand}");
}
