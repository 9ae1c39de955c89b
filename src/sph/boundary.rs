//! Solid boundaries as *fixed ghost particles* (thesis §7.1.1) or as the nodes of a *normal-flux* surface
//! (§7.1.2, [`FluxNodes`]). With ghosts the boundary supplies, at time t, the ghost
//! positions, their interpolation (mirror) points inside the fluid and the wall velocity and acceleration
//! there. The solver fills in the ghosts' velocity, pressure and density from the fluid by MLS
//! ([`crate::sph::mls`], `crate::sph::equations::ghost_conditions`). This file knows nothing of hulls or file formats.

use nalgebra::SVector;

/// Geometry of the ghost particles of one boundary at one instant.
#[derive(Clone, Debug, Default)]
pub struct GhostGeometry<const D: usize> {
    pub pos: Vec<SVector<f64, D>>,
    /// Mirror point inside the fluid whose interpolated values set the ghost's (thesis Fig. 7.2).
    pub interp: Vec<SVector<f64, D>>,
    /// Wall velocity u_B at the ghost (m/s).
    pub wall_vel: Vec<SVector<f64, D>>,
    /// Wall acceleration du_B/dt at the ghost (m/s²), used in the Neumann condition (7.4).
    pub wall_acc: Vec<SVector<f64, D>>,
    /// Volume of each ghost, ds^D (m^D).
    pub volume: Vec<f64>,
    /// How the ghost mirrors its interpolation point: through a plane (a wall side) or through a point
    /// (a corner vertex, the central symmetry of thesis Fig. 7.3).
    pub mirror: Vec<Mirror>,
}

/// The symmetry relating a ghost to its interpolation point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Mirror {
    #[default]
    Plane,
    Point,
    /// Through the coordinate planes whose bits are set (an edge of an axis-aligned 3D box: reflected along
    /// the two axes the ghost is beyond, kept along the edge). Faces are `Plane`, vertices `Point`.
    Axes(u8),
}

impl<const D: usize> GhostGeometry<D> {
    pub fn len(&self) -> usize {
        self.pos.len()
    }
    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }
    pub fn clear(&mut self) {
        self.pos.clear();
        self.interp.clear();
        self.wall_vel.clear();
        self.wall_acc.clear();
        self.volume.clear();
        self.mirror.clear();
    }
    /// The ghosts `keep` accepts (by index), in order.
    pub fn filtered(&self, keep: impl Fn(usize) -> bool) -> Self {
        let mut out = Self::default();
        for k in (0..self.len()).filter(|&k| keep(k)) {
            out.pos.push(self.pos[k]);
            out.interp.push(self.interp[k]);
            out.wall_vel.push(self.wall_vel[k]);
            out.wall_acc.push(self.wall_acc[k]);
            out.volume.push(self.volume[k]);
            out.mirror.push(self.mirror[k]);
        }
        out
    }
    /// Keeps the first `n` ghosts.
    pub fn truncate(&mut self, n: usize) {
        self.pos.truncate(n);
        self.interp.truncate(n);
        self.wall_vel.truncate(n);
        self.wall_acc.truncate(n);
        self.volume.truncate(n);
        self.mirror.truncate(n);
    }
    pub fn append(&mut self, other: &GhostGeometry<D>) {
        self.pos.extend_from_slice(&other.pos);
        self.interp.extend_from_slice(&other.interp);
        self.wall_vel.extend_from_slice(&other.wall_vel);
        self.wall_acc.extend_from_slice(&other.wall_acc);
        self.volume.extend_from_slice(&other.volume);
        self.mirror.extend_from_slice(&other.mirror);
    }
}

/// The nodes of a normal-flux wall at one instant (thesis §7.1.2): points of the solid surface, each standing
/// for the patch of area `area` around it, where the boundary terms of eq. (7.14) are summed.
#[derive(Clone, Debug, Default)]
pub struct FluxNodes<const D: usize> {
    pub pos: Vec<SVector<f64, D>>,
    /// Unit normal out of the fluid, into the solid (n_k of eq. 7.14).
    pub outward: Vec<SVector<f64, D>>,
    /// The patch's area S_k (m^(D−1): a length in 2D).
    pub area: Vec<f64>,
    /// The wall's velocity (m/s) and acceleration (m/s²) at the node.
    pub wall_vel: Vec<SVector<f64, D>>,
    pub wall_acc: Vec<SVector<f64, D>>,
}

