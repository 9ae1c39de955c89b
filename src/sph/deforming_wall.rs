//! A 2D wall whose shape changes in time, given as a function t → polyline with vertex velocities and
//! accelerations. Its fixed ghost particles are regenerated at every right-hand-side evaluation (thesis
//! §7.1.1: "if deformations occur the generation of the fixed ghost particles is repeated at each time step
//! according to the evolving body surface"). The solver core knows nothing of what the profile is: a 2D+t
//! hull section, a rigid wedge, anything that can say where its wall is at time t.

use super::boundary::{Boundary, GhostGeometry};
use super::polyline_wall::{ghost_layers_moving, solid_side, FluidSide, VertexMotion};
use nalgebra::Vector2;
use std::sync::Mutex;

type V2 = Vector2<f64>;

/// The wall at one instant: its polyline and how its vertices move.
#[derive(Clone, Debug, Default)]
pub struct Profile {
    pub points: Vec<V2>,
    pub motion: VertexMotion,
}

impl Profile {
    /// Velocity of the wall at its nearest point to `x` (m/s).
    fn velocity_near(&self, x: &V2) -> V2 {
        let (_, seg, t) = super::polyline_wall::nearest_on_polyline(&self.points, x);
        self.motion.vel[seg] * (1.0 - t) + self.motion.vel[seg + 1] * t
    }
}

/// The shape of the wall as a function of time.
pub type ProfileFn = dyn Fn(f64) -> Profile + Send + Sync;

/// A deforming polyline wall. Its ghosts are sampled from its first point on (`anchor_start`), so a wall
/// whose start continues a fixed wall ending half a spacing before it keeps that wall's ghost lattice across
/// the junction.
pub struct DeformingWall {
    pub name: String,
    profile: Box<ProfileFn>,
    side: FluidSide,
    ds: f64,
    support: f64,
    /// The last profile evaluated, with its time (the safeguard after a step reuses the last stage's).
    cache: Mutex<Option<Cached>>,
}

/// A profile with its time and bounding box.
struct Cached {
    t: f64,
    profile: Profile,
    lo: V2,
    hi: V2,
}

impl DeformingWall {
    /// `ds`: ghost spacing (m); `support`: kernel support (m), the depth the ghost layers must cover.
    pub fn new(name: &str, profile: Box<ProfileFn>, side: FluidSide, ds: f64, support: f64) -> Self {
        DeformingWall {
            name: name.to_string(),
            profile,
            side,
            ds,
            support,
            cache: Mutex::new(None),
        }
    }

    /// The profile at time t (cached for repeated calls at the same t).
    pub fn profile_at(&self, t: f64) -> Profile {
        let mut c = self.cache.lock().expect("profile cache poisoned");
        if let Some(k) = c.as_ref() {
            if k.t == t {
                return k.profile.clone();
            }
        }
        let p = (self.profile)(t);
        let (lo, hi) = p.points.iter().fold(
            (V2::repeat(f64::INFINITY), V2::repeat(f64::NEG_INFINITY)),
            |(lo, hi), q| (lo.inf(q), hi.sup(q)),
        );
        *c = Some(Cached {
            t,
            profile: p.clone(),
            lo,
            hi,
        });
        p
    }
}

impl Boundary<2> for DeformingWall {
    fn name(&self) -> &str {
        &self.name
    }
    fn moves(&self) -> bool {
        true
    }
    fn ghosts(&self, t: f64, out: &mut GhostGeometry<2>) {
        let p = self.profile_at(t);
        let g = ghost_layers_moving(&p.points, Some(&p.motion), self.side, self.ds, self.support, true);
        out.append(&g);
    }
    fn keep_out(&self, t: f64, x: &mut V2, u: &mut V2) -> bool {
        let c = self.cache.lock().expect("profile cache poisoned");
        // The safeguard runs once per particle: use the cached profile (the last stage is at t + dt, the
        // time the safeguard is called with) and skip particles outside its bounding box.
        let Some(k) = c.as_ref() else {
            return false;
        };
        if (k.t - t).abs() > 1e-12 * (1.0 + t.abs()) {
            return false;
        }
        let (p, lo, hi) = (&k.profile, k.lo, k.hi);
        let band = self.support;
        if (0..2).any(|d| x[d] < lo[d] - band || x[d] > hi[d] + band) {
            return false;
        }
        let Some((foot, n)) = solid_side(&p.points, self.side, x, band) else {
            return false;
        };
        let depth = (*x - foot).dot(&n);
        *x = foot - n * (0.5 * self.ds).min(depth.max(0.0) + 0.25 * self.ds);
        let rel = (*u - p.velocity_near(&foot)).dot(&n);
        if rel > 0.0 {
            *u -= n * rel;
        }
        true
    }
}
