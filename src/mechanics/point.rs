//! The motion of a point: what every site, joint and body carries of one.

use super::vector::Vector;

/// Position, velocity and acceleration of a point in `N`.
#[derive(Clone, Debug, Default)]
pub struct PointMotion {
    /// From `N.o`.
    pub position: Vector,
    /// The velocity in `N`.
    pub velocity: Vector,
    /// The acceleration in `N`.
    pub acceleration: Vector,
}
