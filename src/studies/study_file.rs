//! The study file: a TOML description of a Froude sweep (hull, Froude numbers, resolution rule, domain and
//! model options, where to stop, which outputs), resolved into one [`CaseSpec`] per Froude number. Every error
//! names the file, the field and what was expected. The fields and their defaults are documented in
//! `docs/reference/studies.md`.

use crate::input_error::{parse_toml, read_text, InputError};
use crate::twodt::config::{ConfigOption, TwoDtConfig, Until};
use crate::twodt::scene::{auto_dx, estimated_hpj_over_d};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
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
    /// How dx/L is chosen; absent in a `[ship3d]` study, whose spacing is D/res.
    #[serde(default)]
    pub resolution: Resolution,
    /// Options of every case, in the keys of `bowwave twodt` (`TwoDtConfig`; `--give-up-at` is
    /// `give_up_at`), except `fr` and `dx`, which `froude` and `[resolution]` set.
    #[serde(default)]
    pub config: toml::Table,
    /// Options of one case, `[case.N]` for the N-th Froude number (1-based), over `[config]`; besides the
    /// 2D+t options, its own hull (`hull = "FILE"`) or a generated variant (`[case.N.hull_variant]`,
    /// `generator = "athena"` and the generator parameters changed, e.g. `flare_angle = 20`).
    #[serde(default)]
    pub case: BTreeMap<String, toml::Table>,
    /// A 3D study (`[ship3d]`): each case also tows the hull in 3D at the same spacing and compares the two wave
    /// patterns (issue #31).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ship3d: Option<Ship3d>,
}

/// A study's `[ship3d]` table: `bowwave ship`'s options (the same struct, so the two cannot drift apart); every
/// case runs the towed ship and its 2D+t partner at one spacing dx = D/res, in one tank (half width, depth) and at
/// one sound speed (the 2D+t rule). A study also needs `res ≥ 4`, the 2D+t partner's bound.
pub type Ship3d = crate::compare3d::towed_ship::TowOptions;

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

/// The hull of a case.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum CaseHull {
    /// A hull offsets file, as written in the study file (relative to it, or absolute).
    File(PathBuf),
    /// A generated family member with some generator parameters changed (`bowwave hull generate NAME --set
    /// KEY=VALUE`), calibrated to its Cb when the case runs and written into the case's folder as `hull.csv`.
    Variant {
        generator: String,
        set: BTreeMap<String, f64>,
    },
}

impl CaseHull {
    /// The `--set` form of a variant's parameters.
    pub fn set_pairs(set: &BTreeMap<String, f64>) -> Vec<String> {
        set.iter().map(|(k, v)| format!("{k}={v}")).collect()
    }
}

/// One resolved case of a study: everything needed to run it and to recognise it when resumed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CaseSpec {
    /// 1-based position in the study.
    pub index: usize,
    /// The case's hull: the study's `hull`, or its own `[case.N]` `hull` or `hull_variant`.
    pub hull: CaseHull,
    /// The whole configuration of the case: the defaults, the study's `[config]`, the case's `[case.N]`,
    /// its Froude number and its spacing.
    pub config: TwoDtConfig,
    /// The 3D run beside the 2D+t one, in a `[ship3d]` study.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ship3d: Option<Ship3d>,
}

impl CaseSpec {
    /// Folder name of the case inside the study's output folder.
    pub fn dir_name(&self) -> String {
        format!("{:02}-fr{:.3}", self.index, self.fr())
    }

    /// The case's Froude number.
    pub fn fr(&self) -> f64 {
        self.config.fr
    }

    /// The case's fine spacing dx/L (always resolved in a study).
    pub fn dx(&self) -> f64 {
        self.config.dx.unwrap_or(f64::NAN)
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
        let study = Study {
            file: path.to_path_buf(),
            spec,
            hull_path,
            cases,
        };
        for case in &study.cases {
            if let CaseHull::File(f) = &case.hull {
                let p = study.resolve(f);
                if !p.is_file() {
                    return Err(field(
                        &format!("case.{}.hull", case.index),
                        format!(
                            "a hull offsets file (relative to the study file); {} not found",
                            p.display()
                        ),
                    )
                    .into());
                }
            }
        }
        Ok(study)
    }

