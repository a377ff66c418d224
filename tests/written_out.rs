//! The Motion Law's rows written out before "Simplified": each body's cross product and
//! inertia torque (moment rows) or `m a*` dotted term by term (force rows). The terms
//! written out, with the row's external forces, sum to the row as derived; and the double
//! pendulum's terms equal the cross products computed by hand.

use crate::support::{all_problems, explain, problem};
use mbd_tutor::equations::Method;
use mbd_tutor::plan::Sum;
use mbd_tutor::solution::written_out;
use mbd_tutor::symbolic::add;
use mbd_tutor::symbolic::{eval, Values};

/// Values of the unknowns of a row, arbitrary but not special.
fn unknown_value(i: usize) -> f64 {
    0.37 + 0.91 * i as f64 - 0.13 * (i * i) as f64
}

/// The values of every symbol a row may hold at the problem's initial state, with the
/// unknowns given arbitrary values.
fn values_at_start(derivation: &mbd_tutor::equations::Derivation) -> Values {
    let model = &derivation.model;
    let problem = model.problem;
    let q0: Vec<f64> = problem.coordinates.iter().map(|c| c.initial).collect();
    let rates0: Vec<f64> = problem.coordinates.iter().map(|c| c.rate).collect();
    let mut values = model.values_at(0.0, &q0, &rates0);
    let mut unknowns: Vec<_> = derivation.system.unknowns.clone();
    for row in &derivation.rows {
        unknowns.extend(row.unknowns.iter().cloned());
    }
    for (i, u) in unknowns.into_iter().enumerate() {
        values.set(u, unknown_value(i));
    }
    values
}

#[test]
fn the_written_terms_sum_to_each_row_of_every_bundled_problem() {
    let mut rows_written = 0;
    for path in all_problems() {
        let text = std::fs::read_to_string(&path).expect("readable");
        let Ok(p) = mbd_tutor::problem::load(&text) else {
            continue;
        };
        let Ok(derivation) = mbd_tutor::pipeline::derive(
            &p,
            Method::MotionLaw,
            mbd_tutor::pipeline::Purpose::Handout,
        ) else {
            continue;
        };
        let values = values_at_start(&derivation);
        for (i, row) in derivation.rows.iter().enumerate() {
            let Some(written) = written_out(&derivation, row) else {
                continue;
            };
            rows_written += 1;
            let rebuilt = add([
                row.groups.contact.clone(),
                row.groups.distance.clone(),
                add(written.terms.clone()),
            ]);
            // Against the row as formed; and against the row as simplified where the
            // initial values need no assembly (off a position constraint the simplified
            // row may differ by terms that vanish on it).
            let mut rows = vec![row.groups.total()];
            if derivation.model.constraints.dependent.is_empty() {
                rows.push(row.expression.clone());
            }
            for whole in rows {
                let (got, want) = (eval(&rebuilt, &values), eval(&whole, &values));
                let scale = 1.0 + want.abs() + eval(&row.groups.distance, &values).abs();
                assert!(
                    (got - want).abs() < 1e-9 * scale,
                    "{} row {}: written out {got}, the row {want}",
                    path.display(),
                    i + 1
                );
            }
            assert!(written.tex.starts_with("\\begin{aligned}"));
        }
    }
    assert!(rows_written > 40, "only {rows_written} rows written out");
}

/// The 2-D cross product's component along n̂_z.
fn cross_z(u: [f64; 2], v: [f64; 2]) -> f64 {
    u[0] * v[1] - u[1] * v[0]
}

