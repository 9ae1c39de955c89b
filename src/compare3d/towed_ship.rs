//! The ship in steady forward motion in 3D (issue #31): the hull of [`super::ship`] towed through the tank at
//! U = Fr √(gL), from rest with a smooth ramp ([`RigidMotion::Ramp`]), until the bow region is steady; its wave
//! pattern η(x, y) in the ship's frame, beside the 2D+t solution of the same hull at the same spacing.
//!
//! Why towed, not fixed in a current: a towed hull needs a longer tank (the distance it travels) but no open
//! boundary, where a fixed hull needs an inflow and an outflow through the free surface, which 3D SPH codes keep
//! stable only with damping zones that reflect waves back. The tank's faces are images of the fluid
//! ([`GhostKind::Images`]): they follow the moving keel on the centre plane without a per-stage test of which
//! symmetry-plane ghost lies inside the hull, and they held the hull at rest better than fixed tank ghosts
//! (`validate hull-at-rest`). The tank is the 2D+t scene's (half width 4 B, depth 2 D): not open water, a channel
//! whose depth Froude number U/√(g 2D) may exceed 1 (then no transverse waves), the same for both models.
//!
//! Frames: x from the stem, positive aft, in L (2D+t's x = U t + x0); y from the centre plane; η/D.

use super::ship::{ShipScene, ShipTank};
use super::towed_checkpoint;
use crate::analysis::wave_pattern::{along_x, eta_field_3d, sample, tenth_contours, Bins};
use crate::driver::progress::{Progress, Status};
use crate::driver::{drive, Ended, Flow, Outcome, Watch};
use crate::geometry::hydrostatics::section_hydro;
use crate::geometry::surface::HullSurface;
use crate::io::csv_table::Table;
use crate::io::plot::{self, Field};
use crate::sph::boundary::RigidMotion;
use crate::sph::polyline_wall::GhostKind;
use crate::sph::solver::BlowUp;
use crate::twodt::scene::expected_max_speed;
use nalgebra::Vector3;
use std::path::{Path, PathBuf};
use std::time::Instant;

const G: f64 = 9.81;

/// A towed-ship run, in units of the hull's L, D and of U.
#[derive(Clone, Debug)]
pub struct TowedShip {
    pub hull: HullSurface,
    pub fr: f64,
    /// Particles over the draft, D/dx.
    pub d_over_dx: f64,
    /// Ramp from rest to U over this distance (L): the smooth start of r(τ) = τ²(3 − 2τ).
    pub ramp_over_l: f64,
    /// The shortest distance travelled (L): the whole hull's pattern, not only the bow's, must have left the start
    /// behind before the map is compared (the stern passes the stem's starting point after 1 L).
    pub min_travel_over_l: f64,
    /// The longest distance travelled (L); the run stops earlier once the bow is steady past the shortest.
    pub max_travel_over_l: f64,
    /// The bow is steady when its crest height changed by less than this (in D) over the last
    /// [`TowedShip::steady_over_l`] travelled.
    pub steady_tolerance_over_d: f64,
    pub steady_over_l: f64,
    /// Interval between two bow samples (L travelled).
    pub sample_over_l: f64,
    /// Water behind the stern at the start (L); ahead of the stem the tank holds the longest travel plus 0.5 L.
    pub behind_over_l: f64,
    /// The tank's half width from the centre plane, in B: 4, the 2D+t scene's ([`ShipTank`]).
    pub half_width_over_b: f64,
    /// The water's depth, in D: 2, the 2D+t scene's.
    pub depth_over_d: f64,
    /// ParaView frames of the particles and the hull during the run (None: none).
    pub frames: Option<Frames>,
    /// Where and how often to save the run's state, and when to stop with it saved (None: never).
    pub checkpoint: Option<CheckpointPolicy>,
    /// Particle shifting after each step (default the near-wall band; a study's 3D side takes its 2D+t
    /// configuration's).
    pub shifting: crate::sph::particle_shifting::ParticleShifting,
}

/// ParaView frames of a towed run, in the Earth frame (the hull moves along −x through the tank):
/// `fluid_NNNN.vtp` (velocity, pressure, density), `hull_NNNN.vtp` (the hull's starboard surface at the same
/// time) and their indexes `fluid.pvd` and `hull.pvd`, every `every_over_l` L travelled from the start.
#[derive(Clone, Debug)]
pub struct Frames {
    pub dir: PathBuf,
    pub every_over_l: f64,
}

pub use super::towed_checkpoint::CheckpointPolicy;

