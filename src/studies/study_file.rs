//! The study file: a TOML description of a Froude sweep (hull, Froude numbers, resolution rule, domain and
//! model options, where to stop, which outputs), resolved into one [`CaseSpec`] per Froude number. Every error
//! names the file, the field and what was expected. The fields and their defaults are documented in
//! `docs/studies.md`.

use crate::input_error::{parse_toml, read_text, InputError};
use crate::twodt::scene::{auto_dx, estimated_hpj_over_d, ConfigOption, TwoDtConfig, Until};
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// The study file as written.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StudyFile {
    /// Name of the study (output folder `out/study-NAME` by default).
    pub name: String,
    #[serde(default)]
    pub description: String,
    /// Hull offsets file, relative to the study file.
    pub hull: PathBuf,
    /// Ship Froude numbers U/√(gL), one case each.
    pub froude: Vec<f64>,
    pub resolution: Resolution,
    #[serde(default)]
    pub model: Model,
    #[serde(default)]
    pub stop: Stop,
    #[serde(default)]
    pub outputs: Outputs,
}

/// How dx_f/L is chosen: exactly one of `dx` (one value per Froude number), `rule = "auto"` (H_pj/dx > 20,
/// eq. 10.9, with H_pj estimated from Table 10.1) or `level`.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Resolution {
    pub dx: Option<Vec<f64>>,
    pub rule: Option<String>,
    pub level: Option<Level>,
}

/// Named resolution levels, as the ratio H_est/dx of the estimated bow-wave height to the fine spacing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    /// H_est/dx = 8: below the rule (10.9); for smoke runs and trends of the bow wave, jets not resolved.
    Coarse,
    /// H_est/dx = 25: the rule H_pj/dx > 20 (10.9) with a margin for the estimate (same as `rule = "auto"`).
    Medium,
    /// H_est/dx = 50: twice the rule.
    Fine,
}

impl Level {
    /// H_est/dx of the level.
    pub fn h_over_dx(self) -> f64 {
        match self {
            Level::Coarse => 8.0,
            Level::Medium => 25.0,
            Level::Fine => 50.0,
        }
    }
}

/// Domain and model options; every default is the 2D+t run's (see `TwoDtConfig`).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Model {
    /// dx_c/dx_f below the transition (1 = uniform).
    pub ratio: f64,
    /// W/B, thesis §10.1.2: 4.
    pub width_over_beam: f64,
    /// Z/D, thesis §10.1.2 and appendix D: 2.
    pub depth_over_draft: f64,
    /// c0/√(gL); absent: 10 × the expected maximum velocity.
    pub c0: Option<f64>,
    /// Damped settling, in acoustic crossings of the depth.
    pub settle: f64,
    /// Free-surface detection and plunge check every this many steps.
    pub detect_every: usize,
}

impl Default for Model {
    fn default() -> Self {
        let d = TwoDtConfig::default();
        Model {
            ratio: d.coarse_ratio,
            width_over_beam: d.width_over_beam,
            depth_over_draft: d.depth_over_draft,
            c0: d.c0,
            settle: d.settle_crossings,
            detect_every: d.detect_every,
        }
    }
}

/// Where each case stops.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Stop {
    /// `"plunge"` (shortly after it), `"transom"`, or an x/L value.
    pub until: toml::Value,
    /// x/L at which a case looking for the plunge gives up (default 0.5: every plunge of Tables 10.1 and 10.2
    /// is before x/L = 0.27).
    pub give_up_at: f64,
    /// x/L run on after the plunge (default 0.01).
    pub after_plunge: f64,
}

impl Default for Stop {
    fn default() -> Self {
        Stop {
            until: toml::Value::String("plunge".into()),
            give_up_at: 0.5,
            after_plunge: TwoDtConfig::default().after_plunge,
        }
    }
}

/// Which outputs each case writes besides its metrics, series, η table and plunge snapshots.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Outputs {
    pub vtk: bool,
    pub frames: bool,
    /// x/L between outputs (η profiles for the wave-pattern map, frames).
    pub output_dx: f64,
}

