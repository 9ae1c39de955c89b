//! Runs one 2D+t case: damped settling, the ship's passage, free-surface detection every few steps, plunge
//! detection and the jet metrics, outputs (metrics row as CSV and JSON, series, η(y, x) table, plunge
//! snapshots, VTK).

use super::checkpoint;
use super::scene::{build, Scene, TwoDtConfig, Until};
use crate::analysis::{cavity, jet, level_set, Snapshot};
use crate::geometry::surface::HullSurface;
use crate::io::{atomic::write_atomic, csv_table::Table, plot, vtk};
use crate::sph::polyline_wall::nearest_point;
use nalgebra::Vector2;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

type V2 = Vector2<f64>;

/// Output options.
#[derive(Clone, Debug)]
pub struct TwoDtOptions {
    pub out_dir: PathBuf,
    pub progress: bool,
    /// PNG plots at the plunge (the frames and VTK series are the configuration's `frames` and `vtk`).
    pub plots: bool,
    /// Where to attach the progress bar (a study's bars); `None`: a bar of its own.
    pub multi: Option<indicatif::MultiProgress>,
    /// Label in front of the progress bar.
    pub label: String,
    /// Checkpoints: when to save, whether to resume, when to stop.
    pub checkpoint: checkpoint::CheckpointPolicy,
}

impl TwoDtOptions {
    /// Results and tables only, into `out_dir`: no progress bar or plots (tests, charts).
    pub fn quiet(out_dir: PathBuf) -> Self {
        TwoDtOptions {
            out_dir,
            progress: false,
            plots: false,
            multi: None,
            label: String::new(),
            checkpoint: Default::default(),
        }
    }
}

/// Everything measured at the plunge (non-dimensional as named).
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct PlungeMetrics {
    pub x_plunge_over_l: f64,
    pub y_plunge_over_l: f64,
    /// Local Froude number U/√(g x_plunge), x from the stem.
    pub fr_x: f64,
    pub h_pj_over_d: f64,
    /// Crest height minus impact-point height, / D.
    pub fall_over_d: f64,
    pub gamma_over_ud: f64,
    pub cavity_area_over_d2: f64,
    pub l_jet_over_d: f64,
    pub s_jet_over_db: f64,
    pub i_og_over_s2: f64,
    pub y_g_over_d: f64,
    pub z_g_over_d: f64,
    pub v_g_over_u: f64,
    pub w_g_over_u: f64,
    pub alpha_g_deg: f64,
    pub alpha_vg_deg: f64,
    pub jet_particles: usize,
}

/// The result of a run.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct TwoDtResult {
    pub hull: String,
    pub fr: f64,
    pub dx_over_l: f64,
    pub dx_coarse_over_l: f64,
    pub c0_over_sqrt_gl: f64,
    pub particles: usize,
    pub steps: u64,
    pub wall_seconds: f64,
    pub cpu_seconds: f64,
    pub x_end_over_l: f64,
    /// Kinetic energy left by the settling, / (M g D).
    pub ke_after_settle: f64,
    /// Largest change of the mean free-surface level of the far field (y > 3W/4) up to the plunge (or the
    /// end), / D.
    pub far_field_eta_over_d: f64,
    /// Largest max|u|/c0 seen at the detection steps.
    pub max_mach: f64,
    /// (total mass at end − at start) / total mass.
    pub mass_change: f64,
    /// Pressure noise at the end: RMS of p minus its kernel-smoothed field, / (ρ g D).
    #[serde(default)]
    pub pressure_noise_over_rho_g_d: f64,
    /// Highest free-surface elevation outside the waterline at the last output, / D: the bow-wave crest
    /// height at the end of the run (the quantity of the 2D+t speed–accuracy chart).
    #[serde(default)]
    pub crest_at_end_over_d: f64,
    pub wall_corrections: u64,
    pub plunged: bool,
    pub plunge: Option<PlungeMetrics>,
    /// Why the run stopped early, if it did.
    pub blowup: Option<String>,
}

