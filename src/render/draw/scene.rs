//! One picture as a scene in `N`'s coordinates: shapes, marked points and arrows. The
//! layout projects it once; the SVG and TikZ exporters only write what the layout placed.

use super::numbers::P3;

/// What an arrow stands for (`data-kind` in the SVG).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The weight of a body.
    Gravity,
    /// A spring between two points.
    Spring,
    /// A damper between two points.
    Damper,
    /// An applied force or torque.
    Load,
    /// A joint spring, joint damper or actuator.
    JointLoad,
    /// An unknown reaction component.
    Reaction,
    /// The kinetic diagram's `m a*` and `I α`.
    Inertia,
}

impl Kind {
    /// The name written in `data-kind`.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Gravity => "gravity",
            Kind::Spring => "spring",
            Kind::Damper => "damper",
            Kind::Load => "load",
            Kind::JointLoad => "joint-load",
            Kind::Reaction => "reaction",
            Kind::Inertia => "inertia",
        }
    }
}

/// A label: its plain form (`F^O_x`, as `data-label` carries it) and its LaTeX.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// Plain text: `^` and `_` mark a superscript and a subscript.
    pub plain: String,
    /// LaTeX math, without `$`.
    pub tex: String,
}

impl Label {
    /// A label from LaTeX math, its plain form derived.
    pub fn from_tex(tex: &str) -> Label {
        Label {
            plain: plain_of(tex),
            tex: tex.to_string(),
        }
    }

    /// A label of plain words (user text), set upright in LaTeX.
    pub fn text(text: &str) -> Label {
        Label {
            plain: text.to_string(),
            tex: format!(
                "\\text{{{}}}",
                crate::render::escape::latex(text, crate::render::escape::Lines::One)
            ),
        }
    }
}

/// The plain form of simple LaTeX math: `F^{\mathrm{hub}}_{x}` -> `F^hub_x`. A script
/// with a script inside (a site named `rear_contact`) keeps its braces, read as one run:
/// `F^{\mathrm{rear}_{\mathrm{contact}}}_{n}` -> `F^{rear_contact}_n`.
pub fn plain_of(tex: &str) -> String {
    let mut out = String::new();
    let mut chars = tex.chars().peekable();
    // Open groups, whether each is a script's; where the outermost script group opened in
    // `out`, and whether a script was nested in it.
    let mut groups: Vec<bool> = Vec::new();
    let mut script_next = false;
    let mut outermost: Option<(usize, bool)> = None;
    // An accent (`\dot`, `\ddot`, `\hat`) waiting for its letter: set as the combining
    // mark after it, so that Ḣ keeps its dot.
    let mut accent: Option<char> = None;
    while let Some(c) = chars.next() {
        match c {
            '^' | '_' => {
                if let Some((_, nested)) = outermost.as_mut() {
                    *nested = true;
                }
                script_next = true;
                out.push(c);
                continue;
            }
            '{' => {
                if script_next && outermost.is_none() {
                    outermost = Some((out.len(), false));
                }
                groups.push(script_next);
            }
            '}' => {
                groups.pop();
                let closes = outermost.is_some() && !groups.iter().any(|&script| script);
                if let (true, Some((start, nested))) = (closes, outermost) {
                    if nested {
                        out.insert(start, '{');
                        out.push('}');
                    }
                    outermost = None;
                }
            }
            '\\' => {
                let mut command = String::new();
                while let Some(&n) = chars.peek() {
                    if n.is_ascii_alphabetic() {
                        command.push(n);
                        chars.next();
                    } else {
                        break;
                    }
                }
                if command.is_empty() {
                    // `\,` and friends: a space; `\{`: the character.
                    match chars.next() {
                        Some(',' | ';' | ' ' | '!') | None => out.push(' '),
                        Some(other) => out.push(other),
                    }
                    continue;
                }
                match greek(&command) {
                    Some(letter) => {
                        out.push(letter);
                        out.extend(accent.take());
                    }
                    None if matches!(command.as_str(), "dot" | "ddot" | "hat") => {
                        accent = Some(match command.as_str() {
                            "dot" => '\u{307}',
                            "ddot" => '\u{308}',
                            _ => '\u{302}',
                        });
                    }
                    None if matches!(command.as_str(), "cdot" | "times") => out.push(' '),
                    // \mathrm, \mathbf, \hat, \left, \right, \text: only shape the text.
                    None => {}
                }
            }
            _ => {
                out.push(c);
                if !c.is_whitespace() {
                    out.extend(accent.take());
                }
            }
        }
        script_next = false;
    }
    out.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn greek(name: &str) -> Option<char> {
    const TABLE: [(&str, char); 26] = [
        ("ell", 'ℓ'),
        ("alpha", 'α'),
        ("beta", 'β'),
        ("gamma", 'γ'),
        ("delta", 'δ'),
        ("epsilon", 'ε'),
        ("zeta", 'ζ'),
        ("eta", 'η'),
        ("theta", 'θ'),
        ("kappa", 'κ'),
        ("lambda", 'λ'),
        ("mu", 'μ'),
        ("nu", 'ν'),
        ("xi", 'ξ'),
        ("pi", 'π'),
        ("rho", 'ρ'),
        ("sigma", 'σ'),
        ("tau", 'τ'),
        // As LaTeX and MathML set them: `\phi` is ϕ, `\varphi` φ.
        ("phi", 'ϕ'),
        ("varphi", 'φ'),
        ("chi", 'χ'),
        ("psi", 'ψ'),
        ("omega", 'ω'),
        ("Gamma", 'Γ'),
        ("Omega", 'Ω'),
        ("Phi", 'Φ'),
    ];
    TABLE.iter().find(|(n, _)| *n == name).map(|(_, c)| *c)
}

/// A point the acceptance markup names: `joint-O`, `cm-A`, `origin-A`, `point-P`.
#[derive(Clone, Debug, PartialEq)]
pub struct Marker {
    /// The id, unique in a picture.
    pub id: String,
    /// Where it is.
    pub at: P3,
    /// How it is drawn.
    pub role: Role,
    /// The caption beside it (`O`, `A*`), if any.
    pub caption: Option<Label>,
    /// The names of the bodies it belongs to (a joint's two, a mass centre's one): its
    /// caption stands on their side, out of any other body it lies against.
    pub on: Vec<String>,
}

/// How a marked point is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// A joint's point: the joint symbol is drawn separately, the marker is small.
    Joint,
    /// A mass center: the quartered circle.
    Center,
    /// A body origin or a declared point: a dot.
    Point,
}

