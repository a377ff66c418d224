//! The collision law at an impact: Newton's restitution along the normal, Coulomb friction
//! along the surface (sticking when the impulse that stops the slip is within μ times the
//! normal impulse, else sliding with μ times it against the slip), solved on the velocity
//! changes of the struck point per unit impulse.
//!
//! Every vector here is in the unit vectors of the body the surface is fixed in.

use nalgebra::{DMatrix, DVector};

/// What the struck point does and how it responds.
#[derive(Clone, Debug)]
pub struct Contact {
    /// The surface's unit normal, towards the body.
    pub normal: [f64; 3],
    /// The point's velocity relative to the surface just before the impact.
    pub before: [f64; 3],
    /// The change of that velocity from the applied impulses alone.
    pub applied: [f64; 3],
    /// Column k: the change of that velocity per unit impulse along unit vector k (x, y,
    /// and z in 3D; the columns given are the directions the impulse may have).
    pub response: Vec<[f64; 3]>,
    /// The coefficient of restitution e.
    pub restitution: f64,
    /// The coefficient of friction μ; `None` for a smooth surface.
    pub friction: Option<f64>,
}

/// Sticking or sliding during the impact.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// A smooth surface: no tangential impulse.
    Smooth,
    /// The tangential impulse stops the slip, within μ times the normal impulse.
    Stick,
    /// The tangential impulse is μ times the normal one, against the slip.
    Slide,
    /// The applied impulses carry the point off the surface: no collision impulse.
    Separate,
}

impl Mode {
    /// The name in the output.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Smooth => "smooth",
            Mode::Stick => "stick",
            Mode::Slide => "slide",
            Mode::Separate => "separate",
        }
    }
}

/// The collision's impulse.
#[derive(Clone, Debug, PartialEq)]
pub struct CollisionImpulse {
    /// Its components along the surface body's unit vectors.
    pub components: [f64; 3],
    /// Along the normal (never negative).
    pub normal: f64,
    /// Its tangential part, in magnitude.
    pub tangential: f64,
    /// What the impact did.
    pub mode: Mode,
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn combo(terms: &[(f64, &[f64; 3])]) -> [f64; 3] {
    let mut out = [0.0; 3];
    for (s, v) in terms {
        for (o, x) in out.iter_mut().zip(v.iter()) {
            *o += s * x;
        }
    }
    out
}

impl Contact {
    /// The velocity change of the point per impulse `p` (components along unit vectors).
    fn change(&self, p: &[f64; 3]) -> [f64; 3] {
        let terms: Vec<(f64, &[f64; 3])> =
            self.response.iter().zip(p).map(|(c, s)| (*s, c)).collect();
        combo(&terms)
    }

    /// Orthonormal tangents in the directions the impulse may have.
    fn tangents(&self) -> Vec<[f64; 3]> {
        let n = &self.normal;
        if self.response.len() == 2 {
            return vec![[-n[1], n[0], 0.0]];
        }
        // The unit vector least along n, made perpendicular to it; then n × t1.
        let k = (0..3)
            .min_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
            .unwrap_or(0);
        let mut e = [0.0; 3];
        e[k] = 1.0;
        let t = combo(&[(1.0, &e), (-n[k], n)]);
        let size = dot(&t, &t).sqrt();
        let t1 = t.map(|x| x / size);
        let t2 = [
            n[1] * t1[2] - n[2] * t1[1],
            n[2] * t1[0] - n[0] * t1[2],
            n[0] * t1[1] - n[1] * t1[0],
        ];
        vec![t1, t2]
    }

    /// The impulse along `directions` (unit vectors' components) that makes the point's
    /// velocity after the impact meet `targets` along `rows`; `None` when singular.
    fn impulse_for(
        &self,
        directions: &[[f64; 3]],
        rows: &[[f64; 3]],
        targets: &[f64],
    ) -> Option<Vec<f64>> {
        let m = directions.len();
        let start = combo(&[(1.0, &self.before), (1.0, &self.applied)]);
        let a = DMatrix::from_fn(m, m, |i, j| dot(&rows[i], &self.change(&directions[j])));
        let b = DVector::from_fn(m, |i, _| targets[i] - dot(&rows[i], &start));
        let x = a.lu().solve(&b)?;
        Some(x.iter().copied().collect())
    }

