//! Gathers a study's finished cases into its tables: `jets.csv` (one row per Froude number, every metric),
//! `comparison.csv` and `report.md` (ours against the published jets of the same hull, with the hull file's
//! status beside every row so that a geometry difference is not mistaken for a solver error).

use super::runner::CaseRecord;
use crate::io::atomic::write_atomic;
use crate::reference::{published_jets, PublishedJet};
use crate::twodt::run::metrics_csv;
use std::fmt::Write as _;
use std::path::Path;

/// One compared quantity.
#[derive(Clone, Debug)]
pub struct Comparison {
    pub fr: f64,
    pub quantity: &'static str,
    pub ours: Option<f64>,
    pub published: f64,
    pub our_dx: f64,
    pub published_dx: f64,
    /// Why `ours` is missing, or "".
    pub note: String,
}

impl Comparison {
    /// (ours − published)/published.
    pub fn rel_diff(&self) -> Option<f64> {
        self.ours.map(|o| (o - self.published) / self.published)
    }
}

/// Every finished case that has a published jet of `hull` (by name, e.g. "athena") at its Froude number,
/// with that jet, in the order of the cases: a study that runs one Froude number at several spacings (a
/// convergence study) compares each of them.
pub fn published_for<'a>(hull: &str, recs: &'a [CaseRecord]) -> Vec<(PublishedJet, &'a CaseRecord)> {
    let published: Vec<PublishedJet> = published_jets().into_iter().filter(|p| p.hull == hull).collect();
    recs.iter()
        .filter_map(|r| {
            let p = published.iter().find(|p| (r.spec.fr() - p.fr).abs() < 1e-9)?;
            Some((p.clone(), r))
        })
        .collect()
}

/// Ours against the published value of every quantity Table 10.1/10.2 gives, for every finished case that
/// has a published row.
pub fn comparisons(hull: &str, recs: &[CaseRecord]) -> Vec<Comparison> {
    let mut out = vec![];
    for (p, rec) in published_for(hull, recs) {
        let r = &rec.result;
        let note = match (&r.plunge, &r.blowup) {
            (Some(_), _) => String::new(),
            (None, Some(b)) => format!("stopped early: {b}"),
            (None, None) => format!("no plunge up to x/L = {:.3}", r.x_end_over_l),
        };
        let m = r.plunge.as_ref();
        for (quantity, ours, published) in [
            ("x_plunge_over_l", m.map(|m| m.x_plunge_over_l), p.x_plunge_over_l),
            ("y_plunge_over_l", m.map(|m| m.y_plunge_over_l), p.y_plunge_over_l),
            ("h_pj_over_d", m.map(|m| m.h_pj_over_d), p.h_pj_over_d),
        ] {
            out.push(Comparison {
                fr: p.fr,
                quantity,
                ours,
                published,
                our_dx: r.dx_over_l,
                published_dx: p.dx_over_l,
                note: note.clone(),
            });
        }
    }
    out
}

fn cell(x: Option<f64>) -> String {
    x.map(|v| format!("{v:.6}")).unwrap_or_default()
}

/// Writes `jets.csv`, `comparison.csv` and `report.md` into `out`; `hull_facts` is the report's sentence on
/// the station facts the hull honours and those measured on it.
pub fn write_tables(
    out: &Path,
    study_name: &str,
    hull: &str,
    hull_status: &str,
    hull_facts: &str,
    recs: &[CaseRecord],
    n_cases: usize,
) -> anyhow::Result<()> {
    let results: Vec<_> = recs.iter().map(|r| r.result.clone()).collect();
    write_atomic(&out.join("jets.csv"), metrics_csv(&results).as_bytes())?;
    let comps = comparisons(hull, recs);
    let mut csv =
        String::from("hull,hull_status,fr,quantity,ours,published,rel_diff,our_dx_over_l,published_dx_over_l,note\n");
    for c in &comps {
        writeln!(
            csv,
            "{hull},{hull_status},{},{},{},{},{},{:.3e},{:.3e},{}",
            c.fr,
            c.quantity,
            cell(c.ours),
            c.published,
            cell(c.rel_diff()),
            c.our_dx,
            c.published_dx,
            c.note.replace(',', ";")
        )?;
    }
    write_atomic(&out.join("comparison.csv"), csv.as_bytes())?;
    if recs.iter().any(|r| r.ship3d.is_some()) {
        write_atomic(&out.join("ship3d.csv"), ship3d_csv(recs).as_bytes())?;
    }
    write_atomic(
        &out.join("report.md"),
        report(study_name, hull, hull_status, hull_facts, recs, &comps, n_cases).as_bytes(),
    )?;
    Ok(())
}