/// The towed run's options as a user sets them: the same struct is `bowwave ship`'s flattened options (each doc
/// comment its `--help`) and a study's `[ship3d]` table (the same key names, `_` for `-`), so that the two cannot
/// drift apart. Defaults in [`TowOptions::default`] only.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize, clap::Args)]
#[serde(default, deny_unknown_fields)]
pub struct TowOptions {
    /// Particles over the draft, D/dx (D/dx 5 on the Wigley hull: 89 436 particles, some 15–20 min on 2 idle cores).
    #[arg(long, default_value_t = t().res)]
    pub res: f64,
    /// The hull accelerates from rest to U over this distance, in L (a smooth ramp, zero acceleration at both ends).
    #[arg(long, default_value_t = t().ramp)]
    pub ramp: f64,
    /// The longest distance travelled, in L; the run stops earlier once the bow crest is steady.
    #[arg(long, default_value_t = t().travel)]
    pub travel: f64,
    /// The shortest distance travelled, in L, before the run may stop: the pattern along the whole hull must
    /// have left the start behind (the stern passes the stem's starting point after 1 L).
    #[arg(long, default_value_t = t().min_travel)]
    pub min_travel: f64,
    /// The bow is steady when its crest height moved by less than this, in D, over the last `--steady-over` L.
    #[arg(long, default_value_t = t().steady_tol)]
    pub steady_tol: f64,
    /// The stretch of travel (L) over which the bow crest must stay within `--steady-tol`.
    #[arg(long, default_value_t = t().steady_over)]
    pub steady_over: f64,
    /// The tank's half width from the centre plane, in B (the 2D+t scene's 4 B). The tank is a channel, not open
    /// water: a wider one lets the divergent waves leave the hull before they reflect from its side (thesis
    /// appendix D); it must leave at least one row of particles beside the hull.
    #[arg(long, default_value_t = t().half_width)]
    pub half_width: f64,
    /// The water's depth, in D (the 2D+t scene's 2 D); at least one row of particles under the keel.
    #[arg(long, default_value_t = t().depth)]
    pub depth: f64,
}

/// The defaults, for clap's `default_value_t`.
fn t() -> TowOptions {
    TowOptions::default()
}

impl Default for TowOptions {
    /// D/dx 5; ramp over 0.25 L; at least 1.5 L and at most 2.5 L travelled; steady within 0.02 D over the last
    /// 0.25 L; the 2D+t scene's tank, half width 4 B and depth 2 D (thesis §10.1.2).
    fn default() -> Self {
        TowOptions {
            res: 5.0,
            ramp: 0.25,
            travel: 2.5,
            min_travel: 1.5,
            steady_tol: 0.02,
            steady_over: 0.25,
            half_width: 4.0,
            depth: 2.0,
        }
    }
}

impl TowOptions {
    /// The first option out of range, as (key, expected); the tank's fit around the hull and the memory are
    /// checked when the scene is planned.
    pub fn check(&self) -> Option<(&'static str, &'static str)> {
        let positive = |x: f64| x.is_finite() && x > 0.0;
        if !positive(self.res) {
            return Some(("res", "particles over the draft D/dx > 0"));
        }
        if !positive(self.ramp) {
            return Some(("ramp", "a distance in L > 0"));
        }
        if !(positive(self.min_travel) && self.min_travel > self.ramp) {
            return Some(("min_travel", "a distance in L beyond the ramp"));
        }
        if !(self.travel.is_finite() && self.travel >= self.min_travel) {
            return Some(("travel", "a distance in L ≥ min_travel"));
        }
        if !positive(self.steady_tol) {
            return Some(("steady_tol", "a height in D > 0"));
        }
        if !positive(self.steady_over) {
            return Some(("steady_over", "a distance in L > 0"));
        }
        if !(self.half_width.is_finite() && self.half_width > 0.5) {
            return Some(("half_width", "a half width in B > 0.5 (beyond the hull)"));
        }
        if !(self.depth.is_finite() && self.depth > 1.0) {
            return Some(("depth", "a depth in D > 1 (below the keel)"));
        }
        None
    }
}

impl TowedShip {
    /// The defaults ([`TowOptions::default`]) at D/dx `d_over_dx`; samples every 0.05 L, 0.5 L of water behind
    /// the stern.
    pub fn new(hull: HullSurface, fr: f64, d_over_dx: f64) -> Self {
        Self::with_options(
            hull,
            fr,
            &TowOptions {
                res: d_over_dx,
                ..TowOptions::default()
            },
        )
    }

    /// A run of `hull` at `fr` with the user's options.
    pub fn with_options(hull: HullSurface, fr: f64, o: &TowOptions) -> Self {
        TowedShip {
            hull,
            fr,
            d_over_dx: o.res,
            ramp_over_l: o.ramp,
            min_travel_over_l: o.min_travel,
            max_travel_over_l: o.travel,
            steady_tolerance_over_d: o.steady_tol,
            steady_over_l: o.steady_over,
            sample_over_l: 0.05,
            behind_over_l: 0.5,
            half_width_over_b: o.half_width,
            depth_over_d: o.depth,
            frames: None,
            checkpoint: None,
            shifting: Default::default(),
        }
    }
}

/// What the towed run leaves: the wave pattern at the end and the bow's history.
pub struct TowedResult {
    pub fr: f64,
    pub dx_over_l: f64,
    pub c0_over_sqrt_gl: f64,
    pub particles: usize,
    pub hull_ghosts: usize,
    pub steps: u64,
    pub wall_seconds: f64,
    /// Distance travelled at the end (L).
    pub travel_over_l: f64,
    /// (travel / L, bow crest η/D, its x/L from the stem) at every sample.
    pub bow: Vec<(f64, f64, f64)>,
    /// Whether the bow met the steadiness tolerance before the longest travel.
    pub steady: bool,
    /// η/D in the ship's frame at the end: x/L from the stem, y/L from the centre plane.
    pub eta: Field,
    /// The diagnosis, if the run blew up (the result then holds what it had).
    pub blow_up: Option<BlowUp>,
}

