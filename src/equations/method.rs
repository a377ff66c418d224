//! The equation-forming [`Method`]: its name on the command line and as a course writes it.

/// The equation-forming method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Contact + distance + inertia forces = 0, about any point.
    MotionLaw,
    /// Every body a free body; all reactions unknown.
    NewtonEuler,
    /// Generalized active plus inertia forces.
    Kane,
    /// Lagrange's equations: `d/dt(∂L/∂q̇_r) − ∂L/∂q_r = Q_r`, with multipliers.
    Lagrange,
}

impl Method {
    /// Every method.
    pub const ALL: [Method; 4] = [
        Method::MotionLaw,
        Method::NewtonEuler,
        Method::Kane,
        Method::Lagrange,
    ];

    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Method::MotionLaw => "motion-law",
            Method::NewtonEuler => "newton-euler",
            Method::Kane => "kane",
            Method::Lagrange => "lagrange",
        }
    }

    /// The name as a course writes it.
    pub fn title(self) -> &'static str {
        match self {
            Method::MotionLaw => "the Motion Law",
            Method::NewtonEuler => "Newton–Euler",
            Method::Kane => "Kane's method",
            Method::Lagrange => "Lagrange's equations",
        }
    }
}
