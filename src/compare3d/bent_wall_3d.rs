//! The bent-wall channel of thesis §10.2.1 in 3D: the ruled surface of eq. (10.8)
//! ([`crate::geometry::bent_wall`]) towed at U through still water of depth H, beside its 2D+t analogue
//! ([`super::bent_wall`]) at the same spacing and sound speed (issue #31).
//!
//! The thesis runs a stream past a fixed wall; here, as for the ship ([`super::towed_ship`], which says why), the
//! wall moves along −x through a still channel: from rest to U over a smooth ramp ([`RigidMotion::Ramp`]), then
//! steadily, until every cut of the bent part has been passed by water that met it after the ramp. In the
//! wall's frame, ξ = 5 H at the start of the bent part (eq. 10.8), an Earth point at x sits at
//! ξ = x − x_r + 5 + d(t), d the distance travelled and x_r where the bent part started; the cut at ξ is the
//! plate of [`BentWall::plate`] at s = (ξ − 5)/L. Ahead of the bent part the wall is the channel's straight
//! side (y = 0), behind it the last cut carried on (the 45° wall, ours as in 2D+t); both move along themselves,
//! which a free-slip wall does not feel.
//!
//! The wall is one [`SurfaceWall`] (fixed ghosts, MLS at mirror points, thesis §7.1.1) sampled from the point
//! cloud of [`BentWall::oriented_points`]; the floor, the far side (y = W) and the channel's ends are the
//! images of the fluid ([`GhostKind::Images`]), as the towed ship's tank. Non-dimensional with H, g and ρ0
//! (time in √(H/g), Fr_H = U/√(gH)), as the 2D+t analogue.
//!
//! What is compared: along the bent part, the crest away from the wall (the highest water farther than 3h from
//! it, in the slab of 2 dx around each cut) and the run-up on it (the highest water within 1.5 dx of it), against
//! the 2D+t history at the same s; and the steadiness of the 3D crest over the last stretch of travel.

use super::bent_wall::{self as twodt, BentWallOptions};
use super::towed_checkpoint;
pub use super::towed_checkpoint::CheckpointPolicy;
use crate::analysis::wave_pattern::{eta_field_3d, Bins};
use crate::driver::progress::{Progress, Status};
use crate::driver::{drive, Ended, Flow, Outcome, Watch};
use crate::geometry::bent_wall::{BentWall, X_START};
use crate::io::atomic::write_atomic;
use crate::io::csv_table::Table;
use crate::io::plot::{self, Field, Series, Style};
use crate::sph::body_force::BodyForce;
use crate::sph::boundary::{Boundary, RigidMotion};
use crate::sph::box_wall::BoxWall;
use crate::sph::particles::Fluid;
use crate::sph::polyline_wall::GhostKind;
use crate::sph::solver::{Simulation, SolverConfig};
use crate::sph::surface_wall::SurfaceWall;
use nalgebra::{Vector2, Vector3};
use std::path::Path;
use std::time::Instant;

type V2 = Vector2<f64>;
type V3 = Vector3<f64>;

/// The 3D run's options beyond the channel's ([`BentWallOptions`]: Fr_H, L, W, H/dx, c0), lengths in H.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Tow3dOptions {
    /// The wall accelerates from rest to U over this distance (H): 2, a smooth ramp ending with zero acceleration.
    pub ramp: f64,
    /// Distance travelled beyond L + ramp before the run stops (H): 1. At L + ramp the water that met the bent
    /// part's start as the ramp ended reaches its end, so from there on every cut has seen only the steady wall.
    pub settle: f64,
    /// Water ahead of the bent part's start at the end of the run (H): 2, so that the straight side ahead of it
    /// is wetted at every cut the comparison reads.
    pub ahead: f64,
    /// Water behind the bent part's end at the start (H): 2.
    pub behind: f64,
    /// Height of the sampled wall above the floor (H): 3, above any run-up the 2D+t analogue shows at Fr_H 2
    /// (1.5 H); water that would climb higher passes over the wall's top edge.
    pub top: f64,
    /// Distance travelled between two samples of the crest's history (H): 0.5.
    pub sample: f64,
}

impl Default for Tow3dOptions {
    fn default() -> Self {
        Tow3dOptions {
            ramp: 2.0,
            settle: 1.0,
            ahead: 2.0,
            behind: 2.0,
            top: 3.0,
            sample: 0.5,
        }
    }
}

impl Tow3dOptions {
    /// The first option out of range, named as on the command line.
    pub fn check(&self) -> anyhow::Result<()> {
        let bad =
            |name: &str, want: &str, got: f64| anyhow::anyhow!("bent wall 3D: --{name}: expected {want}, got {got}");
        let positive = |x: f64| x.is_finite() && x > 0.0;
        for (name, v) in [("ramp", self.ramp), ("sample", self.sample)] {
            if !positive(v) {
                return Err(bad(name, "a positive distance in H", v));
            }
        }
        for (name, v) in [("settle", self.settle), ("ahead", self.ahead), ("behind", self.behind)] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(bad(name, "a distance in H ≥ 0", v));
            }
        }
        if !(self.top.is_finite() && self.top > 1.5) {
            return Err(bad(
                "top",
                "a height in H above 1.5 (the calm water and its run-up)",
                self.top,
            ));
        }
        Ok(())
    }
}

