//! Kane's auxiliary speeds as Kane and Levinson teach them (ch. 4): for a reaction asked
//! for, the augmented velocities that let the joint slide or turn along it, their partial
//! velocities, which forces drop out and why, and the accelerations at the speed zero.

use super::auxiliary_partials::Moves;
use super::tex::{bodies_tex, vector_tex};
use crate::equations::Derivation;
use crate::plan::Equation;
use crate::problem::BodyId;
use crate::symbolic::{latex_name, Axis, ComponentKind, Symbol, Unknown};

/// The sentences that show how Kane's row `r` (an auxiliary speed of the tree, `row`)
/// brings in its reaction, in the problem's markup; `None` for any other row.
pub fn augmented_note(derivation: &Derivation, row: &Equation, r: usize) -> Option<String> {
    let model = &derivation.model;
    let problem = model.problem;
    let (site, component) = row.unknowns.iter().find_map(|u| match u {
        Symbol::Unknown(Unknown::Reaction { site, component }) => Some((site, component)),
        _ => None,
    })?;
    let j = problem
        .joints
        .iter()
        .position(|joint| joint.name.as_str() == &**site)?;
    let reaction = model.sites[j]
        .reactions
        .iter()
        .find(|c| c.component() == *component)?;
    let subtree = model.subtree(j);
    if subtree != row.free_body {
        return None;
    }
    let unknown = crate::symbolic::latex(&crate::symbolic::Expr::sym(reaction.unknown(site)));
    let bodies = bodies_tex(derivation, &subtree);
    let point = latex_name(site);
    let d = vector_tex(model, &reaction.direction);
    let u = format!("u_{{{r}}}");
    // A direction of several terms in parentheses where it is multiplied.
    let dp = super::tex::factor_of_product(&d);
    let particles_only = subtree
        .iter()
        .all(|&b| crate::mechanics::is_particle(&derivation.model, b));
    let centres = |separator: &str, each: &dyn Fn(&str) -> String| -> String {
        subtree
            .iter()
            .map(|&b| each(&super::tex::centre_tex(&derivation.model, b)))
            .collect::<Vec<_>>()
            .join(separator)
    };
    // A later component at the same joint is told as the first is, in short.
    let first = first_row_at(derivation, row, site, reaction.kind).filter(|&first| first < r);
    let motion = match (reaction.kind, first) {
        (ComponentKind::Force, Some(first)) => {
            let partials = centres(" = ", &|b| format!("\\mathbf{{v}}^{{{b}}}_{{{r}}}"));
            return Some(format!(
                "As in row {first}, along ${d}$: the partial velocities of ${u}$ are ${partials} = {d}$, and only ${unknown}$ and the forces on ${bodies}$ from outside do work with them."
            ));
        }
        (ComponentKind::Moment, Some(first)) => {
            return Some(format!(
                "As in row {first}, turning about ${d}$: the partial angular velocities of ${u}$ are ${d}$, and only ${unknown}$ and the forces on ${bodies}$ from outside do work with them."
            ));
        }
        (ComponentKind::Force, None) => {
            let partials = centres(" = ", &|b| format!("\\mathbf{{v}}^{{{b}}}_{{{r}}}"));
            let angular = if particles_only {
                String::new()
            } else {
                ", its partial angular velocities zero".to_string()
            };
            let written = augmented_centres(derivation, &subtree, &format!("{u}\\, {dp}"))
                .map(|v| format!(": ${v}$. The"))
                .unwrap_or_else(|| ". The".to_string());
            format!(
                "Let ${point}$ slide with speed ${u}$ along ${d}$: every point of ${bodies}$ gains ${u}\\, {dp}$ and its bodies turn as before{written} partial velocities of ${u}$ are ${partials} = {d}${angular}."
            )
        }
        (ComponentKind::Moment, None) => {
            let partials = centres(", ", &|b| {
                format!(
                    "\\mathbf{{v}}^{{{b}}}_{{{r}}} = {dp} \\times \\mathbf{{r}}^{{{point} {b}}}"
                )
            });
            format!(
                "Let ${bodies}$ turn about ${point}$ with angular speed ${u}$ about ${d}$: each of its bodies gains ${u}\\, {dp}$ and each point $X$ of it ${u}\\, {dp} \\times \\mathbf{{r}}^{{{point} X}}$. The partial angular velocities of ${u}$ are ${d}$, the partial velocities ${partials}$."
            )
        }
    };
    let motion = if reaction.axis == Axis::Member {
        let member = latex_name(problem.body_name(problem.joints[j].child));
        format!(
            "The light rod from ${point}$ to the particle ${member}$, with the particle, is a two-force member: every other force on it acts at ${member}$, so the moment about ${member}$ of the force at ${point}$ is zero and that force lies along the rod, $\\mathbf{{F}}^{{{point}}} = {unknown}\\, {d}$: one unknown, the rod's tension (positive when the rod pulls). {motion}"
        )
    } else {
        motion
    };
    let inside = joints_inside(derivation, &subtree);
    // Said once for the bodies: a later row of the same bodies refers to the first.
    let said = first_row_inside(derivation, &subtree).filter(|&first| first < r);
    let inside = match (inside.as_slice(), said) {
        ([], _) => String::new(),
        (_, Some(first)) => format!(" The reactions inside drop out, as in row {first}."),
        ([one], None) => format!(
            " The reaction at ${one}$, inside ${bodies}$, drops out: its equal and opposite forces act at one point."
        ),
        (many, None) => format!(
            " The reactions at ${}$, inside ${bodies}$, drop out: each pair of equal and opposite forces acts at one point.",
            many.join(", ")
        ),
    };
    // Why the accelerations are step 4's is said once, at the first auxiliary speed.
    let accelerations = if r == super::kane::speed_rows(derivation) + 1 {
        format!(" The accelerations are those of step 4, at ${u} = 0$.")
    } else {
        String::new()
    };
    Some(format!(
        "{motion} Only ${unknown}$ and the other forces on ${bodies}$ from outside do work with them.{inside}{accelerations}"
    ))
}

