//! A still 3D wall of any shape, given as points of its surface with their unit normals into the fluid
//! (an oriented point cloud, sampled finer than the particles), made of fixed ghost particles (thesis §7.1.1
//! carried to a curved surface in 3D).
//!
//! The ghosts are the nodes of the fluid's lattice (origin + (i + ½) ds along each axis) on the solid side of
//! the surface within the kernel support of it: with s the sample nearest a node r and n its normal, the node
//! is solid if d = (r − s)·n < 0, and its mirror point is r − 2 d n, the mirror image through the tangent plane
//! at s (the nearest surface point to second order in the sample spacing). Fluid laid on the nodes with d ≥ 0
//! and the ghosts then tile the lattice, each node one or the other. Where samples coincide on a crease (a keel
//! or a stem sampled from both sides) the largest of their signed distances counts: the solid is taken convex
//! there, so a node is solid only behind both faces, and the classification is the same on either side of a
//! symmetry plane (a tie broken by index once classified a node below a keel as solid on one side only).
//! Knows nothing of hulls.

use super::boundary::{Boundary, FluxNodes, GhostGeometry, Mirror, RigidMotion};
use nalgebra::Vector3;
use std::collections::HashMap;

type V3 = Vector3<f64>;

/// A still wall made of the lattice nodes behind an oriented surface.
#[derive(Clone, Debug)]
pub struct SurfaceWall {
    name: String,
    points: Vec<V3>,
    normals: Vec<V3>,
    /// Samples per cell of edge `support`, keyed by the cell's integer coordinates.
    cells: HashMap<[i64; 3], Vec<u32>>,
    ds: f64,
    support: f64,
    /// The samples' bounding box (m).
    lo: V3,
    hi: V3,
    /// Ghost geometry at t = 0.
    base: GhostGeometry<3>,
    /// The wall's translation (a towed hull); still by default.
    motion: RigidMotion<3>,
    /// With [`SurfaceWall::with_normal_flux`], the samples as the nodes of a normal-flux wall at t = 0; none
    /// otherwise.
    nodes: FluxNodes<3>,
}

impl SurfaceWall {
    /// The wall of the surface samples `points` (m) with unit normals `normals` into the fluid, for the lattice
    /// origin + (i + ½) ds and kernel support `support` (m); ghosts are kept only where `keep` accepts their
    /// position (e.g. inside a tank). The samples should be spaced well below ds (a quarter of it keeps the
    /// nearest sample within ds/8 of the nearest surface point).
    pub fn new(
        name: &str,
        points: Vec<V3>,
        normals: Vec<V3>,
        origin: V3,
        ds: f64,
        support: f64,
        keep: impl Fn(&V3) -> bool,
    ) -> Result<Self, String> {
        if points.is_empty() || points.len() != normals.len() {
            return Err(format!(
                "surface wall '{name}': {} points and {} normals, expected as many of each and at least one",
                points.len(),
                normals.len()
            ));
        }
        if !(ds > 0.0 && support > 0.0) {
            return Err(format!(
                "surface wall '{name}': spacing {ds} and support {support} must be positive"
            ));
        }
        let mut cells: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        for (k, p) in points.iter().enumerate() {
            cells.entry(cell_of(p, support)).or_default().push(k as u32);
        }
        let (mut lo, mut hi) = (V3::repeat(f64::INFINITY), V3::repeat(f64::NEG_INFINITY));
        for p in &points {
            lo = lo.inf(p);
            hi = hi.sup(p);
        }
        let mut wall = SurfaceWall {
            name: name.to_string(),
            points,
            normals,
            cells,
            ds,
            support,
            lo,
            hi,
            base: GhostGeometry::default(),
            motion: RigidMotion::Fixed,
            nodes: FluxNodes::default(),
        };
        let first = |a: usize| ((lo[a] - support - origin[a]) / ds - 0.5).floor() as i64;
        let last = |a: usize| ((hi[a] + support - origin[a]) / ds - 0.5).ceil() as i64;
        for k in first(2)..=last(2) {
            for j in first(1)..=last(1) {
                for i in first(0)..=last(0) {
                    let r = origin + V3::new(i as f64 + 0.5, j as f64 + 0.5, k as f64 + 0.5) * ds;
                    if let Some((d, n)) = wall.ghost_side(&r) {
                        if keep(&r) {
                            wall.push_ghost(r, r - n * (2.0 * d));
                        }
                    }
                }
            }
        }
        Ok(wall)
    }