/// The bow region where the crest is watched (x/L from the stem).
pub const BOW_REGION: (f64, f64) = (-0.05, 0.5);

/// The highest η/D of a map over [`BOW_REGION`], and its x/L (the first column holding it); `None` if the region
/// holds no value. The bow crest of both models.
pub fn highest_in_bow_region(f: &Field) -> Option<(f64, f64)> {
    let mut best: Option<(f64, f64)> = None;
    for (i, col) in f.values.iter().enumerate() {
        let x = f.x0 + i as f64 * f.dx;
        if x < BOW_REGION.0 || x > BOW_REGION.1 {
            continue;
        }
        for v in col.iter().filter(|v| v.is_finite()) {
            if best.is_none_or(|b| *v > b.0) {
                best = Some((*v, x));
            }
        }
    }
    best
}

impl TowedShip {
    /// What identifies the configuration (a checkpoint of another one is not resumed).
    pub fn fingerprint(&self) -> String {
        format!(
            "{} fr {} D/dx {} ramp {} travel {}–{} steady {} over {} sample {} behind {} tank {} B {} D shifting {}",
            self.hull.meta.name,
            self.fr,
            self.d_over_dx,
            self.ramp_over_l,
            self.min_travel_over_l,
            self.max_travel_over_l,
            self.steady_tolerance_over_d,
            self.steady_over_l,
            self.sample_over_l,
            self.behind_over_l,
            self.half_width_over_b,
            self.depth_over_d,
            self.shifting
        )
    }
}

/// The ramp's duration (s): after it the travel of r(τ) = τ²(3 − 2τ) is U (t − T/2), so T = 2 × its length / U.
fn ramp_time(opts: &TowedShip, l: f64) -> f64 {
    2.0 * opts.ramp_over_l * l / (opts.fr * (G * l).sqrt())
}

/// The hull's motion: from rest to U along −x over the ramp.
fn tank_motion(opts: &TowedShip, l: f64) -> RigidMotion<3> {
    RigidMotion::Ramp {
        velocity: Vector3::new(-opts.fr * (G * l).sqrt(), 0.0, 0.0),
        time: ramp_time(opts, l),
    }
}

/// Throughput of the towed Wigley on this project's 2-core machine, particle-steps per second on 2 threads with
/// the cores to itself (`bowwave bench --ship --res 5,6.5`: 5.82e4 at 89 436 particles, 5.83e4 at 196 856;
/// session 37, BENCHMARKS.md), for [`plan`]'s estimate. Shared cores give less.
pub const MEASURED_THROUGHPUT: f64 = 5.8e4;

/// What a towed run will cost, before it runs: particles, hull ghosts, c0 and the steps to the shortest and the
/// longest travel (the time step as the sound speed sets it, Δt = CFL h / c0).
#[derive(Clone, Debug)]
pub struct Plan {
    pub particles: usize,
    pub hull_ghosts: usize,
    pub c0_over_sqrt_gl: f64,
    pub steps_min: f64,
    pub steps_max: f64,
}

/// Builds the scene and estimates the run (`bowwave ship --dry-run`).
pub fn plan(opts: &TowedShip) -> anyhow::Result<Plan> {
    let (scene, c0_over_sqrt_gl) = scene(opts)?;
    let (l, u) = (scene.length, opts.fr * (G * scene.length).sqrt());
    let ramp_time = ramp_time(opts, l);
    let cfg = &scene.sim.cfg;
    // The step the sound speed alone sets, shortened by what the flow adds to the signal speed: the first run
    // (Wigley, Fr 0.5, D/dx 5) took 455 steps where CFL h / c0 gives 394.
    let dt = cfg.cfl * cfg.h / cfg.eos.c0 / 1.15;
    // After the ramp the travel is U (t − T/2).
    let steps = |travel: f64| (travel * l / u + 0.5 * ramp_time) / dt;
    Ok(Plan {
        particles: scene.sim.n_fluid(),
        hull_ghosts: scene.hull_ghosts,
        c0_over_sqrt_gl,
        steps_min: steps(opts.min_travel_over_l),
        steps_max: steps(opts.max_travel_over_l),
    })
}

