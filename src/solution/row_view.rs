//! Step 5: one row as the worked solution writes it: as formed (the Motion Law's groups, or
//! Kane's F_r and F*_r), then simplified, with its heading.

use super::long::{coefficient_form, named_inertia_group, LONG_EQUATION, MOST_INERTIA_TERMS};
use super::on_constraint::on_the_constraints;
use super::tex::{bodies_name, initial_sign, unknowns_tex, uses_shown, ACCELERATION_LEVEL};
use crate::equations::Derivation;
use crate::plan::{Equation, Sum};
use crate::render::context::Equation as EquationView;
use crate::render::text::Math;
use crate::symbolic::{
    as_shown, latex, latex_collected, linear_split, roots_of_squares, simplify, Expr, Symbol,
};

fn group_tex(e: &Expr) -> String {
    if e.is_zero() {
        return "0".into();
    }
    let text = latex(e);
    if e.terms().len() > 1 {
        // Like terms summed, as a student finishes them: −m1 g − m2 g is −g (m1 + m2).
        let collected = latex_collected(e);
        if one_product(&collected) {
            return collected;
        }
        format!("\\left[{text}\\right]")
    } else {
        text
    }
}

/// Whether LaTeX `text` is one product: no `+` or `-` outside brackets and braces but a
/// leading sign.
fn one_product(text: &str) -> bool {
    let mut depth = 0i32;
    for (i, c) in text.char_indices() {
        match c {
            '(' | '[' | '{' => depth += 1,
            ')' | ']' | '}' => depth -= 1,
            '+' | '-' if depth == 0 && i > 0 => return false,
            _ => {}
        }
    }
    true
}

/// How many of Kane's rows are the independent speeds' (before the auxiliary speeds').
fn speeds_of(derivation: &Derivation) -> usize {
    derivation
        .dependent_speeds
        .as_ref()
        .map_or(0, |speeds| speeds.independent.len())
}

/// Kane's row `r`: `F_r` and `F*_r` apart (`F̃_r` and `F̃*_r` where formed with the
/// constrained partial velocities), `F*_r` by each body's dot products or contribution
/// where that is what a student writes.
fn kane_forces(
    derivation: &Derivation,
    row: &Equation,
    r: usize,
    by_name: bool,
    shown: &impl Fn(&Expr) -> Expr,
) -> (String, String) {
    let (mut active_tex, mut inertia_tex) =
        super::kane::generalized_forces(&row.groups, r, !by_name, shown);
    let independent = derivation.dependent_speeds.as_ref();
    if independent.is_some() {
        // Formed with the constrained partial velocities: F̃_r and F̃*_r.
        let tilde = |t: String| {
            t.replacen("F_{", "\\tilde{F}_{", 1)
                .replacen("F^{*}_{", "\\tilde{F}^{*}_{", 1)
        };
        (active_tex, inertia_tex) = (tilde(active_tex), tilde(inertia_tex));
    }
    let products = if independent.is_some() {
        // Formed with the constrained partial velocities, the dependent accelerations
        // replaced where they enter.
        super::kane_tilde::inertia_dot_products(derivation, r, &row.groups, &inertia_tex, shown)
    } else {
        super::kane_dots::inertia_dot_products(derivation, r, &inertia_tex, shown)
    };
    if let Some(products) = products {
        // Each body's dot products multiplied out: what a student writes.
        inertia_tex = products;
    } else if inertia_tex.contains("\\text{") || independent.is_some() {
        // Each body's contribution apart: what a student sums, where the whole is too
        // long beside the row's sum or is formed with the constrained partial velocities.
        if let Some(by_body) =
            super::kane_bodies::inertia_by_body(derivation, r, &inertia_tex, shown)
        {
            inertia_tex = by_body;
        }
    }
    (active_tex, inertia_tex)
}

/// The forces an auxiliary speed's row is for (not the friction, which works with the slip
/// rates and may be in it too), and why it is brought in: a normal force the sliding law
/// needs, or a reaction asked for.
fn auxiliary_forces(derivation: &Derivation, row: &Equation) -> (Vec<Symbol>, &'static str) {
    let friction = crate::equations::friction_forces(&derivation.model);
    let forces: Vec<Symbol> = (row.unknowns.iter())
        .filter(|u| matches!(u, Symbol::Unknown(_)) && !friction.contains(u))
        .cloned()
        .collect();
    let normals = crate::equations::normal_forces(&derivation.model);
    let along = if forces.iter().all(|f| normals.contains(f)) {
        "the normal force, which the sliding law needs"
    } else {
        "the reaction asked for"
    };
    (forces, along)
}