/// `ship3d.csv`: one row per case with a 3D run: its cost, the two bow crests, and the first stretch of x/L over
/// which 3D and 2D+t agree within 0.1 D (empty where they agree nowhere; `agreement` lists every stretch).
pub fn ship3d_csv(recs: &[CaseRecord]) -> String {
    let mut csv = String::from(
        "fr,dx_over_l,c0_over_sqrt_gl,particles,hull_ghosts,steps,wall_seconds,travel_over_l,steady,crest_3d_over_d,\
         crest_3d_x_over_l,crest_2dt_over_d,crest_2dt_x_over_l,agree_from_x_over_l,agree_to_x_over_l,agreement,blow_up\n",
    );
    for r in recs {
        let Some(t) = &r.ship3d else { continue };
        let first = t.agreement.first();
        let stretches: Vec<String> = t.agreement.iter().map(|b| format!("{:.3}-{:.3}", b.0, b.1)).collect();
        let _ = writeln!(
            csv,
            "{},{:.6e},{:.4},{},{},{},{:.1},{:.4},{},{},{},{},{},{},{},{},{}",
            r.result.fr,
            t.dx_over_l,
            t.c0_over_sqrt_gl,
            t.particles,
            t.hull_ghosts,
            t.steps,
            t.wall_seconds,
            t.travel_over_l,
            t.steady,
            cell(t.crest_over_d),
            cell(t.crest_x_over_l),
            cell(t.twodt_crest_over_d),
            cell(t.twodt_crest_x_over_l),
            cell(first.map(|b| b.0)),
            cell(first.map(|b| b.1)),
            stretches.join(" "),
            t.blow_up.as_deref().unwrap_or("").replace(',', ";")
        );
    }
    csv
}

/// The report's section on the 3D runs: per case, the crests and where the two models agree, with Fr_x.
fn ship3d_section(s: &mut String, recs: &[CaseRecord]) {
    let runs: Vec<_> = recs
        .iter()
        .filter_map(|r| r.ship3d.as_ref().map(|t| (r.result.fr, t)))
        .collect();
    if runs.is_empty() {
        return;
    }
    let _ = writeln!(
        s,
        "\n## 3D against 2D+t (`ship3d.csv`; each case's maps and tables in `cases/NN-frF/ship3d/`)\n\n\
         Both models at the same spacing, in the same tank (a channel, not open water) and at the same sound speed; \
         η compared column by column across the whole tank, agreement within {} D.\n",
        crate::compare3d::towed_ship::AGREEMENT_OVER_D
    );
    let _ = writeln!(
        s,
        "| Fr | dx/L | particles | steps | wall s | travel/L | bow steady | 3D crest η/D (x/L) | 2D+t crest η/D (x/L) | agree within 0.1 D over x/L (Fr_x) |"
    );
    let _ = writeln!(s, "|{}", "---|".repeat(10));
    for (fr, t) in runs {
        let crest = |h: Option<f64>, x: Option<f64>| match (h, x) {
            (Some(h), Some(x)) => format!("{h:.3} ({x:.3})"),
            _ => "–".into(),
        };
        let bands: Vec<String> = t
            .agreement
            .iter()
            .map(|b| {
                let fr_x = |x: f64| crate::compare3d::towed_ship::fr_x_text(fr, x);
                format!("{:.3}–{:.3} ({}–{})", b.0, b.1, fr_x(b.0), fr_x(b.1))
            })
            .collect();
        let _ = writeln!(
            s,
            "| {fr} | {:.2e} | {} | {} | {:.0} | {:.2} | {} | {} | {} | {} |",
            t.dx_over_l,
            t.particles,
            t.steps,
            t.wall_seconds,
            t.travel_over_l,
            match (&t.blow_up, t.steady) {
                (Some(_), _) => "blew up",
                (None, true) => "yes",
                (None, false) => "no",
            },
            crest(t.crest_over_d, t.crest_x_over_l),
            crest(t.twodt_crest_over_d, t.twodt_crest_x_over_l),
            if bands.is_empty() {
                "nowhere".to_string()
            } else {
                bands.join(", ")
            }
        );
    }
}