/// The towed scene of `opts` and its c0/√(gL).
fn scene(opts: &TowedShip) -> anyhow::Result<(ShipScene, f64)> {
    anyhow::ensure!(
        opts.fr.is_finite() && opts.fr > 0.0,
        "ship: Froude number must be positive, got {}",
        opts.fr
    );
    anyhow::ensure!(
        opts.d_over_dx.is_finite() && opts.d_over_dx >= 2.0,
        "ship: resolution D/dx must be a number ≥ 2, got {}",
        opts.d_over_dx
    );
    anyhow::ensure!(
        opts.ramp_over_l > 0.0
            && opts.min_travel_over_l >= opts.ramp_over_l
            && opts.max_travel_over_l >= opts.min_travel_over_l,
        "ship: expected 0 < ramp ({} L) ≤ shortest travel ({} L) ≤ longest travel ({} L)",
        opts.ramp_over_l,
        opts.min_travel_over_l,
        opts.max_travel_over_l
    );
    let hull = &opts.hull;
    let (l, d) = (hull.meta.length_m, hull.meta.draft_m);
    let d_over_l = d / l;
    let c0_over_sqrt_gl = sound_speed(opts);
    let mut tank = ShipTank::new(
        hull.clone(),
        d_over_l / opts.d_over_dx,
        opts.max_travel_over_l + 0.5,
        opts.behind_over_l,
    );
    tank.tank_ghosts = GhostKind::Images;
    tank.half_width_over_b = opts.half_width_over_b;
    tank.depth_over_d = opts.depth_over_d;
    tank.c0_over_sqrt_gd = c0_over_sqrt_gl / d_over_l.sqrt();
    tank.motion = tank_motion(opts, l);
    tank.shifting = opts.shifting;
    Ok((tank.build()?, c0_over_sqrt_gl))
}

/// The towed scene's simulation at rest, before its first step (`bowwave bench --ship` times its steps).
pub fn simulation(opts: &TowedShip) -> anyhow::Result<crate::sph::solver::Simulation<3>> {
    Ok(scene(opts)?.0.sim)
}

/// c0/√(gL): the 2D+t rule (`docs/decisions/twodt-sound-speed.md`), 10 × the expected largest speed.
fn sound_speed(opts: &TowedShip) -> f64 {
    let hull = &opts.hull;
    let d_over_l = hull.meta.draft_m / hull.meta.length_m;
    10.0 * expected_max_speed(hull, opts.fr, hull.x_range.0, hull.x_range.1, d_over_l)
}

/// The run's resolved configuration as JSON (`manifest.json` of `bowwave ship`): the build, the hull file, every
/// option with its value, and what follows from them (spacing, U, c0, the tank), written before the run starts.
pub fn manifest(
    opts: &TowedShip,
    hull_file: &Path,
    offsets: &crate::geometry::hull_file::HullOffsets,
) -> anyhow::Result<String> {
    let m = &offsets.meta;
    let l = m.length_m;
    let d_over_l = m.draft_m / l;
    let value = serde_json::json!({
        "bowwave_version": env!("CARGO_PKG_VERSION"),
        "git_commit": env!("BOWWAVE_GIT_COMMIT"),
        "command": "ship",
        "threads": rayon::current_num_threads(),
        "hull": {
            "file": hull_file.display().to_string(),
            "name": m.name,
            "status": format!("{:?}", m.status).to_lowercase(),
            "length_m": l,
            "beam_m": m.beam_m,
            "draft_m": m.draft_m,
        },
        "fr": opts.fr,
        "u_m_per_s": opts.fr * (G * l).sqrt(),
        "d_over_dx": opts.d_over_dx,
        "dx_over_l": d_over_l / opts.d_over_dx,
        "c0_over_sqrt_gl": sound_speed(opts),
        "ramp_over_l": opts.ramp_over_l,
        "min_travel_over_l": opts.min_travel_over_l,
        "max_travel_over_l": opts.max_travel_over_l,
        "steady_tolerance_over_d": opts.steady_tolerance_over_d,
        "steady_over_l": opts.steady_over_l,
        "sample_over_l": opts.sample_over_l,
        "tank": {
            "half_width_over_b": opts.half_width_over_b,
            "depth_over_d": opts.depth_over_d,
            "ahead_of_stem_over_l": opts.max_travel_over_l + 0.5,
            "behind_stern_over_l": opts.behind_over_l,
            "faces": "images of the fluid",
            "hull_wall": "fixed ghosts, MLS at mirror points (thesis §7.1.1)",
        },
        "vtk_every_over_l": opts.frames.as_ref().map(|f| f.every_over_l),
    });
    Ok(serde_json::to_string_pretty(&value)?)
}

