//! Runs the cases of a study: resumable (a finished case leaves `case.json`, written atomically, and is
//! skipped on re-run unless its resolved configuration changed or `force` is set), one case or all, cases in
//! parallel (`jobs`) or one after the other with every thread inside the case, an overall progress bar and one
//! per running case, and a manifest (version, commit, resolved configuration, per-case timings).

use super::study_file::{CaseHull, CaseSpec, Study};
use crate::driver::{Ended, Halted};
use crate::io::atomic::write_atomic;
use crate::twodt::run::{run, TwoDtOptions, TwoDtResult};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// Throughput of a 2D+t run on this project's reference machine (2 cores), particle-steps per second, with
/// detection every 5 steps and the outputs: measured on Athena Fr 0.5, dx/L = 5e-4, r = 1.5 packed, 95 890
/// particles, 2 880 steps in 879.7 s (BENCHMARKS.md, session 7). Used only for the `--dry-run` estimate.
pub const REFERENCE_THROUGHPUT: f64 = 3.1e5;

/// What to run.
#[derive(Clone, Debug)]
pub struct StudyOptions {
    pub out_dir: PathBuf,
    /// Recompute finished cases.
    pub force: bool,
    /// Only this case (1-based), e.g. from a batch scheduler's array index.
    pub case: Option<usize>,
    /// Cases run at the same time; each gets `threads / jobs` threads.
    pub jobs: usize,
    /// Worker threads in all.
    pub threads: usize,
    pub progress: bool,
    /// Checkpoints of the running case: how often, and when to stop with one. Its `resume` is not read:
    /// a case goes on from its checkpoint unless `force` is set.
    pub checkpoint: crate::twodt::checkpoint::CheckpointPolicy,
}

/// A finished case as recorded in its folder (`case.json`).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct CaseRecord {
    pub spec: CaseSpec,
    pub result: TwoDtResult,
    /// The git commit of the build that ran the case (`BOWWAVE_GIT_COMMIT`): a study's cases may be run by
    /// different builds on different machines (`--case N`), and the manifest lists each one's. `None` in
    /// records written before this field existed.
    #[serde(default)]
    pub git_commit: Option<String>,
    /// The 3D run beside the 2D+t one, in a `[ship3d]` study.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ship3d: Option<super::ship3d::Ship3dRecord>,
}

/// Folder of a case.
pub fn case_dir(out: &Path, spec: &CaseSpec) -> PathBuf {
    out.join("cases").join(spec.dir_name())
}

/// The finished record of a case, if it exists and matches `spec` (else `None`: to be run).
pub fn finished(out: &Path, spec: &CaseSpec) -> Option<CaseRecord> {
    let text = std::fs::read_to_string(case_dir(out, spec).join("case.json")).ok()?;
    let rec: CaseRecord = serde_json::from_str(&text).ok()?;
    (rec.spec == *spec).then_some(rec)
}

/// Every finished case of the study that matches its current configuration, in study order.
pub fn collect_finished(study: &Study, out: &Path) -> Vec<CaseRecord> {
    study.cases.iter().filter_map(|c| finished(out, c)).collect()
}

/// Per-case estimate for `--dry-run`.
#[derive(Clone, Debug)]
pub struct Estimate {
    pub spec: CaseSpec,
    pub particles: usize,
    pub steps: f64,
    pub seconds: f64,
    /// The 3D run of a `[ship3d]` case: its plan (particles, steps to the shortest and longest travel), priced
    /// at [`crate::compare3d::towed_ship::MEASURED_THROUGHPUT`].
    pub ship3d: Option<crate::compare3d::towed_ship::Plan>,
}