/// The scene, built, with what its measures need.
pub struct Scene3d {
    pub sim: Simulation<3>,
    pub wall: BentWall,
    /// U/√(gH), c0/√(gH), the channel's width W/H (whole spacings), the spacing dx/H.
    pub u: f64,
    pub c0: f64,
    pub width: f64,
    pub dx: f64,
    /// Earth x of the bent part's start at t = 0, and the distance the run travels (H).
    pub x_r: f64,
    pub travel: f64,
    pub motion: RigidMotion<3>,
    /// The tank's corners: x along the channel, y across it from the straight side, z up from the floor.
    pub lo: V3,
    pub hi: V3,
    pub wall_ghosts: usize,
}

impl Scene3d {
    /// ξ/H in the wall's frame (eq. 10.8's x) of Earth x at time t.
    pub fn xi(&self, x: f64, t: f64) -> f64 {
        x - self.x_r + X_START - self.motion.displacement(t).x
    }

    /// Distance travelled at time t (H).
    pub fn travelled(&self, t: f64) -> f64 {
        -self.motion.displacement(t).x
    }
}

/// Whether (y, z) lies behind the cut of the wall at ξ (on its solid side): the plate's line extended, which is
/// the ruled surface's cut exactly (a straight line at every ξ).
fn behind_cut(wall: &BentWall, xi: f64, y: f64, z: f64) -> bool {
    let p = wall.plate((xi - X_START) / wall.length, 0.0);
    (V2::new(y, z) - p.foot).dot(&p.normal()) < 0.0
}

/// The lattice nodes under the floor in the wedge beside the wall's foot that neither the wall nor the floor
/// fills: the wall's ghosts lie behind its plane extended below the floor (y < foot − |z| tan θ in the cut), the
/// floor's images mirror the water (y > foot + |z| tan θ), and the 2θ between them would leave the water at the
/// foot a kernel short on that side. Each is valued as a floor ghost, from its mirror point through the floor
/// (x, y, −z). Earth coordinates at t = 0 over Earth x in `x_range`, on the lattice of origin `lo` and spacing
/// `dx`; `xi_of` maps Earth x to ξ at t = 0; `ghosted` says which nodes the wall ghosts itself.
fn floor_corner_ghosts(
    wall: &BentWall,
    (lo, dx, support): (V3, f64, f64),
    xi_of: &dyn Fn(f64) -> f64,
    ghosted: &dyn Fn(&V3) -> bool,
    x_range: (f64, f64),
) -> Vec<(V3, V3)> {
    let mut out = vec![];
    let layers = (support / dx).ceil() as i64;
    let i0 = ((x_range.0 - lo.x) / dx).floor() as i64;
    let i1 = ((x_range.1 - lo.x) / dx).ceil() as i64;
    for i in i0..=i1 {
        let x = lo.x + (i as f64 + 0.5) * dx;
        let p = wall.plate((xi_of(x) - X_START) / wall.length, 0.0);
        let tan = p.theta.tan();
        if tan <= 0.0 {
            continue;
        }
        for k in 1..=layers {
            let depth = (k as f64 - 0.5) * dx;
            // y between foot − depth tan θ and foot + depth tan θ, on the lattice.
            let (y0, y1) = (p.foot.x - depth * tan, p.foot.x + depth * tan);
            let j0 = ((y0 - lo.y) / dx - 0.5).ceil() as i64;
            let j1 = ((y1 - lo.y) / dx - 0.5).floor() as i64;
            for j in j0..=j1 {
                let y = lo.y + (j as f64 + 0.5) * dx;
                // The wall's own ghosts (behind its plane extended) or a mirror of the water (the images): not here.
                let r = V3::new(x, y, -depth);
                if y >= y1 || ghosted(&r) {
                    continue;
                }
                out.push((r, V3::new(x, y, depth)));
            }
        }
    }
    out
}

