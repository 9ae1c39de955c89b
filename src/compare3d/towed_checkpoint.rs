//! Checkpoints of a towed-ship run (`checkpoint.bin` in its folder, format of [`crate::io::checkpoint`]): the
//! particles, the clock and the bow's history, so that a 3D run longer than a session stops with
//! `--wall-limit` and goes on from where it was, to the same bits (the time step carries no state besides the
//! particles, the clock and the step count; the scene is rebuilt from the same options).

use crate::driver::{Flow, Halted, Observer};
use crate::io::checkpoint::Checkpoint;
use crate::sph::particles::Fluid;
use crate::sph::solver::{SimState, Simulation};
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};
use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// File name of the checkpoint in a run's output folder.
pub const FILE: &str = "checkpoint.bin";

/// The towed run's own state besides the particles.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Progress {
    /// (travel / L, bow crest η/D, its x/L) at every sample so far.
    pub bow: Vec<(f64, f64, f64)>,
    /// Travel (L) at which the next bow sample is taken.
    pub next_sample: f64,
    /// Wall seconds spent in earlier sessions.
    pub wall_before: f64,
    /// Travel (L) at which the next ParaView frame is written, and the frames so far (time in s, number), so
    /// that a resumed run goes on numbering and indexing them.
    #[serde(default)]
    pub next_frame: f64,
    #[serde(default)]
    pub frames: Vec<(f64, String)>,
}

/// Where and how often a towed run (the ship, the bent-wall channel in 3D) saves itself, and when it stops saved.
#[derive(Clone, Debug)]
pub struct CheckpointPolicy {
    /// The run's folder: `checkpoint.bin` is read from it at the start (if it is of the same configuration) and
    /// written to it.
    pub dir: PathBuf,
    /// Wall time between two saves.
    pub every: Duration,
    /// Save and stop once this session has used this much wall time.
    pub wall_limit: Option<Duration>,
    /// Save and stop once the run has taken this many steps (tests; jobs split by steps).
    pub halt_at_step: Option<u64>,
}

/// The observer that saves a towed run every `policy.every` of wall time and halts it, saved, at the policy's
/// wall-time or step limit (no policy: it does nothing); `at(t)` says where the run stands, for the halt's message.
pub struct Saver<'a> {
    policy: Option<&'a CheckpointPolicy>,
    fingerprint: &'a str,
    state: &'a RefCell<Progress>,
    wall_before: f64,
    at: &'a dyn Fn(f64) -> String,
    clock: Instant,
    last_save: Instant,
}

impl<'a> Saver<'a> {
    /// `state` is the run's own progress, saved with the particles; `wall_before` the wall seconds of earlier
    /// sessions.
    pub fn new(
        policy: Option<&'a CheckpointPolicy>,
        fingerprint: &'a str,
        state: &'a RefCell<Progress>,
        wall_before: f64,
        at: &'a dyn Fn(f64) -> String,
    ) -> Self {
        Saver {
            policy,
            fingerprint,
            state,
            wall_before,
            at,
            clock: Instant::now(),
            last_save: Instant::now(),
        }
    }
}

impl Observer<Simulation<3>> for Saver<'_> {
    fn observe(&mut self, sim: &mut Simulation<3>) -> anyhow::Result<Flow> {
        let Some(c) = self.policy else {
            return Ok(Flow::Step);
        };
        let halt =
            c.wall_limit.is_some_and(|w| self.clock.elapsed() >= w) || c.halt_at_step.is_some_and(|n| sim.steps >= n);
        if halt || self.last_save.elapsed() >= c.every {
            let path = c.dir.join(FILE);
            let mut st = self.state.borrow().clone();
            st.wall_before = self.wall_before + self.clock.elapsed().as_secs_f64();
            save(&path, self.fingerprint, sim, &st)?;
            self.last_save = Instant::now();
            if halt {
                return Ok(Flow::Halt(Halted {
                    at: (self.at)(sim.time),
                    steps: sim.steps,
                    checkpoint: path,
                }));
            }
        }
        Ok(Flow::Step)
    }
}