/// Builds each case's scene (no time step) to count its particles and estimate its steps (from the
/// acoustic time-step limit at the fastest phase's c0 with a 10 % margin for the flow speed) and its run time at
/// [`REFERENCE_THROUGHPUT`]. A plunge search is estimated to its give-up point, the worst case. The scenes are
/// built unpacked ([`TwoDtConfig::unpacked`](crate::twodt::scene::TwoDtConfig::unpacked), the same count): at
/// the published resolutions the packing would cost minutes per case (regression test
/// `dry_run_does_not_pack_the_scenes`).
pub fn dry_run(study: &Study) -> anyhow::Result<Vec<Estimate>> {
    study
        .cases
        .iter()
        .map(|spec| {
            let hull = case_surface(study, spec, None)?;
            let scene = crate::twodt::scene::build(hull.clone(), &dry_run_config(spec))?;
            let g = &scene.geom;
            let h = scene.sim.kernel.h;
            // The fastest sound speed sets the step: with air, the air's (`twodt::scene::air_phases`).
            let c_max = match &scene.sim.cfg.multi_fluid {
                None => g.c0,
                Some(mf) => mf.max_sound_speed().max(g.c0),
            };
            let dt = crate::sph::equations::timestep::time_step(scene.sim.cfg.cfl, h, 1.1 * c_max, 1.0);
            let t = scene.profile.t_at(g.x_end);
            let particles = scene.sim.n_fluid();
            let steps = (t / dt).ceil();
            let ship3d = spec
                .ship3d
                .as_ref()
                .map(|ship| {
                    crate::compare3d::towed_ship::plan(&crate::compare3d::towed_ship::TowedShip::with_options(
                        (*hull).clone(),
                        spec.fr(),
                        ship,
                    ))
                })
                .transpose()?;
            Ok(Estimate {
                spec: spec.clone(),
                particles,
                steps,
                seconds: particles as f64 * steps / REFERENCE_THROUGHPUT,
                ship3d,
            })
        })
        .collect()
}

/// The configuration a dry run builds its scene from: the case's, without the packing.
pub fn dry_run_config(spec: &CaseSpec) -> crate::twodt::scene::TwoDtConfig {
    spec.config.unpacked()
}

/// The hull surface of a case: its offsets file read, or its variant generated and calibrated (and, with
/// `dir`, written there as `hull.csv`, the record of what ran).
pub(crate) fn case_surface(
    study: &Study,
    spec: &CaseSpec,
    dir: Option<&Path>,
) -> anyhow::Result<Arc<crate::geometry::surface::HullSurface>> {
    use crate::geometry::parametric;
    let offsets = match &spec.hull {
        CaseHull::File(f) => crate::geometry::hull_file::HullOffsets::read(&study.resolve(f))?,
        CaseHull::Variant { generator, set } => {
            let pairs = CaseHull::set_pairs(set);
            let (_, _, h) = parametric::generate(generator, &pairs, parametric::STATIONS, parametric::POINTS)?;
            if let Some(d) = dir {
                write_atomic(&d.join("hull.csv"), h.to_csv().as_bytes())?;
            }
            h
        }
    };
    Ok(Arc::new(crate::geometry::surface::HullSurface::new(&offsets)))
}

/// The manifest: what ran, with what, and how long each case took.
#[derive(Serialize)]
struct Manifest<'a> {
    bowwave_version: &'a str,
    /// The build that wrote this manifest (each case's own is in `cases`).
    git_commit: &'a str,
    study_file: String,
    hull_file: String,
    hull_status: String,
    study: &'a super::study_file::StudyFile,
    cases: Vec<ManifestCase<'a>>,
}

#[derive(Serialize)]
struct ManifestCase<'a> {
    spec: &'a CaseSpec,
    status: &'static str,
    /// The build that ran the case, if recorded.
    git_commit: Option<String>,
    wall_seconds: Option<f64>,
    cpu_seconds: Option<f64>,
    particles: Option<usize>,
    steps: Option<u64>,
}

/// Writes `manifest.json` from the cases finished so far, holding the study folder's lock.
pub fn write_manifest(study: &Study, out: &Path) -> anyhow::Result<()> {
    super::lock::with_study_lock(out, || write_manifest_locked(study, out))
}