/// Builds the 3D channel: the towed wall, the tank's images, the water at rest and hydrostatic.
pub fn build(ch: &BentWallOptions, o: &Tow3dOptions) -> anyhow::Result<Scene3d> {
    ch.check()?;
    o.check()?;
    let wall = BentWall { length: ch.length };
    let dx = 1.0 / ch.res;
    let c0 = ch
        .c0
        .unwrap_or_else(|| 10.0 * twodt::expected_max_speed(&wall, ch.fr_h));
    let mut cfg = SolverConfig::new(dx, 1.0, c0, BodyForce::Uniform(V3::new(0.0, 0.0, -1.0)));
    let support = cfg.kernel.support_over_h() * cfg.h;
    let whole = |x: f64| (x / dx).round().max(1.0) * dx;
    let travel = ch.length + o.ramp + o.settle;
    let x_r = whole(travel + o.ahead);
    let width = whole(ch.width);
    // The tank's side behind the straight wall is beyond the kernel's reach of any fluid: its images stay empty.
    let back = whole(2.0 * support);
    let lo = V3::new(0.0, -back, 0.0);
    let hi = V3::new(whole(x_r + ch.length + o.behind), width, whole(o.top));
    let u = ch.fr_h;
    let motion = RigidMotion::Ramp {
        velocity: V3::new(-u, 0.0, 0.0),
        time: 2.0 * o.ramp / u,
    };
    cfg.domain = Some((lo - (hi - lo), hi + (hi - lo)));
    let nodes = (hi.x - lo.x) * width * 1.0 / dx.powi(3);
    let need = nodes * super::ship::BYTES_PER_PARTICLE;
    if let Some(free) = crate::process_usage::available_memory_bytes() {
        anyhow::ensure!(
            need <= free as f64,
            "bent wall 3D: H/dx {} asks for about {nodes:.3e} particles, about {:.1} GiB, more than the {:.1} GiB \
             available; expected a coarser spacing",
            ch.res,
            need / 1024f64.powi(3),
            free as f64 / 1024f64.powi(3)
        );
    }
    // The Earth-frame x the wall passes over during the run (the tank within the kernel's reach, the wall's
    // whole travel): its samples, a quarter spacing apart, and its floor-corner ghosts cover it.
    let xi0 = |x: f64| x - x_r + X_START;
    let x_seen = (lo.x - support, hi.x + support + travel + o.ramp);
    let cloud = wall.oriented_points(0.25 * dx, xi0(x_seen.0), xi0(x_seen.1), o.top);
    let top = hi.z;
    let surface = SurfaceWall::new(
        "bent wall",
        cloud
            .iter()
            .map(|p| V3::new(p.pos[0] + x_r - X_START, p.pos[1], p.pos[2]))
            .collect(),
        cloud.iter().map(|p| V3::from(p.normal)).collect(),
        lo,
        dx,
        support,
        |r| r.z > -support && r.z < top && r.y < hi.y,
    )
    .map_err(anyhow::Error::msg)?;
    // The wall's own rule decides which nodes it ghosts (its nearest sample's side), as its constructor did.
    let ghosted = |r: &V3| surface.ghost_side(r).is_some();
    let corner = floor_corner_ghosts(&wall, (lo, dx, support), &|x| xi0(x), &ghosted, x_seen);
    let surface = surface.with_extra_ghosts(&corner).with_motion(motion);
    let solid = |r: &V3| match surface.signed_distance(r) {
        Some((d, _)) => d < 0.0,
        None => behind_cut(&wall, xi0(r.x), r.y, r.z),
    };
    // The tank's edge ghosts behind the wall (at its ends, where the side does not change during the run) would
    // double the wall's.
    let tank = BoxWall::new("tank", lo, hi, dx, support)
        .map_err(anyhow::Error::msg)?
        .with_ghosts(GhostKind::Images)
        .retain_ghosts(|pos, _| !behind_cut(&wall, xi0(pos.x), pos.y, pos.z));
    let eos = cfg.eos;
    let mut fluid = Fluid::default();
    let n = [0, 1].map(|a| ((hi[a] - lo[a]) / dx).round() as usize);
    let nz = ch.res.round() as usize;
    for i in 0..n[0] {
        let x = lo.x + (i as f64 + 0.5) * dx;
        for k in 0..nz {
            let z = (k as f64 + 0.5) * dx;
            let rho = eos.density(1.0 - z);
            for j in 0..n[1] {
                let r = V3::new(x, lo.y + (j as f64 + 0.5) * dx, z);
                if !solid(&r) {
                    fluid.push(r, V3::zeros(), rho, rho * dx.powi(3), 1.0 - z);
                }
            }
        }
    }
    let wall_ghosts = surface.base_ghosts().len();
    let boundaries: Vec<Box<dyn Boundary<3>>> = vec![Box::new(tank), Box::new(surface)];
    Ok(Scene3d {
        sim: Simulation::new(cfg, fluid, boundaries),
        wall,
        u,
        c0,
        width,
        dx,
        x_r,
        travel,
        motion,
        lo,
        hi,
        wall_ghosts,
    })
}

/// How much shorter the 3D channel's time step is than CFL h / c0 (dimensionless): the signal speed of eq. (4.22)
/// carries the flow's speed and the artificial viscosity's h max|π_ij| besides c0. Measured at the defaults:
/// 309 steps where CFL h / c0 gives 251 (H/dx 4), 643 where it gives 377 (H/dx 6).
pub const STEP_SHORTENING: f64 = 1.7;

