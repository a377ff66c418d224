//! A closure's rows as the vector loop's components: the four-bar's rows at R against the
//! acceleration loop written out by hand here, and the handout showing the loop first.

use mbd_tutor::equations::Method;
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::plan::Sum;
use mbd_tutor::problem::load_file;
use mbd_tutor::symbolic::{eval, Symbol, Values};

/// The four-bar (crank a at angle q1 from N.x, coupler b at q1 + q2, rocker c at q3 from the
/// ground pin Q): the acceleration of R as a point of C less that as a point of B, along
/// B's axes x and y. By the pins: a^{R_C} = c q̈3 ĉ_y − c q̇3² ĉ_x and
/// a^{R_B} = a q̈1 â_y − a q̇1² â_x + b (q̈1 + q̈2) b̂_y − b (q̇1 + q̇2)² b̂_x.
fn loop_by_hand(v: &Values) -> [f64; 2] {
    let c = |n: &str| v.get(&Symbol::Const(n.into()));
    let q = |n: &str, order: u8| v.get(&Symbol::Coord(n.into(), order));
    let unit = |angle: f64| [angle.cos(), angle.sin()];
    let normal = |angle: f64| [-angle.sin(), angle.cos()];
    let (q1, q2, q3) = (q("q1", 0), q("q2", 0), q("q3", 0));
    let (w1, w2, w3) = (q("q1", 1), q("q2", 1), q("q3", 1));
    let (e1, e2, e3) = (q("q1", 2), q("q2", 2), q("q3", 2));
    let gap: [f64; 2] = std::array::from_fn(|k| {
        let on_c = c("c") * e3 * normal(q3)[k] - c("c") * w3 * w3 * unit(q3)[k];
        let on_b = c("a") * e1 * normal(q1)[k] - c("a") * w1 * w1 * unit(q1)[k]
            + c("b") * (e1 + e2) * normal(q1 + q2)[k]
            - c("b") * (w1 + w2).powi(2) * unit(q1 + q2)[k];
        on_c - on_b
    });
    let (bx, by) = (unit(q1 + q2), normal(q1 + q2));
    [
        gap[0] * bx[0] + gap[1] * bx[1],
        gap[0] * by[0] + gap[1] * by[1],
    ]
}

#[test]
fn the_four_bars_closure_rows_are_its_acceleration_loop_along_the_couplers_axes() {
    let problem = load_file(&crate::support::problem("four-bar")).expect("problem");
    for method in Method::ALL {
        let derivation = derive(&problem, method, Purpose::Handout).expect("derivation");
        let rows: Vec<_> = derivation
            .rows
            .iter()
            .filter(|r| matches!(&r.sum, Sum::Constraint { name } if name.starts_with("R.F")))
            .map(|r| r.expression.clone())
            .collect();
        assert_eq!(rows.len(), 2, "{}: two rows at R", method.name());
        let mut random = crate::support::Lcg(11);
        for _ in 0..20 {
            let mut values = Values::new();
            for c in &problem.constants {
                values.set(Symbol::Const(c.name.as_str().into()), c.value);
            }
            for i in 0..problem.coordinates.len() {
                for order in 0..3 {
                    values.set(problem.coordinate_symbol(i, order), 3.0 * random.next());
                }
            }
            let hand = loop_by_hand(&values);
            for (row, hand) in rows.iter().zip(hand) {
                let got = eval(row, &values);
                let err = (got - hand).abs().min((got + hand).abs());
                assert!(
                    err <= 1e-12 * (1.0 + hand.abs()),
                    "{got} against {hand} by hand"
                );
            }
        }
    }
}

#[test]
fn the_handout_writes_the_loop_before_its_components() {
    let markdown = crate::support::explain("four-bar", &["--method", "motion-law"]);
    assert!(markdown.contains("{}^{N}\\mathbf{a}^{R_{C}} = {}^{N}\\mathbf{a}^{R_{B}}\\colon"));
    assert!(
        markdown.contains("The loop of row"),
        "the second component refers to the loop"
    );
}