/// [`write_manifest`] for a caller that holds the lock.
pub(crate) fn write_manifest_locked(study: &Study, out: &Path) -> anyhow::Result<()> {
    let status = crate::geometry::hull_file::HullOffsets::read(&study.hull_path)
        .map(|h| format!("{:?}", h.meta.status).to_lowercase())
        .unwrap_or_else(|_| "unknown".into());
    let cases = study
        .cases
        .iter()
        .map(|spec| {
            let rec = finished(out, spec);
            let r = rec.as_ref().map(|r| &r.result);
            ManifestCase {
                spec,
                status: match r {
                    None if case_dir(out, spec).join(crate::twodt::checkpoint::FILE).exists()
                        || case_dir(out, spec)
                            .join(super::ship3d::DIR)
                            .join(crate::compare3d::towed_checkpoint::FILE)
                            .exists() =>
                    {
                        "stopped part-way (checkpoint)"
                    }
                    None => "not run",
                    Some(r) if r.blowup.is_some() => "stopped early",
                    Some(r) if r.plunged => "plunged",
                    Some(_) => "no plunge",
                },
                git_commit: rec.as_ref().and_then(|r| r.git_commit.clone()),
                wall_seconds: r.map(|r| r.wall_seconds),
                cpu_seconds: r.map(|r| r.cpu_seconds),
                particles: r.map(|r| r.particles),
                steps: r.map(|r| r.steps),
            }
        })
        .collect();
    let m = Manifest {
        bowwave_version: env!("CARGO_PKG_VERSION"),
        git_commit: env!("BOWWAVE_GIT_COMMIT"),
        study_file: study.file.display().to_string(),
        hull_file: study.hull_path.display().to_string(),
        hull_status: status,
        study: &study.spec,
        cases,
    };
    write_atomic(&out.join("manifest.json"), serde_json::to_string_pretty(&m)?.as_bytes())?;
    Ok(())
}

/// What [`run_cases`] did.
#[derive(Debug, Default)]
pub struct Ran {
    /// Cases that ran to their end (a blow-up included: its record says so).
    pub finished: usize,
    /// Cases stopped at the wall-time limit with a checkpoint: the same command goes on from them.
    pub halted: Vec<Halted>,
    /// Cases not started because the wall-time limit had passed when their turn came.
    pub not_started: usize,
}

