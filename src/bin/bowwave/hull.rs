//! `hull`: check, import, generate, draw a hull file, or write the Wigley hull.

use clap::Subcommand;
use std::path::PathBuf;

#[derive(Subcommand)]
pub enum HullAction {
    /// Hydrostatics from the spline surface (displacement, Cb, Cp, Cm, Cwp, LCB, girths) beside the declared
    /// particulars; warns where they differ by more than 2 %.
    Check {
        /// Hull offsets file (CSV, see docs/reference/hull-format.md).
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
        /// Number of stations, stem and stern included (4 to 2000; the shipped files have 41).
        #[arg(long, default_value_t = bowwave::geometry::parametric::STATIONS)]
        stations: usize,
        /// Points per station, keel to deck (3 to 2000).
        #[arg(long, default_value_t = bowwave::geometry::parametric::POINTS)]
        points: usize,
        /// Output file (default hulls/NAME.csv).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Override a generator parameter, `key=value` (repeatable; keys as in the file's `# generator:` line,
        /// e.g. `flare_angle=20`, `trim=1` or `x_entry=0.03`; their meaning and units are in docs/reference/hull-format.md)
        /// for sensitivity studies. The hull is then labelled a variant.
        #[arg(long = "set", value_name = "KEY=VALUE")]
        set: Vec<String>,
    },
    /// Write the sections a 2D+t run sees, for another code to run the same deforming section (e.g.
    /// tools/pysph-2dt): at x/L = FROM, FROM + STEP, … ≤ TO, the section at POINTS values of the girth ξ
    /// (uniform, keel 0 to deck 1) with its x-derivatives at fixed ξ (units of L; the wall velocity is
    /// U (y_x, z_x), its acceleration U² (y_xx, z_xx)/L). CSV columns x_over_l, k, xi, y_over_l, z_over_l,
    /// y_x, z_x, y_xx, z_xx.
    Sections {
        /// Hull offsets file.
        file: PathBuf,
        /// First x/L.
        #[arg(long, default_value_t = 0.0)]
        from: f64,
        /// Last x/L.
        #[arg(long, default_value_t = 0.6)]
        to: f64,
        /// Step in x/L.
        #[arg(long, default_value_t = 1e-3)]
        step: f64,
        /// Girth points per section (2 to 2000).
        #[arg(long, default_value_t = 401)]
        points: usize,
        /// Output CSV file.
        #[arg(long)]
        out: PathBuf,
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

/// The most stations (and points per station) a generated or imported hull may ask for: the shipped hulls
/// have 21–41 stations and 31 points, and the spline surface gains nothing from thousands more, while
/// `--stations 100000000` ran for minutes without a word before it was capped.
const MAX_STATIONS: usize = 2000;

fn check_count(flag: &str, n: usize, least: usize) -> anyhow::Result<()> {
    anyhow::ensure!(
        (least..=MAX_STATIONS).contains(&n),
        "{flag}: expected {least} to {MAX_STATIONS}, got {n}"
    );
    Ok(())
}

/// Writes a hull file atomically after reading its text back through the file's own checks, so that nothing
/// is written that `hull check` or a run would refuse (an import at a wrong `--length`, or a generator
/// override that folds a section).
fn write_checked(out: &std::path::Path, h: &bowwave::geometry::hull_file::HullOffsets) -> anyhow::Result<()> {
    let text = h.to_csv();
    bowwave::geometry::hull_file::HullOffsets::parse(&text, &out.display().to_string())?;
    bowwave::io::atomic::write_atomic(out, text.as_bytes())?;
    Ok(())
}

impl HullAction {
    pub fn run(self) -> anyhow::Result<()> {
        match self {
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
                check_count("--stations", stations, 4)?;
                let xs: Vec<f64> = (0..stations).map(|i| (i as f64 + 0.5) / stations as f64).collect();
                let opts = bowwave::geometry::stl::ImportOptions {
                    name,
                    stations: xs,
                    length_m: length,
                    stem_at_max_x,
                    transom,
                };
                let h = bowwave::geometry::stl::import_stl(&stl, &opts)?;
                write_checked(&out, &h)?;
                println!("wrote {} ({} stations)", out.display(), h.stations.len());
            }
            HullAction::Generate {
                hull,
                stations,
                points,
                out,
                set,
            } => {
                check_count("--stations", stations, 4)?;
                check_count("--points", points, 3)?;
                let (spec, cb, h) = bowwave::geometry::parametric::generate(&hull, &set, stations, points)?;
                let out = out.unwrap_or_else(|| PathBuf::from("hulls").join(format!("{hull}.csv")));
                write_checked(&out, &h)?;
                println!(
                    "wrote {} (Cb = {cb:.4}, target {:.4}, n_mid = {:.3})",
                    out.display(),
                    spec.target_cb,
                    spec.n_mid
                );
                let facts =
                    bowwave::geometry::station_facts::measure(&bowwave::geometry::surface::HullSurface::new(&h));
                println!("measured: {facts}");
                if let Some(a) = h.meta.notes.get("attitude") {
                    println!("attitude: {a}");
                }
            }
            HullAction::Sections {
                file,
                from,
                to,
                step,
                points,
                out,
            } => {
                check_count("--points", points, 2)?;
                anyhow::ensure!(
                    step > 0.0 && step.is_finite() && from.is_finite() && to.is_finite() && to >= from,
                    "--from, --to, --step: expected from ≤ to and a positive step, got {from}, {to}, {step}"
                );
                let h = bowwave::geometry::hull_file::HullOffsets::read(&file)?;
                let s = bowwave::geometry::surface::HullSurface::new(&h);
                let cols = [
                    "x_over_l", "k", "xi", "y_over_l", "z_over_l", "y_x", "z_x", "y_xx", "z_xx",
                ];
                let mut t = bowwave::io::csv_table::Table::new(cols.iter().map(|c| c.to_string()).collect());
                let n = ((to - from) / step + 1e-9).floor() as usize;
                for i in 0..=n {
                    let x = from + i as f64 * step;
                    let Some(c) = s.curve(x) else { continue };
                    for k in 0..points {
                        let xi = k as f64 / (points - 1) as f64;
                        let p = c.point(xi);
                        t.push(vec![x, k as f64, xi, p.y, p.z, p.y_x, p.z_x, p.y_xx, p.z_xx]);
                    }
                }
                t.write(&out)?;
                println!(
                    "wrote {} ({} sections of {points} points)",
                    out.display(),
                    t.rows.len() / points
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
                check_count("--stations", stations, 4)?;
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
        }
        Ok(())
    }
}
