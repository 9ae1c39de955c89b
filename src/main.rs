//! The `bowwave` command line: a thin layer over the library.

use anyhow::Context;
use bowwave::{bench, cases, validation};
use clap::{Parser, Subcommand};
use std::path::PathBuf;

#[derive(Parser)]
#[command(name = "bowwave", version, about = "δ-SPH simulation of breaking bow waves (2D+t), with its validation cases", long_about = None)]
struct Cli {
    /// Number of worker threads (default: all cores). Results are bit-identical for any thread count.
    #[arg(long, global = true)]
    threads: Option<usize>,
    #[command(subcommand)]
    command: Command,
}

/// `--ghosts`: the CLI's names for [`bowwave::sph::polyline_wall::GhostKind`].
#[derive(Clone, Copy, Debug, clap::ValueEnum)]
enum GhostsArg {
    Fixed,
    Images,
}

impl From<GhostsArg> for bowwave::sph::polyline_wall::GhostKind {
    fn from(g: GhostsArg) -> Self {
        match g {
            GhostsArg::Fixed => Self::Fixed,
            GhostsArg::Images => Self::Images,
        }
    }
}

#[derive(Subcommand)]
enum Command {
    /// Run a case (built-in name or TOML file) and write its time series, VTK snapshots and plots.
    Run {
        /// Built-in case name (see `bowwave cases`) or path to a case TOML file.
        #[arg(default_value = "dam-break")]
        case: String,
        /// Resolution: reference length / particle spacing (e.g. H/dx for the dam break). Default: the case's.
        #[arg(long)]
        res: Option<f64>,
        /// Output folder (default: out/CASE_NAME).
        #[arg(long)]
        out: Option<PathBuf>,
        /// End time in seconds (default: the case's).
        #[arg(long)]
        end: Option<f64>,
        /// Do not write VTK snapshots.
        #[arg(long)]
        no_vtk: bool,
        /// No progress bar.
        #[arg(long, short)]
        quiet: bool,
        /// Ghosts of every wall's straight sides, overriding the case file: `fixed` (a lattice valued by MLS at
        /// the mirror points, thesis §7.1.1) or `images` (mirror images of the fluid particles, Colagrossi &
        /// Landrini 2003; corners keep fixed ghosts). Default: the case's (fixed unless it says otherwise).
        #[arg(long, value_enum)]
        ghosts: Option<GhostsArg>,
        /// Do not stop the run when its mechanical energy rises by more than 1e-3 of its scale with fixed walls
        /// (by default such a rise is diagnosed as an unstable time integration or a non-conservative term).
        #[arg(long)]
        allow_energy_growth: bool,
    },
    /// Run validation cases and print their errors against analytic solutions and published data;
    /// exits non-zero when a tolerance is missed.
    Validate {
        /// A built-in case to validate (default: all of them).
        case: Option<String>,
        /// Resolution (reference length / dx); default: each case's validation resolution.
        #[arg(long)]
        res: Option<f64>,
        /// Write series and plots of each validation run under this folder.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Ghosts of every wall's straight sides, overriding the case files (see `run --help`).
        #[arg(long, value_enum)]
        ghosts: Option<GhostsArg>,
    },
    /// 2D+t bow-wave run: one hull at one Froude number, from the stem to the plunge of the bow wave (or
    /// further), with the plunge point and jet metrics (metrics.csv/.json), series.csv, eta.csv (free-surface
    /// elevation η(y) at each output x/L, for wave-pattern maps), PNG snapshots at the plunge and optional VTK.
    Twodt {
        /// Hull offsets file (CSV, see docs/hull-format.md).
        #[arg(long, default_value = "hulls/athena.csv")]
        hull: PathBuf,
        /// Ship Froude number U/sqrt(g L).
        #[arg(long, default_value_t = 0.5)]
        fr: f64,
        /// Fine particle spacing dx/L near the free surface (default: from H_pj/dx > 20, eq. 10.9, with the
        /// bow-wave height estimated from Table 10.1 of the thesis).
        #[arg(long)]
        dx: Option<f64>,
        /// Coarse spacing below the transition, as a multiple of dx (constant h; 1 = uniform). Default 1.5,
        /// packed: 42 % fewer particles for the same crest within 0.5 % (docs/twodt.md).
        #[arg(long, default_value_t = 1.5)]
        ratio: f64,
        /// Density diffusion: delta-sph (eq. 5.2, the default), molteni-colagrossi (5.4) or none (standard
        /// WCSPH), for method comparisons.
        #[arg(long, default_value = "delta-sph")]
        diffusion: String,
        /// Evaluate the Gaussian kernel's gradient at every pair instead of from its table in r² (the default
        /// table changes positions by ~1e-6 dx and saves 10–25 % of the CPU; docs/speed-accuracy.md).
        #[arg(long)]
        exact_kernel: bool,
        /// Pack the initial particles (thesis chapter 6: move them along −∇Γ inside the tank closed by a lid
        /// at the calm level, the upper half of the fine layer held) before the damped settling: auto (when
        /// --ratio > 1: graded rows relax with 1e-5 M g D of spurious flow otherwise), on, or off.
        #[arg(long, default_value = "auto")]
        packing: String,
        /// Domain width W as a multiple of the beam B (thesis §10.1.2: 4).
        #[arg(long, default_value_t = 4.0)]
        width: f64,
        /// Water depth Z as a multiple of the draft D (thesis §10.1.2 and appendix D: 2).
        #[arg(long, default_value_t = 2.0)]
        depth: f64,
        /// Where to stop: `plunge` (shortly after it), `transom`, or an x/L value (e.g. 1.3 for stern waves).
        #[arg(long, default_value = "plunge")]
        until: String,
        /// With `--until plunge`: the x/L at which to give up if nothing has plunged (default: the transom).
        #[arg(long)]
        give_up_at: Option<f64>,
        /// Sound speed / sqrt(g L) (default: 10 × the expected largest velocity).
        #[arg(long)]
        c0: Option<f64>,
        /// Free-surface detection and plunge check every N steps.
        #[arg(long, default_value_t = 10)]
        detect_every: usize,
        /// Optional extra plunge criterion (ours, not the issue's; off by default): a closed air cavity counts
        /// as the plunge only if its lowest point lies below this fraction of the crest height, e.g. 0.5 to
        /// keep folds high in a sheet out (docs/jet-metrics.md).
        #[arg(long)]
        plunge_depth: Option<f64>,
        /// Plunge criterion 5: a closed air cavity counts as the plunge only if the circulation around it,
        /// Γ/(U D), is at least this (clockwise positive, the sense of a jet overturning away from the hull);
        /// it keeps out slivers of air between particle rows of the sheet climbing the hull, whose Γ is
        /// near zero (docs/jet-metrics.md).
        #[arg(long, default_value_t = 0.02)]
        plunge_circulation: f64,
        /// Switch plunge criterion 5 (--plunge-circulation) off.
        #[arg(long)]
        no_circulation_check: bool,
        /// x/L between outputs (series row, η profile, VTK frame).
        #[arg(long, default_value_t = 0.005)]
        output_dx: f64,
        /// Output folder (default: out/twodt-HULL-frFR).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Write VTK frames (.vtp + .pvd).
        #[arg(long)]
        vtk: bool,
        /// x/L of the section at the start (default: the stem). A value before the stem runs the tank alone
        /// until the stem arrives.
        #[arg(long)]
        x0: Option<f64>,
        /// Damped settling before the ship starts, in acoustic crossings of the depth (Z/c0).
        #[arg(long, default_value_t = 1.0)]
        settle: f64,
        /// Write a PNG of the bow region at every output.
        #[arg(long)]
        frames: bool,
        /// Minutes of wall time between checkpoints (OUT/checkpoint.bin: the particles and the run's state;
        /// 0: none). A run started again with the same options goes on from its checkpoint, to the same bits.
        #[arg(long, default_value_t = 10.0)]
        checkpoint_every: f64,
        /// Stop after this many minutes of wall time, saving a checkpoint (a batch job's time limit); run
        /// the same command again to go on.
        #[arg(long)]
        wall_limit: Option<f64>,
        /// Ignore a checkpoint in the output folder and start from the beginning.
        #[arg(long)]
        fresh: bool,
        /// No progress bar.
        #[arg(long, short)]
        quiet: bool,
    },
    /// Convergence of a case (built-in name or TOML file): runs it at several resolutions and prints each
    /// validated quantity's value and error per resolution, the observed order (thesis appendix C) and a
    /// Richardson estimate with an uncertainty band; writes converge.csv.
    Converge {
        /// Built-in case name (see `bowwave cases`), case file, or `twodt` for a 2D+t run of --hull at --fr
        /// at the spacings --dx (its quantities: the jet metrics at the plunge when every run plunges, and
        /// the crest height at the end).
        case: String,
        /// Resolutions (reference length / dx), coarse to fine; a constant ratio allows the extrapolation.
        #[arg(long, value_delimiter = ',', default_values_t = vec![20.0, 40.0, 80.0])]
        res: Vec<f64>,
        /// End time override (s).
        #[arg(long)]
        end: Option<f64>,
        /// twodt: hull offsets file.
        #[arg(long, default_value = "hulls/athena.csv")]
        hull: PathBuf,
        /// twodt: ship Froude number U/sqrt(gL).
        #[arg(long, default_value_t = 0.5)]
        fr: f64,
        /// twodt: fine spacings dx/L, coarse to fine (the thesis's Athena study: 2.7e-4,1.9e-4,1.35e-4).
        #[arg(long, value_delimiter = ',', default_values_t = vec![3e-3, 2e-3, 1.333e-3])]
        dx: Vec<f64>,
        /// twodt: where each run stops: plunge (plus a margin), transom, or an x/L value.
        #[arg(long, default_value = "plunge")]
        until: String,
        /// twodt: x/L at which a run that has not plunged gives up.
        #[arg(long)]
        give_up_at: Option<f64>,
        /// twodt: free-surface detection and plunge check every N steps.
        #[arg(long, default_value_t = 10)]
        detect_every: usize,
        /// twodt: gather finished `bowwave twodt` runs (their folders, coarse to fine, comma separated)
        /// instead of running the ladder.
        #[arg(long, value_delimiter = ',')]
        runs: Vec<PathBuf>,
        /// twodt: minutes between checkpoints of the running spacing (0: none); run the same command again
        /// to go on from it. Finished spacings (OUT/dx-*/converge_run.json) are reused.
        #[arg(long, default_value_t = 10.0)]
        checkpoint_every: f64,
        /// twodt: stop after this many minutes of wall time with a checkpoint (exit status 3).
        #[arg(long)]
        wall_limit: Option<f64>,
        /// Output folder for converge.csv and, for twodt, one folder per spacing (default out/converge-CASE).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Charts of speed against accuracy and of stability, from runs of a validation case (PNG + CSV).
    Chart {
        #[command(subcommand)]
        kind: ChartKind,
    },
    /// Froude sweep: run every case of a study file (TOML, see docs/studies.md) that is not finished yet, then
    /// gather them into jets.csv, comparison.csv, report.md, figures and manifest.json. Resumable: finished
    /// cases are recorded and skipped; an interruption loses at most the cases in progress.
    Study {
        /// Study file, e.g. studies/quick.toml.
        file: PathBuf,
        /// Output folder (default out/study-NAME).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Run only case N (1-based, in the order of `froude`), e.g. a batch array index; then collect
        /// whatever is finished.
        #[arg(long)]
        case: Option<usize>,
        /// Do not run anything: gather the finished cases into the tables and figures.
        #[arg(long)]
        collect: bool,
        /// Recompute finished cases.
        #[arg(long)]
        force: bool,
        /// Print each case's particle count, estimated steps and run time, and run nothing.
        #[arg(long)]
        dry_run: bool,
        /// Minutes of wall time between checkpoints of the running case (CASE/checkpoint.bin; 0: none): an
        /// interrupted study loses at most this much of the case in progress, and goes on from it when run
        /// again (to the same bits). `--force` ignores checkpoints too.
        #[arg(long, default_value_t = 10.0)]
        checkpoint_every: f64,
        /// Stop the case in progress after this many minutes of wall time, saving a checkpoint (a batch job's
        /// time limit); run the same command again to go on.
        #[arg(long)]
        wall_limit: Option<f64>,
        /// Cases run at the same time, each with threads/jobs worker threads (default 1: every thread inside
        /// one case, measured faster on 2 cores, see docs/studies.md).
        #[arg(long, default_value_t = 1)]
        jobs: usize,
        /// No progress bars.
        #[arg(long, short)]
        quiet: bool,
    },
    /// The wedge check of the 2D+t machinery: a hull of wedge sections sinking linearly in x against a rigid
    /// wedge entering at the same speed, both against Wagner theory; prints pile-up height and force.
    Wedge {
        /// Particle spacing dx/L (the penetration at the end is 0.03 L).
        #[arg(long, default_value_t = 5e-4)]
        dx: f64,
        /// Deadrise angle in degrees.
        #[arg(long, default_value_t = 30.0)]
        deadrise: f64,
    },
    /// Measure throughput (particle-steps per second) on the dam break.
    Bench {
        /// Resolutions H/dx, comma separated.
        #[arg(long, value_delimiter = ',', default_value = "100")]
        res: Vec<f64>,
        /// End time in t sqrt(g/H).
        #[arg(long, default_value_t = 6.0)]
        end: f64,
        /// Thread counts to compare, comma separated.
        #[arg(long, value_delimiter = ',', default_value = "1,2")]
        threads: Vec<usize>,
        /// Method variants to compare, comma separated (as in `chart speed-accuracy`, e.g. `delta-sph,table`);
        /// `delta-sph` is the case's defaults.
        #[arg(long, value_delimiter = ',', default_value = "delta-sph")]
        variants: Vec<String>,
    },
    /// Hull geometry: check a hull file, or generate the Wigley hull.
    Hull {
        #[command(subcommand)]
        action: HullAction,
    },
    /// (Internal) one benchmark configuration, printed as JSON; used by `bench`.
    #[command(hide = true)]
    BenchOne {
        #[arg(long)]
        res: f64,
        #[arg(long)]
        end: f64,
        #[arg(long, default_value = "delta-sph")]
        variant: String,
    },
    /// List the built-in cases, or print one as TOML to start a case file from.
    Cases {
        /// Print this built-in case's TOML.
        name: Option<String>,
    },
}

#[derive(Subcommand)]
enum HullAction {
    /// Hydrostatics from the spline surface (displacement, Cb, Cp, Cm, Cwp, LCB, girths) beside the declared
    /// particulars; warns where they differ by more than 2 %.
    Check {
        /// Hull offsets file (CSV, see docs/hull-format.md).
        file: PathBuf,
    },
    /// Slice a triangulated hull (STL, metres, z = 0 at the waterline) at stations and write a hull file.
    Import {
        /// The STL file (ASCII or binary).
        stl: PathBuf,
        /// Hull name for the metadata.
        #[arg(long)]
        name: String,
        /// Number of equally spaced stations between the ends (exclusive).
        #[arg(long, default_value_t = 21)]
        stations: usize,
        /// Reference length L (m); default: the mesh's length along x.
        #[arg(long)]
        length: Option<f64>,
        /// The stem is at the largest x of the mesh (default: the smallest).
        #[arg(long)]
        stem_at_max_x: bool,
        /// The hull ends in a transom.
        #[arg(long)]
        transom: bool,
        /// Output hull file.
        #[arg(long)]
        out: PathBuf,
    },
    /// Generate a labelled approximation (athena, alliance) from the parametric family, calibrated to its
    /// particulars (Cb by bisection on the midship section shape), and write it as a hull file.
    Generate {
        /// athena or alliance.
        hull: String,
        #[arg(long, default_value_t = 41)]
        stations: usize,
        #[arg(long, default_value_t = 31)]
        points: usize,
        /// Output file (default hulls/NAME.csv).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Override a generator parameter, `key=value` (repeatable; keys as in the file's `# generator:` line,
        /// e.g. `flare=15` or `p_entrance=3`) for sensitivity studies. The hull is then labelled a variant.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
    },
    /// Draw a hull: body plan, profile, waterline plan and w_n along the girth (PNG).
    Show {
        /// Hull offsets file.
        file: PathBuf,
        /// Output folder.
        #[arg(long, default_value = "out/hull")]
        out: PathBuf,
    },
    /// Write the parabolic Wigley hull (L/B = 5, L/D = 10, wall-sided above the waterline) as a hull file.
    Wigley {
        /// Number of stations, stem and stern included.
        #[arg(long, default_value_t = 21)]
        stations: usize,
        /// Reference length L (m).
        #[arg(long, default_value_t = 100.0)]
        length: f64,
        /// Output file.
        #[arg(long, default_value = "hulls/wigley.csv")]
        out: PathBuf,
    },
}

fn main() {
    if let Err(e) = run() {
        eprintln!("error: {e:#}");
        std::process::exit(1);
    }
}

#[derive(Subcommand)]
enum ChartKind {
    /// Error of one validated quantity against CPU seconds for every variant at every resolution, on log axes,
    /// with the Pareto front; writes speed_accuracy.csv and .png.
    SpeedAccuracy {
        /// Built-in case name or case file.
        case: String,
        /// Method variants: delta-sph, molteni, wcsph, wendland, pc, rk4, table (tabulated kernel gradient, the
        /// default), exact-kernel (the Gaussian evaluated at every pair), images / fixed-ghosts (every wall's
        /// straight sides as image ghosts, or the fixed lattice), alpha=A, delta=D, cfl=C, h=H (h/dx).
        #[arg(long, value_delimiter = ',', default_values_t = vec!["delta-sph".to_string(), "molteni".to_string(), "wcsph".to_string(), "wendland".to_string(), "pc".to_string()])]
        variants: Vec<String>,
        /// Resolutions (reference length / dx).
        #[arg(long, value_delimiter = ',', default_values_t = vec![20.0, 40.0])]
        res: Vec<f64>,
        /// End time override (s).
        #[arg(long)]
        end: Option<f64>,
        /// The validated quantity: the first check whose label contains this text (default: the first check).
        #[arg(long)]
        quantity: Option<String>,
        /// Output folder (default out/chart-CASE).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// 2D+t speed against accuracy: one hull at one Froude number, every variant at every fine spacing, run to
    /// x/L = AT; the error is that of the bow-wave crest height there against a finer δ-SPH reference run.
    /// Writes speed_accuracy.csv/.png and crest.csv.
    Twodt {
        /// Hull offsets file.
        #[arg(long, default_value = "hulls/athena.csv")]
        hull: PathBuf,
        /// Ship Froude number U/sqrt(gL).
        #[arg(long, default_value_t = 0.5)]
        fr: f64,
        /// 2D+t variants: delta-sph, molteni, wcsph, table (tabulated kernel gradient, the default),
        /// exact-kernel, cfl=C (RK4 CFL), ratio=R (graded rows, coarse spacing R dx below 0.2 D).
        #[arg(long, value_delimiter = ',', default_values_t = vec!["delta-sph".to_string(), "wcsph".to_string(), "exact-kernel".to_string(), "cfl=2.5".to_string(), "ratio=1.5".to_string()])]
        variants: Vec<String>,
        /// Fine spacings dx/L of the chart, comma separated.
        #[arg(long, value_delimiter = ',', default_values_t = vec![3e-3, 2e-3, 1.5e-3])]
        dx: Vec<f64>,
        /// Spacing dx/L of the δ-SPH reference run (finer than every --dx).
        #[arg(long, default_value_t = 1e-3)]
        reference_dx: f64,
        /// x/L (from the stem) at which the crest height is measured.
        #[arg(long, default_value_t = 0.2)]
        at: f64,
        /// Output folder (default out/chart-twodt-HULL-FR).
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Redraws speed_accuracy.png from the speed_accuracy.csv in DIR (after a plotting change, or after adding
    /// rows of runs made on other machines) and rewrites the csv with its Pareto column recomputed; runs nothing.
    Replot {
        /// Folder holding speed_accuracy.csv.
        dir: PathBuf,
        /// Label of the error axis, for files written before the csv carried its `quantity` column.
        #[arg(long)]
        quantity: Option<String>,
    },
    /// The case over a grid of two lists of variants (e.g. --rows alpha=0,alpha=0.005 --cols delta-sph,wcsph,
    /// or --rows cfl=1,cfl=2 --cols rk4,pc), each run marked stable or stopped with its diagnosis; writes
    /// stability.csv and .png.
    Stability {
        /// Built-in case name or case file.
        case: String,
        /// Variants along the rows, comma separated (e.g. alpha=0,alpha=0.005 or cfl=1,cfl=2); each run
        /// combines one row with one column.
        #[arg(long, value_delimiter = ',')]
        rows: Vec<String>,
        /// Variants along the columns, comma separated (e.g. wcsph,delta-sph or rk4,pc).
        #[arg(long, value_delimiter = ',')]
        cols: Vec<String>,
        /// Resolution (reference length / dx).
        #[arg(long, default_value_t = 20.0)]
        res: f64,
        /// End time override (s).
        #[arg(long)]
        end: Option<f64>,
        /// Output folder (default out/chart-CASE).
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

fn run() -> anyhow::Result<()> {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("warn")).init();
    let cli = Cli::parse();
    if let Some(n) = cli.threads {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global()
            .context("setting the thread count")?;
    }
    match cli.command {
        Command::Chart { kind } => match kind {
            ChartKind::SpeedAccuracy {
                case,
                variants,
                res,
                end,
                quantity,
                out,
            } => {
                use bowwave::studies::charts;
                let c = bowwave::cases::load(&case)?;
                let (label, points) = charts::speed_accuracy(&c, &variants, &res, end, quantity.as_deref())?;
                let out = out.unwrap_or_else(|| PathBuf::from("out").join(format!("chart-{}", c.name)));
                println!("{}: {label}", c.name);
                println!("variant        res   particles   steps   CPU s      error   stopped");
                for p in &points {
                    println!(
                        "{:<12} {:>5} {:>11} {:>7} {:>7.1} {:>10.3e}   {}",
                        p.variant,
                        p.res,
                        p.particles,
                        p.steps,
                        p.cpu_seconds,
                        p.error,
                        p.stopped.clone().unwrap_or_default()
                    );
                }
                for f in charts::write_speed_accuracy(&out, &c.name, &label, &points)? {
                    println!("wrote {}", f.display());
                }
            }
            ChartKind::Twodt {
                hull,
                fr,
                variants,
                dx,
                reference_dx,
                at,
                out,
            } => {
                use bowwave::studies::twodt_chart;
                let offsets = bowwave::geometry::hull_file::HullOffsets::read(&hull)?;
                let name = offsets.meta.name.clone();
                let surface = std::sync::Arc::new(bowwave::geometry::surface::HullSurface::new(&offsets));
                let base = bowwave::twodt::scene::TwoDtConfig {
                    fr,
                    ..Default::default()
                };
                let chart = twodt_chart::twodt_speed_accuracy(surface, &base, &variants, &dx, reference_dx, at)?;
                let out = out.unwrap_or_else(|| PathBuf::from("out").join(format!("chart-twodt-{name}-{fr}")));
                println!(
                    "{name} Fr {fr}: crest height at x/L = {at}; reference (δ-SPH, dx/L = {reference_dx}) {:.4} D",
                    chart.reference
                );
                println!("variant        dx/L   particles   steps   CPU s   crest/D      error   stopped");
                for (p, v) in chart.points.iter().zip(&chart.values) {
                    println!(
                        "{:<12} {:>7.1e} {:>9} {:>7} {:>7.1} {:>8.4} {:>10.3e}   {}",
                        p.variant,
                        1.0 / p.res,
                        p.particles,
                        p.steps,
                        p.cpu_seconds,
                        v,
                        p.error,
                        p.stopped.clone().unwrap_or_default()
                    );
                }
                twodt_chart::write_twodt_chart(&out, &format!("{name} Fr {fr} (2D+t)"), at, &chart)?;
                println!("wrote {}", out.display());
            }
            ChartKind::Replot { dir, quantity } => {
                use bowwave::studies::charts;
                let (case, label, points) =
                    charts::read_speed_accuracy(&dir.join("speed_accuracy.csv"), quantity.as_deref())?;
                for f in charts::write_speed_accuracy(&dir, &case, &label, &points)? {
                    println!("wrote {}", f.display());
                }
            }
            ChartKind::Stability {
                case,
                rows,
                cols,
                res,
                end,
                out,
            } => {
                use bowwave::studies::charts;
                anyhow::ensure!(
                    !rows.is_empty() && !cols.is_empty(),
                    "--rows and --cols: expected variant lists"
                );
                let c = bowwave::cases::load(&case)?;
                let cells = charts::stability(&c, &rows, &cols, res, end)?;
                for x in &cells {
                    println!(
                        "{:<14} {:<12} {}",
                        x.a,
                        x.b,
                        if x.stable {
                            format!("stable, pressure noise {:.3} ρgL", x.noise)
                        } else {
                            format!("unstable: {}", x.diagnosis)
                        }
                    );
                }
                let out = out.unwrap_or_else(|| PathBuf::from("out").join(format!("chart-{}", c.name)));
                for f in charts::write_stability(&out, &c.name, &cells)? {
                    println!("wrote {}", f.display());
                }
            }
        },
        Command::Converge {
            case,
            res,
            end,
            hull,
            fr,
            dx,
            until,
            give_up_at,
            detect_every,
            runs,
            checkpoint_every,
            wall_limit,
            out,
        } => {
            let (conv, out) = if case == "twodt" && !runs.is_empty() {
                let out = out.unwrap_or_else(|| PathBuf::from("out").join("converge-twodt-runs"));
                (bowwave::studies::twodt_convergence::converge_finished(&runs)?, out)
            } else if case == "twodt" {
                let offsets = bowwave::geometry::hull_file::HullOffsets::read(&hull)?;
                let surface = std::sync::Arc::new(bowwave::geometry::surface::HullSurface::new(&offsets));
                let base = bowwave::twodt::scene::TwoDtConfig {
                    fr,
                    until: until.parse().map_err(anyhow::Error::msg)?,
                    give_up_at,
                    detect_every,
                    ..Default::default()
                };
                let out = out.unwrap_or_else(|| {
                    PathBuf::from("out").join(format!("converge-twodt-{}-fr{fr}", offsets.meta.name))
                });
                let policy = checkpoint_policy(checkpoint_every, wall_limit, true)?;
                let conv =
                    bowwave::studies::twodt_convergence::converge_twodt(surface, &base, &dx, &out, &policy, true);
                (exit_if_halted(conv)?, out)
            } else {
                let c = bowwave::cases::load(&case)?;
                let out = out.unwrap_or_else(|| PathBuf::from("out").join(format!("converge-{}", c.name)));
                (bowwave::convergence::converge(&c, &res, end)?, out)
            };
            print!("{}", conv.report());
            std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
            bowwave::io::atomic::write_atomic(&out.join("converge.csv"), conv.csv().as_bytes())?;
            println!("table in {}", out.join("converge.csv").display());
        }
        Command::Study {
            file,
            out,
            case,
            collect,
            force,
            dry_run,
            checkpoint_every,
            wall_limit,
            jobs,
            quiet,
        } => {
            use bowwave::studies;
            let study = studies::study_file::Study::read(&file)?;
            let out = out.unwrap_or_else(|| PathBuf::from("out").join(format!("study-{}", study.spec.name)));
            if dry_run {
                let est = studies::runner::dry_run(&study)?;
                println!(
                    "study {} ({} cases), {}",
                    study.spec.name,
                    est.len(),
                    study.hull_path.display()
                );
                println!("case  Fr      dx/L       particles  est. steps  est. time (s)");
                for e in &est {
                    println!(
                        "{:4}  {:<6}  {:.3e}  {:9}  {:10.0}  {:13.0}",
                        e.spec.index, e.spec.fr, e.spec.dx, e.particles, e.steps, e.seconds
                    );
                }
                println!(
                    "total {:.0} s at {:.1e} particle-steps/s (the measured 2D+t throughput on 2 cores; a plunge search \
                     is counted to its give-up point, the worst case)",
                    est.iter().map(|e| e.seconds).sum::<f64>(),
                    studies::runner::REFERENCE_THROUGHPUT
                );
                return Ok(());
            }
            if !collect {
                let opts = studies::runner::StudyOptions {
                    out_dir: out.clone(),
                    force,
                    case,
                    jobs,
                    threads: rayon::current_num_threads(),
                    progress: !quiet,
                    // `resume` is set per case by the runner (not with --force).
                    checkpoint: checkpoint_policy(checkpoint_every, wall_limit, true)?,
                };
                let ran = studies::runner::run_cases(&study, &opts)?;
                println!("{ran} case(s) run");
            }
            let n = studies::collect_all(&study, &out)?;
            println!(
                "{n} of {} case(s) finished; tables, report and figures in {}",
                study.cases.len(),
                out.display()
            );
            print!("{}", std::fs::read_to_string(out.join("report.md")).unwrap_or_default());
        }
        Command::Wedge { dx, deadrise } => {
            let spec = bowwave::twodt::wedge::WedgeSpec {
                dx,
                deadrise_deg: deadrise,
                ..Default::default()
            };
            let c = bowwave::twodt::wedge::compare(&spec, &[0.01, 0.02, 0.03])?;
            bowwave::twodt::wedge::print(&c);
        }
        Command::Twodt {
            hull,
            fr,
            dx,
            ratio,
            diffusion,
            exact_kernel,
            packing,
            width,
            depth,
            until,
            give_up_at,
            c0,
            detect_every,
            plunge_depth,
            plunge_circulation,
            no_circulation_check,
            output_dx,
            out,
            vtk,
            frames,
            quiet,
            x0,
            settle,
            checkpoint_every,
            wall_limit,
            fresh,
        } => {
            let offsets = bowwave::geometry::hull_file::HullOffsets::read(&hull)?;
            let surface = std::sync::Arc::new(bowwave::geometry::surface::HullSurface::new(&offsets));
            if let Some(f) = plunge_depth.filter(|f| !(f.is_finite() && *f > 0.0)) {
                anyhow::bail!("--plunge-depth {f}: expected a positive fraction of the crest height");
            }
            if !plunge_circulation.is_finite() {
                anyhow::bail!("--plunge-circulation {plunge_circulation}: expected a finite Γ/(U D)");
            }
            let cfg = bowwave::twodt::scene::TwoDtConfig {
                fr,
                dx,
                coarse_ratio: ratio,
                width_over_beam: width,
                depth_over_draft: depth,
                diffusion: match diffusion.as_str() {
                    "delta-sph" => bowwave::sph::density_diffusion::DensityDiffusion::DeltaSph,
                    "molteni-colagrossi" => bowwave::sph::density_diffusion::DensityDiffusion::MolteniColagrossi,
                    "none" => bowwave::sph::density_diffusion::DensityDiffusion::None,
                    other => anyhow::bail!("--diffusion `{other}`: expected delta-sph, molteni-colagrossi or none"),
                },
                kernel_table: !exact_kernel,
                packing: match packing.as_str() {
                    "auto" => None,
                    "on" => Some(true),
                    "off" => Some(false),
                    other => anyhow::bail!("--packing `{other}`: expected auto, on or off"),
                },
                until: until.parse().map_err(anyhow::Error::msg)?,
                give_up_at,
                c0,
                detect_every,
                plunge_depth,
                plunge_circulation: (!no_circulation_check).then_some(plunge_circulation),
                output_dx,
                x0,
                settle_crossings: settle,
                ..Default::default()
            };
            let out = out.unwrap_or_else(|| PathBuf::from("out").join(format!("twodt-{}-fr{fr}", offsets.meta.name)));
            let opts = bowwave::twodt::run::TwoDtOptions {
                out_dir: out.clone(),
                progress: !quiet,
                vtk,
                plots: true,
                frames,
                multi: None,
                label: String::new(),
                checkpoint: checkpoint_policy(checkpoint_every, wall_limit, !fresh)?,
            };
            let r = exit_if_halted(bowwave::twodt::run::run(surface, &cfg, &opts))?;
            bowwave::twodt::report::print(&r, &out);
            if r.blowup.is_some() {
                std::process::exit(2);
            }
        }
        Command::Run {
            case,
            res,
            out,
            end,
            no_vtk,
            quiet,
            ghosts,
            allow_energy_growth,
        } => {
            let mut case = cases::load(&case)?;
            if let Some(kind) = ghosts {
                case.set_ghosts(kind.into());
            }
            let out = out.unwrap_or_else(|| PathBuf::from("out").join(&case.name));
            let opts = cases::run::RunOptions {
                res,
                end_time: end,
                progress: !quiet,
                vtk: !no_vtk,
                allow_energy_growth,
                ..Default::default()
            };
            let code = validation::run_and_report(&case, &out, opts)?;
            std::process::exit(code);
        }
        Command::Validate { case, res, out, ghosts } => {
            let ok = validation::validate_cli(case.as_deref(), res, out.as_deref(), ghosts.map(Into::into))?;
            std::process::exit(if ok { 0 } else { 1 });
        }
        Command::Bench {
            res,
            end,
            threads,
            variants,
        } => {
            bench::bench_cli(&res, end, &threads, &variants)?;
        }
        Command::Hull { action } => match action {
            HullAction::Check { file } => {
                let h = bowwave::geometry::hull_file::HullOffsets::read(&file)?;
                let (text, warnings) = bowwave::geometry::report::check_report(&h);
                print!("{text}");
                if warnings > 0 {
                    eprintln!("{warnings} warning(s)");
                }
            }
            HullAction::Import {
                stl,
                name,
                stations,
                length,
                stem_at_max_x,
                transom,
                out,
            } => {
                anyhow::ensure!(stations >= 4, "--stations: expected at least 4, got {stations}");
                let xs: Vec<f64> = (0..stations).map(|i| (i as f64 + 0.5) / stations as f64).collect();
                let opts = bowwave::geometry::stl::ImportOptions {
                    name,
                    stations: xs,
                    length_m: length,
                    stem_at_max_x,
                    transom,
                };
                let h = bowwave::geometry::stl::import_stl(&stl, &opts)?;
                let text = h.to_csv();
                bowwave::geometry::hull_file::HullOffsets::parse(&text, &out.display().to_string())?;
                bowwave::io::atomic::write_atomic(&out, text.as_bytes())?;
                println!("wrote {} ({} stations)", out.display(), h.stations.len());
            }
            HullAction::Generate {
                hull,
                stations,
                points,
                out,
                set,
            } => {
                use bowwave::geometry::parametric;
                let mut spec = match hull.as_str() {
                    "athena" => parametric::athena(),
                    "alliance" => parametric::alliance(),
                    other => anyhow::bail!("hull `{other}`: expected `athena` or `alliance`"),
                };
                if !set.is_empty() {
                    spec = spec.with_overrides(&set)?;
                }
                anyhow::ensure!(
                    stations >= 4 && points >= 3,
                    "--stations >= 4 and --points >= 3 expected"
                );
                let cb = spec.calibrate(stations, points);
                let h = spec.offsets(stations, points);
                let out = out.unwrap_or_else(|| PathBuf::from("hulls").join(format!("{hull}.csv")));
                bowwave::io::atomic::write_atomic(&out, h.to_csv().as_bytes())?;
                println!(
                    "wrote {} (Cb = {cb:.4}, target {:.4}, n_mid = {:.3})",
                    out.display(),
                    spec.target_cb,
                    spec.n_mid
                );
            }
            HullAction::Show { file, out } => {
                let h = bowwave::geometry::hull_file::HullOffsets::read(&file)?;
                let s = bowwave::geometry::surface::HullSurface::new(&h);
                for f in bowwave::geometry::drawings::draw(&s, &out)? {
                    println!("{}", f.display());
                }
            }
            HullAction::Wigley { stations, length, out } => {
                anyhow::ensure!(stations >= 4, "--stations: expected at least 4, got {stations}");
                anyhow::ensure!(
                    length > 0.0 && length.is_finite(),
                    "--length: expected a positive length in metres"
                );
                let spec = bowwave::geometry::wigley::WigleySpec {
                    stations,
                    length_m: length,
                    ..Default::default()
                };
                let h = bowwave::geometry::wigley::wigley(&spec);
                bowwave::io::atomic::write_atomic(&out, h.to_csv().as_bytes())?;
                println!("wrote {}", out.display());
            }
        },
        Command::BenchOne { res, end, variant } => {
            let r = bench::bench_one(res, end, &variant)?;
            println!("{}", serde_json::to_string(&r)?);
        }
        Command::Cases { name } => match name {
            None => {
                for (n, text) in cases::builtin::BUILTIN {
                    let c = cases::CaseFile::parse(text, n)?;
                    println!("{n:18} {}", c.description);
                }
            }
            Some(n) => match cases::builtin::builtin_text(&n) {
                Some(t) => print!("{t}"),
                None => anyhow::bail!(
                    "no built-in case `{n}`; built-ins: {}",
                    cases::builtin::builtin_names().join(", ")
                ),
            },
        },
    }
    Ok(())
}

/// A duration given in minutes on the command line: `None` for 0; an error naming the option otherwise.
fn minutes(option: &str, m: f64) -> anyhow::Result<Option<std::time::Duration>> {
    if !(m.is_finite() && m >= 0.0) {
        anyhow::bail!("{option} {m}: expected a number of minutes, 0 or more");
    }
    Ok((m > 0.0).then(|| std::time::Duration::from_secs_f64(60.0 * m)))
}

/// The checkpoint policy of `--checkpoint-every` and `--wall-limit` (minutes), shared by twodt, converge and
/// study.
fn checkpoint_policy(
    every: f64,
    wall_limit: Option<f64>,
    resume: bool,
) -> anyhow::Result<bowwave::twodt::checkpoint::CheckpointPolicy> {
    Ok(bowwave::twodt::checkpoint::CheckpointPolicy {
        every: minutes("--checkpoint-every", every)?,
        resume,
        wall_limit: wall_limit.map(|w| minutes("--wall-limit", w)).transpose()?.flatten(),
        halt_at_step: None,
    })
}

/// A 2D+t run stopped on purpose with its state saved ([`bowwave::twodt::checkpoint::Halted`]) is not a
/// failure: says where it stopped and exits with status 3, which tells a batch script to submit it again.
fn exit_if_halted<T>(r: anyhow::Result<T>) -> anyhow::Result<T> {
    if let Err(e) = &r {
        if let Some(h) = e.downcast_ref::<bowwave::twodt::checkpoint::Halted>() {
            eprintln!("{h}");
            std::process::exit(3);
        }
    }
    r
}