fn snapshot(scene: &mut Scene) -> Snapshot {
    Snapshot::from_simulation(&mut scene.sim, scene.geom.dx_f)
}

/// Looks for a closed air cavity at the bow wave; returns the metrics and the cavity if the wave has plunged.
fn plunge_check(
    scene: &Scene,
    s: &Snapshot,
    t: f64,
    (plunge_depth, plunge_circulation): (Option<f64>, Option<f64>),
    watch: &mut cavity::ClosureWatch,
    between_checks: bool,
) -> Option<(PlungeMetrics, cavity::Cavity)> {
    let g = &scene.geom;
    let h = s.h;
    let zmax = s.pos.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max);
    let lo = V2::new(0.0, -0.5 * g.draft);
    let hi = V2::new(g.width, zmax + 3.0 * h);
    let ls = level_set::level_set(s, lo, hi, g.dx_f);
    let walls = scene.profile.at(t).points;
    let margin = 3.0 * h;
    let keep = |nodes: &[V2]| {
        nodes.iter().all(|p| {
            (nearest_point(&walls, p) - p).norm() > margin && p.x < g.width - margin && p.y > -g.depth + margin
        })
    };
    let closed = if between_checks {
        watch.closed_since_previous(&ls, (2.0 * h).powi(2), keep)?
    } else {
        watch.newly_closed(&ls, (2.0 * h).powi(2), keep)?
    };
    // Crest: the highest free-surface particle over the cavity or up to one cavity width before it.
    let crest_of = |c: &cavity::Cavity| {
        let y_from = c.lo.x - (c.hi.x - c.lo.x);
        (0..s.len())
            .filter(|&k| s.on_surface[k] && s.pos[k].x >= y_from && s.pos[k].x <= c.hi.x)
            .map(|k| s.pos[k].y)
            .fold(f64::NEG_INFINITY, f64::max)
            + 0.5 * g.dx_f
    };
    let u = g.fr;
    // Criterion 3 (optional): a plunge closes the cavity against the free surface in front of the wave, so
    // the cavity reaches down into the lower part of the wave. Criterion 5: the jet closing it turns
    // clockwise around it; a sliver of air between particle rows of a sheet has no such circulation.
    let (c, crest, gamma) = closed.into_iter().find_map(|c| {
        let crest = crest_of(&c);
        if !plunge_depth.is_none_or(|f| c.lo.y < f * crest) {
            return None;
        }
        let gamma = cavity::circulation(s, &ls, &c);
        plunge_circulation
            .is_none_or(|min| gamma / (u * g.draft) >= min)
            .then_some((c, crest, gamma))
    })?;
    let idx = jet::jet_particles(s, &ls, &c);
    let m = jet::metrics(s, &ls, &idx)?;
    let x = scene.profile.x_at(t);
    let pm = PlungeMetrics {
        x_plunge_over_l: x,
        y_plunge_over_l: c.rightmost.x,
        fr_x: u / (x - scene.profile.hull.x_range.0).max(1e-12).sqrt(),
        h_pj_over_d: crest / g.draft,
        fall_over_d: (crest - c.rightmost.y) / g.draft,
        gamma_over_ud: gamma / (u * g.draft),
        cavity_area_over_d2: c.area / (g.draft * g.draft),
        l_jet_over_d: m.length / g.draft,
        s_jet_over_db: m.area / (g.draft * g.beam),
        i_og_over_s2: m.i_og / (m.area * m.area),
        y_g_over_d: m.y_g / g.draft,
        z_g_over_d: m.z_g / g.draft,
        v_g_over_u: m.v_g / u,
        w_g_over_u: m.w_g / u,
        alpha_g_deg: m.alpha_g_deg,
        alpha_vg_deg: m.alpha_vg_deg,
        jet_particles: m.particles,
    };
    Some((pm, c))
}

/// The state of a run at a plunge check (regular or at an output), kept until the next one: when that one
/// finds a plunge, the run goes back here and checks every step to the plunge, so that t_p is known to one
/// step without checking every step all along. Stepping is deterministic, so the steps run again are the
/// same bits.
struct Rewind {
    sim: crate::sph::solver::SimState<2>,
    passage: checkpoint::Passage,
}

