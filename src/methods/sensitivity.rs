//! Hull sensitivity (`bowwave chart sensitivity`): a study whose cases are one-parameter variants of a
//! generated hull (`[case.N.hull_variant]`, issue #30) gathered into one row per case and one tornado chart
//! per jet metric: for each parameter, the range of the metric over its values (the approximation's own value
//! included), against the approximation and the published value. The band is the one-at-a-time range, and a
//! linear superposition of the parameters' extreme effects labelled as an estimate, not a run.

use crate::io::atomic::write_atomic;
use crate::io::csv_table::Table;
use crate::io::plot::{tornado, TornadoBar};
use crate::reference::published_jet;
use crate::studies::collect::RESOLVED_JET_PARTICLES as TRUSTED_JET_PARTICLES;
use crate::studies::runner::{case_dir, collect_finished, CaseRecord};
use crate::studies::study_file::{CaseHull, Study};
use crate::twodt::result::PlungeMetrics;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// One finished case: which parameter it changed (none for the approximation itself) and what it measured.
#[derive(Clone, Debug)]
pub struct Row {
    pub case: usize,
    /// The changed parameter, `""` for the study's own hull.
    pub parameter: String,
    /// Its value in the case and in the approximation.
    pub value: f64,
    pub baseline_value: f64,
    pub plunge: Option<PlungeMetrics>,
    /// The highest free-surface elevation of the passage, η_max/D (the first crest, at the hull), and the x/L
    /// where it is reached, from the case's `eta.csv`: resolved at spacings where the plunge is not.
    pub crest: Option<(f64, f64)>,
    pub particles: usize,
    pub steps: u64,
    pub wall_seconds: f64,
    pub cpu_seconds: f64,
}

impl Row {
    /// The parameter as `sensitivity.csv` names it: `approximation` for the study's own hull.
    pub fn parameter_label(&self) -> &str {
        if self.parameter.is_empty() {
            "approximation"
        } else {
            &self.parameter
        }
    }
}

/// A metric of a case, with its name in the table and its label on a chart.
pub struct Metric {
    pub key: &'static str,
    pub label: &'static str,
    pub get: fn(&Row) -> Option<f64>,
    /// The published value of the same hull and Froude number, if Table 10.1/10.2 gives it.
    pub published: Option<fn(&crate::reference::PublishedJet) -> f64>,
    /// A plunge metric (its jet may be too small to trust, and a case without a plunge has none).
    pub of_plunge: bool,
}

/// The charted metrics: plunge position, jet height and circulation; the highest crest and where it is.
pub fn metrics() -> Vec<Metric> {
    vec![
        Metric {
            key: "x_plunge_over_l",
            label: "x_plunge / L",
            get: |r| r.plunge.as_ref().map(|p| p.x_plunge_over_l),
            published: Some(|j| j.x_plunge_over_l),
            of_plunge: true,
        },
        Metric {
            key: "y_plunge_over_l",
            label: "y_plunge / L",
            get: |r| r.plunge.as_ref().map(|p| p.y_plunge_over_l),
            published: Some(|j| j.y_plunge_over_l),
            of_plunge: true,
        },
        Metric {
            key: "h_pj_over_d",
            label: "H_pj / D",
            get: |r| r.plunge.as_ref().map(|p| p.h_pj_over_d),
            published: Some(|j| j.h_pj_over_d),
            of_plunge: true,
        },
        Metric {
            key: "gamma_over_ud",
            label: "Γ / (U D)",
            get: |r| r.plunge.as_ref().map(|p| p.gamma_over_ud),
            published: None,
            of_plunge: true,
        },
        Metric {
            key: "crest_max_over_d",
            label: "highest crest η_max / D",
            get: |r| r.crest.map(|c| c.0),
            published: None,
            of_plunge: false,
        },
        Metric {
            key: "x_crest_max_over_l",
            label: "x/L of the highest crest",
            get: |r| r.crest.map(|c| c.1),
            published: None,
            of_plunge: false,
        },
    ]
}

/// The rows of a study's finished cases. A case must be the study's own hull or a variant of one generator
/// changing one parameter (a case changing several is refused: a tornado bar is one parameter).
pub fn rows(study: &Study, out: &Path) -> anyhow::Result<Vec<Row>> {
    let recs = collect_finished(study, out);
    anyhow::ensure!(
        !recs.is_empty(),
        "{}: no finished case of {} (run `bowwave study` first)",
        out.display(),
        study.file.display()
    );
    recs.iter().map(|r| row(r, &case_dir(out, &r.spec))).collect()
}