/// What a run will cost, before it runs (`--dry-run`): particles, wall ghosts and the steps to the end of the
/// travel (the time step CFL h / c0 / [`STEP_SHORTENING`]).
pub fn plan(ch: &BentWallOptions, o: &Tow3dOptions) -> anyhow::Result<(usize, usize, f64)> {
    let s = build(ch, o)?;
    let cfg = &s.sim.cfg;
    let dt = cfg.cfl * cfg.h / cfg.eos.c0 / STEP_SHORTENING;
    // After the ramp the travel is U (t − T/2), T = 2 ramp / U.
    let t_end = (s.travel + o.ramp) / s.u;
    Ok((s.sim.n_fluid(), s.wall_ghosts, t_end / dt))
}

/// One cut of the final state: the crest away from the wall and the run-up on it, in 3D and in 2D+t at the same s.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct Cut {
    /// Fraction of the wall passed and ξ/H.
    pub s: f64,
    pub xi: f64,
    /// 3D: crest above the calm level /H and its y/H; run-up on the wall /H (NaN where the slab holds no water
    /// there).
    pub crest: f64,
    pub crest_y: f64,
    pub run_up: f64,
    /// 2D+t at the same s (its samples interpolated linearly).
    pub crest_2dt: f64,
    pub crest_y_2dt: f64,
    pub run_up_2dt: f64,
}

/// The crest (farther than `far` from the wall) and the run-up (within 1.5 dx of it, above its foot) of the
/// particles (ξ, y, z) in slabs of `bin` in ξ centred on `centres`: (crest, its y, run-up) above the calm level.
pub fn cut_heights(
    wall: &BentWall,
    points: impl Iterator<Item = (f64, f64, f64)>,
    centres: &[f64],
    bin: f64,
    dx: f64,
    far: f64,
) -> Vec<(f64, f64, f64)> {
    let (Some(&first), true) = (centres.first(), bin > 0.0) else {
        return vec![];
    };
    let mut out = vec![(f64::NEG_INFINITY, f64::NAN, f64::NEG_INFINITY); centres.len()];
    let plates: Vec<_> = centres
        .iter()
        .map(|xi| wall.plate((xi - X_START) / wall.length, 0.0))
        .collect();
    for (xi, y, z) in points {
        let k = ((xi - first) / bin + 0.5).floor();
        if k < 0.0 || k as usize >= centres.len() {
            continue;
        }
        let k = k as usize;
        let p = &plates[k];
        let r = V2::new(y, z) - p.foot;
        let d = r.dot(&p.normal());
        let o = &mut out[k];
        if d < 1.5 * dx && r.dot(&p.up()) > 0.0 {
            o.2 = o.2.max(z);
        } else if d > far && z > o.0 {
            o.0 = z;
            o.1 = y;
        }
    }
    let level = |z: f64| if z.is_finite() { z + 0.5 * dx - 1.0 } else { f64::NAN };
    out.into_iter().map(|(c, y, r)| (level(c), y, level(r))).collect()
}

/// What a 3D run measured, with its 2D+t analogue.
#[derive(serde::Serialize)]
pub struct BentWall3dResult {
    pub channel: BentWallOptions,
    pub tow: Tow3dOptions,
    pub width: f64,
    pub c0: f64,
    pub particles: usize,
    pub wall_ghosts: usize,
    pub steps: u64,
    pub wall_seconds: f64,
    /// Distance travelled at the end (H).
    pub travelled: f64,
    /// (travel /H, highest crest over the bent part /H, its ξ/H) at every sample.
    pub history: Vec<(f64, f64, f64)>,
    /// The change of the highest crest over the last L/4 of travel (H): how steady the end state is.
    pub crest_drift: f64,
    pub cuts: Vec<Cut>,
    /// The largest |crest_3D − crest_2D+t| over the cuts past s = 0.1 (H), and the fraction of those cuts within
    /// 0.1 H; the same for the run-up.
    pub crest_max_diff: f64,
    pub crest_within: f64,
    pub run_up_max_diff: f64,
    pub run_up_within: f64,
    /// The 2D+t run at the same spacing and c0 (its plunge, if any, is its own).
    pub twodt_particles: usize,
    pub twodt_plunge_s: Option<f64>,
    /// Why the 3D run stopped early (a blow-up's diagnosis); what it had is kept.
    pub stopped: Option<String>,
    pub commit: String,
    #[serde(skip)]
    pub eta: Option<Field>,
}

/// The agreement the comparison counts: within a tenth of the depth H.
pub const AGREEMENT_OVER_H: f64 = 0.1;