impl Rewind {
    fn keep(scene: &Scene, p: &checkpoint::Passage) -> Self {
        Rewind {
            sim: scene.sim.state(),
            passage: p.clone(),
        }
    }

    fn restore(self, scene: &mut Scene, p: &mut checkpoint::Passage) {
        scene.sim.set_state(self.sim);
        *p = self.passage;
    }
}

/// The bins of η(y): their width (4 dx_f) and the first bin of the far field (y > 3W/4), where the calm level is
/// watched.
fn eta_bins(g: &super::scene::SceneGeometry) -> (f64, usize) {
    let bin = 4.0 * g.dx_f;
    (bin, (0.75 * g.width / bin) as usize)
}

/// Free-surface elevation η(y) as the top of the fluid in bins of `bin` across [0, width] (NaN where empty).
fn eta_profile(pos: &[V2], width: f64, bin: f64, dx: f64) -> Vec<f64> {
    let n = (width / bin).ceil() as usize;
    let mut top = vec![f64::NAN; n];
    for p in pos {
        let k = ((p.x / bin) as usize).min(n - 1);
        if top[k].is_nan() || p.y > top[k] {
            top[k] = p.y;
        }
    }
    top.iter().map(|z| z + 0.5 * dx).collect()
}

/// The half-breadth of a section polyline at the calm level z = 0: the largest y where it crosses z = 0
/// (0 if it does not reach the water).
fn waterline_half_breadth(points: &[V2]) -> f64 {
    points
        .windows(2)
        .filter(|w| (w[0].y <= 0.0) != (w[1].y <= 0.0))
        .map(|w| w[0].x + (w[1].x - w[0].x) * (0.0 - w[0].y) / (w[1].y - w[0].y))
        .fold(0.0, f64::max)
}

/// Mean of the finite values (bins of η with fluid in them); 0 if there are none.
fn mean_finite(v: &[f64]) -> f64 {
    let (sum, n) = v
        .iter()
        .filter(|z| z.is_finite())
        .fold((0.0, 0usize), |(s, n), z| (s + z, n + 1));
    sum / n.max(1) as f64
}

