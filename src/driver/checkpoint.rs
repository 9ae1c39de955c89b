//! Checkpoints of a run of the solver, for every kind of run that outlasts a session (the towed ship, the 3D
//! bent wall, the wedge check; the 2D+t passage reads and writes its particles with the same functions): the
//! particles, the clock and the run's own progress (any serde type) in `checkpoint.bin` in the run's folder
//! (format of [`crate::io::checkpoint`]). The time step carries no state besides the particles, the clock and
//! the step count, so a run rebuilt from the same options and restored goes on to the same bits.
//!
//! [`Saver`] is the observer that saves every [`CheckpointPolicy::every`] of wall time and halts the run,
//! saved, at the policy's wall-time or step limit.

use super::{Flow, Halted, Observer};
use crate::io::checkpoint::Checkpoint;
use crate::sph::particles::Fluid;
pub use crate::sph::solver::Clock;
use crate::sph::solver::Simulation;
use nalgebra::SVector;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use std::cell::RefCell;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// File name of the checkpoint in a run's output folder.
pub const FILE: &str = "checkpoint.bin";

/// The deadline of a run given `wall_limit` from now, the command's start: `None` without a limit or with one
/// beyond the clock's range.
pub fn deadline(wall_limit: Option<Duration>) -> Option<Instant> {
    wall_limit.and_then(|w| Instant::now().checked_add(w))
}

/// Where and how often a run saves itself, and when it stops saved.
#[derive(Clone, Debug)]
pub struct CheckpointPolicy {
    /// The run's folder: `checkpoint.bin` is read from it at the start (if it is of the same configuration) and
    /// written to it.
    pub dir: PathBuf,
    /// Wall time between two saves.
    pub every: Duration,
    /// Save and stop at the first step from this instant on: the command's start plus its `--wall-limit`, so
    /// that the set-up before the run's first step (building, packing, settling) counts against the limit too.
    pub deadline: Option<Instant>,
    /// Save and stop once the run has taken this many steps (tests; jobs split by steps).
    pub halt_at_step: Option<u64>,
}

impl CheckpointPolicy {
    /// The checkpoint file in the run's folder.
    pub fn path(&self) -> PathBuf {
        self.dir.join(FILE)
    }
}

/// A run's own progress: whatever it gathers besides the particles, and the wall seconds of its earlier
/// sessions, which the saver brings up to date at every save.
pub trait RunProgress: Clone + Serialize + DeserializeOwned {
    fn set_wall_before(&mut self, seconds: f64);
}

