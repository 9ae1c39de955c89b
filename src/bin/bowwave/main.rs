//! The `bowwave` command line: a thin layer over the library. Each file of this folder holds the options
//! of one group of subcommands (clap's `Args`, whose doc comments are the `--help` text) and the few lines
//! that hand them to the library.

mod bench;
mod bent_wall;
mod case;
mod chart;
mod converge;
mod frames;
mod hull;
mod options;
mod ship;
mod slab;
mod study;
mod twodt;

use anyhow::Context;
use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "bowwave", version, about = "δ-SPH simulation of breaking bow waves (2D+t), with its validation cases", long_about = None)]
struct Cli {
    /// Number of worker threads (default: all cores). Results are bit-identical for any thread count.
    #[arg(long, global = true)]
    threads: Option<usize>,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a case (built-in name or TOML file) and write its time series, VTK snapshots and plots.
    Run(case::RunArgs),
    /// Run validation cases and print their errors against analytic solutions and published data;
    /// exits non-zero when a tolerance is missed.
    Validate(case::ValidateArgs),
    /// 2D+t bow-wave run: one hull at one Froude number, from the stem to the plunge of the bow wave (or
    /// further), with the plunge point and jet metrics (metrics.csv/.json), series.csv, eta.csv (free-surface
    /// elevation η(y) at each output x/L, for wave-pattern maps), PNG snapshots at the plunge and optional VTK.
    Twodt(twodt::TwodtArgs),
    /// Convergence of a case (built-in name or TOML file): runs it at several resolutions and prints each
    /// validated quantity's value and error per resolution, the observed order (thesis appendix C) and a
    /// Richardson estimate with an uncertainty band; writes converge.csv.
    Converge(converge::ConvergeArgs),
    /// Charts of speed against accuracy and of stability, from runs of a validation case (PNG + CSV).
    Chart {
        #[command(subcommand)]
        kind: chart::ChartKind,
    },
    /// Froude sweep: run every case of a study file (TOML, see docs/reference/studies.md) that is not finished yet, then
    /// gather them into jets.csv, comparison.csv, report.md, figures and manifest.json. Resumable: finished
    /// cases are recorded and skipped; an interruption loses at most the cases in progress.
    Study(study::StudyArgs),
    /// The wedge check of the 2D+t machinery: a hull of wedge sections sinking linearly in x against a rigid
    /// wedge entering at the same speed, both against Wagner theory; prints pile-up height and force.
    Wedge(twodt::WedgeArgs),
    /// The plunge and the jet measured by bowwave's criteria in 2D+t particle frames written by another code
    /// (a cross-check on one hull by one measure); writes crest.csv and plunge.json.
    Frames(frames::FramesArgs),
    /// Measure throughput (particle-steps per second) on the dam break.
    Bench(bench::BenchArgs),
    /// The 3D comparison mode's first case: the dam break in 2D and as a 3D slab between free-slip side
    /// walls at the same spacing; prints how far the 3D front and wall pressures are from the 2D ones and
    /// what the third dimension costs; writes slab.csv.
    Slab(slab::SlabArgs),
    /// The 3D mode's ship: a hull file's surface as a 3D wall, towed from rest to U = Fr √(gL) through the 2D+t
    /// scene's tank extruded along x until its bow crest is steady; its wave pattern η(x, y) (ship3d_eta.csv, a
    /// PNG map), the bow's history (bow.csv), and with `--twodt` the 2D+t map beside it, their difference and
    /// the stretches of x/L over which they agree within 0.1 D (agreement.csv).
    Ship(ship::ShipArgs),
    /// The bent-wall channel of thesis §10.2.1 in 2D+t: the cut of its ruled surface (eq. 10.8), a plate whose
    /// foot slides along the floor at U/4 while it turns from vertical to 45° over the water, pushes water of
    /// depth H towards a straight side wall; records the run-up and the crest, and the plunge (the first
    /// closed air cavity); writes bent_wall.csv, bent_wall.json, a PNG and ParaView frames.
    BentWall(bent_wall::BentWallArgs),
    /// The bent-wall channel of thesis §10.2.1 in 3D: the ruled surface of eq. (10.8) towed from rest to U
    /// through still water of depth H until every cut of it has seen only the steady wall, beside its 2D+t
    /// analogue at the same spacing; the crest and the run-up along the wall in both (bent_wall_3d.csv, a PNG),
    /// the η map in the wall's frame; checkpoints and resumes like `ship`.
    #[command(name = "bent-wall-3d")]
    BentWall3d(bent_wall::BentWall3dArgs),
    /// Hull geometry: check a hull file, import one from STL, generate the Athena or Alliance approximation,
    /// draw a hull, or write the Wigley hull.
    Hull {
        #[command(subcommand)]
        action: hull::HullAction,
    },
    /// (Internal) one benchmark configuration, printed as JSON; used by `bench`.
    #[command(hide = true)]
    BenchOne(bench::BenchOneArgs),
    /// List the built-in cases, or print one as TOML to start a case file from.
    Cases(case::CasesArgs),
}

