//! Kane's method with independent speeds as the handout teaches it (step 5): which speeds
//! are independent and why, `u_D = C u_I` in symbols, the constrained partial velocities
//! `ṽ_r = v_r + Σ_s C_sr v_s`, which forces drop out and why, the auxiliary speeds of the
//! requested reactions and drives, and the order in which the system is solved.

use super::partial_rows::BodyPartials;
use crate::equations::{partials, Derivation};
use crate::mechanics::DependentSpeeds as Speeds;
use crate::render::context::{DependentSpeeds, PartialVelocity};
use crate::render::text::{MarkupLine, Math};
use crate::symbolic::{
    latex, latex_collected, latex_name, roots_of_squares, simplify, Expr, Symbol,
};

/// `u_k = \dot{q}` of independent speed `r` (0-based).
pub fn speed_tex(derivation: &Derivation, speeds: &Speeds, r: usize) -> String {
    let rate = latex(
        &derivation
            .model
            .problem
            .coordinate_expr(speeds.independent[r], 1),
    );
    format!("u_{{{}}} = {rate}", r + 1)
}

/// The constrained partial velocities and partial angular velocities of every body, one
/// line per body and independent speed, then the auxiliary speeds' (see
/// [`super::auxiliary_partials`]).
pub fn partial_velocities(derivation: &Derivation, speeds: &Speeds) -> Vec<PartialVelocity> {
    let model = &derivation.model;
    let problem = model.problem;
    let n = problem.coordinates.len();
    let rates: Vec<Symbol> = (0..n).map(|i| problem.coordinate_symbol(i, 1)).collect();
    let per_body: Vec<BodyPartials> = model
        .order
        .iter()
        .map(|&body| {
            let state = &model.bodies[body.0];
            (
                body,
                partials(&state.center.velocity, &rates),
                partials(&state.omega, &rates),
            )
        })
        .collect();
    let mut out = Vec::new();
    for r in 0..speeds.independent.len() {
        let weights = speeds.independent_weights(r, n);
        let speed = speed_tex(derivation, speeds, r);
        out.extend(super::partial_rows::body_rows(
            derivation,
            &per_body,
            &weights,
            r,
            (speed, None),
        ));
        out.extend(super::partial_rows::slip_partials(
            model, &rates, &weights, r,
        ));
    }
    out.extend(super::auxiliary_partials::table_rows(
        derivation, speeds, &per_body, &rates,
    ));
    out
}

