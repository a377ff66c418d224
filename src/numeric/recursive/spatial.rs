//! Spatial vectors (angular part first, then linear) in a body's own unit vectors, about
//! its origin: the few operations the articulated-body passes need.

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

/// The angular part.
pub(super) fn angular(v: &Vector6<f64>) -> Vector3<f64> {
    v.fixed_rows::<3>(0).into_owned()
}

/// The linear part.
pub(super) fn linear(v: &Vector6<f64>) -> Vector3<f64> {
    v.fixed_rows::<3>(3).into_owned()
}

/// A spatial vector from its two parts.
pub(super) fn join(angular: Vector3<f64>, linear: Vector3<f64>) -> Vector6<f64> {
    Vector6::new(
        angular.x, angular.y, angular.z, linear.x, linear.y, linear.z,
    )
}

/// `v ×` a motion vector `u`.
pub(super) fn cross_motion(v: &Vector6<f64>, u: &Vector6<f64>) -> Vector6<f64> {
    let (w, vl) = (angular(v), linear(v));
    join(
        w.cross(&angular(u)),
        w.cross(&linear(u)) + vl.cross(&angular(u)),
    )
}

/// `v ×*` a force `f`.
pub(super) fn cross_force(v: &Vector6<f64>, f: &Vector6<f64>) -> Vector6<f64> {
    let (w, vl) = (angular(v), linear(v));
    join(
        w.cross(&angular(f)) + vl.cross(&linear(f)),
        w.cross(&linear(f)),
    )
}

/// The cross-product matrix `[a×]`.
pub(super) fn skew(a: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -a.z, a.y, a.z, 0.0, -a.x, -a.y, a.x, 0.0)
}

/// The spatial inertia about a body's origin of mass `m`, mass centre `h` from the origin
/// and central inertia `ic`, all in the body's unit vectors.
pub(super) fn inertia(m: f64, h: &Vector3<f64>, ic: &Matrix3<f64>) -> Matrix6<f64> {
    let hx = skew(h);
    let mut i = Matrix6::zeros();
    i.fixed_view_mut::<3, 3>(0, 0)
        .copy_from(&(ic - hx * hx * m));
    i.fixed_view_mut::<3, 3>(0, 3).copy_from(&(hx * m));
    i.fixed_view_mut::<3, 3>(3, 0).copy_from(&(hx * -m));
    i.fixed_view_mut::<3, 3>(3, 3)
        .copy_from(&(Matrix3::identity() * m));
    i
}

/// The change of coordinates from a parent's frame to a child's whose frame is turned by
/// `e` (child components = `e` × parent components) and whose origin is at `r` from the
/// parent's origin (parent components).
#[derive(Clone, Copy, Debug)]
pub(super) struct Transform {
    pub e: Matrix3<f64>,
    pub r: Vector3<f64>,
}

impl Transform {
    /// A motion vector of the parent, in the child's coordinates about its origin.
    pub fn motion(&self, v: &Vector6<f64>) -> Vector6<f64> {
        let w = angular(v);
        join(self.e * w, self.e * (linear(v) - self.r.cross(&w)))
    }

    /// A force on the child, in the parent's coordinates about its origin (the transpose).
    pub fn force_back(&self, f: &Vector6<f64>) -> Vector6<f64> {
        let force = self.e.transpose() * linear(f);
        join(
            self.e.transpose() * angular(f) + self.r.cross(&force),
            force,
        )
    }

    /// An articulated inertia of the child, in the parent's coordinates: `Xᵀ I X`, by
    /// blocks. With `X = diag(E, E) T`, `T = [1 0; −r× 1]` and the rotated blocks
    /// `[A B; Bᵀ C]`: `[A − B r× + r×(Bᵀ − C r×), B + r× C; (B + r× C)ᵀ, C]`.
    pub fn inertia_back(&self, i: &Matrix6<f64>) -> Matrix6<f64> {
        let (e, et) = (&self.e, self.e.transpose());
        let a = et * i.fixed_view::<3, 3>(0, 0) * e;
        let b = et * i.fixed_view::<3, 3>(0, 3) * e;
        let c = et * i.fixed_view::<3, 3>(3, 3) * e;
        let rx = skew(&self.r);
        let top_right = b + rx * c;
        let top_left = a - b * rx + rx * (b.transpose() - c * rx);
        let mut out = Matrix6::zeros();
        out.fixed_view_mut::<3, 3>(0, 0).copy_from(&top_left);
        out.fixed_view_mut::<3, 3>(0, 3).copy_from(&top_right);
        out.fixed_view_mut::<3, 3>(3, 0)
            .copy_from(&top_right.transpose());
        out.fixed_view_mut::<3, 3>(3, 3).copy_from(&c);
        out
    }
}