/// The Markdown report: cases, comparison, and the published trends checked on our numbers.
pub fn report(
    study_name: &str,
    hull: &str,
    hull_status: &str,
    hull_facts: &str,
    recs: &[CaseRecord],
    comps: &[Comparison],
    n_cases: usize,
) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "# Study `{study_name}`: hull `{hull}` ({hull_status})\n");
    if hull_status != "exact" {
        let _ = writeln!(
            s,
            "**The hull file is an {hull_status}**, not the hull of the published results: differences below \
             mix geometry and solver; read them as such.\n"
        );
    }
    if !hull_facts.is_empty() {
        let _ = writeln!(s, "{hull_facts}\n");
    }
    let _ = writeln!(s, "{} of {} cases finished.\n", recs.len(), n_cases);
    let _ = writeln!(
        s,
        "| Fr | dx/L | particles | steps | CPU s | outcome | x_p/L | y_p/L | Fr_x | H_pj/D | jet particles | Γ/(UD) | L_jet/D | S_jet/(DB) | I_OG/S² | α_G ° | α_VG ° |"
    );
    let _ = writeln!(s, "|{}", "---|".repeat(17));
    for r in recs.iter().map(|r| &r.result) {
        let outcome = match (&r.plunge, &r.blowup) {
            (Some(_), _) => "plunge".to_string(),
            (None, Some(_)) => "stopped early".to_string(),
            (None, None) => format!("no plunge to x/L {:.3}", r.x_end_over_l),
        };
        let outcome = match r.air_over_d {
            Some(a) => format!("{outcome}, with {a} D of air"),
            None => outcome,
        };
        let f = |v: Option<f64>| v.map(|v| format!("{v:.3}")).unwrap_or_else(|| "–".into());
        let m = r.plunge.as_ref();
        let _ = writeln!(
            s,
            "| {} | {:.2e} | {} | {} | {:.0} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.fr,
            r.dx_over_l,
            r.particles,
            r.steps,
            r.cpu_seconds,
            outcome,
            f(m.map(|m| m.x_plunge_over_l)),
            f(m.map(|m| m.y_plunge_over_l)),
            f(m.map(|m| m.fr_x)),
            f(m.map(|m| m.h_pj_over_d)),
            m.map(|m| m.jet_particles.to_string()).unwrap_or_else(|| "–".into()),
            f(m.map(|m| m.gamma_over_ud)),
            f(m.map(|m| m.l_jet_over_d)),
            f(m.map(|m| m.s_jet_over_db)),
            f(m.map(|m| m.i_og_over_s2)),
            f(m.map(|m| m.alpha_g_deg)),
            f(m.map(|m| m.alpha_vg_deg)),
        );
    }
    if recs
        .iter()
        .filter_map(|r| r.result.plunge.as_ref())
        .any(|m| m.jet_particles < RESOLVED_JET_PARTICLES)
    {
        let _ = writeln!(
            s,
            "\nJets of fewer than {RESOLVED_JET_PARTICLES} particles: their Γ, L_jet, S_jet, I_OG, α_G and α_VG are \
             at round-off level (a round-off change of the initial state moved them by 40–150 % and 9° at dx/L 7e-4, \
             docs/reference/twodt.md); read x_p, y_p and H_pj only."
        );
    }
    if comps.is_empty() {
        let _ = writeln!(s, "\nNo published jet data for hull `{hull}` at these Froude numbers.");
    } else {
        let _ = writeln!(
            s,
            "\n## Against the published jets (Marrone 2011, Tables 10.1–10.2; `data/reference/published_jets.csv`)\n"
        );
        let _ = writeln!(
            s,
            "| Fr | quantity | ours | published | difference | our dx/L | published dx/L | note |"
        );
        let _ = writeln!(s, "|---|---|---|---|---|---|---|---|");
        for c in comps {
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} | {:.2e} | {:.2e} | {} |",
                c.fr,
                c.quantity,
                c.ours.map(|v| format!("{v:.4}")).unwrap_or_else(|| "–".into()),
                c.published,
                c.rel_diff()
                    .map(|d| format!("{:+.1} %", 100.0 * d))
                    .unwrap_or_else(|| "–".into()),
                c.our_dx,
                c.published_dx,
                c.note
            );
        }
        if let Some(reading) = super::gap_reading::gap_reading(hull).filter(|_| hull_status != "exact") {
            let _ = writeln!(
                s,
                "\n### What the difference was measured to mean (issue #30)\n\n{reading}"
            );
        }
    }
    let with_air: Vec<String> = recs
        .iter()
        .filter_map(|r| {
            r.result
                .air_over_d
                .map(|a| format!("Fr {} dx/L {:.2e} ({a} D)", r.result.fr, r.result.dx_over_l))
        })
        .collect();
    let air = match with_air.is_empty() {
        true => "the runs are single phase, so what follows the closure in their outputs (the cavity's collapse, \
                 the splash-up) is without the trapped air"
            .to_string(),
        false => format!(
            "the runs are single phase except those with a layer of air, {}, where the trapped air cannot \
             escape sideways as in 3D (`docs/reference/twodt.md`, \"Air\"); in the others what follows the \
             closure (the cavity's collapse, the splash-up) is without the trapped air",
            with_air.join(", ")
        ),
    };
    let _ = writeln!(
        s,
        "\nEvery metric is taken at the plunge, when the jet closes its cavity; {air} (`docs/reference/method.md`, \
         \"Several phases\")."
    );
    ship3d_section(&mut s, recs);
    let _ = writeln!(s, "\n## Published trends, checked on our plunging cases\n");
    for line in trends(recs) {
        let _ = writeln!(s, "- {line}");
    }
    s
}