impl Default for Outputs {
    fn default() -> Self {
        Outputs {
            vtk: false,
            frames: false,
            output_dx: TwoDtConfig::default().output_dx,
        }
    }
}

/// One resolved case of a study: everything needed to run it and to recognise it when resumed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CaseSpec {
    /// 1-based position in the study.
    pub index: usize,
    pub fr: f64,
    pub dx: f64,
    pub ratio: f64,
    pub width_over_beam: f64,
    pub depth_over_draft: f64,
    pub c0: Option<f64>,
    pub settle: f64,
    pub detect_every: usize,
    /// `plunge`, `transom` or an x/L value, as text.
    pub until: String,
    pub give_up_at: f64,
    pub after_plunge: f64,
    pub vtk: bool,
    pub frames: bool,
    pub output_dx: f64,
}

impl CaseSpec {
    /// Folder name of the case inside the study's output folder.
    pub fn dir_name(&self) -> String {
        format!("{:02}-fr{:.3}", self.index, self.fr)
    }

    /// The 2D+t configuration of the case. A plunge search stops at `give_up_at` if nothing plunged.
    pub fn config(&self) -> TwoDtConfig {
        let until = match self.until.as_str() {
            "plunge" => Until::Plunge,
            "transom" => Until::Transom,
            v => Until::X(v.parse().unwrap_or(self.give_up_at)),
        };
        TwoDtConfig {
            fr: self.fr,
            dx: Some(self.dx),
            coarse_ratio: self.ratio,
            width_over_beam: self.width_over_beam,
            depth_over_draft: self.depth_over_draft,
            until,
            give_up_at: (until == Until::Plunge).then_some(self.give_up_at),
            after_plunge: self.after_plunge,
            c0: self.c0,
            settle_crossings: self.settle,
            detect_every: self.detect_every,
            output_dx: self.output_dx,
            ..Default::default()
        }
    }
}

/// A parsed and checked study.
#[derive(Clone, Debug)]
pub struct Study {
    pub file: PathBuf,
    pub spec: StudyFile,
    /// The hull file, resolved against the study file's folder.
    pub hull_path: PathBuf,
    pub cases: Vec<CaseSpec>,
}

impl Study {
    /// Reads and checks a study file. `draft_over_l` of the hull is needed by the resolution rules, so the
    /// hull file is read here too (its own errors name it).
    pub fn read(path: &Path) -> anyhow::Result<Study> {
        let file = path.display().to_string();
        let spec: StudyFile = parse_toml(&read_text(path)?, &file)?;
        let base = path.parent().unwrap_or(Path::new("."));
        let hull_path = if spec.hull.is_absolute() {
            spec.hull.clone()
        } else {
            base.join(&spec.hull)
        };
        let field = |field: &str, expected: String| InputError::field(&file, field, expected);
        if !hull_path.is_file() {
            return Err(field(
                "hull",
                format!(
                    "a hull offsets file (relative to the study file); {} not found",
                    hull_path.display()
                ),
            )
            .into());
        }
        let offsets = crate::geometry::hull_file::HullOffsets::read(&hull_path)?;
        let draft = offsets.meta.draft_m / offsets.meta.length_m;
        let cases = resolve(&spec, draft).map_err(|(f, e)| field(&f, e))?;
        Ok(Study {
            file: path.to_path_buf(),
            spec,
            hull_path,
            cases,
        })
    }
}