/// Runs a case and writes its outputs into `opts.out_dir`. With `opts.checkpoint.resume` and a checkpoint of
/// the same configuration in that folder, goes on from it (`twodt::checkpoint`); a run that ends removes its
/// checkpoint. A run stopped on purpose returns the error [`Halted`](super::checkpoint::Halted).
pub fn run(hull: Arc<HullSurface>, cfg: &TwoDtConfig, opts: &TwoDtOptions) -> anyhow::Result<TwoDtResult> {
    let clock = Instant::now();
    let cpu0 = crate::bench::cpu_seconds();
    std::fs::create_dir_all(&opts.out_dir)
        .map_err(|e| anyhow::anyhow!("cannot create output directory {}: {e}", opts.out_dir.display()))?;
    let ckpt_path = opts.out_dir.join(checkpoint::FILE);
    let (mut scene, mut p, fingerprint) = match resume(&hull, cfg, opts, &ckpt_path)? {
        Some(resumed) => resumed,
        None => start(&hull, cfg)?,
    };
    let g = scene.geom.clone();
    let n = scene.sim.n_fluid();
    let t_start = scene.profile.t_start;
    let ke = |sim: &crate::sph::solver::Simulation<2>| -> f64 {
        crate::sph::diagnostics::energies(&sim.fluid, &sim.cfg.eos, &sim.cfg.body_force).kinetic
    };

    // 2. The passage.
    let bar = opts.progress.then(|| {
        let b = indicatif::ProgressBar::new(1000);
        let b = match &opts.multi {
            Some(m) => m.add(b),
            None => b,
        };
        b.set_style(
            indicatif::ProgressStyle::with_template(&format!(
                "{}{{bar:40}} x/L = {{msg}} [{{elapsed_precise}} / eta {{eta_precise}}]",
                opts.label
            ))
            .expect("valid template"),
        );
        b
    });
    let (bin, far_from) = eta_bins(&g);
    let mut blowup = None;
    let mut last_save = Instant::now();
    let policy = &opts.checkpoint;
    // The state at the last check ([`Rewind`]), and, while a plunge found at a check is searched again step
    // by step from the check before, the step where it was found.
    let mut rewind: Option<Rewind> = None;
    let mut replay_until: Option<u64> = None;
    loop {
        let x = scene.profile.x_at(scene.sim.time);
        if let Some(m) = replay_until.filter(|&m| scene.sim.steps > m) {
            // Cannot happen while stepping is deterministic; should it, the run goes on with its regular
            // checks, which find the plunge again, to within `detect_every` steps, rather than stop.
            log::warn!("the plunge found at step {m} was not found again stepping from the check before it");
            replay_until = None;
        }
        let searching = replay_until.is_some();
        let regular = (scene.sim.steps - p.steps0) % cfg.detect_every.max(1) as u64 == 0;
        // Checkpoints are taken here, at the top of an iteration, where a resumed run re-enters the loop, and
        // only before a regular check: the resumed run then keeps its first point to come back to ([`Rewind`],
        // not in the checkpoint) at the same check as the uninterrupted run would; never while a plunge
        // instant is searched step by step.
        let may_save = regular && !searching;
        let halt = may_save
            && (policy.halt_at_step.is_some_and(|h| scene.sim.steps >= h)
                || policy.wall_limit.is_some_and(|w| clock.elapsed() >= w));
        if halt || (may_save && policy.every.is_some_and(|e| last_save.elapsed() >= e)) {
            let wall = p.wall_before + clock.elapsed().as_secs_f64();
            let cpu = p.cpu_before + crate::bench::cpu_seconds() - cpu0;
            checkpoint::save(&ckpt_path, &fingerprint, &scene, &p, wall, cpu)?;
            last_save = Instant::now();
            if halt {
                if let Some(b) = &bar {
                    b.finish_and_clear();
                }
                return Err(checkpoint::Halted {
                    x,
                    steps: scene.sim.steps,
                    checkpoint: ckpt_path,
                }
                .into());
            }
        }
        let detect = regular || searching;
        let output = x >= p.next_output;
        let mut checked = false;
        if detect || output || x >= p.x_stop {
            let s = snapshot(&mut scene);
            let umax = s.vel.iter().map(|v| v.norm()).fold(0.0, f64::max);
            let mach = umax / g.c0;
            if mach > 0.1 && p.max_mach <= 0.1 {
                log::warn!("Mach number {mach:.3} above 0.1 at x/L = {x:.4}: raise c0 (--c0)");
            }
            p.max_mach = p.max_mach.max(mach);
            let eta = eta_profile(&s.pos, g.width, bin, g.dx_f);
            if p.plunge.is_none() {
                checked = true;
                // The mean level of the far field (the top particles jitter by a tenth of a spacing).
                let far = (mean_finite(&eta[far_from..]) - p.far_ref).abs();
                p.far_eta = p.far_eta.max(far / g.draft);
                let found = plunge_check(
                    &scene,
                    &s,
                    scene.sim.time,
                    (cfg.plunge_depth, cfg.plunge_circulation.threshold()),
                    &mut p.closure_watch,
                    searching,
                );
                if found.is_some() && !searching {
                    if let Some(r) = rewind.take() {
                        // t_p lies between the previous check and this one: go back and check every step.
                        replay_until = Some(scene.sim.steps);
                        r.restore(&mut scene, &mut p);
                        continue;
                    }
                }
                if let Some((pm, c)) = found {
                    replay_until = None;
                    log::info!("plunge at x/L = {:.4}", pm.x_plunge_over_l);
                    if opts.plots {
                        plunge_plots(&scene, &s, &c, &opts.out_dir)?;
                    }
                    p.bow = Some(bow_tables(&scene, &s));
                    if cfg.until == Until::Plunge {
                        p.x_stop = p.x_stop.min(pm.x_plunge_over_l + cfg.after_plunge);
                    }
                    p.plunge = Some(pm);
                }
            }
            if output || x >= p.x_stop {
                p.next_output += cfg.output_dx;
                p.series.push(vec![
                    x,
                    scene.sim.time - t_start,
                    scene.sim.steps as f64,
                    ke(&scene.sim) / (p.total_mass * g.draft),
                    mach,
                    p.far_eta,
                    s.on_surface.iter().filter(|b| **b).count() as f64,
                    scene.sim.wall_corrections as f64,
                ]);
                let y_wl = waterline_half_breadth(&scene.profile.at(scene.sim.time).points);
                p.crest = f64::NEG_INFINITY;
                for (k, z) in eta.iter().enumerate() {
                    // Bins inside the hull's waterline would show the water under the hull, not a free surface.
                    if z.is_finite() && (k as f64 + 0.5) * bin > y_wl {
                        p.eta_table.push(vec![x, (k as f64 + 0.5) * bin, z / g.draft]);
                        p.crest = p.crest.max(z / g.draft);
                    }
                }
                if cfg.frames {
                    let path = opts.out_dir.join(format!("frame_{:04}.png", p.series.rows.len()));
                    depth_plot(
                        &scene,
                        &s,
                        &path,
                        (0.0, 2.0 * g.beam, -g.draft, 2.5 * g.draft),
                        &format!("x/L = {x:.4}"),
                    )?;
                }
                if cfg.vtk {
                    let name = format!("frame_{:05}.vtp", p.vtk_frames.len());
                    write_frame(&scene, &s, &opts.out_dir.join(&name))?;
                    p.vtk_frames.push((x, name));
                }
            }
            if let Some(b) = &bar {
                b.set_position((1000.0 * (x - g.x0) / (p.x_stop - g.x0)).clamp(0.0, 1000.0) as u64);
                b.set_message(format!("{x:.4}"));
            }
        }
        // Every check that moved the closure watch (regular or at an output) is a point to come back to:
        // the step-by-step search compares with the same earlier check as the check that found the plunge.
        if checked && !searching && p.plunge.is_none() && cfg.detect_every > 1 {
            rewind = Some(Rewind::keep(&scene, &p));
        }
        if x >= p.x_stop {
            break;
        }
        if let Err(b) = scene.sim.step() {
            blowup = Some(b.to_string());
            break;
        }
    }
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    let mass_end: f64 = scene.sim.fluid.mass.iter().sum();
    scene.sim.refresh();
    let noise = scene.sim.pressure_noise() / g.draft;
    let result = TwoDtResult {
        hull: hull.meta.name.clone(),
        fr: cfg.fr,
        dx_over_l: g.dx_f,
        dx_coarse_over_l: g.dx_c,
        c0_over_sqrt_gl: g.c0,
        particles: n,
        steps: scene.sim.steps,
        wall_seconds: p.wall_before + clock.elapsed().as_secs_f64(),
        cpu_seconds: p.cpu_before + crate::bench::cpu_seconds() - cpu0,
        x_end_over_l: scene.profile.x_at(scene.sim.time),
        ke_after_settle: p.ke_after_settle,
        far_field_eta_over_d: p.far_eta,
        max_mach: p.max_mach,
        mass_change: (mass_end - p.total_mass) / p.total_mass,
        pressure_noise_over_rho_g_d: noise,
        crest_at_end_over_d: p.crest,
        wall_corrections: scene.sim.wall_corrections,
        plunged: p.plunge.is_some(),
        plunge: p.plunge.clone(),
        blowup,
    };
    let (bow_particles, bow_wall) = match p.bow.take() {
        Some(b) => b,
        None => {
            let s = snapshot(&mut scene);
            bow_tables(&scene, &s)
        }
    };
    bow_particles.write(&opts.out_dir.join("snapshot.csv"))?;
    bow_wall.write(&opts.out_dir.join("snapshot_wall.csv"))?;
    p.series.write(&opts.out_dir.join("series.csv"))?;
    p.eta_table.write(&opts.out_dir.join("eta.csv"))?;
    if cfg.vtk {
        vtk::write_pvd(&opts.out_dir.join("series.pvd"), &p.vtk_frames)?;
    }
    write_atomic(
        &opts.out_dir.join("metrics.json"),
        serde_json::to_string_pretty(&result)?.as_bytes(),
    )?;
    write_atomic(
        &opts.out_dir.join("metrics.csv"),
        metrics_csv(std::slice::from_ref(&result)).as_bytes(),
    )?;
    if ckpt_path.exists() {
        std::fs::remove_file(&ckpt_path)
            .map_err(|e| anyhow::anyhow!("cannot remove the finished run's {}: {e}", ckpt_path.display()))?;
    }
    Ok(result)
}

