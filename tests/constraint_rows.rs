//! Every constraint row of every bundled problem, by every method, is named by what it
//! holds, read against the problem file: a row along a rolling or contact surface's normal
//! is "no penetration", one across it "no slip" (while it sticks, where there is friction),
//! a gear's row along the line of centres "the centres stay R - r apart" (the problem's
//! radii, R + r outside) and across it "no slip", a closure's "loop closure", a joint's friction "no slip … while it sticks"
//! along the joint's axis; the problem's own `position` and `velocity` entries keep their
//! names. Each direction is one unit vector (the frame that writes it simplest) of the
//! surface's own frame, or of N where that frame only translates.

use mbd_tutor::equations::Method;
use mbd_tutor::pipeline::{derive, Purpose};
use mbd_tutor::plan::Sum;
use mbd_tutor::solution::equation_view;
use serde_json::Value;

use crate::support::{all_problems, problem_json};

/// A direction written as one unit vector: its sign, frame letter and axis (`x`, `y`, `z`,
/// or `r`, `t` for step 1's ê_r and ê_t).
#[derive(Debug, PartialEq)]
struct Unit {
    negative: bool,
    frame: String,
    axis: String,
}

fn unit(tex: &str) -> Option<Unit> {
    let (negative, rest) = match tex.trim().strip_prefix('-') {
        Some(rest) => (true, rest.trim()),
        None => (false, tex.trim()),
    };
    let rest = rest.strip_prefix("\\hat{\\mathbf{")?;
    let (frame, rest) = rest.split_once("}}_{")?;
    let axis = rest.strip_suffix('}')?;
    let simple = |s: &str| !s.is_empty() && s.chars().all(|c| c.is_ascii_alphanumeric());
    (simple(frame) && simple(axis)).then(|| Unit {
        negative,
        frame: frame.to_string(),
        axis: axis.to_string(),
    })
}

/// A vector of the problem file, `B.y` or `-N.x`, as a unit: its frame letter and axis.
fn file_unit(vector: &str) -> Option<Unit> {
    let (negative, rest) = match vector.trim().strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, vector.trim()),
    };
    let (frame, axis) = rest.split_once('.')?;
    (frame.len() == 1 && matches!(axis, "x" | "y" | "z")).then(|| Unit {
        negative,
        frame: frame.to_lowercase(),
        axis: axis.to_string(),
    })
}

/// A row's label split into what it holds, the place named and the direction: `\text{no
/// slip at the mesh}\text{, along } \hat{\mathbf{n}}_{y}` gives ("no slip", "mesh",
/// Some(…)).
fn parts(label: &str) -> Option<(String, String, Option<String>)> {
    let rest = label.strip_prefix("\\text{")?;
    let (what, rest) = rest.split_once('}')?;
    let direction = rest
        .strip_prefix("\\text{, along }")
        .map(|d| d.trim().to_string());
    for kind in ["no slip", "no penetration", "loop closure"] {
        if let Some(place) = what.strip_prefix(&format!("{kind} at ")) {
            let place = place
                .strip_suffix(" while it sticks")
                .map_or_else(|| place.to_string(), |p| format!("{p} (sticking)"));
            let place = place.strip_prefix("the ").unwrap_or(&place).to_string();
            return Some((kind.to_string(), place, direction));
        }
    }
    // A closure straight to the body a joint hangs from holds a guide's rows: "the rod
    // keeps the collar on its line", "the rod stops the collar turning".
    if let Some(rest) = what.strip_prefix("the ") {
        let guides = [" keeps ", " stops "];
        if let Some(place) = guides
            .iter()
            .find_map(|g| rest.split_once(g).map(|(p, _)| p))
        {
            return Some(("guide".to_string(), place.to_string(), direction));
        }
    }
    for kind in ["position constraint", "velocity constraint"] {
        if let Some(name) = what.strip_prefix(&format!("{kind} ")) {
            return Some((kind.to_string(), name.to_string(), direction));
        }
    }
    None
}

/// Whether the body `frame` (a letter) only translates: joined to N by a prismatic joint.
fn translates(problem: &Value, frame: &str) -> bool {
    frame == "n"
        || problem["joints"].as_array().into_iter().flatten().any(|j| {
            j["type"] == "prismatic"
                && j["parent"] == "N"
                && j["child"]
                    .as_str()
                    .is_some_and(|c| c.to_lowercase() == frame)
        })
}

