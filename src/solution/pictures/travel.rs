//! A carrier (a rack, a cart) in the motion: drawn as long as the contacts on it travel
//! along it over the whole motion, so that a rack stays under its pinion, in mesh, where
//! the still picture's block (a few wheel diameters) would slide out from under it. The
//! picture is fitted to the motion before: a long rack runs through it.

use super::numbers::{dot, sub, Numbers, P3};
use crate::equations::Derivation;
use crate::mechanics::SiteKind;
use crate::numeric::Frame;
use crate::problem::BodyId;
use crate::render::draw::{Part, Sheet};

/// Stretches the block of each planar carrier among `sheets` (of the bodies `owners`)
/// along its face to reach every place the contacts on it take over `frames`, with the
/// overhang it has at the start past the contact at each end.
pub fn stretch_carriers(
    derivation: &Derivation,
    frames: &[Frame],
    owners: &[BodyId],
    sheets: &mut [Sheet],
) {
    let model = &derivation.model;
    if !model.is_planar() {
        return;
    }
    let contacts: Vec<(usize, BodyId)> = (model.sites.iter().enumerate())
        .filter(|(_, s)| matches!(s.kind, SiteKind::Contact(_)) && s.parent != BodyId::GROUND)
        .map(|(k, s)| (k, s.parent))
        .collect();
    for (site, carrier) in contacts {
        let Some(index) = owners.iter().position(|b| *b == carrier) else {
            continue;
        };
        // Where the contact is on the carrier, in its own axes, at every frame.
        let along: Vec<[f64; 2]> = frames
            .iter()
            .map(|f| {
                let n = Numbers::new(model, f.t, &f.q, &f.rates);
                let origin = n.point_on(carrier, &[0.0; 3]);
                let p = sub(n.vector(&model.sites[site].point.position), origin);
                let axis = |k: usize| {
                    let mut e: P3 = [0.0; 3];
                    e[k] = 1.0;
                    dot(p, n.in_ground(carrier, &e))
                };
                [axis(0), axis(1)]
            })
            .collect();
        for sheet in sheets.iter_mut().filter(|s| s.body == index) {
            for part in &mut sheet.parts {
                if let Part::Outline(corners) = part {
                    if corners.len() == 4 {
                        stretch(corners, &along);
                    }
                }
            }
        }
    }
}

/// A block's corners (face first: the face's two ends, then the far side's) stretched
/// along the face to reach every point of `along` with the overhang the first has.
fn stretch(corners: &mut [[f64; 2]], along: &[[f64; 2]]) {
    let (a, b) = (corners[0], corners[1]);
    let face = [b[0] - a[0], b[1] - a[1]];
    let length = face[0].hypot(face[1]);
    if length <= 0.0 || along.is_empty() {
        return;
    }
    let e = [face[0] / length, face[1] / length];
    let at = |p: [f64; 2]| (p[0] - a[0]) * e[0] + (p[1] - a[1]) * e[1];
    let first = at(along[0]);
    let overhang = first.min(length - first).max(0.0);
    let lo = along.iter().map(|p| at(*p) - overhang).fold(0.0, f64::min);
    let hi = (along.iter())
        .map(|p| at(*p) + overhang)
        .fold(length, f64::max);
    let shift = |p: [f64; 2], s: f64| [p[0] + e[0] * s, p[1] + e[1] * s];
    let (c, d) = (corners[2], corners[3]);
    corners[0] = shift(a, lo);
    corners[1] = shift(a, hi);
    corners[2] = shift(c, hi - length);
    corners[3] = shift(d, lo);
}

#[cfg(test)]
mod tests {
    use super::stretch;

    #[test]
    fn a_block_reaches_every_place_of_its_contact_with_its_first_overhang() {
        // A block 2 long, its contact at 0.5 (overhang 0.5); the contact travels to -3.
        let mut corners = [[0.0, 0.0], [2.0, 0.0], [2.0, -1.0], [0.0, -1.0]];
        stretch(&mut corners, &[[0.5, 0.0], [-1.0, 0.0], [-3.0, 0.0]]);
        assert_eq!(
            corners,
            [[-3.5, 0.0], [2.0, 0.0], [2.0, -1.0], [-3.5, -1.0]]
        );
    }
}
