//! What the handout says of its own rows and of the motion, against the rows it prints and
//! against numbers found another way: a moment written out names the force the free body
//! carries, a quoted row is the row of step 5 as printed, a reaction's components along
//! fixed unit vectors are of one instant, and the energy traded is the range of T that
//! `simulate` gives, to the figures printed.

use crate::support::{between, explain, problem, run};

fn handout(name: &str, method: &str) -> String {
    explain(name, &["--method", method])
}

/// The four-bar's free body B, about P: the coupler carries −F^R at R (F^R acts on the
/// rocker). By hand, r^{PR} = b b̂_x and F^R = F_x b̂_x + F_y b̂_y, so
/// (r^{PR} × (−F^R))·n̂_z = −b F_y.
#[test]
fn a_moment_written_out_names_the_force_its_free_body_carries() {
    let text = handout("four-bar", "motion-law");
    assert!(
        text.contains(
            "(\\mathbf{r}^{P R} \\times (-\\mathbf{F}^{R})) \\cdot \\hat{\\mathbf{n}}_{z} &= -b F^{R}_{y}"
        ),
        "{text}"
    );
}

/// The top's `show` quotes row 2 of step 5: by Lagrange's method that row is printed with
/// the mass term positive, and the quote is the same line.
#[test]
fn a_quoted_row_is_the_row_step_5_prints() {
    for method in ["lagrange", "motion-law"] {
        let text = handout("heavy-symmetric-top", method);
        let answer = between(&text, "Equation (2) of step 5:", "With the conditions");
        let quoted = between(answer, "$$", "= 0$$").trim_start_matches("$$");
        let step5 = between(&text, "## Step 5", "## Step 6");
        assert!(
            step5.contains(quoted.trim()),
            "{method}: {quoted} not in step 5"
        );
    }
}

/// The top precesses: the floor's force along n̂_y at ψ = 0 turns with it, so the words
/// say the components are of this instant.
#[test]
fn a_moving_systems_force_in_fixed_unit_vectors_is_of_this_instant() {
    let text = handout("heavy-symmetric-top", "motion-law");
    let answers = &text[text.find("## Answers").expect("answers")..];
    let said = " up ($+\\hat{\\mathbf{n}}_{z}$), at this instant.";
    // Said for the slow precession; the fast one points to the closed form above.
    assert_eq!(answers.matches(said).count(), 1, "{answers}");
    assert!(answers
        .contains("The closed form above, with this motion's values, gives these components."));
}

/// The energy traded between T and V is the range of T over the run, which `simulate`
/// writes at its own output times: the handout gives it to three figures.
#[test]
fn the_energy_traded_is_the_range_of_t_to_the_figures_printed() {
    let text = handout("double-pendulum-rods", "motion-law");
    let said: f64 = between(&text, "while about ", " J is traded")
        .trim_start_matches("while about ")
        .parse()
        .expect("a number");
    let out = run(&[
        "simulate".as_ref(),
        problem("double-pendulum-rods").as_os_str(),
        "--format".as_ref(),
        "csv".as_ref(),
        "--no-checks".as_ref(),
    ]);
    let csv = String::from_utf8_lossy(&out.stdout);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().expect("a header").split(',').collect();
    let column = header
        .iter()
        .position(|h| *h == "kinetic")
        .expect("kinetic");
    let kinetic: Vec<f64> = lines
        .map(|l| {
            l.split(',')
                .nth(column)
                .expect("a value")
                .parse()
                .expect("a number")
        })
        .collect();
    let (low, high) = kinetic
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &x| {
            (l.min(x), h.max(x))
        });
    let range = high - low;
    assert!(
        (said - range).abs() <= 0.005,
        "{said} J said, {range} J simulated"
    );
    assert_eq!(
        format!("{said}")
            .replace('.', "")
            .trim_start_matches('0')
            .len(),
        3
    );
}
