//! Checkpoints of a 2D+t run: the particles and the state of the passage loop, saved every few minutes into
//! the run's folder (`checkpoint.bin`, format of [`crate::io::checkpoint`]) so that a run stopped by a
//! batch system's time limit, a kill or a crash goes on from where it was. A resumed run gives the same bits
//! as an uninterrupted one (test `resumed_run_gives_the_same_bits_as_an_uninterrupted_one`): the time step
//! carries no state besides the particles, the clock and the step count.

use super::result::PlungeMetrics;
use super::scene::Scene;
use crate::analysis::cavity::ClosureWatch;
use crate::analysis::level_set::LevelSet;
use crate::driver::checkpoint::{put_fluid, take_fluid, Clock, YZ};
use crate::io::checkpoint::Checkpoint;
use crate::io::csv_table::Table;
use nalgebra::Vector2;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// File name of the checkpoint in a run's output folder.
pub const FILE: &str = "checkpoint.bin";

/// When to save and when to stop.
#[derive(Clone, Debug, Default)]
pub struct CheckpointPolicy {
    /// Wall time between checkpoints; `None`: never save one (except when halting).
    pub every: Option<Duration>,
    /// Go on from the folder's checkpoint when there is one of the same configuration.
    pub resume: bool,
    /// Save and stop once this instant has passed (a batch job's limit, `--wall-limit` counted from the
    /// command's start, [`crate::driver::checkpoint::deadline`]), at the next plunge check (within
    /// `detect_every` steps). A study's cases share it: one that starts after it halts at its first check.
    pub deadline: Option<Instant>,
    /// Save and stop at the first plunge check with at least this many time steps done (tests; jobs split by
    /// steps).
    pub halt_at_step: Option<u64>,
}

/// A run stopped on purpose ([`CheckpointPolicy::deadline`] or `halt_at_step`), its state saved.
#[derive(Debug, thiserror::Error)]
#[error("stopped at x/L = {x:.4} after {steps} steps, the state saved in {}: run the same command again to go on", .checkpoint.display())]
pub struct Halted {
    pub x: f64,
    pub steps: u64,
    pub checkpoint: PathBuf,
}

/// What the passage loop (the observers of `twodt::passage`) carries from one iteration to the next: what a
/// checkpoint saves besides the particles.
#[derive(Clone, Debug)]
pub struct Passage {
    /// Step count when the ship started (after the settling); detection runs every `detect_every` from it.
    pub steps0: u64,
    pub total_mass: f64,
    /// E_K/(M g D) left by the settling.
    pub ke_after_settle: f64,
    /// Mean far-field level at the start, and the largest departure from it so far / D.
    pub far_ref: f64,
    pub far_eta: f64,
    pub max_mach: f64,
    pub plunge: Option<PlungeMetrics>,
    pub closure_watch: ClosureWatch,
    pub x_stop: f64,
    pub next_output: f64,
    pub vtk_frames: Vec<(f64, String)>,
    /// Crest height at the last output / D (NaN before the first).
    pub crest: f64,
    pub series: Table,
    pub eta_table: Table,
    /// Particle and wall tables of the bow region at the plunge.
    pub bow: Option<(Table, Table)>,
    /// Wall and CPU seconds spent in earlier sessions of this run.
    pub wall_before: f64,
    pub cpu_before: f64,
    /// Wall seconds spent before the passage began (building and packing the scene, settling): left out of
    /// the pace from which `study --status` estimates the time still needed.
    pub setup_seconds: f64,
}

/// The small state, stored as the JSON header.
#[derive(Serialize, Deserialize)]
struct Header {
    fingerprint: String,
    #[serde(flatten)]
    clock: Clock,
    packing: Option<crate::sph::packing::PackingReport>,
    steps0: u64,
    total_mass: f64,
    ke_after_settle: f64,
    far_ref: f64,
    far_eta: f64,
    max_mach: f64,
    plunge: Option<PlungeMetrics>,
    x_stop: f64,
    next_output: f64,
    vtk_frames: Vec<(f64, String)>,
    crest: Option<f64>,
    tables: Vec<(String, Vec<String>)>,
    level_set: Option<LevelSetHeader>,
    wall_seconds: f64,
    cpu_seconds: f64,
    /// Absent (0) in checkpoints written before session 19.
    #[serde(default)]
    setup_seconds: f64,
}

