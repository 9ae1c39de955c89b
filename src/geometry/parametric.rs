//! A small parametric hull family for hulls without public offsets (R/V Athena, NRV Alliance): a raked stem
//! with a forefoot, waterline entrance and run curves ending in a transom, sections that go from V-shaped at
//! the bow to round-bilged amidships (superellipse exponent n(x)), flare above the waterline over the forward
//! part, a keel that rises aft to the transom immersion. Units of L; x/L from the stem, z up from the
//! waterline. The block coefficient is matched by bisection on the midship section exponent.
//!
//! Half-breadth at (x, z):
//! * keel depth d(x) = −F + (F + T)(1 − (1 − x/x_ff)²) forward of the forefoot x_ff (a raked, curved stem
//!   from the deck at x = 0 that meets the flat keel tangentially), T amidships, rising quadratically aft of
//!   x_keel_rise to the transom immersion; the stem line x_s(z) is its inverse;
//! * planform b(x, z) = (B/2) E(s), s = (x − x_s(z))/(x_m − x_s(z)), E(s) = 1 − (1 − s)^p_e, before the
//!   maximum-beam station x_m, and (B/2)[1 − (1 − w_t) ((x − x_m)/(1 − x_m))^p_r] aft of it;
//! * below the waterline, y = b(x, z) (1 − (−z/d(x))^n(x))^(1/n(x)) with d(x) the local keel depth;
//! * above it, y = b(x, z) (1 + φ(x) z), φ(x) = φ0 (1 − x/x_flare)² forward of x_flare, 0 aft (wall-sided).

use super::hull_file::{HullMeta, HullOffsets, HullStatus, Station};
use super::hydrostatics::hydrostatics;
use super::surface::HullSurface;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Generator parameters (lengths in units of L unless stated).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ParametricSpec {
    pub name: String,
    pub length_m: f64,
    pub beam: f64,
    pub draft: f64,
    pub freeboard: f64,
    /// Forefoot: x/L where the raked stem meets the keel.
    pub x_forefoot: f64,
    /// Station of maximum beam.
    pub x_max_beam: f64,
    /// Entrance and run exponents of the planform.
    pub p_entrance: f64,
    pub p_run: f64,
    /// Transom half-breadth as a fraction of B/2 (0: pointed stern, no transom).
    pub transom_width: f64,
    /// Transom immersion below the waterline (units of L).
    pub transom_immersion: f64,
    /// x/L where the keel starts rising towards the transom.
    pub x_keel_rise: f64,
    /// Section exponents: V at the bow, round bilge amidships (calibrated), reached at x_round.
    pub n_bow: f64,
    pub n_mid: f64,
    pub x_round: f64,
    /// Flare coefficient φ0 (1/L) and its extent x_flare.
    pub flare: f64,
    pub x_flare: f64,
    /// Calibration target for Cb, and the sources of the particulars.
    pub target_cb: f64,
    pub source: String,
}

impl ParametricSpec {
    /// The same family member with numeric parameters replaced, from `key=value` strings (keys are the
    /// field names). The result is renamed `NAME-variant` and its source says which values changed, so a
    /// variant is never mistaken for the calibrated approximation.
    pub fn with_overrides(&self, pairs: &[String]) -> anyhow::Result<Self> {
        let mut v = serde_json::to_value(self)?;
        let original = v.clone();
        let keys = numeric_keys(&original);
        let obj = v.as_object_mut().expect("a struct serializes to an object");
        for pair in pairs {
            let (key, value) = pair
                .split_once('=')
                .ok_or_else(|| anyhow::anyhow!("--set `{pair}`: expected KEY=VALUE"))?;
            let key = key.trim();
            let slot = obj.get_mut(key).filter(|x| x.is_number()).ok_or_else(|| {
                anyhow::anyhow!(
                    "--set `{pair}`: unknown parameter `{key}`; expected one of {}",
                    keys.join(", ")
                )
            })?;
            let x: f64 = value
                .trim()
                .parse()
                .ok()
                .filter(|x: &f64| x.is_finite())
                .ok_or_else(|| anyhow::anyhow!("--set `{pair}`: expected a finite number after `=`"))?;
            *slot = serde_json::json!(x);
        }
        let mut out: Self = serde_json::from_value(v)?;
        out.name = format!("{}-variant", self.name);
        out.source = format!(
            "VARIANT of the {} approximation ({}); {}",
            self.name,
            pairs.join(", "),
            self.source
        );
        Ok(out)
    }

