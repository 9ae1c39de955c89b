//! `twodt` (one hull at one Froude number, from the stem to the plunge) and `wedge` (the 2D+t machinery
//! against a rigid wedge entry and Wagner theory).

use crate::options::{checkpoint_policy, exit_if_halted};
use bowwave::geometry::{hull_file::HullOffsets, surface::HullSurface};
use bowwave::sph::density_diffusion::DensityDiffusion;
use bowwave::twodt;
use clap::{Args, ValueEnum};
use std::path::PathBuf;
use std::sync::Arc;

/// `--diffusion`: the CLI's names for [`DensityDiffusion`].
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum DiffusionArg {
    DeltaSph,
    MolteniColagrossi,
    None,
}

impl From<DiffusionArg> for DensityDiffusion {
    fn from(d: DiffusionArg) -> Self {
        match d {
            DiffusionArg::DeltaSph => Self::DeltaSph,
            DiffusionArg::MolteniColagrossi => Self::MolteniColagrossi,
            DiffusionArg::None => Self::None,
        }
    }
}

/// `--packing`: `auto` leaves the choice to the scene ([`twodt::scene::TwoDtConfig::packing`]).
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum PackingArg {
    Auto,
    On,
    Off,
}

#[derive(Args)]
pub struct TwodtArgs {
    /// Hull offsets file (CSV, see docs/hull-format.md).
    #[arg(long, default_value = "hulls/athena.csv")]
    pub hull: PathBuf,
    /// Ship Froude number U/sqrt(g L).
    #[arg(long, default_value_t = 0.5)]
    pub fr: f64,
    /// Fine particle spacing dx/L near the free surface (default: from H_pj/dx > 20, eq. 10.9, with the
    /// bow-wave height estimated from Table 10.1 of the thesis).
    #[arg(long)]
    pub dx: Option<f64>,
    /// Coarse spacing below the transition, as a multiple of dx, in [1, 4] (constant h; 1 = uniform). Default 1.5,
    /// packed: 42 % fewer particles for the same crest within 0.5 % (docs/twodt.md).
    #[arg(long, default_value_t = 1.5)]
    pub ratio: f64,
    /// Density diffusion: delta-sph (eq. 5.2, the default), molteni-colagrossi (5.4) or none (standard
    /// WCSPH), for method comparisons.
    #[arg(long, value_enum, default_value_t = DiffusionArg::DeltaSph)]
    pub diffusion: DiffusionArg,
    /// Evaluate the Gaussian kernel's gradient at every pair instead of from its table in r² (the default
    /// table changes positions by ~1e-6 dx and saves 10–25 % of the CPU; docs/speed-accuracy.md).
    #[arg(long)]
    pub exact_kernel: bool,
    /// Pack the initial particles (thesis chapter 6: move them along −∇Γ inside the tank closed by a lid
    /// at the calm level, the upper half of the fine layer held) before the damped settling: auto (when
    /// --ratio > 1: graded rows relax with 1e-5 M g D of spurious flow otherwise), on, or off.
    #[arg(long, value_enum, default_value_t = PackingArg::Auto)]
    pub packing: PackingArg,
    /// Domain width W as a multiple of the beam B (thesis §10.1.2: 4).
    #[arg(long, default_value_t = 4.0)]
    pub width: f64,
    /// Water depth Z as a multiple of the draft D (thesis §10.1.2 and appendix D: 2).
    #[arg(long, default_value_t = 2.0)]
    pub depth: f64,
    /// Where to stop: `plunge` (shortly after it), `transom`, or an x/L value (e.g. 1.3 for stern waves).
    #[arg(long, default_value = "plunge")]
    pub until: String,
    /// With `--until plunge`: the x/L at which to give up if nothing has plunged (default: the transom).
    #[arg(long)]
    pub give_up_at: Option<f64>,
    /// Sound speed / sqrt(g L) (default: 10 × the expected largest velocity).
    #[arg(long)]
    c0: Option<f64>,
    /// Free-surface detection and plunge check every N steps.
    #[arg(long, default_value_t = 10)]
    pub detect_every: usize,
    /// Optional extra plunge criterion (ours, not the issue's; off by default): a closed air cavity counts
    /// as the plunge only if its lowest point lies below this fraction of the crest height, e.g. 0.5 to
    /// keep folds high in a sheet out (docs/jet-metrics.md).
    #[arg(long)]
    pub plunge_depth: Option<f64>,
    /// Plunge criterion 5: a closed air cavity counts as the plunge only if the circulation around it,
    /// Γ/(U D), is at least this (clockwise positive, the sense of a jet overturning away from the hull);
    /// it keeps out slivers of air between particle rows of the sheet climbing the hull, whose Γ is
    /// near zero (docs/jet-metrics.md).
    #[arg(long, default_value_t = 0.02)]
    pub plunge_circulation: f64,
    /// Switch plunge criterion 5 (--plunge-circulation) off.
    #[arg(long)]
    pub no_circulation_check: bool,
    /// x/L between outputs (series row, η profile, VTK frame).
    #[arg(long, default_value_t = 0.005)]
    pub output_dx: f64,
    /// Output folder (default: out/twodt-HULL-frFR).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Write VTK frames (.vtp + .pvd).
    #[arg(long)]
    pub vtk: bool,
    /// x/L of the section at the start (default: the stem). A value before the stem runs the tank alone
    /// until the stem arrives.
    #[arg(long)]
    x0: Option<f64>,
    /// Damped settling before the ship starts, in acoustic crossings of the depth (Z/c0).
    #[arg(long, default_value_t = 1.0)]
    pub settle: f64,
    /// Write a PNG of the bow region at every output.
    #[arg(long)]
    pub frames: bool,
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
    /// Runs the case and prints its metrics; exits with status 2 after a blow-up, 3 when halted with a
    /// checkpoint.
    pub fn run(self) -> anyhow::Result<()> {
        let offsets = HullOffsets::read(&self.hull)?;
        let surface = Arc::new(HullSurface::new(&offsets));
        if let Some(f) = self.plunge_depth.filter(|f| !(f.is_finite() && *f > 0.0)) {
            anyhow::bail!("--plunge-depth {f}: expected a positive fraction of the crest height");
        }
        if !self.plunge_circulation.is_finite() {
            anyhow::bail!(
                "--plunge-circulation {}: expected a finite Γ/(U D)",
                self.plunge_circulation
            );
        }
        let fr = self.fr;
        let cfg = twodt::scene::TwoDtConfig {
            fr,
            dx: self.dx,
            coarse_ratio: self.ratio,
            width_over_beam: self.width,
            depth_over_draft: self.depth,
            diffusion: self.diffusion.into(),
            kernel_table: !self.exact_kernel,
            packing: match self.packing {
                PackingArg::Auto => None,
                PackingArg::On => Some(true),
                PackingArg::Off => Some(false),
            },
            until: self.until.parse().map_err(anyhow::Error::msg)?,
            give_up_at: self.give_up_at,
            c0: self.c0,
            detect_every: self.detect_every,
            plunge_depth: self.plunge_depth,
            plunge_circulation: (!self.no_circulation_check).then_some(self.plunge_circulation),
            output_dx: self.output_dx,
            x0: self.x0,
            settle_crossings: self.settle,
            ..Default::default()
        };
        let out = self
            .out
            .unwrap_or_else(|| PathBuf::from("out").join(format!("twodt-{}-fr{fr}", offsets.meta.name)));
        let opts = twodt::run::TwoDtOptions {
            out_dir: out.clone(),
            progress: !self.quiet,
            vtk: self.vtk,
            plots: true,
            frames: self.frames,
            multi: None,
            label: String::new(),
            checkpoint: checkpoint_policy(self.checkpoint_every, self.wall_limit, !self.fresh)?,
        };
        let r = exit_if_halted(twodt::run::run(surface, &cfg, &opts))?;
        twodt::report::print(&r, &out);
        if r.blowup.is_some() {
            std::process::exit(2);
        }
        Ok(())
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