/// Checks the fields and resolves one case per Froude number; errors are (field, expected).
fn resolve(s: &StudyFile, draft: f64) -> Result<Vec<CaseSpec>, (String, String)> {
    let err = |f: &str, e: &str| Err((f.to_string(), e.to_string()));
    if s.name.is_empty() || s.name.contains(['/', '\\']) {
        return err("name", "a non-empty name without path separators");
    }
    if s.froude.is_empty() {
        return err("froude", "a non-empty list of Froude numbers in (0, 3)");
    }
    let r = &s.resolution;
    let given = r.dx.is_some() as u8 + r.rule.is_some() as u8 + r.level.is_some() as u8;
    if given != 1 {
        return err(
            "resolution",
            "exactly one of `dx = [...]` (one dx/L per Froude number), `rule = \"auto\"` or `level = \"coarse\" | \"medium\" | \"fine\"`",
        );
    }
    let dxs: Vec<f64> = if let Some(dx) = &r.dx {
        if dx.len() != s.froude.len() {
            return Err((
                "resolution.dx".into(),
                format!(
                    "{} values (one dx/L per Froude number), got {}",
                    s.froude.len(),
                    dx.len()
                ),
            ));
        }
        if dx.iter().any(|d| !(d.is_finite() && *d > 0.0 && *d < draft / 4.0)) {
            return Err((
                "resolution.dx".into(),
                format!("values in (0, D/4 = {:.4e})", draft / 4.0),
            ));
        }
        dx.clone()
    } else if let Some(rule) = &r.rule {
        if rule != "auto" {
            return err("resolution.rule", "\"auto\" (H_pj/dx > 20, eq. 10.9)");
        }
        s.froude.iter().map(|&fr| auto_dx(fr, draft)).collect()
    } else {
        let level = r.level.expect("one of the three is given");
        s.froude
            .iter()
            .map(|&fr| estimated_hpj_over_d(fr) * draft / level.h_over_dx())
            .collect()
    };
    let m = &s.model;
    let until = match &s.stop.until {
        toml::Value::String(v) if v == "plunge" || v == "transom" => v.clone(),
        toml::Value::Float(x) if *x > 0.0 => x.to_string(),
        toml::Value::Integer(x) if *x > 0 => x.to_string(),
        _ => return err("stop.until", "\"plunge\", \"transom\" or an x/L value > 0"),
    };
    // A study's cases start at the stem, so its stop points lie beyond it (the 2D+t run alone may start
    // before the stem and accepts any number).
    if !(s.stop.give_up_at > 0.0 && s.stop.give_up_at.is_finite()) {
        return err("stop.give_up_at", "an x/L value > 0");
    }
    let cases: Vec<CaseSpec> = s
        .froude
        .iter()
        .zip(dxs)
        .enumerate()
        .map(|(k, (&fr, dx))| CaseSpec {
            index: k + 1,
            fr,
            dx,
            ratio: m.ratio,
            width_over_beam: m.width_over_beam,
            depth_over_draft: m.depth_over_draft,
            c0: m.c0,
            settle: m.settle,
            detect_every: m.detect_every,
            until: until.clone(),
            give_up_at: s.stop.give_up_at,
            after_plunge: s.stop.after_plunge,
            vtk: s.outputs.vtk,
            frames: s.outputs.frames,
            output_dx: s.outputs.output_dx,
        })
        .collect();
    // The values themselves are checked by the 2D+t run's own rules (one list, `TwoDtConfig::check`), each
    // error told with the study's field name; the give-up point has had the study's stricter rule above.
    for case in &cases {
        case.config().check().map_err(|e| {
            (
                study_field(e.option).to_string(),
                format!("{}, got {}", e.expected, e.got),
            )
        })?;
    }
    Ok(cases)
}

/// The study file's field for an option of the 2D+t configuration.
fn study_field(option: ConfigOption) -> &'static str {
    match option {
        ConfigOption::Fr => "froude",
        ConfigOption::CoarseRatio => "model.ratio",
        ConfigOption::WidthOverBeam => "model.width_over_beam",
        ConfigOption::DepthOverDraft => "model.depth_over_draft",
        ConfigOption::C0 => "model.c0",
        ConfigOption::Settle => "model.settle",
        ConfigOption::DetectEvery => "model.detect_every",
        ConfigOption::Until => "stop.until",
        ConfigOption::GiveUpAt => "stop.give_up_at",
        ConfigOption::AfterPlunge => "stop.after_plunge",
        ConfigOption::OutputDx => "outputs.output_dx",
        // Options a study file does not set; their defaults pass.
        o
        @ (ConfigOption::Cfl | ConfigOption::Layers | ConfigOption::PlungeDepth | ConfigOption::PlungeCirculation) => {
            o.describe()
        }
    }
}