/// Which bodies Kane's row `r` (an auxiliary speed of a constraint force, `row`) moves,
/// where that is not every body, and which free body of step 2 shows the force that does
/// work with it: the moved bodies' own where the force acts on them from outside (the disc
/// on a cart, lifted off it), else the one that draws it on the body it acts on (the
/// four-bar's pin at R, inside the moved B + C, drawn on free body C). Said in full at the
/// first such row; a later one on the same bodies in short.
pub fn moved_note(derivation: &Derivation, row: &Equation, r: usize) -> Option<String> {
    if row.free_body == derivation.model.order {
        return tree_note(derivation, row, r);
    }
    // The bodies that move with the speed on the loop, and how; the row's bodies else.
    let motions = super::auxiliary_partials::body_motions(derivation, r);
    let moving: Vec<BodyId> = match &motions {
        Some(list) => (list.iter())
            .filter(|(b, m)| *m != Moves::Still && row.free_body.contains(b))
            .map(|(b, _)| *b)
            .collect(),
        None => row.free_body.clone(),
    };
    let how = motions
        .as_ref()
        .map(|list| {
            let moving: Vec<_> = (list.iter())
                .filter(|(b, _)| moving.contains(b))
                .copied()
                .collect();
            format!(" ({})", motions_words(derivation, &moving, &[]))
        })
        .unwrap_or_default();
    let still: Vec<BodyId> = (row.free_body.iter())
        .filter(|b| !moving.contains(b))
        .copied()
        .collect();
    let names = moved_names(derivation, &moving);
    let moves = if moving.len() == 1 { "moves" } else { "move" };
    let speeds = super::kane::speed_rows(derivation);
    let rows = derivation.rows.iter();
    let generalized = rows.filter(|x| matches!(x.sum, crate::plan::Sum::Generalized { .. }));
    let first = (generalized.enumerate().skip(speeds))
        .find(|(_, x)| x.free_body == row.free_body)
        .map(|(k, _)| k + 1)?;
    let inside = relaxed_inside(derivation, row);
    Some(match (first < r, inside) {
        (true, None) => format!("Again only {names} {moves}."),
        (true, Some(pair)) if still.is_empty() => format!(
            "As in row {first}, of the constraint forces only the pair at ${}$ does work with $u_{{{r}}}$.",
            pair.point
        ),
        (true, Some(pair)) => {
            let (verb, their, add) = match still.len() {
                1 => ("does not move", "its partial velocities", "adds"),
                _ => ("do not move", "their partial velocities", "add"),
            };
            format!(
                "Only {names} {moves} with $u_{{{r}}}${how}; {} {verb}, {their} zero on the loop, and {add} nothing to $\\tilde{{F}}_{{{r}}}$ and $\\tilde{{F}}^{{*}}_{{{r}}}$. As in row {first}, of the constraint forces only the pair at ${}$ does work with $u_{{{r}}}$.",
                moved_names(derivation, &still),
                pair.point
            )
        }
        (false, None) => {
            let bodies = bodies_tex(derivation, &row.free_body);
            format!("Only {names} {moves} with $u_{{{r}}}$: free body ${bodies}$ of step 2 shows the forces that can do work with it.")
        }
        (false, Some(pair)) => {
            let drawn = match &pair.drawn_on {
                Some(set) => format!(", drawn on free body ${set}$ of step 2,"),
                None => String::new(),
            };
            format!(
                "Only {names} {moves} with $u_{{{r}}}${how}, and ${on}$ parts from ${by}$ at ${point}$ (the table's last line for $u_{{{r}}}$): of the constraint forces only the pair at ${point}$ does work with it, ${force}$ on ${on}${drawn} and its opposite on ${by}$.",
                on = pair.on,
                by = pair.by,
                point = pair.point,
                force = pair.force,
            )
        }
    })
}

