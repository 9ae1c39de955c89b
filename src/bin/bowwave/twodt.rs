//! `twodt` (one hull at one Froude number, from the stem to the plunge) and `wedge` (the 2D+t machinery
//! against a rigid wedge entry and Wagner theory).

use crate::options::{halted, CheckpointArgs, BLEW_UP};
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
    /// Checkpoints in OUT (the particles and the passage's state), and when to stop saved.
    #[command(flatten)]
    pub checkpoint: CheckpointArgs,
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
            checkpoint: self.checkpoint.passage_policy(!self.fresh)?,
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
    /// Particle spacings dx/L, comma separated (the penetration at the end is 0.03 L); three in a constant
    /// ratio give the observed order of each error.
    #[arg(long, value_delimiter = ',', default_values_t = vec![5e-4])]
    pub dx: Vec<f64>,
    /// Deadrise angles in degrees, comma separated (the similarity solution is on record at 10, 20 and 30).
    #[arg(long, value_delimiter = ',', default_values_t = vec![30.0])]
    pub deadrise: Vec<f64>,
    /// Sound speed: `root` (10 × Wagner's spray-root speed V π/(2 tanβ), Mach ≤ 0.1 at the root) or `scene`
    /// (the 2D+t scene's rule, from w_n: fast but compressible at the root below 30°).
    #[arg(long, default_value = "root")]
    pub c0: String,
    /// Penetrations Vt/L at which the runs are sampled, comma separated (at most 0.03, the wedge's draft).
    #[arg(long, value_delimiter = ',', default_values_t = vec![0.01, 0.02, 0.03])]
    pub at: Vec<f64>,
    /// Water depth as a multiple of the wedge's draft 0.03 L (the similarity solution is for infinite depth:
    /// at 2, the scene's default, the bottom lies 2 Vt below the apex at the last default sample).
    #[arg(long, default_value_t = 2.0)]
    pub depth: f64,
    /// Particle shifting after each step: sun2017-walls (within two kernel supports of a wall,
    /// away from the free surface), sun2017-leaving (the default: that band only where the flow leaves a wall), sun2017
    /// (everywhere) or none (docs/reference/method.md).
    #[arg(long, default_value_t = bowwave::sph::particle_shifting::ParticleShifting::default())]
    pub shifting: bowwave::sph::particle_shifting::ParticleShifting,
    /// Write wedge.csv (every sample of every run) and the pressure profiles into this folder; each run saves
    /// itself in its own folder under OUT/runs (a checkpoint while it runs, its samples once finished), so the
    /// same command run again skips finished runs and goes on with the one in progress.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// With `--out`: checkpoints of the run in progress, and when to stop it saved.
    #[command(flatten)]
    pub checkpoint: CheckpointArgs,
    /// With `--out`: run everything again, ignoring (and replacing) the runs saved in OUT/runs by an earlier
    /// command, e.g. after a change of the program (to go on after a `--wall-limit` stop, leave it out).
    #[arg(long)]
    pub fresh: bool,
}

impl WedgeArgs {
    pub fn run(self) -> anyhow::Result<std::process::ExitCode> {
        anyhow::ensure!(
            self.c0 == "root" || self.c0 == "scene",
            "--c0 {}: expected `root` or `scene`",
            self.c0
        );
        let (every, wall_limit) = self.checkpoint.limits()?;
        anyhow::ensure!(
            self.out.is_some() || wall_limit.is_none(),
            "--wall-limit: needs --out, the folder the runs save themselves in"
        );
        let saving = self.out.as_ref().map(|out| twodt::wedge::WedgeCheckpoints {
            dir: out.join("runs"),
            every: every.unwrap_or(std::time::Duration::MAX),
            deadline: bowwave::driver::checkpoint::deadline(wall_limit),
            halt_at_step: None,
            fresh: self.fresh,
        });
        let mut all = vec![];
        for &beta in &self.deadrise {
            anyhow::ensure!(
                beta > 0.0 && beta < 90.0,
                "--deadrise {beta}: expected an angle in (0, 90) degrees"
            );
            for &dx in &self.dx {
                let mut spec = twodt::wedge::WedgeSpec {
                    dx,
                    deadrise_deg: beta,
                    depth_over_draft: self.depth,
                    shifting: self.shifting,
                    ..Default::default()
                };
                if self.c0 == "root" {
                    spec.c0 = Some(spec.mach_safe_c0());
                }
                let clock = std::time::Instant::now();
                anyhow::ensure!(
                    self.at.iter().all(|&a| a > 0.0 && a <= spec.penetration),
                    "--at {:?}: expected penetrations in (0, {}]",
                    self.at,
                    spec.penetration
                );
                let c = match twodt::wedge::compare(&spec, &self.at, saving.as_ref())? {
                    Ended::Ran(c) => c,
                    Ended::Halted(h) => return Ok(halted(&h)),
                };
                twodt::wedge::print(&c);
                println!(
                    "  ({:.1} s for both runs in this session)",
                    clock.elapsed().as_secs_f64()
                );
                all.push(c);
            }
        }
        if self.dx.len() == 3 {
            print_orders(&all, &self.dx);
        }
        if let Some(out) = self.out {
            bowwave::io::atomic::write_atomic(&out.join("wedge.csv"), twodt::wedge::csv(&all)?.as_bytes())?;
            let mut profiles = String::from("deadrise_deg,dx_over_l,run,penetration_over_l,z_over_vt,cp\n");
            for c in &all {
                for (name, runs) in [("2dt", &c.twodt), ("rigid", &c.rigid)] {
                    for a in runs {
                        for (z, cp) in &a.cp_profile {
                            profiles +=
                                &format!("{},{},{name},{},{z},{cp}\n", c.spec_deadrise_deg, c.dx, a.penetration);
                        }
                    }
                }
            }
            bowwave::io::atomic::write_atomic(&out.join("wedge_profiles.csv"), profiles.as_bytes())?;
            for &beta in &self.deadrise {
                plot_profiles(&all, beta, &out)?;
            }
            println!("wrote {} and wedge_profiles.csv", out.join("wedge.csv").display());
        }
        Ok(std::process::ExitCode::SUCCESS)
    }
}