/// The highest η/D over the passage and its x/L, from a case's `eta.csv` (None without one).
fn crest(dir: &Path) -> Option<(f64, f64)> {
    let t = Table::read(&dir.join("eta.csv")).ok()?;
    let (x, e) = (t.column("x_over_l")?, t.column("eta_over_d")?);
    x.iter()
        .zip(&e)
        .filter(|(_, e)| e.is_finite())
        .map(|(x, e)| (*e, *x))
        .max_by(|a, b| a.0.total_cmp(&b.0))
}

/// Fills the highest crest of the rows whose `eta.csv` is gone (a study gathered again from its committed case
/// files, which keep no η map) from an earlier `sensitivity.csv` of the same study, matched by case number,
/// parameter and value. Returns the cases filled, for `band.md` to name. A missing or unreadable earlier table
/// fills nothing.
pub fn crest_from_earlier(rows: &mut [Row], earlier: &Path) -> Vec<usize> {
    let Ok(mut reader) = csv::Reader::from_path(earlier) else {
        return vec![];
    };
    let Ok(header) = reader.headers().cloned() else {
        return vec![];
    };
    let at = |name: &str| header.iter().position(|h| h == name);
    let (Some(c_case), Some(c_par), Some(c_val), Some(c_crest), Some(c_x)) = (
        at("case"),
        at("parameter"),
        at("value"),
        at("crest_max_over_d"),
        at("x_crest_max_over_l"),
    ) else {
        return vec![];
    };
    let mut filled = vec![];
    for rec in reader.records().map_while(Result::ok) {
        let num = |c: usize| rec.get(c).and_then(|v| v.trim().parse::<f64>().ok());
        let (Some(case), Some(crest), Some(x)) = (num(c_case), num(c_crest), num(c_x)) else {
            continue;
        };
        let parameter = rec.get(c_par).unwrap_or("");
        for r in rows.iter_mut().filter(|r| r.crest.is_none() && r.case as f64 == case) {
            let same_parameter = parameter == r.parameter_label();
            let same_value = match num(c_val) {
                Some(v) => v == r.value,
                None => !r.value.is_finite(),
            };
            if same_parameter && same_value {
                r.crest = Some((crest, x));
                filled.push(r.case);
            }
        }
    }
    filled
}

fn row(r: &CaseRecord, dir: &Path) -> anyhow::Result<Row> {
    let (parameter, value, baseline_value) = match &r.spec.hull {
        CaseHull::File(_) => (String::new(), f64::NAN, f64::NAN),
        CaseHull::Variant { generator, set } => {
            anyhow::ensure!(
                set.len() == 1,
                "case {}: a sensitivity case changes one generator parameter; it changes {}",
                r.spec.index,
                set.len()
            );
            let (k, v) = set.iter().next().expect("one entry");
            let base = serde_json::to_value(crate::geometry::parametric::named(generator)?)?;
            let b = base.get(k).and_then(|x| x.as_f64()).unwrap_or(f64::NAN);
            (k.clone(), *v, b)
        }
    };
    Ok(Row {
        case: r.spec.index,
        parameter,
        value,
        baseline_value,
        plunge: r.result.plunge.clone(),
        crest: crest(dir),
        particles: r.result.particles,
        steps: r.result.steps,
        wall_seconds: r.result.wall_seconds,
        cpu_seconds: r.result.cpu_seconds,
    })
}

/// The table (`sensitivity.csv`): one row per case.
pub fn table(rows: &[Row]) -> String {
    let mut s = String::from(
        "case,parameter,value,baseline_value,plunged,x_plunge_over_l,y_plunge_over_l,h_pj_over_d,gamma_over_ud,\
         jet_particles,crest_max_over_d,x_crest_max_over_l,particles,steps,wall_seconds,cpu_seconds\n",
    );
    for r in rows {
        let p = r.plunge.as_ref();
        let f = |g: fn(&PlungeMetrics) -> f64| p.map(|p| format!("{}", g(p))).unwrap_or_default();
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{:.1},{:.1}",
            r.case,
            r.parameter_label(),
            if r.value.is_finite() {
                r.value.to_string()
            } else {
                String::new()
            },
            if r.baseline_value.is_finite() {
                r.baseline_value.to_string()
            } else {
                String::new()
            },
            p.is_some(),
            f(|p| p.x_plunge_over_l),
            f(|p| p.y_plunge_over_l),
            f(|p| p.h_pj_over_d),
            f(|p| p.gamma_over_ud),
            p.map(|p| p.jet_particles.to_string()).unwrap_or_default(),
            r.crest.map(|c| c.0.to_string()).unwrap_or_default(),
            r.crest.map(|c| c.1.to_string()).unwrap_or_default(),
            r.particles,
            r.steps,
            r.wall_seconds,
            r.cpu_seconds
        );
    }
    s
}