/// `u_D = C u_I` in symbols, Kane's equations with these speeds, and the paragraphs that
/// say what was chosen, what drops out, and how the system is solved.
pub fn dependent_speeds(
    derivation: &Derivation,
    speeds: &Speeds,
    q: &[f64],
    q_rates: &[f64],
) -> DependentSpeeds {
    let problem = derivation.model.problem;
    let sign = super::tex::initial_sign(&derivation.model);
    let rate = |i: usize| latex(&problem.coordinate_expr(i, 1));
    let rates = |list: &[usize]| list.iter().map(|&i| rate(i)).collect::<Vec<_>>();
    let listed = |list: &[usize]| {
        let all: Vec<String> = rates(list).iter().map(|r| format!("${r}$")).collect();
        words(&all)
    };
    let start = derivation.model.values_at(0.0, q, q_rates);
    // Step 1 found the same rates over another denominator: the two linked on the loop.
    let link = (!speeds.at_each_state)
        .then(|| super::kane_delta::on_the_loop(&derivation.model, speeds))
        .flatten();
    let relations_tex: Vec<String> = (speeds.dependent.iter().enumerate())
        .map(|(s, &d)| {
            if let Some(simplest) = simplest_relation(derivation, link.as_ref(), speeds, s) {
                return format!("{} = {simplest}", rate(d));
            }
            // Each speed's rate with its entry of C (or C_P), in the order of the speeds.
            let pairs = (speeds.independent.iter().zip(&speeds.c[s]))
                .chain(speeds.prescribed.iter().zip(&speeds.c_prescribed[s]));
            if speeds.at_each_state {
                return evaluated_relation(rate(d), pairs, &speeds.rest[s], &rate, &start);
            }
            let terms = pairs
                .map(|(&i, c)| c * &problem.coordinate_expr(i, 1))
                .chain(std::iter::once(speeds.rest[s].clone()));
            let sum = roots_of_squares(&simplify(&crate::symbolic::add(terms)), &sign);
            format!("{} = {}", rate(d), latex_collected(&sum))
        })
        .collect();
    let relation_tex = format!(
        "\\begin{{aligned}} {} \\end{{aligned}}",
        relations_tex
            .iter()
            .map(|r| r.replacen(" = ", " &= ", 1))
            .collect::<Vec<_>>()
            .join(" \\\\ ")
    );
    // What holds on the motion and not identically, which C and the rows use.
    let relations: Vec<String> = (derivation.model.constraints.relations.iter())
        .map(|(_, relation)| format!("${}$", relation.latex()))
        .collect();
    let using = if relations.is_empty() {
        String::new()
    } else {
        let hold = ["hold", "holds"][usize::from(relations.len() == 1)];
        format!(
            " (here and in the rows below written with {}, which {hold} on the motion)",
            words(&relations)
        )
    };
    let over = over_delta(speeds, &relation_tex);
    let mut paragraphs = vec![format!(
        "The constraints fix the rates {} by the others, {}{}; solved for the dependent rates, the velocity constraints give{using}{over}:",
        listed(&speeds.dependent),
        if speeds.independent.len() == 1 {
            format!(
                "so the one generalized speed is the rate that stays free, {}",
                listed(&speeds.independent)
            )
        } else {
            format!(
                "so the generalized speeds are the rates that stay free, {}",
                listed(&speeds.independent)
            )
        },
        if speeds.prescribed.is_empty() {
            String::new()
        } else {
            format!(
                " (the rate of {} is prescribed, not a speed)",
                listed(&speeds.prescribed)
            )
        }
    )];
    if speeds.at_each_state {
        if let Some(head) = paragraphs[0].strip_suffix(':') {
            paragraphs[0] = format!(
                "{head}. Solved in symbols, the entries of $C = -A_D^{{-1}} A_I$ would run to pages, since the {d} dependent rates are coupled through every constraint; they are named instead, $C_{{sr}}$, and evaluated at each state from $A_D$ (${d} \\times {d}$) and $A_I$ (${d} \\times {i}$), the coefficients of the dependent and the independent rates in the velocity constraints, by solving those constraints for the dependent rates:",
                d = speeds.dependent.len(),
                i = speeds.independent.len(),
            );
        }
    }
    let partials = if speeds.at_each_state {
        "The constrained partial velocities are $\\tilde{\\mathbf{v}}_r = \\mathbf{v}_r + \\sum_s C_{sr}\\,\\mathbf{v}_s$ (and $\\tilde{\\boldsymbol{\\omega}}_r$ likewise)"
    } else {
        "The constrained partial velocities are $\\tilde{\\mathbf{v}}_r = \\mathbf{v}_r + \\sum_s \\frac{\\partial \\dot{q}_s}{\\partial u_r}\\,\\mathbf{v}_s$, summed over the dependent rates $\\dot{q}_s$ of the relations above (and $\\tilde{\\boldsymbol{\\omega}}_r$ likewise)"
    };
    let partials = with_auxiliary(derivation, speeds, partials);
    let partials = linked(partials, link.as_ref(), &rates(&speeds.dependent));
    paragraphs.push(if speeds.at_each_state {
        format!("{partials}. Written out, they would carry the entries of $C$ into every component; the rows take them by name instead, $\\tilde{{F}}_r = F_r + \\sum_s C_{{sr}} F_s$ and $\\tilde{{F}}^*_r = F^*_r + \\sum_s C_{{sr}} F^*_s$, with $F_s$ and $F^*_s$ formed, as below, with the partial velocities of each coordinate's rate:")
    } else {
        format!("{partials}:")
    });
    let kane_tex = kane_equations_tex(speeds.independent.len());
    let delta = relation_tex.contains("\\Delta");
    // The matrices of the dependent rates by names the problem does not use.
    let names = crate::problem::MatrixNames::of(problem);
    let paragraphs: Vec<String> = paragraphs
        .iter()
        .map(|p| renamed_matrices(p, &names))
        .collect();
    let kane_tex = renamed_matrices(&kane_tex, &names);
    DependentSpeeds {
        relation_tex: Math::from(relation_tex),
        relations_tex: Math::all(relations_tex),
        kane_tex: Math::from(kane_tex),
        reduced_tex: Vec::new(),
        kane_speeds_notes: MarkupLine::all(paragraphs),
        kane_solve_notes: MarkupLine::all(after_rows(derivation, speeds, delta, link.as_ref())),
        kane_kept_note: MarkupLine::from(String::new()),
        time_terms: problem.moves_with_time(),
        start_tex: Vec::new(),
    }
}