fn fingerprint(ch: &BentWallOptions, o: &Tow3dOptions) -> String {
    format!(
        "bent wall 3D Fr_H {} L {} W {} res {} c0 {:?} ramp {} settle {} ahead {} behind {} top {} sample {} \
         shifting {}",
        ch.fr_h,
        ch.length,
        ch.width,
        ch.res,
        ch.c0,
        o.ramp,
        o.settle,
        o.ahead,
        o.behind,
        o.top,
        o.sample,
        crate::sph::particle_shifting::ParticleShifting::default()
    )
}

/// Runs the 3D channel (or goes on from its checkpoint), then its 2D+t analogue; `Halted` when the checkpoint
/// policy stopped it with its state saved.
pub fn run(
    ch: &BentWallOptions,
    o: &Tow3dOptions,
    checkpoint: Option<&CheckpointPolicy>,
    progress: bool,
) -> anyhow::Result<Ended<BentWall3dResult>> {
    let Scene3d {
        mut sim,
        wall,
        travel,
        wall_ghosts,
        x_r,
        motion,
        c0,
        width,
        dx,
        ..
    } = build(ch, o)?;
    let travelled = |t: f64| -motion.displacement(t).x;
    let xi = |x: f64, t: f64| x - x_r + X_START - motion.displacement(t).x;
    let far = 3.0 * sim.cfg.h;
    let bin = 2.0 * dx;
    let nbin = (ch.length / bin).floor() as usize;
    let centres: Vec<f64> = (0..nbin).map(|k| X_START + (k as f64 + 0.5) * bin).collect();
    let heights = |sim: &Simulation<3>| {
        let t = sim.time;
        cut_heights(
            &wall,
            sim.fluid.pos.iter().map(|p| (xi(p.x, t), p.y, p.z)),
            &centres,
            bin,
            dx,
            far,
        )
    };
    let fp = fingerprint(ch, o);
    let mut state = towed_checkpoint::Progress::default();
    if let Some(c) = checkpoint {
        let path = c.dir.join(towed_checkpoint::FILE);
        if path.exists() {
            if let Some(p) = towed_checkpoint::restore(&path, &fp, &mut sim)? {
                log::info!(
                    "{}: going on from {:.2} H travelled",
                    path.display(),
                    travelled(sim.time)
                );
                state = p;
            }
        }
    }
    let wall_before = state.wall_before;
    let state = std::cell::RefCell::new(state);
    let mut watch = Watch(|sim: &mut Simulation<3>| {
        let d = travelled(sim.time);
        let mut st = state.borrow_mut();
        if d >= st.next_sample {
            st.next_sample += o.sample;
            let best = heights(sim).iter().zip(&centres).filter(|(h, _)| h.0.is_finite()).fold(
                (f64::NEG_INFINITY, f64::NAN),
                |b, (h, xi)| if h.0 > b.0 { (h.0, *xi) } else { b },
            );
            st.bow.push((d, best.0, best.1));
        }
        Ok(if d >= travel { Flow::Stop } else { Flow::Step })
    });
    let mut bar = Progress::new("bent wall 3D ", progress, None, |sim: &Simulation<3>| Status {
        fraction: travelled(sim.time) / travel,
        text: format!("{:.2} H travelled", travelled(sim.time)),
        steps: sim.steps,
    });
    let clock = Instant::now();
    let at = |t: f64| format!("{:.2} H travelled", travelled(t));
    let mut saver = towed_checkpoint::Saver::new(checkpoint, &fp, &state, wall_before, &at);
    let outcome = drive(&mut sim, &mut [&mut watch, &mut bar, &mut saver])?;
    let stopped = match outcome {
        Outcome::BlewUp(b) => Some(format!("blew up at {:.2} H travelled: {b}", travelled(sim.time))),
        Outcome::Halted(h) => return Ok(Ended::Halted(h)),
        Outcome::Finished => None,
    };
    if let Some(c) = checkpoint {
        let _ = std::fs::remove_file(c.dir.join(towed_checkpoint::FILE));
    }
    let wall_seconds = wall_before + clock.elapsed().as_secs_f64();
    let history = state.into_inner().bow;
    let end = sim.time;
    let final_heights = heights(&sim);

    // The 2D+t analogue at the same spacing and sound speed, over the whole wall.
    let analogue = BentWallOptions {
        c0: Some(c0),
        s_end: 1.0,
        stop_at_plunge: false,
        frames: 0,
        ..ch.clone()
    };
    let r2 = twodt::run(&analogue, None, false)?;
    let at = |s: f64, f: fn(&twodt::Sample) -> f64| interpolate(&r2.samples, s, f);
    let cuts: Vec<Cut> = centres
        .iter()
        .zip(&final_heights)
        .map(|(&xi, h)| {
            let s = (xi - X_START) / ch.length;
            Cut {
                s,
                xi,
                crest: h.0,
                crest_y: h.1,
                run_up: h.2,
                crest_2dt: at(s, |r| r.crest),
                crest_y_2dt: at(s, |r| r.crest_y),
                run_up_2dt: at(s, |r| r.run_up),
            }
        })
        .collect();
    let compare = |f: fn(&Cut) -> (f64, f64)| {
        let diffs: Vec<f64> = cuts
            .iter()
            .filter(|c| c.s > 0.1)
            .map(|c| {
                let (a, b) = f(c);
                (a - b).abs()
            })
            .filter(|d| d.is_finite())
            .collect();
        let max = diffs.iter().copied().fold(f64::NAN, f64::max);
        let within = diffs.iter().filter(|d| **d <= AGREEMENT_OVER_H).count() as f64 / diffs.len().max(1) as f64;
        (max, within)
    };
    let (crest_max_diff, crest_within) = compare(|c| (c.crest, c.crest_2dt));
    let (run_up_max_diff, run_up_within) = compare(|c| (c.run_up, c.run_up_2dt));
    let last = history.last().copied();
    let crest_drift = match last {
        Some((d, c, _)) => history
            .iter()
            .filter(|h| h.0 >= d - ch.length / 4.0 - 1e-9)
            .map(|h| (h.1 - c).abs())
            .fold(0.0, f64::max),
        None => f64::NAN,
    };
    // The η map in the wall's frame over the bent part and 2 H either side, masked behind the wall's foot.
    let (x0, x1) = (X_START - 2.0, X_START + ch.length + 2.0);
    let bins = Bins {
        x0,
        y0: 0.5 * bin,
        bin,
        nx: ((x1 - x0) / bin).ceil() as usize + 1,
        ny: (width / bin).floor() as usize,
    };
    let eta = eta_field_3d(
        sim.fluid.pos.iter().map(|p| (xi(p.x, end), p.y, p.z - 1.0)),
        bins,
        dx,
        1.0,
        |xi, y| behind_cut(&wall, xi, y, 0.0),
    );
    Ok(Ended::Ran(BentWall3dResult {
        channel: ch.clone(),
        tow: o.clone(),
        width,
        c0,
        particles: sim.n_fluid(),
        wall_ghosts,
        steps: sim.steps,
        wall_seconds,
        travelled: travelled(end),
        history,
        crest_drift,
        cuts,
        crest_max_diff,
        crest_within,
        run_up_max_diff,
        run_up_within,
        twodt_particles: r2.particles,
        twodt_plunge_s: r2.plunge.as_ref().map(|p| p.s),
        stopped,
        commit: option_env!("BOWWAVE_GIT_COMMIT").unwrap_or("unknown").to_string(),
        eta: Some(eta),
    }))
}

