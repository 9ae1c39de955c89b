//! The study's figures: jet characteristics against Fr with the published points where they exist (thesis
//! Figs. 10.10–10.12), the breaking wave at the plunge for every Froude number on one sheet (Fig. 10.9), and
//! the reconstructed steady wave pattern η(x, y) of each case with Fr_x marked along the hull (Figs.
//! 10.13–10.14, 10.18).

use super::collect::RESOLVED_JET_PARTICLES;
use super::runner::{case_dir, CaseRecord};
use crate::analysis::wave_pattern::{eta_field, tenth_contours};
use crate::io::csv_table::Table;
use crate::io::plot::{self, ScatterPanel, Series, Style};
use crate::reference::PublishedJet;
use crate::twodt::run::PlungeMetrics;
use std::path::{Path, PathBuf};

/// A metric of the plunge, read from the metrics.
type Metric = fn(&PlungeMetrics) -> f64;

/// One figure of a metric against Fr.
struct MetricPlot {
    file: &'static str,
    title: &'static str,
    ylabel: &'static str,
    /// (legend, metric) pairs drawn as ours.
    ours: Vec<(&'static str, Metric)>,
    /// The published value of the same quantity, if Table 10.1/10.2 gives it.
    published: Option<fn(&PublishedJet) -> f64>,
}

fn metric_plots() -> Vec<MetricPlot> {
    vec![
        MetricPlot {
            file: "plunge_x.png",
            title: "Longitudinal position of the plunge point (Fig. 10.10 left)",
            ylabel: "x_plunge / L",
            ours: vec![("bowwave", |m| m.x_plunge_over_l)],
            published: Some(|p| p.x_plunge_over_l),
        },
        MetricPlot {
            file: "plunge_fr_x.png",
            title: "Local Froude number at the plunge point (Fig. 10.10 middle)",
            ylabel: "Fr_x = U / sqrt(g x_plunge)",
            ours: vec![("bowwave", |m| m.fr_x)],
            published: Some(|p| p.fr / p.x_plunge_over_l.sqrt()),
        },
        MetricPlot {
            file: "circulation.png",
            title: "Circulation around the nascent cavity (Fig. 10.10 right)",
            ylabel: "Γ / (U D)",
            ours: vec![("bowwave", |m| m.gamma_over_ud)],
            published: None,
        },
        MetricPlot {
            file: "plunge_y.png",
            title: "Transverse position of the plunge point (Table 10.1)",
            ylabel: "y_plunge / L",
            ours: vec![("bowwave", |m| m.y_plunge_over_l)],
            published: Some(|p| p.y_plunge_over_l),
        },
        MetricPlot {
            file: "wave_height.png",
            title: "Bow-wave height at the plunge (Table 10.1)",
            ylabel: "H_pj / D",
            ours: vec![("bowwave", |m| m.h_pj_over_d)],
            published: Some(|p| p.h_pj_over_d),
        },
        MetricPlot {
            file: "jet_length.png",
            title: "Jet length (Fig. 10.11 left)",
            ylabel: "L_jet / D",
            ours: vec![("bowwave", |m| m.l_jet_over_d)],
            published: None,
        },
        MetricPlot {
            file: "jet_area.png",
            title: "Jet area (Fig. 10.11 middle)",
            ylabel: "S_jet / (D B)",
            ours: vec![("bowwave", |m| m.s_jet_over_db)],
            published: None,
        },
        MetricPlot {
            file: "jet_inertia.png",
            title: "Jet moment of inertia about its centre of mass (Fig. 10.11 right)",
            ylabel: "I_OG / S_jet²",
            ours: vec![("bowwave", |m| m.i_og_over_s2)],
            published: None,
        },
        MetricPlot {
            file: "jet_centre.png",
            title: "Jet centre of mass (Fig. 10.12 left)",
            ylabel: "coordinate / D",
            ours: vec![("y_G / D", |m| m.y_g_over_d), ("z_G / D", |m| m.z_g_over_d)],
            published: None,
        },
        MetricPlot {
            file: "jet_velocity.png",
            title: "Jet centre-of-mass velocity (Fig. 10.12 middle)",
            ylabel: "velocity / U",
            ours: vec![("v_G / U", |m| m.v_g_over_u), ("w_G / U", |m| m.w_g_over_u)],
            published: None,
        },
        MetricPlot {
            file: "jet_angles.png",
            title: "Impact angles (Fig. 10.12 right)",
            ylabel: "degrees to the horizontal",
            ours: vec![
                ("α_G (jet axis)", |m| m.alpha_g_deg),
                ("α_VG (velocity)", |m| m.alpha_vg_deg),
            ],
            published: None,
        },
    ]
}

/// Writes every figure into `out`; returns the files written. Figures whose data are missing (no plunging
/// case) are still drawn with the published points, so the sheet of figures is always complete.
pub fn write_all(out: &Path, hull: &str, recs: &[CaseRecord], study_out: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = vec![];
    let published: Vec<PublishedJet> = crate::reference::published_jets()
        .into_iter()
        .filter(|p| p.hull == hull)
        .collect();
    for mp in metric_plots() {
        let mut series: Vec<Series> = vec![];
        for (name, f) in &mp.ours {
            let points: Vec<(f64, f64)> = recs
                .iter()
                .filter_map(|r| r.result.plunge.as_ref().map(|m| (r.result.fr, f(m))))
                .collect();
            let name = if points.is_empty() {
                format!("{name} (ours: no plunging case)")
            } else {
                format!("{name} (ours)")
            };
            // The report distrusts jets of fewer than RESOLVED_JET_PARTICLES: mark them on the plot too.
            let thin: Vec<(f64, f64)> = recs
                .iter()
                .filter_map(|r| r.result.plunge.as_ref().map(|m| (r.result.fr, m)))
                .filter(|(_, m)| m.jet_particles < RESOLVED_JET_PARTICLES)
                .map(|(fr, m)| (fr, f(m)))
                .collect();
            series.push(Series {
                name,
                points,
                style: Style::LineMarkers,
            });
            if !thin.is_empty() {
                series.push(Series {
                    name: format!("jet < {RESOLVED_JET_PARTICLES} particles: not trusted"),
                    points: thin,
                    style: Style::Markers,
                });
            }
        }
        if let Some(f) = mp.published {
            if !published.is_empty() {
                series.push(Series {
                    name: format!("Marrone 2011, {hull}"),
                    points: published.iter().map(|p| (p.fr, f(p))).collect(),
                    style: Style::Markers,
                });
            }
        }
        let path = out.join(mp.file);
        plot::line_plot(&path, mp.title, "Fr = U / sqrt(g L)", mp.ylabel, &series)?;
        files.push(path);
    }
    if let Some(p) = snapshot_sheet(out, recs, study_out)? {
        files.push(p);
    }
    files.extend(wave_patterns(out, recs, study_out)?);
    Ok(files)
}

/// All cases' bow regions at the plunge (or at the end, without one) on one sheet, particles coloured by
/// initial depth with the two top rows marked (thesis Figs. 10.7 and 10.9).
fn snapshot_sheet(out: &Path, recs: &[CaseRecord], study_out: &Path) -> anyhow::Result<Option<PathBuf>> {
    let mut panels = vec![];
    for r in recs {
        let dir = case_dir(study_out, &r.spec);
        let (Ok(parts), Ok(wall)) = (
            Table::read(&dir.join("snapshot.csv")),
            Table::read(&dir.join("snapshot_wall.csv")),
        ) else {
            continue;
        };
        let y = parts.column("y_over_l").unwrap_or_default();
        let z = parts.column("z_over_l").unwrap_or_default();
        let mark = parts.column("mark").unwrap_or_default();
        let res = &r.result;
        let d = 2.0 * res.dx_over_l.max(1e-9);
        let zmax = z.iter().copied().fold(0.0, f64::max) + d;
        let (y_hi, title) = match &res.plunge {
            Some(m) => (
                (m.y_plunge_over_l * 1.3).max(1e-3),
                format!("Fr {}: plunge at x/L = {:.3}", res.fr, m.x_plunge_over_l),
            ),
            None => (
                y.iter().copied().fold(0.0, f64::max).min(0.12),
                format!("Fr {}: no plunge, x/L = {:.3}", res.fr, res.x_end_over_l),
            ),
        };
        let z_lo = -0.4 * zmax.max(0.01);
        // From just inside the hull side at the lowest level drawn.
        let y_lo = wall
            .rows
            .iter()
            .filter(|p| p[1] >= z_lo && p[1] <= zmax)
            .map(|p| p[0])
            .fold(f64::INFINITY, f64::min);
        let y_lo = if y_lo.is_finite() {
            (y_lo - 0.1 * (y_hi - y_lo)).max(0.0)
        } else {
            0.0
        };
        let walls = vec![wall
            .rows
            .iter()
            .map(|p| (p[0], p[1]))
            .filter(|p| p.1 <= zmax && p.1 >= z_lo)
            .collect()];
        panels.push(ScatterPanel {
            title,
            points: y.into_iter().zip(z).collect(),
            values: mark,
            walls,
            range: (y_lo, y_hi, z_lo, zmax),
        });
    }
    if panels.is_empty() {
        return Ok(None);
    }
    let path = out.join("snapshots.png");
    let columns = if panels.len() > 4 { 2 } else { 1 };
    plot::scatter_sheet(
        &path,
        "Bow wave at the plunge (y/L across, z/L up; top two rows red and yellow)",
        &panels,
        columns,
        900,
    )?;
    Ok(Some(path))
}

/// The file of a case's wave-pattern map: `wave_pattern_frF.png`, or, where several finished cases share that
/// Froude number (hull variants, method variants), `wave_pattern_frF_caseNN.png`, so that none overwrites another.
fn wave_pattern_name(frs: &[f64], fr: f64, index: usize) -> String {
    if frs.iter().filter(|&&f| f == fr).count() > 1 {
        format!("wave_pattern_fr{fr:.3}_case{index:02}.png")
    } else {
        format!("wave_pattern_fr{fr:.3}.png")
    }
}

/// The steady wave pattern η(x, y)/D of each case from its η(y) profiles at every output x/L (each section's
/// free surface placed at x = U t + x0), with contours every 0.1 D and Fr_x = U/√(g x) marked along the top.
fn wave_patterns(out: &Path, recs: &[CaseRecord], study_out: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = vec![];
    let frs: Vec<f64> = recs.iter().map(|o| o.result.fr).collect();
    for r in recs {
        let Ok(t) = Table::read(&case_dir(study_out, &r.spec).join("eta.csv")) else {
            continue;
        };
        let (Some(x), Some(y), Some(eta)) = (t.column("x_over_l"), t.column("y_over_l"), t.column("eta_over_d")) else {
            continue;
        };
        let Some(mut field) = eta_field(&x, &y, &eta) else {
            continue;
        };
        // Crop the calm far field: up to 1.3 × the farthest bin disturbed by more than 0.02 D.
        let disturbed = field
            .values
            .iter()
            .filter_map(|col| col.iter().rposition(|v| v.abs() > 0.02))
            .max()
            .unwrap_or(0);
        let keep = ((disturbed as f64 * 1.3) as usize + 2).min(field.values[0].len());
        for col in field.values.iter_mut() {
            col.truncate(keep);
        }
        let segs = tenth_contours(&field, -5, 15);
        let fr = r.result.fr;
        let ticks: Vec<(f64, String)> = [4.0, 3.0, 2.0, 1.5, 1.2, 1.0, 0.8, 0.7, 0.6, 0.5, 0.4]
            .iter()
            .map(|&fx: &f64| ((fr / fx).powi(2), format!("Fr_x {fx}")))
            .collect();
        let path = out.join(wave_pattern_name(&frs, fr, r.spec.index));
        plot::field_map(
            &path,
            &format!("Wave pattern η/D, Fr = {fr} (contours every 0.1 D)"),
            ("x / L from the stem", "y / L from the centre plane"),
            &field,
            (-0.3, 1.0),
            &segs,
            &ticks,
            (1400, 700),
        )?;
        files.push(path);
    }
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::wave_pattern_name;

    /// Regression: a study with several cases at one Froude number (the sensitivity sweeps, the shifting
    /// study) wrote every case's map to the same `wave_pattern_frF.png`, each overwriting the last.
    #[test]
    fn cases_at_one_froude_number_get_a_wave_pattern_each() {
        let frs = [0.5, 0.64, 0.5];
        assert_eq!(wave_pattern_name(&frs, 0.5, 1), "wave_pattern_fr0.500_case01.png");
        assert_eq!(wave_pattern_name(&frs, 0.5, 3), "wave_pattern_fr0.500_case03.png");
        assert_eq!(wave_pattern_name(&frs, 0.64, 2), "wave_pattern_fr0.640.png");
    }
}
