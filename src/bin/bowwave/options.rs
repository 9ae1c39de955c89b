//! Options and exit conventions shared by several subcommands.

/// `--ghosts`: the CLI's names for [`bowwave::sph::polyline_wall::GhostKind`].
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
pub enum GhostsArg {
    Fixed,
    Images,
    NormalFlux,
}

impl From<GhostsArg> for bowwave::sph::polyline_wall::GhostKind {
    fn from(g: GhostsArg) -> Self {
        match g {
            GhostsArg::Fixed => Self::Fixed,
            GhostsArg::Images => Self::Images,
            GhostsArg::NormalFlux => Self::NormalFlux,
        }
    }
}

/// A duration given in minutes on the command line: `None` for 0; an error naming the option otherwise.
pub fn minutes(option: &str, m: f64) -> anyhow::Result<Option<std::time::Duration>> {
    if !(m.is_finite() && m >= 0.0) {
        anyhow::bail!("{option} {m}: expected a number of minutes, 0 or more");
    }
    if m == 0.0 {
        return Ok(None);
    }
    std::time::Duration::try_from_secs_f64(60.0 * m)
        .map(Some)
        .map_err(|_| anyhow::anyhow!("{option} {m}: expected a number of minutes a clock can hold, at most about 3e17"))
}

/// `--checkpoint-every` and `--wall-limit`, the same for every command whose runs save themselves in their
/// folders (`twodt`, `study`, `converge twodt`, `ship`, `bent-wall-3d`, `wedge`).
#[derive(clap::Args)]
pub struct CheckpointArgs {
    /// Minutes of wall time between checkpoints (checkpoint.bin in the run's folder: a study's case, a
    /// ladder's spacing; 0: none). The same command run again goes on from the checkpoint, to the same bits.
    #[arg(long, default_value_t = 10.0)]
    pub checkpoint_every: f64,
    /// Stop after this many minutes of wall time, counted from the command's start (a study's cases share
    /// them; a case whose turn comes later is not started), with the state saved (exit status 3); run the same
    /// command again to go on.
    #[arg(long)]
    pub wall_limit: Option<f64>,
}

impl CheckpointArgs {
    /// The time between checkpoints and the wall-time limit, each `None` when not asked for.
    pub fn limits(&self) -> anyhow::Result<(Option<std::time::Duration>, Option<std::time::Duration>)> {
        let every = minutes("--checkpoint-every", self.checkpoint_every)?;
        let wall_limit = self
            .wall_limit
            .map(|w| minutes("--wall-limit", w))
            .transpose()?
            .flatten();
        Ok((every, wall_limit))
    }

    /// The policy of a 2D+t passage (`twodt`, `study`, `converge twodt`), which saves in its output folder;
    /// `resume`: go on from a checkpoint found there.
    pub fn passage_policy(&self, resume: bool) -> anyhow::Result<bowwave::twodt::checkpoint::CheckpointPolicy> {
        let (every, wall_limit) = self.limits()?;
        Ok(bowwave::twodt::checkpoint::CheckpointPolicy {
            every,
            resume,
            deadline: bowwave::driver::checkpoint::deadline(wall_limit),
            halt_at_step: None,
        })
    }

    /// The policy saving into `dir`; `None` when neither option asks for one.
    pub fn policy(
        &self,
        dir: &std::path::Path,
    ) -> anyhow::Result<Option<bowwave::driver::checkpoint::CheckpointPolicy>> {
        let (every, wall_limit) = self.limits()?;
        Ok(
            (every.is_some() || wall_limit.is_some()).then(|| bowwave::driver::checkpoint::CheckpointPolicy {
                dir: dir.to_path_buf(),
                every: every.unwrap_or(std::time::Duration::MAX),
                deadline: bowwave::driver::checkpoint::deadline(wall_limit),
                halt_at_step: None,
            }),
        )
    }
}

/// Exit status of a run that blew up (its outputs and diagnosis kept).
pub const BLEW_UP: u8 = 2;

/// A run stopped on purpose with its state saved is not a failure: says where it stopped and gives exit
/// status 3, which tells a batch script to submit it again.
pub fn halted(h: &bowwave::driver::Halted) -> std::process::ExitCode {
    eprintln!("{h}");
    std::process::ExitCode::from(3)
}

/// A kinematic viscosity given on the command line (`--nu`): finite and positive, in m²/s.
pub fn viscosity_nu(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(nu) if nu.is_finite() && nu > 0.0 => Ok(nu),
        _ => Err(format!(
            "expected a positive kinematic viscosity in m²/s (e.g. 1.456e-4), got `{s}`"
        )),
    }
}
