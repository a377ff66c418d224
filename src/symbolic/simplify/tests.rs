//! Identities one per line, each checked three ways: the exact expected form, numeric
//! equality with the input at random points, and the expected form being left alone.

use super::steps::{COS_DIFFERENCE, COS_SUM, PYTHAGORAS};
use super::{shortest_of, simplify, simplify_with, simplify_with_steps, Options};
use crate::symbolic::build::{add, cos, mul, sin};
use crate::symbolic::eval::{eval, Values};
use crate::symbolic::expr::{Expr, Symbol};

/// `q1`, `q2`, ... are coordinates, a name with primes is a rate, anything else a constant.
fn p(text: &str) -> Expr {
    crate::symbolic::parse::parse_scalar(text, |name| {
        name.starts_with('q') && name.len() > 1 && name[1..].chars().all(|c| c.is_ascii_digit())
    })
}

/// A small xorshift generator, so the points are the same on every run.
struct Random(u64);
impl Random {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Asserts that `a` and `b` agree at a few random points: coordinates and rates in
/// [-3, 3], constants in [0.5, 2.5] (positive, so square roots stay real).
fn assert_numerically_equal(a: &Expr, b: &Expr) {
    let mut symbols = Vec::new();
    a.for_each_symbol(&mut |s| symbols.push(s.clone()));
    b.for_each_symbol(&mut |s| symbols.push(s.clone()));
    symbols.sort();
    symbols.dedup();
    let mut random = Random(0x9e37_79b9_7f4a_7c15);
    for _ in 0..5 {
        let mut values = Values::new();
        for s in &symbols {
            let u = random.next();
            let value = if matches!(s, Symbol::Const(_)) {
                0.5 + 2.0 * u
            } else {
                6.0 * u - 3.0
            };
            values.set(s.clone(), value);
        }
        let (x, y) = (eval(a, &values), eval(b, &values));
        let scale = 1.0 + x.abs().max(y.abs());
        assert!((x - y).abs() <= 1e-9 * scale, "{a} = {x} but {b} = {y}");
    }
}

/// `input` simplifies to exactly `expected`, which is equal to it numerically and which
/// is itself left alone; every recorded step is an equality too.
fn check(input: &str, expected: &str) {
    let (e, want) = (p(input), p(expected));
    let got = simplify(&e);
    assert_eq!(got.to_string(), want.to_string(), "simplify({input})");
    assert_eq!(got, want, "simplify({input})");
    assert_numerically_equal(&e, &got);
    assert_eq!(simplify(&want), want, "simplify({expected}) changed it");
    let (with_steps, steps) = simplify_with_steps(&e);
    assert_eq!(
        with_steps, got,
        "recording steps changed the result of {input}"
    );
    for step in &steps {
        assert_numerically_equal(&step.before, &step.after);
    }
}

#[test]
fn pythagoras() {
    check("sin(q1)^2 + cos(q1)^2", "1");
    check(
        "m*L^2*sin(q1)^2*q1'^2 + m*L^2*cos(q1)^2*q1'^2",
        "m*L^2*q1'^2",
    );
    check("1 - sin(q1)^2", "cos(q1)^2");
    check("1 - cos(q1)^2", "sin(q1)^2");
    check("2*m - 2*m*sin(q1+q2)^2", "2*m*cos(q1+q2)^2");
    check("sin(q1)^2 + cos(q1)^2 + 1", "2");
    check("3*sin(q1)^2 + 3*cos(q1)^2 - 3", "0");
    // (sin² + cos²)² = 1, as the rolling coin's acceleration constraints hold it.
    check("2 - sin(q1)^4 - cos(q1)^4 - 2*sin(q1)^2*cos(q1)^2", "1");
    check(
        "R*q2'*(1 - sin(q1)^4 - cos(q1)^4 - 2*sin(q1)^2*cos(q1)^2)/cos(q2) + R",
        "R",
    );
    check("sin(q1)^4 - cos(q1)^4", "2*sin(q1)^2 - 1");
    check("L/2*sin(q2)^2*q1' + L/2*cos(q2)^2*q1' + g", "L/2*q1' + g");
    check("sin(q1)^3 + sin(q1)*cos(q1)^2", "sin(q1)");
    check("sin(q1)^2*cos(q1)^2 + cos(q1)^4", "cos(q1)^2");
    check("sin(q1)^2*cos(q2)^2 + cos(q1)^2*cos(q2)^2 + sin(q2)^2", "1");
}

#[test]
fn pythagoras_leaves_what_would_not_be_shorter() {
    check("cos(q1)^2 - sin(q1)^2", "cos(q1)^2 - sin(q1)^2");
    check("1 + sin(q1)^2", "1 + sin(q1)^2");
    check("sin(q1)^2 + 2*cos(q1)^2", "sin(q1)^2 + 2*cos(q1)^2");
    check("sin(q1)^2 + cos(q2)^2", "sin(q1)^2 + cos(q2)^2");
    check("a*sin(q1)^2 + b*cos(q1)^2", "a*sin(q1)^2 + b*cos(q1)^2");
}

#[test]
fn angle_sums() {
    check("cos(q1)*cos(q2) - sin(q1)*sin(q2)", "cos(q1+q2)");
    check("cos(q1)*cos(q2) + sin(q1)*sin(q2)", "cos(q1-q2)");
    check("sin(q1)*cos(q2) + cos(q1)*sin(q2)", "sin(q1+q2)");
    check("sin(q1)*cos(q2) - cos(q1)*sin(q2)", "sin(q1-q2)");
    check("sin(q2)*cos(q1) - cos(q2)*sin(q1)", "sin(q2-q1)");
    check("cos(q1)*cos(q1+q2) + sin(q1)*sin(q1+q2)", "cos(q2)");
    check("sin(q1+q2)*cos(q1) - cos(q1+q2)*sin(q1)", "sin(q2)");
    check(
        "2*L*sin(q1)*cos(q2) + 2*L*cos(q1)*sin(q2)",
        "2*L*sin(q1+q2)",
    );
    check(
        "-m/3*q1'*cos(q1)*cos(q2) + m/3*q1'*sin(q1)*sin(q2)",
        "-m/3*q1'*cos(q1+q2)",
    );
    check(
        "cos(q1)*cos(q2) - sin(q1)*sin(q2) + cos(q1+q2)",
        "2*cos(q1+q2)",
    );
    check(
        "cos(q1)*cos(q2)*cos(q3) - sin(q1)*sin(q2)*cos(q3) - sin(q1)*cos(q2)*sin(q3) - cos(q1)*sin(q2)*sin(q3)",
        "cos(q1+q2+q3)",
    );
    check(
        "L*(cos(q1)*cos(q2) - sin(q1)*sin(q2)) + L*sin(q1)^2 + L*cos(q1)^2",
        "L*cos(q1+q2) + L",
    );
}

#[test]
fn angle_sums_need_matching_coefficients() {
    check(
        "cos(q1)*cos(q2) - 2*sin(q1)*sin(q2)",
        "cos(q1)*cos(q2) - 2*sin(q1)*sin(q2)",
    );
    check(
        "a*cos(q1)*cos(q2) - b*sin(q1)*sin(q2)",
        "a*cos(q1)*cos(q2) - b*sin(q1)*sin(q2)",
    );
    check("sin(q1)*cos(q1)", "sin(q1)*cos(q1)");
}

#[test]
fn inside_functions_and_denominators() {
    check("sqrt(sin(q1)^2 + cos(q1)^2 + 3)", "2");
    check("1/(m1 + m2*sin(q2)^2 + m2*cos(q2)^2)", "1/(m1 + m2)");
    check("sin(q3*(cos(q1)^2 + sin(q1)^2))", "sin(q3)");
    check("q1'/(m1 + m2 - m2*cos(q2)^2)", "q1'/(m1 + m2*sin(q2)^2)");
}

/// The kinetic energy of a double pendulum (relative angle `q2`) from the velocity
/// components of the two bobs, against the textbook form
/// `T = ½(m1+m2)L1²q1'² + ½m2L2²(q1'+q2')² + m2L1L2 q1'(q1'+q2') cos q2`.
#[test]
fn double_pendulum_kinetic_energy() {
    let vx1 = "L1*cos(q1)*q1'";
    let vy1 = "L1*sin(q1)*q1'";
    let vx2 = format!("{vx1} + L2*cos(q1+q2)*(q1'+q2')");
    let vy2 = format!("{vy1} + L2*sin(q1+q2)*(q1'+q2')");
    let kinetic = format!("m1/2*(({vx1})^2 + ({vy1})^2) + m2/2*(({vx2})^2 + ({vy2})^2)");
    check(
        &kinetic,
        "(m1+m2)/2*L1^2*q1'^2 + m2/2*L2^2*(q1'+q2')^2 + m2*L1*L2*q1'*(q1'+q2')*cos(q2)",
    );
}

#[test]
fn steps_name_the_identity_and_the_terms() {
    let (result, steps) = simplify_with_steps(&p("m*L^2*sin(q1)^2 + m*L^2*cos(q1)^2"));
    assert_eq!(result, p("m*L^2"));
    assert_eq!(steps.len(), 1);
    assert_eq!(steps[0].rule, PYTHAGORAS);
    assert_eq!(steps[0].before, p("m*L^2*sin(q1)^2 + m*L^2*cos(q1)^2"));
    assert_eq!(steps[0].after, p("m*L^2"));

    let (_, steps) = simplify_with_steps(&p("cos(q1)*cos(q2) - sin(q1)*sin(q2) + 5"));
    let rules: Vec<&str> = steps.iter().map(|s| s.rule).collect();
    assert_eq!(rules, [COS_SUM]);
    assert_eq!(steps[0].after, p("cos(q1+q2)"));

    let (_, steps) = simplify_with_steps(&p("cos(q1)*cos(q1+q2) + sin(q1)*sin(q1+q2)"));
    assert_eq!(
        steps.iter().map(|s| s.rule).collect::<Vec<_>>(),
        [COS_DIFFERENCE]
    );

    let (_, steps) = simplify_with_steps(&p("m*g*L"));
    assert!(steps.is_empty());
}

#[test]
fn double_angle_only_when_asked_and_shorter() {
    let on = Options {
        double_angle: true,
        ..Options::default()
    };
    let e = p("2*sin(q1)*cos(q1)");
    assert_eq!(simplify(&e), e);
    let doubled = simplify_with(&e, &on, None);
    assert_eq!(doubled, p("sin(2*q1)"));
    assert_numerically_equal(&e, &doubled);
    // Not shorter: m*sin(q1)*cos(q1) and m*sin(2*q1)/2 take the same operations.
    let e = p("m*sin(q1)*cos(q1)");
    assert_eq!(simplify_with(&e, &on, None), e);
    // Not a single symbol.
    let e = p("2*sin(q1+q2)*cos(q1+q2)");
    assert_eq!(simplify_with(&e, &on, None), e);
}

#[test]
fn shortest_of_prefers_fewer_operations_then_the_first() {
    let candidates = [p("sin(q1)^2 + cos(q1)^2"), p("1 + 0*q1"), p("q2")];
    assert_eq!(shortest_of(&candidates), 1);
    assert_eq!(shortest_of(&[p("a*b"), p("b*c")]), 0);
    assert_eq!(shortest_of(&[]), 0);
}

/// The planar rotations R(q1)·R(q2)·…·R(q5) multiplied out give products of five sines
/// and cosines per term (16 terms per entry); the angle-sum identities, applied
/// repeatedly, must give back R(q1 + … + q5).
#[test]
fn composed_rotations_give_the_rotation_by_the_sum() {
    let n = 5;
    let mut r = [[Expr::one(), Expr::zero()], [Expr::zero(), Expr::one()]];
    for i in 1..=n {
        let q = Expr::coord(&format!("q{i}"), 0);
        let step = [[cos(q.clone()), -sin(q.clone())], [sin(q.clone()), cos(q)]];
        r = [0, 1]
            .map(|row| [0, 1].map(|col| &r[row][0] * &step[0][col] + &r[row][1] * &step[1][col]));
    }
    let total = add((1..=n).map(|i| Expr::coord(&format!("q{i}"), 0)));
    let expected = [
        [cos(total.clone()), -sin(total.clone())],
        [sin(total.clone()), cos(total)],
    ];
    for row in 0..2 {
        for col in 0..2 {
            assert_eq!(r[row][col].terms().len(), 16);
            let got = simplify(&r[row][col]);
            assert_eq!(got, expected[row][col], "entry ({row}, {col})");
            assert_numerically_equal(&r[row][col], &got);
        }
    }
}

/// The kinetic energy of a planar chain of `n` links with relative angles, from the
/// velocity components of each link's tip (a point mass there), and its textbook form
/// `T = Σ_k m_k/2 Σ_{i,j≤k} L_i L_j θ_i' θ_j' cos(θ_i − θ_j)`, `θ_i = q1 + … + qi`.
fn chain_kinetic_energy(n: usize) -> (Expr, Expr) {
    let q = |i: usize, order: u8| Expr::coord(&format!("q{i}"), order);
    let constant = |name: &str, i: usize| Expr::constant(&format!("{name}{i}"));
    let theta = |i: usize, order: u8| add((1..=i).map(|j| q(j, order)));
    let mut energy = Vec::new();
    let mut textbook = Vec::new();
    for k in 1..=n {
        let vx = add((1..=k).map(|i| mul([constant("L", i), cos(theta(i, 0)), theta(i, 1)])));
        let vy = add((1..=k).map(|i| mul([constant("L", i), sin(theta(i, 0)), theta(i, 1)])));
        energy.push(mul([
            Expr::ratio(1, 2),
            constant("m", k),
            add([&vx * &vx, &vy * &vy]),
        ]));
        for i in 1..=k {
            for j in 1..=k {
                let angle = cos(theta(i, 0) - theta(j, 0));
                let lengths = mul([constant("L", i), constant("L", j), theta(i, 1), theta(j, 1)]);
                textbook.push(mul([Expr::ratio(1, 2), constant("m", k), lengths, angle]));
            }
        }
    }
    (add(energy), add(textbook))
}

#[test]
fn chain_of_four_links_reaches_the_textbook_form() {
    let (energy, textbook) = chain_kinetic_energy(4);
    let got = simplify(&energy);
    assert_eq!(got, textbook);
    assert_numerically_equal(&energy, &got);
}

/// Hundreds of terms must take well under a second in an optimized build; the bound here
/// is loose for unoptimized test builds on a busy machine.
#[test]
fn chain_of_ten_links_is_fast() {
    let (energy, textbook) = chain_kinetic_energy(10);
    let start = std::time::Instant::now();
    let got = simplify(&energy);
    let elapsed = start.elapsed();
    assert_eq!(got, textbook);
    assert!(
        elapsed.as_secs_f64() < 20.0,
        "{} terms took {elapsed:?}",
        energy.terms().len()
    );
    eprintln!(
        "{} terms -> {} in {elapsed:?}",
        energy.terms().len(),
        got.terms().len()
    );
}
