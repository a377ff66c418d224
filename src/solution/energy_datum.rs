//! Where the potential energy of an energy answer is zero, said beside the value: an
//! energy without its datum means nothing. Said only where the answer at the start equals
//! the kinetic energy plus gravity's potential measured from the height of the ground's
//! origin (plus the potentials of forces that have one), so that the datum named is the one
//! the answer uses. Where a force's potential adds to gravity's (a gas law), the parts
//! T, V of gravity and V of that force are given each with its value.

use crate::mechanics::SiteKind;
use crate::problem::{BodyId, LoadKind};
use crate::Worked;

/// The ground's origin as the handout names it: a joint of the ground at its origin (pin
/// O), else the origin of N.
fn origin_name(worked: &Worked) -> String {
    let model = &worked.derivation.model;
    let at_origin = model.sites.iter().find(|s| {
        s.parent == BodyId::GROUND
            && matches!(s.kind, SiteKind::Joint(_))
            && (s
                .point
                .position
                .components_in(BodyId::GROUND, &model.frames)
                .iter())
            .all(|c| crate::symbolic::simplify(c).is_zero())
    });
    match at_origin {
        Some(site) => super::force_labels::place(&site.name),
        None => "the origin of N".into(),
    }
}

/// The potential energy of gravity at the start, zero at the height of N's origin:
/// −Σ m g · r*, each mass centre from the origin.
fn gravity_potential(worked: &Worked) -> Option<f64> {
    let model = &worked.derivation.model;
    let g = crate::mechanics::vector_of(model.problem.gravity.as_ref()?);
    let values = model.values_at(0.0, &worked.q0, &worked.rates0);
    let v: f64 = (model.problem.body_ids())
        .map(|b| {
            let body = &model.bodies[b.0];
            let height = body.center.position.dot(&g, &model.frames);
            -crate::symbolic::eval(&body.mass, &values) * crate::symbolic::eval(&height, &values)
        })
        .sum();
    Some(v)
}

/// The steps (sentence, math) for an energy `value` given at the start: where `V` is
/// gravity's alone, its datum; where forces with a potential (a gas law) add theirs, `T`
/// and each part of `V` with its formula and value, gravity's with its datum. Empty where
/// the simulation did not run, the problem has springs, or the value is not that sum.
pub fn steps(worked: &Worked, value: f64) -> Vec<(String, String)> {
    let Some(gravity) = gravity_potential(worked) else {
        return Vec::new();
    };
    let model = &worked.derivation.model;
    let values = model.values_at(0.0, &worked.q0, &worked.rates0);
    let forces: Vec<(usize, crate::symbolic::Expr, f64)> = (0..model.problem.loads.len())
        .filter_map(|i| {
            let v = crate::equations::force_potential(model, i)?;
            let at_start = crate::symbolic::eval(&v, &values);
            Some((i, v, at_start))
        })
        .collect();
    let others: f64 = forces.iter().map(|f| f.2).sum();
    let Some((kinetic, datum)) = sentence(worked, value, gravity + others) else {
        return Vec::new();
    };
    if forces.is_empty() {
        return vec![(datum, String::new())];
    }
    let joules = |x: f64| format!(r"{}\ \mathrm{{J}}", crate::symbolic::fixed(x));
    // Written as step 5 writes: s_1 for sin q_1, the problem's decimals.
    let angles: Vec<&str> = (model.problem.coordinates.iter())
        .filter(|c| c.kind == crate::problem::CoordinateKind::Angle)
        .map(|c| c.name.as_str())
        .collect();
    let style = super::tex::style_of(model.problem).with_coordinates(&angles);
    let tex = |e: &crate::symbolic::Expr| {
        let e = crate::symbolic::simplify(e);
        crate::symbolic::with_style(style.clone(), || crate::symbolic::latex_collected(&e)).0
    };
    let gravity_tex = tex(&super::potential_tex::gravity_potential(model));
    let mut steps = vec![
        (
            "Its parts at the start: the kinetic energy of the bodies,".to_string(),
            format!("T = {}", joules(kinetic)),
        ),
        (
            format!(
                "the potential energy of gravity, zero at the height of {},",
                origin_name(worked)
            ),
            format!("V_{{g}} = {gravity_tex} = {}", joules(gravity)),
        ),
    ];
    let several = forces.len() > 1;
    for (k, (i, v, at_start)) in forces.into_iter().enumerate() {
        let of = match &model.problem.loads[i].name {
            Some(name) => format!("the {name}"),
            None => "the applied force".to_string(),
        };
        // A letter, not the load's name, as a script: V_F, or V_{F_1}, V_{F_2}.
        let sub = match several {
            true => format!("F_{{{}}}", k + 1),
            false => "F".to_string(),
        };
        steps.push((
            format!("and the potential energy $V_{{{sub}}}$ of {of}, whose force is minus its derivative,"),
            format!("V_{{{sub}}} = {} = {}", tex(&v), joules(at_start)),
        ));
    }
    steps
}

