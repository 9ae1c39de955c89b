//! A small parametric hull family for hulls without public offsets (R/V Athena, NRV Alliance). Units of L;
//! x/L from the stem, z up from the calm waterline. Every station fact a source states is its own parameter,
//! so that one can be honoured without moving another (issue #30):
//!
//! * **stem and keel** — the keel depth d(x) (positive below the waterline) rises from the deck at the stem
//!   (x = 0, d = −F) through the waterline at `x_entry` to `keel_forefoot`·T at the forefoot `x_forefoot`:
//!   d = d_ff − (d_ff + F)(1 − x/x_ff)^q, with q fixed by d(x_entry) = 0 (a raked stem, rounded into the
//!   keel with zero slope); from the forefoot the keel descends to the full draft T at `x_deepest` along a
//!   smoothstep (zero slope at both ends, no kink for the x-splines to ring on), then rises quadratically to
//!   the transom immersion at x = 1. The stem line x_s(z) is the inverse of the stem curve.
//! * **planform** — b(x, z) = (B/2) E(s), s = (x − x_s(z))/(x_m − x_s(z)), E(s) = 1 − (1 − s)^p_e before the
//!   maximum-beam station x_m = `x_max_beam`, with p_e set by the waterline entrance half-angle α
//!   (`entrance_angle`): tan α = (B/2) p_e/(x_m − x_entry); aft of x_m, (B/2)[1 − (1 − w_t) ((x − x_m)/(1 −
//!   x_m))^p_r] with w_t = `transom_width`.
//! * **sections** — below the waterline y = b (1 − (−z/d)^n)^(1/n), a superellipse whose exponent n(x) goes
//!   from `n_bow` (V) at the stem to `n_mid` (round bilge, calibrated to Cb) at `x_round`.
//! * **flare** — above the waterline y = b(x, z) + tan θ(x) · z · r, θ(x) = `flare_angle` over the forward
//!   `x_flare` and fading to wall-sided over the next [`FLARE_FADE`]; r ramps from 0 at the stem line to 1
//!   within [`FLARE_RAMP`] behind it (a section cannot be wider than nothing ahead of the stem).
//! * **running attitude** — the hull is trimmed by `trim` degrees bow up about the point x/L = `trim_pivot` of
//!   the calm waterline, and sunk until it displaces what it displaces at rest (the design volume) plus
//!   `sinkage` (units of L, down positive). The offsets are written in the earth frame: their z = 0 is the
//!   calm water, so a 2D+t run sees the hull as it runs.

use super::hull_file::{HullMeta, HullOffsets, HullStatus, Station};
use super::hydrostatics::hydrostatics;
use super::surface::HullSurface;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Length behind the stem line over which the flare grows from nothing to its angle (units of L). With a
/// 40° flare and Athena's freeboard the deck line then opens at about 30° more than the waterline (a flared
/// bow's deck, not a blunt one); a ramp of 0.02 L made the deck edge expand at twice the ship speed.
pub const FLARE_RAMP: f64 = 0.1;
/// Length over which the flare fades to a wall-sided topside aft of `x_flare` (units of L).
pub const FLARE_FADE: f64 = 0.1;

/// Generator parameters (lengths in units of L unless stated).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ParametricSpec {
    pub name: String,
    pub length_m: f64,
    /// Beam B at the waterline, draft T (the keel's deepest point), freeboard F (deck above the waterline).
    pub beam: f64,
    pub draft: f64,
    pub freeboard: f64,
    /// x/L where the stem crosses the calm waterline.
    pub x_entry: f64,
    /// x/L of the forefoot, where the stem curve meets the keel with zero slope.
    pub x_forefoot: f64,
    /// Keel depth at the forefoot as a fraction of T (1: a flat keel from the forefoot to `x_deepest`).
    pub keel_forefoot: f64,
    /// x/L of the keel's deepest point; aft of it the keel rises to the transom immersion.
    pub x_deepest: f64,
    /// x/L of the widest waterline.
    pub x_max_beam: f64,
    /// Waterline entrance half-angle at the stem (degrees).
    pub entrance_angle: f64,
    /// Run exponent of the planform aft of the widest waterline.
    pub p_run: f64,
    /// Transom half-breadth as a fraction of B/2 (0: pointed stern, no transom).
    pub transom_width: f64,
    /// Transom immersion below the waterline (units of L).
    pub transom_immersion: f64,
    /// Section exponents: V at the bow, round bilge amidships (calibrated), reached at x_round.
    pub n_bow: f64,
    pub n_mid: f64,
    pub x_round: f64,
    /// Flare of the topside from the vertical (degrees) over the forward `x_flare` (x/L).
    pub flare_angle: f64,
    pub x_flare: f64,
    /// Running trim (degrees, bow up) about x/L = `trim_pivot` on the calm waterline.
    pub trim: f64,
    pub trim_pivot: f64,
    /// Sinkage beyond the one that keeps the design displacement under trim (units of L, down positive).
    pub sinkage: f64,
    /// Calibration target for Cb, and the sources of the particulars.
    pub target_cb: f64,
    pub source: String,
    /// The facts of the sources the member is built to honour (written to the file header; a variant
    /// says which parameters moved it away from them).
    pub honours: String,
}

