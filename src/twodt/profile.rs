//! The wall of the 2D+t scene that deforms: the symmetry plane below the keel, the hull section from keel
//! to deck, and a vertical extension of the deck edge up to the top of the domain so no fluid runs over the
//! deck. Its vertices move with the section: a point at fixed girth parameter ξ moves at U (y_x, z_x) and
//! accelerates at U² (y_xx, z_xx), whose normal components are w_n (10.4) and a_n. Before the stem and after
//! the transom there is no section: the wall is the symmetry plane alone.

use crate::geometry::surface::HullSurface;
use crate::sph::deforming_wall::Profile;
use crate::sph::polyline_wall::VertexMotion;
use nalgebra::Vector2;
use std::sync::Arc;

type V2 = Vector2<f64>;

/// What the profile needs to know (units of L, time in √(L/g)). It is the one owner of the ship's speed U
/// and of the time ↔ x mapping of eq. (10.2) ([`Self::x_at`], [`Self::t_at`]).
#[derive(Clone)]
pub struct SectionProfile {
    pub hull: Arc<HullSurface>,
    /// Ship speed U = Fr in units of √(gL).
    pub u: f64,
    /// x/L of the section at t = 0.
    pub x0: f64,
    /// Sampling of the section (units of L).
    pub ds: f64,
    /// Lower end of the moving symmetry wall (the fixed tank wall stops just below).
    pub z_cut: f64,
    /// Top of the symmetry wall and of the deck extension.
    pub z_top: f64,
    /// Time at which the ship starts moving (after the settling of the particles); before it the section
    /// stands still at x0.
    pub t_start: f64,
}

impl SectionProfile {
    /// x/L at time t, eq. (10.2): x = U (t − t_start) + x0 once the ship has started, x0 before.
    pub fn x_at(&self, t: f64) -> f64 {
        self.u * (t - self.t_start).max(0.0) + self.x0
    }

    /// The time at which the section reaches x/L = `x` (the inverse of [`Self::x_at`] for x ≥ x0).
    pub fn t_at(&self, x: f64) -> f64 {
        self.t_start + (x - self.x0) / self.u
    }

    /// The wall at time t.
    pub fn at(&self, t: f64) -> Profile {
        let x = self.x_at(t);
        let moving = if t >= self.t_start { 1.0 } else { 0.0 };
        let mut pts: Vec<V2> = vec![V2::new(0.0, self.z_cut)];
        let mut vel = vec![V2::zeros()];
        let mut acc = vec![V2::zeros()];
        let min_gap = 1e-3 * self.ds;
        let mut push = |p: V2, v: V2, a: V2, pts: &mut Vec<V2>| {
            if (p - *pts.last().unwrap()).norm() > min_gap {
                pts.push(p);
                vel.push(v);
                acc.push(a);
            }
        };
        match self.hull.section(x, self.ds) {
            Some(samples) if samples[0].z > self.z_cut => {
                let (u, u2) = (self.u * moving, self.u * self.u * moving);
                let k = &samples[0];
                if k.y > min_gap {
                    push(V2::new(0.0, k.z), V2::new(0.0, u * k.point.z_x), V2::zeros(), &mut pts);
                }
                for s in &samples {
                    let p = &s.point;
                    push(
                        V2::new(s.y, s.z.min(self.z_top)),
                        V2::new(u * p.y_x, u * p.z_x),
                        V2::new(u2 * p.y_xx, u2 * p.z_xx),
                        &mut pts,
                    );
                }
                let d = samples.last().unwrap();
                if d.z < self.z_top {
                    push(
                        V2::new(d.y, self.z_top),
                        V2::new(u * d.point.y_x, 0.0),
                        V2::new(u2 * d.point.y_xx, 0.0),
                        &mut pts,
                    );
                }
            }
            _ => push(V2::new(0.0, self.z_top), V2::zeros(), V2::zeros(), &mut pts),
        }
        Profile {
            points: pts,
            motion: VertexMotion { vel, acc },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::wigley::{wigley, WigleySpec};

    /// The vertices of the section move with a normal velocity equal to w_n of eq. (10.4), and the wall runs
    /// from the symmetry plane through the keel to the top.
    #[test]
    fn section_vertices_move_with_the_expansion_velocity() {
        let hull = Arc::new(HullSurface::new(&wigley(&WigleySpec::default())));
        let prof = SectionProfile {
            hull: hull.clone(),
            u: 0.5,
            x0: 0.1,
            ds: 2e-3,
            z_cut: -0.15,
            z_top: 0.1,
            t_start: 0.0,
        };
        let t = 0.2; // x = 0.2
        let p = prof.at(t);
        assert_eq!(p.points[0], V2::new(0.0, -0.15));
        assert!((p.points.last().unwrap().y - 0.1).abs() < 1e-12);
        let samples = hull.section(prof.x_at(t), prof.ds).unwrap();
        for s in samples.iter().skip(1).take(samples.len() - 2) {
            let k = p
                .points
                .iter()
                .position(|q| (q - V2::new(s.y, s.z)).norm() < 1e-12)
                .expect("sample is a vertex");
            let n = V2::new(s.normal[0], s.normal[1]);
            let wn = p.motion.vel[k].dot(&n);
            assert!(
                (wn - prof.u * s.w_n_over_u).abs() < 1e-12,
                "w_n {wn} vs {}",
                prof.u * s.w_n_over_u
            );
        }
        // Before the ship starts, the wall stands still.
        let still = SectionProfile { t_start: 1.0, ..prof };
        assert!(still.at(0.5).motion.vel.iter().all(|v| v.norm() == 0.0));
    }
}