#[derive(Serialize, Deserialize)]
struct Header {
    fingerprint: String,
    time: f64,
    steps: u64,
    last_dt: f64,
    wall_corrections: u64,
    progress: Progress,
}

const AXES: [&str; 3] = ["x", "y", "z"];

/// Saves the particles and `progress` to `path` (atomically).
pub fn save(path: &Path, fingerprint: &str, sim: &Simulation<3>, progress: &Progress) -> anyhow::Result<()> {
    let f = &sim.fluid;
    let mut c = Checkpoint::default();
    for (a, name) in AXES.iter().enumerate() {
        c.arrays
            .insert(format!("pos_{name}"), f.pos.iter().map(|p| p[a]).collect());
        c.arrays
            .insert(format!("vel_{name}"), f.vel.iter().map(|v| v[a]).collect());
    }
    c.arrays.insert("rho".into(), f.rho.clone());
    c.arrays.insert("mass".into(), f.mass.clone());
    c.arrays.insert("id".into(), f.id.iter().map(|&i| i as f64).collect());
    c.arrays.insert("tag".into(), f.tag.clone());
    c.header = serde_json::to_value(Header {
        fingerprint: fingerprint.to_string(),
        time: sim.time,
        steps: sim.steps,
        last_dt: sim.last_dt,
        wall_corrections: sim.wall_corrections,
        progress: progress.clone(),
    })?;
    c.write(path)
}

/// Restores the particles of a checkpoint of the same configuration into `sim` and returns the run's progress;
/// `None` if the file is of another configuration (the run then starts afresh).
pub fn restore(path: &Path, fingerprint: &str, sim: &mut Simulation<3>) -> anyhow::Result<Option<Progress>> {
    let c = Checkpoint::read(path)?;
    let h: Header = serde_json::from_value(c.header.clone())
        .map_err(|e| anyhow::anyhow!("checkpoint {}: header: {e}", path.display()))?;
    if h.fingerprint != fingerprint {
        return Ok(None);
    }
    let n = c.array(path, "rho", None)?.len();
    let a = |name: &str| c.array(path, name, Some(n));
    let v3 = |prefix: &str| -> anyhow::Result<Vec<Vector3<f64>>> {
        let (x, y, z) = (
            a(&format!("{prefix}_x"))?,
            a(&format!("{prefix}_y"))?,
            a(&format!("{prefix}_z"))?,
        );
        Ok((0..n).map(|i| Vector3::new(x[i], y[i], z[i])).collect())
    };
    sim.set_state(SimState {
        fluid: Fluid {
            pos: v3("pos")?,
            vel: v3("vel")?,
            rho: a("rho")?.to_vec(),
            mass: a("mass")?.to_vec(),
            id: a("id")?.iter().map(|&i| i as u32).collect(),
            tag: a("tag")?.to_vec(),
            phase: vec![0; n],
        },
        time: h.time,
        steps: h.steps,
        last_dt: h.last_dt,
        wall_corrections: h.wall_corrections,
    });
    Ok(Some(h.progress))
}

/// Where a saved run stands, read from its checkpoint without restoring it (`bowwave study --status`).
#[derive(Clone, Debug, PartialEq)]
pub struct Peek {
    /// Whether the checkpoint is of this configuration (a run goes on from it) or of another (a run starts
    /// afresh).
    pub same_configuration: bool,
    pub steps: u64,
    /// Travel (L) at the last bow sample, 0 before the ramp ended.
    pub travel_over_l: f64,
    /// Wall seconds of the sessions so far.
    pub wall_seconds: f64,
}

/// Reads the header of the checkpoint at `path` against the configuration's `fingerprint`.
pub fn peek(path: &Path, fingerprint: &str) -> anyhow::Result<Peek> {
    let c = Checkpoint::read(path)?;
    let h: Header = serde_json::from_value(c.header.clone())
        .map_err(|e| anyhow::anyhow!("checkpoint {}: header: {e}", path.display()))?;
    Ok(Peek {
        same_configuration: h.fingerprint == fingerprint,
        steps: h.steps,
        travel_over_l: h.progress.bow.last().map_or(0.0, |b| b.0),
        wall_seconds: h.progress.wall_before,
    })
}
