//! Checkpoints of a towed-ship run (`checkpoint.bin` in its folder, format of [`crate::io::checkpoint`]): the
//! particles, the clock and the bow's history, so that a 3D run longer than a session stops with
//! `--wall-limit` and goes on from where it was, to the same bits (the time step carries no state besides the
//! particles, the clock and the step count; the scene is rebuilt from the same options).

use crate::io::checkpoint::Checkpoint;
use crate::sph::particles::Fluid;
use crate::sph::solver::{SimState, Simulation};
use nalgebra::Vector3;
use serde::{Deserialize, Serialize};
use std::path::Path;

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
