//! Speed against accuracy (`bowwave chart speed-accuracy`): a validation case run for every method variant at
//! every resolution; the error of one validated quantity against the CPU seconds, on log axes, with the
//! Pareto front (the runs no other run beats on both). And the stability map (`bowwave chart stability`):
//! the case run over a grid of two method parameters, each run marked stable or not, with the diagnosis.

use crate::cases::run::{run, RunOptions};
use crate::cases::CaseFile;
use crate::io::atomic::write_atomic;
use std::path::{Path, PathBuf};

pub use crate::cases::variant::apply_variant;

/// The code of this project's own chart points; any other `code` is a peer (another code's runs, drawn
/// beside ours and left out of the Pareto front, which marks the product's options).
pub const OWN_CODE: &str = "bowwave";

/// One run of the chart.
#[derive(Clone, Debug)]
pub struct Point {
    /// Which code ran it: [`OWN_CODE`], or a peer's name (e.g. "DualSPHysics 5.0").
    pub code: String,
    pub variant: String,
    pub res: f64,
    pub cpu_seconds: f64,
    pub particles: usize,
    pub steps: u64,
    /// Error of the chosen quantity; NaN if the run stopped early.
    pub error: f64,
    pub stopped: Option<String>,
}

/// The chosen quantity of a case: the first check whose label contains `quantity` (default: the first).
fn error_of(result: &crate::cases::run::RunResult, quantity: Option<&str>) -> anyhow::Result<(String, f64)> {
    let cs = crate::validation::checks(result)
        .ok_or_else(|| anyhow::anyhow!("case `{}` has no validation checks", result.case.name))?;
    let c = match quantity {
        Some(q) => cs.iter().find(|c| c.quantity.contains(q)).ok_or_else(|| {
            let names: Vec<&str> = cs.iter().map(|c| c.quantity.as_str()).collect();
            anyhow::anyhow!(
                "--quantity `{q}`: no check of `{}` matches; expected one of: {}",
                result.case.name,
                names.join(" | ")
            )
        })?,
        None => cs.first().ok_or_else(|| anyhow::anyhow!("no checks"))?,
    };
    Ok((c.quantity.clone(), c.error))
}

/// Runs every variant at every resolution. CPU seconds are the process's user + system time of the run
/// (all threads), so that they do not depend on how busy the machine was.
pub fn speed_accuracy(
    case: &CaseFile,
    variants: &[String],
    res: &[f64],
    end_time: Option<f64>,
    quantity: Option<&str>,
) -> anyhow::Result<(String, Vec<Point>)> {
    let mut points = vec![];
    let mut label = String::new();
    for v in variants {
        let mut c = case.clone();
        apply_variant(&mut c, v)?;
        for &r in res {
            let cpu0 = crate::process_usage::cpu_seconds();
            let result = run(
                &c,
                &RunOptions {
                    res: Some(r),
                    end_time,
                    ..Default::default()
                },
            )?;
            let cpu = crate::process_usage::cpu_seconds() - cpu0;
            let (name, error) = match &result.blowup {
                None => error_of(&result, quantity)?,
                Some(_) => (String::new(), f64::NAN),
            };
            if !name.is_empty() {
                label = name;
            }
            log::info!("{v} res {r}: error {error:.3e}, CPU {cpu:.1} s");
            points.push(Point {
                code: OWN_CODE.into(),
                variant: v.clone(),
                res: r,
                cpu_seconds: cpu,
                particles: result.n_fluid,
                steps: result.steps,
                error,
                stopped: result.blowup.as_ref().map(|b| b.to_string()),
            });
        }
    }
    Ok((label, points))
}

/// Indices of the Pareto front among this project's runs (no other finished run of ours has both less CPU and
/// less error), by CPU. Peers' points are not on it: the front marks the product's own options.
pub fn pareto_front(points: &[Point]) -> Vec<usize> {
    let ok = |p: &Point| p.code == OWN_CODE && p.error.is_finite() && p.error > 0.0;
    let mut front: Vec<usize> = (0..points.len())
        .filter(|&i| ok(&points[i]))
        .filter(|&i| {
            !points.iter().any(|q| {
                ok(q)
                    && q.cpu_seconds <= points[i].cpu_seconds
                    && q.error <= points[i].error
                    && (q.cpu_seconds < points[i].cpu_seconds || q.error < points[i].error)
            })
        })
        .collect();
    front.sort_by(|&a, &b| points[a].cpu_seconds.total_cmp(&points[b].cpu_seconds));
    front
}