/// The observed order (appendix C, eq. C.2) of the force and Cp_max at the last penetration, per deadrise,
/// over three spacings, with the error of the finest against the similarity solution.
fn print_orders(all: &[twodt::wedge::WedgeComparison], dx: &[f64]) {
    use bowwave::methods::convergence::order_c2;
    let rho = dx[0] / dx[1];
    println!("orders over dx/L {dx:?} (ratio {rho:.3}), at the last penetration:");
    for c3 in all.chunks(3) {
        for (name, rigid) in [("2D+t", false), ("rigid", true)] {
            let s: Vec<_> = c3
                .iter()
                .filter_map(|c| if rigid { c.rigid.last() } else { c.twodt.last() }.cloned())
                .collect();
            if s.len() < 3 {
                continue;
            }
            let of = |f: fn(&twodt::wedge::WedgeSample) -> f64| order_c2(f(&s[0]), f(&s[1]), f(&s[2]), rho);
            println!(
                "  β {}° {name}: force {:.3} {:.3} {:.3} (order {:.2}), Cp_max {:.2} {:.2} {:.2} (order {:.2})",
                c3[0].spec_deadrise_deg,
                s[0].force_coefficient,
                s[1].force_coefficient,
                s[2].force_coefficient,
                of(|a| a.force_coefficient),
                s[0].cp_max,
                s[1].cp_max,
                s[2].cp_max,
                of(|a| a.cp_max),
            );
        }
    }
}

/// `wedge_cp_BETA.png`: Cp along the face against z/(V t) at the last penetration of every spacing (2D+t
/// runs), beside the similarity solution's digitised curve where there is one.
fn plot_profiles(all: &[twodt::wedge::WedgeComparison], beta: f64, out: &std::path::Path) -> anyhow::Result<()> {
    use bowwave::io::plot::{line_plot, Series, Style};
    let mut series = vec![];
    let t = bowwave::reference::load("wedge_similarity_pressure");
    let (b, z, cp) = (
        bowwave::reference::named(&t, "deadrise_deg"),
        bowwave::reference::named(&t, "z_over_Vt"),
        bowwave::reference::named(&t, "cp"),
    );
    let exact: Vec<(f64, f64)> = (0..b.len())
        .filter(|&k| (b[k] - beta).abs() < 1e-9)
        .map(|k| (z[k], cp[k]))
        .collect();
    if !exact.is_empty() {
        series.push(Series {
            name: "similarity (Zhao & Faltinsen 1993)".into(),
            points: exact,
            style: Style::Line,
        });
    }
    for c in all.iter().filter(|c| (c.spec_deadrise_deg - beta).abs() < 1e-9) {
        if let Some(a) = c.twodt.last() {
            series.push(Series {
                name: format!("2D+t dx/L {:.1e}, Vt = {:.0} dx", c.dx, a.penetration / c.dx),
                points: a.cp_profile.clone(),
                style: Style::LineMarkers,
            });
        }
    }
    line_plot(
        &out.join(format!("wedge_cp_{beta}.png")),
        &format!("wedge {beta}°: pressure along the face at the last penetration"),
        "z/(Vt)",
        "Cp = (p − ρg(−z)) / (½ρV²)",
        &series,
    )
}
