//! `ship`: the 3D mode's ship in steady forward motion, beside its 2D+t solution (issue #31).

use crate::options::{halted, CheckpointArgs, BLEW_UP};
use bowwave::compare3d::towed_ship::{self, TowOptions, TowedShip};
use bowwave::driver::Ended;
use bowwave::geometry::{hull_file::HullOffsets, surface::HullSurface};
use bowwave::io::atomic::write_atomic;
use clap::Args;
use std::path::PathBuf;
use std::process::ExitCode;

#[derive(Args)]
pub struct ShipArgs {
    /// Hull offsets file (CSV, see docs/reference/hull-format.md); the Wigley hull's exact form by default.
    #[arg(long, default_value = "hulls/wigley.csv")]
    pub hull: PathBuf,
    /// Froude number U/√(gL).
    #[arg(long, default_value_t = 0.5)]
    pub fr: f64,
    #[command(flatten)]
    pub tow: TowOptions,
    /// Write ParaView frames every this many L travelled (OUT/vtk: fluid_NNNN.vtp with velocity, pressure and
    /// density, hull_NNNN.vtp the hull's surface, indexed by fluid.pvd and hull.pvd; Earth frame, the hull moving
    /// along −x). 0: none.
    #[arg(long, default_value_t = 0.0)]
    pub vtk_every: f64,
    /// A `bowwave twodt` output folder of the same hull and Froude number (its eta.csv): the 2D+t map is drawn
    /// beside the 3D one, their difference mapped, and the stretches of x/L where they agree within 0.1 D printed.
    /// Run it at the same spacing: `bowwave twodt --hull H --fr F --dx (D/L)/res --ratio 1 --until transom`.
    #[arg(long)]
    pub twodt: Option<PathBuf>,
    #[command(flatten)]
    pub checkpoint: CheckpointArgs,
    /// Output folder (default out/ship-NAME-frF-resR).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Build the scene and print its particles, hull ghosts, c0 and the steps and time to the shortest and the
    /// longest travel (at the throughput of the first towed run), and run nothing.
    #[arg(long)]
    pub dry_run: bool,
    /// No progress bars.
    #[arg(short, long)]
    pub quiet: bool,
}

impl ShipArgs {
    pub fn run(self) -> anyhow::Result<ExitCode> {
        let offsets = HullOffsets::read(&self.hull)?;
        let name = offsets.meta.name.clone();
        let hull = HullSurface::new(&offsets);
        // The 2D+t map first: a wrong folder fails before an hour of 3D.
        let twodt = self.twodt.as_deref().map(towed_ship::read_twodt_eta).transpose()?;
        if let Some((key, expected)) = self.tow.check() {
            anyhow::bail!("--{}: expected {expected}", key.replace('_', "-"));
        }
        let mut opts = TowedShip::with_options(hull.clone(), self.fr, &self.tow);
        anyhow::ensure!(
            self.vtk_every.is_finite() && self.vtk_every >= 0.0,
            "--vtk-every: expected a distance in L ≥ 0 (0: no frames), got {}",
            self.vtk_every
        );
        if self.dry_run {
            let p = towed_ship::plan(&opts)?;
            let rate = towed_ship::MEASURED_THROUGHPUT;
            let hours = |steps: f64| p.particles as f64 * steps / rate / 3600.0;
            println!(
                "{name}, Fr {}, D/dx {}: {} particles, {} hull ghosts, about {:.2} GiB, c0 {:.2} √(gL); {:.0} steps to {} L \
                 travelled (about {:.1} h), {:.0} to {} L ({:.1} h), at {rate:.2e} particle-steps/s (2 threads, measured)",
                self.fr,
                self.tow.res,
                p.particles,
                p.hull_ghosts,
                p.particles as f64 * bowwave::compare3d::ship::BYTES_PER_PARTICLE / 1024f64.powi(3),
                p.c0_over_sqrt_gl,
                p.steps_min,
                self.tow.min_travel,
                hours(p.steps_min),
                p.steps_max,
                self.tow.travel,
                hours(p.steps_max)
            );
            return Ok(ExitCode::SUCCESS);
        }
        let out = self
            .out
            .unwrap_or_else(|| PathBuf::from(format!("out/ship-{name}-fr{}-res{}", self.fr, self.tow.res)));
        std::fs::create_dir_all(&out).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", out.display()))?;
        if self.vtk_every > 0.0 {
            let dir = out.join("vtk");
            std::fs::create_dir_all(&dir).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", dir.display()))?;
            opts.frames = Some(towed_ship::Frames {
                dir,
                every_over_l: self.vtk_every,
            });
        }
        let manifest = towed_ship::manifest(&opts, &self.hull, &offsets)?;
        write_atomic(&out.join("manifest.json"), manifest.as_bytes())?;
        opts.checkpoint = self.checkpoint.policy(&out)?;
        let r = match towed_ship::run(&opts, !self.quiet)? {
            Ended::Ran(r) => r,
            Ended::Halted(h) => return Ok(halted(&h)),
        };
        let x_end = hull.x_range.1 - hull.x_range.0;
        let c = twodt.as_ref().map(|f| towed_ship::compare(&r.eta, f, self.fr, x_end));
        for (file, t) in towed_ship::tables(&r, twodt.as_ref().zip(c.as_ref())) {
            let path = out.join(file);
            t.write(&path)
                .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", path.display()))?;
        }
        towed_ship::plots(&r, twodt.as_ref().zip(c.as_ref()), &out)?;
        let text = towed_ship::summary(&r, c.as_ref());
        write_atomic(&out.join("summary.txt"), text.as_bytes())?;
        print!("{text}");
        println!("written: {}", out.display());
        Ok(if r.blow_up.is_some() {
            ExitCode::from(BLEW_UP)
        } else {
            ExitCode::SUCCESS
        })
    }
}
