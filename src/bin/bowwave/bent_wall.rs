//! `bent-wall`: the bent-wall channel of thesis §10.2.1 in 2D+t (the plate of eq. 10.8's cut).

use bowwave::compare3d::bent_wall::{run, summary, write_outputs, BentWallOptions};
use clap::Args;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct BentWallArgs {
    /// Froude number of the stream, U/sqrt(gH), H the water depth (ours: the thesis does not print it).
    #[arg(long, default_value_t = 2.0)]
    pub fr_h: f64,
    /// L/H, the bent wall's length along the channel (the thesis does not print it; ours: 12).
    #[arg(long, default_value_t = 12.0)]
    pub length: f64,
    /// W/H, the channel's width, the straight side wall's distance from the wall's start (ours: 10; the foot
    /// ends at L/4).
    #[arg(long, default_value_t = 10.0)]
    pub width: f64,
    /// Resolution H/dx.
    #[arg(long, default_value_t = 20.0)]
    pub res: f64,
    /// Sound speed c0/sqrt(gH) (default: 10 times the expected largest speed, 2.5 times the plate's fastest
    /// wetted point).
    #[arg(long)]
    pub c0: Option<f64>,
    /// Run until this fraction of the wall's length has passed (1: its end; at most 2: past its end the
    /// channel's side goes on as the wall's last cut, a 45-degree wall).
    #[arg(long, default_value_t = 1.0)]
    pub until: f64,
    /// Go on after the first closed cavity (the plunge) instead of stopping there.
    #[arg(long)]
    pub past_plunge: bool,
    /// ParaView frames per passage of the wall, into OUT/frames (0: none).
    #[arg(long, default_value_t = 20)]
    pub frames: usize,
    /// Output folder for bent_wall.csv, bent_wall.json, bent_wall_heights.png and frames/ (default
    /// out/bent-wall-frF-resN).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
}

impl BentWallArgs {
    /// Exit status 0, or 2 when the run blew up (its outputs are kept).
    pub fn run(self) -> anyhow::Result<ExitCode> {
        let opts = BentWallOptions {
            fr_h: self.fr_h,
            length: self.length,
            width: self.width,
            res: self.res,
            c0: self.c0,
            s_end: self.until,
            stop_at_plunge: !self.past_plunge,
            frames: self.frames,
        };
        opts.check()?;
        let out = self
            .out
            .unwrap_or_else(|| PathBuf::from(format!("out/bent-wall-fr{}-res{}", self.fr_h, self.res)));
        let frames = out.join("frames");
        let dir = if self.frames > 0 { &frames } else { &out };
        std::fs::create_dir_all(dir).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", dir.display()))?;
        let r = run(&opts, (self.frames > 0).then_some(frames.as_path()), !self.quiet)?;
        write_outputs(&r, &out)?;
        print!("{}", summary(&r));
        println!(
            "written: {} (bent_wall.csv, bent_wall.json, bent_wall_heights.png)",
            out.display()
        );
        Ok(if r.stopped.is_some() {
            ExitCode::from(2)
        } else {
            ExitCode::SUCCESS
        })
    }
}
