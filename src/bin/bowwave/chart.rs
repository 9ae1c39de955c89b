//! `chart`: speed against accuracy (validation cases and 2D+t), stability grids, and redrawing a chart.

use clap::Subcommand;
use std::path::PathBuf;

#[derive(Subcommand)]
pub enum ChartKind {
    /// Error of one validated quantity against CPU seconds for every variant at every resolution, on log axes,
    /// with the Pareto front; writes speed_accuracy.csv and .png.
    SpeedAccuracy {
        /// Built-in case name or case file.
        case: String,
        /// Method variants: delta-sph, molteni, wcsph, wendland, pc, rk4, table (tabulated kernel gradient, the
        /// default), exact-kernel (the Gaussian evaluated at every pair), images / fixed-ghosts (every wall's
        /// straight sides as image ghosts, or the fixed lattice), sun2017 / sun2017-walls / sun2017-leaving /
        /// no-shifting (particle shifting everywhere, near the walls only, there only where the flow leaves
        /// them, or off), alpha=A, delta=D, cfl=C,
        /// h=H (h/dx); names joined by `+` combine, applied left to right (e.g. wendland+h=1.4).
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
        /// Other codes' runs of the same case to draw beside ours: a speed_accuracy.csv whose rows have a `code`
        /// other than bowwave, the same case and the same `quantity` label, each error computed from that code's
        /// outputs (e.g. studies/results/speed-accuracy/dam-break/peers.csv, written by
        /// tools/dam-break-peers/p1c_error.py). They are left out of the Pareto front.
        #[arg(long)]
        peers: Option<PathBuf>,
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
        /// The base options of every run (as `bowwave twodt`'s; each variant changes one of them).
        #[command(flatten, next_help_heading = "2D+t options")]
        config: Box<bowwave::twodt::config::TwoDtConfig>,
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
        /// Other codes' runs to add or replace (as `speed-accuracy --peers`): rows of these codes already in the
        /// csv are replaced by the file's.
        #[arg(long)]
        peers: Option<PathBuf>,
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
    /// Hull sensitivity: gathers a study whose cases are one-parameter hull variants
    /// (`[case.N.hull_variant]`, e.g. studies/athena-sensitivity-fr0.5.toml) into sensitivity.csv, band.md
    /// (each metric's one-at-a-time range, a superposed estimate, and whether the published value lies inside)
    /// and a tornado chart per jet metric; runs nothing.
    Sensitivity {
        /// The study file.
        study: PathBuf,
        /// The study's output folder (default out/study-NAME, as `bowwave study` writes).
        #[arg(long)]
        from: Option<PathBuf>,
        /// Output folder (default: the study's output folder).
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

impl ChartKind {
    pub fn run(self) -> anyhow::Result<()> {
        match self {
            ChartKind::SpeedAccuracy {
                case,
                variants,
                res,
                end,
                quantity,
                peers,
                out,
            } => {
                use bowwave::methods::charts;
                let c = bowwave::cases::load(&case)?;
                // Read before the runs, so that a bad file stops the command before an hour of them.
                let peer_points = peers.as_deref().map(charts::read_peers).transpose()?;
                let (label, mut points) = charts::speed_accuracy(&c, &variants, &res, end, quantity.as_deref())?;
                if let (Some(path), Some(read)) = (&peers, peer_points) {
                    charts::merge_peers(&mut points, (&c.name, &label), path, read)?;
                }
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
            ChartKind::Sensitivity { study, from, out } => {
                use bowwave::methods::sensitivity;
                let st = bowwave::studies::study_file::Study::read(&study)?;
                let from = from.unwrap_or_else(|| PathBuf::from("out").join(format!("study-{}", st.spec.name)));
                let out = out.unwrap_or_else(|| from.clone());
                let mut rows = sensitivity::rows(&st, &from)?;
                // Read before `write` replaces it: the crests of cases whose η map was not kept.
                let carried = sensitivity::crest_from_earlier(&mut rows, &out.join("sensitivity.csv"));
                let frs: Vec<f64> = st.cases.iter().map(|c| c.fr()).collect();
                anyhow::ensure!(
                    frs.windows(2).all(|w| w[0] == w[1]),
                    "{}: a sensitivity study runs one Froude number; it has {frs:?}",
                    study.display()
                );
                let hull = bowwave::geometry::hull_file::HullOffsets::read(&st.hull_path)?
                    .meta
                    .name;
                print!("{}", sensitivity::table(&rows));
                for f in sensitivity::write(&out, &hull, frs[0], &rows, &carried)? {
                    println!("wrote {}", f.display());
                }
            }
            ChartKind::Twodt {
                hull,
                config,
                variants,
                dx,
                reference_dx,
                at,
                out,
            } => {
                use bowwave::methods::twodt_chart;
                let offsets = bowwave::geometry::hull_file::HullOffsets::read(&hull)?;
                let name = offsets.meta.name.clone();
                let surface = std::sync::Arc::new(bowwave::geometry::surface::HullSurface::new(&offsets));
                let base = *config;
                base.check()?;
                let fr = base.fr;
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
            ChartKind::Replot { dir, quantity, peers } => {
                use bowwave::methods::charts;
                let (case, label, mut points) =
                    charts::read_speed_accuracy(&dir.join("speed_accuracy.csv"), quantity.as_deref())?;
                if let Some(path) = &peers {
                    charts::merge_peers(&mut points, (&case, &label), path, charts::read_peers(path)?)?;
                }
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
                use bowwave::methods::charts;
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
        }
        Ok(())
    }
}