/// `partials` followed, where auxiliary speeds have lines in the table, by what those lines
/// are and the dependent rates each one's motion fixes.
fn with_auxiliary(derivation: &Derivation, speeds: &Speeds, partials: &str) -> String {
    if !super::auxiliary_partials::any(derivation) {
        return partials.to_string();
    }
    let rates = super::auxiliary_partials::rates_text(derivation, speeds);
    let rates = if rates.is_empty() {
        rates
    } else {
        format!(". {rates}")
    };
    format!("{partials}. The lines after them are for the auxiliary speeds: each one's partial velocities are those of the motion in which its own constraint alone is relaxed{rates}")
}

/// Dependent rate `s` in its simplest form alone where the loop simplifies it (the
/// four-bar's `q̇3 = −a b sin q2/(c Δ) q̇1`), its right side; `None` otherwise.
fn simplest_relation(
    derivation: &Derivation,
    link: Option<&super::kane_delta::OnTheLoop>,
    speeds: &Speeds,
    s: usize,
) -> Option<String> {
    let (_, c) = link?.simplest.iter().find(|(k, _)| *k == s)?;
    let [free] = speeds.independent.as_slice() else {
        return None;
    };
    let rate_of = c * &derivation.model.problem.coordinate_expr(*free, 1);
    Some(latex_collected(&simplify(&rate_of)))
}

/// The common denominator defined where the rates first have it: `, over the common
/// denominator $\Delta = …$`, or nothing.
fn over_delta(speeds: &Speeds, relation_tex: &str) -> String {
    match super::kane_delta::definition_tex(speeds) {
        Some(delta) if relation_tex.contains("\\Delta") && !speeds.at_each_state => {
            format!(", over the common denominator ${delta}$")
        }
        _ => String::new(),
    }
}

/// Kane's equations of `count` independent speeds, numbered as the speeds and the rows'
/// headings are: `r = 1` for `u₁`, never by the rates.
fn kane_equations_tex(count: usize) -> String {
    let numbers = match count {
        1..=3 => (1..=count)
            .map(|r| r.to_string())
            .collect::<Vec<_>>()
            .join(", "),
        k => format!("1, \\ldots, {k}"),
    };
    format!("\\tilde{{F}}_r + \\tilde{{F}}^*_r = 0 \\; (r = {numbers})")
}

/// `partials` after the words that step 1's rates are these, where `link` says how their
/// denominators agree on the loop (and which of the `dependent` rates, in LaTeX, a
/// further identity of the loop writes in its simplest form).
fn linked(
    partials: String,
    link: Option<&super::kane_delta::OnTheLoop>,
    dependent: &[String],
) -> String {
    match link {
        Some(link) => {
            let also: String = (link.also.iter().zip(&link.simplest))
                .map(|((identity, along), (s, _))| {
                    let rate = dependent.get(*s).map_or("", String::as_str);
                    format!(", and ${rate}$ is written with ${identity}$, since the loop dotted with ${along}$ is zero")
                })
                .collect();
            format!(
                "These are the rates of step 1: on the loop $\\Delta = {}$, since the loop dotted with ${}$ is zero{also}. {partials}",
                link.equal_tex, link.along_tex
            )
        }
        None => partials,
    }
}

/// What drops out and why, the auxiliary speeds, and the order of the solve.
fn after_rows(
    derivation: &Derivation,
    speeds: &Speeds,
    delta: bool,
    link: Option<&super::kane_delta::OnTheLoop>,
) -> Vec<String> {
    let model = &derivation.model;
    let problem = model.problem;
    let friction = &model.constraints.friction;
    let asked = !problem.find_reactions.is_empty() || !speeds.prescribed.is_empty();
    let mut out = vec!["The forces that enforce the constraints do no work with the constrained partial velocities and drop out.".to_string()];
    if !friction.is_empty() {
        out.push(friction_note(derivation));
    }
    out.extend(super::light_rods::notes(derivation));
    if asked || !friction.is_empty() {
        let which = match (asked, friction.is_empty()) {
            (true, true) => "A reaction asked for",
            (true, false) => "A reaction asked for, or a normal force the sliding law needs,",
            _ => "A normal force the sliding law needs",
        };
        let mut text = format!("{which} is brought in by an auxiliary speed $u$ (Kane and Levinson, ch. 4): $u$ lets only the constraint of that reaction give way, so the reaction does work with the partial velocities of $u$ while the other constraint forces do not; the accelerations are taken at $u = 0$.");
        if !speeds.prescribed.is_empty() {
            text.push_str(" A prescribed coordinate's drive comes likewise from its own rate as an auxiliary speed.");
        }
        out.push(text);
    }
    // Where the constraints cannot be solved for the dependent rates.
    let zero = link.map_or(String::new(), |l| {
        format!(", that is where ${} = 0$,", l.zero_tex)
    });
    let singular = format!("The dependent rates have $\\Delta$ in every denominator: at $\\Delta = 0${zero} the velocity constraints do not fix them, a singular configuration of the mechanism where these equations fail.");
    // The order of the solve is said after the matrix form (with friction, in step 3);
    // only the singular configuration of the dependent rates is said here.
    if friction.is_empty() && delta {
        out.push(singular);
    }
    out
}

