//! `bent-wall`: the bent-wall channel of thesis §10.2.1 in 2D+t (the plate of eq. 10.8's cut), and
//! `bent-wall-3d`: the same channel in 3D beside it.

use crate::options::{halted, CheckpointArgs, BLEW_UP};
use bowwave::compare3d::bent_wall::{run, summary, write_outputs, BentWallOptions};
use bowwave::compare3d::bent_wall_3d::{self, Tow3dOptions};
use bowwave::driver::Ended;
use clap::Args;
use std::path::PathBuf;
use std::process::ExitCode;

/// The channel, the same for both models.
#[derive(Args)]
pub struct ChannelArgs {
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
    /// Sound speed c0/sqrt(gH) (default: 10 times the expected largest speed, 2.5 times the plate's fastest
    /// wetted point).
    #[arg(long)]
    pub c0: Option<f64>,
}

impl ChannelArgs {
    fn options(&self, res: f64) -> BentWallOptions {
        BentWallOptions {
            fr_h: self.fr_h,
            length: self.length,
            width: self.width,
            res,
            c0: self.c0,
            ..Default::default()
        }
    }
}

#[derive(Args)]
pub struct BentWallArgs {
    #[command(flatten)]
    pub channel: ChannelArgs,
    /// Resolution H/dx.
    #[arg(long, default_value_t = 20.0)]
    pub res: f64,
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
            s_end: self.until,
            stop_at_plunge: !self.past_plunge,
            frames: self.frames,
            ..self.channel.options(self.res)
        };
        opts.check()?;
        let out = self
            .out
            .unwrap_or_else(|| PathBuf::from(format!("out/bent-wall-fr{}-res{}", opts.fr_h, opts.res)));
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

#[derive(Args)]
pub struct BentWall3dArgs {
    #[command(flatten)]
    pub channel: ChannelArgs,
    /// Resolution H/dx, the same for the 3D run and its 2D+t analogue (6: 61 016 particles and 27 927 wall
    /// ghosts at the default channel; `--dry-run` says what another costs).
    #[arg(long, default_value_t = 6.0)]
    pub res: f64,
    /// The wall accelerates from rest to U over this distance, in H (a smooth ramp).
    #[arg(long, default_value_t = Tow3dOptions::default().ramp)]
    pub ramp: f64,
    /// Distance travelled beyond L + ramp before the run stops, in H: from L + ramp on every cut of the bent part
    /// has seen only the steadily moving wall.
    #[arg(long, default_value_t = Tow3dOptions::default().settle)]
    pub settle: f64,
    /// Water ahead of the bent part's start at the end of the run, in H.
    #[arg(long, default_value_t = Tow3dOptions::default().ahead)]
    pub ahead: f64,
    /// Water behind the bent part's end at the start, in H.
    #[arg(long, default_value_t = Tow3dOptions::default().behind)]
    pub behind: f64,
    /// Height of the wall above the floor, in H (water climbing higher passes over its top edge).
    #[arg(long, default_value_t = Tow3dOptions::default().top)]
    pub top: f64,
    /// Distance travelled between two samples of the crest's history, in H.
    #[arg(long, default_value_t = Tow3dOptions::default().sample)]
    pub sample: f64,
    #[command(flatten)]
    pub checkpoint: CheckpointArgs,
    /// Output folder for bent_wall_3d.csv (the cuts, 3D beside 2D+t), bent_wall_3d_history.csv,
    /// bent_wall_3d_eta.csv, bent_wall_3d.json, bent_wall_3d_heights.png and bent_wall_3d_eta.png (default out/bent-wall-3d-frF-resN).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Build the scene, print its particles, wall ghosts and the steps and time the run will take, run nothing.
    #[arg(long)]
    pub dry_run: bool,
    /// No progress bar.
    #[arg(short, long)]
    pub quiet: bool,
}

impl BentWall3dArgs {
    /// Exit status 0, 2 when the run blew up (its outputs are kept), 3 when it stopped with its state saved.
    pub fn run(self) -> anyhow::Result<ExitCode> {
        let ch = self.channel.options(self.res);
        let o = Tow3dOptions {
            ramp: self.ramp,
            settle: self.settle,
            ahead: self.ahead,
            behind: self.behind,
            top: self.top,
            sample: self.sample,
        };
        ch.check()?;
        o.check()?;
        if self.dry_run {
            let (particles, ghosts, steps) = bent_wall_3d::plan(&ch, &o)?;
            let rate = bowwave::compare3d::towed_ship::MEASURED_THROUGHPUT;
            println!(
                "bent wall 3D, Fr_H {}, L/H {}, W/H {}, H/dx {}: {particles} particles, {ghosts} wall ghosts, about \
                 {steps:.0} steps, {:.2} h at {rate:.1e} particle-steps/s (the towed ship's, 2 threads)",
                ch.fr_h,
                ch.length,
                ch.width,
                ch.res,
                particles as f64 * steps / rate / 3600.0
            );
            return Ok(ExitCode::SUCCESS);
        }
        let out = self
            .out
            .unwrap_or_else(|| PathBuf::from(format!("out/bent-wall-3d-fr{}-res{}", ch.fr_h, ch.res)));
        std::fs::create_dir_all(&out).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", out.display()))?;
        let policy = self.checkpoint.policy(&out)?;
        let r = match bent_wall_3d::run(&ch, &o, policy.as_ref(), !self.quiet)? {
            Ended::Ran(r) => r,
            Ended::Halted(h) => return Ok(halted(&h)),
        };
        bent_wall_3d::write_outputs(&r, &out)?;
        print!("{}", bent_wall_3d::summary(&r));
        println!("written: {}", out.display());
        Ok(if r.stopped.is_some() {
            ExitCode::from(BLEW_UP)
        } else {
            ExitCode::SUCCESS
        })
    }
}
