//! Checkpoints of a towed run (the ship, the bent-wall channel in 3D): the generic particles-and-clock
//! checkpoint of [`crate::driver::checkpoint`] with the towed run's own progress, the bow's history, so that a
//! 3D run longer than a session stops with `--wall-limit` and goes on from where it was, to the same bits.

pub use crate::driver::checkpoint::{restore, save, CheckpointPolicy, RunProgress, Saver, FILE};
use serde::{Deserialize, Serialize};
use std::path::Path;

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

impl RunProgress for Progress {
    fn set_wall_before(&mut self, seconds: f64) {
        self.wall_before = seconds;
    }
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
    let (same_configuration, steps, progress) = crate::driver::checkpoint::peek::<Progress>(path, fingerprint)?;
    Ok(Peek {
        same_configuration,
        steps,
        travel_over_l: progress.bow.last().map_or(0.0, |b| b.0),
        wall_seconds: progress.wall_before,
    })
}
