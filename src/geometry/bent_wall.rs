//! The bent wall of the thesis's channel (§10.2.1, eq. 10.8): a ruled surface that starts as a vertical wall and
//! ends leaning 45° over the water, its foot moving sideways, so that a uniform stream along it breaks as a
//! ship's flared bow wave does. Knows nothing of SPH.
//!
//! Eq. (10.8), lengths in units of the inflow depth H, x along the channel, y across it (into the water), z up
//! from the floor: S(t, u) = u α(t) + (1 − u) β(t) with α(t) = (5, 0, t) and β(t) = (5 + L, √2/2 t + L/4,
//! √2/2 t), u ∈ [0, 1], t ∈ [0, 5]. Write s = 1 − u = (x − 5)/L for the fraction of the wall passed. The cut of
//! the surface at that x is a straight line from the foot (y, z) = (s L/4, 0) along d(s) = (s √2/2, 1 − s +
//! s √2/2): a plate leaning θ(s) from the vertical, tan θ = s √2/2 / (1 − s (1 − √2/2)), from 0 at s = 0 to 45°
//! at s = 1. The thesis prints neither L nor the channel's width: both are ours, stated where a run is made.
//!
//! In 2D+t (x = 5 + U t) the cut is that plate moving rigidly: its foot slides along the floor at U/4 and it
//! turns about the foot at θ̇ = (dθ/ds) U/L. A rigid motion is exact here, not an approximation: the normal
//! velocity of a moving line does not depend on how its points are labelled, and the cut's normal velocity is
//! that of the foot plus the turn (`rigid_motion_is_the_normal_velocity_of_the_ruled_surface`).

use nalgebra::{Vector2, Vector3};

type V2 = Vector2<f64>;

/// √2/2, the slope of the line β of eq. (10.8).
const A: f64 = std::f64::consts::FRAC_1_SQRT_2;
/// 1 − √2/2: how much of the height the line β loses against α per unit t.
const B: f64 = 1.0 - std::f64::consts::FRAC_1_SQRT_2;
/// x of the wall's start in eq. (10.8) (units of H).
pub const X_START: f64 = 5.0;
/// The range of the surface's parameter t in eq. (10.8).
pub const T_MAX: f64 = 5.0;

/// The bent wall of eq. (10.8) for a wall length `length` = L/H.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BentWall {
    /// L/H, the length of the ruled surface along the channel (ours: the thesis does not print it).
    pub length: f64,
}

/// The cut of the wall at one x, with its time derivatives for a stream (or a cut) at speed U.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlateState {
    /// The foot on the floor, (y, z) = (s L/4, 0).
    pub foot: V2,
    /// θ (rad from the vertical, towards +y), θ̇ and θ̈ (per unit time, for the given U).
    pub theta: f64,
    pub omega: f64,
    pub alpha: f64,
    /// The foot's velocity (U/4, 0); its acceleration is zero.
    pub foot_velocity: V2,
}

impl PlateState {
    /// Unit vector up the plate, e = (sin θ, cos θ).
    pub fn up(&self) -> V2 {
        V2::new(self.theta.sin(), self.theta.cos())
    }

    /// Unit normal of the plate into the water (+y side), n = (cos θ, −sin θ).
    pub fn normal(&self) -> V2 {
        V2::new(self.theta.cos(), -self.theta.sin())
    }

    /// The plate point at distance r from the foot, with its velocity and acceleration (rigid motion: the foot's
    /// translation and the turn about it).
    pub fn point(&self, r: f64) -> (V2, V2, V2) {
        let (e, n) = (self.up(), self.normal());
        let x = self.foot + e * r;
        let v = self.foot_velocity + n * (self.omega * r);
        let a = n * (self.alpha * r) - e * (self.omega * self.omega * r);
        (x, v, a)
    }
}

impl BentWall {
    /// The fraction s of the wall passed at time t for a stream at speed `u` (H per unit time): s = u t / L.
    pub fn s_at(&self, t: f64, u: f64) -> f64 {
        u * t / self.length
    }

    /// x/H along the channel of the cut at fraction s (eq. 10.8: the wall starts at x = 5).
    pub fn x_of(&self, s: f64) -> f64 {
        X_START + s * self.length
    }

    /// tan θ(s) of the cut at fraction s of the wall.
    pub fn tan_theta(s: f64) -> f64 {
        A * s / (1.0 - B * s)
    }

    /// dθ/ds and d²θ/ds²: θ = atan(A s / (1 − B s)) gives dθ/ds = A / D(s), D = (1 − B s)² + A² s².
    fn theta_derivatives(s: f64) -> (f64, f64) {
        let d = (1.0 - B * s).powi(2) + A * A * s * s;
        let dd = -2.0 * B * (1.0 - B * s) + 2.0 * A * A * s;
        (A / d, -A * dd / (d * d))
    }

