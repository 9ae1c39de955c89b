//! What a 2D+t run measures: the jet metrics at the plunge and the run's result (written as metrics.json
//! and metrics.csv, recorded in a study's case.json and a checkpoint).

/// Everything measured at the plunge (non-dimensional as named).
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct PlungeMetrics {
    pub x_plunge_over_l: f64,
    pub y_plunge_over_l: f64,
    /// Local Froude number U/√(g x_plunge), x from the stem.
    pub fr_x: f64,
    pub h_pj_over_d: f64,
    /// Crest height minus impact-point height, / D.
    pub fall_over_d: f64,
    pub gamma_over_ud: f64,
    pub cavity_area_over_d2: f64,
    pub l_jet_over_d: f64,
    pub s_jet_over_db: f64,
    pub i_og_over_s2: f64,
    pub y_g_over_d: f64,
    pub z_g_over_d: f64,
    pub v_g_over_u: f64,
    pub w_g_over_u: f64,
    pub alpha_g_deg: f64,
    pub alpha_vg_deg: f64,
    pub jet_particles: usize,
}

/// The result of a run.
#[derive(Clone, Debug, serde::Serialize, serde::Deserialize)]
pub struct TwoDtResult {
    pub hull: String,
    pub fr: f64,
    pub dx_over_l: f64,
    pub dx_coarse_over_l: f64,
    pub c0_over_sqrt_gl: f64,
    pub particles: usize,
    pub steps: u64,
    pub wall_seconds: f64,
    pub cpu_seconds: f64,
    pub x_end_over_l: f64,
    /// Kinetic energy left by the settling, / (M g D).
    pub ke_after_settle: f64,
    /// Largest change of the mean free-surface level of the far field (y > 3W/4) up to the plunge (or the
    /// end), / D.
    pub far_field_eta_over_d: f64,
    /// Largest max|u|/c0 seen at the detection steps.
    pub max_mach: f64,
    /// (total mass at end − at start) / total mass.
    pub mass_change: f64,
    /// Pressure noise at the end: RMS of p minus its kernel-smoothed field, / (ρ g D).
    #[serde(default)]
    pub pressure_noise_over_rho_g_d: f64,
    /// Highest free-surface elevation outside the waterline at the last output, / D: the bow-wave crest
    /// height at the end of the run (the quantity of the 2D+t speed–accuracy chart).
    #[serde(default)]
    pub crest_at_end_over_d: f64,
    pub wall_corrections: u64,
    pub plunged: bool,
    pub plunge: Option<PlungeMetrics>,
    /// Why the run stopped early, if it did.
    pub blowup: Option<String>,
    /// Height of the air layer / D when air was modelled (`--air`); `None`: one phase.
    #[serde(default)]
    pub air_over_d: Option<f64>,
}

/// The metrics rows as CSV: the fields of [`TwoDtResult`] in order, those of the plunge flattened in place
/// (empty when there was no plunge). One header for all rows, taken from a result with a plunge.
pub fn metrics_csv(results: &[TwoDtResult]) -> String {
    let flat = |r: &TwoDtResult| -> Vec<(String, String)> {
        let mut r = r.clone();
        let plunged = r.plunge.is_some();
        let p = r.plunge.take().unwrap_or_default();
        let v = serde_json::to_value(&r).expect("serialisable");
        let pv = serde_json::to_value(&p).expect("serialisable");
        let cell = |x: &serde_json::Value| match x {
            serde_json::Value::String(s) => s.replace(',', ";"),
            serde_json::Value::Null => String::new(),
            other => other.to_string(),
        };
        let mut out = vec![];
        for (k, x) in v.as_object().expect("object") {
            if k == "plunge" {
                for (pk, px) in pv.as_object().expect("object") {
                    out.push((pk.clone(), if plunged { cell(px) } else { String::new() }));
                }
            } else {
                out.push((k.clone(), cell(x)));
            }
        }
        out
    };
    let rows: Vec<Vec<(String, String)>> = results.iter().map(flat).collect();
    let Some(first) = rows.first() else {
        return String::new();
    };
    let mut out = first.iter().map(|c| c.0.as_str()).collect::<Vec<_>>().join(",") + "\n";
    for r in &rows {
        out += &(r.iter().map(|c| c.1.as_str()).collect::<Vec<_>>().join(",") + "\n");
    }
    out
}
