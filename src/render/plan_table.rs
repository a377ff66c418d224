//! Step 3's table laid out for LaTeX: each column as wide as what it prints, the unknowns
//! the rest of the line.

use super::context::{PlanColumns, PlanRow};
use super::math_width::symbols;

/// The width of the four columns together, in centimetres: the line less the gaps between
/// columns.
const TABLE_CM: f64 = 16.0;

/// How wide a printed symbol may be at the handout's 10 pt, in centimetres (7 pt): a
/// column set too narrow wraps its entry.
const SYMBOL_CM: f64 = 0.25;

/// The narrowest and widest each of the first three columns may be: at least its heading,
/// at most what the fixed layout gave, beyond which an entry wraps.
const FREE_BODY_CM: (f64, f64) = (1.8, 4.2);
const EQUATION_CM: (f64, f64) = (1.7, 3.0);
const DIRECTION_CM: (f64, f64) = (1.8, 2.8);

/// The columns' widths for `rows`, to a millimetre.
pub fn columns(rows: &[PlanRow]) -> PlanColumns {
    let widest = |entry: fn(&PlanRow) -> &str, (least, most): (f64, f64)| {
        let symbols = rows.iter().map(|r| symbols(entry(r))).fold(0.0, f64::max);
        let cm = (symbols * SYMBOL_CM + 0.2).clamp(least, most);
        (cm * 10.0).ceil() / 10.0
    };
    let free_body_cm = widest(|r| &r.free_body_tex, FREE_BODY_CM);
    let equation_cm = widest(|r| &r.equation_tex, EQUATION_CM);
    // Kane's rows alone name no direction: the table has no such column.
    let direction_cm = match rows.iter().all(|r| r.direction_tex.is_empty()) {
        true => 0.0,
        false => widest(|r| &r.direction_tex, DIRECTION_CM),
    };
    let unknowns_cm =
        ((TABLE_CM - free_body_cm - equation_cm - direction_cm) * 10.0).round() / 10.0;
    PlanColumns {
        free_body_cm,
        equation_cm,
        direction_cm,
        unknowns_cm,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(free_body: &str, equation: &str) -> PlanRow {
        PlanRow {
            free_body_tex: free_body.into(),
            equation_tex: equation.into(),
            direction_tex: "\\hat{\\mathbf{b}}_{x}".into(),
            unknowns_tex: "\\ddot{x}".into(),
        }
    }

    #[test]
    fn single_bodies_leave_the_unknowns_the_room_a_group_needs() {
        let single = columns(&[row("B", "\\sum \\mathbf{F}")]);
        assert_eq!(
            (single.free_body_cm, single.equation_cm, single.direction_cm),
            (1.8, 1.7, 1.8)
        );
        assert_eq!(single.unknowns_cm, 10.7);
        let group = columns(&[row("A + B + C + D + E + G", "\\sum \\mathbf{M}_{O}")]);
        assert_eq!(group.free_body_cm, 4.2);
        assert!(group.unknowns_cm < single.unknowns_cm);
    }

    #[test]
    fn rows_without_a_direction_give_its_room_to_the_unknowns() {
        let mut kane = row("A + B", "F_{1} + F^{*}_{1}");
        kane.direction_tex = "".into();
        let c = columns(&[kane]);
        assert_eq!(c.direction_cm, 0.0);
        assert!((c.free_body_cm + c.equation_cm + c.unknowns_cm - TABLE_CM).abs() < 1e-9);
    }
}