    /// The cut at fraction s ∈ [0, 1] of the wall, moving as it does in 2D+t at speed `u` (H per unit time):
    /// ds/dt = u/L. Outside [0, 1] the wall is the channel's straight side (s < 0, at y = 0) or its end
    /// (s > 1, the last cut, still): both with no motion.
    pub fn plate(&self, s: f64, u: f64) -> PlateState {
        let inside = (0.0..=1.0).contains(&s);
        let sc = s.clamp(0.0, 1.0);
        let (d1, d2) = Self::theta_derivatives(sc);
        let rate = if inside { u / self.length } else { 0.0 };
        PlateState {
            foot: V2::new(sc * self.length / 4.0, 0.0),
            theta: Self::tan_theta(sc).atan(),
            omega: d1 * rate,
            alpha: d2 * rate * rate,
            foot_velocity: V2::new(if inside { u / 4.0 } else { 0.0 }, 0.0),
        }
    }

    /// The point S(t, u) of eq. (10.8) in channel coordinates (x, y, z).
    pub fn surface_point(&self, t: f64, u: f64) -> Vector3<f64> {
        let alpha = Vector3::new(X_START, 0.0, t);
        let beta = Vector3::new(X_START + self.length, A * t + self.length / 4.0, A * t);
        alpha * u + beta * (1.0 - u)
    }
}

impl BentWall {
    /// Unit normal of the ruled surface at S(t, u), into the water (+y): ∂S/∂t × ∂S/∂u, ∂S/∂t = (0, (1 − u) √2/2,
    /// u + (1 − u) √2/2), ∂S/∂u = α(t) − β(t) = (−L, −(√2/2 t + L/4), (1 − √2/2) t).
    pub fn surface_normal(&self, t: f64, u: f64) -> Vector3<f64> {
        let st = Vector3::new(0.0, (1.0 - u) * A, u + (1.0 - u) * A);
        let su = Vector3::new(-self.length, -(A * t + self.length / 4.0), B * t);
        let n = st.cross(&su).normalize();
        if n.y < 0.0 {
            -n
        } else {
            n
        }
    }

