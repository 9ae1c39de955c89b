//! `twodt` (one hull at one Froude number, from the stem to the plunge) and `wedge` (the 2D+t machinery
//! against a rigid wedge entry and Wagner theory).

use crate::options::{checkpoint_policy, halted, BLEW_UP};
use bowwave::driver::Ended;
use bowwave::geometry::{hull_file::HullOffsets, surface::HullSurface};
use bowwave::twodt;
use clap::Args;
use std::path::PathBuf;
use std::sync::Arc;

#[derive(Args)]
pub struct TwodtArgs {
    /// Hull offsets file (CSV, see docs/reference/hull-format.md).
    #[arg(long, default_value = "hulls/athena.csv")]
    pub hull: PathBuf,
    /// Fine particle spacing dx/L near the free surface (default: from H_pj/dx > 20, eq. 10.9, with the
    /// bow-wave height estimated from Table 10.1 of the thesis).
    #[arg(long)]
    pub dx: Option<f64>,
    /// Every option of the case (the same keys as a study file's `[config]`, docs/reference/studies.md).
    #[command(flatten)]
    pub config: twodt::config::TwoDtConfig,
    /// Output folder (default: out/twodt-HULL-frFR).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Minutes of wall time between checkpoints (OUT/checkpoint.bin: the particles and the run's state;
    /// 0: none). A run started again with the same options goes on from its checkpoint, to the same bits.
    #[arg(long, default_value_t = 10.0)]
    pub checkpoint_every: f64,
    /// Stop after this many minutes of wall time, saving a checkpoint (a batch job's time limit); run
    /// the same command again to go on.
    #[arg(long)]
    pub wall_limit: Option<f64>,
    /// Ignore a checkpoint in the output folder and start from the beginning.
    #[arg(long)]
    pub fresh: bool,
    /// No progress bar.
    #[arg(long, short)]
    pub quiet: bool,
}

impl TwodtArgs {
    /// Runs the case and prints its metrics; exit status 2 after a blow-up, 3 when halted with a checkpoint.
    pub fn run(self) -> anyhow::Result<std::process::ExitCode> {
        let offsets = HullOffsets::read(&self.hull)?;
        let surface = Arc::new(HullSurface::new(&offsets));
        let cfg = twodt::config::TwoDtConfig {
            dx: self.dx,
            ..self.config
        };
        cfg.check()?;
        let fr = cfg.fr;
        let out = self
            .out
            .unwrap_or_else(|| PathBuf::from("out").join(format!("twodt-{}-fr{fr}", offsets.meta.name)));
        let opts = twodt::run::TwoDtOptions {
            out_dir: out.clone(),
            progress: !self.quiet,
            plots: true,
            multi: None,
            label: format!("{} Fr {fr} ", offsets.meta.name),
            checkpoint: checkpoint_policy(self.checkpoint_every, self.wall_limit, !self.fresh)?,
        };
        let r = match twodt::run::run(surface, &cfg, &opts)? {
            Ended::Ran(r) => r,
            Ended::Halted(h) => return Ok(halted(&h)),
        };
        twodt::report::print(&r, &out);
        Ok(if r.blowup.is_some() {
            std::process::ExitCode::from(BLEW_UP)
        } else {
            std::process::ExitCode::SUCCESS
        })
    }
}

#[derive(Args)]
pub struct WedgeArgs {
    /// Particle spacing dx/L (the penetration at the end is 0.03 L).
    #[arg(long, default_value_t = 5e-4)]
    pub dx: f64,
    /// Deadrise angle in degrees.
    #[arg(long, default_value_t = 30.0)]
    pub deadrise: f64,
}

impl WedgeArgs {
    pub fn run(self) -> anyhow::Result<()> {
        let spec = twodt::wedge::WedgeSpec {
            dx: self.dx,
            deadrise_deg: self.deadrise,
            ..Default::default()
        };
        let c = twodt::wedge::compare(&spec, &[0.01, 0.02, 0.03])?;
        twodt::wedge::print(&c);
        Ok(())
    }
}
