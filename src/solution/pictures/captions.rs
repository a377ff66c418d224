//! Points drawn at one spot share one caption: a wheel's mass centre on its axle's pin is
//! named with the pin, `O_A = A*`, rather than as two names crowding one dot (the second
//! pushed off to float beside the body).

use super::numbers::{norm, sub};
use crate::render::draw::{Label, Marker, Role};

/// Merges the caption of each mass centre into that of a captioned joint or point at the
/// same spot (within `1e-9 size`), leaving the centre's mark uncaptioned.
pub fn merge_coincident(markers: &mut [Marker], size: f64) {
    let near = 1e-9 * size.max(1.0);
    for c in 0..markers.len() {
        if markers[c].role != Role::Center {
            continue;
        }
        let Some(centre) = markers[c].caption.clone() else {
            continue;
        };
        let at = markers[c].at;
        let host = (0..markers.len()).find(|&k| {
            k != c
                && markers[k].role != Role::Center
                && markers[k].caption.is_some()
                && norm(sub(markers[k].at, at)) <= near
        });
        let Some(k) = host else {
            continue;
        };
        if let Some(name) = &markers[k].caption {
            markers[k].caption = Some(Label::from_tex(&format!("{} = {}", name.tex, centre.tex)));
            markers[c].caption = None;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn marker(id: &str, at: [f64; 3], role: Role, tex: &str) -> Marker {
        Marker {
            id: id.into(),
            at,
            role,
            caption: Some(Label::from_tex(tex)),
        }
    }

    #[test]
    fn a_centre_on_a_pin_is_named_with_the_pin() {
        let mut markers = vec![
            marker("joint-OA", [0.0, 0.0, 0.0], Role::Joint, "O_{A}"),
            marker("cm-A", [0.0, 0.0, 0.0], Role::Center, "A^*"),
            marker("cm-B", [1.0, 0.0, 0.0], Role::Center, "B^*"),
        ];
        merge_coincident(&mut markers, 1.0);
        let captions: Vec<Option<String>> = (markers.iter())
            .map(|m| m.caption.as_ref().map(|c| c.tex.clone()))
            .collect();
        assert_eq!(
            captions,
            [Some("O_{A} = A^*".into()), None, Some("B^*".into())]
        );
    }
}