    /// Local keel depth d(x) (positive below the waterline; negative where the keel is above it).
    fn keel_depth(&self, x: f64) -> f64 {
        let (t, f) = (self.draft, self.freeboard);
        if x < self.x_forefoot {
            // Curved forefoot meeting the flat keel tangentially (a kink here makes the x-splines ring).
            let s = 1.0 - x / self.x_forefoot;
            -f + (f + t) * (1.0 - s * s)
        } else if x > self.x_keel_rise {
            let s = (x - self.x_keel_rise) / (1.0 - self.x_keel_rise);
            t - (t - self.transom_immersion) * s * s
        } else {
            t
        }
    }

    /// The stem line: x where the keel is at height z (inverse of the forefoot curve).
    fn stem_x(&self, z: f64) -> f64 {
        let r = ((self.draft + z) / (self.freeboard + self.draft)).clamp(0.0, 1.0);
        self.x_forefoot * (1.0 - r.sqrt())
    }

    fn planform(&self, x: f64, z: f64) -> f64 {
        let half = 0.5 * self.beam;
        if x <= self.x_max_beam {
            let xs = self.stem_x(z.max(-self.draft));
            if x <= xs {
                return 0.0;
            }
            let s = ((x - xs) / (self.x_max_beam - xs)).clamp(0.0, 1.0);
            half * (1.0 - (1.0 - s).powf(self.p_entrance))
        } else {
            let s = (x - self.x_max_beam) / (1.0 - self.x_max_beam);
            half * (1.0 - (1.0 - self.transom_width) * s.powf(self.p_run))
        }
    }

    fn exponent(&self, x: f64) -> f64 {
        let s = (x / self.x_round).clamp(0.0, 1.0);
        let w = s * s * (3.0 - 2.0 * s);
        self.n_bow + (self.n_mid - self.n_bow) * w
    }

    fn flare_at(&self, x: f64) -> f64 {
        if x < self.x_flare {
            self.flare * (1.0 - x / self.x_flare).powi(2)
        } else {
            0.0
        }
    }

    /// Half-breadth y/L at (x, z).
    pub fn half_breadth(&self, x: f64, z: f64) -> f64 {
        let b = self.planform(x, z);
        if z >= 0.0 {
            return b * (1.0 + self.flare_at(x) * z);
        }
        let d = self.keel_depth(x);
        if d <= 0.0 || -z >= d {
            return 0.0;
        }
        let n = self.exponent(x);
        b * (1.0 - (-z / d).powf(n)).max(0.0).powf(1.0 / n)
    }

    /// Offsets at `stations` stations (cosine-clustered towards the bow), `points` points per station.
    pub fn offsets(&self, stations: usize, points: usize) -> HullOffsets {
        let mut st = vec![];
        for i in 0..stations {
            let u = i as f64 / (stations - 1) as f64;
            let x = (0.5 * (1.0 - (std::f64::consts::PI * u).cos())).mul_add(0.5, 0.5 * u);
            let zk = -self
                .keel_depth(x)
                .max(-self.freeboard + 1e-3 * (self.freeboard + self.draft));
            let mut pts = vec![];
            for k in 0..points {
                let s = k as f64 / (points - 1) as f64;
                // Cosine clustering at the keel and the deck; finer below the waterline.
                let z = zk + (self.freeboard - zk) * 0.5 * (1.0 - (std::f64::consts::PI * s).cos());
                let y = if k == 0 { 0.0 } else { self.half_breadth(x, z) };
                pts.push([y, z]);
            }
            // The stem station degenerates to the stem line; keep its points distinct.
            st.push(Station { x, points: pts });
        }
        let mut notes = BTreeMap::new();
        notes.insert(
            "generator".into(),
            format!(
                "bowwave geometry::parametric {}",
                serde_json::to_string(self).unwrap_or_default()
            ),
        );
        notes.insert("target_cb".into(), format!("{:.4}", self.target_cb));
        HullOffsets {
            meta: HullMeta {
                name: self.name.clone(),
                status: HullStatus::Approximation,
                length_m: self.length_m,
                draft_m: self.draft * self.length_m,
                beam_m: self.beam * self.length_m,
                model_scale: 1.0,
                transom: self.transom_width > 0.0,
                transom_immersion_m: self.transom_immersion * self.length_m,
                source: self.source.clone(),
                notes,
            },
            stations: st,
        }
    }