/// How a tree joint's auxiliary speed moves the bodies where constraints close the tree:
/// the joint gives way along its force (or turns about its moment) with the bodies outboard
/// of it, and the dependent rates keep the constraints, so that of the constraint forces
/// only the joint's does work with it. Said in full at the joint's first row.
fn tree_note(derivation: &Derivation, row: &Equation, r: usize) -> Option<String> {
    let model = &derivation.model;
    super::auxiliary_partials::motion(derivation, r)?.rigid?;
    let (site, component) = super::relaxed::relaxed_reaction(derivation, row)?;
    let j = (model.problem.joints.iter()).position(|joint| joint.name.as_str() == site)?;
    let unknown = crate::symbolic::latex(&crate::symbolic::Expr::sym(component.unknown(site)));
    let d = vector_tex(model, &component.direction);
    let point = latex_name(site);
    let rows = derivation.rows.iter();
    let generalized = rows.filter(|x| matches!(x.sum, crate::plan::Sum::Generalized { .. }));
    let first = (generalized.enumerate())
        .find(|(_, x)| {
            super::relaxed::relaxed_reaction(derivation, x).is_some_and(|(s, _)| s == site)
        })
        .map(|(k, _)| k + 1)?;
    let only = format!("of the constraint forces only ${unknown}$ does work with it");
    if first < r {
        return Some(format!("As in row {first}, along ${d}$: {only}."));
    }
    let names = moved_names(derivation, &model.subtree(j));
    // How each body moves, read from the table's lines: the subtree's own motion and
    // the dependent rates' together.
    if let Some(motions) = super::auxiliary_partials::body_motions(derivation, r) {
        let moving: Vec<_> = (motions.into_iter())
            .filter(|(_, m)| *m != Moves::Still)
            .collect();
        let how = motions_words(derivation, &moving, &model.subtree(j));
        let gives = match component.kind {
            ComponentKind::Force => format!("${point}$ slides with $u_{{{r}}}$ along ${d}$"),
            ComponentKind::Moment => {
                format!("{names} turn with $u_{{{r}}}$ about ${d}$ at ${point}$")
            }
        };
        return Some(format!(
            "{gives} and the dependent rates keep the constraints of step 1 (the table's lines for $u_{{{r}}}$): {how}. Of the constraint forces only ${unknown}$ does work with it."
        ));
    }
    Some(match component.kind {
        ComponentKind::Force => format!(
            "${point}$ slides with $u_{{{r}}}$ along ${d}$, {names} with it, and the dependent rates keep the constraints of step 1 (the table's lines for $u_{{{r}}}$): {only}."
        ),
        ComponentKind::Moment => format!(
            "{names} turn with $u_{{{r}}}$ about ${d}$ at ${point}$, and the dependent rates keep the constraints of step 1 (the table's lines for $u_{{{r}}}$): {only}."
        ),
    })
}

