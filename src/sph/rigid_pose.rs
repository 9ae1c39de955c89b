//! The pose of a rigidly moving 2D wall (a tank in sway, heave and roll): a translation d(t) of the wall's
//! frame and a rotation θ(t) (counter-clockwise, rad) about a centre fixed in the wall, with their first and
//! second time derivatives. A wall point p (its position at t = 0) is at x = c + d + R(θ)(p − c), c the centre's
//! position at t = 0; its velocity is ḋ + θ̇ k × r and its acceleration d̈ + θ̈ k × r − θ̇² r, r = x − c − d.
//!
//! The ghost conditions use these at the wall: free slip (7.2) with the wall point's velocity, and the Neumann
//! condition (7.4) with its acceleration. Eq. (7.4) is exact for a translating wall (dn/dt = 0); for a rotating
//! one it omits the terms of the normal's rotation (of order ρ θ̇ u), small for the slow rolls of sloshing tanks.

use nalgebra::{Matrix2, Vector2};
use std::sync::Arc;

type V2 = Vector2<f64>;

/// Pose of a rigid 2D wall at one instant (see the module doc).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Pose2 {
    /// Translation d (m), its velocity ḋ (m/s) and acceleration d̈ (m/s²).
    pub d: V2,
    pub v: V2,
    pub a: V2,
    /// Rotation θ (rad, counter-clockwise), θ̇ (rad/s), θ̈ (rad/s²).
    pub theta: f64,
    pub omega: f64,
    pub alpha: f64,
    /// The rotation centre's position at t = 0 (m).
    pub centre: V2,
}

impl Pose2 {
    /// A pure translation.
    pub fn translation(d: V2, v: V2, a: V2) -> Self {
        Pose2 {
            d,
            v,
            a,
            ..Default::default()
        }
    }

    /// R(θ).
    pub fn rotation(&self) -> Matrix2<f64> {
        let (s, c) = self.theta.sin_cos();
        Matrix2::new(c, -s, s, c)
    }

    /// Where the wall point that was at `p` at t = 0 is.
    pub fn point(&self, p: &V2) -> V2 {
        self.centre + self.d + self.rotation() * (p - self.centre)
    }

    /// The t = 0 position of the wall point now at `x` (the inverse of [`Pose2::point`]).
    pub fn local(&self, x: &V2) -> V2 {
        self.centre + self.rotation().transpose() * (x - self.centre - self.d)
    }

    /// A direction of the wall (a normal, say) rotated with it.
    pub fn vector(&self, n: &V2) -> V2 {
        self.rotation() * n
    }

    /// Velocity of the wall's material point now at `x` (m/s).
    pub fn velocity_at(&self, x: &V2) -> V2 {
        let r = x - self.centre - self.d;
        self.v + V2::new(-r.y, r.x) * self.omega
    }

    /// Acceleration of the wall's material point now at `x` (m/s²).
    pub fn acceleration_at(&self, x: &V2) -> V2 {
        let r = x - self.centre - self.d;
        self.a + V2::new(-r.y, r.x) * self.alpha - r * (self.omega * self.omega)
    }

    /// (R, b) with x = R p + b for every wall point p.
    pub fn affine(&self) -> (Matrix2<f64>, V2) {
        let r = self.rotation();
        (r, self.centre + self.d - r * self.centre)
    }
}

/// A prescribed rigid motion: the pose at each time.
#[derive(Clone)]
pub struct MotionLaw(pub Arc<dyn Fn(f64) -> Pose2 + Send + Sync>);

impl MotionLaw {
    pub fn new(f: impl Fn(f64) -> Pose2 + Send + Sync + 'static) -> Self {
        MotionLaw(Arc::new(f))
    }
    pub fn pose(&self, t: f64) -> Pose2 {
        (self.0)(t)
    }
}

impl std::fmt::Debug for MotionLaw {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "MotionLaw(pose at t = 0: {:?})", self.pose(0.0))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn point_velocity_and_acceleration_are_the_time_derivatives_of_the_pose() {
        // θ = 0.1 sin(2t) about (1, 0.5), d = (0.05 sin 3t, 0.02 t²): central differences of the point.
        let law = |t: f64| Pose2 {
            d: V2::new(0.05 * (3.0 * t).sin(), 0.02 * t * t),
            v: V2::new(0.15 * (3.0 * t).cos(), 0.04 * t),
            a: V2::new(-0.45 * (3.0 * t).sin(), 0.04),
            theta: 0.1 * (2.0 * t).sin(),
            omega: 0.2 * (2.0 * t).cos(),
            alpha: -0.4 * (2.0 * t).sin(),
            centre: V2::new(1.0, 0.5),
        };
        let p = V2::new(0.3, -0.2);
        let (t, h) = (0.7, 1e-4);
        let x = |t: f64| law(t).point(&p);
        let v = (x(t + h) - x(t - h)) / (2.0 * h);
        let a = (x(t + h) - 2.0 * x(t) + x(t - h)) / (h * h);
        let pose = law(t);
        assert!((pose.velocity_at(&x(t)) - v).norm() < 1e-7);
        assert!((pose.acceleration_at(&x(t)) - a).norm() < 1e-5);
        assert!((pose.local(&x(t)) - p).norm() < 1e-12);
        let (r, b) = pose.affine();
        assert!((r * p + b - x(t)).norm() < 1e-12);
    }
}