/// `f` of the 2D+t samples at s, linear between the two around it (NaN outside them).
fn interpolate(samples: &[twodt::Sample], s: f64, f: fn(&twodt::Sample) -> f64) -> f64 {
    let k = samples.partition_point(|r| r.s < s);
    if k == 0 || k >= samples.len() {
        return f64::NAN;
    }
    let (a, b) = (&samples[k - 1], &samples[k]);
    let w = if b.s > a.s { (s - a.s) / (b.s - a.s) } else { 0.0 };
    f(a) + (f(b) - f(a)) * w
}

/// Writes bent_wall_3d.csv (the cuts), bent_wall_3d_history.csv, bent_wall_3d_eta.csv (the η map in the
/// wall's frame), bent_wall_3d.json, bent_wall_3d_heights.png and bent_wall_3d_eta.png into `out`.
pub fn write_outputs(r: &BentWall3dResult, out: &Path) -> anyhow::Result<()> {
    let named = |cols: &[&str]| Table::new(cols.iter().map(|c| c.to_string()).collect());
    let mut t = named(&[
        "s",
        "xi_over_h",
        "crest_3d",
        "crest_y_3d",
        "run_up_3d",
        "crest_2dt",
        "crest_y_2dt",
        "run_up_2dt",
    ]);
    for c in &r.cuts {
        t.push(vec![
            c.s,
            c.xi,
            c.crest,
            c.crest_y,
            c.run_up,
            c.crest_2dt,
            c.crest_y_2dt,
            c.run_up_2dt,
        ]);
    }
    let write = |t: &Table, name: &str| {
        let p = out.join(name);
        t.write(&p)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", p.display()))
    };
    write(&t, "bent_wall_3d.csv")?;
    let mut h = named(&["travel_over_h", "crest_max_over_h", "crest_xi_over_h"]);
    for s in &r.history {
        h.push(vec![s.0, s.1, s.2]);
    }
    write(&h, "bent_wall_3d_history.csv")?;
    if let Some(eta) = &r.eta {
        let mut e = named(&["xi_over_h", "y_over_h", "eta_over_h"]);
        for (i, col) in eta.values.iter().enumerate() {
            for (j, v) in col.iter().enumerate().filter(|(_, v)| v.is_finite()) {
                e.push(vec![eta.x0 + i as f64 * eta.dx, eta.y0 + j as f64 * eta.dy, *v]);
            }
        }
        write(&e, "bent_wall_3d_eta.csv")?;
    }
    let json = out.join("bent_wall_3d.json");
    write_atomic(&json, serde_json::to_string_pretty(r)?.as_bytes())
        .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", json.display()))?;
    let series = |name: &str, f: fn(&Cut) -> f64, style: Style| Series {
        name: name.to_string(),
        points: r.cuts.iter().map(|c| (c.s, f(c))).filter(|p| p.1.is_finite()).collect(),
        style,
    };
    let ch = &r.channel;
    plot::line_plot(
        &out.join("bent_wall_3d_heights.png"),
        &format!(
            "Bent wall, 3D (towed) and 2D+t, Fr_H {}, L/H {}, W/H {}, H/dx {}",
            ch.fr_h, ch.length, r.width, ch.res
        ),
        "s = (x - 5 H)/L, fraction of the wall passed",
        "elevation above the calm level / H",
        &[
            series("crest, 3D", |c| c.crest, Style::Markers),
            series("crest, 2D+t", |c| c.crest_2dt, Style::Line),
            series("run-up on the wall, 3D", |c| c.run_up, Style::Markers),
            series("run-up on the wall, 2D+t", |c| c.run_up_2dt, Style::Line),
        ],
    )?;
    if let Some(eta) = &r.eta {
        let ticks: Vec<(f64, String)> = [0.0, 0.25, 0.5, 0.75, 1.0]
            .iter()
            .map(|s| (X_START + s * ch.length, format!("s {s}")))
            .collect();
        plot::field_map(
            &out.join("bent_wall_3d_eta.png"),
            &format!(
                "Bent wall in 3D: eta / H in the wall's frame after {:.1} H travelled (Fr_H {}, H/dx {})",
                r.travelled, ch.fr_h, ch.res
            ),
            ("x / H (eq. 10.8)", "y / H"),
            eta,
            (-0.5, 1.0),
            &[],
            &ticks,
            (1400, 700),
        )?;
    }
    Ok(())
}

