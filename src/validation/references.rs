//! A case's own references (`[[references]]` in a case file): a measured series beside one of the case's
//! series columns, compared over a window (the mean |ours − reference| with the case's tolerance, and the
//! peaks), and plotted. What a user's experiment gets without a built-in's name.

use super::{check, Check};
use crate::cases::case_file::ReferenceSpec;
use crate::cases::reference_file::load;
use crate::cases::run::RunResult;
use crate::cases::CaseFile;
use crate::io::plot::{line_plot, Series, Style};
use crate::reference::interp;
use std::path::{Path, PathBuf};

/// The reference's points in the column's units and the series' time: (t, value), shifted and scaled.
fn reference_points(case: &CaseFile, r: &ReferenceSpec) -> anyhow::Result<Vec<(f64, f64)>> {
    let (t, v) = load(&r.path(case))?;
    Ok(t.iter().zip(&v).map(|(t, v)| (t + r.shift, v * r.scale)).collect())
}

/// The comparisons of every reference of a run: the mean |ours − reference| over the window (checked when the
/// case gives a tolerance) and the peaks there (reported). Our series is interpolated at the reference's times.
pub fn reference_checks(r: &RunResult) -> Vec<Check> {
    let mut out = vec![];
    for spec in &r.case.references {
        let label = format!("{} vs {}", spec.column, spec.file);
        let (Some(ts), Some(ys)) = (r.series.column(&spec.time), r.series.column(&spec.column)) else {
            continue;
        };
        let pts = match reference_points(&r.case, spec) {
            Ok(p) => p,
            Err(e) => {
                out.push(check(
                    r,
                    &format!("{label}: unreadable ({e})"),
                    f64::NAN,
                    f64::NAN,
                    f64::NAN,
                    spec.tolerance,
                ));
                continue;
            }
        };
        let [a, b] = spec.window.unwrap_or([pts[0].0, pts[pts.len() - 1].0]);
        let inside: Vec<(f64, f64, f64)> = pts
            .iter()
            .filter(|p| p.0 >= a && p.0 <= b)
            .filter_map(|p| interp(&ts, &ys, p.0).map(|o| (p.0, o, p.1)))
            .collect();
        let n = inside.len().max(1) as f64;
        let mean_err = if inside.is_empty() {
            f64::NAN
        } else {
            inside.iter().map(|p| (p.1 - p.2).abs()).sum::<f64>() / n
        };
        let mean_ours = inside.iter().map(|p| p.1).sum::<f64>() / n;
        let mean_ref = inside.iter().map(|p| p.2).sum::<f64>() / n;
        out.push(check(
            r,
            &format!(
                "{label}: mean |ours - ref| over {a}..{b} ({}, {} points)",
                spec.time,
                inside.len()
            ),
            mean_ours,
            mean_ref,
            mean_err,
            spec.tolerance,
        ));
        let peak_ours = ts
            .iter()
            .zip(&ys)
            .filter(|(t, _)| **t >= a && **t <= b)
            .map(|(_, y)| *y)
            .fold(f64::NEG_INFINITY, f64::max);
        let peak_ref = inside.iter().map(|p| p.2).fold(f64::NEG_INFINITY, f64::max);
        out.push(check(
            r,
            &format!("{label}: peak over {a}..{b} (ours at every sample, ref at its points)"),
            peak_ours,
            peak_ref,
            (peak_ours - peak_ref).abs(),
            None,
        ));
    }
    out
}

/// A plot per reference: the column against the reference's time unit, the reference as markers.
pub fn reference_plots(r: &RunResult, dir: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = vec![];
    for (k, spec) in r.case.references.iter().enumerate() {
        let (Some(ts), Some(ys)) = (r.series.column(&spec.time), r.series.column(&spec.column)) else {
            continue;
        };
        let Ok(pts) = reference_points(&r.case, spec) else {
            continue;
        };
        let p = dir.join(format!("{}_reference{}_{}.png", r.case.name, k + 1, spec.column));
        line_plot(
            &p,
            &format!("{}: {} against {}", r.case.name, spec.column, spec.file),
            &spec.time,
            &spec.column,
            &[
                Series {
                    name: "bowwave".into(),
                    points: ts.iter().copied().zip(ys.iter().copied()).collect(),
                    style: Style::Line,
                },
                Series {
                    name: spec.file.clone(),
                    points: pts,
                    style: Style::Markers,
                },
            ],
        )?;
        files.push(p);
    }
    Ok(files)
}