/// `(T, the datum's sentence)` for an energy `value` given at the start, where `V` at the
/// start is `potential`; `None` where the simulation did not run, the problem has springs,
/// or the value is not T + V.
fn sentence(worked: &Worked, value: f64, potential: f64) -> Option<(f64, String)> {
    let Some(Ok((trajectory, _))) = &worked.simulation else {
        return None;
    };
    let problem = worked.derivation.model.problem;
    let springs = (problem.loads.iter()).any(|l| {
        matches!(
            l.kind,
            LoadKind::Spring { .. } | LoadKind::JointSpring { .. }
        )
    });
    if springs {
        return None;
    }
    let kinetic = trajectory.series("kinetic")?.first()?.1;
    let total = kinetic + potential;
    if (total - value).abs() > 1e-9 * value.abs().max(1e-9) {
        return None;
    }
    let origin = origin_name(worked);
    Some((
        kinetic,
        format!(
            "{} $V$ is zero at the height of {origin}.",
            definition(worked, kinetic, total - kinetic)
        ),
    ))
}

/// `E = T + V` as a student writes it, each with its value at the start: the kinetic
/// energy of every body from the velocities of step 4, gravity's potential from the
/// heights of the mass centres.
fn definition(worked: &Worked, kinetic: f64, potential: f64) -> String {
    use crate::symbolic::{latex, latex_name};
    let model = &worked.derivation.model;
    let bodies: Vec<BodyId> = (model.problem.body_ids())
        .filter(|b| !model.bodies[b.0].mass.is_zero())
        .collect();
    let term = |b: BodyId| {
        let (mass, centre) = (
            latex(&model.bodies[b.0].mass),
            super::tex::centre_tex(model, b),
        );
        // A coordinate that is the height of the centre is named as it is.
        let height = height_coordinate(worked, b).unwrap_or(format!("h_{{{centre}}}"));
        let name = latex_name(model.problem.body_name(b));
        let spin = if crate::mechanics::is_particle(model, b) {
            String::new()
        } else {
            format!(
                " + \\tfrac{{1}}{{2}}\\, {{}}^{{N}}\\boldsymbol{{\\omega}}^{{{name}}} \\cdot \\mathbf{{I}}^{{{name}}} \\cdot {{}}^{{N}}\\boldsymbol{{\\omega}}^{{{name}}}"
            )
        };
        (
            format!("\\tfrac{{1}}{{2}} {mass} |{{}}^{{N}}\\mathbf{{v}}^{{{centre}}}|^{{2}}{spin}"),
            format!("{mass} g {height}"),
        )
    };
    let (t, v): (Vec<String>, Vec<String>) = bodies.iter().map(|&b| term(b)).unzip();
    let named: Vec<BodyId> = (bodies.iter().copied())
        .filter(|&b| height_coordinate(worked, b).is_none())
        .collect();
    let heights = match named[..] {
        [] => String::new(),
        [one] => {
            let centre = super::tex::centre_tex(model, one);
            format!(", $h_{{{centre}}}$ the height of ${centre}$")
        }
        _ => ", each $h$ the height of a mass centre".to_string(),
    };
    let number = |x: f64| super::answer_numbers::number_tex(x);
    format!(
        "$E = T + V$, with the velocities of step 4 at the start: $T = {} = {}\\ \\mathrm{{J}}$ and $V = {} = {}\\ \\mathrm{{J}}${heights}.",
        t.join(" + "),
        number(kinetic),
        v.join(" + "),
        number(potential)
    )
}

/// The coordinate that is the height of body `b`'s mass centre above N's origin, as LaTeX
/// (`z` for a coin whose centre is at `(x, y, z)`): the centre's position dotted with
/// gravity is minus g times that coordinate alone. `None` where no coordinate is.
fn height_coordinate(worked: &Worked, b: BodyId) -> Option<String> {
    use crate::symbolic::{eval, latex, partial, simplify};
    let model = &worked.derivation.model;
    let problem = model.problem;
    let g = crate::mechanics::vector_of(problem.gravity.as_ref()?);
    let values = model.values_at(0.0, &worked.q0, &worked.rates0);
    let size: f64 = (g.components_in(BodyId::GROUND, &model.frames).iter())
        .map(|c| eval(c, &values).powi(2))
        .sum::<f64>()
        .sqrt();
    let along = simplify(&model.bodies[b.0].center.position.dot(&g, &model.frames));
    (0..problem.coordinates.len()).find_map(|c| {
        let q = problem.coordinate_expr(c, 0);
        let k = simplify(&partial(&along, &problem.coordinate_symbol(c, 0)).ok()?);
        let minus_g = (eval(&k, &values) + size).abs() <= 1e-12 * size.max(1.0);
        (minus_g && simplify(&(&along - &(&k * &q))).is_zero()).then(|| latex(&q))
    })
}
