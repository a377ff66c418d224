//! A contact in the model is two-sided: it holds its body on the surface whatever its
//! normal force. Step 6's "contacts press" check says where the force turns to a pull, the
//! instant a real contact leaves. Checked against the classic ladder on a smooth wall and a
//! smooth floor, released from rest at θ₀ from the vertical: energy and the wall's force
//! vanishing give the instant it leaves the wall, at cos θ = (2/3) cos θ₀.

use crate::support::{column, run, table};
use serde_json::Value;

const THETA0: f64 = 0.3;
const HALF_LENGTH: f64 = 1.25;

/// The rough-wall ladder of problems/validation with μ = 0 at both ends, from rest.
fn smooth_ladder() -> std::path::PathBuf {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("problems/validation/ladder-on-rough-wall-and-floor.json");
    let mut json: Value =
        serde_json::from_str(&std::fs::read_to_string(path).expect("reads")).expect("JSON");
    json["constants"]["mu1"]["value"] = 0.0.into();
    json["constants"]["mu2"]["value"] = 0.0.into();
    let theta = &mut json["coordinates"]["theta"];
    theta["initial"] = THETA0.into();
    theta["rate"] = 0.0.into();
    json["coordinates"]["x"]["initial"] = (HALF_LENGTH * THETA0.sin()).into();
    json["coordinates"]["y"]["initial"] = (HALF_LENGTH * THETA0.cos()).into();
    json["simulate"] =
        serde_json::json!({ "duration": 1.0, "output_step": 0.001, "tolerance": 1e-10 });
    let out = std::env::temp_dir().join(format!("smooth-ladder-{}.json", std::process::id()));
    std::fs::write(&out, json.to_string()).expect("writes");
    out
}

#[test]
fn a_ladder_on_smooth_surfaces_leaves_the_wall_at_two_thirds_of_its_height() {
    let path = smooth_ladder();
    let out = run(&[
        "simulate".as_ref(),
        path.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
    ]);
    let _ = std::fs::remove_file(&path);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    let line = (stderr.lines())
        .find(|l| l.contains("contacts press"))
        .unwrap_or_else(|| panic!("no contact check in:\n{stderr}"));
    assert!(line.contains("(FAIL)"), "{line}");
    let when: f64 = line
        .split("turns to a pull at t ≈ ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next())
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("no instant in `{line}`"));
    let json: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let (columns, rows) = table(&json);
    let (t, theta) = (column(&columns, "t"), column(&columns, "theta"));
    let after = rows.iter().position(|r| r[t] >= when).expect("a row after");
    let (a, b) = (&rows[after - 1], &rows[after]);
    let at = a[theta] + (b[theta] - a[theta]) * (when - a[t]) / (b[t] - a[t]);
    let expected = (2.0 / 3.0 * THETA0.cos()).acos();
    assert!(
        (at - expected).abs() < 1e-4,
        "θ = {at} when the wall lets go, by hand {expected}"
    );
}
