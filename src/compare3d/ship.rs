//! The 3D ship scene (issue #31): any hull the 2D+t mode reads, as a 3D wall of fixed ghosts
//! ([`crate::sph::surface_wall::SurfaceWall`] on the same spline surface, [`crate::geometry::hull_solid`]), in a
//! tank that is the 2D+t scene extruded along x: half width 4 B from the centre plane (a free-slip symmetry plane,
//! port–starboard symmetry), depth 2 D, on the lattice of the fluid; the hull still (`validate hull-at-rest`) or
//! towed ([`ShipTank::motion`], [`super::towed_ship`]).
//!
//! How the walls share the lattice: the hull's ghosts are the nodes on the solid side of its surface within
//! the kernel support, on both sides of the centre plane (the mirrored hull gives the ghosts beyond the
//! symmetry plane near the keel); the tank's symmetry-plane ghosts whose mirror point is inside the hull are
//! dropped (those nodes are the hull's). Water fills the nodes below z = 0 that are neither.

use crate::geometry::hull_solid::{oriented_points, polygon_contains, section_polygon};
use crate::geometry::surface::HullSurface;
use crate::sph::body_force::BodyForce;
use crate::sph::boundary::RigidMotion;
use crate::sph::box_wall::BoxWall;
use crate::sph::particles::Fluid;
use crate::sph::polyline_wall::GhostKind;
use crate::sph::solver::{Simulation, SolverConfig};
use crate::sph::surface_wall::SurfaceWall;
use nalgebra::Vector3;

type V3 = Vector3<f64>;

const G: f64 = 9.81;
const RHO0: f64 = 1000.0;

/// Memory of a 3D ship run per lattice node of water, in bytes: the particles with their neighbour lists, stage
/// copies and the tank's and hull's ghosts. Measured as the slope of the peak resident memory between towed
/// Wigley runs (`bench-one --ship --steps 3 --threads 1`, session 46: D/dx 3 / 4 / 5, 19 316 / 45 798 / 89 436
/// fluid particles, 46.1 / 90.4 / 160.8 MB: 1 671 and 1 612 B per particle), with a tenth added for the second
/// thread's buffers and rounded up. Used to refuse a spacing the machine cannot hold, before anything is
/// allocated.
pub const BYTES_PER_PARTICLE: f64 = 1.9e3;

/// The tank around a hull, in units of the hull's L, B and D.
#[derive(Clone, Debug)]
pub struct ShipTank {
    pub hull: HullSurface,
    /// Particle spacing dx/L.
    pub dx_over_l: f64,
    /// Tank half width from the centre plane, in B: 4, the 2D+t scene's.
    pub half_width_over_b: f64,
    /// Water depth, in D: 2, the 2D+t scene's.
    pub depth_over_d: f64,
    /// Water ahead of the stem and behind the stern, in L.
    pub ahead_over_l: f64,
    pub behind_over_l: f64,
    /// The tank's flat faces (the symmetry plane among them): fixed ghosts on the lattice, or the images of the
    /// fluid ([`GhostKind::Images`], which hold the 3D still tank's hydrostatic pressure where fixed ghosts let
    /// it creep at coarse spacings, docs/reference/method.md "Three dimensions").
    pub tank_ghosts: GhostKind,
    /// The hull's motion: still (the default) or towed ([`RigidMotion::Ramp`], `towed_ship`).
    pub motion: RigidMotion<3>,
    /// Sound speed c0/√(g D): 10 keeps the density within about 1 % at the keel at rest (Mach 0.1 for a flow
    /// of √(g D)).
    pub c0_over_sqrt_gd: f64,
    /// Particle shifting after each step: the solver's default (the near-wall band), or a study's 2D+t
    /// configuration's, so that both models of a case run the same method.
    pub shifting: crate::sph::particle_shifting::ParticleShifting,
    /// The hull's wall: fixed ghosts on the lattice behind its surface (the default, thesis §7.1.1 carried to a
    /// curved surface) or the normal-flux method on its surface points ([`GhostKind::NormalFlux`], §7.1.2, the
    /// thesis's choice for its 3D hull); images are refused.
    pub hull_wall: GhostKind,
}