/// The measured range of one metric: the approximation's value, each parameter's bar, the one-at-a-time
/// band and the superposed estimate.
pub struct Band {
    pub baseline: f64,
    pub bars: Vec<TornadoBar>,
    /// Smallest and largest value over all cases.
    pub one_at_a_time: (f64, f64),
    /// Baseline plus the sum of every parameter's most negative (most positive) change: an estimate of what
    /// the combinations could span if the effects added up, not a run.
    pub superposed: (f64, f64),
    /// Cases without a value of the metric (their parameter and value): for a plunge metric the cases that did
    /// not plunge, for the crest the cases whose `eta.csv` was not kept.
    pub missing: Vec<String>,
}

/// The band of `metric` over the rows; `None` when the approximation itself did not plunge or is missing.
pub fn band(rows: &[Row], metric: &Metric) -> Option<Band> {
    let base_row = rows.iter().find(|r| r.parameter.is_empty())?;
    let base = (metric.get)(base_row)?;
    let mark = |r: &Row| match &r.plunge {
        Some(p) if metric.of_plunge && p.jet_particles < TRUSTED_JET_PARTICLES => "*",
        _ => "",
    };
    let base_mark = mark(base_row);
    let mut params: Vec<&str> = rows
        .iter()
        .filter(|r| !r.parameter.is_empty())
        .map(|r| r.parameter.as_str())
        .collect();
    params.sort();
    params.dedup();
    let mut bars = vec![];
    let (mut lo, mut hi) = (base, base);
    let (mut sum_neg, mut sum_pos) = (0.0, 0.0);
    let mut missing_cases = vec![];
    for k in params {
        let of_k: Vec<&Row> = rows.iter().filter(|r| r.parameter == k).collect();
        let mut pts: Vec<(f64, f64, &str)> = vec![(of_k[0].baseline_value, base, base_mark)];
        let mut missing_values = vec![];
        for r in of_k {
            match (metric.get)(r) {
                Some(v) => pts.push((r.value, v, mark(r))),
                None => {
                    missing_cases.push(format!("{k} = {}", r.value));
                    missing_values.push(r.value.to_string());
                }
            }
        }
        let (Some(min), Some(max)) = (
            pts.iter().copied().min_by(|a, b| a.1.total_cmp(&b.1)),
            pts.iter().copied().max_by(|a, b| a.1.total_cmp(&b.1)),
        ) else {
            continue;
        };
        lo = lo.min(min.1);
        hi = hi.max(max.1);
        sum_neg += (min.1 - base).min(0.0);
        sum_pos += (max.1 - base).max(0.0);
        let label = |p: (f64, f64, &str)| format!("{} {}{}", short(p.0), format_value(p.1), p.2);
        bars.push(TornadoBar {
            label: match (missing_values.is_empty(), metric.of_plunge) {
                (true, _) => k.to_string(),
                (false, true) => format!("{k} (none at {})", missing_values.join(", ")),
                (false, false) => format!("{k} (not recorded at {})", missing_values.join(", ")),
            },
            low: (min.1, label(min)),
            high: (max.1, label(max)),
        });
    }
    Some(Band {
        baseline: base,
        bars,
        one_at_a_time: (lo, hi),
        superposed: (base + sum_neg, base + sum_pos),
        missing: missing_cases,
    })
}

fn short(v: f64) -> String {
    let s = format!("{v:.3}");
    format!("{}:", s.trim_end_matches('0').trim_end_matches('.'))
}

fn format_value(v: f64) -> String {
    format!("{v:.3}")
}

