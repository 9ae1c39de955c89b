//! Speed against accuracy (`bowwave chart speed-accuracy`): a validation case run for every method variant at
//! every resolution; the error of one validated quantity against the CPU seconds, on log axes, with the
//! Pareto front (the runs no other run beats on both). And the stability map (`bowwave chart stability`):
//! the case run over a grid of two method parameters, each run marked stable or not, with the diagnosis.

use crate::cases::run::{run, RunOptions};
use crate::cases::CaseFile;
use crate::io::atomic::write_atomic;
use crate::sph::polyline_wall::GhostKind;
use crate::sph::{
    density_diffusion::DensityDiffusion, integrator::Integrator, kernel::KernelKind, viscosity::Viscosity,
};
use std::path::{Path, PathBuf};

/// A method variant, by name: `delta-sph` (the default scheme), `molteni` (Molteni–Colagrossi diffusion (5.4),
/// no gradient correction), `wcsph` (no density diffusion), `wendland` (Wendland C2 kernel, h = 2 dx),
/// `pc` (predictor–corrector at its default CFL), `table`/`exact-kernel` (tabulated or exact kernel gradient),
/// `images`/`fixed-ghosts` (every wall's straight sides as image ghosts, or the fixed lattice), or `alpha=A`,
/// `delta=D`, `cfl=C`, `h=H` (h/dx) for one parameter.
pub fn apply_variant(case: &mut CaseFile, name: &str) -> anyhow::Result<()> {
    let ghosts = match name {
        "images" => Some(GhostKind::Images),
        "fixed-ghosts" => Some(GhostKind::Fixed),
        _ => None,
    };
    if let Some(kind) = ghosts {
        case.set_ghosts(kind);
        return Ok(());
    }
    let n = &mut case.numerics;
    match name {
        "delta-sph" => n.density_diffusion = DensityDiffusion::DeltaSph,
        "molteni" => n.density_diffusion = DensityDiffusion::MolteniColagrossi,
        "wcsph" => n.density_diffusion = DensityDiffusion::None,
        "wendland" => {
            n.kernel = KernelKind::WendlandC2;
            n.h_over_dx = None;
        }
        "pc" => {
            n.integrator = Integrator::PredictorCorrector;
            n.cfl = None;
        }
        "rk4" => {
            n.integrator = Integrator::Rk4;
            n.cfl = None;
        }
        "table" => n.kernel_table = true,
        "exact-kernel" => n.kernel_table = false,
        "sun2017" => n.shifting = crate::sph::particle_shifting::ParticleShifting::Sun2017,
        other => {
            let (k, v) = other.split_once('=').ok_or_else(|| {
                anyhow::anyhow!(
                    "variant `{other}`: expected delta-sph, molteni, wcsph, wendland, pc, rk4, table, exact-kernel, sun2017, images, fixed-ghosts, alpha=A, delta=D, cfl=C or h=H (h/dx)"
                )
            })?;
            let x: f64 = v
                .parse()
                .ok()
                .filter(|x: &f64| x.is_finite() && *x >= 0.0)
                .ok_or_else(|| anyhow::anyhow!("variant `{other}`: expected a number ≥ 0 after `=`"))?;
            match k {
                "alpha" => n.viscosity = Viscosity::Artificial { alpha: x },
                "delta" => n.delta = x,
                "cfl" if x > 0.0 => n.cfl = Some(x),
                // The case file's range for h/dx (a support of 100 spacings would run for days).
                "h" if (0.5..=4.0).contains(&x) => n.h_over_dx = Some(x),
                _ => anyhow::bail!("variant `{other}`: expected alpha=A, delta=D, cfl=C (C > 0) or h=H (0.5 ≤ H ≤ 4)"),
            }
        }
    }
    Ok(())
}

/// One run of the chart.
#[derive(Clone, Debug)]
pub struct Point {
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

/// Indices of the Pareto front (no other finished run has both less CPU and less error), by CPU.
pub fn pareto_front(points: &[Point]) -> Vec<usize> {
    let ok = |p: &Point| p.error.is_finite() && p.error > 0.0;
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
const CSV_HEADER: [&str; 10] = [
    "case",
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
/// the `quantity` column existed need `quantity` given.
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
        points.push(Point {
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

/// Draws the error against CPU seconds, one line per variant, and the Pareto front.
pub fn plot_speed_accuracy(png: &Path, case: &str, quantity: &str, points: &[Point]) -> anyhow::Result<()> {
    let front = pareto_front(points);
    let mut variants: Vec<&str> = points.iter().map(|p| p.variant.as_str()).collect();
    variants.dedup();
    let mut series: Vec<crate::io::plot::Series> = variants
        .iter()
        .map(|v| crate::io::plot::Series {
            name: v.to_string(),
            points: points
                .iter()
                .filter(|p| p.variant == *v && p.error.is_finite() && p.error > 0.0)
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

    #[test]
    fn variants_set_their_parameter_and_bad_ones_are_refused() {
        let mut c = crate::cases::load("dam-break").unwrap();
        assert!(c.numerics.kernel_table, "the tabulated gradient is the default");
        for v in ["exact-kernel", "h=1.5", "cfl=2.5", "alpha=0.01", "molteni"] {
            apply_variant(&mut c, v).unwrap();
        }
        let n = &c.numerics;
        assert!(!n.kernel_table);
        assert_eq!(n.h_over_dx, Some(1.5));
        assert_eq!(n.cfl, Some(2.5));
        assert_eq!(n.density_diffusion, DensityDiffusion::MolteniColagrossi);
        assert!(
            c.walls.iter().all(|w| w.ghosts == GhostKind::Fixed),
            "fixed ghosts are the default"
        );
        apply_variant(&mut c, "images").unwrap();
        assert!(c.walls.iter().all(|w| w.ghosts == GhostKind::Images));
        apply_variant(&mut c, "fixed-ghosts").unwrap();
        assert!(c.walls.iter().all(|w| w.ghosts == GhostKind::Fixed));
        // h=100 and cfl=0 were accepted (a support of 300 spacings; a zero time step).
        for bad in ["h=0", "h=-1", "h=100", "cfl=0", "cfl=x", "speed=2", "gauss"] {
            let e = apply_variant(&mut c, bad).unwrap_err().to_string();
            assert!(e.contains(bad) && e.contains("expected"), "{e}");
        }
    }
}