/// The names of a state's coordinate arrays in a checkpoint: positions and velocities per axis.
#[derive(Clone, Copy, Debug)]
pub struct Axes<const D: usize> {
    pub pos: [&'static str; D],
    pub vel: [&'static str; D],
}

/// x, y(, z): the case files' and the 3D runs' axes.
pub const XYZ: Axes<3> = Axes {
    pos: ["pos_x", "pos_y", "pos_z"],
    vel: ["vel_x", "vel_y", "vel_z"],
};
/// The 2D+t plane's axes: y across, z up; velocities v, w.
pub const YZ: Axes<2> = Axes {
    pos: ["pos_y", "pos_z"],
    vel: ["vel_v", "vel_w"],
};

/// Puts the fluid's particles into `c` (every array a restart needs, bit for bit).
pub fn put_fluid<const D: usize>(c: &mut Checkpoint, f: &Fluid<D>, axes: &Axes<D>) {
    for a in 0..D {
        c.arrays
            .insert(axes.pos[a].into(), f.pos.iter().map(|p| p[a]).collect());
        c.arrays
            .insert(axes.vel[a].into(), f.vel.iter().map(|v| v[a]).collect());
    }
    c.arrays.insert("rho".into(), f.rho.clone());
    c.arrays.insert("mass".into(), f.mass.clone());
    c.arrays.insert("id".into(), f.id.iter().map(|&i| i as f64).collect());
    c.arrays.insert("tag".into(), f.tag.clone());
    c.arrays
        .insert("phase".into(), f.phase.iter().map(|&k| k as f64).collect());
}

/// The fluid's particles read from `c` (read from `path`, named in errors). A checkpoint without phases (one
/// written before several phases were possible) holds one phase.
pub fn take_fluid<const D: usize>(c: &Checkpoint, path: &Path, axes: &Axes<D>) -> anyhow::Result<Fluid<D>> {
    let n = c.array(path, "rho", None)?.len();
    let a = |name: &str| c.array(path, name, Some(n));
    let vectors = |names: &[&str; D]| -> anyhow::Result<Vec<SVector<f64, D>>> {
        let cols = names.iter().map(|name| a(name)).collect::<anyhow::Result<Vec<_>>>()?;
        Ok((0..n).map(|i| SVector::from_fn(|k, _| cols[k][i])).collect())
    };
    Ok(Fluid {
        pos: vectors(&axes.pos)?,
        vel: vectors(&axes.vel)?,
        rho: a("rho")?.to_vec(),
        mass: a("mass")?.to_vec(),
        id: a("id")?.iter().map(|&i| i as u32).collect(),
        tag: a("tag")?.to_vec(),
        phase: match c.arrays.contains_key("phase") {
            true => a("phase")?.iter().map(|&k| k as u8).collect(),
            false => vec![0; n],
        },
    })
}

#[derive(Serialize, Deserialize)]
struct Header<P> {
    fingerprint: String,
    #[serde(flatten)]
    clock: Clock,
    progress: P,
}

/// The axes a run of dimension `D` saves under (2D: the plane's x and y, as a case file's).
fn axes<const D: usize>() -> Axes<D> {
    Axes {
        pos: std::array::from_fn(|k| XYZ.pos[k]),
        vel: std::array::from_fn(|k| XYZ.vel[k]),
    }
}

/// Saves the particles, the clock and `progress` to `path` (atomically); `fingerprint` names the configuration.
pub fn save<const D: usize, P: Serialize>(
    path: &Path,
    fingerprint: &str,
    sim: &Simulation<D>,
    progress: &P,
) -> anyhow::Result<()> {
    let mut c = Checkpoint::default();
    put_fluid(&mut c, &sim.fluid, &axes::<D>());
    c.header = serde_json::to_value(Header {
        fingerprint: fingerprint.to_string(),
        clock: sim.clock(),
        progress,
    })?;
    c.write(path)
}

/// Restores the particles and the clock of a checkpoint of the same configuration into `sim` and returns the
/// run's progress; `None` if the file is of another configuration (the run then starts afresh).
pub fn restore<const D: usize, P: DeserializeOwned>(
    path: &Path,
    fingerprint: &str,
    sim: &mut Simulation<D>,
) -> anyhow::Result<Option<P>> {
    let c = Checkpoint::read(path)?;
    let h: Header<P> = serde_json::from_value(c.header.clone())
        .map_err(|e| anyhow::anyhow!("checkpoint {}: header: {e}", path.display()))?;
    if h.fingerprint != fingerprint {
        return Ok(None);
    }
    sim.set_state(h.clock.with(take_fluid(&c, path, &axes::<D>())?));
    Ok(Some(h.progress))
}

/// A saved run's header without its particles: whether it is of `fingerprint`'s configuration, its steps and
/// its progress.
pub fn peek<P: DeserializeOwned>(path: &Path, fingerprint: &str) -> anyhow::Result<(bool, u64, P)> {
    let h: Header<P> = serde_json::from_value(Checkpoint::read_header(path)?)
        .map_err(|e| anyhow::anyhow!("checkpoint {}: header: {e}", path.display()))?;
    Ok((h.fingerprint == fingerprint, h.clock.steps, h.progress))
}

/// The observer that saves a run every `policy.every` of wall time and halts it, saved, at the policy's
/// wall-time or step limit (no policy: it does nothing); `at(t)` says where the run stands, for the halt's
/// message.
pub struct Saver<'a, P> {
    policy: Option<&'a CheckpointPolicy>,
    fingerprint: &'a str,
    state: &'a RefCell<P>,
    wall_before: f64,
    at: &'a dyn Fn(f64) -> String,
    clock: Instant,
    last_save: Instant,
}

impl<'a, P: RunProgress> Saver<'a, P> {
    /// `state` is the run's own progress, saved with the particles; `wall_before` the wall seconds of earlier
    /// sessions.
    pub fn new(
        policy: Option<&'a CheckpointPolicy>,
        fingerprint: &'a str,
        state: &'a RefCell<P>,
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

impl<const D: usize, P: RunProgress> Observer<Simulation<D>> for Saver<'_, P> {
    fn observe(&mut self, sim: &mut Simulation<D>) -> anyhow::Result<Flow> {
        let Some(c) = self.policy else {
            return Ok(Flow::Step);
        };
        let halt = c.deadline.is_some_and(|d| Instant::now() >= d) || c.halt_at_step.is_some_and(|n| sim.steps >= n);
        if halt || self.last_save.elapsed() >= c.every {
            let path = c.path();
            let mut st = self.state.borrow().clone();
            st.set_wall_before(self.wall_before + self.clock.elapsed().as_secs_f64());
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::body_force::BodyForce;
    use crate::sph::solver::SolverConfig;
    use nalgebra::Vector2;

    #[derive(Clone, Serialize, Deserialize)]
    struct Wall(f64);
    impl RunProgress for Wall {
        fn set_wall_before(&mut self, seconds: f64) {
            self.0 = seconds;
        }
    }

    /// Regression: `--wall-limit` was counted from the observer's creation, after the run's set-up (a 10° wedge at
    /// dx/L 5e-4 packed and settled for 8 minutes before it, so it halted 8 minutes late). The limit is now an
    /// instant fixed when the command starts: one that passed during the set-up halts the run at its first step.
    #[test]
    fn a_wall_limit_that_passed_during_the_set_up_halts_at_the_first_step() {
        let dx = 0.1;
        let cfg = SolverConfig::new(dx, 1000.0, 10.0, BodyForce::Uniform(Vector2::zeros()));
        let mut fluid = Fluid::default();
        for i in 0..4 {
            fluid.push(Vector2::new(i as f64 * dx, 0.0), Vector2::zeros(), 1000.0, 10.0, 0.0);
        }
        let mut sim = Simulation::new(cfg, fluid, vec![]);
        let dir = std::env::temp_dir().join(format!("bowwave-deadline-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let policy = |deadline| CheckpointPolicy {
            dir: dir.clone(),
            every: Duration::MAX,
            deadline,
            halt_at_step: None,
        };
        let state = RefCell::new(Wall(0.0));
        let at = |t: f64| format!("t = {t}");
        let passed = policy(Some(Instant::now()));
        std::thread::sleep(Duration::from_millis(5)); // the set-up
        let mut saver = Saver::new(Some(&passed), "f", &state, 0.0, &at);
        assert!(
            matches!(saver.observe(&mut sim).unwrap(), Flow::Halt(_)),
            "the deadline passed: halt"
        );
        assert!(passed.path().exists(), "halted with the state saved");
        let later = policy(Some(Instant::now() + Duration::from_secs(3600)));
        let mut saver = Saver::new(Some(&later), "f", &state, 0.0, &at);
        assert!(
            matches!(saver.observe(&mut sim).unwrap(), Flow::Step),
            "an hour left: step on"
        );
        std::fs::remove_dir_all(&dir).ok();
    }
}