#[test]
fn the_double_pendulums_moment_row_about_o_is_written_body_by_body() {
    // By hand, in N's unit vectors with â_x = (c1, s1), â_y = (−s1, c1) and b̂ likewise at
    // q1 + q2: r^{OA*} = −(L1/2) â_y, a^{A*} = (L1/2)(q1'' â_x + q1'² â_y);
    // r^{OB*} = −L1 â_y − (L2/2) b̂_y, a^{B*} = L1 (q1'' â_x + q1'² â_y)
    // + (L2/2)((q1'' + q2'') b̂_x + (q1' + q2')² b̂_y). The row about O along n̂_z has
    // −(r × m a*)·n̂_z and −I α for each rod, I = m L²/12.
    let text = std::fs::read_to_string(problem("double-pendulum-rods")).expect("readable");
    let p = mbd_tutor::problem::load(&text).expect("valid");
    let derivation =
        mbd_tutor::pipeline::derive(&p, Method::MotionLaw, mbd_tutor::pipeline::Purpose::Handout)
            .expect("derives");
    let row = derivation
        .rows
        .iter()
        .find(|r| {
            r.free_body.len() == 2 && matches!(&r.sum, Sum::Moment { point, .. } if point == "O")
        })
        .expect("a moment row of A + B about O");
    let written = written_out(&derivation, row).expect("written out");
    let values = values_at_start(&derivation);
    let (m1, l1, m2, l2) = (1.2, 0.6, 0.8, 0.4);
    let (q1, q2, u1, u2) = (0.7, -0.4, 1.0, -0.5);
    let index = |name: &str| {
        p.coordinates
            .iter()
            .position(|c| c.name == name)
            .expect("q")
    };
    let qdd = |name: &str| values.get(&p.coordinate_symbol(index(name), 2));
    let (a1, a2) = (qdd("q1"), qdd("q2"));
    let unit = |angle: f64| ([angle.cos(), angle.sin()], [-angle.sin(), angle.cos()]);
    let ((ax, ay), (bx, by)) = (unit(q1), unit(q1 + q2));
    let comb = |terms: &[(f64, [f64; 2])]| {
        terms
            .iter()
            .fold([0.0, 0.0], |s, (k, v)| [s[0] + k * v[0], s[1] + k * v[1]])
    };
    let r_a = comb(&[(-l1 / 2.0, ay)]);
    let a_a = comb(&[(l1 / 2.0 * a1, ax), (l1 / 2.0 * u1 * u1, ay)]);
    let r_b = comb(&[(-l1, ay), (-l2 / 2.0, by)]);
    let a_b = comb(&[
        (l1 * a1, ax),
        (l1 * u1 * u1, ay),
        (l2 / 2.0 * (a1 + a2), bx),
        (l2 / 2.0 * (u1 + u2) * (u1 + u2), by),
    ]);
    let by_hand = [
        -m1 * cross_z(r_a, a_a),
        -m1 * l1 * l1 / 12.0 * a1,
        -m2 * cross_z(r_b, a_b),
        -m2 * l2 * l2 / 12.0 * (a1 + a2),
    ];
    assert_eq!(written.terms.len(), by_hand.len());
    for (k, (term, want)) in written.terms.iter().zip(by_hand).enumerate() {
        let got = eval(term, &values);
        assert!(
            (got - want).abs() < 1e-12,
            "term {k}: {got} against {want} by hand"
        );
    }
    // The handout writes them between the row as formed and its simplified form.
    let handout = explain(
        "double-pendulum-rods",
        &["--method", "motion-law", "--format", "markdown"],
    );
    let step5 = &handout[handout.find("## Step 5").expect("step 5")..];
    let (written_at, simplified_at) = (
        step5.find("Written out:").expect("written out"),
        step5.find("Simplified:").expect("simplified"),
    );
    assert!(written_at < simplified_at);
    assert!(step5.contains("r_{x}\\, (m a)_{y} - r_{y}\\, (m a)_{x}"));
    // With the sign the row holds it: the inertia force is −m a.
    assert!(
        step5.contains("-(r_{x}\\, (m a)_{y}") || step5.contains("-\\left(r_{x}\\, (m a)_{y}"),
        "{step5}"
    );
}

/// The rolling coin's moment row has components with `√(c²)` as the model writes them: the
/// row prints them by the initial sign, and its written-out lines are printed alike.
#[test]
fn a_row_with_roots_of_squares_is_written_out_by_the_initial_sign() {
    let text = explain("rolling-coin", &["--format", "markdown"]);
    let step5 = &text[text.find("## Step 5").expect("step 5")..];
    let written = step5.find("Written out:").expect("a row written out");
    let block = &step5[written..];
    let block = &block[..block.find("\n$$\n\n").expect("its display")];
    assert!(block.contains("\\times"), "{block}");
    assert!(!block.contains("\\sqrt"), "{block}");
}