/// Fewest jet particles whose jet metrics (Γ, L_jet, S_jet, I_OG, α_G, α_VG) the report reads as signal.
/// Measured (docs/reference/twodt.md, session 16): with 15–32 jet particles (dx/L 7e-4) a round-off change of the initial
/// packing moved Γ by 42 %, L_jet by 48 %, I_OG/S² by a factor 2.5 and α_G by 9°, while x_plunge, y_plunge
/// and H_pj moved by 0.1–3.6 %; the thesis's spacings give 190–283. 100 lies between; its own noise is not
/// measured.
pub const RESOLVED_JET_PARTICLES: usize = 100;

/// The trends the thesis reports (§10.1.3), each stated with our numbers: holds, does not hold, or cannot
/// be checked (plunging cases at fewer than two Froude numbers, as in a convergence study of one; for the
/// jet's own metrics, a jet of fewer than [`RESOLVED_JET_PARTICLES`] particles).
pub fn trends(recs: &[CaseRecord]) -> Vec<String> {
    let plunged: Vec<&CaseRecord> = recs.iter().filter(|r| r.result.plunge.is_some()).collect();
    let groups = trend_groups(&plunged);
    if groups.is_empty() {
        let mut froude: Vec<f64> = plunged.iter().map(|r| r.result.fr).collect();
        froude.sort_by(f64::total_cmp);
        froude.dedup();
        return vec![format!(
            "{} plunging case(s) at {} Froude number(s) of the same configuration and spacing: the trends of the \
             thesis (x_plunge and y_plunge grow with Fr, Γ/(UD) grows up to Fr ≈ 0.5 then falls, I_OG/S² falls \
             with Fr, α_G rises from about 40° to 55°) cannot be checked",
            plunged.len(),
            froude.len()
        )];
    }
    let several = groups.len() > 1;
    groups.iter().flat_map(|g| group_trends(g, several)).collect()
}

