//! A case's own references (`[[references]]` in a case file): a measured series beside one of the case's
//! series columns, compared over a window (the mean |ours − reference| with the case's tolerance; reported: the
//! peaks, the impulses ∫ y dt and the first crossings of half the reference's peak), and plotted. What a user's experiment gets without a built-in's name.

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
        // A wall sensor's peak is held between outputs from every step (`ppeak_`, `pstarpeak_`).
        let peaks = peak_column(&spec.column)
            .and_then(|c| r.series.column(&c))
            .unwrap_or_else(|| ys.clone());
        let window: Vec<usize> = (0..ts.len()).filter(|&k| ts[k] >= a && ts[k] <= b).collect();
        let peak_ours = window.iter().map(|&k| peaks[k]).fold(f64::NEG_INFINITY, f64::max);
        let in_ref: Vec<(f64, f64)> = pts.iter().copied().filter(|p| p.0 >= a && p.0 <= b).collect();
        let peak_ref = in_ref.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
        out.push(check(
            r,
            &format!("{label}: peak over {a}..{b} (ours from every step or sample, ref at its points)"),
            peak_ours,
            peak_ref,
            (peak_ours - peak_ref).abs(),
            None,
        ));
        let ours: Vec<(f64, f64)> = window.iter().map(|&k| (ts[k], ys[k])).collect();
        let (imp_ours, imp_ref) = (trapezoid(&ours), trapezoid(&in_ref));
        out.push(check(
            r,
            &format!(
                "{label}: impulse (integral over {a}..{b}, trapezoidal, in {})",
                spec.time
            ),
            imp_ours,
            imp_ref,
            (imp_ours - imp_ref).abs(),
            None,
        ));
        let level = 0.5 * peak_ref;
        let (cross_ours, cross_ref) = (first_crossing(&ours, level), first_crossing(&in_ref, level));
        out.push(check(
            r,
            &format!(
                "{label}: first crossing of half the reference's peak ({level:.4}), {}",
                spec.time
            ),
            cross_ours,
            cross_ref,
            (cross_ours - cross_ref).abs(),
            None,
        ));
    }
    out
}

/// The peak-between-outputs column of a wall sensor's reading column, if it is one.
fn peak_column(column: &str) -> Option<String> {
    if let Some(n) = column.strip_prefix("pstar_") {
        Some(format!("pstarpeak_{n}"))
    } else {
        column.strip_prefix("p_").map(|n| format!("ppeak_{n}"))
    }
}

/// ∫ y dt of (t, y) points by the trapezoidal rule.
fn trapezoid(p: &[(f64, f64)]) -> f64 {
    p.windows(2).map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0)).sum()
}

/// The first time (t, y) points reach `level`, interpolated linearly between them; NaN if they never do.
fn first_crossing(p: &[(f64, f64)], level: f64) -> f64 {
    if p.first().is_some_and(|q| q.1 >= level) {
        return p[0].0;
    }
    p.windows(2)
        .find(|w| w[0].1 < level && w[1].1 >= level)
        .map_or(f64::NAN, |w| {
            w[0].0 + (level - w[0].1) / (w[1].1 - w[0].1) * (w[1].0 - w[0].0)
        })
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn impulse_and_first_crossing_of_a_ramp() {
        let p: Vec<(f64, f64)> = (0..=10).map(|k| (k as f64 * 0.1, k as f64)).collect();
        assert!((trapezoid(&p) - 5.0).abs() < 1e-12);
        assert!((first_crossing(&p, 2.5) - 0.25).abs() < 1e-12);
        assert!(first_crossing(&p, 11.0).is_nan());
        assert_eq!(peak_column("pstar_P1").as_deref(), Some("pstarpeak_P1"));
        assert_eq!(peak_column("p_P1").as_deref(), Some("ppeak_P1"));
        assert_eq!(peak_column("eta_g"), None);
    }
}