    /// The same wall with `extra` ghosts of the caller's (positions, mirror points and volumes at t = 0), carried
    /// along with it: where the wall meets another boundary and neither's rule fills the solid behind both (the
    /// bent-wall channel's floor corner, `compare3d::bent_wall_3d`).
    pub fn with_extra_ghosts(mut self, extra: &[(V3, V3)]) -> Self {
        for (r, m) in extra {
            self.push_ghost(*r, *m);
        }
        self
    }

    /// The signed distance and normal at lattice node `r` if the wall's rule makes it a ghost: on the solid side
    /// of its nearest sample, within the kernel support of it (the constructor's `keep` aside).
    pub fn ghost_side(&self, r: &V3) -> Option<(f64, V3)> {
        self.signed_distance(r).filter(|(d, _)| *d < 0.0 && -d < self.support)
    }

    fn push_ghost(&mut self, r: V3, mirror: V3) {
        self.base.pos.push(r);
        self.base.interp.push(mirror);
        self.base.wall_vel.push(V3::zeros());
        self.base.wall_acc.push(V3::zeros());
        self.base.volume.push(self.ds.powi(3));
        self.base.mirror.push(Mirror::Plane);
    }

    /// The same wall translating with `motion` (its ghosts carried along, each with the wall's velocity and
    /// acceleration; off the fluid's lattice once it moves, as the 2D+t section's are).
    /// The same surface as a normal-flux wall (thesis §7.1.2): no ghosts, its samples the nodes, `areas` (m²)
    /// the patch of surface each stands for. The samples still decide which side of the wall a point is on
    /// ([`SurfaceWall::signed_distance`], [`Boundary::keep_out`]).
    pub fn with_normal_flux(mut self, areas: Vec<f64>) -> Result<Self, String> {
        if areas.len() != self.points.len() || areas.iter().any(|a| !(a.is_finite() && *a >= 0.0)) {
            return Err(format!(
                "surface wall '{}': {} areas for {} points, expected one finite area ≥ 0 per point",
                self.name,
                areas.len(),
                self.points.len()
            ));
        }
        self.base = GhostGeometry::default();
        self.nodes = FluxNodes {
            pos: self.points.clone(),
            outward: self.normals.iter().map(|n| -n).collect(),
            wall_vel: vec![V3::zeros(); areas.len()],
            wall_acc: vec![V3::zeros(); areas.len()],
            area: areas,
        };
        Ok(self)
    }

    /// The displacement, velocity and acceleration (m, m/s, m/s²) the wall carries its ghosts or nodes with
    /// at time t; `None` for a still wall.
    fn carried(&self, t: f64) -> Option<(V3, V3, V3)> {
        self.moves().then(|| {
            (
                self.motion.displacement(t),
                self.motion.velocity(t),
                self.motion.acceleration(t),
            )
        })
    }

    pub fn with_motion(mut self, motion: RigidMotion<3>) -> Self {
        self.motion = motion;
        self
    }

    /// [`SurfaceWall::signed_distance`] of the wall as it stands at time t.
    pub fn signed_distance_at(&self, t: f64, r: &V3) -> Option<(f64, V3)> {
        self.signed_distance(&(r - self.motion.displacement(t)))
    }

    /// The distance from `r` to the surface's tangent plane at the nearest sample, negative on the solid side,
    /// with that sample's normal; `None` if no sample is within the kernel support. The wall at t = 0.
    pub fn signed_distance(&self, r: &V3) -> Option<(f64, V3)> {
        // Beyond the samples' box grown by the support no sample is within reach (most of a tank's particles).
        if (0..3).any(|a| r[a] < self.lo[a] - self.support || r[a] > self.hi[a] + self.support) {
            return None;
        }
        let c = cell_of(r, self.support);
        // The nearest sample (d², signed distance, index). Where samples coincide on a crease (a keel or a stem
        // line sampled from both sides, each with its own normal), a convex solid: a point is solid only if
        // it is behind every face that meets there, so the largest signed distance counts, and among equal
        // ones the lowest index (whatever the visiting order).
        let mut best: Option<(f64, f64, u32)> = None;
        for dz in -1..=1 {
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let Some(list) = self.cells.get(&[c[0] + dx, c[1] + dy, c[2] + dz]) else {
                        continue;
                    };
                    for &k in list {
                        let rel = r - self.points[k as usize];
                        let d2 = rel.norm_squared();
                        let d = rel.dot(&self.normals[k as usize]);
                        let better = match best {
                            None => true,
                            Some((b2, bd, bk)) => d2 < b2 || (d2 == b2 && (d > bd || (d == bd && k < bk))),
                        };
                        if better {
                            best = Some((d2, d, k));
                        }
                    }
                }
            }
        }
        let (d2, d, k) = best?;
        (d2 < self.support * self.support).then(|| (d, self.normals[k as usize]))
    }

    /// Whether `r` lies on the solid side within the kernel support of the surface.
    pub fn is_solid(&self, r: &V3) -> bool {
        self.signed_distance(r).is_some_and(|(d, _)| d < 0.0)
    }

    /// Ghost geometry (for tests and plots).
    pub fn base_ghosts(&self) -> &GhostGeometry<3> {
        &self.base
    }
}