/// Writes `sensitivity.csv`, `band.md` and a tornado PNG per metric into `dir`; returns the files written.
pub fn write(dir: &Path, hull: &str, fr: f64, rows: &[Row], crest_carried: &[usize]) -> anyhow::Result<Vec<PathBuf>> {
    std::fs::create_dir_all(dir)?;
    let mut files = vec![];
    let csv = dir.join("sensitivity.csv");
    write_atomic(&csv, table(rows).as_bytes())?;
    files.push(csv);
    let published = published_jet(hull, fr);
    let mut md = format!(
        "# {hull} at Fr {fr}: what the unknown geometry moves\n\n{} finished cases (`sensitivity.csv`). Bars: \
         the range of each metric over one parameter's values, the approximation's own included; `*` marks a \
         jet of fewer than {TRUSTED_JET_PARTICLES} particles. The superposed band adds every parameter's \
         largest change of each sign: an estimate of what combinations could span if the effects added up, \
         not a run.\n\n| metric | approximation | one at a time | superposed (estimate) | published | inside one-at-a-time? |\n|---|---|---|---|---|---|\n",
        rows.len()
    );
    let (mut no_plunge, mut no_crest) = (String::new(), String::new());
    for m in metrics() {
        let Some(b) = band(rows, &m) else { continue };
        let pubv = published.as_ref().zip(m.published).map(|(j, f)| f(j));
        let inside = pubv.map(|v| {
            if (b.one_at_a_time.0..=b.one_at_a_time.1).contains(&v) {
                "yes"
            } else if (b.superposed.0..=b.superposed.1).contains(&v) {
                "no (inside the superposed estimate)"
            } else {
                "no"
            }
        });
        let _ = writeln!(
            md,
            "| {} | {:.4} | {:.4} – {:.4} | {:.4} – {:.4} | {} | {} |",
            m.label,
            b.baseline,
            b.one_at_a_time.0,
            b.one_at_a_time.1,
            b.superposed.0,
            b.superposed.1,
            pubv.map(|v| format!("{v:.4}")).unwrap_or_else(|| "–".into()),
            inside.unwrap_or("–")
        );
        // Regression: a case whose crest was not recorded (no `eta.csv`) was listed as one without a plunge.
        let (note, what) = match m.of_plunge {
            true => (
                &mut no_plunge,
                "No plunge, so no plunge metric (left out of their bars)",
            ),
            false => (
                &mut no_crest,
                "No highest crest recorded (no `eta.csv`, none carried; left out of the crest bars)",
            ),
        };
        if !b.missing.is_empty() && note.is_empty() {
            *note = format!("\n{what}: {}.\n", b.missing.join(", "));
        }
        let marks: Vec<(String, f64)> = pubv.map(|v| vec![(format!("published {v:.3}"), v)]).unwrap_or_default();
        let png = dir.join(format!("tornado_{}.png", m.key));
        tornado(
            &png,
            &if m.of_plunge {
                format!(
                    "{hull} Fr {fr}: {} by hull parameter (* jet < {TRUSTED_JET_PARTICLES} particles)",
                    m.label
                )
            } else {
                format!("{hull} Fr {fr}: {} by hull parameter", m.label)
            },
            m.label,
            b.baseline,
            &b.bars,
            &marks,
        )?;
        files.push(png);
    }
    md.push_str(&no_plunge);
    md.push_str(&no_crest);
    if !crest_carried.is_empty() {
        let cases: Vec<String> = crest_carried.iter().map(|c| c.to_string()).collect();
        let _ = write!(
            md,
            "\nThe highest crest of case(s) {} is carried from this folder's earlier `sensitivity.csv`: their `eta.csv`, \
             from which it is read, was not kept with the committed case files.\n",
            cases.join(", ")
        );
    }
    let p = dir.join("band.md");
    write_atomic(&p, md.as_bytes())?;
    files.push(p);
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(case: usize, parameter: &str, value: f64, baseline_value: f64, x: Option<f64>) -> Row {
        Row {
            case,
            parameter: parameter.into(),
            value,
            baseline_value,
            plunge: x.map(|x| PlungeMetrics {
                x_plunge_over_l: x,
                jet_particles: 150,
                ..Default::default()
            }),
            crest: None,
            particles: 1,
            steps: 1,
            wall_seconds: 1.0,
            cpu_seconds: 1.0,
        }
    }

    /// Each bar spans its parameter's values with the approximation's own value included; the one-at-a-time
    /// band is the extreme cases; the superposed estimate adds each parameter's largest change of each sign;
    /// a case without a plunge is named, not charted.
    #[test]
    fn bars_and_bands_of_one_parameter_variants() {
        let rows = vec![
            row(1, "", f64::NAN, f64::NAN, Some(0.30)),
            row(2, "flare_angle", 0.0, 10.0, Some(0.35)),
            row(3, "flare_angle", 40.0, 10.0, Some(0.25)),
            row(4, "trim", 1.0, 0.0, Some(0.32)),
            row(5, "trim", 1.5, 0.0, None),
        ];
        let m = &metrics()[0];
        let b = band(&rows, m).unwrap();
        assert_eq!(b.baseline, 0.30);
        let flare = b.bars.iter().find(|b| b.label == "flare_angle").unwrap();
        assert_eq!((flare.low.0, flare.high.0), (0.25, 0.35));
        assert!(
            flare.low.1.starts_with("40:") && flare.high.1.starts_with("0:"),
            "{} {}",
            flare.low.1,
            flare.high.1
        );
        let trim = b.bars.iter().find(|b| b.label.starts_with("trim")).unwrap();
        assert_eq!(
            trim.label, "trim (none at 1.5)",
            "a value without a plunge is named on its bar"
        );
        assert_eq!((trim.low.0, trim.high.0), (0.30, 0.32));
        assert_eq!(b.one_at_a_time, (0.25, 0.35));
        assert!((b.superposed.0 - 0.25).abs() < 1e-12 && (b.superposed.1 - 0.37).abs() < 1e-12);
        assert_eq!(b.missing, vec!["trim = 1.5".to_string()]);
        let csv = table(&rows);
        assert!(
            csv.lines().nth(1).unwrap().starts_with("1,approximation,,,true,0.3,"),
            "{csv}"
        );
        assert!(csv.lines().nth(5).unwrap().starts_with("5,trim,1.5,0,false,,"), "{csv}");
    }

    /// Regression: `band.md` listed a case that plunged but whose highest crest was not recorded (its `eta.csv`
    /// not kept) under "No plunge", and its crest bar said "none at". Plunge and crest notes are now apart.
    #[test]
    fn missing_crest_is_not_called_no_plunge() {
        let mut rows = vec![
            row(1, "", f64::NAN, f64::NAN, Some(0.30)),
            row(2, "entrance_angle", 19.0, 14.6, Some(0.35)),
            row(3, "trim", 1.5, 0.0, None),
        ];
        rows[0].crest = Some((0.9, 0.15));
        rows[2].crest = Some((0.5, 0.14));
        let crest = metrics().into_iter().find(|m| m.key == "crest_max_over_d").unwrap();
        let b = band(&rows, &crest).unwrap();
        assert_eq!(b.missing, vec!["entrance_angle = 19".to_string()]);
        assert!(b.bars.iter().any(|b| b.label == "entrance_angle (not recorded at 19)"));
        let dir = std::env::temp_dir().join(format!("bowwave-band-notes-{}", std::process::id()));
        write(&dir, "athena", 0.5, &rows, &[]).unwrap();
        let md = std::fs::read_to_string(dir.join("band.md")).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        let no_plunge = md.lines().find(|l| l.starts_with("No plunge")).unwrap();
        assert!(
            no_plunge.contains("trim = 1.5") && !no_plunge.contains("entrance"),
            "{md}"
        );
        let no_crest = md.lines().find(|l| l.starts_with("No highest crest")).unwrap();
        assert!(no_crest.contains("entrance_angle = 19"), "{md}");
    }

    /// A gather from committed case files (no `eta.csv`) takes each case's highest crest from the earlier table
    /// of the same study, matched by case, parameter and value; a row that has its own crest keeps it, and a
    /// row whose value changed since is not filled.
    #[test]
    fn crest_is_carried_from_the_earlier_table_only_for_the_same_case() {
        let dir = std::env::temp_dir().join(format!("bowwave-crest-carry-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let earlier = dir.join("sensitivity.csv");
        let mut old = vec![
            row(1, "", f64::NAN, f64::NAN, Some(0.31)),
            row(2, "trim", 1.5, 0.0, Some(0.2)),
        ];
        old.push(row(3, "trim", 1.0, 0.0, Some(0.22)));
        old[0].crest = Some((0.9, 0.15));
        old[1].crest = Some((0.48, 0.145));
        old[2].crest = Some((0.63, 0.145));
        std::fs::write(&earlier, table(&old)).unwrap();
        let mut now = vec![
            row(1, "", f64::NAN, f64::NAN, Some(0.31)),
            row(2, "trim", 1.5, 0.0, Some(0.2)),
        ];
        now.push(row(3, "trim", 0.5, 0.0, Some(0.3)));
        now.push(row(4, "flare_angle", 20.0, 10.0, Some(0.33)));
        now[3].crest = Some((0.97, 0.16));
        let filled = crest_from_earlier(&mut now, &earlier);
        assert_eq!(filled, vec![1, 2]);
        assert_eq!(now[0].crest, Some((0.9, 0.15)));
        assert_eq!(now[1].crest, Some((0.48, 0.145)));
        assert_eq!(now[2].crest, None);
        assert_eq!(now[3].crest, Some((0.97, 0.16)));
        assert!(crest_from_earlier(&mut now, &dir.join("missing.csv")).is_empty());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