    /// Adjusts `n_mid` by bisection so that Cb of the generated hull matches `target_cb`; returns Cb, or an
    /// error when no n_mid in [1.2, 12] comes within 0.1 % of the target (overrides that leave the family's
    /// range, e.g. `flare=1e9`, used to be written with Cb 0.03 against 0.46).
    pub fn calibrate(&mut self, stations: usize, points: usize) -> anyhow::Result<f64> {
        let cb_of = |s: &ParametricSpec| {
            let h = s.offsets(stations, points);
            hydrostatics(&HullSurface::new(&h), 200, 800).0.cb
        };
        let (mut lo, mut hi) = (1.2, 12.0);
        for _ in 0..40 {
            self.n_mid = 0.5 * (lo + hi);
            if cb_of(self) < self.target_cb {
                lo = self.n_mid;
            } else {
                hi = self.n_mid;
            }
        }
        self.n_mid = 0.5 * (lo + hi);
        let cb = cb_of(self);
        anyhow::ensure!(
            (cb - self.target_cb).abs() <= 1e-3 * self.target_cb,
            "calibration: Cb = {cb:.4} at the end of the midship exponent's range [1.2, 12]; expected the \
             target {:.4} (the parameters leave the family's range)",
            self.target_cb
        );
        Ok(cb)
    }
}

fn numeric_keys(v: &serde_json::Value) -> Vec<&str> {
    v.as_object()
        .map(|o| {
            o.iter()
                .filter(|(_, x)| x.is_number())
                .map(|(k, _)| k.as_str())
                .collect()
        })
        .unwrap_or_default()
}

/// Stations and points per station of the shipped generated hulls (`bowwave hull generate` defaults).
pub const STATIONS: usize = 41;
pub const POINTS: usize = 31;

/// The generator of a family by name: `athena` or `alliance`.
pub fn named(name: &str) -> anyhow::Result<ParametricSpec> {
    match name {
        "athena" => Ok(athena()),
        "alliance" => Ok(alliance()),
        other => anyhow::bail!("hull generator `{other}`: expected `athena` or `alliance`"),
    }
}

/// A family member, `set` applied (`key=value`; a variant when not empty), calibrated to its Cb: the spec,
/// the Cb reached, and its offsets at `stations` × `points`.
pub fn generate(
    name: &str,
    set: &[String],
    stations: usize,
    points: usize,
) -> anyhow::Result<(ParametricSpec, f64, crate::geometry::hull_file::HullOffsets)> {
    let mut spec = named(name)?;
    if !set.is_empty() {
        spec = spec.with_overrides(set)?;
    }
    let cb = spec.calibrate(stations, points)?;
    let offsets = spec.offsets(stations, points);
    Ok((spec, cb, offsets))
}

/// R/V Athena (DTMB model 5365) approximation: L = 47 m, B = 6.9 m (between the 6.4–7.3 m of the sources),
/// T = 1.63 m, wide immersed transom, round-bilge semi-planing form, Cb 0.46 (middle of 0.43–0.49).
pub fn athena() -> ParametricSpec {
    let l = 47.0;
    ParametricSpec {
        name: "athena".into(),
        length_m: l,
        beam: 6.9 / l,
        draft: 1.63 / l,
        freeboard: 2.4 / l,
        x_forefoot: 0.12,
        x_max_beam: 0.55,
        p_entrance: 1.8,
        p_run: 2.5,
        transom_width: 0.8,
        transom_immersion: 0.55 / l,
        x_keel_rise: 0.45,
        n_bow: 1.15,
        n_mid: 3.0,
        x_round: 0.45,
        flare: 6.0,
        x_flare: 0.25,
        target_cb: 0.46,
        source: "APPROXIMATION: no public offsets. Parametric hull calibrated to L = 47 m (OMAE2010 Fu et al.), draft 1.63 m and beam 6.4-7.3 m (Asheville class, Naval Vessel Register data), Cb 0.43-0.49; see data/reference/hulls".into(),
    }
}

/// NRV Alliance approximation: Lpp = 82 m, B = 15.2 m, T = 5.2 m, Δ = 2920 t (Cb ≈ 0.44).
pub fn alliance() -> ParametricSpec {
    let l = 82.0;
    ParametricSpec {
        name: "alliance".into(),
        length_m: l,
        beam: 15.2 / l,
        draft: 5.2 / l,
        freeboard: 4.0 / l,
        x_forefoot: 0.06,
        x_max_beam: 0.5,
        p_entrance: 2.0,
        p_run: 2.2,
        transom_width: 0.55,
        transom_immersion: 0.8 / l,
        x_keel_rise: 0.6,
        n_bow: 1.2,
        n_mid: 3.0,
        x_round: 0.35,
        flare: 3.0,
        x_flare: 0.3,
        target_cb: 2920.0 / 1.025 / (82.0 * 15.2 * 5.2),
        source: "APPROXIMATION: no public offsets. Parametric hull calibrated to Lpp = 82 m, B = 15.2 m, T = 5.2 m, displacement 2920 t (de.wikipedia mirror), Cb = 0.440; see data/reference/hulls".into(),
    }
}