fn cell_of(p: &V3, edge: f64) -> [i64; 3] {
    [0, 1, 2].map(|a| (p[a] / edge).floor() as i64)
}

impl Boundary<3> for SurfaceWall {
    fn name(&self) -> &str {
        &self.name
    }
    fn moves(&self) -> bool {
        self.motion != RigidMotion::Fixed
    }
    fn ghosts(&self, t: f64, out: &mut GhostGeometry<3>) {
        let n = out.len();
        out.append(&self.base);
        if let Some((s, v, a)) = self.carried(t) {
            for k in n..out.len() {
                out.pos[k] += s;
                out.interp[k] += s;
                out.wall_vel[k] = v;
                out.wall_acc[k] = a;
            }
        }
    }
    fn flux_nodes(&self, t: f64, out: &mut FluxNodes<3>) {
        let n = out.len();
        out.append(&self.nodes);
        if let Some((s, v, a)) = self.carried(t) {
            for k in n..out.len() {
                out.pos[k] += s;
                out.wall_vel[k] = v;
                out.wall_acc[k] = a;
            }
        }
    }
    /// A particle found on the solid side is put back on the fluid side, a quarter spacing off the tangent
    /// plane, its velocity into the wall removed.
    fn keep_out(&self, t: f64, x: &mut V3, u: &mut V3) -> bool {
        let Some((d, n)) = self.signed_distance_at(t, x) else {
            return false;
        };
        if d >= 0.0 {
            return false;
        }
        *x += n * (0.25 * self.ds - d);
        let un = (*u - self.motion.velocity(t)).dot(&n);
        if un < 0.0 {
            *u -= n * un;
        }
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sphere of radius R sampled finely: its ghosts are the lattice nodes inside it within the support of
    /// its surface, each mirrored through the sphere to the point at the same distance outside.
    #[test]
    fn ghosts_of_a_sphere_mirror_through_its_surface() {
        let (radius, ds, support) = (1.0, 0.1, 0.4);
        let (mut pts, mut nrm) = (vec![], vec![]);
        let (nt, np) = (200, 400);
        for a in 0..=nt {
            let theta = std::f64::consts::PI * a as f64 / nt as f64;
            for b in 0..np {
                let phi = 2.0 * std::f64::consts::PI * b as f64 / np as f64;
                let n = V3::new(theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos());
                pts.push(n * radius);
                nrm.push(n); // the fluid is outside
            }
        }
        let wall = SurfaceWall::new("sphere", pts, nrm, V3::zeros(), ds, support, |_| true).unwrap();
        let g = wall.base_ghosts();
        // Every node inside the shell R − support < |r| < R is a ghost, none other.
        let mut expected = 0;
        for k in -12..12 {
            for j in -12..12 {
                for i in -12..12 {
                    let r = V3::new(i as f64 + 0.5, j as f64 + 0.5, k as f64 + 0.5) * ds;
                    let n = r.norm();
                    if n < radius - 1e-3 && n > radius - support + 1e-3 {
                        expected += 1;
                    }
                }
            }
        }
        let near_shell = |n: f64| (n - radius).abs() < 1e-3 || (n - radius + support).abs() < 1e-3;
        let clear = g.pos.iter().filter(|r| !near_shell(r.norm())).count();
        assert_eq!(clear, expected);
        for (r, m) in g.pos.iter().zip(&g.interp) {
            // The mirror point is outside at the node's depth, along the radius.
            assert!((m.norm() - (2.0 * radius - r.norm())).abs() < 2e-4, "{r:?} → {m:?}");
            assert!((m.normalize() - r.normalize()).norm() < 2e-2);
        }
        assert!(wall.is_solid(&V3::new(0.0, 0.0, 0.9)) && !wall.is_solid(&V3::new(0.0, 0.0, 1.1)));
        // Far from the surface nothing is known.
        assert!(wall.signed_distance(&V3::zeros()).is_none());
    }

    /// Regression: a V keel sampled from both sides has coincident samples with mirrored normals; the nearest
    /// sample was chosen by index, so a node below the keel and its mirror image across the centre plane were
    /// classified differently (one solid, one fluid).
    #[test]
    fn node_below_a_keel_is_fluid_on_both_sides_of_the_centre_plane() {
        let (mut pts, mut nrm) = (vec![], vec![]);
        let s = std::f64::consts::FRAC_1_SQRT_2;
        for i in 0..=80 {
            for k in 0..=40 {
                let (x, t) = (i as f64 * 0.025 - 1.0, k as f64 * 0.025);
                // The wedge z = |y| − 0.5 (solid above), both faces from the keel line y = 0.
                pts.push(V3::new(x, t, t - 0.5));
                nrm.push(V3::new(0.0, s, -s));
                pts.push(V3::new(x, -t, t - 0.5));
                nrm.push(V3::new(0.0, -s, -s));
            }
        }
        let wall = SurfaceWall::new("keel", pts, nrm, V3::zeros(), 0.1, 0.4, |_| true).unwrap();
        for (y, z) in [(0.05, -0.55), (0.05, -0.6), (0.15, -0.52), (0.05, -0.4)] {
            let (a, b) = (V3::new(0.05, y, z), V3::new(0.05, -y, z));
            assert_eq!(wall.is_solid(&a), wall.is_solid(&b), "{a:?}");
            assert_eq!(wall.is_solid(&a), z > y - 0.5, "{a:?}");
        }
    }

    /// The plate z = 0, |x|, |y| ≤ ½, sampled at a quarter of 0.1, its normal up.
    fn unit_plate() -> (Vec<V3>, Vec<V3>) {
        let pts: Vec<V3> = (0..41 * 41)
            .map(|k| V3::new((k % 41) as f64 * 0.025 - 0.5, (k / 41) as f64 * 0.025 - 0.5, 0.0))
            .collect();
        let nrm = vec![V3::z(); pts.len()];
        (pts, nrm)
    }

    #[test]
    fn particle_inside_the_wall_is_put_back_without_its_velocity_into_it() {
        let (pts, nrm) = unit_plate();
        let wall = SurfaceWall::new("floor", pts, nrm, V3::zeros(), 0.1, 0.4, |r| {
            r.x.abs() < 0.5 && r.y.abs() < 0.5
        })
        .unwrap();
        let mut x = V3::new(0.0, 0.0, -0.02);
        let mut u = V3::new(0.3, 0.0, -1.0);
        assert!(wall.keep_out(0.0, &mut x, &mut u));
        assert!((x.z - 0.025).abs() < 1e-12, "{x:?}");
        assert_eq!(u, V3::new(0.3, 0.0, 0.0));
        // The plane's ghosts: 4 layers under each of the 10 × 10 nodes over it.
        assert_eq!(wall.base_ghosts().len(), 4 * 100);
    }

    /// A towed wall carries its ghosts, mirror points and the solid side along, with its velocity.
    #[test]
    fn towed_wall_carries_its_ghosts_along() {
        let (pts, nrm) = unit_plate();
        let v = V3::new(-1.0, 0.0, 0.5);
        let wall = SurfaceWall::new("floor", pts, nrm, V3::zeros(), 0.1, 0.4, |_| true)
            .unwrap()
            .with_motion(RigidMotion::ConstantVelocity(v));
        assert!(wall.moves());
        let mut g = GhostGeometry::default();
        wall.ghosts(2.0, &mut g);
        let base = wall.base_ghosts();
        for k in 0..g.len() {
            assert!((g.pos[k] - (base.pos[k] + v * 2.0)).norm() < 1e-12);
            assert!(((g.interp[k] - g.pos[k]) - (base.interp[k] - base.pos[k])).norm() < 1e-12);
            assert_eq!(g.wall_vel[k], v);
        }
        // At t = 2 the plane is at z = 1: a point at z = 0.95 is solid, and one pushed in at the wall's speed
        // leaves with the wall's normal velocity.
        assert!(wall.signed_distance_at(2.0, &V3::new(-2.0, 0.0, 0.95)).unwrap().0 < 0.0);
        let (mut x, mut u) = (V3::new(-2.0, 0.0, 0.95), V3::new(0.0, 0.0, -1.0));
        assert!(wall.keep_out(2.0, &mut x, &mut u));
        assert!((x.z - 1.025).abs() < 1e-12 && (u.z - 0.5).abs() < 1e-12, "{x:?} {u:?}");
    }
}
