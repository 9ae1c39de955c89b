//! `bowwave converge twodt`: one hull at one Froude number run at several fine spacings dx/L, with the
//! quantities of a 2D+t run as the converging values: the jet metrics at the plunge when every run plunges,
//! and always the bow-wave crest height at the end of the run. The orders, the (C.2) order and the Richardson
//! value are those of [`crate::methods::convergence`]; the published Table 10.1 row, when there is one for this hull and
//! Froude number, is the reference of x_plunge/L, y_plunge/L and H_pj/D (with the hull's status beside it, as
//! an approximated hull's geometry differs from the thesis's).

use crate::driver::Ended;
use crate::geometry::surface::HullSurface;
use crate::io::atomic::write_atomic;
use crate::methods::convergence::{Convergence, Quantity};
use crate::twodt::checkpoint::CheckpointPolicy;
use crate::twodt::run::{run, PlungeMetrics, TwoDtOptions, TwoDtResult};
use crate::twodt::scene::TwoDtConfig;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// A jet metric: its name in the report and how to read it from the plunge metrics.
type Metric = (&'static str, fn(&PlungeMetrics) -> f64);

const JET_METRICS: [Metric; 15] = [
    ("x_plunge/L", |m| m.x_plunge_over_l),
    ("y_plunge/L", |m| m.y_plunge_over_l),
    ("Fr_x", |m| m.fr_x),
    ("H_pj/D", |m| m.h_pj_over_d),
    ("fall height/D", |m| m.fall_over_d),
    ("Gamma/(UD)", |m| m.gamma_over_ud),
    ("L_jet/D", |m| m.l_jet_over_d),
    ("S_jet/(DB)", |m| m.s_jet_over_db),
    ("I_OG/S^2", |m| m.i_og_over_s2),
    ("y_G/D", |m| m.y_g_over_d),
    ("z_G/D", |m| m.z_g_over_d),
    ("v_G/U", |m| m.v_g_over_u),
    ("w_G/U", |m| m.w_g_over_u),
    ("alpha_G (deg)", |m| m.alpha_g_deg),
    ("alpha_VG (deg)", |m| m.alpha_vg_deg),
];

/// The published value of a jet metric for `hull` at `fr` (Table 10.1–10.2), or NaN.
fn published(hull: &str, fr: f64, metric: &str) -> f64 {
    let Some(p) = crate::reference::published_jet(hull, fr) else {
        return f64::NAN;
    };
    match metric {
        "x_plunge/L" => p.x_plunge_over_l,
        "y_plunge/L" => p.y_plunge_over_l,
        "H_pj/D" => p.h_pj_over_d,
        _ => f64::NAN,
    }
}

/// Gathers the quantities of finished runs (coarse to fine) into a [`Convergence`].
pub fn convergence_of(label: &str, results: &[TwoDtResult]) -> Convergence {
    let mut c = Convergence {
        case: label.to_string(),
        res: results.iter().map(|r| 1.0 / r.dx_over_l).collect(),
        wall_seconds: results.iter().map(|r| r.wall_seconds).collect(),
        particles: results.iter().map(|r| r.particles).collect(),
        quantities: vec![],
        notes: vec![],
    };
    let error = |v: f64, reference: f64| ((v - reference) / reference).abs();
    let plunges: Vec<&PlungeMetrics> = results.iter().filter_map(|r| r.plunge.as_ref()).collect();
    if plunges.len() == results.len() {
        for (name, get) in JET_METRICS {
            let reference = results.first().map_or(f64::NAN, |r| published(&r.hull, r.fr, name));
            c.quantities.push(Quantity {
                name: name.to_string(),
                reference,
                values: plunges.iter().map(|m| (get(m), error(get(m), reference))).collect(),
            });
        }
    } else {
        let missing: Vec<String> = results
            .iter()
            .filter(|r| r.plunge.is_none())
            .map(|r| format!("{:.3e}", r.dx_over_l))
            .collect();
        c.notes.push(format!(
            "no plunge at dx/L = {} (up to x/L = {:.3}): the jet metrics are not converged, only the crest height",
            missing.join(", "),
            results.iter().map(|r| r.x_end_over_l).fold(f64::NAN, f64::max)
        ));
    }
    c.quantities.push(Quantity {
        name: "crest height at the end/D".into(),
        reference: f64::NAN,
        values: results.iter().map(|r| (r.crest_at_end_over_d, f64::NAN)).collect(),
    });
    if let Some(r) = results.first().filter(|_| plunges.len() == results.len()) {
        if crate::reference::published_jet(&r.hull, r.fr).is_some() {
            c.notes.push(format!(
                "references are the thesis's Table 10.1 for `{}` at Fr {}; check the hull file's status \
                 (an approximated hull is a different geometry)",
                r.hull, r.fr
            ));
        }
    }
    c
}

/// A finished run of a ladder, as recorded in its folder ([`RECORD`]).
#[derive(serde::Serialize, serde::Deserialize)]
struct LadderRun {
    /// The hull's name and the run's full configuration: a record of another configuration is run again.
    configuration: String,
    result: TwoDtResult,
}

/// File name of a finished ladder run's record in its folder.
pub const RECORD: &str = "converge_run.json";

/// The folder of the run at spacing `dx` in a ladder's output folder.
pub fn run_dir(out: &Path, dx: f64) -> PathBuf {
    out.join(format!("dx-{dx:.3e}"))
}

/// Runs `base` at each fine spacing in `dxs` (coarse to fine), each in its folder [`run_dir`] with its
/// outputs and checkpoints (`policy`), and gathers the convergence. A run recorded as finished with the same
/// configuration is reused, and a run stopped part-way goes on from its checkpoint, so a ladder whose finest
/// runs take hours can be spread over several sessions or batch jobs. A run that stops early ends the study
/// with its diagnosis; one halted at the wall-time limit ends it [`Ended::Halted`].
pub fn converge_twodt(
    hull: Arc<HullSurface>,
    base: &TwoDtConfig,
    dxs: &[f64],
    out: &Path,
    policy: &CheckpointPolicy,
    progress: bool,
) -> anyhow::Result<Ended<Convergence>> {
    anyhow::ensure!(dxs.len() >= 2, "--dx: expected at least two spacings");
    anyhow::ensure!(
        dxs.windows(2).all(|w| w[1] < w[0]) && dxs.iter().all(|&d| d > 0.0),
        "--dx: expected positive spacings from coarse to fine, found {dxs:?}"
    );
    let mut results = vec![];
    for &dx in dxs {
        let mut cfg = base.clone();
        cfg.dx = Some(dx);
        let dir = run_dir(out, dx);
        let configuration = format!("{} | {:?}", hull.meta.name, cfg.physics());
        let recorded = std::fs::read_to_string(dir.join(RECORD))
            .ok()
            .and_then(|t| serde_json::from_str::<LadderRun>(&t).ok())
            .filter(|r| r.configuration == configuration);
        let r = match recorded {
            Some(rec) => {
                log::info!("dx/L {dx}: finished run reused from {}", dir.display());
                rec.result
            }
            None => {
                let opts = TwoDtOptions {
                    progress,
                    plots: true,
                    label: format!("dx/L {dx:.3e} "),
                    checkpoint: policy.clone(),
                    ..TwoDtOptions::quiet(dir.clone())
                };
                let result = match run(hull.clone(), &cfg, &opts)? {
                    Ended::Ran(r) => r,
                    Ended::Halted(h) => return Ok(Ended::Halted(h)),
                };
                let rec = LadderRun { configuration, result };
                write_atomic(&dir.join(RECORD), serde_json::to_string_pretty(&rec)?.as_bytes())?;
                rec.result
            }
        };
        if let Some(b) = &r.blowup {
            anyhow::bail!("the 2D+t run at dx/L = {dx} stopped early: {b}");
        }
        log::info!(
            "dx/L {dx}: {} particles, {} steps, plunge {}",
            r.particles,
            r.steps,
            r.plunged
        );
        results.push(r);
    }
    let label = format!("{} Fr {} (2D+t)", results[0].hull, base.fr);
    Ok(Ended::Ran(convergence_of(&label, &results)))
}

/// The convergence of finished `bowwave twodt` runs, from their folders' `metrics.json`, coarse to fine:
/// runs made one by one (with their own options, or on several machines) gathered into one table. They must
/// be of one hull and Froude number, at decreasing spacings.
pub fn converge_finished(dirs: &[PathBuf]) -> anyhow::Result<Convergence> {
    anyhow::ensure!(dirs.len() >= 2, "--runs: expected at least two run folders");
    let results = dirs
        .iter()
        .map(|d| {
            let path = d.join("metrics.json");
            let text = std::fs::read_to_string(&path).map_err(|e| {
                anyhow::anyhow!("{}: {e} (expected the metrics of a finished twodt run)", path.display())
            })?;
            serde_json::from_str::<TwoDtResult>(&text).map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))
        })
        .collect::<anyhow::Result<Vec<_>>>()?;
    let first = &results[0];
    for (d, r) in dirs.iter().zip(&results) {
        anyhow::ensure!(
            r.hull == first.hull && r.fr == first.fr,
            "{}: {} at Fr {}, expected {} at Fr {} like {}",
            d.display(),
            r.hull,
            r.fr,
            first.hull,
            first.fr,
            dirs[0].display()
        );
    }
    anyhow::ensure!(
        results.windows(2).all(|w| w[1].dx_over_l < w[0].dx_over_l),
        "--runs: expected the folders from coarse to fine, found dx/L {:?}",
        results.iter().map(|r| r.dx_over_l).collect::<Vec<_>>()
    );
    let label = format!("{} Fr {} (2D+t)", first.hull, first.fr);
    Ok(convergence_of(&label, &results))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn result(dx: f64, crest: f64, plunge: Option<f64>) -> TwoDtResult {
        TwoDtResult {
            hull: "athena".into(),
            fr: 0.5,
            dx_over_l: dx,
            dx_coarse_over_l: dx,
            c0_over_sqrt_gl: 1.0,
            particles: 100,
            steps: 10,
            wall_seconds: 1.0,
            cpu_seconds: 1.0,
            x_end_over_l: 0.3,
            ke_after_settle: 0.0,
            far_field_eta_over_d: 0.0,
            max_mach: 0.0,
            mass_change: 0.0,
            pressure_noise_over_rho_g_d: 0.0,
            crest_at_end_over_d: crest,
            wall_corrections: 0,
            plunged: plunge.is_some(),
            plunge: plunge.map(|x| PlungeMetrics {
                x_plunge_over_l: x,
                ..Default::default()
            }),
            blowup: None,
            air_over_d: None,
        }
    }

    #[test]
    fn jet_metrics_converge_only_when_every_run_plunges() {
        // x_plunge = 0.2 + dx: first order towards 0.2; the published Athena Fr 0.5 row is the reference.
        let all: Vec<TwoDtResult> = [4e-3, 2e-3, 1e-3]
            .iter()
            .map(|&d| result(d, 1.0, Some(0.2 + d)))
            .collect();
        let c = convergence_of("t", &all);
        let x = c.quantities.iter().find(|q| q.name == "x_plunge/L").unwrap();
        let published = crate::reference::published_jet("athena", 0.5).unwrap().x_plunge_over_l;
        assert_eq!(x.reference, published);
        assert_eq!(x.values[2].0, 0.201);
        assert!(c.report().contains("order (C.2) 1.00"), "{}", c.report());

        let some = vec![result(4e-3, 0.9, None), result(2e-3, 0.95, Some(0.2))];
        let c = convergence_of("t", &some);
        assert_eq!(c.quantities.len(), 1, "only the crest height");
        assert!(c.notes[0].contains("no plunge at dx/L = 4.000e-3"), "{:?}", c.notes);
    }
}
