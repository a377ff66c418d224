//! Answers say their frame: a reaction's components are along its site's parent's unit
//! vectors (a gear's along its `on` wheel's) and `answer --format json` names that frame;
//! `"in": "N"` rotates them into N. Each checked against components written by hand: the
//! gear pair's tooth force, the double pendulum's elbow by Newton's law for the lower rod,
//! the four-bar's closure by the rocker's moment equation about its ground pin.

use crate::support::{problem, problem_json, run, run_json, scratch};
use serde_json::{json, Value};

fn answers(path: &std::path::Path) -> Vec<Value> {
    let out = run_json(&[
        "answer".as_ref(),
        path.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    out["answers"].as_array().expect("answers").clone()
}

fn close(found: f64, expected: f64, what: &str) {
    assert!(
        (found - expected).abs() <= 1e-6 * expected.abs().max(1.0),
        "{what}: {found} against {expected}"
    );
}

fn component(answer: &Value, axis: &str) -> f64 {
    answer["components"][axis].as_f64().unwrap_or(0.0)
}

/// `solve`'s text line of a reaction: the frame it names and the force's components.
fn solved_force(path: &std::path::Path, joint: &str) -> (String, [f64; 3]) {
    let out = run(&["solve".as_ref(), path.as_os_str()]);
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    let line = text
        .lines()
        .find(|l| l.starts_with(&format!("{joint}: force [")))
        .unwrap_or_else(|| panic!("no line of {joint} in {text}"));
    let inside = &line[line.find('[').expect("[") + 1..line.find(']').expect("]")];
    let v: Vec<f64> = inside
        .split(',')
        .map(|x| x.trim().parse().expect("a number"))
        .collect();
    let frame = line
        .rsplit_once('(')
        .and_then(|(_, f)| f.strip_suffix("'s unit vectors)"))
        .unwrap_or_else(|| panic!("no frame named: {line}"));
    (frame.to_string(), [v[0], v[1], v[2]])
}

/// `solve` prints a few digits: the components to its last one.
fn printed_close(found: f64, expected: f64, what: &str) {
    assert!(
        (found - expected).abs() <= 1e-4 * expected.abs().max(1.0),
        "{what}: {found} against {expected}"
    );
}

/// The handout's Answers label the reaction's components with the unit vectors of each
/// frame the questions give them in (`letters`: a, b, n), and with no other frame's.
fn labels_in_the_handout(path: &std::path::Path, joint: &str, letters: &[&str]) {
    let out = run(&[
        "explain".as_ref(),
        path.as_os_str(),
        "--format".as_ref(),
        "markdown".as_ref(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let answers = &text[text.rfind("## Answers").expect("the Answers")..];
    for letter in ["a", "b", "c", "n"] {
        let label = format!(
            "\\mathbf{{F}}^{{\\mathrm{{{joint}}}}} \\cdot \\hat{{\\mathbf{{{letter}}}}}_{{x}}"
        );
        assert_eq!(
            answers.contains(&label),
            letters.contains(&letter),
            "{joint}: {label} in {answers}"
        );
    }
}

/// The force of `joint`, (F_x, F_y) in N, as answered (`own`), solved and labelled in its
/// frame, turned by θ about n̂_z from N: x̂ = (cos θ, sin θ), ŷ = (−sin θ, cos θ), so its
/// components are F_x cos θ + F_y sin θ and −F_x sin θ + F_y cos θ; the handout labels
/// them with that frame's unit vectors and N's.
fn in_its_frame(
    path: &std::path::Path,
    joint: &str,
    own: &Value,
    (frame, turned): (&str, f64),
    (fx, fy): (f64, f64),
) {
    let x = fx * turned.cos() + fy * turned.sin();
    let y = -fx * turned.sin() + fy * turned.cos();
    assert_eq!(own["frame"], frame);
    close(
        component(own, "x"),
        x,
        &format!("{joint} along {frame}'s x"),
    );
    close(
        component(own, "y"),
        y,
        &format!("{joint} along {frame}'s y"),
    );
    let (solved, f) = solved_force(path, joint);
    assert_eq!(solved, frame);
    printed_close(f[0], x, &format!("solve's {joint} along {frame}'s x"));
    printed_close(f[1], y, &format!("solve's {joint} along {frame}'s y"));
    let letter = frame.to_lowercase();
    labels_in_the_handout(path, joint, &[letter.as_str(), "n"]);
}

fn state(answer: &Value, name: &str) -> f64 {
    answer["state"][name].as_f64().expect("state value")
}

/// The tooth force on the gear is tangential, +15 N along n̂_y: I_B |q̈_B| / r_B with
/// q̈_A = T / (I_A + I_B (r_A/r_B)²) = 225 rad/s², q̈_B = −75 rad/s². Along the pinion's
/// â (turned by q_A = 0.3) it is (15 sin 0.3, 15 cos 0.3). The bundled question asks for
/// it in N, as its statement does; without `in` it is in the pinion's frame.
#[test]
fn the_gear_pairs_tooth_force_names_the_pinions_frame_and_turns_into_n() {
    let mut p = problem_json("gear-pair-torque");
    p["find"]["questions"]
        .as_array_mut()
        .expect("questions")
        .push(json!({ "reaction": "mesh" }));
    let path = scratch("answer-frames", "gear", &p);
    let found = answers(&path);
    let (own, in_n) = (&found[2], &found[1]);
    let force = 0.03 * (1.2 / (0.002 + 0.03 / 9.0)) / 3.0 / 0.15;
    close(force, 15.0, "the tooth force by hand");
    // `solve`'s text: the same components, naming the pinion's frame.
    let (frame, f) = solved_force(&path, "mesh");
    assert_eq!(frame, "A");
    printed_close(f[0], force * 0.3f64.sin(), "solve's â_x");
    printed_close(f[1], force * 0.3f64.cos(), "solve's â_y");
    assert_eq!(own["frame"], "A");
    close(component(own, "x"), force * 0.3f64.sin(), "â_x");
    close(component(own, "y"), force * 0.3f64.cos(), "â_y");
    assert_eq!(in_n["frame"], "N");
    close(component(in_n, "x"), 0.0, "n̂_x");
    close(component(in_n, "y"), force, "n̂_y");
}

/// The elbow P of the double pendulum: the force of rod A on rod B, in A's unit vectors by
/// default, in N's when asked. By hand in N: m₂ a_B* = F + m₂ g, with B's centre at
/// L₁ (sin q₁, −cos q₁) + L₂/2 (sin q₁₂, −cos q₁₂), q₁₂ = q₁ + q₂.
#[test]
fn the_double_pendulums_elbow_in_a_and_in_n() {
    let mut p = problem_json("double-pendulum-rods");
    p["find"]["reactions"] = json!(["O", "P"]);
    p["find"]["questions"] = json!([
        { "value": "q1''" },
        { "value": "q2''" },
        { "reaction": "P" },
        { "reaction": "P", "in": "N" }
    ]);
    let path = scratch("answer-frames", "elbow", &p);
    let found = answers(&path);
    let constant = |name: &str| p["constants"][name]["value"].as_f64().expect("constant");
    let (l1, l2, m2, g) = (
        constant("L1"),
        constant("L2"),
        constant("m2"),
        constant("g"),
    );
    let (q1, q2) = (state(&found[0], "q1"), state(&found[0], "q2"));
    let (u1, u2) = (state(&found[0], "q1'"), state(&found[0], "q2'"));
    let (a1, a2) = (
        found[0]["value"].as_f64().expect("q1''"),
        found[1]["value"].as_f64().expect("q2''"),
    );
    let (q12, u12, a12) = (q1 + q2, u1 + u2, a1 + a2);
    // a_B* = d²/dt² of the centre's position, term by term.
    let ax = l1 * (a1 * q1.cos() - u1 * u1 * q1.sin())
        + l2 / 2.0 * (a12 * q12.cos() - u12 * u12 * q12.sin());
    let ay = l1 * (a1 * q1.sin() + u1 * u1 * q1.cos())
        + l2 / 2.0 * (a12 * q12.sin() + u12 * u12 * q12.cos());
    let (fx, fy) = (m2 * ax, m2 * ay + m2 * g);
    let (own, in_n) = (&found[2], &found[3]);
    assert_eq!(in_n["frame"], "N");
    close(component(in_n, "x"), fx, "elbow n̂_x");
    close(component(in_n, "y"), fy, "elbow n̂_y");
    // A is turned by q₁ from N.
    in_its_frame(&path, "P", own, ("A", q1), (fx, fy));
}

/// The four-bar's closure R: the coupler's force on the rocker, in the coupler's unit
/// vectors by default. In N it satisfies the rocker's moment equation about its ground pin
/// Q: (m c²/3) q̈₃ = c (cos q₃ F_y − sin q₃ F_x) − m g (c/2) cos q₃.
#[test]
fn the_four_bars_closure_in_b_and_in_n() {
    let mut p = problem_json("four-bar");
    p["find"]["questions"] = json!([
        { "value": "q3''" },
        { "reaction": "R" },
        { "reaction": "R", "in": "N" }
    ]);
    let path = scratch("answer-frames", "four-bar", &p);
    let found = answers(&path);
    let constant = |name: &str| p["constants"][name]["value"].as_f64().expect("constant");
    let (c, m, g) = (constant("c"), constant("m"), constant("g"));
    let (q1, q2, q3) = (
        state(&found[0], "q1"),
        state(&found[0], "q2"),
        state(&found[0], "q3"),
    );
    let a3 = found[0]["value"].as_f64().expect("q3''");
    let (own, in_n) = (&found[1], &found[2]);
    assert_eq!(in_n["frame"], "N");
    let (fx, fy) = (component(in_n, "x"), component(in_n, "y"));
    close(
        m * c * c / 3.0 * a3,
        c * (q3.cos() * fy - q3.sin() * fx) - m * g * c / 2.0 * q3.cos(),
        "the rocker's moments about Q",
    );
    // B is turned by q₁ + q₂ from N.
    in_its_frame(&path, "R", own, ("B", q1 + q2), (fx, fy));
}

/// The key's columns name the frame; the handout's Answers write its unit vectors.
#[test]
fn the_key_and_the_handout_name_the_frame() {
    let dir = std::env::temp_dir().join(format!("mbd-frames-key-{}", std::process::id()));
    let mut p = problem_json("gear-pair-torque");
    p["constants"]["T"]["vary"] = json!([1.0, 1.4]);
    p["constants"]["T"]["step"] = json!(0.1);
    let varied = scratch("answer-frames", "varied", &p);
    let out = run(&[
        "variants".as_ref(),
        varied.as_os_str(),
        "--count".as_ref(),
        "1".as_ref(),
        "--seed".as_ref(),
        "3".as_ref(),
        "-o".as_ref(),
        dir.as_os_str(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let key = std::fs::read_to_string(dir.join("key.csv")).expect("key.csv");
    let header = key.lines().next().expect("header");
    assert!(
        header.contains("1.x@N") && header.contains("1.y@N"),
        "{header}"
    );
    let handout = run(&[
        "explain".as_ref(),
        problem("gear-pair-torque").as_os_str(),
        "--format".as_ref(),
        "latex".as_ref(),
    ]);
    let text = String::from_utf8_lossy(&handout.stdout);
    let answers = &text[text.rfind("Answers").expect("the Answers")..];
    assert!(answers.contains("\\hat{\\mathbf{n}}_{y}"), "{answers}");
    assert!(!answers.contains("\\hat{\\mathbf{a}}_{x}"), "{answers}");
    std::fs::remove_dir_all(&dir).ok();
}

/// `in` is for a vector answer and names a frame of the problem.
#[test]
fn in_is_refused_on_a_scalar_and_for_an_unknown_frame() {
    for (question, path) in [
        (
            json!({ "value": "qA''", "in": "N" }),
            "find.questions[2].in",
        ),
        (
            json!({ "reaction": "mesh", "in": "Z" }),
            "find.questions[2].in",
        ),
    ] {
        let mut p = problem_json("gear-pair-torque");
        p["find"]["questions"]
            .as_array_mut()
            .expect("questions")
            .push(question);
        let out = run(&[
            "answer".as_ref(),
            scratch("answer-frames", "bad-in", &p).as_os_str(),
        ]);
        assert_eq!(out.status.code(), Some(1));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(path) && err.contains("hint"), "{err}");
    }
}

/// External gears need parallel axles: a gear whose axle turns against its mate's is
/// refused by `check` and `solve` at the gear's path.
#[test]
fn a_gear_pair_with_crossed_axles_is_refused() {
    let mut p = problem_json("gear-pair-torque");
    p["dimension"] = 3.into();
    p["bodies"]["A"]["inertia"] = json!({ "xx": "IA/2", "yy": "IA/2", "zz": "IA" });
    p["bodies"]["B"]["inertia"] = json!({ "xx": "IB/2", "yy": "IB/2", "zz": "IB" });
    p["constraints"][0]["axis"] = "B.z".into();
    p["joints"][0]["axis"] = "N.x".into();
    let path = scratch("answer-frames", "crossed", &p);
    for command in ["check", "solve"] {
        let out = run(&[command.as_ref(), path.as_os_str()]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{command}: {err}");
        assert!(
            err.contains("constraints[0]") && err.contains("parallel") && err.contains("hint"),
            "{command}: {err}"
        );
    }
    // Parallel axles (both along N.z) are accepted.
    p["joints"][0]["axis"] = "N.z".into();
    let out = run(&[
        "check".as_ref(),
        scratch("answer-frames", "parallel", &p).as_os_str(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// Step 5's table of reactions writes each in the frame with the fewest components: the
/// gear pair's tooth force, tangential, is I_B |q̈_B| / r_B = 15 N along n̂_y there, as the
/// Answers give it, not along the turning pinion's â_x, â_y.
#[test]
fn the_reaction_table_writes_the_tooth_force_in_its_simplest_frame() {
    let out = run(&[
        "explain".as_ref(),
        problem("gear-pair-torque").as_os_str(),
        "--format".as_ref(),
        "markdown".as_ref(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    // The reaction table leaves out a reaction the Answers give: then the answer's lines.
    let row = match text.lines().find(|l| l.starts_with("| mesh |")) {
        Some(row) => row.to_string(),
        None => text
            .lines()
            .filter(|l| l.contains("\\mathbf{F}^{P} \\cdot"))
            .collect::<Vec<_>>()
            .join(" "),
    };
    let force: f64 = 0.03 * (1.2 / (0.002 + 0.03 / 9.0)) / 3.0 / 0.15;
    assert!((force - 15.0).abs() < 1e-9, "by hand: {force}");
    assert!(
        (row.contains("15 \\hat{\\mathbf{n}}_{y}")
            || row.contains("\\hat{\\mathbf{n}}_{y} = 15\\ \\mathrm{N}"))
            && !row.contains("\\hat{\\mathbf{a}}"),
        "{row}"
    );
}

/// The disc in the cylinder, at rest at x = 0.05 m: the normal force at the contact is a
/// push, drawn toward the cylinder's axis (into the disc), so it comes out positive; by
/// hand its size is m g cos φ = m g √((R − r)² − x²)/(R − r) = 9.73306 N along
/// −(x, y)/(R − r), and the handout has no negative normal force to explain.
#[test]
fn the_normal_force_inside_a_cylinder_is_a_push_drawn_inward() {
    let (m, r_big, r, g, x) = (1.0f64, 0.5f64, 0.1f64, 9.81f64, 0.05f64);
    let y = -((r_big - r).powi(2) - x * x).sqrt();
    let inward = [-x / (r_big - r), -y / (r_big - r)];
    let push = m * g * (-y) / (r_big - r);
    let solved = run_json(&[
        "solve".as_ref(),
        problem("disc-in-cylinder").as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    let force = &solved["reactions"]["contact"]["force"];
    let f = [force[0].as_f64().unwrap(), force[1].as_f64().unwrap()];
    let normal = f[0] * inward[0] + f[1] * inward[1];
    assert!(
        (normal - push).abs() <= 1e-6 * push,
        "{normal} against {push} by hand"
    );
    let out = run(&[
        "explain".as_ref(),
        problem("disc-in-cylinder").as_os_str(),
        "--format".as_ref(),
        "markdown".as_ref(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(!text.contains("comes out negative"), "no pull to explain");
    // The free body's arrow of the normal force, on the page (y down): toward the axis.
    let arrow = text
        .split("data-label=\"F^P_n\"")
        .nth(1)
        .and_then(|rest| rest.split("<line ").nth(1))
        .expect("the normal force's arrow");
    let coordinate = |key: &str| -> f64 {
        let start = arrow.find(&format!("{key}=\"")).expect(key) + key.len() + 2;
        let rest = &arrow[start..];
        rest[..rest.find('"').expect("a quoted value")]
            .parse()
            .expect("a number")
    };
    let drawn = [
        coordinate("x2") - coordinate("x1"),
        -(coordinate("y2") - coordinate("y1")),
    ];
    let along = (drawn[0] * inward[0] + drawn[1] * inward[1]) / drawn[0].hypot(drawn[1]);
    assert!(
        along > 0.999,
        "drawn along {drawn:?}, not inward {inward:?}"
    );
}