    /// The collision's impulse; `None` where the point cannot be stopped along the normal
    /// (no mass moves it there).
    pub fn solve(&self) -> Option<CollisionImpulse> {
        let n = self.normal;
        let normal_target = -self.restitution * dot(&n, &self.before);
        let tangents = self.tangents();
        let finish = |p: [f64; 3], mode: Mode| {
            let normal = dot(&p, &n);
            let tangential = combo(&[(1.0, &p), (-normal, &n)]);
            CollisionImpulse {
                components: p,
                normal,
                tangential: dot(&tangential, &tangential).sqrt(),
                mode,
            }
        };
        let along = |dirs: &[[f64; 3]], x: &[f64]| {
            let terms: Vec<(f64, &[f64; 3])> = x.iter().copied().zip(dirs).collect();
            combo(&terms)
        };
        let smooth = self.impulse_for(&[n], &[n], &[normal_target])?;
        if smooth[0] <= 0.0 {
            return Some(finish([0.0; 3], Mode::Separate));
        }
        let Some(mu) = self.friction else {
            return Some(finish(along(&[n], &smooth), Mode::Smooth));
        };
        let mut dirs = vec![n];
        dirs.extend(tangents.iter().copied());
        let mut targets = vec![normal_target];
        targets.extend(tangents.iter().map(|_| 0.0));
        let stick = self.impulse_for(&dirs, &dirs, &targets)?;
        let p_stick = along(&dirs, &stick);
        let t_stick = combo(&[(1.0, &p_stick), (-stick[0], &n)]);
        let t_size = dot(&t_stick, &t_stick).sqrt();
        if stick[0] > 0.0 && t_size <= mu * stick[0] * (1.0 + 1e-12) {
            return Some(finish(p_stick, Mode::Stick));
        }
        // Sliding: against the slip the impact has to stop (before it, with the applied
        // impulses), or against the sticking impulse's pull where there is none.
        let start = combo(&[(1.0, &self.before), (1.0, &self.applied)]);
        let slip = combo(&[(1.0, &start), (-dot(&start, &n), &n)]);
        let slip_size = dot(&slip, &slip).sqrt();
        let against = if slip_size > 1e-12 * (1.0 + dot(&start, &start).sqrt()) {
            slip.map(|x| -x / slip_size)
        } else if t_size > 0.0 {
            t_stick.map(|x| x / t_size)
        } else {
            [0.0; 3]
        };
        let direction = combo(&[(1.0, &n), (mu, &against)]);
        let slide = self.impulse_for(&[direction], &[n], &[normal_target])?;
        if slide[0] <= 0.0 {
            return Some(finish([0.0; 3], Mode::Separate));
        }
        Some(finish(along(&[direction], &slide), Mode::Slide))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A particle of mass m striking a floor: Δv = P/m along every direction.
    fn particle(before: [f64; 3], e: f64, mu: Option<f64>) -> CollisionImpulse {
        let m = 2.0;
        Contact {
            normal: [0.0, 1.0, 0.0],
            before,
            applied: [0.0; 3],
            response: vec![[1.0 / m, 0.0, 0.0], [0.0, 1.0 / m, 0.0]],
            restitution: e,
            friction: mu,
        }
        .solve()
        .expect("solvable")
    }

    #[test]
    fn a_smooth_bounce_reverses_the_normal_velocity_times_e() {
        // P = m (1 + e) |v_n|.
        let p = particle([3.0, -4.0, 0.0], 0.5, None);
        assert!((p.normal - 2.0 * 1.5 * 4.0).abs() < 1e-12);
        assert_eq!(p.mode, Mode::Smooth);
    }

    #[test]
    fn a_rough_particle_slides_when_mu_is_small_and_sticks_when_large() {
        // Stopping the slip needs m |v_t| = 6 against the normal 2 · 4 = 8 (e = 0).
        let slide = particle([3.0, -4.0, 0.0], 0.0, Some(0.5));
        assert_eq!(slide.mode, Mode::Slide);
        assert!((slide.components[0] + 0.5 * 8.0).abs() < 1e-12);
        let stick = particle([3.0, -4.0, 0.0], 0.0, Some(0.8));
        assert_eq!(stick.mode, Mode::Stick);
        assert!((stick.components[0] + 6.0).abs() < 1e-12);
    }
}