/// A new run: builds the scene, lets it settle (1.) and sets up the passage loop.
fn start(hull: &Arc<HullSurface>, cfg: &TwoDtConfig) -> anyhow::Result<(Scene, checkpoint::Passage, String)> {
    let clock = Instant::now();
    let mut scene = build(hull.clone(), cfg)?;
    let fingerprint = checkpoint::fingerprint(cfg, &scene);
    let g = scene.geom.clone();
    let total_mass: f64 = scene.sim.fluid.mass.iter().sum();

    // 1. Damped settling: the section stands still at x0.
    let ke_after_settle = scene.settle()? / (total_mass * g.draft);
    log::info!("settled: E_K/(M g D) = {ke_after_settle:.3e}");
    let (bin, far_from) = eta_bins(&g);
    let eta0 = eta_profile(&scene.sim.fluid.pos, g.width, bin, g.dx_f);
    let columns = |c: &[&str]| c.iter().map(|s| s.to_string()).collect();
    let series = Table::new(columns(&[
        "x_over_l",
        "t",
        "steps",
        "ke_over_mgd",
        "max_mach",
        "far_eta_over_d",
        "surface_particles",
        "wall_corrections",
    ]));
    let p = checkpoint::Passage {
        steps0: scene.sim.steps,
        total_mass,
        ke_after_settle,
        far_ref: mean_finite(&eta0[far_from..]),
        far_eta: 0.0,
        max_mach: 0.0,
        plunge: None,
        closure_watch: cavity::ClosureWatch::default(),
        x_stop: match cfg.until {
            Until::Plunge | Until::Transom => hull.x_range.1.min(g.x_end),
            Until::X(x) => x,
        },
        next_output: g.x0,
        vtk_frames: vec![],
        crest: f64::NAN,
        series,
        eta_table: Table::new(columns(&["x_over_l", "y_over_l", "eta_over_d"])),
        bow: None,
        wall_before: 0.0,
        cpu_before: 0.0,
        setup_seconds: clock.elapsed().as_secs_f64(),
    };
    Ok((scene, p, fingerprint))
}