/// Runs the cases that are not finished yet (or all with `force`, or only `case`), then rewrites the
/// manifest.
pub fn run_cases(study: &Study, opts: &StudyOptions) -> anyhow::Result<Ran> {
    let todo: Vec<CaseSpec> = study
        .cases
        .iter()
        .filter(|c| opts.case.is_none_or(|k| k == c.index))
        .filter(|c| {
            let done = finished(&opts.out_dir, c).is_some();
            if done && !opts.force {
                log::info!("case {} (Fr {}) already finished, skipped", c.index, c.fr());
            }
            opts.force || !done
        })
        .cloned()
        .collect();
    if let Some(k) = opts.case {
        anyhow::ensure!(
            (1..=study.cases.len()).contains(&k),
            "--case {k}: expected 1 to {} (the study has {} Froude numbers)",
            study.cases.len(),
            study.cases.len()
        );
    }
    std::fs::create_dir_all(&opts.out_dir)
        .map_err(|e| anyhow::anyhow!("cannot create output directory {}: {e}", opts.out_dir.display()))?;
    write_manifest(study, &opts.out_dir)?;
    if todo.is_empty() {
        return Ok(Ran::default());
    }
    let multi = indicatif::MultiProgress::new();
    if !opts.progress {
        multi.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    }
    let overall = multi.add(indicatif::ProgressBar::new(todo.len() as u64));
    overall.set_style(
        indicatif::ProgressStyle::with_template("cases {pos}/{len} {bar:30} [{elapsed_precise} / eta {eta_precise}]")
            .expect("valid template"),
    );
    let jobs = opts.jobs.clamp(1, todo.len());
    let threads_each = (opts.threads / jobs).max(1);
    let queue = Mutex::new(todo.into_iter().rev().collect::<Vec<_>>());
    let errors: Mutex<Vec<String>> = Mutex::new(vec![]);
    let ran = Mutex::new(Ran::default());
    std::thread::scope(|scope| {
        for _ in 0..jobs {
            scope.spawn(|| {
                let pool = match rayon::ThreadPoolBuilder::new().num_threads(threads_each).build() {
                    Ok(p) => p,
                    Err(e) => {
                        errors.lock().expect("lock").push(format!("thread pool: {e}"));
                        return;
                    }
                };
                loop {
                    // The limit is the command's: a case whose turn comes after it waits for the next command.
                    if opts.checkpoint.deadline.is_some_and(|d| std::time::Instant::now() >= d) {
                        break;
                    }
                    let Some(spec) = queue.lock().expect("lock").pop() else {
                        break;
                    };
                    let r = pool.install(|| run_one(study, &spec, opts, &multi));
                    match r {
                        Ok(None) => ran.lock().expect("lock").finished += 1,
                        Ok(Some(h)) => ran.lock().expect("lock").halted.push(h),
                        Err(e) => {
                            errors
                                .lock()
                                .expect("lock")
                                .push(format!("case {} (Fr {}): {e:#}", spec.index, spec.fr()))
                        }
                    }
                    overall.inc(1);
                    if let Err(e) = write_manifest(study, &opts.out_dir) {
                        errors.lock().expect("lock").push(format!("manifest: {e:#}"));
                    }
                }
            });
        }
    });
    overall.finish_and_clear();
    let errors = errors.into_inner().expect("lock");
    anyhow::ensure!(errors.is_empty(), "{}", errors.join("\n"));
    let mut ran = ran.into_inner().expect("lock");
    ran.not_started = queue.into_inner().expect("lock").len();
    Ok(ran)
}

/// Runs one case into its folder and records it; `Some` when it halted with a checkpoint.
fn run_one(
    study: &Study,
    spec: &CaseSpec,
    opts: &StudyOptions,
    multi: &indicatif::MultiProgress,
) -> anyhow::Result<Option<Halted>> {
    let dir = case_dir(&opts.out_dir, spec);
    // A stale record must not survive a re-run that is interrupted.
    let _ = std::fs::remove_file(dir.join("case.json"));
    let hull = case_surface(study, spec, Some(&dir))?;
    let topts = TwoDtOptions {
        out_dir: dir.clone(),
        progress: opts.progress,
        plots: true,
        multi: Some(multi.clone()),
        label: format!("{} Fr {:.3} ", study.spec.name, spec.fr()),
        checkpoint: crate::twodt::checkpoint::CheckpointPolicy {
            resume: !opts.force,
            ..opts.checkpoint.clone()
        },
    };
    let result = match run(hull.clone(), &spec.config, &topts)? {
        Ended::Ran(r) => r,
        Ended::Halted(h) => return Ok(Some(h)),
    };
    let ship3d = match &spec.ship3d {
        None => None,
        Some(ship) => {
            let c = &opts.checkpoint;
            match super::ship3d::run(
                &hull,
                spec.fr(),
                ship,
                spec.config.shifting(),
                &dir,
                (c.every, c.deadline, opts.force),
                opts.progress,
            )? {
                Ended::Ran(r) => Some(r),
                Ended::Halted(h) => return Ok(Some(h)),
            }
        }
    };
    let rec = CaseRecord {
        spec: spec.clone(),
        result,
        git_commit: Some(env!("BOWWAVE_GIT_COMMIT").to_string()),
        ship3d,
    };
    write_atomic(&dir.join("case.json"), serde_json::to_string_pretty(&rec)?.as_bytes())?;
    Ok(None)
}
