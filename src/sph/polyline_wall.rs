//! A 2D wall given as a polyline with the fluid on one side, turned into layers of fixed ghost particles
//! (thesis §7.1.1, steps a–d): the profile is offset towards the solid by (k + ½) ds, k = 0, 1, …, until the
//! layers cover the kernel support, and each offset profile is sampled at spacing ds.
//!
//! Interpolation points are the mirror images of the ghosts through their *nearest point on the wall*.
//! Along a straight side this is the mirror in the wall; in the region facing a convex corner of the solid
//! (e.g. the inner side of a tank corner, fluid angle π/2) the nearest point is the vertex, so the mirror is
//! the central symmetry of Fig. 7.3, and adjacent ghosts keep adjacent interpolation points.
//! Offset profiles are joined at corners by mitres; corners (turns above 30°) split the profile into chains
//! that are sampled from the corner outwards, so a rectangular tank gets ghosts on the fluid's own lattice.
//! Fluid angles above π (Figs. 7.4–7.5: bisector ghosts, narrow angles) are not treated specially yet.

use super::boundary::{image_reach, Boundary, FluxNodes, GhostGeometry, Mirror, RigidMotion};
use super::rigid_pose::{MotionLaw, Pose2};
use nalgebra::Vector2;

type V2 = Vector2<f64>;

/// Which side of the polyline (walking from its first point to its last) the fluid is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FluidSide {
    Left,
    Right,
}

/// How a polyline wall makes the ghosts along its straight sides.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum GhostKind {
    /// Fixed ghost particles on a lattice, valued by MLS at their mirror points (thesis §7.1.1). The default:
    /// it handles any profile, moving or deforming.
    #[default]
    Fixed,
    /// The mirror images of the fluid particles within the kernel support of each straight side, carrying
    /// their particle's values (the standard ghosts of Colagrossi & Landrini 2003, J. Comput. Phys.
    /// 191:448). The corner quadrants keep their fixed point-mirror ghosts (Fig. 7.3). For tanks: under a
    /// stagnation point that the flow leaves along the wall's normal, the fixed lattice over-pressures (the
    /// `jet-floor` case: Cp 2.8 against 1.0), the images do not (studies/results/validation/LOG.md, check 12). Meant for walls of
    /// straight sides meeting at corners (turns above 30°), such as tanks: at a gentle bend two sides' images
    /// would overlap or leave a gap.
    Images,
    /// No ghosts: the wall's surface nodes carry the boundary terms of the normal-flux method (thesis §7.1.2,
    /// eq. 7.14), nodes at [`FLUX_NODES_PER_DX`] per particle spacing along each side, each the midpoint of
    /// its piece of the side. Free slip only. Meant for comparison with the ghosts (the method the thesis used
    /// for a 3D hull, issue #31): the thesis notes it is in principle the less accurate of the two.
    NormalFlux,
}

/// Normal-flux nodes per particle spacing along a side: the integral of W n over the side (eq. 7.14) by the
/// midpoint rule with pieces of dx/2, whose error (h/dx 1.33 for the default kernel) is below 1e-3 of it.
pub const FLUX_NODES_PER_DX: f64 = 2.0;

/// A rigid 2D polyline wall.
#[derive(Clone, Debug)]
pub struct PolylineWall {
    pub name: String,
    pub points: Vec<V2>,
    pub fluid_side: FluidSide,
    pub motion: RigidMotion<2>,
    ds: f64,
    support: f64,
    kind: GhostKind,
    /// Fixed ghost geometry at t = 0 (with [`GhostKind::Images`], the corner ghosts only).
    base: GhostGeometry<2>,
    /// A prescribed rigid motion (sway, heave, roll) replacing `motion` when set.
    law: Option<MotionLaw>,
}

/// Turn angle above which a vertex splits the offset profile into separately sampled chains (radians).
const CORNER_TURN: f64 = 30.0 * std::f64::consts::PI / 180.0;

impl PolylineWall {
    /// Builds the wall and its ghost layers for particle spacing `ds` (m) and kernel support `support` (m).
    pub fn new(
        name: &str,
        points: Vec<V2>,
        fluid_side: FluidSide,
        motion: RigidMotion<2>,
        ds: f64,
        support: f64,
    ) -> Self {
        let mut wall = PolylineWall {
            name: name.to_string(),
            points,
            fluid_side,
            motion,
            ds,
            support,
            kind: GhostKind::Fixed,
            base: GhostGeometry::default(),
            law: None,
        };
        wall.base = ghost_layers(&wall.points, fluid_side, ds, support);
        wall
    }