/// Writes speed_accuracy.csv and speed_accuracy.png into `out`.
pub fn write_speed_accuracy(out: &Path, case: &str, quantity: &str, points: &[Point]) -> anyhow::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(out).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", out.display()))?;
    let front = pareto_front(points);
    let mut w = csv::Writer::from_writer(vec![]);
    w.write_record(CSV_HEADER)?;
    for (i, p) in points.iter().enumerate() {
        w.write_record([
            case.to_string(),
            p.code.clone(),
            p.variant.clone(),
            p.res.to_string(),
            p.particles.to_string(),
            p.steps.to_string(),
            format!("{:.3}", p.cpu_seconds),
            p.error.to_string(),
            front.contains(&i).to_string(),
            p.stopped.clone().unwrap_or_default(),
            quantity.to_string(),
        ])?;
    }
    let csv_path = out.join("speed_accuracy.csv");
    write_atomic(&csv_path, &w.into_inner().map_err(|e| anyhow::anyhow!("{e}"))?)?;
    let png = out.join("speed_accuracy.png");
    plot_speed_accuracy(&png, case, quantity, points)?;
    Ok(vec![csv_path, png])
}

/// The columns of speed_accuracy.csv.
const CSV_HEADER: [&str; 11] = [
    "case",
    "code",
    "variant",
    "res",
    "particles",
    "steps",
    "cpu_seconds",
    "error",
    "pareto",
    "stopped",
    "quantity",
];

/// Reads a speed_accuracy.csv back: the case label, the quantity label and the points. Files written before
/// the `quantity` column existed need `quantity` given; rows of files without a `code` column are this
/// project's ([`OWN_CODE`]).
pub fn read_speed_accuracy(path: &Path, quantity: Option<&str>) -> anyhow::Result<(String, String, Vec<Point>)> {
    let ctx = |what: String| anyhow::anyhow!("{}: {what}", path.display());
    let mut r = csv::Reader::from_path(path).map_err(|e| ctx(format!("cannot read: {e}")))?;
    let header: Vec<String> = r
        .headers()
        .map_err(|e| ctx(e.to_string()))?
        .iter()
        .map(String::from)
        .collect();
    let col = |name: &str| header.iter().position(|h| h == name);
    let need = |name: &str| col(name).ok_or_else(|| ctx(format!("no column `{name}`; expected {CSV_HEADER:?}")));
    let (kc, kv, kr, kp, ks, kt, ke, kx) = (
        need("case")?,
        need("variant")?,
        need("res")?,
        need("particles")?,
        need("steps")?,
        need("cpu_seconds")?,
        need("error")?,
        need("stopped")?,
    );
    let kq = col("quantity");
    let kcode = col("code");
    let (mut case, mut label) = (String::new(), quantity.map(String::from));
    let mut points = vec![];
    for (i, rec) in r.records().enumerate() {
        let rec = rec.map_err(|e| ctx(format!("row {}: {e}", i + 1)))?;
        let field = |k: usize, name: &str| -> anyhow::Result<&str> {
            rec.get(k)
                .ok_or_else(|| ctx(format!("row {}: field `{name}` missing", i + 1)))
        };
        let num = |k: usize, name: &str| -> anyhow::Result<f64> {
            let v = field(k, name)?;
            v.parse::<f64>()
                .map_err(|_| ctx(format!("row {}: field `{name}`: expected a number, found `{v}`", i + 1)))
        };
        case = field(kc, "case")?.to_string();
        if label.is_none() {
            label = kq.and_then(|k| rec.get(k)).map(String::from);
        }
        let stopped = field(kx, "stopped")?;
        let code = match kcode {
            Some(k) => field(k, "code")?.to_string(),
            None => OWN_CODE.to_string(),
        };
        anyhow::ensure!(
            !code.is_empty(),
            "{}: row {}: field `code` is empty; expected a code's name",
            path.display(),
            i + 1
        );
        points.push(Point {
            code,
            variant: field(kv, "variant")?.to_string(),
            res: num(kr, "res")?,
            particles: num(kp, "particles")? as usize,
            steps: num(ks, "steps")? as u64,
            cpu_seconds: num(kt, "cpu_seconds")?,
            error: num(ke, "error")?,
            stopped: (!stopped.is_empty()).then(|| stopped.to_string()),
        });
    }
    anyhow::ensure!(!points.is_empty(), "{}: no rows", path.display());
    let label =
        label.ok_or_else(|| ctx("no `quantity` column; give the quantity's label with --quantity".to_string()))?;
    Ok((case, label, points))
}

/// Reads a peers file (a speed_accuracy.csv of other codes' runs): its case, quantity label and points. Every
/// row must name a code other than this project's.
pub fn read_peers(path: &Path) -> anyhow::Result<(String, String, Vec<Point>)> {
    let (case, label, points) = read_speed_accuracy(path, None)?;
    if let Some(i) = points.iter().position(|p| p.code == OWN_CODE) {
        anyhow::bail!(
            "{}: row {}: field `code` is `{OWN_CODE}`; a peers file holds other codes' runs (expected e.g. `DualSPHysics 5.0`)",
            path.display(),
            i + 1
        );
    }
    Ok((case, label, points))
}