/// A short summary for the terminal.
pub fn summary(r: &BentWall3dResult) -> String {
    let ch = &r.channel;
    let mut s = format!(
        "bent wall 3D, Fr_H {}, L/H {}, W/H {}, H/dx {}: {} particles, {} wall ghosts, {} steps, {:.0} s, c0 {:.2} \
         sqrt(gH), {:.2} H travelled\n",
        ch.fr_h, ch.length, r.width, ch.res, r.particles, r.wall_ghosts, r.steps, r.wall_seconds, r.c0, r.travelled
    );
    s += &format!(
        "  highest crest over the bent part moved by {:.3} H over the last L/4 of travel\n",
        r.crest_drift
    );
    s += &format!(
        "  against 2D+t at the same spacing ({} particles): crest within {} H at {:.0} % of the cuts past s = 0.1 \
         (largest difference {:.3} H), run-up at {:.0} % ({:.3} H)\n",
        r.twodt_particles,
        AGREEMENT_OVER_H,
        100.0 * r.crest_within,
        r.crest_max_diff,
        100.0 * r.run_up_within,
        r.run_up_max_diff
    );
    if let Some(sp) = r.twodt_plunge_s {
        s += &format!("  the 2D+t analogue closed a cavity at s = {sp:.3}\n");
    }
    if let Some(b) = &r.stopped {
        s += &format!("  STOPPED EARLY: {b}\n");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn small() -> (BentWallOptions, Tow3dOptions) {
        let ch = BentWallOptions {
            length: 4.0,
            width: 3.0,
            res: 4.0,
            ..Default::default()
        };
        let o = Tow3dOptions {
            ramp: 1.0,
            settle: 0.0,
            ahead: 1.0,
            behind: 1.0,
            top: 2.0,
            sample: 0.5,
        };
        (ch, o)
    }

    /// At rest the water fills the channel up to the calm level on the open side of the wall and nowhere
    /// behind it: no particle behind any cut, every cut reads crest and run-up zero (the lattice's top row is
    /// dx/2 below the level), and the wall's ghosts all lie behind it.
    #[test]
    fn the_channel_at_rest_is_full_to_the_calm_level_and_empty_behind_the_wall() {
        let (ch, o) = small();
        let s = build(&ch, &o).unwrap();
        let pos = &s.sim.fluid.pos;
        assert!(!pos.is_empty());
        assert!(pos.iter().all(|p| !behind_cut(&s.wall, s.xi(p.x, 0.0), p.y, p.z)));
        // The fluid volume: the tank's water less what lies behind the wall, within a row of particles per face.
        let dx = s.dx;
        let expected: f64 = {
            let n = ((s.hi.x - s.lo.x) / dx).round() as usize;
            (0..n)
                .map(|i| {
                    let xi = s.xi(s.lo.x + (i as f64 + 0.5) * dx, 0.0);
                    let p = s.wall.plate((xi - X_START) / s.wall.length, 0.0);
                    // The wall's mean y over the depth: its foot plus tan θ / 2.
                    (s.width - p.foot.x - 0.5 * p.theta.tan()) * dx
                })
                .sum()
        };
        let volume = pos.len() as f64 * dx.powi(3);
        assert!(
            (volume - expected).abs() < 0.05 * expected,
            "volume {volume} against {expected}"
        );
        let centres: Vec<f64> = (0..8).map(|k| X_START + 0.25 + 0.5 * k as f64).collect();
        let h = cut_heights(
            &s.wall,
            pos.iter().map(|p| (s.xi(p.x, 0.0), p.y, p.z)),
            &centres,
            0.5,
            dx,
            0.5,
        );
        for (xi, (crest, _, run_up)) in centres.iter().zip(h) {
            assert!(
                crest.abs() < 1e-12 && run_up.abs() < 1e-12,
                "ξ {xi}: crest {crest}, run-up {run_up}"
            );
        }
        assert!(s.wall_ghosts > 0);
    }

    /// Under the floor beside the wall's foot every lattice node within the kernel's reach of the foot is
    /// filled once: by the wall's ghosts (behind its plane extended), by the corner's (the wedge between), or, in
    /// front of the wedge, by the floor's images of the water above it; none twice.
    #[test]
    fn the_floor_corner_under_the_wall_foot_is_filled_once() {
        let (ch, o) = small();
        let s = build(&ch, &o).unwrap();
        let gs = &s.sim.ghosts;
        let dx = s.dx;
        let support = s.sim.kernel.support;
        let key = |r: &V3| [r.x, r.y, r.z].map(|c| (c / dx - 0.5).round() as i64);
        let mut wall = std::collections::HashMap::new();
        for (g, r) in gs.geom.pos.iter().enumerate() {
            if gs.owner[g] == 1 {
                *wall.entry(key(r)).or_insert(0) += 1;
            }
        }
        assert!(wall.values().all(|&c| c == 1), "a node ghosted twice");
        let mut checked = 0;
        // The 45° wall behind the bent part, and a cut half way along it.
        for xi in [X_START + 0.5 * ch.length, X_START + ch.length + 0.5] {
            let x = ((xi - X_START + s.x_r) / dx).floor() * dx + 0.5 * dx;
            let p = s.wall.plate((s.xi(x, 0.0) - X_START) / s.wall.length, 0.0);
            for k in 1..=(support / dx).ceil() as i64 {
                let z = -(k as f64 - 0.5) * dx;
                for j in -40..40 {
                    let y = (p.foot.x / dx).floor() * dx + (j as f64 + 0.5) * dx;
                    // Within the kernel's reach of the foot, where the water's nearest particles are.
                    if (y - p.foot.x).hypot(z) > support {
                        continue;
                    }
                    let ghost = wall.contains_key(&key(&V3::new(x, y, z)));
                    // The water reaches the wall's plane itself (a particle on it is fluid), so does its image.
                    let image = y >= p.foot.x - z * p.theta.tan() - 1e-9;
                    assert!(
                        ghost != image,
                        "ξ {xi}, y {y}, z {z}: ghost {ghost}, image region {image}"
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 20);
    }

    /// A run stopped at a step and resumed from its checkpoint reaches the same bits as one run straight through.
    #[test]
    fn a_resumed_run_gives_the_bits_of_an_uninterrupted_one() {
        let (ch, o) = small();
        let dir = std::env::temp_dir().join(format!("bowwave-bent3d-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let policy = |n: u64| CheckpointPolicy {
            dir: dir.clone(),
            every: std::time::Duration::MAX,
            deadline: None,
            halt_at_step: Some(n),
        };
        let Ended::Halted(_) = run(&ch, &o, Some(&policy(2)), false).unwrap() else {
            panic!("expected a halt at step 2")
        };
        let Ended::Halted(_) = run(&ch, &o, Some(&policy(4)), false).unwrap() else {
            panic!("expected a halt at step 4")
        };
        let resumed = towed_checkpoint_positions(&dir);
        std::fs::remove_file(dir.join(towed_checkpoint::FILE)).unwrap();
        let Ended::Halted(_) = run(&ch, &o, Some(&policy(4)), false).unwrap() else {
            panic!("expected a halt at step 4")
        };
        let straight = towed_checkpoint_positions(&dir);
        let _ = std::fs::remove_dir_all(&dir);
        assert_eq!(resumed, straight);
    }

    fn towed_checkpoint_positions(dir: &Path) -> Vec<u64> {
        let c = crate::io::checkpoint::Checkpoint::read(&dir.join(towed_checkpoint::FILE)).unwrap();
        ["pos_x", "pos_y", "pos_z", "rho"]
            .iter()
            .flat_map(|k| c.arrays[*k].iter().map(|v| v.to_bits()).collect::<Vec<_>>())
            .collect()
    }
}