    /// The same wall with ghosts of kind `kind`: with [`GhostKind::Images`] only the fixed ghosts that
    /// mirror through a corner vertex are kept; the straight sides get images of the fluid at each stage.
    pub fn with_ghosts(mut self, kind: GhostKind) -> Self {
        self.kind = kind;
        match kind {
            GhostKind::Images => self.base = self.base.filtered(|k| self.base.mirror[k] == Mirror::Point),
            GhostKind::NormalFlux => self.base = GhostGeometry::default(),
            GhostKind::Fixed => {}
        }
        self
    }

    /// The same wall moving rigidly with the pose `law` gives at each time (instead of `motion`).
    pub fn with_motion_law(mut self, law: MotionLaw) -> Self {
        self.law = Some(law);
        self
    }

    /// The wall's pose at time t.
    pub fn pose(&self, t: f64) -> Pose2 {
        match &self.law {
            Some(law) => law.pose(t),
            None => Pose2::translation(
                self.motion.displacement(t),
                self.motion.velocity(t),
                self.motion.acceleration(t),
            ),
        }
    }

    /// How the straight sides make their ghosts.
    pub fn ghost_kind(&self) -> GhostKind {
        self.kind
    }

    /// Particle spacing and kernel support used for the ghosts (m).
    pub fn spacing(&self) -> (f64, f64) {
        (self.ds, self.support)
    }

    /// Ghost geometry at t = 0 (for tests and plots).
    pub fn base_ghosts(&self) -> &GhostGeometry<2> {
        &self.base
    }
}

impl Boundary<2> for PolylineWall {
    fn name(&self) -> &str {
        &self.name
    }
    fn moves(&self) -> bool {
        self.motion != RigidMotion::Fixed || self.law.is_some()
    }
    /// The ghosts at t = 0 carried by the pose; each takes the velocity and acceleration of the wall point
    /// between it and its mirror point (on the wall for a side's ghost, the vertex for a corner's).
    fn ghosts(&self, t: f64, out: &mut GhostGeometry<2>) {
        let pose = self.pose(t);
        for (g, i) in self.base.pos.iter().zip(&self.base.interp) {
            let (g, i) = (pose.point(g), pose.point(i));
            let w = (g + i) * 0.5;
            out.pos.push(g);
            out.interp.push(i);
            out.wall_vel.push(pose.velocity_at(&w));
            out.wall_acc.push(pose.acceleration_at(&w));
        }
        out.volume.extend_from_slice(&self.base.volume);
        out.mirror.extend_from_slice(&self.base.mirror);
    }

    fn images(&self, t: f64, pos: &[V2], out: &mut GhostGeometry<2>, source: &mut Vec<usize>) {
        if self.kind != GhostKind::Images {
            return;
        }
        let pose = self.pose(t);
        let normals = solid_normals(&self.points, self.fluid_side);
        for (w, n0) in self.points.windows(2).zip(&normals) {
            let (p0, p1) = (pose.point(&w[0]), pose.point(&w[1]));
            let n = pose.vector(n0);
            let along = p1 - p0;
            let l2 = along.norm_squared();
            // Signed distance from the side's line, positive on the fluid side.
            let depth_of = |x: &V2| -(x - p0).dot(&n);
            let nearest = pos.iter().map(depth_of).fold(f64::INFINITY, f64::min);
            let reach = image_reach(self.support, nearest);
            for (j, x) in pos.iter().enumerate() {
                let s = (x - p0).dot(&along) / l2;
                let depth = depth_of(x);
                if !(0.0..=1.0).contains(&s) || depth <= 0.0 || depth >= reach {
                    continue;
                }
                let foot = x + n * depth;
                out.pos.push(x + n * (2.0 * depth));
                out.interp.push(*x);
                out.wall_vel.push(pose.velocity_at(&foot));
                out.wall_acc.push(pose.acceleration_at(&foot));
                out.volume.push(0.0); // the solver gives an image its particle's volume m/ρ
                out.mirror.push(Mirror::Plane);
                source.push(j);
            }
        }
    }