/// What a body is drawn as (`data-shape` in the SVG).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BodyKind {
    /// A slender body: a thick line.
    Rod,
    /// A wheel or disc.
    Disc,
    /// A block under a contact: a closed outline.
    Block,
    /// A particle: a dot.
    Particle,
    /// Any other body: its outline.
    Outline,
}

impl BodyKind {
    /// The name written in `data-shape`.
    pub fn name(self) -> &'static str {
        match self {
            BodyKind::Rod => "rod",
            BodyKind::Disc => "disc",
            BodyKind::Block => "block",
            BodyKind::Particle => "particle",
            BodyKind::Outline => "outline",
        }
    }
}

/// A shape drawn in `N`'s coordinates (sizes in picture units where it says so).
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// One body's shapes, grouped so that a picture (or an animation) can find the body.
    Body {
        /// The body's name.
        name: String,
        /// What it is drawn as.
        kind: BodyKind,
        /// Its shapes.
        parts: Vec<Shape>,
    },
    /// A wheel: the disc of `radius` about `center` perpendicular to the unit `normal`,
    /// lightly filled, with a spoke towards the unit `mark` (fixed in the body) that shows
    /// it turning.
    Wheel {
        /// The centre.
        center: P3,
        /// The unit normal of the disc's plane.
        normal: P3,
        /// The radius.
        radius: f64,
        /// The unit direction of the spoke, fixed in the body.
        mark: P3,
    },
    /// A massless link to a particle: a thin line.
    LightRod {
        /// One end.
        from: P3,
        /// The other end.
        to: P3,
    },
    /// A surface a body rolls on: a line through `at` along `along` (a vector, its half
    /// length); when `fixed` in `N`, hatched on the side opposite the unit `up` as the
    /// ground is, else plain, the face of the body that carries it.
    Surface {
        /// The line's middle.
        at: P3,
        /// Half the line, as a vector.
        along: P3,
        /// The unit side away from the hatching.
        up: P3,
        /// Whether the surface is fixed in `N` (hatched).
        fixed: bool,
    },
    /// A patch of a floor fixed in `N` (3D) that bodies roll on: a parallelogram through
    /// the corners, lightly filled and hatched, seen from the side of the unit `up`.
    Floor {
        /// The parallelogram's corners, in order.
        corners: [P3; 4],
        /// The unit side it is seen from.
        up: P3,
    },
    /// A circle fixed in `N` that a disc rolls on or, `inside`, in (a gear's fixed partner,
    /// a cylinder): hatched on the side away from the disc.
    Track {
        /// The centre.
        center: P3,
        /// The unit normal of the circle's plane.
        normal: P3,
        /// The radius.
        radius: f64,
        /// Whether the disc rolls inside it.
        inside: bool,
    },
    /// A rod: a thick line through the points.
    Bar(Vec<P3>),
    /// A block: a closed outline, lightly filled.
    Polygon(Vec<P3>),
    /// A disc or sphere outline, a closed curve given by its points.
    Outline(Vec<P3>),
    /// A particle.
    Dot(P3),
    /// A pin (revolute) joint: a hollow circle.
    Pin(P3),
    /// A slider (prismatic, cylindrical) joint: a sleeve along the unit `axis`.
    Slider {
        /// The sleeve's middle.
        at: P3,
        /// The unit axis it slides along.
        axis: P3,
    },
    /// A ball (spherical, universal) joint.
    Ball(P3),
    /// A welded joint.
    Weld(P3),
    /// Ground at a point, on the side opposite the unit `up`: a rail of half length
    /// `along` (a vector), or a small support when `along` is zero.
    Ground {
        /// The point supported.
        at: P3,
        /// Half the rail, as a vector (zero for a small support).
        along: P3,
        /// The unit side away from the ground.
        up: P3,
    },
    /// A spring as a zig-zag, `lane` steps to the side of the line between its ends when
    /// it shares them with others (the solution stage gives each its lane).
    Spring {
        /// One end.
        from: P3,
        /// The other end.
        to: P3,
        /// Its lane, in steps to the side.
        lane: f64,
    },
    /// A damper as a dashpot, likewise.
    Damper {
        /// One end.
        from: P3,
        /// The other end.
        to: P3,
        /// Its lane, in steps to the side.
        lane: f64,
    },
    /// Unit vectors at a frame's origin (`None`: in a corner of the picture), with labels.
    Triad {
        /// The frame's origin, or `None` for a corner of the picture.
        origin: Option<P3>,
        /// Each unit vector with its label.
        axes: Vec<(P3, Label)>,
    },
    /// An angle: an arc about `center` from unit `from`, turning by `angle` about unit `axis`.
    Angle {
        /// The arc's centre.
        center: P3,
        /// The unit direction the angle is measured from.
        from: P3,
        /// The unit axis it turns about.
        axis: P3,
        /// The angle, in radians.
        angle: f64,
        /// The angle's name.
        label: Label,
    },
    /// A distance: a dimension line from `from` to `to`.
    Distance {
        /// Where the distance starts.
        from: P3,
        /// Where it ends.
        to: P3,
        /// The distance's name.
        label: Label,
    },
    /// A velocity the problem names (a starting speed `v_0`): a short arrow from `at`
    /// along the unit `direction`, with its symbol.
    Velocity {
        /// Where it is (a mass centre).
        at: P3,
        /// Which way it points.
        direction: P3,
        /// Its symbol.
        label: Label,
    },
    /// A thin dashed line (a reference direction).
    Dashed {
        /// One end.
        from: P3,
        /// The other end.
        to: P3,
    },
}