/// Kane's row `r`: its heading and the words beside it (which speed it is for), the row
/// solved for its one force where an auxiliary speed brings that force in (`simplified`,
/// not where the row is written `by_name`), and the note on an augmented row.
fn kane_heading(
    derivation: &Derivation,
    row: &Equation,
    r: usize,
    simplified: &Expr,
    by_name: bool,
) -> ((String, String), String, String) {
    let problem = derivation.model.problem;
    let mut solved_tex = String::new();
    let mut augmented_note = String::new();
    let independent = derivation.dependent_speeds.as_ref();
    let heading = if let Some(speeds) = independent.filter(|s| r <= s.independent.len()) {
        (
            format!(
                "r = {r}\\colon\\; {}",
                super::independent::speed_tex(derivation, speeds, r - 1)
            ),
            "(an independent speed)".to_string(),
        )
    } else if independent.is_some() {
        let (forces, along) = auxiliary_forces(derivation, row);
        if !by_name {
            // One force in the row: solved for it, as a textbook ends an auxiliary row.
            solved_tex = solved_for_reaction(simplified, &forces);
        }
        let friction = crate::equations::friction_forces(&derivation.model);
        let slides = row.unknowns.iter().any(|u| friction.contains(u));
        let brings = if slides {
            "; friction works with it too"
        } else {
            ""
        };
        // Said in full at the first auxiliary speed for a reason; later ones refer to it.
        let first = (derivation.rows.iter())
            .filter(|x| matches!(x.sum, Sum::Generalized { .. }))
            .enumerate()
            .skip(speeds_of(derivation))
            .find(|(_, x)| auxiliary_forces(derivation, x).1 == along)
            .map_or(r, |(i, _)| i + 1);
        let why = if r == first {
            format!("(an auxiliary speed along {along}{brings})")
        } else {
            format!("(an auxiliary speed, as in row {first}{brings})")
        };
        augmented_note = super::auxiliary::moved_note(derivation, row, r).unwrap_or_default();
        (
            format!(
                "r = {r}\\colon\\; {}",
                super::tex::auxiliary_speed_tex(r, &unknowns_tex(&forces))
            ),
            why,
        )
    } else if r <= problem.coordinates.len() {
        // The speeds are named once where they are chosen: a row of a rate of a
        // coordinate, u_r = q̇_r, is headed by r alone, one of a named speed by its name.
        let heading = match problem.has_speeds() {
            true => format!(
                "r = {r}\\colon\\; {}",
                super::kane::speed_tex(derivation, r - 1)
            ),
            false => format!("r = {r}"),
        };
        (heading, String::new())
    } else {
        augmented_note = super::auxiliary::augmented_note(derivation, row, r).unwrap_or_default();
        let reactions: Vec<Symbol> = row
            .unknowns
            .iter()
            .filter(|u| matches!(u, Symbol::Unknown(_)))
            .cloned()
            .collect();
        if !by_name {
            solved_tex = solved_for_reaction(simplified, &reactions);
        }
        (
            format!(
                "r = {r}\\colon\\; {}",
                super::tex::auxiliary_speed_tex(r, &unknowns_tex(&reactions))
            ),
            format!(
                "(an auxiliary speed: it moves {} against the joint)",
                bodies_name(problem, &row.free_body)
            ),
        )
    };
    (heading, solved_tex, augmented_note)
}