/// Runs the towed ship (or goes on from its checkpoint), until its bow is steady past the shortest travel or it
/// reaches the longest; `Halted` when the checkpoint policy's wall-time limit stopped it with its state saved.
pub fn run(opts: &TowedShip, progress: bool) -> anyhow::Result<Ended<TowedResult>> {
    let (scene, c0_over_sqrt_gl) = scene(opts)?;
    let hull = &opts.hull;
    let (l, d) = (hull.meta.length_m, hull.meta.draft_m);
    let dx_over_l = d / l / opts.d_over_dx;
    let motion = tank_motion(opts, l);
    let ShipScene {
        mut sim,
        hull_ghosts,
        lo,
        hi,
        ..
    } = scene;
    let dx = sim.cfg.dx;
    let stem = hull.x_range.0;
    // The map: bins of 2 dx from 0.3 L ahead of the stem to the stern, across the tank.
    let bin = 2.0 * dx_over_l;
    let bins = Bins {
        x0: -0.3,
        y0: 0.5 * bin,
        bin,
        nx: ((hull.x_range.1 - stem + 0.3) / bin).ceil() as usize + 1,
        ny: (((hi.y - lo.y) / l) / bin).floor() as usize,
    };
    // The hull's waterplane, as the 2D+t η(y) leaves out the bins inside the section's waterline.
    let half_breadth = |x: f64| {
        if x <= 0.0 || x >= hull.x_range.1 - stem {
            0.0
        } else {
            section_hydro(hull, x + stem, 200).half_breadth_wl
        }
    };
    let waterline: Vec<f64> = (0..bins.nx).map(|i| half_breadth(bins.x0 + i as f64 * bin)).collect();
    let map = |sim: &crate::sph::solver::Simulation<3>| {
        let shift = motion.displacement(sim.time).x;
        eta_field_3d(
            sim.fluid.pos.iter().map(|p| ((p.x - shift) / l - stem, p.y / l, p.z)),
            bins,
            dx,
            d,
            |x, y| {
                let i = ((x - bins.x0) / bin).round() as usize;
                y < waterline[i.min(bins.nx - 1)]
            },
        )
    };
    let travel = |t: f64| -motion.displacement(t).x / l;
    let fingerprint = opts.fingerprint();
    let mut state = towed_checkpoint::Progress {
        next_sample: opts.ramp_over_l,
        ..Default::default()
    };
    if let Some(c) = &opts.checkpoint {
        let path = c.dir.join(towed_checkpoint::FILE);
        if path.exists() {
            if let Some(p) = towed_checkpoint::restore(&path, &fingerprint, &mut sim)? {
                log::info!("{}: going on from {:.3} L travelled", path.display(), travel(sim.time));
                state = p;
            }
        }
    }
    let wall_before = state.wall_before;
    let state = std::cell::RefCell::new(state);
    let mut steady = false;
    let (tol, window, every, min_travel, max_travel) = (
        opts.steady_tolerance_over_d,
        opts.steady_over_l,
        opts.sample_over_l,
        opts.min_travel_over_l,
        opts.max_travel_over_l,
    );
    let mut watch = Watch(|sim: &mut crate::sph::solver::Simulation<3>| {
        let s = travel(sim.time);
        let mut st = state.borrow_mut();
        if s >= st.next_sample {
            st.next_sample += every;
            let crest = highest_in_bow_region(&map(sim)).unwrap_or((f64::NEG_INFINITY, f64::NAN));
            st.bow.push((s, crest.0, crest.1));
            // Steady: the crest within `tol` of its value `window` L of travel ago, after the ramp.
            let back = st.bow.iter().rev().find(|b| b.0 <= s - window + 1e-9);
            if let Some(b) = back {
                if b.0 >= opts.ramp_over_l - 1e-9 && s >= min_travel && (crest.0 - b.1).abs() < tol {
                    steady = true;
                    return Ok(Flow::Stop);
                }
            }
        }
        Ok(if s >= max_travel { Flow::Stop } else { Flow::Step })
    });
    // The hull's starboard surface at rest (m), drawn beside the particles at each frame's displacement.
    let mesh = opts.frames.as_ref().map(|_| hull_mesh(hull, 120, 24));
    let mut framer = Watch(|sim: &mut crate::sph::solver::Simulation<3>| {
        let (Some(fr), Some((points, polys))) = (&opts.frames, &mesh) else {
            return Ok(Flow::Step);
        };
        let s = travel(sim.time);
        let mut st = state.borrow_mut();
        if s + 1e-12 >= st.next_frame {
            st.next_frame += fr.every_over_l;
            let k = st.frames.len();
            write_frame(sim, &fr.dir, k, motion.displacement(sim.time).x, points, polys)?;
            st.frames.push((sim.time, format!("{k:04}")));
            write_indexes(&fr.dir, &st.frames)?;
        }
        Ok(Flow::Step)
    });
    let mut bar = Progress::new("ship ", progress, None, |sim: &crate::sph::solver::Simulation<3>| {
        Status {
            fraction: travel(sim.time) / max_travel,
            text: format!("{:.3} L travelled", travel(sim.time)),
            steps: sim.steps,
        }
    });
    let clock = Instant::now();
    let at = |t: f64| format!("{:.3} L travelled", travel(t));
    let mut saver = towed_checkpoint::Saver::new(opts.checkpoint.as_ref(), &fingerprint, &state, wall_before, &at);
    let outcome = drive(&mut sim, &mut [&mut framer, &mut watch, &mut bar, &mut saver])?;
    let blow_up = match outcome {
        Outcome::BlewUp(b) => Some(b),
        Outcome::Halted(h) => return Ok(Ended::Halted(h)),
        Outcome::Finished => None,
    };
    if let Some(c) = &opts.checkpoint {
        // Finished: the checkpoint has served its purpose (results are kept, checkpoints are not).
        let _ = std::fs::remove_file(c.dir.join(towed_checkpoint::FILE));
    }
    let bow = state.into_inner().bow;
    Ok(Ended::Ran(TowedResult {
        fr: opts.fr,
        dx_over_l,
        c0_over_sqrt_gl,
        particles: sim.n_fluid(),
        hull_ghosts,
        steps: sim.steps,
        wall_seconds: wall_before + clock.elapsed().as_secs_f64(),
        travel_over_l: travel(sim.time),
        bow,
        steady,
        eta: map(&sim),
        blow_up,
    }))
}