/// How each of `motions` moves, in words: `$A$ slides without turning, $B$ moves and
/// turns, and $C$ turns about $Q$` (a body pinned to the ground at a fixed point turns
/// about it, unless it is among the bodies `carried` with the joint that gives way).
fn motions_words(
    derivation: &Derivation,
    motions: &[(BodyId, Moves)],
    carried: &[BodyId],
) -> String {
    let model = &derivation.model;
    let problem = model.problem;
    // Pinned to the ground at a point that stays where it is: not one the speed carries.
    let pinned = |body: BodyId| {
        if carried.contains(&body) {
            return None;
        }
        let j = (problem.joints.iter()).position(|joint| joint.child == body)?;
        let joint = &problem.joints[j];
        let fixed = joint.parent == BodyId::GROUND && model.sites.get(j)?.point.velocity.is_zero();
        fixed.then(|| latex_name(&joint.name))
    };
    let clauses: Vec<String> = (motions.iter())
        .map(|&(body, moves)| {
            let name = latex_name(problem.body_name(body));
            let what = match (moves, pinned(body)) {
                (Moves::Still, _) => "does not move".to_string(),
                (Moves::Turns | Moves::Both, Some(pin)) => format!("turns about ${pin}$"),
                (Moves::Slides, _) => "slides without turning".to_string(),
                (Moves::Turns, None) => "turns about its mass centre".to_string(),
                (Moves::Both, None) => "moves and turns".to_string(),
            };
            format!("${name}$ {what}")
        })
        .collect();
    match clauses.as_slice() {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{}, and {last}", rest.join(", ")),
    }
}