/// Step 5: one row, grouped as the Motion Law groups it and simplified.
pub fn equation_view(derivation: &Derivation, row: &Equation) -> EquationView {
    let sign = initial_sign(&derivation.model);
    // Kane's rows write F_r and F*_r instead of the groups, Lagrange's the derivatives of
    // L (see below): not formed.
    let kane_row = matches!(row.sum, Sum::Generalized { .. })
        && super::kane::row_number(derivation, row).is_some();
    // Kane's rows with dependent speeds: finished with the position constraints.
    let on_loop = kane_row
        .then(|| super::kane_loop::OnTheLoop::of(derivation))
        .flatten();
    let shown = |e: &Expr| {
        let e = if uses_shown(derivation) {
            as_shown(e)
        } else {
            e.clone()
        };
        let e = roots_of_squares(&e, &sign);
        match &on_loop {
            Some(on_loop) => on_loop.reduce(&e),
            None => e,
        }
    };
    let lagrange_text = super::lagrange::row_text(derivation, row, &shown);
    let mut grouped_tex = match kane_row || lagrange_text.is_some() {
        true => String::new(),
        false => grouped_row(derivation, row, &shown),
    };
    // On the motion: a coordinate a constraint holds (h = R) written as its value.
    let held = super::on_constraint::held_coordinates(&derivation.model);
    let index = derivation.rows.iter().position(|r| std::ptr::eq(r, row));
    // Far too long as formed to come out short: written by name without simplifying.
    let surely_long = index.is_some() && super::long::surely_long(&row.expression);
    let mut simplified = match surely_long {
        true => Expr::int(0),
        false => shown(&on_the_constraints(&simplify(&row.expression), &held)),
    };
    let mut simplified_note = String::new();
    if index.is_some_and(|i| super::kane::sign_changed(derivation, i)) {
        // F*_r is minus the mass matrix times q̈: written with the signs changed, the
        // equation reads M q̈ = …, with the mass matrix positive.
        simplified = -simplified;
        // Said in full once; the rows after it refer to it.
        let first =
            index.is_some_and(|i| !(0..i).any(|k| super::kane::sign_changed(derivation, k)));
        simplified_note = if first {
            "Their sum set to zero, Kane's equation, simplified and rearranged:"
        } else {
            "Kane's equation, rearranged likewise:"
        }
        .into();
    }
    let mut simplified_tex = match surely_long {
        true => String::new(),
        false => format!("{} = 0", latex_collected(&simplified)),
    };
    let mut by_name = false;
    if surely_long || simplified_tex.len() > LONG_EQUATION {
        // Too long to read: the same row with the coefficients of the matrix form by name.
        if let Some(i) = index {
            simplified_tex = coefficient_form(derivation, i);
            simplified_note = "With the coefficients of the matrix form below:".into();
            by_name = true;
        }
    }
    let mut label_tex = index
        .map(|i| super::row_names::row_heading_tex(derivation, i))
        .unwrap_or_default();
    let mut label = if matches!(row.sum, Sum::Constraint { .. }) {
        ACCELERATION_LEVEL.to_string()
    } else {
        String::new()
    };
    let (mut active_tex, mut inertia_tex) = (String::new(), String::new());
    let mut augmented_note = String::new();
    let mut solved_tex = String::new();
    if let (Sum::Generalized { .. }, Some(r)) = (&row.sum, super::kane::row_number(derivation, row))
    {
        // Kane's row: F_r and F_r* apart, then their sum, which is the row as formed.
        (active_tex, inertia_tex) = kane_forces(derivation, row, r, by_name, &shown);
        grouped_tex = String::new();
        ((label_tex, label), solved_tex, augmented_note) =
            kane_heading(derivation, row, r, &simplified, by_name);
    }
    let mut lagrange_tex = Vec::new();
    if let Some(text) = lagrange_text {
        // Lagrange's row: the derivatives of L and the generalized force, then the row.
        (label_tex, label, lagrange_tex) = (text.label_tex, text.label, text.lines);
        (grouped_tex, active_tex, inertia_tex) = (String::new(), String::new(), String::new());
        augmented_note = text.intro;
        if !by_name {
            simplified_note = text.note;
        }
        if !by_name && !solved_tex.is_empty() {
            // A relaxed joint's equation solved for its reaction, in Lagrange's words.
            simplified_tex = std::mem::take(&mut solved_tex);
            let note = simplified_note.trim_end_matches(':');
            simplified_note = format!("{note}, solved for the reaction:");
        }
    }
    if matches!(row.sum, Sum::Constraint { .. }) && !by_name {
        // A constraint differentiated is one sum with no groups: as formed it is the
        // simplified row in another order, so it is written once; a closure's is the
        // component of its vector loop, which is written first.
        grouped_tex.clear();
        if let Some(vector_loop) = super::loops::closure_loop_tex(derivation, row) {
            grouped_tex = vector_loop;
            simplified_note = super::loops::component_note();
        }
    }
    // The inertia terms written out, cross products and dot products, as a student does.
    let same = grouped_tex == simplified_tex || same_terms(&grouped_tex, &simplified_tex);
    let written_tex = super::written_out::written_out_shown(derivation, row, &shown)
        .filter(|_| !same || matches!(row.sum, Sum::Moment { .. }))
        .filter(|_| !grouped_tex.is_empty())
        .map(|w| w.tex)
        // Its components as the row prints them, a root of a square taken by the initial
        // sign; one left (no sign to take it by) where the row has none goes without.
        .filter(|tex| !tex.contains("\\sqrt") || grouped_tex.contains("\\sqrt"))
        .unwrap_or_default();
    // Formed already in its simplest form, or with the same terms in another order: written
    // once, after its terms written out if any (a moment row's r × F; a force row none).
    // A constraint differentiated with nothing formed before it (no vector loop) is
    // written once too: "Simplified:" would lead a display with nothing above it.
    let alone = matches!(row.sum, Sum::Constraint { .. }) && grouped_tex.is_empty();
    let bare = (same || alone) && simplified_note.is_empty() && written_tex.is_empty();
    if same && simplified_note.is_empty() {
        grouped_tex.clear();
    }
    EquationView {
        label,
        augmented_note: augmented_note.into(),
        label_tex: Math::from(label_tex),
        grouped_tex: Math::from(grouped_tex),
        written_tex: Math::from(written_tex),
        simplified_tex: Math::from(simplified_tex),
        simplified_note,
        bare,
        by_name,
        active_tex: Math::from(active_tex),
        inertia_tex: Math::from(inertia_tex),
        solved_tex: Math::from(solved_tex),
        lagrange_tex: Math::all(lagrange_tex),
    }
}