    /// A path of the study file, resolved against the study file's folder.
    pub fn resolve(&self, path: &Path) -> PathBuf {
        if path.is_absolute() {
            path.to_path_buf()
        } else {
            self.file.parent().unwrap_or(Path::new(".")).join(path)
        }
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
    if let Some(ship) = &s.ship3d {
        if given != 0 {
            return err(
                "resolution",
                "no [resolution] in a [ship3d] study: both models run at dx = D/res (`ship3d.res`)",
            );
        }
        if let Some((key, expected)) = ship.check() {
            return Err((format!("ship3d.{key}"), expected.to_string()));
        }
        if ship.res < 4.0 {
            return err(
                "ship3d.res",
                "D/dx ≥ 4 (the 2D+t partner needs 4 particles over the draft)",
            );
        }
    } else if given != 1 {
        return err(
            "resolution",
            "exactly one of `dx = [...]` (one dx/L per Froude number), `rule = \"auto\"` or `level = \"coarse\" | \"medium\" | \"fine\"`",
        );
    }
    let dxs: Vec<f64> = if let Some(ship) = &s.ship3d {
        vec![draft / ship.res; s.froude.len()]
    } else if let Some(dx) = &r.dx {
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
        if dx.iter().any(|d| !(d.is_finite() && *d > 0.0 && *d <= draft / 4.0)) {
            return Err((
                "resolution.dx".into(),
                format!("values in (0, D/4 = {:.4e}]", draft / 4.0),
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
    let mut base = TwoDtConfig::default()
        .with_overrides(&s.config)
        .map_err(|e| ("config".to_string(), e))?;
    if let Some(ship) = &s.ship3d {
        // One tank, one spacing and one sound speed for both models: the 2D+t partner's are set here.
        for (k, table) in std::iter::once(("config".to_string(), &s.config))
            .chain(s.case.iter().map(|(k, t)| (format!("case.{k}"), t)))
        {
            for key in SHIP3D_SETS {
                if table.contains_key(*key) {
                    return Err((
                        format!("{k}.{key}"),
                        "no `ratio`, `width`, `depth`, `until` or `c0` in a [ship3d] study: both models share one \
                         uniform tank (`ship3d.half_width`, `ship3d.depth`), run to the transom at the 2D+t sound speed"
                            .into(),
                    ));
                }
            }
        }
        base.coarse_ratio = 1.0;
        base.width_over_beam = ship.half_width;
        base.depth_over_draft = ship.depth;
        base.until = Until::Transom;
    }
    for (key, field) in [("fr", "froude"), ("dx", "resolution")] {
        if s.config.contains_key(key) {
            return Err((format!("config.{key}"), format!("no `{key}` here: `{field}` sets it")));
        }
    }
    let mut overrides: Vec<Option<toml::Table>> = vec![None; s.froude.len()];
    let mut hulls: Vec<CaseHull> = vec![CaseHull::File(s.hull.clone()); s.froude.len()];
    for (k, table) in &s.case {
        let index = k.parse::<usize>().ok().filter(|i| (1..=s.froude.len()).contains(i));
        let Some(index) = index else {
            return Err((
                format!("case.{k}"),
                format!("a case number from 1 to {} (one per Froude number)", s.froude.len()),
            ));
        };
        for key in ["fr", "dx"] {
            if table.contains_key(key) {
                return Err((
                    format!("case.{k}.{key}"),
                    "no `fr` or `dx` here: `froude` and `[resolution]` set them".into(),
                ));
            }
        }
        let mut table = table.clone();
        hulls[index - 1] = case_hull(&mut table, k, &s.hull)?;
        if s.ship3d.is_some() && hulls[index - 1] != CaseHull::File(s.hull.clone()) {
            return Err((
                format!("case.{k}"),
                "no `hull` or `hull_variant` in a [ship3d] study: its spacing is the study hull's D/res, one hull \
                 for every case (write one study per hull)"
                    .into(),
            ));
        }
        overrides[index - 1] = Some(table);
    }
    let mut cases = Vec::with_capacity(s.froude.len());
    for (k, (&fr, dx)) in s.froude.iter().zip(dxs).enumerate() {
        let own = overrides[k].as_ref();
        let mut config = match own {
            Some(t) => base.with_overrides(t).map_err(|e| (format!("case.{}", k + 1), e))?,
            None => base.clone(),
        };
        config.fr = fr;
        config.dx = Some(dx);
        // The values are checked by the 2D+t run's own rules (one list, `TwoDtConfig::check`), each error told
        // with the study's field name.
        let field = |option: ConfigOption| match option {
            ConfigOption::Fr => "froude".to_string(),
            o if own.is_some_and(|t| t.contains_key(o.key())) => format!("case.{}.{}", k + 1, o.key()),
            o => format!("config.{}", o.key()),
        };
        config
            .check()
            .map_err(|e| (field(e.option), format!("{}, got {}", e.expected, e.got)))?;
        // A study's cases start at the stem, so its stop points lie beyond it (a 2D+t run alone may start
        // before the stem and accepts any number).
        if let Until::X(x) = config.until {
            if x <= 0.0 {
                return Err((
                    field(ConfigOption::Until),
                    format!("\"plunge\", \"transom\" or an x/L value > 0, got {x}"),
                ));
            }
        }
        if let Some(x) = config.give_up_at.filter(|&x| x <= 0.0) {
            return Err((field(ConfigOption::GiveUpAt), format!("an x/L value > 0, got {x}")));
        }
        cases.push(CaseSpec {
            index: k + 1,
            hull: hulls[k].clone(),
            config,
            ship3d: s.ship3d.clone(),
        });
    }
    Ok(cases)
}

/// The 2D+t options a `[ship3d]` study sets itself (the tank, the stop, the sound speed).
const SHIP3D_SETS: &[&str] = &["ratio", "width", "depth", "until", "c0"];

/// Takes a case's own hull out of its `[case.N]` table: `hull = "FILE"` or `[case.N.hull_variant]`; the
/// study's hull when it has neither. The variant's generator and keys are checked here, its calibration is
/// left to the run.
fn case_hull(table: &mut toml::Table, k: &str, study_hull: &Path) -> Result<CaseHull, (String, String)> {
    let file = table.remove("hull");
    let variant = table.remove("hull_variant");
    match (file, variant) {
        (Some(_), Some(_)) => Err((format!("case.{k}"), "either `hull` or `hull_variant`, not both".into())),
        (Some(toml::Value::String(f)), None) => Ok(CaseHull::File(PathBuf::from(f))),
        (Some(_), None) => Err((format!("case.{k}.hull"), "a hull offsets file name".into())),
        (None, Some(toml::Value::Table(mut t))) => {
            let field = format!("case.{k}.hull_variant");
            let generator = match t.remove("generator") {
                Some(toml::Value::String(g)) => g,
                _ => return Err((format!("{field}.generator"), "`athena` or `alliance`".into())),
            };
            let mut set = BTreeMap::new();
            for (key, v) in t {
                let x = match v {
                    toml::Value::Float(x) => x,
                    toml::Value::Integer(i) => i as f64,
                    _ => return Err((format!("{field}.{key}"), "a number".into())),
                };
                set.insert(key, x);
            }
            let spec = crate::geometry::parametric::named(&generator)
                .map_err(|e| (format!("{field}.generator"), e.to_string()))?;
            spec.with_overrides(&CaseHull::set_pairs(&set))
                .map_err(|e| (field.clone(), e.to_string()))?;
            Ok(CaseHull::Variant { generator, set })
        }
        (None, Some(_)) => Err((
            format!("case.{k}.hull_variant"),
            "a table: `generator = \"athena\"` and the parameters changed".into(),
        )),
        (None, None) => Ok(CaseHull::File(study_hull.to_path_buf())),
    }
}