/// `$B$ and $C$`: the moved bodies by name, in the markup.
fn moved_names(derivation: &Derivation, bodies: &[BodyId]) -> String {
    let problem = derivation.model.problem;
    let names: Vec<String> = (bodies.iter())
        .map(|&b| format!("${}$", latex_name(problem.body_name(b))))
        .collect();
    match names.as_slice() {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// The relaxed constraint's force of an auxiliary row where both bodies it joins move with
/// the speed, so that it is inside the moved bodies: its point, the bodies, its vector's
/// name, and the smallest free body of step 2 that draws it on the body it acts on.
struct InsidePair {
    point: String,
    on: String,
    by: String,
    force: String,
    drawn_on: Option<String>,
}

/// The relaxed constraint's force of `row` where it acts between two moved bodies; `None`
/// where it acts on them from outside (or the row relaxes no site).
fn relaxed_inside(derivation: &Derivation, row: &Equation) -> Option<InsidePair> {
    let problem = derivation.model.problem;
    let (site, on, by) = inside(derivation, row)?;
    let drawn_on = drawn_on(derivation, row).map(|set| bodies_tex(derivation, &set));
    let name = |b: BodyId| latex_name(problem.body_name(b));
    let point = latex_name(&site);
    Some(InsidePair {
        force: format!("\\mathbf{{F}}^{{{point}}}"),
        point,
        on: name(on),
        by: name(by),
        drawn_on,
    })
}

/// The site of `row`'s relaxed force, the body it acts on and the body that exerts it,
/// where both are among the row's bodies.
fn inside(derivation: &Derivation, row: &Equation) -> Option<(String, BodyId, BodyId)> {
    let model = &derivation.model;
    let problem = model.problem;
    if !matches!(row.sum, crate::plan::Sum::Generalized { .. }) {
        return None;
    }
    let site = row.unknowns.iter().find_map(|u| match u {
        Symbol::Unknown(Unknown::Reaction { site, .. }) => Some(site),
        _ => None,
    })?;
    let index = model
        .sites
        .iter()
        .position(|s| s.name.as_str() == &**site)?;
    let on = super::sense_words::carried_body(problem, index)?;
    let s = &model.sites[index];
    let by = if s.child == on { s.parent } else { s.child };
    if !row.free_body.contains(&on) || !row.free_body.contains(&by) {
        return None;
    }
    Some((site.to_string(), on, by))
}

/// The free body of step 2 that shows an auxiliary row's relaxed force where that force
/// acts between two bodies the row moves (the four-bar's pin at R, inside the moved B + C):
/// the smallest of the other rows' free bodies (and the asked reactions') with the body
/// it acts on and without the body that exerts it, free body C. The plan names it for the
/// row, and the row's own bodies, which do not show the force, are not drawn for it.
pub fn drawn_on(derivation: &Derivation, row: &Equation) -> Option<Vec<BodyId>> {
    let (_, on, by) = inside(derivation, row)?;
    let mut sets: Vec<Vec<BodyId>> = Vec::new();
    for x in &derivation.rows {
        if !x.free_body.is_empty()
            && inside(derivation, x).is_none()
            && !sets.contains(&x.free_body)
        {
            sets.push(x.free_body.clone());
        }
    }
    (super::asked_bodies::with_asked(derivation, sets).into_iter())
        .filter(|set| set.contains(&on) && !set.contains(&by))
        .min_by_key(Vec::len)
}

/// The pin (or contact) at which an auxiliary row's relaxed force acts between two of the
/// bodies the row moves, as LaTeX: the plan names the row's bodies cut there, since the
/// force is inside them taken whole (the four-bar's B + C, cut at R).
pub fn cut_at(derivation: &Derivation, row: &Equation) -> Option<String> {
    inside(derivation, row).map(|(site, _, _)| crate::symbolic::latex_name(&site))
}

/// The first of Kane's rows (1-based) that moves `bodies` together as an auxiliary speed
/// of the tree, where the reactions inside them are first said to drop out.
fn first_row_inside(derivation: &Derivation, bodies: &[BodyId]) -> Option<usize> {
    let rows = derivation.rows.iter();
    let generalized = rows.filter(|row| matches!(row.sum, crate::plan::Sum::Generalized { .. }));
    let speeds = super::kane::speed_rows(derivation);
    generalized
        .enumerate()
        .find(|(k, row)| *k >= speeds && row.free_body == bodies)
        .map(|(k, _)| k + 1)
}

/// The mass centres' velocities of `bodies` with `gain` added, as step 4 writes them,
/// `{}^{N}\mathbf{v}^{P_1^*} = L_1 \dot{q}_1 \hat{…}_x + u_3\, \hat{…}_y`, and a bob's
/// chained from the centre before it as step 4 chains it; `None` when one would take more
/// than a line.
fn augmented_centres(derivation: &Derivation, bodies: &[BodyId], gain: &str) -> Option<String> {
    let model = &derivation.model;
    let mut written = Vec::new();
    for &b in bodies {
        let v = &model.bodies[b.0].center.velocity;
        let name = super::tex::centre_tex(model, b);
        // Chained from its parent's centre as step 4 writes it: from a centre written
        // before it, which has the give-way already, or from one that does not move with it.
        let text = if let Some((parent, chained)) =
            super::kinematics::velocity_from_parent_centre(model, b)
        {
            if bodies.contains(&parent) {
                format!("{{}}^{{N}}\\mathbf{{v}}^{{{name}}} = {chained}")
            } else {
                format!("{{}}^{{N}}\\mathbf{{v}}^{{{name}}} = {chained} + {gain}")
            }
        } else if v.is_zero() {
            format!("{{}}^{{N}}\\mathbf{{v}}^{{{name}}} = {gain}")
        } else {
            let own = super::tex::shortest_tex(model, v, b);
            format!("{{}}^{{N}}\\mathbf{{v}}^{{{name}}} = {own} + {gain}")
        };
        if crate::render::printed_width(&text) as f64 > crate::render::LINE_SYMBOLS {
            return None;
        }
        written.push(text);
    }
    Some(written.join(",\\; "))
}

/// The number of Kane's first auxiliary row (1-based) that brings in a reaction of the
/// joint `site` of `kind` on the same free body as `row`.
fn first_row_at(
    derivation: &Derivation,
    row: &Equation,
    site: &str,
    kind: ComponentKind,
) -> Option<usize> {
    let speeds = super::kane::speed_rows(derivation);
    let brings_in = |u: &Symbol| {
        matches!(u, Symbol::Unknown(Unknown::Reaction { site: s, component })
            if &**s == site && component.kind == kind)
    };
    derivation
        .rows
        .iter()
        .filter(|x| matches!(x.sum, crate::plan::Sum::Generalized { .. }))
        .enumerate()
        .skip(speeds)
        .find(|(_, x)| x.free_body == row.free_body && x.unknowns.iter().any(brings_in))
        .map(|(i, _)| i + 1)
}

/// The joints both of whose bodies are among `bodies`, by name in LaTeX.
fn joints_inside(derivation: &Derivation, bodies: &[BodyId]) -> Vec<String> {
    derivation
        .model
        .problem
        .joints
        .iter()
        .filter(|joint| bodies.contains(&joint.parent) && bodies.contains(&joint.child))
        .map(|joint| latex_name(&joint.name))
        .collect()
}
