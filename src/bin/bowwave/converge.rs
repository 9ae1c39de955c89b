//! `converge`: a case at several resolutions, with the observed order and a Richardson estimate.

use crate::options::{halted, CheckpointArgs};
use anyhow::Context;
use bowwave::driver::Ended;
use bowwave::geometry::{hull_file::HullOffsets, surface::HullSurface};
use bowwave::methods::twodt_convergence;
use clap::Args;
use std::path::PathBuf;
use std::sync::Arc;

#[derive(Args)]
pub struct ConvergeArgs {
    /// Built-in case name (see `bowwave cases`), case file, or `twodt` for a 2D+t run of --hull at --fr
    /// at the spacings --dx (its quantities: the jet metrics at the plunge when every run plunges, and
    /// the crest height at the end).
    pub case: String,
    /// Resolutions (reference length / dx), coarse to fine; a constant ratio allows the extrapolation.
    #[arg(long, value_delimiter = ',', default_values_t = vec![20.0, 40.0, 80.0])]
    pub res: Vec<f64>,
    /// End time override (s).
    #[arg(long)]
    pub end: Option<f64>,
    /// twodt: hull offsets file.
    #[arg(long, default_value = "hulls/athena.csv")]
    pub hull: PathBuf,
    /// twodt: fine spacings dx/L, coarse to fine (the thesis's Athena study: 2.7e-4,1.9e-4,1.35e-4). Each
    /// runs in OUT/dx-*: the same command run again reuses finished spacings (their converge_run.json) and
    /// goes on with a halted one from its checkpoint.
    #[arg(long, value_delimiter = ',', default_values_t = vec![3e-3, 2e-3, 1.333e-3])]
    pub dx: Vec<f64>,
    /// twodt: gather finished `bowwave twodt` runs (their folders, coarse to fine, comma separated)
    /// instead of running the ladder.
    #[arg(long, value_delimiter = ',')]
    pub runs: Vec<PathBuf>,
    /// twodt: checkpoints of the running spacing (OUT/dx-*), and when to stop saved; the same command run
    /// again goes on, reusing finished spacings (OUT/dx-*/converge_run.json).
    #[command(flatten)]
    pub checkpoint: CheckpointArgs,
    /// The options of each 2D+t run (as `bowwave twodt`'s).
    #[command(flatten, next_help_heading = "2D+t options (converge twodt)")]
    pub config: bowwave::twodt::config::TwoDtConfig,
    /// Output folder for converge.csv and, for twodt, one folder per spacing (default out/converge-CASE).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

impl ConvergeArgs {
    /// Prints the convergence table and writes converge.csv; exit status 3 when a 2D+t ladder halted with a
    /// checkpoint.
    pub fn run(self) -> anyhow::Result<std::process::ExitCode> {
        let (conv, out) = if self.case == "twodt" && !self.runs.is_empty() {
            let out = self
                .out
                .unwrap_or_else(|| PathBuf::from("out").join("converge-twodt-runs"));
            (twodt_convergence::converge_finished(&self.runs)?, out)
        } else if self.case == "twodt" {
            let offsets = HullOffsets::read(&self.hull)?;
            let surface = Arc::new(HullSurface::new(&offsets));
            let base = self.config;
            base.check()?;
            let fr = base.fr;
            let out = self
                .out
                .unwrap_or_else(|| PathBuf::from("out").join(format!("converge-twodt-{}-fr{fr}", offsets.meta.name)));
            let policy = self.checkpoint.passage_policy(true)?;
            match twodt_convergence::converge_twodt(surface, &base, &self.dx, &out, &policy, true)? {
                Ended::Ran(conv) => (conv, out),
                Ended::Halted(h) => return Ok(halted(&h)),
            }
        } else {
            let c = bowwave::cases::load(&self.case)?;
            let out = self
                .out
                .unwrap_or_else(|| PathBuf::from("out").join(format!("converge-{}", c.name)));
            (bowwave::methods::convergence::converge(&c, &self.res, self.end)?, out)
        };
        print!("{}", conv.report());
        std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
        bowwave::io::atomic::write_atomic(&out.join("converge.csv"), conv.csv().as_bytes())?;
        println!("table in {}", out.join("converge.csv").display());
        Ok(std::process::ExitCode::SUCCESS)
    }
}