/// The hull's starboard surface (m) as `nx` × `nxi` quadrilaterals: stations uniform in x from stem to stern,
/// girth uniform from the keel to the deck.
fn hull_mesh(hull: &HullSurface, nx: usize, nxi: usize) -> (Vec<[f64; 3]>, Vec<Vec<usize>>) {
    let l = hull.meta.length_m;
    let (x0, x1) = hull.x_range;
    let mut points = vec![];
    let mut rows = vec![];
    for i in 0..=nx {
        let x = x0 + (x1 - x0) * i as f64 / nx as f64;
        // A station where the surface has no section (a pointed end) is left out.
        let Some(c) = hull.curve(x) else { continue };
        rows.push(points.len());
        for k in 0..=nxi {
            let p = c.point(k as f64 / nxi as f64);
            points.push([x * l, p.y.max(0.0) * l, p.z * l]);
        }
    }
    let polys = rows
        .windows(2)
        .flat_map(|w| (0..nxi).map(move |k| vec![w[0] + k, w[1] + k, w[1] + k + 1, w[0] + k + 1]))
        .collect();
    (points, polys)
}

/// Writes frame `k`: the particles and the hull's surface shifted by `shift` (m) along x.
fn write_frame(
    sim: &crate::sph::solver::Simulation<3>,
    dir: &Path,
    k: usize,
    shift: f64,
    hull: &[[f64; 3]],
    polys: &[Vec<usize>],
) -> anyhow::Result<()> {
    use crate::io::vtk::{write_mesh_vtp, write_vtp, PointData};
    let f = &sim.fluid;
    let pts: Vec<[f64; 3]> = f.pos.iter().map(|p| [p.x, p.y, p.z]).collect();
    let path = dir.join(format!("fluid_{k:04}.vtp"));
    write_vtp(
        &path,
        &pts,
        &[
            PointData::Vector("velocity", f.vel.iter().map(|v| [v.x, v.y, v.z]).collect()),
            PointData::Scalar("pressure", sim.state_pressures()),
            PointData::Scalar("density", f.rho.clone()),
        ],
    )
    .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
    let moved: Vec<[f64; 3]> = hull.iter().map(|p| [p[0] + shift, p[1], p[2]]).collect();
    let path = dir.join(format!("hull_{k:04}.vtp"));
    write_mesh_vtp(&path, &moved, polys).map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))
}

/// Writes `fluid.pvd` and `hull.pvd`, the indexes of the frames so far ((time in s, frame number) pairs).
fn write_indexes(dir: &Path, frames: &[(f64, String)]) -> anyhow::Result<()> {
    for kind in ["fluid", "hull"] {
        let entries: Vec<(f64, String)> = frames.iter().map(|(t, k)| (*t, format!("{kind}_{k}.vtp"))).collect();
        let path = dir.join(format!("{kind}.pvd"));
        crate::io::vtk::write_pvd(&path, &entries)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
    }
    Ok(())
}

/// The 2D+t wave pattern of a `bowwave twodt` output folder (its `eta.csv`), for [`compare`]; the error names the
/// file and what was expected.
pub fn read_twodt_eta(dir: &Path) -> anyhow::Result<Field> {
    let path = dir.join("eta.csv");
    let t = Table::read(&path)?;
    let col = |c: &str| {
        t.column(c)
            .ok_or_else(|| anyhow::anyhow!("{}: no column '{c}', expected a twodt eta.csv", path.display()))
    };
    let (x, y, e) = (col("x_over_l")?, col("y_over_l")?, col("eta_over_d")?);
    crate::analysis::wave_pattern::eta_field(&x, &y, &e).ok_or_else(|| {
        anyhow::anyhow!(
            "{}: fewer than two x/L or y/L values, expected a wave pattern",
            path.display()
        )
    })
}

/// The 3D and 2D+t wave patterns compared column by column of the 3D map.
pub struct Comparison {
    /// η_3D − η_2D+t over D, on the 3D map's grid (NaN where either is missing).
    pub difference: Field,
    /// (x/L, largest |Δη|/D over the column, Fr_x = Fr/√(x/L)) for each column with both.
    pub columns: Vec<(f64, f64, f64)>,
    /// The stretches (first and last x/L) of consecutive columns that agree within [`AGREEMENT_OVER_D`]; the
    /// 2D+t approximation is expected to hold near the bow, where Fr_x is large.
    pub bands: Vec<(f64, f64)>,
}

/// The agreement the issue asks for: η within 10 % of D.
pub const AGREEMENT_OVER_D: f64 = 0.1;