/// The scene, built: the simulation (boundary 0 the tank, 1 the hull) and what its measures need.
pub struct ShipScene {
    pub sim: Simulation<3>,
    /// L, B, D (m).
    pub length: f64,
    pub beam: f64,
    pub draft: f64,
    /// The tank's corners (m): x from ahead of the stem, y from the centre plane, z from the bottom to the top.
    pub lo: V3,
    pub hi: V3,
    pub hull_ghosts: usize,
}

impl ShipTank {
    /// The defaults of the 2D+t scene (4 B, 2 D) with `ahead` and `behind` L of water beyond the hull's ends.
    pub fn new(hull: HullSurface, dx_over_l: f64, ahead: f64, behind: f64) -> Self {
        ShipTank {
            hull,
            dx_over_l,
            half_width_over_b: 4.0,
            depth_over_d: 2.0,
            ahead_over_l: ahead,
            behind_over_l: behind,
            tank_ghosts: GhostKind::Fixed,
            motion: RigidMotion::Fixed,
            c0_over_sqrt_gd: 10.0,
            shifting: Default::default(),
            hull_wall: GhostKind::Fixed,
        }
    }

    /// Builds the scene: the tank, the hull, and the water at rest with its hydrostatic pressure.
    pub fn build(&self) -> anyhow::Result<ShipScene> {
        let m = &self.hull.meta;
        let (l, b, d) = (m.length_m, m.beam_m, m.draft_m);
        let dx = self.dx_over_l * l;
        anyhow::ensure!(
            self.dx_over_l > 0.0 && d / dx >= 2.0,
            "3D ship: spacing dx/L {} gives {:.2} particles over the draft, expected at least 2",
            self.dx_over_l,
            d / dx
        );
        anyhow::ensure!(
            [self.ahead_over_l, self.behind_over_l]
                .iter()
                .all(|a| a.is_finite() && *a >= 0.0),
            "3D ship: water ahead of the stem ({} L) and behind the stern ({} L) must be ≥ 0",
            self.ahead_over_l,
            self.behind_over_l
        );
        let cells = |length: f64| (length / dx).round().max(1.0);
        let (x0, x1) = self.hull.x_range;
        let lo = V3::new(
            (x0 * l / dx).floor() * dx - cells(self.ahead_over_l * l) * dx,
            0.0,
            -cells(self.depth_over_d * d) * dx,
        );
        let deck = m.draft_m.max(self.top_of_hull() * l);
        let hi = V3::new(
            lo.x + cells((x1 - x0) * l + (self.ahead_over_l + self.behind_over_l) * l) * dx,
            cells(self.half_width_over_b * b) * dx,
            lo.z + cells(-lo.z + deck) * dx,
        );
        let c0 = self.c0_over_sqrt_gd * (G * d).sqrt();
        let mut cfg = SolverConfig::new(dx, RHO0, c0, BodyForce::Uniform(V3::new(0.0, 0.0, -G)));
        cfg.domain = Some((lo - (hi - lo), hi + (hi - lo)));
        cfg.shifting = self.shifting;
        let support = cfg.kernel.support_over_h() * cfg.h;

        // Before anything is allocated: the tank must hold the hull with water around it (one row at least), and the machine the
        // particles.
        let (half_beam, keel) = self.extent();
        // At least one row of water between the hull and a face: less, and no particle fits there; the kernel
        // may reach across the gap, where the two walls' ghosts both act.
        let side = (hi.y - half_beam * l) / dx;
        anyhow::ensure!(
            side >= 1.0,
            "3D ship: the tank's half width {} B leaves {:.2} dx of water between the hull's widest point ({:.3} B from \
             the centre plane) and the tank's side; expected at least 1 dx (a row of particles): a narrower tank \
             cuts the hull",
            self.half_width_over_b,
            side.max(0.0),
            half_beam * l / b
        );
        let under = (keel * l - lo.z) / dx;
        anyhow::ensure!(
            under >= 1.0,
            "3D ship: the water's depth {} D leaves {:.2} dx under the keel ({:.3} D deep); expected at least 1 dx \
             (a row of particles): a shallower tank cuts the hull",
            self.depth_over_d,
            under.max(0.0),
            -keel * l / d
        );
        let nodes = [(hi.x - lo.x) / dx, (hi.y - lo.y) / dx, -lo.z / dx]
            .iter()
            .product::<f64>();
        let need = nodes * BYTES_PER_PARTICLE;
        if let Some(free) = crate::process_usage::available_memory_bytes() {
            anyhow::ensure!(
                need <= free as f64,
                "3D ship: spacing dx/L {:.3e} asks for about {:.3e} particles, about {:.1} GiB at {BYTES_PER_PARTICLE} \
                 bytes each (measured), more than the {:.1} GiB this machine has available; expected a coarser spacing \
                 (fewer particles over the draft)",
                self.dx_over_l,
                nodes,
                need / 1024f64.powi(3),
                free as f64 / 1024f64.powi(3)
            );
        }

        let samples = oriented_points(&self.hull, 0.25 * self.dx_over_l);
        let hull_wall = SurfaceWall::new(
            "hull",
            samples.iter().map(|p| V3::from(p.pos) * l).collect(),
            samples.iter().map(|p| V3::from(p.normal)).collect(),
            lo,
            dx,
            support,
            |r| r.x > lo.x && r.x < hi.x && r.z > lo.z && r.y < hi.y,
        )
        .map_err(anyhow::Error::msg)?
        .with_motion(self.motion);
        let hull_wall = match self.hull_wall {
            GhostKind::Fixed => hull_wall,
            GhostKind::NormalFlux => hull_wall
                .with_normal_flux(samples.iter().map(|p| p.area * l * l).collect())
                .map_err(anyhow::Error::msg)?,
            GhostKind::Images => anyhow::bail!(
                "3D ship: the hull's wall takes fixed ghosts or normal-flux nodes, not images (those are for the \
                 tank's flat faces)"
            ),
        };
        // Solid: the surface decides near it, the section polygon deeper inside.
        let polygons = |x: f64| section_polygon(&self.hull, x / l, 400);
        // `inside` (the polygon test) is asked only when the surface does not decide.
        let solid = |r: &V3, inside: &dyn Fn(&V3) -> bool| match hull_wall.signed_distance(r) {
            Some((dist, _)) => dist < 0.0,
            None => inside(r),
        };
        let in_polygon =
            |p: &Option<Vec<[f64; 2]>>, r: &V3| p.as_ref().is_some_and(|p| polygon_contains(p, r.y / l, r.z / l));
        let tank = BoxWall::new("tank", lo, hi, dx, support)
            .map_err(anyhow::Error::msg)?
            .with_ghosts(self.tank_ghosts)
            .retain_ghosts(|_, mirror| !solid(mirror, &|r| in_polygon(&polygons(r.x), r)));

        let eos = cfg.eos;
        let mut fluid = Fluid::default();
        let n = [0, 1, 2].map(|a| ((hi[a] - lo[a]) / dx).round() as usize);
        let nz_water = (-lo.z / dx).round() as usize;
        for i in 0..n[0] {
            let x = lo.x + (i as f64 + 0.5) * dx;
            let poly = polygons(x);
            let inside = |r: &V3| in_polygon(&poly, r);
            for k in 0..nz_water {
                let z = lo.z + (k as f64 + 0.5) * dx;
                let rho = eos.density(RHO0 * G * (-z));
                for j in 0..n[1] {
                    let r = V3::new(x, lo.y + (j as f64 + 0.5) * dx, z);
                    if !solid(&r, &inside) {
                        fluid.push(r, V3::zeros(), rho, rho * dx.powi(3), -z);
                    }
                }
            }
        }
        let hull_ghosts = hull_wall.base_ghosts().len();
        let sim = Simulation::new(cfg, fluid, vec![Box::new(tank), Box::new(hull_wall)]);
        Ok(ShipScene {
            sim,
            length: l,
            beam: b,
            draft: d,
            lo,
            hi,
            hull_ghosts,
        })
    }