/// The run saved in `path`, if resuming is asked, the file exists and is of this configuration. The scene is
/// built unpacked (the checkpoint holds the packed particles).
fn resume(
    hull: &Arc<HullSurface>,
    cfg: &TwoDtConfig,
    opts: &TwoDtOptions,
    path: &Path,
) -> anyhow::Result<Option<(Scene, checkpoint::Passage, String)>> {
    if !opts.checkpoint.resume || !path.exists() {
        return Ok(None);
    }
    let (mut scene, fingerprint) = scene_to_restore_into(hull, cfg)?;
    match checkpoint::restore(path, &fingerprint, &mut scene) {
        Ok(p) => {
            log::info!(
                "resuming from {} at x/L = {:.4}, step {}",
                path.display(),
                scene.profile.x_at(scene.sim.time),
                scene.sim.steps
            );
            Ok(Some((scene, p, fingerprint)))
        }
        Err(e) if e.is::<checkpoint::OtherConfiguration>() => {
            log::warn!("{e}: starting afresh (it will be overwritten)");
            Ok(None)
        }
        Err(e) => Err(e),
    }
}

/// The scene a checkpoint of `cfg` is restored into, built unpacked (the checkpoint holds the particles), and
/// the fingerprint that checkpoint must carry.
fn scene_to_restore_into(hull: &Arc<HullSurface>, cfg: &TwoDtConfig) -> anyhow::Result<(Scene, String)> {
    let scene = build(hull.clone(), &cfg.unpacked())?;
    let fingerprint = checkpoint::fingerprint(cfg, &scene);
    Ok((scene, fingerprint))
}

