//! Speed against accuracy for a 2D+t case (`bowwave chart twodt`): one hull at one Froude number, run for
//! every method variant at every fine spacing to a fixed x/L, with the bow-wave crest height there
//! (highest free surface outside the waterline, / D) as the measured quantity.
//!
//! Why the crest height and not the jet metrics: none of our 2D+t runs of the approximated hulls plunges
//! (docs/reference/twodt.md), so there are no jet metrics to compare; the crest height at a fixed x/L is what every run
//! produces and what the jet grows from. Its reference is the δ-SPH run at the finer `reference_dx` (not a
//! published value): the error measured is the discretisation and method error, not the model's.

use super::charts::Point;
use crate::geometry::surface::HullSurface;
use crate::sph::density_diffusion::DensityDiffusion;
use crate::twodt::run::{run, TwoDtOptions, TwoDtResult};
use crate::twodt::scene::{TwoDtConfig, Until};
use std::path::Path;
use std::sync::Arc;

/// Applies a 2D+t method variant by name: `delta-sph` (the default), `molteni`, `wcsph`, `table` (tabulated
/// kernel gradient, the default) or `exact-kernel`, `cfl=C` (RK4 CFL) or `ratio=R` (graded rows, dx_c = R dx_f).
pub fn apply_twodt_variant(cfg: &mut TwoDtConfig, name: &str) -> anyhow::Result<()> {
    match name {
        "delta-sph" => cfg.diffusion = DensityDiffusion::DeltaSph,
        "molteni" => cfg.diffusion = DensityDiffusion::MolteniColagrossi,
        "wcsph" => cfg.diffusion = DensityDiffusion::None,
        "table" => cfg.exact_kernel = false,
        "exact-kernel" => cfg.exact_kernel = true,
        other => {
            let parsed = other.split_once('=').and_then(|(k, v)| {
                v.parse::<f64>()
                    .ok()
                    .filter(|x| x.is_finite() && *x > 0.0)
                    .map(|x| (k, x))
            });
            match parsed {
                Some(("cfl", x)) => cfg.cfl = Some(x),
                Some(("ratio", x)) if x >= 1.0 => cfg.coarse_ratio = x,
                _ => anyhow::bail!(
                    "2D+t variant `{other}`: expected delta-sph, molteni, wcsph, table, exact-kernel, cfl=C (C > 0) or ratio=R (R ≥ 1)"
                ),
            }
        }
    }
    Ok(())
}

/// The runs of the chart and the reference value they are measured against.
pub struct TwoDtChart {
    pub points: Vec<Point>,
    /// Crest height / D of the reference run.
    pub reference: f64,
    /// Crest height / D of each point, in the order of `points`.
    pub values: Vec<f64>,
}

fn one_run(
    hull: &Arc<HullSurface>,
    base: &TwoDtConfig,
    variant: &str,
    dx: f64,
    at: f64,
) -> anyhow::Result<TwoDtResult> {
    let mut cfg = base.clone();
    apply_twodt_variant(&mut cfg, variant)?;
    cfg.dx = Some(dx);
    cfg.until = Until::X(at);
    cfg.output_dx = (at / 10.0).max(0.005);
    let opts = TwoDtOptions::quiet(std::env::temp_dir().join(format!("bowwave-chart-twodt-{}", std::process::id())));
    let r = run(hull.clone(), &cfg, &opts).and_then(|e| e.ran());
    let _ = std::fs::remove_dir_all(&opts.out_dir);
    r
}

/// Runs the reference (δ-SPH at `reference_dx`) and every variant at every `dxs`, each to x/L = `at`.
pub fn twodt_speed_accuracy(
    hull: Arc<HullSurface>,
    base: &TwoDtConfig,
    variants: &[String],
    dxs: &[f64],
    reference_dx: f64,
    at: f64,
) -> anyhow::Result<TwoDtChart> {
    anyhow::ensure!(
        dxs.iter().all(|&d| d > reference_dx),
        "--reference-dx {reference_dx}: expected finer than every --dx"
    );
    for v in variants {
        apply_twodt_variant(&mut base.clone(), v)?;
    }
    let reference = one_run(&hull, base, "delta-sph", reference_dx, at)?;
    anyhow::ensure!(
        reference.blowup.is_none() && reference.crest_at_end_over_d.is_finite(),
        "the reference run (δ-SPH, dx/L = {reference_dx}) did not finish: {:?}",
        reference.blowup
    );
    let h_ref = reference.crest_at_end_over_d;
    log::info!("reference crest {h_ref:.4} D ({} particles)", reference.particles);
    let mut chart = TwoDtChart {
        points: vec![],
        reference: h_ref,
        values: vec![],
    };
    for v in variants {
        for &dx in dxs {
            let r = one_run(&hull, base, v, dx, at)?;
            let value = r.crest_at_end_over_d;
            let error = match &r.blowup {
                None => ((value - h_ref) / h_ref).abs(),
                Some(_) => f64::NAN,
            };
            log::info!(
                "{v} dx {dx}: crest {value:.4} D, error {error:.3e}, CPU {:.1} s",
                r.cpu_seconds
            );
            chart.points.push(Point {
                code: super::charts::OWN_CODE.into(),
                variant: v.clone(),
                res: 1.0 / dx,
                cpu_seconds: r.cpu_seconds,
                particles: r.particles,
                steps: r.steps,
                error,
                stopped: r.blowup.clone(),
            });
            chart.values.push(value);
        }
    }
    Ok(chart)
}

/// Writes `speed_accuracy.csv`/`.png` (as the case charts) and `crest.csv` (every run's crest height and the
/// reference) into `out`.
pub fn write_twodt_chart(out: &Path, label: &str, at: f64, chart: &TwoDtChart) -> anyhow::Result<()> {
    let quantity = format!("|crest - crest_ref|/crest_ref at x/L = {at}");
    super::charts::write_speed_accuracy(out, label, &quantity, &chart.points)?;
    let mut csv = String::from("variant,dx_over_l,crest_over_d,reference_crest_over_d\n");
    for (p, v) in chart.points.iter().zip(&chart.values) {
        csv += &format!("{},{},{v},{}\n", p.variant, 1.0 / p.res, chart.reference);
    }
    crate::io::atomic::write_atomic(&out.join("crest.csv"), csv.as_bytes())?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn twodt_variants_set_their_field_and_bad_names_are_refused() {
        let mut c = TwoDtConfig::default();
        assert!(!c.exact_kernel, "the tabulated kernel gradient is the default");
        for v in ["wcsph", "exact-kernel", "cfl=2.5", "ratio=1.5"] {
            apply_twodt_variant(&mut c, v).unwrap();
        }
        assert_eq!(c.diffusion, DensityDiffusion::None);
        assert!(c.exact_kernel);
        assert_eq!(c.cfl, Some(2.5));
        assert_eq!(c.coarse_ratio, 1.5);
        for bad in ["wendland", "ratio=0.5", "cfl=-1", "cfl=x", "speed=2"] {
            let e = apply_twodt_variant(&mut c, bad).unwrap_err().to_string();
            assert!(e.contains(bad) && e.contains("expected"), "{e}");
        }
    }
}