/// A peers file must be of the chart's case and measure the chart's quantity, or its points mean nothing beside
/// ours: `ours` and `theirs` are (case, quantity label).
pub fn check_peers(path: &Path, ours: (&str, &str), theirs: (&str, &str)) -> anyhow::Result<()> {
    anyhow::ensure!(
        theirs.0 == ours.0,
        "{}: field `case` is `{}`; expected `{}`, the chart's case",
        path.display(),
        theirs.0,
        ours.0
    );
    anyhow::ensure!(
        theirs.1 == ours.1,
        "{}: field `quantity` is `{}`; expected the chart's quantity `{}`",
        path.display(),
        theirs.1,
        ours.1
    );
    Ok(())
}

/// Adds the peers read by [`read_peers`] from `path` to a chart's `points` of case and quantity `ours`, after
/// [`check_peers`]; rows of a code the file holds that `points` already has are replaced by the file's.
pub fn merge_peers(
    points: &mut Vec<Point>,
    ours: (&str, &str),
    path: &Path,
    (case, label, peers): (String, String, Vec<Point>),
) -> anyhow::Result<()> {
    check_peers(path, ours, (&case, &label))?;
    points.retain(|p| !peers.iter().any(|q| q.code == p.code));
    points.extend(peers);
    Ok(())
}

/// Draws the error against CPU seconds, one line per code and variant (a peer's lines named with its code),
/// and the Pareto front of this project's runs.
pub fn plot_speed_accuracy(png: &Path, case: &str, quantity: &str, points: &[Point]) -> anyhow::Result<()> {
    let front = pareto_front(points);
    let mut lines: Vec<(&str, &str)> = points.iter().map(|p| (p.code.as_str(), p.variant.as_str())).collect();
    lines.dedup();
    let mut series: Vec<crate::io::plot::Series> = lines
        .iter()
        .map(|&(code, v)| crate::io::plot::Series {
            name: if code == OWN_CODE {
                v.to_string()
            } else {
                format!("{code}: {v}")
            },
            points: points
                .iter()
                .filter(|p| p.code == code && p.variant == v && p.error.is_finite() && p.error > 0.0)
                .map(|p| (p.cpu_seconds, p.error))
                .collect(),
            style: crate::io::plot::Style::LineMarkers,
        })
        .collect();
    series.push(crate::io::plot::Series {
        name: "Pareto front".into(),
        points: front
            .iter()
            .map(|&i| (points[i].cpu_seconds, points[i].error))
            .collect(),
        style: crate::io::plot::Style::Line,
    });
    crate::io::plot::log_log_plot(
        png,
        &format!("{case}: error against CPU time (each line: one variant, resolution rising)"),
        "CPU seconds",
        quantity,
        &series,
    )
}

/// One cell of the stability map.
#[derive(Clone, Debug)]
pub struct Cell {
    pub a: String,
    pub b: String,
    pub stable: bool,
    /// Pressure noise at the end (RMS of p minus its kernel-smoothed field) / (ρ0 g L); NaN if stopped.
    pub noise: f64,
    pub diagnosis: String,
}

/// Pressure noise / (ρ0 g L) above which a run that finished counts as unstable ("strong numerical
/// instabilities", thesis §4.1.1): 4× the noise of the default δ-SPH on the dam break at H/dx = 20 and
/// t√(g/H) = 2 (0.051; standard WCSPH: 0.377).
pub const NOISE_LIMIT: f64 = 0.2;

/// Runs the case for every pair (variant of list A, variant of list B), e.g. alpha × delta or cfl ×
/// integrator. A run that stops (NaN, particle out of the domain, time-step collapse) is unstable with its
/// diagnosis; so is one that finishes with a pressure noise above [`NOISE_LIMIT`].
pub fn stability(
    case: &CaseFile,
    a: &[String],
    b: &[String],
    res: f64,
    end_time: Option<f64>,
) -> anyhow::Result<Vec<Cell>> {
    let mut cells = vec![];
    for va in a {
        for vb in b {
            let mut c = case.clone();
            apply_variant(&mut c, vb)?;
            apply_variant(&mut c, va)?;
            let r = run(
                &c,
                &RunOptions {
                    res: Some(res),
                    end_time,
                    ..Default::default()
                },
            )?;
            let scale = c.fluid.rho0 * c.gravity_magnitude() * c.scales.length;
            let noise = match &r.blowup {
                None => r.sim.pressure_noise() / scale,
                Some(_) => f64::NAN,
            };
            let diagnosis = match &r.blowup {
                Some(b) => format!("stopped ({}): {b}", b.reason.short()),
                None if noise > NOISE_LIMIT => format!("pressure noise {noise:.3} ρgL above {NOISE_LIMIT}"),
                None => String::new(),
            };
            cells.push(Cell {
                a: va.clone(),
                b: vb.clone(),
                stable: r.blowup.is_none() && noise <= NOISE_LIMIT,
                noise,
                diagnosis,
            });
        }
    }
    Ok(cells)
}