    /// The channel's side as an oriented point cloud (a 3D wall's input), at spacing about `ds` (units of H)
    /// along x and up the wall, from x = `x_from` to `x_to` and up to `top` above the floor: the straight side
    /// y = 0 before the bent wall (x < 5), the ruled surface of eq. (10.8) over 5 ≤ x ≤ 5 + L, and its last cut
    /// carried on beyond (the 45° wall; ours, see [`crate::geometry::bent_wall`]). Normals point into the water.
    pub fn oriented_points(&self, ds: f64, x_from: f64, x_to: f64, top: f64) -> Vec<super::hull_solid::OrientedPoint> {
        let nx = (((x_to - x_from) / ds).ceil() as usize).max(1);
        let xs: Vec<f64> = (0..=nx)
            .map(|i| x_from + (x_to - x_from) * i as f64 / nx as f64)
            .collect();
        let wx = super::hull_solid::trapezoid_weights(&xs);
        let mut out = vec![];
        for (i, &x) in xs.iter().enumerate() {
            let s = ((x - X_START) / self.length).clamp(0.0, 1.0);
            let p = self.plate(s, 0.0);
            // The cut's length up to `top`, sampled evenly.
            let len = top / p.theta.cos();
            let nr = ((len / ds).ceil() as usize).max(1);
            let straight = !(X_START..=X_START + self.length).contains(&x);
            // t of eq. (10.8) at height z on this cut: z = t (u + (1 − u) √2/2) with u = 1 − s. The surface is
            // not developable: its normal turns along the cut, so each point takes its own.
            let u = 1.0 - s;
            let per_t = u + (1.0 - u) * A;
            let along: Vec<f64> = (0..=nr).map(|k| len * k as f64 / nr as f64).collect();
            for (k, w) in super::hull_solid::trapezoid_weights(&along).iter().enumerate() {
                let (q, _, _) = p.point(along[k]);
                let normal = if straight {
                    let n2 = p.normal();
                    [0.0, n2.x, n2.y]
                } else {
                    let n = self.surface_normal(q.y / per_t, u);
                    [n.x, n.y, n.z]
                };
                out.push(super::hull_solid::OrientedPoint {
                    pos: [x, q.x, q.y],
                    normal,
                    area: super::hull_solid::patch_area(wx[i], *w, &normal),
                });
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The ruled surface's normal is perpendicular to both its tangents and faces the water; its (y, z) part is
    /// along the cut's normal (cos θ, −sin θ), its x part is what makes the cut move (a wall turning into the
    /// stream faces upstream: n_x < 0).
    #[test]
    fn the_ruled_surface_normal_faces_the_water_and_matches_the_cut() {
        let w = BentWall { length: 12.0 };
        for (t, u) in [(0.5, 0.9), (2.0, 0.5), (4.0, 0.1)] {
            let n = w.surface_normal(t, u);
            let h = 1e-6;
            let st = (w.surface_point(t + h, u) - w.surface_point(t - h, u)) / (2.0 * h);
            let su = (w.surface_point(t, u + h) - w.surface_point(t, u - h)) / (2.0 * h);
            assert!(n.dot(&st).abs() < 1e-8 && n.dot(&su).abs() < 1e-8, "{n:?}");
            assert!((n.norm() - 1.0).abs() < 1e-12 && n.y > 0.0 && n.x < 0.0, "{n:?}");
            let cut = w.plate(1.0 - u, 1.0).normal();
            let yz = Vector2::new(n.y, n.z).normalize();
            assert!((yz - cut).norm() < 1e-12, "t {t} u {u}: {yz:?} vs {cut:?}");
        }
        // The point cloud covers the straight side, the bent wall and its continuation, normals into the water.
        let cloud = w.oriented_points(0.25, 0.0, 20.0, 2.0);
        assert!(cloud.iter().all(|p| p.normal[1] > 0.0));
        let at = |x: f64| cloud.iter().filter(|p| (p.pos[0] - x).abs() < 1e-9).count();
        assert!(at(0.0) >= 9 && at(20.0) >= 9);
        assert!(cloud.iter().filter(|p| p.pos[0] < X_START).all(|p| p.pos[1] == 0.0));
        // On the bent wall each sample is the surface point of its height, with that point's own normal.
        for p in cloud
            .iter()
            .filter(|p| p.pos[0] > X_START && p.pos[0] < X_START + w.length)
        {
            let u = 1.0 - (p.pos[0] - X_START) / w.length;
            let t = p.pos[2] / (u + (1.0 - u) * A);
            let (q, n) = (w.surface_point(t, u), w.surface_normal(t, u));
            assert!((q - Vector3::from(p.pos)).norm() < 1e-12, "{:?} vs {q:?}", p.pos);
            assert!((n - Vector3::from(p.normal)).norm() < 1e-12);
        }
    }

    /// The cut of eq. (10.8) at x is the plate: every surface point of that x lies on the line from the foot
    /// along (sin θ, cos θ), and the ends are vertical (s = 0) and 45° (s = 1).
    #[test]
    fn the_cut_of_the_ruled_surface_is_the_leaning_plate() {
        let w = BentWall { length: 8.0 };
        assert_eq!(BentWall::tan_theta(0.0), 0.0);
        assert!((BentWall::tan_theta(1.0) - 1.0).abs() < 1e-15);
        for s in [0.0, 0.3, 0.77, 1.0] {
            let p = w.plate(s, 1.0);
            for t in [0.0, 1.0, 2.5, T_MAX] {
                let q = w.surface_point(t, 1.0 - s);
                assert!((q.x - (X_START + s * w.length)).abs() < 1e-12);
                let rel = V2::new(q.y, q.z) - p.foot;
                assert!(
                    rel.dot(&p.normal()).abs() < 1e-12,
                    "s {s} t {t}: off the plate by {}",
                    rel.dot(&p.normal())
                );
            }
        }
    }

    /// The 2D+t analogue moves the plate rigidly; its normal velocity at every point is the rate at which the
    /// cut of the ruled surface moves along its normal as x = 5 + U t advances (a centred difference in x).
    #[test]
    fn rigid_motion_is_the_normal_velocity_of_the_ruled_surface() {
        let (w, u) = (BentWall { length: 8.0 }, 1.7);
        let dt = 1e-5;
        for s in [0.1, 0.5, 0.9] {
            let p = w.plate(s, u);
            let ds = u * dt / w.length;
            let (before, after) = (w.plate(s - ds, u), w.plate(s + ds, u));
            for r in [0.0, 0.8, 2.0, 3.5] {
                let (x, v, acc) = p.point(r);
                // Signed distance of x from the cut line at s ± ds, along that line's normal.
                let dist = |q: &PlateState| (x - q.foot).dot(&q.normal());
                let rate = (dist(&before) - dist(&after)) / (2.0 * dt);
                assert!(
                    (v.dot(&p.normal()) - rate).abs() < 1e-8,
                    "s {s} r {r}: {} vs {rate}",
                    v.dot(&p.normal())
                );
                // The acceleration is the derivative of the velocity of the same plate point.
                let (_, v1, _) = after.point(r);
                let (_, v0, _) = before.point(r);
                let a_fd = (v1 - v0) / (2.0 * dt);
                assert!(
                    (acc - a_fd).norm() < 1e-6 * (1.0 + acc.norm()),
                    "s {s} r {r}: {acc:?} vs {a_fd:?}"
                );
            }
        }
        // Outside the wall nothing moves.
        let still = w.plate(1.2, u);
        assert_eq!((still.omega, still.foot_velocity), (0.0, V2::zeros()));
    }
}
