//! A large system whose rows step 5 writes out in full is shown in matrix form by where A
//! and b are not zero: each dot must be an unknown its row holds, and the shape must be
//! the one the mechanics gives.

use std::collections::BTreeSet;

/// The five-link chain (relative angles q1…q5, pins O, P2…P5) by Newton–Euler, Markdown.
fn five_links() -> String {
    crate::support::explain(
        "five-link-chain",
        &["--method", "newton-euler", "--format", "markdown"],
    )
}

/// The dots of the pattern table: (row, column) from 1, column `n + 1` for b.
fn dots(markdown: &str) -> BTreeSet<(usize, usize)> {
    let start = markdown
        .find("\\begin{array}{l\\vert c")
        .expect("a pattern table");
    let end = start + markdown[start..].find("\\end{array}").expect("its end");
    let table = &markdown[start..end];
    let mut found = BTreeSet::new();
    // The first line heads the columns; each other starts with its row's number, `(i)`.
    for line in table.split("\\\\").skip(1) {
        let cells: Vec<&str> = line.split('&').map(str::trim).collect();
        let Some(row) = cells[0]
            .trim_start_matches("\\hline")
            .trim()
            .strip_prefix('(')
            .and_then(|r| r.strip_suffix(')'))
        else {
            continue;
        };
        let row: usize = row.parse().expect("a row number");
        for (j, cell) in cells.iter().enumerate().skip(1) {
            if *cell == "\\bullet" {
                found.insert((row, j));
            }
        }
    }
    found
}

/// The unknowns by column as the handout names them: `x_{j} = …`.
fn unknowns(markdown: &str) -> Vec<String> {
    let line = markdown
        .lines()
        .find(|l| l.starts_with("The unknowns by column:"))
        .expect("the unknowns by column");
    line.split("$x_{")
        .skip(1)
        .map(|part| {
            let value = part.split_once("} = ").expect("x_j = …").1;
            value.rsplit_once('$').expect("closing $").0.to_string()
        })
        .collect()
}

/// Row `i`'s last display in step 5 (its simplified form), with a run of second
/// derivatives `\ddot{q}_{a} + \cdots + \ddot{q}_{b}` written out.
fn simplified_row(markdown: &str, i: usize) -> String {
    let start = markdown
        .find(&format!("\n**{i}. "))
        .unwrap_or_else(|| panic!("row {i}"));
    let rest = &markdown[start + 3..];
    let end = ["\n**", "\nIn matrix form"]
        .iter()
        .filter_map(|next| rest.find(next))
        .min()
        .unwrap_or(rest.len());
    let row = &rest[..end];
    let close = row.rfind("\n$$").expect("a display");
    let open = row[..close].rfind("$$\n").expect("its start") + 3;
    let mut text = row[open..close].to_string();
    for a in 1..=5 {
        for b in a + 2..=5 {
            let run = format!("\\ddot{{q}}_{{{a}}} + \\cdots + \\ddot{{q}}_{{{b}}}");
            let all: Vec<String> = (a..=b).map(|k| format!("\\ddot{{q}}_{{{k}}}")).collect();
            text = text.replace(&run, &all.join(" + "));
        }
    }
    text
}

#[test]
fn every_dot_is_an_unknown_its_row_holds_in_step_5() {
    let markdown = five_links();
    let dots = dots(&markdown);
    let unknowns = unknowns(&markdown);
    assert_eq!(
        unknowns.len(),
        15,
        "5 angles and 2 pin forces at each of 5 pins"
    );
    for i in 1..=15 {
        let row = simplified_row(&markdown, i);
        for (j, unknown) in unknowns.iter().enumerate() {
            assert_eq!(
                dots.contains(&(i, j + 1)),
                row.contains(unknown.as_str()),
                "row {i}, {unknown}: {row}"
            );
        }
    }
}