    fn flux_nodes(&self, t: f64, out: &mut FluxNodes<2>) {
        if self.kind != GhostKind::NormalFlux {
            return;
        }
        let pose = self.pose(t);
        let normals = solid_normals(&self.points, self.fluid_side);
        for (w, n) in self.points.windows(2).zip(&normals) {
            let side = w[1] - w[0];
            let m = ((side.norm() * FLUX_NODES_PER_DX / self.ds).ceil() as usize).max(1);
            let area = side.norm() / m as f64;
            for k in 0..m {
                let x = pose.point(&(w[0] + side * ((k as f64 + 0.5) / m as f64)));
                out.pos.push(x);
                out.outward.push(pose.vector(n));
                out.area.push(area);
                out.wall_vel.push(pose.velocity_at(&x));
                out.wall_acc.push(pose.acceleration_at(&x));
            }
        }
    }

    fn keep_out(&self, t: f64, x: &mut V2, u: &mut V2) -> bool {
        let pose = self.pose(t);
        let local = pose.local(x);
        let Some((foot, n)) = solid_side(&self.points, self.fluid_side, &local, self.support) else {
            return false;
        };
        let depth = (local - foot).dot(&n);
        *x = pose.point(&(foot - n * (0.5 * self.ds).min(depth.max(0.0) + 0.25 * self.ds)));
        let n = pose.vector(&n);
        let rel = (*u - pose.velocity_at(x)).dot(&n);
        if rel > 0.0 {
            *u -= n * rel;
        }
        true
    }
}

/// If `x` is on the solid side of the polyline within `band` of it, its foot on the wall and the wall's
/// solid-side normal there. Points whose nearest wall point is a free end of the polyline are never inside
/// (they went round the wall's end, not through it).
pub fn solid_side(points: &[V2], side: FluidSide, x: &V2, band: f64) -> Option<(V2, V2)> {
    let mut best: Option<(f64, usize, f64)> = None; // (distance², segment, parameter)
    for (k, w) in points.windows(2).enumerate() {
        let ab = w[1] - w[0];
        let l2 = ab.norm_squared();
        let t = ((x - w[0]).dot(&ab) / l2).clamp(0.0, 1.0);
        let d2 = (x - (w[0] + ab * t)).norm_squared();
        if best.is_none_or(|b| d2 < b.0) {
            best = Some((d2, k, t));
        }
    }
    let (d2, k, t) = best?;
    if d2 > band * band {
        return None;
    }
    // Only a point within the band needs the normals (this runs for every particle at every step).
    let normals = solid_normals(points, side);
    let nseg = points.len() - 1;
    let foot = points[k] + (points[k + 1] - points[k]) * t;
    let n = if t <= 0.0 {
        if k == 0 {
            return None;
        }
        (normals[k - 1] + normals[k]).normalize()
    } else if t >= 1.0 {
        if k + 1 == nseg {
            return None;
        }
        (normals[k] + normals[k + 1]).normalize()
    } else {
        normals[k]
    };
    ((x - foot).dot(&n) > 0.0).then_some((foot, n))
}

/// Unit normal of each segment pointing away from the fluid (into the solid).
pub fn solid_normals(points: &[V2], side: FluidSide) -> Vec<V2> {
    points
        .windows(2)
        .map(|w| {
            let t = (w[1] - w[0]).normalize();
            let left = V2::new(-t.y, t.x);
            match side {
                FluidSide::Left => -left,
                FluidSide::Right => left,
            }
        })
        .collect()
}

/// Offset of the polyline by `d` towards the solid, with mitred joints.
fn offset_polyline(points: &[V2], normals: &[V2], d: f64) -> Vec<V2> {
    let n = points.len();
    (0..n)
        .map(|k| {
            if k == 0 {
                points[0] + normals[0] * d
            } else if k == n - 1 {
                points[k] + normals[k - 1] * d
            } else {
                let (a, b) = (normals[k - 1], normals[k]);
                let denom = (1.0 + a.dot(&b)).max(0.1);
                points[k] + (a + b) * (d / denom)
            }
        })
        .collect()
}

fn is_corner(normals: &[V2], k: usize) -> bool {
    // Vertex k joins segments k-1 and k.
    let c = normals[k - 1].dot(&normals[k]).clamp(-1.0, 1.0);
    c.acos() > CORNER_TURN
}

/// Point at arc length s along a chain of points.
fn point_at(chain: &[V2], cum: &[f64], s: f64) -> V2 {
    let k = match cum.iter().position(|&c| c >= s) {
        Some(0) => return chain[0],
        Some(k) => k,
        None => return *chain.last().unwrap(),
    };
    let seg = cum[k] - cum[k - 1];
    let f = if seg > 0.0 { (s - cum[k - 1]) / seg } else { 0.0 };
    chain[k - 1] + (chain[k] - chain[k - 1]) * f
}