/// Writes stability.csv and stability.png (a grid of cells, green stable, red unstable).
pub fn write_stability(out: &Path, case: &str, cells: &[Cell]) -> anyhow::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(out).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", out.display()))?;
    let mut csv = String::from("case,a,b,stable,noise_over_rho_g_l,diagnosis\n");
    for c in cells {
        csv += &format!(
            "{case},{},{},{},{:.4e},{}\n",
            c.a,
            c.b,
            c.stable,
            c.noise,
            c.diagnosis.replace(',', ";")
        );
    }
    let csv_path = out.join("stability.csv");
    write_atomic(&csv_path, csv.as_bytes())?;
    // Rows and columns in the order they were given.
    let mut rows: Vec<&str> = vec![];
    let mut cols: Vec<&str> = vec![];
    for c in cells {
        if !rows.contains(&c.a.as_str()) {
            rows.push(&c.a);
        }
        if !cols.contains(&c.b.as_str()) {
            cols.push(&c.b);
        }
    }
    let grid: Vec<Vec<Option<(bool, String)>>> = rows
        .iter()
        .map(|r| {
            cols.iter()
                .map(|c| {
                    cells.iter().find(|x| x.a == *r && x.b == *c).map(|x| {
                        let text = if x.noise.is_finite() {
                            format!("noise {:.3}", x.noise)
                        } else {
                            // "stopped (reason): full diagnosis" → "stopped (reason)".
                            x.diagnosis.split(':').next().unwrap_or("stopped").to_string()
                        };
                        (x.stable, text)
                    })
                })
                .collect()
        })
        .collect();
    let png = out.join("stability.png");
    crate::io::plot::label_grid(
        &png,
        &format!("{case}: pressure noise / (ρgL) at the end; green: stable, red: stopped or noise > {NOISE_LIMIT}"),
        &rows,
        &cols,
        &grid,
    )?;
    Ok(vec![csv_path, png])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(code: &str, variant: &str, cpu: f64, error: f64) -> Point {
        Point {
            code: code.into(),
            variant: variant.into(),
            res: 40.0,
            cpu_seconds: cpu,
            particles: 3200,
            steps: 100,
            error,
            stopped: None,
        }
    }

    #[test]
    fn peers_are_drawn_but_left_off_the_pareto_front() {
        let points = vec![
            point(OWN_CODE, "delta-sph", 10.0, 0.2),
            point(OWN_CODE, "wcsph", 20.0, 0.3),
            // Faster and more accurate than both of ours: still not on our front.
            point("DualSPHysics 5.0", "Wendland", 5.0, 0.1),
        ];
        assert_eq!(pareto_front(&points), vec![0]);
        let dir = std::env::temp_dir().join(format!("bowwave-peers-{}", std::process::id()));
        let files = write_speed_accuracy(&dir, "dam-break", "P1c error", &points).unwrap();
        let (case, label, back) = read_speed_accuracy(&files[0], None).unwrap();
        assert_eq!((case.as_str(), label.as_str()), ("dam-break", "P1c error"));
        assert_eq!(
            back.iter().map(|p| p.code.as_str()).collect::<Vec<_>>(),
            [OWN_CODE, OWN_CODE, "DualSPHysics 5.0"]
        );
        // A peers file must hold other codes only, of the chart's case and quantity.
        let e = read_peers(&files[0]).unwrap_err().to_string();
        assert!(e.contains("row 1") && e.contains("`code`"), "{e}");
        let peers = dir.join("peers.csv");
        std::fs::write(
            &peers,
            "case,code,variant,res,particles,steps,cpu_seconds,error,pareto,stopped,quantity\n\
             dam-break,PySPH 1.0b2,EDAC,40,3200,9000,50.0,0.07,false,,P1c error\n",
        )
        .unwrap();
        let (pc, pl, pp) = read_peers(&peers).unwrap();
        assert_eq!(pp.len(), 1);
        check_peers(&peers, ("dam-break", "P1c error"), (&pc, &pl)).unwrap();
        let e = check_peers(&peers, ("dam-break", "P1 vs Marrone"), (&pc, &pl))
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("peers.csv") && e.contains("`quantity`") && e.contains("P1 vs Marrone"),
            "{e}"
        );
        let e = check_peers(&peers, ("dam-break-mm", "P1c error"), (&pc, &pl))
            .unwrap_err()
            .to_string();
        assert!(e.contains("`case`") && e.contains("dam-break-mm"), "{e}");
        std::fs::remove_dir_all(&dir).ok();
    }
}