/// A run stopped part-way, as its checkpoint tells: how far it got, and whether it would be resumed.
#[derive(Clone, Debug)]
pub struct Progress {
    /// x/L of the section at the checkpoint.
    pub x_over_l: f64,
    /// x/L where the run starts (the stem side of the passage).
    pub x_start: f64,
    /// The checkpoint belongs to `cfg`: running the case goes on from it. When false, a run of `cfg`
    /// starts afresh and overwrites it.
    pub same_configuration: bool,
    /// What the checkpoint's header says (steps, stop point, plunge found, seconds spent).
    pub saved: checkpoint::Saved,
}

/// The progress of the run of `cfg` whose checkpoint is in `dir`, or `None` when there is no checkpoint. Builds
/// the scene unpacked (seconds, not the packing's minutes) to tell whether the checkpoint is of this
/// configuration, as a resumed run does, and where its section is.
pub fn progress(hull: &Arc<HullSurface>, cfg: &TwoDtConfig, dir: &Path) -> anyhow::Result<Option<Progress>> {
    let path = dir.join(checkpoint::FILE);
    if !path.exists() {
        return Ok(None);
    }
    let saved = checkpoint::peek(&path)?;
    let (scene, fingerprint) = scene_to_restore_into(hull, cfg)?;
    Ok(Some(Progress {
        x_over_l: scene.profile.x_at(saved.time),
        x_start: scene.geom.x0,
        same_configuration: saved.fingerprint == fingerprint,
        saved,
    }))
}

/// The metrics rows as CSV: the fields of [`TwoDtResult`] in order, those of the plunge flattened in place
/// (empty when there was no plunge). One header for all rows, taken from a result with a plunge.
pub fn metrics_csv(results: &[TwoDtResult]) -> String {
    let flat = |r: &TwoDtResult| -> Vec<(String, String)> {
        let mut r = r.clone();
        let plunged = r.plunge.is_some();
        let p = r.plunge.take().unwrap_or_default();
        let v = serde_json::to_value(&r).expect("serialisable");
        let pv = serde_json::to_value(&p).expect("serialisable");
        let cell = |x: &serde_json::Value| match x {
            serde_json::Value::String(s) => s.replace(',', ";"),
            serde_json::Value::Null => String::new(),
            other => other.to_string(),
        };
        let mut out = vec![];
        for (k, x) in v.as_object().expect("object") {
            if k == "plunge" {
                for (pk, px) in pv.as_object().expect("object") {
                    out.push((pk.clone(), if plunged { cell(px) } else { String::new() }));
                }
            } else {
                out.push((k.clone(), cell(x)));
            }
        }
        out
    };
    let rows: Vec<Vec<(String, String)>> = results.iter().map(flat).collect();
    let Some(first) = rows.first() else {
        return String::new();
    };
    let mut out = first.iter().map(|c| c.0.as_str()).collect::<Vec<_>>().join(",") + "\n";
    for r in &rows {
        out += &(r.iter().map(|c| c.1.as_str()).collect::<Vec<_>>().join(",") + "\n");
    }
    out
}