/// Compares the 3D map with the 2D+t one (`eta.csv`'s field, x/L from the stem), from x/L 0 to the stern `x_end`.
pub fn compare(three: &Field, twodt: &Field, fr: f64, x_end: f64) -> Comparison {
    let mut values = three.values.clone();
    let mut columns = vec![];
    for (i, col) in values.iter_mut().enumerate() {
        let x = three.x0 + i as f64 * three.dx;
        let mut worst = f64::NAN;
        for (j, v) in col.iter_mut().enumerate() {
            let y = three.y0 + j as f64 * three.dy;
            let other = sample(twodt, x, y);
            *v = if v.is_finite() && other.is_finite() && x > 0.0 {
                *v - other
            } else {
                f64::NAN
            };
            if v.is_finite() {
                worst = if worst.is_nan() { v.abs() } else { worst.max(v.abs()) };
            }
        }
        if worst.is_finite() && x <= x_end + 1e-9 {
            columns.push((x, worst, fr / x.sqrt()));
        }
    }
    let mut bands: Vec<(f64, f64)> = vec![];
    let mut open = false;
    for c in &columns {
        match (c.1 < AGREEMENT_OVER_D, open) {
            (true, true) => bands.last_mut().expect("an open band").1 = c.0,
            (true, false) => bands.push((c.0, c.0)),
            _ => {}
        }
        open = c.1 < AGREEMENT_OVER_D;
    }
    Comparison {
        difference: Field {
            x0: three.x0,
            dx: three.dx,
            y0: three.y0,
            dy: three.dy,
            values,
        },
        columns,
        bands,
    }
}

/// The result's tables: `ship3d_eta.csv` (x_over_l, y_over_l, eta_over_d of the final map), `bow.csv` (the
/// crest's history), `profile.csv` (per column of the map: the wave profile on the hull, the crest and its y, and
/// with a 2D+t map the same read from it at the nearest x) and, with a 2D+t map, `agreement.csv` (per column: x/L,
/// largest |Δη|/D, Fr_x).
pub fn tables(r: &TowedResult, twodt: Option<(&Field, &Comparison)>) -> Vec<(&'static str, Table)> {
    let cols = |names: &[&str]| names.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let mut eta = Table::new(cols(&["x_over_l", "y_over_l", "eta_over_d"]));
    for (i, col) in r.eta.values.iter().enumerate() {
        for (j, v) in col.iter().enumerate() {
            if v.is_finite() {
                eta.push(vec![r.eta.x0 + i as f64 * r.eta.dx, r.eta.y0 + j as f64 * r.eta.dy, *v]);
            }
        }
    }
    let mut bow = Table::new(cols(&["travel_over_l", "crest_over_d", "crest_x_over_l"]));
    for b in &r.bow {
        bow.push(vec![b.0, b.1, b.2]);
    }
    let mut names = vec!["x_over_l", "hull_eta_over_d", "crest_over_d", "crest_y_over_l"];
    if twodt.is_some() {
        names.extend(["twodt_hull_eta_over_d", "twodt_crest_over_d", "twodt_crest_y_over_l"]);
    }
    let mut profile = Table::new(cols(&names));
    let two = twodt.map(|(f, _)| (along_x(f), f.x0, f.dx));
    for row in along_x(&r.eta) {
        let mut v = row.to_vec();
        if let Some((t, x0, dx)) = &two {
            let i = ((row[0] - x0) / dx).round();
            match (i >= 0.0).then(|| t.get(i as usize)).flatten() {
                Some(c) => v.extend_from_slice(&c[1..]),
                None => v.extend([f64::NAN; 3]),
            }
        }
        profile.push(v);
    }
    let mut out = vec![("ship3d_eta.csv", eta), ("bow.csv", bow), ("profile.csv", profile)];
    if let Some((_, c)) = twodt {
        let mut t = Table::new(cols(&["x_over_l", "max_abs_diff_over_d", "fr_x"]));
        for col in &c.columns {
            t.push(vec![col.0, col.1, col.2]);
        }
        out.push(("agreement.csv", t));
    }
    out
}

/// The maps as PNG: the 3D pattern, and with a 2D+t map that one and the difference, each with contours every
/// 0.1 D and Fr_x along the top.
pub fn plots(r: &TowedResult, twodt: Option<(&Field, &Comparison)>, out: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let fr = r.fr;
    let ticks: Vec<(f64, String)> = [3.0, 2.0, 1.5, 1.2, 1.0, 0.8, 0.7, 0.6]
        .iter()
        .map(|&fx: &f64| ((fr / fx).powi(2), format!("Fr_x {fx}")))
        .collect();
    let draw = |name: &str, title: String, f: &Field, range: (f64, f64)| -> anyhow::Result<PathBuf> {
        let segs = tenth_contours(f, -10, 15);
        let path = out.join(name);
        plot::field_map(
            &path,
            &title,
            ("x / L from the stem", "y / L from the centre plane"),
            f,
            range,
            &segs,
            &ticks,
            (1400, 700),
        )?;
        Ok(path)
    };
    let mut files = vec![draw(
        "wave_pattern_3d.png",
        format!(
            "3D towed ship, Fr = {fr}, dx/L = {:.2e}: η/D (contours every 0.1 D)",
            r.dx_over_l
        ),
        &r.eta,
        (-0.3, 1.0),
    )?];
    if let Some((two, c)) = twodt {
        files.push(draw(
            "wave_pattern_2dt.png",
            format!("2D+t, Fr = {fr}: η/D (contours every 0.1 D)"),
            two,
            (-0.3, 1.0),
        )?);
        files.push(draw(
            "wave_pattern_difference.png",
            format!("3D − 2D+t, Fr = {fr}: Δη/D (contours every 0.1 D)"),
            &c.difference,
            (-0.5, 0.5),
        )?);
    }
    Ok(files)
}

