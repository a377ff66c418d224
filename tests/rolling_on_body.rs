//! `rolling` on a moving body: a disc rolling on a cart that slides freely, against the
//! classic closed form worked by hand below, and the work–energy balance in simulation.

use crate::support::{assert_close, column, simulate, solve_all};

/// `problems/disc-on-cart.json`: cart M pulled by P, uniform disc m of radius R on it.
const M: f64 = 3.0;
const MD: f64 = 2.0;
const R: f64 = 0.1;
const P: f64 = 12.0;
const G: f64 = 9.81;

/// By hand: friction f (on the disc, along C.x) accelerates the disc's centre, m a_d = f,
/// and turns it, (m R²/2) θ'' = R f; no slip at the contact, a_d + R θ'' = a_c; the cart,
/// M a_c = P − f. So f = m a_c / 3, a_c = 3P/(3M + m), a_d = P/(3M + m).
#[test]
fn a_disc_on_a_free_cart_matches_the_classic_result_by_every_method() {
    let a_cart = 3.0 * P / (3.0 * M + MD);
    let a_disc = P / (3.0 * M + MD);
    let friction = MD * a_disc;
    for s in solve_all("disc-on-cart", &[]) {
        let what = |q: &str| format!("{}: {q}", s.method);
        assert_close(s.acc("x"), a_cart, 1e-9, 1.0, &what("x''"));
        assert_close(
            s.acc("x") + s.acc("s"),
            a_disc,
            1e-9,
            1.0,
            &what("disc centre"),
        );
        assert_close(
            s.acc("theta"),
            (a_cart - a_disc) / R,
            1e-9,
            1.0,
            &what("theta''"),
        );
        assert_close(s.acc("h"), 0.0, 1e-9, 1.0, &what("h''"));
        // The cart's push on the disc, in the cart's unit vectors: friction, then the
        // normal force carrying the disc's weight.
        let contact = s.force("contact");
        assert_close(contact[0], friction, 1e-9, 1.0, &what("friction"));
        assert_close(contact[1], MD * G, 1e-9, 1.0, &what("normal"));
        // No slip is relative: the disc's contact point moves with the cart.
        let state = &s.json["state"];
        let rate = |q: &str| state[q].as_f64().unwrap();
        assert_close(
            rate("s'") + R * rate("theta'"),
            0.0,
            1e-12,
            1.0,
            &what("no slip"),
        );
    }
}

#[test]
fn the_disc_on_the_cart_keeps_the_work_energy_balance() {
    let (columns, rows) = simulate("disc-on-cart", &[]);
    let at = |name: &str| column(&columns, name);
    let (x, xd, sd, td) = (at("x"), at("x'"), at("s'"), at("theta'"));
    // Kinetic energy minus the work of P: the rolling contact does no work.
    let balance = |r: &[f64]| {
        let v_disc = r[xd] + r[sd];
        M * r[xd].powi(2) / 2.0 + MD * v_disc.powi(2) / 2.0 + MD * R * R / 4.0 * r[td].powi(2)
            - P * r[x]
    };
    let start = balance(&rows[0]);
    let last = rows.last().unwrap();
    assert!(last[x] > 1.0, "the cart has moved: {}", last[x]);
    for row in &rows {
        assert_close(balance(row), start, 1e-7, 1.0, "kinetic energy − work of P");
        assert_close(row[sd] + R * row[td], 0.0, 1e-7, 1.0, "no slip on the cart");
    }
}

/// The cart's mass centre lies c below its top, where the disc stands at s = 0.2 m; its
/// slide S holds it at its origin, on the vertical through the mass centre. The cart does
/// not turn: about its mass centre the disc's push
/// on it, −(f, N) at (s, c), turns it by −s N + c f, the pull P and F_y^S act on the
/// vertical through it, so the slide's couple is M_z^S = s N − c f, with N = m g (the disc
/// does not rise) and f = m a_disc. Vertically, F_y^S = (M + m) g.
#[test]
fn the_carts_slide_holds_the_disc_off_its_mass_centre() {
    let (c, s) = (0.06, 0.2);
    let friction = MD * P / (3.0 * M + MD);
    let mut p: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(crate::support::problem("disc-on-cart")).unwrap(),
    )
    .unwrap();
    assert_eq!(p["constants"]["c"]["value"], serde_json::json!(c));
    assert_eq!(p["coordinates"]["s"]["initial"], serde_json::json!(s));
    p["find"]["reactions"] = serde_json::json!(["contact", "S"]);
    let dir = std::env::temp_dir().join(format!("mbd-cart-slide-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("cart-slide.json");
    std::fs::write(&path, p.to_string()).unwrap();
    for method in crate::support::METHODS {
        let solved = crate::support::Solution {
            method: method.to_string(),
            json: crate::support::method_json("solve", &path, method, &[]),
        };
        let what = |q: &str| format!("{method}: {q}");
        let force = solved.force("S");
        assert_close(force[1], (M + MD) * G, 1e-9, 1.0, &what("F_y^S"));
        let couple = s * MD * G - c * friction;
        assert_close(solved.moment("S")[2], couple, 1e-9, 1.0, &what("M_z^S"));
    }
    std::fs::remove_dir_all(&dir).ok();
}