impl<const D: usize> FluxNodes<D> {
    pub fn len(&self) -> usize {
        self.pos.len()
    }
    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }
    pub fn clear(&mut self) {
        self.pos.clear();
        self.outward.clear();
        self.area.clear();
        self.wall_vel.clear();
        self.wall_acc.clear();
    }
    pub fn append(&mut self, other: &FluxNodes<D>) {
        self.pos.extend_from_slice(&other.pos);
        self.outward.extend_from_slice(&other.outward);
        self.area.extend_from_slice(&other.area);
        self.wall_vel.extend_from_slice(&other.wall_vel);
        self.wall_acc.extend_from_slice(&other.wall_acc);
    }
}

/// How far behind a plane wall an image ghost can touch the fluid (m): a pair on either side of the plane is at
/// least as far apart as the sum of its two distances to the plane, so an image deeper than the support less the
/// smallest signed distance of any fluid particle to the plane (`nearest`, on the fluid side positive) is outside
/// every particle's support and adds nothing to any sum. Making only the images within this reach keeps every
/// sum, with fewer ghosts to build and scan (issue #31's ghost count). A particle on the solid side of the
/// plane (`nearest` ≤ 0) leaves the reach at the full support, the bound without the fluid's distance.
pub fn image_reach(support: f64, nearest: f64) -> f64 {
    support - nearest.max(0.0)
}

/// Anything that can produce fixed ghost particles: a tank wall, a moving wedge, a deforming hull section.
pub trait Boundary<const D: usize>: Send + Sync {
    /// A short name, used for force outputs.
    fn name(&self) -> &str;
    /// Whether the ghosts move or deform (if not, they are generated once).
    fn moves(&self) -> bool;
    /// Writes the ghost geometry at time `t` into `out` (cleared first by the caller).
    fn ghosts(&self, t: f64, out: &mut GhostGeometry<D>);
    /// Ghosts that are the mirror images of the fluid particles at `pos` (the standard ghost technique of
    /// Colagrossi & Landrini 2003, recalled at the start of thesis §7.1.1), appended to `out`, with the index
    /// of each image's fluid particle appended to `source`. The image's mirror point (`interp`) is its
    /// particle. Walls with fixed ghosts only write none (the default).
    fn images(&self, _t: f64, _pos: &[SVector<f64, D>], _out: &mut GhostGeometry<D>, _source: &mut Vec<usize>) {}
    /// The wall's normal-flux nodes at time `t` (thesis §7.1.2), appended to `out`: a wall held by boundary
    /// terms on its surface rather than by ghosts. Walls of ghosts write none (the default).
    fn flux_nodes(&self, _t: f64, _out: &mut FluxNodes<D>) {}
    /// Safeguard against wall penetration: if `x` lies on the solid side of the boundary at time `t`
    /// (within the kernel support of the wall), move it back to the fluid side, remove its normal velocity
    /// relative to the wall, and return true. The solver counts these corrections and reports them.
    fn keep_out(&self, _t: f64, _x: &mut SVector<f64, D>, _u: &mut SVector<f64, D>) -> bool {
        false
    }
}

/// Rigid motion of a wall.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RigidMotion<const D: usize> {
    Fixed,
    /// Translation at constant velocity (m/s) from the initial position.
    ConstantVelocity(SVector<f64, D>),
    /// Translation from rest to `velocity` (m/s) over `time` (s), the speed growing as v r(t/T) with
    /// r(τ) = τ²(3 − 2τ) (zero acceleration at both ends, so the start sends no pressure wave of a jump in
    /// acceleration), then steady.
    Ramp {
        velocity: SVector<f64, D>,
        time: f64,
    },
}