/// The bow region (y < 2B, z > −D) at the plunge, or at the end without one, for the study's sheet of
/// snapshots: particles (y/L, z/L, initial row 0 and 1 marked as 1 and 0.75, deeper ones by depth/D up to
/// 0.5, as in [`depth_plot`]) and the wall polyline.
fn bow_tables(scene: &Scene, s: &Snapshot) -> (Table, Table) {
    let g = &scene.geom;
    let mut parts = Table::new(vec!["y_over_l".into(), "z_over_l".into(), "mark".into()]);
    for (k, p) in s.pos.iter().enumerate() {
        if p.x < 2.0 * g.beam && p.y > -g.draft {
            let id = scene.sim.fluid.id[k] as usize;
            let mark = match scene.initial_row[id] {
                0 => 1.0,
                1 => 0.75,
                _ => (scene.initial_depth[id] / g.draft).min(0.5),
            };
            parts.push(vec![p.x, p.y, mark]);
        }
    }
    let mut wall = Table::new(vec!["y_over_l".into(), "z_over_l".into()]);
    for p in scene.profile.at(scene.sim.time).points {
        wall.push(vec![p.x, p.y]);
    }
    (parts, wall)
}

/// Points of a plot.
type PlotPoints = Vec<(f64, f64)>;

/// Particle positions and the current wall polyline, for plots.
fn plot_points(scene: &Scene, s: &Snapshot) -> (PlotPoints, PlotPoints) {
    let pts = s.pos.iter().map(|p| (p.x, p.y)).collect();
    let wall = scene
        .profile
        .at(scene.sim.time)
        .points
        .iter()
        .map(|p| (p.x, p.y))
        .collect();
    (pts, wall)
}

fn write_frame(scene: &Scene, s: &Snapshot, path: &Path) -> anyhow::Result<()> {
    let f = &scene.sim.fluid;
    let pts: Vec<[f64; 3]> = f.pos.iter().map(|p| [p.x, p.y, 0.0]).collect();
    let data = vec![
        vtk::PointData::Scalar("pressure", scene.sim.pressure().to_vec()),
        vtk::PointData::Scalar("initial_depth", f.tag.clone()),
        vtk::PointData::Scalar("free_surface", s.on_surface.iter().map(|b| *b as u8 as f64).collect()),
        vtk::PointData::Vector("velocity", f.vel.iter().map(|v| [v.x, v.y, 0.0]).collect()),
    ];
    vtk::write_vtp(path, &pts, &data)?;
    Ok(())
}

/// PNG snapshots at the plunge: pressure, and initial depth with the two top rows marked (thesis Fig. 10.7).
fn plunge_plots(scene: &Scene, s: &Snapshot, c: &cavity::Cavity, dir: &Path) -> anyhow::Result<()> {
    let g = &scene.geom;
    let span = (c.hi.x - 0.0).max(g.draft) * 1.3;
    let range = (0.0, span, -0.6 * g.draft, (c.hi.y + 1.2 * g.draft).min(g.z_top));
    let (pts, wall) = plot_points(scene, s);
    let p: Vec<f64> = scene.sim.pressure().iter().map(|p| p / g.draft).collect();
    plot::scatter_plot(
        &dir.join("plunge_pressure.png"),
        "pressure p/(ρ g D) at the plunge",
        ("y/L", "z/L"),
        &pts,
        &p,
        (0.0, 1.0),
        Some("p/(ρ g D)"),
        std::slice::from_ref(&wall),
        range,
        1400,
    )?;
    depth_plot(
        scene,
        s,
        &dir.join("plunge_initial_depth.png"),
        range,
        "initial depth / D (top two rows marked red and yellow)",
    )
}

/// Particles coloured by their initial depth, the two top rows marked (thesis Fig. 10.7).
fn depth_plot(
    scene: &Scene,
    s: &Snapshot,
    path: &Path,
    range: (f64, f64, f64, f64),
    title: &str,
) -> anyhow::Result<()> {
    let g = &scene.geom;
    let (pts, wall) = plot_points(scene, s);
    let ids = &scene.sim.fluid.id;
    let marks: Vec<f64> = ids
        .iter()
        .map(|&id| match scene.initial_row[id as usize] {
            0 => 1.0,
            1 => 0.75,
            _ => (scene.initial_depth[id as usize] / g.draft).min(0.5),
        })
        .collect();
    plot::scatter_plot(
        path,
        title,
        ("y/L", "z/L"),
        &pts,
        &marks,
        (0.0, 1.0),
        None,
        std::slice::from_ref(&wall),
        range,
        1400,
    )?;
    Ok(())
}
