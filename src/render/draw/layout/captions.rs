//! The marked points' captions: each waits with the other labels, and two points at one
//! dot are named together there.

use super::super::picture::{Ink, Mark, P2};
use super::super::scene::{Label, Marker, Role};
use super::super::strokes::p2norm;
use super::labels::Beside;
use super::Painter;

/// Two marked points closer than this on the page (px) are one dot.
const ONE_DOT: f64 = 1.0;

impl Painter {
    /// The captions of the marked points wait with the other labels, ahead of the arrows'
    /// (an arrow's label can move out along its arrow; a caption must stay at its point):
    /// a point on a body's edge keeps its caption outside the bodies where it can, a mass
    /// centre beside it.
    pub(super) fn caption_marks(&mut self, markers: &[Marker], marks: &[Mark]) {
        let mut captions = Vec::new();
        self.owners = markers.iter().map(|m| m.on.clone()).collect();
        for (k, (m, mark)) in markers.iter().zip(marks).enumerate() {
            if let Some(caption) = &m.caption {
                // Two points at one dot are named together there, `C*, S`: neither name
                // stands alone at a dot that is the other's too.
                let one_dot = |c: &&mut (P2, f64, Label, Ink, Beside)| {
                    p2norm([c.0[0] - mark.at[0], c.0[1] - mark.at[1]]) < ONE_DOT
                };
                if let Some(named) = captions.iter_mut().find(one_dot) {
                    named.2 = Label::from_tex(&format!("{},\\ {}", named.2.tex, caption.tex));
                    continue;
                }
                let beside = if m.role == Role::Center {
                    Beside::Caption(k)
                } else {
                    Beside::Point(k)
                };
                let toward = -std::f64::consts::FRAC_PI_4;
                captions.push((mark.at, toward, caption.clone(), Ink::Black, beside));
            }
        }
        self.pending.splice(0..0, captions);
    }
}
