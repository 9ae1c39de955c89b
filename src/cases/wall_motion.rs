//! Prescribed rigid motion of a case's wall (`[walls.motion]`): a tank in sway, heave and roll, each a sine or
//! all three from a table, turned into the pose law the solver's wall follows (`sph::rigid_pose`).
//!
//! A sine of amplitude A, period T and phase φ (deg) is s(t) = A [sin(2πt/T + φ) − sin φ]: the wall starts where
//! the case draws it, with velocity A (2π/T) cos φ (φ = −90° starts it at rest: s = A (1 − cos 2πt/T)). Sway is
//! along x (m), heave along y (m), roll counter-clockwise (deg) about `centre` (m, fixed in the wall; default the
//! centre of the wall's bounding box). A table (`table = "FILE.csv"`, beside the case file) gives rows of time (s),
//! sway (m), heave (m) and roll (deg), read as natural cubic splines whose first and second derivatives are the
//! wall's velocity and acceleration; it must cover the run (from t = 0 to the end time).

use super::case_file::{CaseFile, WallSpec};
use crate::geometry::spline::CubicSpline;
use crate::sph::rigid_pose::{MotionLaw, Pose2};
use nalgebra::Vector2;
use serde::{Deserialize, Serialize};
use std::path::Path;

type V2 = Vector2<f64>;

/// `[walls.motion]`.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MotionSpec {
    /// Horizontal displacement (m).
    #[serde(default)]
    pub sway: Option<Sine>,
    /// Vertical displacement (m).
    #[serde(default)]
    pub heave: Option<Sine>,
    /// Rotation about `centre` (deg, counter-clockwise).
    #[serde(default)]
    pub roll: Option<Sine>,
    /// A CSV of time (s), sway (m), heave (m), roll (deg), instead of the sines.
    #[serde(default)]
    pub table: Option<String>,
    /// The roll centre (m) at t = 0; default the centre of the wall's bounding box.
    #[serde(default)]
    pub centre: Option<Vec<f64>>,
}

/// A A [sin(2πt/T + φ) − sin φ] law.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sine {
    /// A (m, or deg for roll).
    pub amplitude: f64,
    /// T (in the case's time unit).
    pub period: f64,
    /// φ (deg); default 0.
    #[serde(default)]
    pub phase: f64,
}

impl Sine {
    /// (s, ṡ, s̈) at time t (s), the period in seconds.
    pub fn eval(&self, t: f64) -> (f64, f64, f64) {
        let w = 2.0 * std::f64::consts::PI / self.period;
        let phi = self.phase.to_radians();
        let (s, c) = (w * t + phi).sin_cos();
        (
            self.amplitude * (s - phi.sin()),
            self.amplitude * w * c,
            -self.amplitude * w * w * s,
        )
    }
}

/// The columns (time, sway, heave, roll) of a motion table ([`super::reference_file::numeric_columns`]).
pub fn load_table(path: &Path) -> anyhow::Result<[Vec<f64>; 4]> {
    let cols = super::reference_file::numeric_columns(path, 4)?;
    anyhow::ensure!(
        cols[0].len() >= 3,
        "{}: expected at least three rows of four numeric columns (time s, sway m, heave m, roll deg), found {}",
        path.display(),
        cols[0].len()
    );
    cols.try_into().map_err(|_| anyhow::anyhow!("four columns"))
}

/// Checks a wall's motion, but for its table's file ([`check_tables`]). Returns (field, what was expected).
pub fn check(k: usize, w: &WallSpec) -> Result<(), (String, String)> {
    let Some(m) = &w.motion else { return Ok(()) };
    let field = |f: &str| format!("walls[{k}].motion.{f}");
    if w.velocity.is_some() {
        return Err((
            format!("walls[{k}].velocity"),
            "either `velocity` or `motion`, not both".into(),
        ));
    }
    let sines = [("sway", m.sway), ("heave", m.heave), ("roll", m.roll)];
    for (name, s) in sines {
        if let Some(s) = s {
            if !(s.amplitude.is_finite() && s.period.is_finite() && s.period > 0.0 && s.phase.is_finite()) {
                return Err((
                    field(name),
                    "{ amplitude (m, or deg for roll), period > 0 (the case's time unit), phase (deg) }".into(),
                ));
            }
        }
    }
    let any_sine = sines.iter().any(|(_, s)| s.is_some());
    match (&m.table, any_sine) {
        (Some(_), true) => {
            return Err((
                field("table"),
                "either a table or sines (sway, heave, roll), not both".into(),
            ));
        }
        (None, false) => return Err((field("sway"), "a sway, heave or roll sine, or a table".into())),
        _ => {}
    }
    if let Some(c) = &m.centre {
        if c.len() != 2 || !c.iter().all(|v| v.is_finite()) {
            return Err((field("centre"), "a 2-component point (m)".into()));
        }
    }
    Ok(())
}

