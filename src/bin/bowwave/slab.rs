//! `slab`: the dam break in 2D and as a 3D slab at the same spacing (the 3D comparison mode's first case).

use crate::options::GhostsArg;
use bowwave::compare3d::slab::{compare, SlabOptions};
use clap::Args;
use std::path::PathBuf;

#[derive(Args)]
pub struct SlabArgs {
    /// Resolution H/dx of both runs.
    #[arg(long, default_value_t = 20.0)]
    pub res: f64,
    /// Slab width in particle spacings: the 3D run has this many times the 2D run's particles, each with about 5
    /// times the neighbours. The side walls are free-slip, so any width is the same 2D flow; narrower is cheaper.
    #[arg(long, default_value_t = 6)]
    pub width: usize,
    /// End time in t sqrt(g/H) (the front meets the wall at about 2.4; P1 and P2 are compared after that).
    #[arg(long, default_value_t = 3.0)]
    pub end: f64,
    /// Ghosts of the tank's faces in both runs: `fixed` (thesis §7.1.1, the default) or `images`.
    #[arg(long, value_enum, default_value = "fixed")]
    pub ghosts: GhostsArg,
    /// Sampling interval in t sqrt(g/H).
    #[arg(long, default_value_t = 0.01)]
    pub every: f64,
    /// CFL number of both runs (default: the integrator's, RK4 2.0).
    #[arg(long)]
    pub cfl: Option<f64>,
    /// Output folder for slab.csv, slab_front.png and slab_pressure.png (default out/slab-resN).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// No progress bars.
    #[arg(short, long)]
    pub quiet: bool,
}

impl SlabArgs {
    pub fn run(self) -> anyhow::Result<()> {
        let opts = SlabOptions {
            res: self.res,
            width_cells: self.width,
            end: self.end,
            ghosts: self.ghosts.into(),
            every: self.every,
            cfl: self.cfl,
        };
        let c = compare(&opts, !self.quiet)?;
        let out = self
            .out
            .unwrap_or_else(|| PathBuf::from(format!("out/slab-res{}", self.res)));
        std::fs::create_dir_all(&out).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", out.display()))?;
        let csv = out.join("slab.csv");
        c.table()
            .write(&csv)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", csv.display()))?;
        bowwave::compare3d::slab::write_plots(&c, &out)?;
        println!("{}", bowwave::compare3d::slab::summary(&c));
        println!(
            "written: {} (slab.csv, slab_front.png, slab_pressure.png)",
            out.display()
        );
        Ok(())
    }
}
