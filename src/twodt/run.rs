//! Runs one 2D+t case: damped settling, the ship's passage, free-surface detection every few steps, plunge
//! detection and the jet metrics, outputs (metrics row as CSV and JSON, series, η(y, x) table, plunge
//! snapshots, VTK).

use super::checkpoint;
use super::passage::{
    eta_bins, eta_profile, mean_finite, snapshot, Begin, Checkpoints, Detector, End, Outputs, TwoDtRun,
};
use super::pictures::bow_tables;
use super::scene::{build, Scene, TwoDtConfig, Until};
use crate::analysis::cavity;
use crate::driver::progress::{Progress, Status};
use crate::driver::{drive, Ended, Outcome};
use crate::geometry::surface::HullSurface;
use crate::io::{atomic::write_atomic, csv_table::Table, vtk};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

pub use super::result::{metrics_csv, PlungeMetrics, TwoDtResult};

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

/// Runs a case and writes its outputs into `opts.out_dir`. With `opts.checkpoint.resume` and a checkpoint of
/// the same configuration in that folder, goes on from it (`twodt::checkpoint`); a run that ends removes its
/// checkpoint. A run stopped on purpose with a checkpoint ends [`Ended::Halted`]; one that blows up ends with
/// its result, the diagnosis in [`TwoDtResult::blowup`], and its outputs written.
pub fn run(hull: Arc<HullSurface>, cfg: &TwoDtConfig, opts: &TwoDtOptions) -> anyhow::Result<Ended<TwoDtResult>> {
    let clock = Instant::now();
    let cpu0 = crate::process_usage::cpu_seconds();
    std::fs::create_dir_all(&opts.out_dir)
        .map_err(|e| anyhow::anyhow!("cannot create output directory {}: {e}", opts.out_dir.display()))?;
    let ckpt_path = opts.out_dir.join(checkpoint::FILE);
    let (scene, p, fingerprint) = match resume(&hull, cfg, opts, &ckpt_path)? {
        Some(resumed) => resumed,
        None => start(&hull, cfg)?,
    };
    let g = scene.geom.clone();
    let n = scene.sim.n_fluid();

    // 2. The passage.
    let mut run = TwoDtRun::new(scene, p);
    let mut begin = Begin { cfg };
    let mut checkpoints = Checkpoints {
        path: ckpt_path.clone(),
        fingerprint,
        policy: &opts.checkpoint,
        clock,
        cpu0,
        last_save: Instant::now(),
    };
    let mut detector = Detector {
        cfg,
        out_dir: &opts.out_dir,
        plots: opts.plots,
    };
    let mut outputs = Outputs {
        cfg,
        out_dir: &opts.out_dir,
    };
    let mut progress = Progress::new(&opts.label, opts.progress, opts.multi.as_ref(), |r: &TwoDtRun| {
        let x = r.x();
        Status {
            fraction: (x - g.x0) / (r.p.x_stop - g.x0),
            text: format!("x/L = {x:.4}"),
            steps: r.scene.sim.steps,
        }
    });
    let mut end = End { cfg };
    let outcome = drive(
        &mut run,
        &mut [
            &mut begin,
            &mut checkpoints,
            &mut detector,
            &mut outputs,
            &mut progress,
            &mut end,
        ],
    )?;
    let blowup = match outcome {
        Outcome::Halted(h) => return Ok(Ended::Halted(h)),
        Outcome::BlewUp(b) => Some(b.to_string()),
        Outcome::Finished => None,
    };
    let mass_end: f64 = run.scene.sim.fluid.mass.iter().sum();
    run.scene.sim.refresh();
    let noise = run.scene.sim.pressure_noise() / g.draft;
    let result = TwoDtResult {
        hull: hull.meta.name.clone(),
        fr: cfg.fr,
        dx_over_l: g.dx_f,
        dx_coarse_over_l: g.dx_c,
        c0_over_sqrt_gl: g.c0,
        particles: n,
        steps: run.scene.sim.steps,
        wall_seconds: run.p.wall_before + clock.elapsed().as_secs_f64(),
        cpu_seconds: run.p.cpu_before + crate::process_usage::cpu_seconds() - cpu0,
        x_end_over_l: run.scene.profile.x_at(run.scene.sim.time),
        ke_after_settle: run.p.ke_after_settle,
        far_field_eta_over_d: run.p.far_eta,
        max_mach: run.p.max_mach,
        mass_change: (mass_end - run.p.total_mass) / run.p.total_mass,
        pressure_noise_over_rho_g_d: noise,
        crest_at_end_over_d: run.p.crest,
        wall_corrections: run.scene.sim.wall_corrections,
        plunged: run.p.plunge.is_some(),
        plunge: run.p.plunge.clone(),
        blowup,
        air_over_d: cfg.air,
    };
    let (bow_particles, bow_wall) = match run.p.bow.take() {
        Some(b) => b,
        None => {
            let s = snapshot(&mut run.scene);
            bow_tables(&run.scene, &s)
        }
    };
    bow_particles.write(&opts.out_dir.join("snapshot.csv"))?;
    bow_wall.write(&opts.out_dir.join("snapshot_wall.csv"))?;
    run.p.series.write(&opts.out_dir.join("series.csv"))?;
    run.p.eta_table.write(&opts.out_dir.join("eta.csv"))?;
    if cfg.vtk {
        vtk::write_pvd(&opts.out_dir.join("series.pvd"), &run.p.vtk_frames)?;
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
    Ok(Ended::Ran(result))
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
    // The water's surface (with `--air` the air lies above it).
    let water = scene.sim.fluid.phase_subset(0).pos;
    let eta0 = eta_profile(&water, g.width, bin, g.dx_f);
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
pub struct CheckpointProgress {
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
pub fn progress(hull: &Arc<HullSurface>, cfg: &TwoDtConfig, dir: &Path) -> anyhow::Result<Option<CheckpointProgress>> {
    let path = dir.join(checkpoint::FILE);
    if !path.exists() {
        return Ok(None);
    }
    let saved = checkpoint::peek(&path)?;
    let (scene, fingerprint) = scene_to_restore_into(hull, cfg)?;
    Ok(Some(CheckpointProgress {
        x_over_l: scene.profile.x_at(saved.time),
        x_start: scene.geom.x0,
        same_configuration: saved.fingerprint == fingerprint,
        saved,
    }))
}