impl<const D: usize> RigidMotion<D> {
    pub fn displacement(&self, t: f64) -> SVector<f64, D> {
        match self {
            RigidMotion::Fixed => SVector::zeros(),
            RigidMotion::ConstantVelocity(v) => v * t,
            RigidMotion::Ramp { velocity, time } => {
                let tau = (t / time).clamp(0.0, 1.0);
                // ∫ r = T (τ³ − τ⁴/2) during the ramp, T/2 at its end.
                velocity * (time * (tau.powi(3) - 0.5 * tau.powi(4)) + (t - time).max(0.0))
            }
        }
    }
    pub fn velocity(&self, t: f64) -> SVector<f64, D> {
        match self {
            RigidMotion::Fixed => SVector::zeros(),
            RigidMotion::ConstantVelocity(v) => *v,
            RigidMotion::Ramp { velocity, time } => {
                let tau = (t / time).clamp(0.0, 1.0);
                velocity * (tau * tau * (3.0 - 2.0 * tau))
            }
        }
    }
    pub fn acceleration(&self, t: f64) -> SVector<f64, D> {
        match self {
            RigidMotion::Ramp { velocity, time } if t < *time && t > 0.0 => {
                let tau = t / time;
                velocity * (6.0 * tau * (1.0 - tau) / time)
            }
            _ => SVector::zeros(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector1;

    /// The ramp's displacement, velocity and acceleration are each other's integrals and derivatives, and it
    /// ends at the steady speed with the distance T v / 2 behind the steady motion's.
    #[test]
    fn ramp_motion_is_consistent_and_ends_steady() {
        let m = RigidMotion::Ramp {
            velocity: Vector1::new(2.0),
            time: 3.0,
        };
        let e = 1e-6;
        for t in [0.1, 1.0, 1.5, 2.9, 3.5, 7.0] {
            let v = (m.displacement(t + e) - m.displacement(t - e)) / (2.0 * e);
            assert!((v - m.velocity(t)).norm() < 1e-8, "velocity at {t}");
            let a = (m.velocity(t + e) - m.velocity(t - e)) / (2.0 * e);
            assert!((a - m.acceleration(t)).norm() < 1e-6, "acceleration at {t}");
        }
        assert_eq!(m.velocity(0.0).x, 0.0);
        assert_eq!(m.velocity(5.0).x, 2.0);
        assert!((m.displacement(5.0).x - (2.0 * 5.0 - 3.0)).abs() < 1e-12);
    }
}

/// Test support shared by the walls that make image ghosts.
#[cfg(test)]
pub(crate) mod image_oracle {
    use nalgebra::SVector;

    /// A deterministic jitter of ± `amplitude` / 2 (a linear congruential generator; no dependency).
    pub fn jitter(seed: u64, amplitude: f64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * amplitude
        }
    }

    /// The brute-force check of a wall's images against `candidates`, the (particle, image) pairs the full
    /// support would make: every candidate within the support of some particle is made, every image made is a
    /// candidate, and fewer are made than candidates.
    pub fn check<const D: usize>(
        fluid: &[SVector<f64, D>],
        candidates: &[(usize, SVector<f64, D>)],
        source: &[usize],
        images: &[SVector<f64, D>],
        support: f64,
    ) {
        let same = |a: &SVector<f64, D>, b: &SVector<f64, D>| (a - b).norm() < 1e-12;
        let made = |j: usize, p: &SVector<f64, D>| source.iter().zip(images).any(|(&s, q)| s == j && same(q, p));
        let mut touching = 0;
        for (j, p) in candidates {
            if fluid.iter().any(|x| (x - p).norm() < support) {
                touching += 1;
                assert!(
                    made(*j, p),
                    "image of particle {j} at {p:?} touches the fluid but was not made"
                );
            }
        }
        for (j, p) in source.iter().zip(images) {
            assert!(
                candidates.iter().any(|(cj, cp)| cj == j && same(cp, p)),
                "{p:?} is no candidate"
            );
        }
        assert!(touching > 0 && source.len() >= touching);
        assert!(
            source.len() < candidates.len(),
            "{} of {}",
            source.len(),
            candidates.len()
        );
    }
}