/// What is wrong with the row labelled `label` of `problem` (named `file`).
fn fault(file: &str, problem: &Value, label: &str) -> Option<String> {
    let wrong = |why: &str| Some(format!("{file}: `{label}`: {why}"));
    if label.ends_with("\\text{ held by its support}")
        || label.starts_with("\\text{prescribed motion of }")
    {
        return None;
    }
    if let Some(rest) = label.strip_prefix("\\text{the centres stay } ") {
        return centres_fault(problem, rest).and_then(wrong);
    }
    let Some((kind, place, direction)) = parts(label) else {
        return wrong("not named by what it holds");
    };
    let sticking = place.ends_with(" (sticking)");
    let place = place.trim_end_matches(" (sticking)").replace(' ', "_");
    let named = |key: &str| {
        problem[key]
            .as_array()
            .into_iter()
            .flatten()
            .find(|c| c["name"] == place.as_str())
            .cloned()
    };
    let direction = direction.as_deref();
    match kind.as_str() {
        "position constraint" | "velocity constraint" => {
            let Some(entry) = named("constraints") else {
                return wrong("names no entry of the problem");
            };
            let declared = format!("{} constraint", entry["type"].as_str().unwrap_or("?"));
            (declared != kind || direction.is_some()).then(|| format!("{file}: `{label}`"))
        }
        "loop closure" | "guide" => match (named("closures"), direction.map(unit)) {
            (None, _) => wrong("no closure of that name"),
            (Some(_), Some(None)) => wrong("not along one unit vector"),
            _ => None,
        },
        _ => {
            if let Some(joint) = named("joints").or_else(|| named("closures")) {
                // Friction in a joint: no slip along its axis while it sticks.
                let axis = joint["axis"].as_str().unwrap_or("");
                return match (kind.as_str(), sticking, file_unit(axis), direction) {
                    ("no slip", true, Some(a), Some(d)) => unit(d)
                        .is_none_or(|d| d.axis != a.axis || d.frame != a.frame)
                        .then(|| format!("{file}: `{label}` not along the joint's axis {axis}")),
                    // An axis of no one frame (the slope): written with its own terms.
                    ("no slip", true, None, Some(d)) => ["n}}_{x}", "n}}_{y}"]
                        .iter()
                        .any(|u| !d.contains(u))
                        .then(|| format!("{file}: `{label}` not along {axis}")),
                    ("no slip", true, _, None) => None,
                    _ => wrong("a joint's row named as a contact's"),
                };
            }
            let Some(contact) = named("constraints") else {
                return wrong("names no constraint of the problem");
            };
            surface_fault(file, problem, label, &kind, sticking, &contact, direction)
        }
    }
}

/// A rolling, contact or gear row: named by its direction against the surface's normal.
fn surface_fault(
    file: &str,
    problem: &Value,
    label: &str,
    kind: &str,
    sticking: bool,
    contact: &Value,
    direction: Option<&str>,
) -> Option<String> {
    let wrong = |why: &str| Some(format!("{file}: `{label}`: {why}"));
    let friction = contact.get("friction").is_some();
    if sticking != (friction && kind == "no slip") {
        return wrong("\"while it sticks\" where there is friction, and only there");
    }
    // A row without a direction (the plan's) has nothing more to read.
    let direction = direction?;
    let Some(d) = unit(direction) else {
        return wrong("not along one unit vector");
    };
    if contact["type"] == "gear" {
        // Step 1 names the line of centres ê_r and the tangent ê_t where the distance is a
        // constraint; the gear pair's axles keep it, on a line along n̂_x.
        return match (kind, d.frame.as_str(), d.axis.as_str()) {
            ("no slip", "e", "t") | ("no slip", "n", "y") => None,
            _ => wrong("a gear's row named against its line of centres"),
        };
    }
    let Some(normal) = contact["normal"].as_str().and_then(file_unit) else {
        return wrong("a surface whose normal is no unit vector");
    };
    let frame_ok =
        d.frame == normal.frame || (d.frame == "n" && translates(problem, &normal.frame));
    if !frame_ok {
        return wrong("not in the surface's own frame");
    }
    match kind {
        "no penetration" if d.axis == normal.axis => None,
        "no slip" if d.axis != normal.axis => None,
        _ => wrong(&format!("named against the normal {}", normal.axis)),
    }
}