    /// The hull's largest half breadth and its deepest point (units of L, the latter ≤ 0), from its sections.
    fn extent(&self) -> (f64, f64) {
        let (x0, x1) = self.hull.x_range;
        let (mut y, mut z) = (0.0f64, 0.0f64);
        for i in 0..=100 {
            if let Some(c) = self.hull.curve(x0 + (x1 - x0) * i as f64 / 100.0) {
                for k in 0..=100 {
                    let p = c.point(k as f64 / 100.0);
                    y = y.max(p.y);
                    z = z.min(p.z);
                }
            }
        }
        (y, z)
    }

    /// The highest point of the hull (units of L).
    fn top_of_hull(&self) -> f64 {
        let (x0, x1) = self.hull.x_range;
        (0..=20)
            .filter_map(|i| self.hull.curve(x0 + (x1 - x0) * i as f64 / 20.0))
            .map(|c| c.point(1.0).z)
            .fold(0.0, f64::max)
    }
}

/// Points of the hull's starboard side (y > 0) at the section x/L where it crosses depth f D below the calm
/// waterline, for each f in `depths`, with the unit normal into the water (both in metres and L-free); a depth
/// the section does not reach is left out.
pub fn side_points(hull: &HullSurface, x: f64, depths: &[f64]) -> Vec<(f64, V3, V3)> {
    let (l, d) = (hull.meta.length_m, hull.meta.draft_m / hull.meta.length_m);
    let Some(c) = hull.curve(x) else {
        return vec![];
    };
    let mut out = vec![];
    for &f in depths {
        let z = -f * d;
        // The girth from the keel upwards: the first ξ where the section reaches z.
        let n = 2000;
        let Some(k) = (1..=n).find(|&k| c.point(k as f64 / n as f64).z >= z) else {
            continue;
        };
        let (mut a, mut b) = ((k - 1) as f64 / n as f64, k as f64 / n as f64);
        if c.point(a).z > z {
            continue; // the keel is above this depth
        }
        for _ in 0..50 {
            let m = 0.5 * (a + b);
            if c.point(m).z < z {
                a = m;
            } else {
                b = m;
            }
        }
        let p = c.point(0.5 * (a + b));
        let n = [-(p.y_x * p.z_xi - p.z_x * p.y_xi), p.z_xi, -p.y_xi];
        let nn = V3::from(n).normalize();
        out.push((f, V3::new(x, p.y, p.z) * l, nn));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The hull's ghosts are mirror-symmetric across the centre plane (the hull is), node for node, and no
    /// lattice node is taken twice, by the hull and by the tank's symmetry plane.
    #[test]
    fn hull_ghosts_are_symmetric_and_share_no_node_with_the_tank() {
        let hull = HullSurface::new(&crate::geometry::wigley::wigley(&Default::default()));
        let d_over_l = hull.meta.draft_m / hull.meta.length_m;
        let scene = ShipTank::new(hull, d_over_l / 3.0, 0.1, 0.1).build().unwrap();
        let dx = scene.sim.cfg.dx;
        let key = |r: &V3| [0, 1, 2].map(|a| ((r[a] - scene.lo[a]) / dx - 0.5).round() as i64);
        let mut ghosts = crate::sph::boundary::GhostGeometry::default();
        let mut owner = vec![];
        for (b, wall) in scene.sim.boundaries.iter().enumerate() {
            let n = ghosts.len();
            wall.ghosts(0.0, &mut ghosts);
            owner.extend(std::iter::repeat_n(b, ghosts.len() - n));
        }
        let mut seen = std::collections::HashMap::new();
        for (k, r) in ghosts.pos.iter().enumerate() {
            if let Some(other) = seen.insert(key(r), owner[k]) {
                panic!("node {r:?} taken by boundaries {other} and {}", owner[k]);
            }
        }
        let hull_nodes: std::collections::HashSet<_> = (0..ghosts.len())
            .filter(|&k| owner[k] == 1)
            .map(|k| key(&ghosts.pos[k]))
            .collect();
        let asymmetric = hull_nodes
            .iter()
            .filter(|k| !hull_nodes.contains(&[k[0], -1 - k[1], k[2]]))
            .count();
        assert_eq!(asymmetric, 0, "of {} hull ghosts", hull_nodes.len());
    }
}