/// A force or couple to draw as an arrow.
#[derive(Clone, Debug, PartialEq)]
pub struct Arrow {
    /// What it stands for.
    pub kind: Kind,
    /// Its symbol.
    pub label: Label,
    /// The id of the marker it acts at.
    pub at_id: String,
    /// Where it acts.
    pub at: P3,
    /// The direction it acts in (a force) or the moment vector (a couple), in `N`.
    pub direction: P3,
    /// A couple rather than a force.
    pub couple: bool,
}

/// One picture.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scene {
    /// The caption above the picture.
    pub title: String,
    /// Planar (drawn in the N.x–N.y plane).
    pub planar: bool,
    /// The shapes, drawn first.
    pub shapes: Vec<Shape>,
    /// The marked points.
    pub markers: Vec<Marker>,
    /// The arrows.
    pub arrows: Vec<Arrow>,
    /// The kinetic diagram drawn beside it: its shapes and arrows.
    pub kinetic: Option<(Vec<Shape>, Vec<Arrow>)>,
    /// Gravity's direction: straight down the page in a planar picture, and down the
    /// page in the isometric view of a spatial one.
    pub down: Option<P3>,
    /// A line under the picture saying how arrows are scaled.
    pub legend: String,
    /// The largest extent of the system in the picture, in px ([`super::fit::CONTENT`]
    /// unless the handout has many pictures of this kind to keep short).
    pub content: f64,
}

#[cfg(test)]
mod tests {
    use super::plain_of;

    #[test]
    fn plain_labels_follow_the_printed_symbols() {
        assert_eq!(plain_of("F^{O}_{x}"), "F^O_x");
        assert_eq!(plain_of("M^{\\mathrm{hub}}_{2}"), "M^hub_2");
        assert_eq!(plain_of("m_{1} g"), "m_1 g");
        assert_eq!(plain_of("I^{A} \\alpha^{A}"), "I^A α^A");
        assert_eq!(
            plain_of("F^{\\mathrm{rear}_{\\mathrm{contact}}}_{n}"),
            "F^{rear_contact}_n"
        );
        // An overdot stays on its letter.
        assert_eq!(plain_of("\\dot{\\mathbf{H}}^{O}"), "H\u{307}^O");
    }
}