#[derive(Serialize, Deserialize)]
struct LevelSetHeader {
    origin: (f64, f64),
    spacing: f64,
    ny: usize,
    nz: usize,
    surface_level: f64,
}

/// What identifies the configuration of a run: a checkpoint of another configuration is not resumed (the
/// output-only options may differ, [`TwoDtConfig::physics`](super::config::TwoDtConfig::physics)).
pub fn fingerprint(cfg: &super::scene::TwoDtConfig, scene: &Scene) -> String {
    format!(
        "{} | {:?} | {:?}",
        scene.profile.hull.meta.name,
        cfg.physics(),
        scene.geom
    )
}

/// Saves the scene's particles and the loop state to `path` (atomically); `wall`/`cpu`: seconds so far.
pub fn save(path: &Path, fingerprint: &str, scene: &Scene, p: &Passage, wall: f64, cpu: f64) -> anyhow::Result<()> {
    let sim = &scene.sim;
    let mut c = Checkpoint::default();
    put_fluid(&mut c, &sim.fluid, &YZ);
    let mut put = |name: &str, v: Vec<f64>| {
        c.arrays.insert(name.to_string(), v);
    };
    put("initial_depth", scene.initial_depth.clone());
    put("initial_row", scene.initial_row.iter().map(|&r| r as f64).collect());
    let mut tables = vec![];
    let mut put_table = |name: &str, t: &Table| {
        tables.push((name.to_string(), t.columns.clone()));
        put(name, t.rows.iter().flatten().copied().collect());
    };
    put_table("series", &p.series);
    put_table("eta", &p.eta_table);
    if let Some((a, b)) = &p.bow {
        put_table("bow_particles", a);
        put_table("bow_wall", b);
    }
    let level_set = p.closure_watch.previous().map(|(ls, mask)| {
        put("closure_phi", ls.phi.clone());
        put("closure_mask", mask.iter().map(|&b| b as u8 as f64).collect());
        LevelSetHeader {
            origin: (ls.origin.x, ls.origin.y),
            spacing: ls.spacing,
            ny: ls.ny,
            nz: ls.nz,
            surface_level: ls.surface_level,
        }
    });
    c.header = serde_json::to_value(Header {
        fingerprint: fingerprint.to_string(),
        clock: sim.clock(),
        packing: scene.packing,
        steps0: p.steps0,
        total_mass: p.total_mass,
        ke_after_settle: p.ke_after_settle,
        far_ref: p.far_ref,
        far_eta: p.far_eta,
        max_mach: p.max_mach,
        plunge: p.plunge.clone(),
        x_stop: p.x_stop,
        next_output: p.next_output,
        vtk_frames: p.vtk_frames.clone(),
        crest: p.crest.is_finite().then_some(p.crest),
        tables,
        level_set,
        wall_seconds: wall,
        cpu_seconds: cpu,
        setup_seconds: p.setup_seconds,
    })?;
    c.write(path)
}

/// Where a saved run stands, from its checkpoint's header alone (the particles are not read).
#[derive(Clone, Debug, PartialEq)]
pub struct Saved {
    /// The configuration it belongs to ([`fingerprint`]).
    pub fingerprint: String,
    /// Simulated time and time steps done.
    pub time: f64,
    pub steps: u64,
    /// Where the passage will stop, x/L: the give-up point of a plunge search, or the plunge plus its margin
    /// once found.
    pub x_stop: f64,
    /// Whether the plunge has been found already.
    pub plunged: bool,
    /// Wall and CPU seconds spent on the run so far, over all its sessions.
    pub wall_seconds: f64,
    pub cpu_seconds: f64,
    /// Of `wall_seconds`, those spent before the passage began (packing, settling); 0 when not recorded.
    pub setup_seconds: f64,
}