#[test]
fn every_constraint_row_is_named_by_what_it_holds() {
    let mut faults = Vec::new();
    let mut named = 0;
    for path in all_problems() {
        let file = path
            .file_stem()
            .expect("a name")
            .to_string_lossy()
            .into_owned();
        let json: Value =
            serde_json::from_str(&std::fs::read_to_string(&path).expect("read")).expect("json");
        let problem = mbd_tutor::problem::load_file(&path).expect("a bundled problem");
        // Every constraint and closure of the file heads a row by some method.
        let mut places: Vec<String> = ["constraints", "closures"]
            .iter()
            .flat_map(|k| json[*k].as_array().cloned().unwrap_or_default())
            .filter_map(|c| c["name"].as_str().map(str::to_string))
            .collect();
        for method in Method::ALL {
            let derivation = derive(&problem, method, Purpose::Handout)
                .unwrap_or_else(|e| panic!("{file}: {e}"));
            for row in &derivation.rows {
                if !matches!(row.sum, Sum::Constraint { .. }) {
                    continue;
                }
                let label = equation_view(&derivation, row).label_tex.to_string();
                named += 1;
                faults.extend(fault(&file, &json, &label));
                if let Some((_, place, _)) = parts(&label) {
                    let place = place.trim_end_matches(" (sticking)").replace(' ', "_");
                    places.retain(|p| *p != place);
                }
            }
        }
        if !places.is_empty() {
            faults.push(format!("{file}: no row names {places:?}"));
        }
    }
    assert!(named > 100, "only {named} constraint rows");
    assert!(faults.is_empty(), "{}", faults.join("\n"));
}

/// The reading itself: the rows the issue found misnamed fail it.
#[test]
fn the_check_finds_a_misnamed_row() {
    let rack = problem_json("rack-and-pinion");
    let gear = problem_json("gear-pair-torque");
    let cylinder = problem_json("disc-in-cylinder");
    for (file, problem, label) in [
        (
            "rack-and-pinion",
            &rack,
            "\\text{no penetration at the teeth}\\text{, along } \\hat{\\mathbf{r}}_{x}",
        ),
        (
            "rack-and-pinion",
            &rack,
            "\\text{no slip at the teeth}\\text{, along } \\hat{\\mathbf{r}}_{y}",
        ),
        (
            "gear-pair-torque",
            &gear,
            "\\text{no slip at the mesh}\\text{, along } s_{q_{A}} \\hat{\\mathbf{a}}_{x} + c_{q_{A}} \\hat{\\mathbf{a}}_{y}",
        ),
        ("disc-in-cylinder", &cylinder, "\\text{rolling constraint}"),
        (
            "disc-in-cylinder",
            &cylinder,
            "\\text{no slip at the contact}\\text{, along } -\\hat{\\mathbf{e}}_{r}",
        ),
    ] {
        assert!(fault(file, problem, label).is_some(), "{label} passes");
    }
    assert_eq!(
        fault(
            "rack-and-pinion",
            &rack,
            "\\text{no slip at the teeth}\\text{, along } \\hat{\\mathbf{r}}_{x}"
        ),
        None
    );
}

/// What is wrong with a gear's position row, `rest` its label after "the centres stay ":
/// the distance its centres keep, in the problem's radii (`R - r` inside the other disc,
/// `R + r` outside it), and its direction along the line of centres ê_r.
fn centres_fault(problem: &Value, rest: &str) -> Option<&'static str> {
    let Some((apart, tail)) = rest.split_once(" \\text{ apart}") else {
        return Some("no distance between the centres said");
    };
    let gears = problem["constraints"].as_array().into_iter().flatten();
    let said = gears.filter(|g| g["type"] == "gear").any(|g| {
        let (r, on) = (g["radius"].as_str(), g["on_radius"].as_str());
        let sign = if g["internal"] == true { "-" } else { "+" };
        matches!((on, r), (Some(on), Some(r)) if apart == format!("{on} {sign} {r}"))
    });
    if !said {
        return Some("not the distance a gear's centres keep");
    }
    match tail.strip_prefix("\\text{, along }").map(unit) {
        None => None,
        Some(Some(d)) if d.frame == "e" && d.axis == "r" => None,
        Some(_) => Some("a gear's distance row not along its line of centres"),
    }
}