/// Samples one offset profile at spacing ds, chain by chain (see module doc). With `anchor_start` the first
/// chain is sampled from the polyline's first point even when it ends at a corner (evenly, at the spacing
/// nearest ds that fits), so a wall that continues another one at its start keeps the other's lattice.
fn sample_offset(q: &[V2], normals: &[V2], ds: f64, anchor_start: bool) -> Vec<V2> {
    let n = q.len();
    let mut breaks = vec![0usize];
    for k in 1..n - 1 {
        if is_corner(normals, k) {
            breaks.push(k);
        }
    }
    breaks.push(n - 1);
    let mut out = vec![];
    for (b, w) in breaks.windows(2).enumerate() {
        let (a, e) = (w[0], w[1]);
        let chain = &q[a..=e];
        let mut cum = vec![0.0];
        for s in chain.windows(2) {
            cum.push(cum.last().unwrap() + (s[1] - s[0]).norm());
        }
        let len = *cum.last().unwrap();
        let start_corner = b > 0;
        let end_corner = b + 2 < breaks.len();
        let eps = 1e-9 * ds;
        let arcs: Vec<f64> = match (start_corner, end_corner) {
            (true, true) => {
                let m = ((len / ds).round() as usize).max(1);
                (0..m).map(|k| k as f64 * len / m as f64).collect()
            }
            (true, false) | (false, false) => {
                let m = ((len + eps) / ds).floor() as usize;
                (0..=m).map(|k| k as f64 * ds).collect()
            }
            (false, true) if anchor_start => {
                let m = ((len / ds).round() as usize).max(1);
                (0..m).map(|k| k as f64 * len / m as f64).collect()
            }
            (false, true) => {
                let m = ((len + eps) / ds).floor() as usize;
                (1..=m).rev().map(|k| len - k as f64 * ds).collect()
            }
        };
        out.extend(arcs.into_iter().map(|s| point_at(chain, &cum, s)));
    }
    out
}

/// Nearest point on the polyline to `x`.
pub fn nearest_point(points: &[V2], x: &V2) -> V2 {
    nearest_on_polyline(points, x).0
}