/// Reads the header of the checkpoint at `path`; errors name the file and what is wrong.
pub fn peek(path: &Path) -> anyhow::Result<Saved> {
    let h: Header = serde_json::from_value(Checkpoint::read_header(path)?)
        .map_err(|e| anyhow::anyhow!("checkpoint {}: header: {e}", path.display()))?;
    Ok(Saved {
        fingerprint: h.fingerprint,
        time: h.clock.time,
        steps: h.clock.steps,
        x_stop: h.x_stop,
        plunged: h.plunge.is_some(),
        wall_seconds: h.wall_seconds,
        cpu_seconds: h.cpu_seconds,
        setup_seconds: h.setup_seconds,
    })
}

/// Why a checkpoint was not resumed.
#[derive(Debug, thiserror::Error)]
#[error("checkpoint {} is of another configuration", .0.display())]
pub struct OtherConfiguration(pub PathBuf);

/// Puts the checkpoint's particles into `scene` (built for the same configuration) and returns the loop
/// state. A checkpoint of another configuration gives [`OtherConfiguration`]; an unreadable one an error
/// naming the file and what is wrong.
pub fn restore(path: &Path, fingerprint: &str, scene: &mut Scene) -> anyhow::Result<Passage> {
    let c = Checkpoint::read(path)?;
    let h: Header = serde_json::from_value(c.header.clone())
        .map_err(|e| anyhow::anyhow!("checkpoint {}: header: {e}", path.display()))?;
    if h.fingerprint != fingerprint {
        return Err(OtherConfiguration(path.to_path_buf()).into());
    }
    // Water (phase 0) and, with `--air`, air (1).
    scene.sim.set_state(h.clock.with(take_fluid(&c, path, &YZ)?));
    scene.initial_depth = c.array(path, "initial_depth", None)?.to_vec();
    scene.initial_row = c
        .array(path, "initial_row", None)?
        .iter()
        .map(|&r| r as usize)
        .collect();
    scene.packing = h.packing;
    let table = |name: &str| -> anyhow::Result<Option<Table>> {
        let Some((_, columns)) = h.tables.iter().find(|(t, _)| t == name) else {
            return Ok(None);
        };
        let flat = c.array(path, name, None)?;
        if columns.is_empty() || flat.len() % columns.len() != 0 {
            anyhow::bail!(
                "checkpoint {}: table `{name}` holds {} values, not a whole number of rows",
                path.display(),
                flat.len()
            );
        }
        Ok(Some(Table {
            columns: columns.clone(),
            rows: flat.chunks(columns.len()).map(|r| r.to_vec()).collect(),
        }))
    };
    let missing = |name: &str| anyhow::anyhow!("checkpoint {}: no table `{name}`", path.display());
    let bow = match (table("bow_particles")?, table("bow_wall")?) {
        (Some(a), Some(b)) => Some((a, b)),
        _ => None,
    };
    let previous = match &h.level_set {
        Some(l) => {
            let cells = Some(l.ny * l.nz);
            let phi = c.array(path, "closure_phi", cells)?.to_vec();
            let mask = c
                .array(path, "closure_mask", cells)?
                .iter()
                .map(|&b| b != 0.0)
                .collect();
            let ls = LevelSet {
                origin: Vector2::new(l.origin.0, l.origin.1),
                spacing: l.spacing,
                ny: l.ny,
                nz: l.nz,
                phi,
                surface_level: l.surface_level,
            };
            Some((ls, mask))
        }
        None => None,
    };
    Ok(Passage {
        steps0: h.steps0,
        total_mass: h.total_mass,
        ke_after_settle: h.ke_after_settle,
        far_ref: h.far_ref,
        far_eta: h.far_eta,
        max_mach: h.max_mach,
        plunge: h.plunge,
        closure_watch: ClosureWatch::resume(previous),
        x_stop: h.x_stop,
        next_output: h.next_output,
        vtk_frames: h.vtk_frames,
        crest: h.crest.unwrap_or(f64::NAN),
        series: table("series")?.ok_or_else(|| missing("series"))?,
        eta_table: table("eta")?.ok_or_else(|| missing("eta"))?,
        bow,
        wall_before: h.wall_seconds,
        cpu_before: h.cpu_seconds,
        setup_seconds: h.setup_seconds,
    })
}