#[test]
fn each_link_s_rows_hold_its_two_pins_and_the_angles_inboard_of_it() {
    let markdown = five_links();
    let dots = dots(&markdown);
    // By hand: link k (rows 3k−2 … 3k) is touched only by its own pin (columns 6 + 2(k−1)
    // and 7 + 2(k−1)) and its child's, and its mass centre moves with q1 … qk alone. Its
    // angular acceleration is q̈1 + … + q̈k, so its moment row holds every one of them.
    for k in 1..=5 {
        let rows = 3 * k - 2..=3 * k;
        let own_pin = 6 + 2 * (k - 1)..=7 + 2 * (k - 1);
        let child_pin = 8 + 2 * (k - 1)..=9 + 2 * (k - 1);
        for &(i, j) in dots.iter().filter(|(i, _)| rows.contains(i)) {
            let allowed =
                j <= k || own_pin.contains(&j) || (k < 5 && child_pin.contains(&j)) || j == 16; // b
            assert!(allowed, "link {k}, row {i} holds column {j}");
        }
        for j in 1..=k {
            assert!(
                dots.contains(&(3 * k, j)),
                "link {k}'s moment row holds q̈{j}"
            );
        }
    }
    assert!(
        dots.len() > 15,
        "the table has dots beyond one a row: {dots:?}"
    );
}

#[test]
fn the_rows_written_by_name_are_given_by_their_values_beside_the_pattern() {
    let markdown = crate::support::explain(
        "validation/whipple-bicycle",
        &["--method", "newton-euler", "--format", "markdown"],
    );
    // 30 rows: 24 of the four bodies and the rear contact's 3, written out; the front
    // contact's 3, by name.
    assert!(markdown.contains("Step 5 writes rows (1)–(27) out"));
    let dots = dots(&markdown);
    assert!(dots.iter().all(|&(i, _)| (1..=30).contains(&i)));
    let row = |i: usize| {
        let start = markdown
            .find(&format!("\nRow {i}, $"))
            .unwrap_or_else(|| panic!("row {i}'s values"));
        let line = markdown[start + 1..].lines().nth(1).expect("the values");
        line.split(", ")
            .map(|v| {
                let (name, value) = v.trim_matches(['$', '.']).split_once(" = ").expect("=");
                (name.to_string(), value.parse::<f64>().expect("a number"))
            })
            .collect::<Vec<_>>()
    };
    // By hand, upright and running straight, the front contact's velocity along n̂x: the
    // rear contact's ẋ one for one; the frame's pitch θ̇ turns the front hub about the rear
    // hub, (r_R − r_F) θ̇, and rolls the front wheel on, r_F θ̇, so r_R = 0.3 in all; the
    // front wheel's spin, r_F = 0.35; yaw, lean and steer move it sideways or not at all.
    let expected = [
        ("S_{28,1}", 1.0),
        ("S_{28,4}", 0.0),
        ("S_{28,5}", 0.0),
        ("S_{28,6}", 0.3),
        ("S_{28,8}", 0.0),
        ("S_{28,9}", 0.35),
        // The bicycle's one-letter names take b, f, h and w, and E, H, U, W are kept for
        // energy, momentum, a contact point and work: the system and its right-hand side
        // are S and d.
        ("d_{28}", 0.0),
    ];
    let got = row(28);
    assert_eq!(got.len(), expected.len(), "{got:?}");
    for ((name, value), (want_name, want)) in got.iter().zip(expected) {
        assert_eq!(name, want_name);
        assert!((value - want).abs() < 1e-9, "{name} = {value}, not {want}");
    }
    // Each value printed is a dot of the table, and the other rows' values are not listed.
    for (name, _) in got.iter().filter(|(n, _)| n.starts_with("U_")) {
        let j: usize = name[6..name.len() - 1].parse().expect("a column");
        assert!(dots.contains(&(28, j)), "{name}");
    }
    assert!(!markdown.contains("\nRow 27, $(27)"));
}