/// Hermite smoothstep on [0, 1]: zero slope at both ends.
fn smoothstep(s: f64) -> f64 {
    let s = s.clamp(0.0, 1.0);
    s * s * (3.0 - 2.0 * s)
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
        out.honours = format!(
            "VARIANT ({}): measure its station facts; the {} approximation honours: {}",
            pairs.join(", "),
            self.name,
            self.honours
        );
        out.check()?;
        Ok(out)
    }

    /// The parameters' ranges, each error naming the parameter and what was expected.
    pub fn check(&self) -> anyhow::Result<()> {
        let in_open = |name: &str, v: f64, lo: f64, hi: f64| -> anyhow::Result<()> {
            anyhow::ensure!(
                v.is_finite() && v > lo && v < hi,
                "hull parameter `{name}` = {v}: expected a number between {lo} and {hi} (exclusive)"
            );
            Ok(())
        };
        in_open("beam", self.beam, 0.0, 1.0)?;
        in_open("draft", self.draft, 0.0, 1.0)?;
        in_open("freeboard", self.freeboard, 0.0, 1.0)?;
        in_open("x_entry", self.x_entry, 0.0, self.x_forefoot)?;
        in_open("x_forefoot", self.x_forefoot, self.x_entry, self.x_deepest)?;
        in_open("x_deepest", self.x_deepest, self.x_forefoot, 1.0)?;
        in_open("keel_forefoot", self.keel_forefoot, 0.0, 1.0 + 1e-12)?;
        in_open("x_max_beam", self.x_max_beam, self.x_entry, 1.0)?;
        in_open("entrance_angle", self.entrance_angle, 0.0, 60.0)?;
        in_open("flare_angle", self.flare_angle, -30.0, 60.0)?;
        in_open("x_flare", self.x_flare, -1e-12, 1.0)?;
        in_open("trim", self.trim, -10.0, 10.0)?;
        in_open("trim_pivot", self.trim_pivot, -1e-12, 1.0 + 1e-12)?;
        in_open("sinkage", self.sinkage, -self.draft, self.freeboard)?;
        in_open("transom_width", self.transom_width, -1e-12, 1.0)?;
        in_open("transom_immersion", self.transom_immersion, -1e-12, self.draft)?;
        let q = self.stem_exponent();
        anyhow::ensure!(
            q.is_finite() && q >= 1.2,
            "hull parameters `x_entry` = {}, `x_forefoot` = {}, `keel_forefoot` = {}: the stem curve through the \
             waterline at x_entry has exponent {q:.2}; expected at least 1.2 (move x_entry forward or the \
             forefoot aft)",
            self.x_entry,
            self.x_forefoot,
            self.keel_forefoot
        );
        let pe = self.entrance_exponent();
        anyhow::ensure!(
            pe >= 1.0,
            "hull parameter `entrance_angle` = {}°: with the widest waterline at x/L {} the planform exponent \
             would be {pe:.2}; expected at least 1 (a wider angle or a widest waterline further aft)",
            self.entrance_angle,
            self.x_max_beam
        );
        Ok(())
    }

    /// Keel depth at the forefoot.
    fn d_forefoot(&self) -> f64 {
        self.keel_forefoot * self.draft
    }

    /// Exponent q of the stem curve, from d(x_entry) = 0.
    fn stem_exponent(&self) -> f64 {
        let d = self.d_forefoot();
        (d / (d + self.freeboard)).ln() / (1.0 - self.x_entry / self.x_forefoot).ln()
    }

    /// Planform entrance exponent p_e from the waterline entrance half-angle.
    fn entrance_exponent(&self) -> f64 {
        self.entrance_angle.to_radians().tan() * (self.x_max_beam - self.x_entry) / (0.5 * self.beam)
    }

    /// Local keel depth d(x) in the hull frame (positive below the waterline; negative where the keel is
    /// above it).
    fn keel_depth(&self, x: f64) -> f64 {
        let (t, f, dff) = (self.draft, self.freeboard, self.d_forefoot());
        if x < self.x_forefoot {
            dff - (dff + f) * (1.0 - x / self.x_forefoot).powf(self.stem_exponent())
        } else if x <= self.x_deepest {
            dff + (t - dff) * smoothstep((x - self.x_forefoot) / (self.x_deepest - self.x_forefoot))
        } else {
            let s = (x - self.x_deepest) / (1.0 - self.x_deepest);
            t - (t - self.transom_immersion) * s * s
        }
    }

    /// The stem line: x where the stem is at height z (inverse of the stem curve; the forefoot below it).
    fn stem_x(&self, z: f64) -> f64 {
        let dff = self.d_forefoot();
        let r = ((dff + z) / (dff + self.freeboard)).clamp(0.0, 1.0);
        self.x_forefoot * (1.0 - r.powf(1.0 / self.stem_exponent()))
    }

    fn planform(&self, x: f64, z: f64) -> f64 {
        let half = 0.5 * self.beam;
        if x <= self.x_max_beam {
            let xs = self.stem_x(z);
            if x <= xs {
                return 0.0;
            }
            let s = ((x - xs) / (self.x_max_beam - xs)).clamp(0.0, 1.0);
            half * (1.0 - (1.0 - s).powf(self.entrance_exponent()))
        } else {
            let s = (x - self.x_max_beam) / (1.0 - self.x_max_beam);
            (half * (1.0 - (1.0 - self.transom_width) * s.powf(self.p_run))).max(0.0)
        }
    }

    fn exponent(&self, x: f64) -> f64 {
        let w = smoothstep(x / self.x_round);
        self.n_bow + (self.n_mid - self.n_bow) * w
    }

    /// Flare angle θ(x) (radians).
    fn flare_at(&self, x: f64) -> f64 {
        let fade = 1.0 - smoothstep((x - self.x_flare) / FLARE_FADE);
        self.flare_angle.to_radians() * fade
    }

    /// Half-breadth y/L at (x, z) in the hull frame (before the running attitude).
    pub fn half_breadth(&self, x: f64, z: f64) -> f64 {
        let b = self.planform(x, z);
        if z >= 0.0 {
            if b <= 0.0 {
                return 0.0;
            }
            let ramp = smoothstep((x - self.stem_x(z)) / FLARE_RAMP);
            return (b + self.flare_at(x).tan() * z * ramp).max(0.0);
        }
        let d = self.keel_depth(x);
        if d <= 0.0 || -z >= d {
            return 0.0;
        }
        let n = self.exponent(x);
        b * (1.0 - (-z / d).powf(n)).max(0.0).powf(1.0 / n)
    }

    /// The running attitude: trim (radians) and the total sinkage (units of L).
    fn attitude(&self, extra_sinkage: f64) -> Attitude {
        Attitude {
            sin: self.trim.to_radians().sin(),
            cos: self.trim.to_radians().cos(),
            pivot: self.trim_pivot,
            sinkage: self.sinkage + extra_sinkage,
        }
    }

    /// Offsets at `stations` stations (cosine-clustered towards the bow), `points` points per station, in the
    /// earth frame with `extra_sinkage` added to the stated sinkage.
    fn offsets_with(&self, stations: usize, points: usize, extra_sinkage: f64) -> Vec<Station> {
        let a = self.attitude(extra_sinkage);
        let (f, t) = (self.freeboard, self.draft);
        let mut st = vec![];
        for i in 0..stations {
            let u = i as f64 / (stations - 1) as f64;
            let x = (0.5 * (1.0 - (std::f64::consts::PI * u).cos())).mul_add(0.5, 0.5 * u);
            let deck = a.deck(x, f);
            let zk = a.keel(x, deck, |xh| self.keel_depth(xh)).min(deck - 1e-3 * (f + t));
            let mut pts = vec![];
            for k in 0..points {
                let s = k as f64 / (points - 1) as f64;
                // Cosine clustering at the keel and the deck; finer below the waterline.
                let z = zk + (deck - zk) * 0.5 * (1.0 - (std::f64::consts::PI * s).cos());
                let y = if k == 0 {
                    0.0
                } else {
                    let (xh, zh) = a.to_hull(x, z);
                    self.half_breadth(xh, zh)
                };
                pts.push([y, z]);
            }
            // The stem station degenerates to the stem line; keep its points distinct.
            st.push(Station { x, points: pts });
        }
        st
    }

    /// The sinkage (units of L) that makes the trimmed hull displace `volume`: zero without trim.
    fn displacement_sinkage(&self, stations: usize, points: usize, volume: f64) -> anyhow::Result<f64> {
        if self.trim == 0.0 && self.sinkage == 0.0 {
            return Ok(0.0);
        }
        let vol = |s: f64| {
            let h = self.with_stations(self.offsets_with(stations, points, s));
            hydrostatics(&HullSurface::new(&h), 200, 800).0.volume
        };
        let (mut lo, mut hi) = (-0.5 * self.draft, 0.5 * self.draft);
        anyhow::ensure!(
            vol(lo) < volume && vol(hi) > volume,
            "hull parameters `trim` = {}°, `sinkage` = {}: no sinkage within ±T/2 keeps the displacement",
            self.trim,
            self.sinkage
        );
        for _ in 0..40 {
            let mid = 0.5 * (lo + hi);
            if vol(mid) < volume {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Ok(0.5 * (lo + hi))
    }

    fn with_stations(&self, stations: Vec<Station>) -> HullOffsets {
        let mut notes = BTreeMap::new();
        notes.insert(
            "generator".into(),
            format!(
                "bowwave geometry::parametric {}",
                serde_json::to_string(self).unwrap_or_default()
            ),
        );
        notes.insert("target_cb".into(), format!("{:.4}", self.target_cb));
        notes.insert("honours".into(), self.honours.clone());
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
            stations,
        }
    }

    /// The offsets at rest (no trim, no sinkage) — what the Cb calibration measures.
    fn at_rest(&self) -> ParametricSpec {
        ParametricSpec {
            trim: 0.0,
            sinkage: 0.0,
            ..self.clone()
        }
    }

    /// Offsets at `stations` stations, `points` points per station, at the running attitude (earth frame,
    /// z = 0 the calm water). The header records the attitude and the sinkage that kept the displacement.
    pub fn offsets(&self, stations: usize, points: usize) -> anyhow::Result<HullOffsets> {
        self.check()?;
        let rest = self
            .at_rest()
            .with_stations(self.at_rest().offsets_with(stations, points, 0.0));
        let volume = hydrostatics(&HullSurface::new(&rest), 200, 800).0.volume;
        let kept = self.displacement_sinkage(stations, points, volume)?;
        let mut h = self.with_stations(self.offsets_with(stations, points, kept));
        h.meta.notes.insert(
            "attitude".into(),
            format!(
                "trim {:.3} deg bow up about x/L {:.3}, sinkage {:.6} L ({:.6} L keeps the displacement, {:.6} L stated)",
                self.trim,
                self.trim_pivot,
                kept + self.sinkage,
                kept,
                self.sinkage
            ),
        );
        Ok(h)
    }

    /// Adjusts `n_mid` by bisection so that Cb of the generated hull at rest matches `target_cb`; returns Cb,
    /// or an error when no n_mid in [1.2, 12] comes within 0.1 % of the target (overrides that leave the
    /// family's range used to be written with Cb 0.03 against 0.46).
    pub fn calibrate(&mut self, stations: usize, points: usize) -> anyhow::Result<f64> {
        self.check()?;
        let cb_of = |s: &ParametricSpec| {
            let r = s.at_rest();
            let h = r.with_stations(r.offsets_with(stations, points, 0.0));
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

/// Rotation by the trim about the pivot on the calm waterline, then the sinkage: hull frame (x, z) ↦ earth
/// frame x' = x_p + c (x − x_p) + s z, z' = −s (x − x_p) + c z − sinkage (bow up for s > 0, the bow at x = 0).
struct Attitude {
    sin: f64,
    cos: f64,
    pivot: f64,
    sinkage: f64,
}

impl Attitude {
    /// Hull-frame point of the earth-frame point (x', z').
    fn to_hull(&self, x: f64, z: f64) -> (f64, f64) {
        let (dx, dz) = (x - self.pivot, z + self.sinkage);
        (
            self.pivot + self.cos * dx - self.sin * dz,
            self.sin * dx + self.cos * dz,
        )
    }

    /// Earth-frame height of the deck (hull z = F) at earth x'.
    fn deck(&self, x: f64, freeboard: f64) -> f64 {
        (freeboard - self.sin * (x - self.pivot)) / self.cos - self.sinkage
    }

    /// Earth-frame height of the keel at earth x' (bisection on hull z + d(hull x) = 0, which grows with z'
    /// for trims of a few degrees), or `top` when the keel is above it there.
    fn keel(&self, x: f64, top: f64, depth: impl Fn(f64) -> f64) -> f64 {
        let g = |z: f64| {
            let (xh, zh) = self.to_hull(x, z);
            zh + depth(xh)
        };
        if g(top) <= 0.0 {
            return top;
        }
        let (mut lo, mut hi) = (-1.0, top);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if g(mid) < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
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
    let offsets = spec.offsets(stations, points)?;
    Ok((spec, cb, offsets))
}

/// R/V Athena (DTMB model 5365) approximation: L = 47 m, B = 6.9 m (between the 6.4–7.3 m of the sources),
/// T = 1.63 m, wide immersed transom, round-bilge semi-planing form, Cb 0.46 (middle of 0.43–0.49). The
/// stations of Marrone (2011, Fig. 10.7) are parameters: the stem enters the calm water at x/L 0.024 (S_1),
/// the keel is deepest at 0.446 (S_5), the waterline widest at 0.711 (S_6). Not stated anywhere, so chosen:
/// the forefoot at 0.12 with the keel there at 0.75 T (a keel with drag down to S_5), the entrance half-angle
/// 14.6° of the earlier approximation, a 10° flare over the forward 0.3 L, no trim (the sweeps of
/// `studies/athena-sensitivity*.toml` measure what each of these moves).
pub fn athena() -> ParametricSpec {
    let l = 47.0;
    ParametricSpec {
        name: "athena".into(),
        length_m: l,
        beam: 6.9 / l,
        draft: 1.63 / l,
        freeboard: 2.4 / l,
        x_entry: 0.024,
        x_forefoot: 0.12,
        keel_forefoot: 0.75,
        x_deepest: 0.446,
        x_max_beam: 0.711,
        entrance_angle: 14.6,
        p_run: 2.5,
        transom_width: 0.8,
        transom_immersion: 0.55 / l,
        n_bow: 1.15,
        n_mid: 3.0,
        x_round: 0.45,
        flare_angle: 10.0,
        x_flare: 0.3,
        trim: 0.0,
        trim_pivot: 0.5,
        sinkage: 0.0,
        target_cb: 0.46,
        source: "APPROXIMATION: no public offsets. Parametric hull calibrated to L = 47 m (OMAE2010 Fu et al.), draft 1.63 m and beam 6.4-7.3 m (Asheville class, Naval Vessel Register data), Cb 0.43-0.49; see data/reference/hulls".into(),
        honours: "Marrone 2011 Fig. 10.7: S_0 x/L 0 out of the water; S_1 x/L 0.024 water entry; S_5 x/L 0.446 deepest keel; S_6 x/L 0.711 widest; S_7 x/L 1 transom. Kept: L 47 m, B 6.9 m, T 1.63 m, Cb 0.46, transom 0.8 B immersed 0.55 m, freeboard 2.4 m".into(),
    }
}

/// NRV Alliance approximation: Lpp = 82 m, B = 15.2 m at the waterline, T = 5.2 m, Δ = 2920 t (Cb ≈ 0.44),
/// Marrone (2011) §10.1.4 and Table 10.4; the body plan (Fig. 10.20) is not public, so the stem, keel,
/// widest station (amidships), entrance (20.9°) and flare (10°) are chosen.
pub fn alliance() -> ParametricSpec {
    let l = 82.0;
    ParametricSpec {
        name: "alliance".into(),
        length_m: l,
        beam: 15.2 / l,
        draft: 5.2 / l,
        freeboard: 4.0 / l,
        x_entry: 0.015,
        x_forefoot: 0.06,
        keel_forefoot: 1.0,
        x_deepest: 0.6,
        x_max_beam: 0.5,
        entrance_angle: 20.9,
        p_run: 2.2,
        transom_width: 0.55,
        transom_immersion: 0.8 / l,
        n_bow: 1.2,
        n_mid: 3.0,
        x_round: 0.35,
        flare_angle: 10.0,
        x_flare: 0.3,
        trim: 0.0,
        trim_pivot: 0.5,
        sinkage: 0.0,
        target_cb: 2920.0 / 1.025 / (82.0 * 15.2 * 5.2),
        source: "APPROXIMATION: no public offsets. Parametric hull calibrated to Lpp = 82 m, B = 15.2 m, T = 5.2 m, displacement 2920 t (de.wikipedia mirror), Cb = 0.440; see data/reference/hulls".into(),
        honours: "Marrone 2011 section 10.1.4 and Table 10.4: Lpp 82 m, B 15.2 m at the waterline, T 5.2 m, displacement 2920 t (Cb 0.440 at rho 1.025 t/m3)".into(),
    }
}
