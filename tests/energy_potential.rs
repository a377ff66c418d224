//! A force with a potential, the gas law of slider-crank-flywheel, is in V with gravity:
//! its potential is the statement's, step 6 keeps E = T + V constant rather than counting
//! the gas's work, the Answers give T and each part of V, and Lagrange's Q_r leave it out.
//! A force of constant size is still an applied load that does work.

use crate::support::{between, column, markdown_handout, simulate};
use mbd_tutor::equations::force_potential;
use mbd_tutor::mechanics::Model;
use mbd_tutor::problem::load_file;
use mbd_tutor::symbolic::eval;

#[test]
fn the_gas_has_the_potential_the_statement_gives() {
    let problem = load_file(&crate::support::problem("slider-crank-flywheel")).expect("loads");
    let model = Model::build(&problem).expect("builds");
    let v = force_potential(&model, 0).expect("the gas law has a potential");
    let x = (0..problem.coordinates.len())
        .find(|&i| problem.coordinates[i].name == "x")
        .expect("x");
    let mut values = model.values.clone();
    // The statement's V = F0 e^1.4 (h − x)^(−0.4)/0.4, F0 = 100 N, e = 0.03 m, h = 0.48 m.
    for at in [0.30, 0.40, 0.45] {
        values.set(problem.coordinate_symbol(x, 0), at);
        let want = 100.0 * 0.03f64.powf(1.4) * (0.48 - at).powf(-0.4) / 0.4;
        let got = eval(&v, &values);
        assert!(
            (got - want).abs() < 1e-12 * want,
            "x = {at}: {got} against {want}"
        );
    }
}

#[test]
fn a_force_of_constant_size_has_no_potential_here() {
    let problem = load_file(&crate::support::problem("disc-on-cart")).expect("loads");
    let model = Model::build(&problem).expect("builds");
    for i in 0..problem.loads.len() {
        assert!(force_potential(&model, i).is_none(), "load {i}");
    }
}

#[test]
fn the_total_energy_with_the_gas_stays_constant() {
    let (columns, rows) = simulate("slider-crank-flywheel", &[]);
    let (total, potential) = (column(&columns, "total"), column(&columns, "potential"));
    let (low, high) = (rows.iter()).fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), r| {
        (l.min(r[potential]), h.max(r[potential]))
    });
    // Gravity alone swings V by about 0.6 J; with the gas V runs over several joules.
    assert!(high - low > 3.0, "V ranges over {} J", high - low);
    let first = rows[0][total];
    for r in &rows {
        assert!(
            (r[total] - first).abs() < 1e-5,
            "t = {}: E − E(0) = {}",
            r[0],
            r[total] - first
        );
    }
}

#[test]
fn step_six_and_the_answers_put_the_gas_in_v() {
    for method in ["kane", "lagrange", "newton-euler", "motion-law"] {
        let text = markdown_handout("slider-crank-flywheel", method);
        let step6 = between(&text, "## Step 6", "## Answers");
        assert!(
            !step6.contains("does work on the system, and"),
            "{method}: {step6}"
        );
        assert!(
            step6.contains("has a potential, so its total energy"),
            "{method}: {step6}"
        );
        let answers = between(&text, "## Answers", "\u{0}");
        // T, V of gravity and V of the gas at the start, which add up to E = 19.3716 J.
        let value = |name: &str| -> f64 {
            let after = answers
                .split(&format!("{name} = "))
                .nth(1)
                .unwrap_or_else(|| panic!("{method}: no {name} in {answers}"));
            let number = after[..after.find("\\ \\mathrm{J}").expect("J")]
                .rsplit("= ")
                .next()
                .unwrap_or_default();
            number.trim().parse().expect("a number")
        };
        let (t, g, gas) = (value("T"), value("V_{g}"), value("V_{F}"));
        assert!((t - 12.405).abs() < 1e-3, "{method}: T = {t}");
        assert!((g - 0.287).abs() < 1e-3, "{method}: V_g = {g}");
        assert!((gas - 6.680).abs() < 1e-3, "{method}: V_gas = {gas}");
        assert!(
            (t + g + gas - 19.3716).abs() < 1e-3,
            "{method}: the parts add up to E"
        );
        assert!(answers.contains("stays constant"), "{method}: {answers}");
    }
}

#[test]
fn lagranges_generalized_forces_leave_the_gas_to_v() {
    let text = markdown_handout("slider-crank-flywheel", "lagrange");
    let step2 = between(&text, "## Step 2", "## Step 3");
    let v = step2.split("V = ").nth(1).expect("V");
    assert!(v.split("$$").next().unwrap_or("").contains("F_{0}"), "{v}");
}