/// Whether two rows `… = 0` as LaTeX hold the same signed terms, in any order and with a
/// group's brackets taken away (`[F - G] - m g = 0` and `-m g + F - G = 0`); a group after
/// a minus sign is not opened, so such a row is never said to be the same.
fn same_terms(a: &str, b: &str) -> bool {
    fn terms(row: &str) -> Option<Vec<String>> {
        let left = (row.strip_suffix(" = 0")?)
            .replace("\\left[", "[")
            .replace("\\right]", "]");
        if left.contains("- [") || left.contains("-[") {
            return None;
        }
        let flat: Vec<char> = left.chars().filter(|c| !matches!(c, '[' | ']')).collect();
        let (mut out, mut term, mut depth, mut sign) = (Vec::new(), String::new(), 0i32, '+');
        for (k, &c) in flat.iter().enumerate() {
            match c {
                '{' | '(' => depth += 1,
                '}' | ')' => depth -= 1,
                _ => {}
            }
            let at_top = depth == 0 && (c == '+' || c == '-');
            // A sign between terms is spaced; one at the very start opens the first term.
            let between = flat.get(k + 1) == Some(&' ') || term.trim().is_empty();
            if at_top && between {
                if !term.trim().is_empty() {
                    out.push(format!("{sign}{}", term.trim()));
                }
                (term, sign) = (String::new(), c);
            } else {
                term.push(c);
            }
        }
        out.push(format!("{sign}{}", term.trim()));
        out.sort();
        Some(out)
    }
    !a.is_empty() && terms(a).is_some_and(|t| Some(t) == terms(b))
}