/// A dependent rate `rate` with its entries of `C` named, `C_{s1} u_1 + C_{s2} u_2 + …`
/// (and `d_s`), and beside it what it is at the start, `start`, which a reader can check
/// against the velocity constraints.
fn evaluated_relation<'a>(
    rate: String,
    pairs: impl Iterator<Item = (&'a usize, &'a Expr)> + Clone,
    rest: &Expr,
    rate_of: &dyn Fn(usize) -> String,
    start: &crate::symbolic::Values,
) -> String {
    let each: Vec<String> = (pairs.clone())
        .filter(|(_, c)| !c.is_zero())
        .map(|(&i, c)| format!("{} {}", latex(c), rate_of(i)))
        .chain(Some(rest).filter(|d| !d.is_zero()).map(latex))
        .collect();
    let sum = if each.is_empty() {
        "0".to_string()
    } else {
        each.join(" + ")
    };
    let numbers = pairs.map(|(&i, c)| (crate::symbolic::eval(c, start), rate_of(i)));
    let at_start = super::tex::numeric_sum(numbers, 1e-13).unwrap_or_else(|| "0".into());
    format!("{rate} = {sum} \\qquad \\left(= {at_start} \\text{{ at the start}}\\right)")
}

/// Why the friction forces stay in Kane's rows and how the normal forces come in.
fn friction_note(derivation: &Derivation) -> String {
    let model = &derivation.model;
    let friction = crate::equations::friction_forces(model);
    let normals = crate::equations::normal_forces(model);
    let tex = |list: &[Symbol]| -> String {
        let each: Vec<String> = (list.iter())
            .map(|u| format!("${}$", latex(&Expr::sym(u.clone()))))
            .collect();
        words(&each)
    };
    let sites: Vec<String> = (model.constraints.friction.iter())
        .map(|f| format!("${}$", latex_name(&f.name)))
        .collect();
    let one = friction.len() == 1;
    let (force, does, it, given) = if one {
        ("force", "does", "it is", "it is given")
    } else {
        ("forces", "do", "they are", "each is given")
    };
    let (normal, does_no, is_brought) = if normals.len() == 1 {
        ("force", "does", "is")
    } else {
        ("forces", "do", "are each")
    };
    let asked = if derivation.model.problem.find_reactions.is_empty() {
        String::new()
    } else {
        " (as is each reaction asked for)".to_string()
    };
    format!(
        "The friction {force} {} at {} {does} work when the contact slips, so {it} in $\\tilde{{F}}_r$: {given} by the no-slip condition while the contact sticks and by the sliding law while it slips. The normal {normal} {}, which the sliding law needs, {does_no} no work and {is_brought} brought in by an auxiliary speed{asked}.",
        tex(&friction),
        words(&sites),
        tex(&normals),
    )
}

/// `a`, `a and b`, `a, b and c`.
fn words(list: &[String]) -> String {
    match list {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// The prose's matrices `C`, `A_D` and `A_I` by the problem's free names (`C_{sr}`,
/// `$C$`, `C = -A_D^{-1} A_I` are the only places these letters stand for them).
fn renamed_matrices(text: &str, names: &crate::problem::MatrixNames) -> String {
    let (a, c) = (names.a.as_str(), names.c.as_str());
    text.replace("C_{sr}", &format!("{c}_{{sr}}"))
        .replace("= C\\,", &format!("= {c}\\,"))
        .replace("$C$", &format!("${c}$"))
        .replace("$C = ", &format!("${c} = "))
        .replace("A_D", &format!("{a}_D"))
        .replace("A_I", &format!("{a}_I"))
}