/// Exit status: 0 done, 1 an error or a missed tolerance, 2 a run that blew up (its outputs kept), 3 a run
/// halted with a checkpoint (run the same command again to go on).
fn main() -> ExitCode {
    match run() {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> anyhow::Result<ExitCode> {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let cli = Cli::parse();
    if let Some(n) = cli.threads {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global()
            .context("setting the thread count")?;
    }
    let done = |r: anyhow::Result<()>| r.map(|()| ExitCode::SUCCESS);
    match cli.command {
        Command::Run(a) => a.run(),
        Command::Validate(a) => a.run(),
        Command::Twodt(a) => a.run(),
        Command::Converge(a) => a.run(),
        Command::Chart { kind } => done(kind.run()),
        Command::Study(a) => a.run(),
        Command::Wedge(a) => a.run(),
        Command::Frames(a) => done(a.run()),
        Command::Bench(a) => done(a.run()),
        Command::Slab(a) => done(a.run()),
        Command::Ship(a) => a.run(),
        Command::BentWall(a) => a.run(),
        Command::BentWall3d(a) => a.run(),
        Command::Hull { action } => done(action.run()),
        Command::BenchOne(a) => done(a.run()),
        Command::Cases(a) => done(a.run()),
    }
}

#[cfg(test)]
mod tests {
    use super::Cli;
    use clap::CommandFactory;

    /// clap's own consistency check of the whole command tree: no two options share a name or short flag,
    /// every default value parses, every subcommand is reachable (it panics with the offending argument).
    #[test]
    fn command_line_definition_is_consistent() {
        Cli::command().debug_assert();
    }

    /// The README's two commands and the study subcommand's resume options parse as documented.
    #[test]
    fn documented_invocations_parse() {
        for args in [
            &["bowwave", "study", "studies/quick.toml"][..],
            &["bowwave", "run", "dam-break", "--res", "40", "--ghosts", "images"],
            &[
                "bowwave",
                "twodt",
                "--fr",
                "0.64",
                "--diffusion",
                "molteni-colagrossi",
                "--packing",
                "off",
            ],
            &[
                "bowwave",
                "study",
                "studies/athena.toml",
                "--case",
                "2",
                "--wall-limit",
                "150",
            ],
            &["bowwave", "--threads", "1", "validate", "dam-break"],
            &[
                "bowwave", "slab", "--res", "20", "--width", "6", "--end", "3", "--ghosts", "images",
            ],
        ] {
            if let Err(e) = <Cli as clap::Parser>::try_parse_from(args) {
                panic!("{args:?}: {e}");
            }
        }
        assert!(<Cli as clap::Parser>::try_parse_from(["bowwave", "twodt", "--packing", "maybe"]).is_err());
    }
}