/// Checks that every motion table of a case read from disk loads and covers the run (from t = 0 to the end
/// time, in seconds), when the case is read.
pub fn check_tables(case: &CaseFile, file: &str) -> Result<(), crate::input_error::InputError> {
    for (k, w) in case.walls.iter().enumerate() {
        let Some(table) = w.motion.as_ref().and_then(|m| m.table.as_ref()) else {
            continue;
        };
        let field = format!("walls[{k}].motion.table");
        let path = case.beside(table);
        let cols = load_table(&path).map_err(|e| {
            crate::input_error::InputError::field(file, &field, format!("a readable motion table: {e}"))
        })?;
        let (t0, t1, end) = (cols[0][0], *cols[0].last().unwrap(), case.output.end_time);
        if t0 > 0.0 || t1 < end {
            return Err(crate::input_error::InputError::field(
                file,
                &field,
                format!("a table covering the run, t = 0 to {end} s (it covers {t0} to {t1} s)"),
            ));
        }
    }
    Ok(())
}

/// The pose law of every wall of a case, in order: its `motion`'s ([`law`]), a translation for a `velocity`, or
/// `None` for a still wall. What the ghosts, the sensors and the gauges on a wall follow.
pub fn laws(case: &CaseFile) -> anyhow::Result<Vec<Option<MotionLaw>>> {
    case.walls
        .iter()
        .map(|w| {
            Ok(match &w.velocity {
                Some(v) => {
                    let v = V2::new(v[0], v[1]);
                    Some(MotionLaw::new(move |t| Pose2::translation(v * t, v, V2::zeros())))
                }
                None => law(case, w)?,
            })
        })
        .collect()
}

/// The pose law of a wall with a motion (checked by [`check`]); `None` without one.
pub fn law(case: &CaseFile, w: &WallSpec) -> anyhow::Result<Option<MotionLaw>> {
    let Some(m) = &w.motion else { return Ok(None) };
    let centre = match &m.centre {
        Some(c) => V2::new(c[0], c[1]),
        None => {
            let (mut lo, mut hi) = (V2::repeat(f64::INFINITY), V2::repeat(f64::NEG_INFINITY));
            for p in &w.points {
                lo = lo.inf(&V2::new(p[0], p[1]));
                hi = hi.sup(&V2::new(p[0], p[1]));
            }
            (lo + hi) * 0.5
        }
    };
    if let Some(file) = &m.table {
        let path = case.beside(file);
        let [t, sway, heave, roll] = load_table(&path)?;
        let (sx, sy, sr) = (
            CubicSpline::new(&t, &sway),
            CubicSpline::new(&t, &heave),
            CubicSpline::new(&t, &roll),
        );
        // The table's values at t = 0 are where the case draws the wall: the pose is relative to them.
        let (x0, y0, r0) = (sx.eval(0.0).0, sy.eval(0.0).0, sr.eval(0.0).0);
        return Ok(Some(MotionLaw::new(move |t| {
            let (x, y, r) = (sx.eval(t), sy.eval(t), sr.eval(t));
            Pose2 {
                d: V2::new(x.0 - x0, y.0 - y0),
                v: V2::new(x.1, y.1),
                a: V2::new(x.2, y.2),
                theta: (r.0 - r0).to_radians(),
                omega: r.1.to_radians(),
                alpha: r.2.to_radians(),
                centre,
            }
        })));
    }
    let zero = Sine {
        amplitude: 0.0,
        period: 1.0,
        phase: 0.0,
    };
    let (sx, sy, sr) = (m.sway.unwrap_or(zero), m.heave.unwrap_or(zero), m.roll.unwrap_or(zero));
    Ok(Some(MotionLaw::new(move |t| {
        let (x, y, r) = (sx.eval(t), sy.eval(t), sr.eval(t));
        Pose2 {
            d: V2::new(x.0, y.0),
            v: V2::new(x.1, y.1),
            a: V2::new(x.2, y.2),
            theta: r.0.to_radians(),
            omega: r.1.to_radians(),
            alpha: r.2.to_radians(),
            centre,
        }
    })))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sine_starts_where_the_case_draws_the_wall_and_its_derivatives_are_exact() {
        let s = Sine {
            amplitude: 0.01,
            period: 1.2,
            phase: -90.0,
        };
        let (x, v, a) = s.eval(0.0);
        assert!(x.abs() < 1e-15 && v.abs() < 1e-15);
        let w = 2.0 * std::f64::consts::PI / 1.2;
        assert!((a - 0.01 * w * w).abs() < 1e-12);
        let h = 1e-5;
        let t = 0.37;
        assert!(((s.eval(t + h).0 - s.eval(t - h).0) / (2.0 * h) - s.eval(t).1).abs() < 1e-8);
    }
}