/// Nearest point on the polyline to `x`, with the segment it lies on and its parameter in [0, 1] there.
pub fn nearest_on_polyline(points: &[V2], x: &V2) -> (V2, usize, f64) {
    let mut best = (points[0], 0, 0.0);
    let mut best_d2 = f64::INFINITY;
    for (k, w) in points.windows(2).enumerate() {
        let (a, b) = (w[0], w[1]);
        let ab = b - a;
        let l2 = ab.norm_squared();
        let t = if l2 > 0.0 {
            ((x - a).dot(&ab) / l2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let p = a + ab * t;
        let d2 = (x - p).norm_squared();
        if d2 < best_d2 {
            best_d2 = d2;
            best = (p, k, t);
        }
    }
    best
}

/// Velocity and acceleration of every vertex of a deforming polyline (m/s, m/s²); the wall's values at a
/// ghost are interpolated linearly along the segment of its foot.
#[derive(Clone, Debug, Default)]
pub struct VertexMotion {
    pub vel: Vec<V2>,
    pub acc: Vec<V2>,
}

/// The ghost layers of a still polyline: offsets (k + ½) ds for all k with (k + ½) ds < support.
pub fn ghost_layers(points: &[V2], side: FluidSide, ds: f64, support: f64) -> GhostGeometry<2> {
    ghost_layers_moving(points, None, side, ds, support, false)
}

/// The ghost layers of a polyline whose vertices move with `motion` (a deforming wall, thesis §7.1.1:
/// "the generation of the fixed ghost particles is repeated at each time step"). Ghosts whose foot is a
/// corner vertex (turn above 30°) mirror through that point (Fig. 7.3); all others through the wall.
/// `anchor_start`: sample from the first point (see `sample_offset`), for a wall that continues another.
pub fn ghost_layers_moving(
    points: &[V2],
    motion: Option<&VertexMotion>,
    side: FluidSide,
    ds: f64,
    support: f64,
    anchor_start: bool,
) -> GhostGeometry<2> {
    let mut g = GhostGeometry::default();
    if points.len() < 2 {
        return g;
    }
    let normals = solid_normals(points, side);
    let corners: Vec<V2> = (1..points.len() - 1)
        .filter(|&k| is_corner(&normals, k))
        .map(|k| points[k])
        .collect();
    // A closed polyline (last point on the first, e.g. a lidded tank started in the middle of a side) has its
    // two ends meet: both end chains sample the meeting point, which must be one ghost, not two.
    let closed = (points[0] - points[points.len() - 1]).norm() < 1e-9 * ds;
    let mut k = 0;
    let mut samples = vec![];
    while (k as f64 + 0.5) * ds < support {
        let d = (k as f64 + 0.5) * ds;
        let q = offset_polyline(points, &normals, d);
        let mut layer = sample_offset(&q, &normals, ds, anchor_start);
        if closed && layer.len() > 1 && (layer[0] - layer[layer.len() - 1]).norm() < 1e-6 * ds {
            layer.pop();
        }
        samples.extend(layer);
        k += 1;
    }
    use rayon::prelude::*;
    let feet: Vec<(V2, usize, f64)> = samples.par_iter().map(|p| nearest_on_polyline(points, p)).collect();
    for (p, (foot, seg, t)) in samples.into_iter().zip(feet) {
        let at_corner = corners.iter().any(|v| (v - foot).norm() < 1e-9 * ds);
        g.mirror.push(if at_corner { Mirror::Point } else { Mirror::Plane });
        g.pos.push(p);
        g.interp.push(foot * 2.0 - p);
        let (v, a) = match motion {
            Some(m) => (
                m.vel[seg] * (1.0 - t) + m.vel[seg + 1] * t,
                m.acc[seg] * (1.0 - t) + m.acc[seg + 1] * t,
            ),
            None => (V2::zeros(), V2::zeros()),
        };
        g.wall_vel.push(v);
        g.wall_acc.push(a);
        g.volume.push(ds * ds);
    }
    g
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tank_ghosts_lie_on_the_fluid_lattice_and_mirror_into_the_fluid() {
        let dx = 0.1;
        let pts = vec![
            V2::new(0.0, 1.0),
            V2::new(0.0, 0.0),
            V2::new(2.0, 0.0),
            V2::new(2.0, 1.0),
        ];
        let g = ghost_layers(&pts, FluidSide::Left, dx, 0.399);
        // 4 layers; every ghost sits at ((i + ½) dx, (j + ½) dx), outside the tank, within the support.
        for (p, q) in g.pos.iter().zip(&g.interp) {
            let fx = p.x / dx - 0.5;
            let fy = p.y / dx - 0.5;
            assert!(
                (fx - fx.round()).abs() < 1e-9 && (fy - fy.round()).abs() < 1e-9,
                "{p:?} off lattice"
            );
            assert!(p.x < 0.0 || p.x > 2.0 || p.y < 0.0, "{p:?} inside the fluid");
            assert!(q.x > 0.0 && q.x < 2.0 && q.y > 0.0, "mirror {q:?} not in the fluid");
        }
        // No duplicates.
        for i in 0..g.pos.len() {
            for j in i + 1..g.pos.len() {
                assert!((g.pos[i] - g.pos[j]).norm() > 1e-9, "duplicate ghost {:?}", g.pos[i]);
            }
        }
        // Corner block: the 4×4 ghosts below-left of the origin mirror through the vertex (central symmetry).
        let corner: Vec<_> = g
            .pos
            .iter()
            .zip(&g.interp)
            .filter(|(p, _)| p.x < 0.0 && p.y < 0.0)
            .collect();
        assert_eq!(corner.len(), 16);
        for (p, q) in corner {
            assert!((p + q).norm() < 1e-12);
        }
        // A point inside the floor is detected; one past the free top end of a side is not.
        assert!(solid_side(&pts, FluidSide::Left, &V2::new(1.0, -0.02), 0.4).is_some());
        assert!(solid_side(&pts, FluidSide::Left, &V2::new(1.0, 0.02), 0.4).is_none());
        assert!(solid_side(&pts, FluidSide::Left, &V2::new(-0.05, 1.1), 0.4).is_none());
        assert!(solid_side(&pts, FluidSide::Left, &V2::new(2.01, -0.01), 0.4).is_some());
        let points = g.mirror.iter().filter(|m| **m == Mirror::Point).count();
        assert_eq!(points, 32, "the two 4x4 corner blocks mirror through the vertices");
        // Count: bottom 4 layers × 20 + two sides × 4 layers × 10 + two corners × 16.
        assert_eq!(g.pos.len(), 4 * 20 + 2 * 4 * 10 + 2 * 16);
    }

    /// The two-sided tank of the image tests: floor 2 long, sides 1 high, dx 0.1, support 0.399.
    fn image_tank() -> (PolylineWall, f64, f64) {
        let (dx, support) = (0.1, 0.399);
        let pts = vec![
            V2::new(0.0, 1.0),
            V2::new(0.0, 0.0),
            V2::new(2.0, 0.0),
            V2::new(2.0, 1.0),
        ];
        let wall = PolylineWall::new("tank", pts, FluidSide::Left, RigidMotion::Fixed, dx, support)
            .with_ghosts(GhostKind::Images);
        (wall, dx, support)
    }

    /// Oracle for the images' reach (`image_reach`): on a jittered lattice filling the tank, every image that a
    /// brute-force search finds within the support of some particle is made, every image made is one the full
    /// support would make, and fewer are made than the full support would (the lattice's fourth row, 3.5 dx
    /// deep, is 4.0 dx from the first row's reflection: beyond the support of 3.99 dx).
    #[test]
    fn images_are_made_where_they_touch_the_fluid_and_nowhere_deeper() {
        let (wall, dx, support) = image_tank();
        let mut jitter = crate::sph::boundary::image_oracle::jitter(12345, 0.2 * dx);
        let mut fluid = vec![];
        for i in 0..20 {
            for k in 0..8 {
                fluid.push(V2::new(
                    (i as f64 + 0.5) * dx + jitter(),
                    (k as f64 + 0.5) * dx + jitter(),
                ));
            }
        }
        let (mut out, mut source) = (GhostGeometry::default(), vec![]);
        wall.images(0.0, &fluid, &mut out, &mut source);
        // The full-support candidates: (particle, image) through each of the three sides.
        let mut candidates = vec![];
        for (j, x) in fluid.iter().enumerate() {
            if x.x < support {
                candidates.push((j, V2::new(-x.x, x.y)));
            }
            if x.y < support {
                candidates.push((j, V2::new(x.x, -x.y)));
            }
            if 2.0 - x.x < support {
                candidates.push((j, V2::new(4.0 - x.x, x.y)));
            }
        }
        crate::sph::boundary::image_oracle::check(&fluid, &candidates, &source, &out.pos, support);
    }

    #[test]
    fn image_ghosts_mirror_each_particle_within_the_support_of_each_side() {
        let (wall, dx, support) = image_tank();
        // Only the two 4×4 corner blocks of fixed ghosts remain.
        let mut fixed = GhostGeometry::default();
        wall.ghosts(0.0, &mut fixed);
        assert_eq!(fixed.len(), 32);
        assert!(fixed.mirror.iter().all(|m| *m == Mirror::Point));
        // A particle near the left-hand corner has two images (floor and side wall), one mid-tank near the
        // floor has one, one beyond the support of every side none.
        let fluid = [V2::new(0.15, 0.05), V2::new(1.0, 0.25), V2::new(1.0, 0.5)];
        let (mut out, mut source) = (GhostGeometry::default(), vec![]);
        wall.images(0.0, &fluid, &mut out, &mut source);
        let mut got: Vec<(usize, V2)> = source.iter().copied().zip(out.pos.iter().copied()).collect();
        got.sort_by(|a, b| (a.0, a.1.x).partial_cmp(&(b.0, b.1.x)).unwrap());
        let want = [
            (0, V2::new(-0.15, 0.05)),
            (0, V2::new(0.15, -0.05)),
            (1, V2::new(1.0, -0.25)),
        ];
        assert_eq!(got.len(), want.len(), "{got:?}");
        for ((j, p), (wj, wp)) in got.iter().zip(&want) {
            assert_eq!(j, wj);
            assert!((p - wp).norm() < 1e-12, "{p:?} != {wp:?}");
        }
        // Each image's mirror point is its particle, and the wall is halfway between.
        for (k, &j) in source.iter().enumerate() {
            assert_eq!(out.interp[k], fluid[j]);
            assert_eq!(out.mirror[k], Mirror::Plane);
        }
        // A wall with fixed ghosts makes no images.
        let plain = PolylineWall::new(
            "t",
            vec![V2::new(0.0, 0.0), V2::new(2.0, 0.0)],
            FluidSide::Left,
            RigidMotion::Fixed,
            dx,
            support,
        );
        let (mut out2, mut src2) = (GhostGeometry::default(), vec![]);
        plain.images(0.0, &fluid, &mut out2, &mut src2);
        assert!(out2.is_empty() && src2.is_empty());
    }
}
