//! The display rule that writes terms differing only in their constants once, with the
//! constants summed, and a sum that leads with a minus with its positive terms first. Each
//! test reads a real handout and compares with a form derived by hand.

/// Asserts that the Markdown handout of `problem` by `method` prints `expected`.
fn prints(problem: &str, method: &str, expected: &str) {
    let markdown = crate::support::explain(problem, &["--method", method]);
    assert!(
        markdown.contains(expected),
        "{problem} by {method} lacks {expected}"
    );
}

#[test]
fn the_heavy_tops_moment_of_inertia_about_the_vertical_is_collected() {
    // About the vertical the top's inertia is I₃ cos²θ + (I_t + m h²) sin²θ: the transverse
    // moment about the support point, I_t + m h² by the parallel-axis theorem, comes as one.
    prints(
        "heavy-symmetric-top",
        "kane",
        r"(I_{3} c_{\theta}^{2} + (I_{t} + h^{2} m) s_{\theta}^{2}) \ddot{\psi}",
    );
}

#[test]
fn a_joint_points_acceleration_groups_the_offsets_as_the_rigid_body_formula_does() {
    // a^P = a^{H*} + α × r + ω × (ω × r), r from H* to the front hub, (w − x_H, 0, −(r_F + z_H))
    // in H. Its x component: a^{H*}_x + r_z (α_y + ω_x ω_z) − r_x (ω_y² + ω_z²).
    let expected = [
        r"\tilde{a}^{\mathrm{front}_{\mathrm{hub}}}_{x} = \tilde{a}^{H^{*}}_{x}",
        r" - (r_{F} + z_{H}) (\tilde{\alpha}^{H}_{y} + \omega^{H}_{x} \omega^{H}_{z})",
        r" + (x_{H} - w) ({\omega^{H}_{y}}^{2} + {\omega^{H}_{z}}^{2})$",
    ]
    .concat();
    prints("validation/whipple-bicycle", "kane", &expected);
}

#[test]
fn eulers_equations_write_the_difference_of_inertias_positive_first() {
    // I₂ u̇₂ = (I₃ − I₁) u₃ u₁, as Euler wrote it; the handout writes Kane's row with the
    // mass matrix positive, I₂ u̇₂ + (I₁ − I₃) u₁ u₃ = 0.
    let euler = r"I_{2} \dot{u}_{2} + (I_{1} - I_{3}) u_{1} u_{3} = 0";
    prints("torque-free-body-speeds", "kane", euler);
}

#[test]
fn a_vectors_component_is_collected_by_its_constants() {
    // A turntable arm B (angle q1 about N.z) carries a tip C on a joint at a along B.x, turning
    // about B.x; C's centre lies b further along C.x = B.x. By hand v^{C*} = q̇1 n̂z × (a + b) b̂x
    // = (a + b) q̇1 b̂y: the arm's a and the tip's b are one length.
    let problem = r#"{
      "title": "A turntable arm with a tip turning about it", "dimension": 3,
      "constants": { "a": { "value": 0.4 }, "b": { "value": 0.1 }, "m": { "value": 1 }, "J": { "value": 0.01 } },
      "coordinates": { "q1": { "initial": 0, "rate": 1 }, "q2": { "initial": 0.3, "rate": 2 } },
      "bodies": {
        "B": { "mass": "m", "inertia": { "xx": "J", "yy": "J", "zz": "J" } },
        "C": { "mass": "m", "center": "b*C.x", "inertia": { "xx": "J", "yy": "J", "zz": "J" } }
      },
      "joints": [
        { "name": "O", "type": "revolute", "parent": "N", "child": "B", "axis": "N.z", "coordinates": ["q1"] },
        { "name": "P", "type": "revolute", "parent": "B", "child": "C", "at": "a*B.x", "axis": "B.x", "coordinates": ["q2"] }
      ]
    }"#;
    let path = std::env::temp_dir().join(format!("mbd-arm-{}.json", std::process::id()));
    std::fs::write(&path, problem).expect("temporary file");
    let out = crate::support::run(&[
        std::ffi::OsStr::new("explain"),
        path.as_os_str(),
        std::ffi::OsStr::new("--method"),
        std::ffi::OsStr::new("kane"),
    ]);
    let _ = std::fs::remove_file(&path);
    let markdown = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // (Step 4 writes v^{C*} from the pin P; the partial velocity is the vector whole.)
    let expected = r"{}^{N}\mathbf{v}^{C^*}_{1} = (a + b) \hat{\mathbf{b}}_{y}";
    assert!(markdown.contains(expected), "no {expected}");
}

#[test]
fn sums_that_share_a_factor_of_constants_write_it_once() {
    // In a moment row, the inertia force of the whole cart, −(m_C + 2 m_W) ẍ, has the arm
    // R sin θ + b cos θ (axle height R and centre offset b, pitched by θ): the two terms
    // R (m_C + 2 m_W) s_θ + b (m_C + 2 m_W) c_θ are written with the mass once.
    prints(
        "two-wheeled-cart",
        "motion-law",
        r"c_{\psi} (m_{C} + 2 m_{W}) (R s_{\theta} + b c_{\theta}) \ddot{x}",
    );
}

#[test]
fn a_vectors_component_that_would_lead_with_a_minus_puts_its_positive_terms_first() {
    // The elbow motor applies T₂ = τ₂ + k_p2 (r₂ − q₂) − k_d2 q̇₂ to the forearm and −T₂ to the
    // upper arm A (along â_z): −τ₂ − k_p2 r₂ + k_p2 q₂ + k_d2 q̇₂, which a textbook writes with the positive
    // terms first rather than opening with −τ₂.
    prints(
        "two-link-robot-arm",
        "newton-euler",
        r"| elbow motor (couple) | $(k_{d2} \dot{q}_{2} + k_{p2} q_{2} - \tau_{2} - k_{p2} r_{2}) \hat{\mathbf{a}}_{z}$",
    );
}