/// The local Froude number Fr_x = Fr/√(x/L) at `x` (L from the stem) for a table: "∞" at the stem, where a
/// column's x is the stem's up to round-off.
pub fn fr_x_text(fr: f64, x: f64) -> String {
    if x > 1e-6 {
        format!("{:.2}", fr / x.sqrt())
    } else {
        "∞".to_string()
    }
}

/// A short report of the run and, with a 2D+t map, the verdict.
pub fn summary(r: &TowedResult, c: Option<&Comparison>) -> String {
    let mut s = format!(
        "3D towed ship, Fr {}: dx/L {:.3e}, {} particles, {} hull ghosts, c0 {:.2} √(gL), {} steps, {:.0} s; \
         {:.2} L travelled\n",
        r.fr, r.dx_over_l, r.particles, r.hull_ghosts, r.c0_over_sqrt_gl, r.steps, r.wall_seconds, r.travel_over_l
    );
    match r.bow.last() {
        Some(b) => {
            s += &format!(
                "bow crest {:.3} D at x/L {:.3}; {}\n",
                b.1,
                b.2,
                if r.steady {
                    "steady: it changed by less than the tolerance over the last stretch".to_string()
                } else {
                    "NOT steady by the end of the travel".to_string()
                }
            )
        }
        None => s += "no bow sample (the ramp did not end)\n",
    }
    if let Some(b) = &r.blow_up {
        s += &format!("blew up: {b}\n");
    }
    if let Some(c) = c {
        let fr_x = |x: f64| fr_x_text(r.fr, x);
        s += &if c.bands.is_empty() {
            format!("3D and 2D+t agree within {AGREEMENT_OVER_D} D in η nowhere along the hull\n")
        } else {
            let bands: Vec<String> = c
                .bands
                .iter()
                .map(|b| format!("x/L {:.3}–{:.3} (Fr_x {}–{})", b.0, b.1, fr_x(b.0), fr_x(b.1)))
                .collect();
            format!(
                "3D and 2D+t agree within {AGREEMENT_OVER_D} D in η (every column across the tank) over {}\n",
                bands.join(", ")
            )
        };
        s += "x/L     max|Δη|/D   Fr_x\n";
        for col in &c.columns {
            s += &format!("{:6.3}  {:9.3}  {:>6}\n", col.0, col.1, fr_x_text(r.fr, col.0));
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn field(f: impl Fn(f64, f64) -> f64, x0: f64, dx: f64, nx: usize, ny: usize) -> Field {
        Field {
            x0,
            dx,
            y0: 0.5 * dx,
            dy: dx,
            values: (0..nx)
                .map(|i| (0..ny).map(|j| f(x0 + i as f64 * dx, (j as f64 + 0.5) * dx)).collect())
                .collect(),
        }
    }

    /// Two maps that differ by 0.3 D ahead of x/L 0.42 and by 0.05 D after it agree from the first column past
    /// it (0.45) to the stern, one band, and the difference map carries the difference.
    #[test]
    fn agreement_starts_after_the_last_column_off_by_more_than_a_tenth_of_d() {
        let a = field(|x, y| (x * 3.0).sin() * y, -0.2, 0.05, 25, 10);
        let b = field(
            |x, y| (x * 3.0).sin() * y + if x < 0.42 { 0.3 } else { 0.05 },
            -0.2,
            0.01,
            121,
            50,
        );
        let c = compare(&a, &b, 0.5, 1.0);
        assert_eq!(c.bands.len(), 1, "{:?}", c.bands);
        let (from, to) = c.bands[0];
        assert!(
            (from - 0.45).abs() < 1e-9 && (to - 1.0).abs() < 1e-9,
            "agrees over {from}–{to}"
        );
        for (x, worst, fr_x) in &c.columns {
            assert!(*x > 0.0);
            assert!((fr_x - 0.5 / x.sqrt()).abs() < 1e-12);
            let want = if *x < 0.42 { 0.3 } else { 0.05 };
            assert!((worst - want).abs() < 0.02, "x {x}: {worst}");
        }
        // Nothing agrees: no band.
        let far = field(|_, _| 1.0, -0.2, 0.01, 121, 50);
        assert!(compare(&a, &far, 0.5, 1.0).bands.is_empty());
    }

    /// The crest is looked for over the bow region only: a higher value aft of it is not the bow's.
    #[test]
    fn the_twodt_crest_is_the_highest_value_in_the_bow_region_only() {
        let f = Field {
            x0: -0.05,
            dx: 0.1,
            y0: 0.0,
            dy: 0.1,
            values: (0..10)
                .map(|i| {
                    let x = -0.05 + i as f64 * 0.1;
                    vec![f64::NAN, if x > 0.5 { 2.0 } else { x }]
                })
                .collect(),
        };
        let (h, x) = highest_in_bow_region(&f).unwrap();
        assert!((h - 0.45).abs() < 1e-12 && (x - 0.45).abs() < 1e-12, "{h} at {x}");
    }
}