/// The row as formed: contact + distance + inertia forces + inertia torques, each group
/// as it is shortest; too long, the same sum in vector form.
fn grouped_row(derivation: &Derivation, row: &Equation, shown: &dyn Fn(&Expr) -> Expr) -> String {
    let g = &row.groups;
    let g = [&g.contact, &g.distance, &g.inertia_force, &g.inertia_torque].map(shown);
    // Contact + distance + inertia forces + inertia torques, leaving out the empty groups;
    // a long inertia group by the names of step 4; a force group with the identities
    // (sin² + cos² = 1) applied when that is shorter, as the simplified row has them.
    let mut grouped = String::new();
    for (k, e) in g.iter().enumerate().filter(|(_, e)| !e.is_zero()) {
        let inertia = k >= 2;
        let mut written = group_tex(e);
        if !inertia {
            let simpler = group_tex(&simplify(e));
            if simpler.len() < written.len() {
                written = simpler;
            }
            // Reduced by what the constraints keep (x² + y² = (R − r)²), where shorter.
            let kept = group_tex(&super::force_moments::reduced(derivation, simplify(e)));
            if kept.len() < written.len() {
                written = kept;
            }
        } else {
            // An inertia group keeps its terms as formed, unless an identity merges some
            // (R m ẍ s²_θ + R m ẍ c²_θ is R m ẍ): then it is written with it applied.
            let simpler = simplify(e);
            if simpler.terms().len() < e.terms().len() {
                written = group_tex(&simpler);
            }
        }
        let named = (inertia && e.terms().len() > MOST_INERTIA_TERMS)
            .then(|| named_inertia_group(derivation, row, k == 3))
            .flatten()
            .filter(|named| named.len() < written.len());
        let text = named.unwrap_or(written);
        match (grouped.is_empty(), text.strip_prefix('-')) {
            (true, _) => grouped = text,
            (false, Some(rest)) => grouped.push_str(&format!(" - {rest}")),
            (false, None) => grouped.push_str(&format!(" + {text}")),
        }
    }
    if grouped.is_empty() {
        grouped = "0".into();
    }
    let grouped_tex = format!("{grouped} = 0");
    if grouped_tex.len() > LONG_EQUATION {
        // Too long as formed: the same sum in vector form, in the quantities of steps 2 and 4.
        return super::long::vector_form(derivation, row);
    }
    grouped_tex
}

/// An auxiliary speed's row holds one reaction: solved for it, `T^{O} = …`, with the
/// second derivatives of the rows before it known (empty when it holds more, or the
/// solved form would be too long to read).
fn solved_for_reaction(row: &Expr, reactions: &[Symbol]) -> String {
    let [reaction] = reactions else {
        return String::new();
    };
    let Ok((coefficients, rest)) = linear_split(row, std::slice::from_ref(reaction)) else {
        return String::new();
    };
    let coefficient = &coefficients[0];
    if coefficient.is_zero() {
        return String::new();
    }
    let value = simplify(&(-rest / coefficient.clone()));
    let tex = format!(
        "{} = {}",
        latex(&Expr::sym(reaction.clone())),
        latex_collected(&value)
    );
    if tex.len() > LONG_EQUATION {
        String::new()
    } else {
        tex
    }
}

#[cfg(test)]
mod tests {
    use super::{one_product, same_terms};

    #[test]
    fn like_terms_collected_are_one_product_and_unlike_ones_are_not() {
        assert!(one_product("-g (m_{1} + m_{2})"));
        assert!(one_product(
            "-\\frac{L m}{12} (\\ddot{q}_{1} + \\ddot{q}_{2})"
        ));
        assert!(!one_product("-m_{1} g - m_{2} g"));
        assert!(!one_product(
            "2 l F^{P}_{x} c_{\\theta} + 2 l F^{P}_{y} s_{\\theta}"
        ));
    }

    #[test]
    fn a_row_in_another_order_or_without_its_brackets_has_the_same_terms() {
        let grouped = "\\left[F^{O}_{y} - F^{P}_{t}\\right] - m_{A} g = 0";
        assert!(same_terms(grouped, "F^{O}_{y} - F^{P}_{t} - m_{A} g = 0"));
        assert!(same_terms(
            "-r_{B} F^{P}_{t} - I_{B} \\ddot{q}_{B} = 0",
            "-I_{B} \\ddot{q}_{B} - r_{B} F^{P}_{t} = 0"
        ));
        // A sign turned, a term changed, a group after a minus: not the same.
        assert!(!same_terms("a - b = 0", "b - a = 0"));
        assert!(!same_terms("a - b = 0", "a - 2 b = 0"));
        assert!(!same_terms("a - [b - c] = 0", "a - b + c = 0"));
        assert!(!same_terms(
            "-\\frac{a - b}{2} = 0",
            "-\\frac{b - a}{2} = 0"
        ));
    }
}