/// The plunging cases split into series a trend can be read on: the same configuration apart from the Froude
/// number, the spacing and the stop rule, each Froude number once (where one repeats, the series splits by
/// spacing), in increasing Fr; only series of two Froude numbers or more. Regression: the trends were read
/// over every plunging case in the study file's order, so a finer case at a Froude number already present
/// made "x_plunge grows with Fr" fail on cases that hold it (`studies/results/athena-shifting/`).
fn trend_groups<'a>(plunged: &[&'a CaseRecord]) -> Vec<Vec<&'a CaseRecord>> {
    let key = |r: &CaseRecord, with_dx: bool| {
        let mut c = r.spec.config.clone();
        c.fr = 0.0;
        c.until = crate::twodt::config::TwoDtConfig::default().until;
        c.give_up_at = None;
        c.vtk = false;
        c.frames = false;
        if !with_dx {
            c.dx = None;
        }
        serde_json::to_string(&(&r.spec.hull, &c)).unwrap_or_default()
    };
    let mut groups: Vec<(String, Vec<&CaseRecord>)> = vec![];
    for r in plunged {
        let k = key(r, false);
        match groups.iter_mut().find(|g| g.0 == k) {
            Some(g) => g.1.push(r),
            None => groups.push((k, vec![r])),
        }
    }
    let mut out = vec![];
    for (_, g) in groups {
        let mut frs: Vec<f64> = g.iter().map(|r| r.result.fr).collect();
        frs.sort_by(f64::total_cmp);
        let repeats = frs.windows(2).any(|w| w[0] == w[1]);
        let mut split: Vec<(String, Vec<&CaseRecord>)> = vec![];
        for r in g {
            let k = if repeats { key(r, true) } else { String::new() };
            match split.iter_mut().find(|s| s.0 == k) {
                Some(s) => s.1.push(r),
                None => split.push((k, vec![r])),
            }
        }
        for (_, mut s) in split {
            s.sort_by(|a, b| a.result.fr.total_cmp(&b.result.fr));
            let mut f: Vec<f64> = s.iter().map(|r| r.result.fr).collect();
            f.dedup();
            if f.len() >= 2 && f.len() == s.len() {
                out.push(s);
            }
        }
    }
    out
}

/// The trend lines of one series of cases in increasing Fr (`labelled`: name its cases, when there are
/// several series).
fn group_trends(cases: &[&CaseRecord], labelled: bool) -> Vec<String> {
    let plunged: Vec<(f64, &crate::twodt::run::PlungeMetrics)> = cases
        .iter()
        .filter_map(|r| r.result.plunge.as_ref().map(|m| (r.result.fr, m)))
        .collect();
    let series = |f: &dyn Fn(&crate::twodt::run::PlungeMetrics) -> f64| -> Vec<f64> {
        plunged.iter().map(|(_, m)| f(m)).collect()
    };
    let rising = |v: &[f64]| v.windows(2).all(|w| w[1] > w[0]);
    let falling = |v: &[f64]| v.windows(2).all(|w| w[1] < w[0]);
    let list = |v: &[f64]| v.iter().map(|x| format!("{x:.3}")).collect::<Vec<_>>().join(", ");
    let frs: Vec<f64> = plunged.iter().map(|p| p.0).collect();
    let yes = |b: bool| if b { "holds" } else { "does NOT hold" };
    let xp = series(&|m| m.x_plunge_over_l);
    let yp = series(&|m| m.y_plunge_over_l);
    let io = series(&|m| m.i_og_over_s2);
    let ag = series(&|m| m.alpha_g_deg);
    let fewest = plunged.iter().map(|(_, m)| m.jet_particles).min().unwrap_or(0);
    // A jet metric's trend is judged only on jets resolved well enough for it to be more than round-off.
    let jet_verdict = |b: bool| {
        if fewest < RESOLVED_JET_PARTICLES {
            format!(
                "not assessed (a jet of {fewest} particles, fewer than {RESOLVED_JET_PARTICLES}: round-off alone moves \
                 this metric by tens of percent at such jets, docs/reference/twodt.md)"
            )
        } else {
            yes(b).to_string()
        }
    };
    let label = if labelled {
        let idx: Vec<String> = cases.iter().map(|r| r.spec.index.to_string()).collect();
        format!(" (cases {})", idx.join(", "))
    } else {
        String::new()
    };
    vec![
        format!("Fr = {}{label}", list(&frs)),
        format!("x_plunge/L grows with Fr: {} ({})", yes(rising(&xp)), list(&xp)),
        format!("y_plunge/L grows with Fr: {} ({})", yes(rising(&yp)), list(&yp)),
        format!("I_OG/S² falls with Fr: {} ({})", jet_verdict(falling(&io)), list(&io)),
        format!(
            "α_G rises with Fr (thesis: about 40° to 55°): {} ({})",
            jet_verdict(rising(&ag)),
            list(&ag)
        ),
        format!(
            "Γ/(UD): {} (thesis: about linear up to Fr 0.5, then falling)",
            list(&series(&|m| m.gamma_over_ud))
        ),
    ]
}
