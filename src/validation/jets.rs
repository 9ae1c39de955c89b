//! Plane jets on walls (`jet-wall`, `jet-plate`, `jet-floor`) against Taylor's free-streamline solution and
//! the momentum balance.

use super::{check, col, Check};
use crate::cases::{case_file::BlockSpec, run::RunResult};

/// Start of the steady window of the `jet-wall` case (s): after the tapered front has split and the run-up
/// left the sensors (about 8 h/U after the first contact at 0.05 s).
pub const JET_WALL_STEADY_FROM: f64 = 0.4;

/// Wall pressure coefficient Cp = 1 − r² of a plane jet of full width `h` meeting a wall at right angles, at
/// distance `y` from the stagnation point: the free-streamline solution (data/reference/README.md §6,
/// x(r) = (h/π)[ln((1+r)/(1−r)) + 2 atan r]) inverted by bisection.
pub fn taylor_jet_cp(y: f64, h: f64) -> f64 {
    let x = |r: f64| h / std::f64::consts::PI * (((1.0 + r) / (1.0 - r)).ln() + 2.0 * r.atan());
    let (mut lo, mut hi) = (0.0, 1.0 - 1e-15);
    for _ in 0..100 {
        let m = 0.5 * (lo + hi);
        if x(m) < y.abs() {
            lo = m;
        } else {
            hi = m;
        }
    }
    1.0 - lo * lo
}

/// Means over the steady window of a `jet-wall` or `jet-plate` run: the force on the case's first wall, its
/// momentum-theorem value ρU² × the jet's width on the wall side of the symmetry plane (b for `jet-wall`,
/// whose floor is that plane; 2b for `jet-plate`), with U from the case's moving blocks, and for each sensor
/// (y/h, Cp, Taylor's Cp).
pub(super) fn jet_wall_means(r: &RunResult) -> (f64, f64, Vec<(f64, f64, f64)>) {
    let b = r.case.scales.length;
    let u = r
        .case
        .blocks
        .iter()
        .find_map(|bl| match bl {
            BlockSpec::Rectangle { velocity: Some(v), .. } => Some(v[0]),
            _ => None,
        })
        .unwrap_or(f64::NAN);
    let q = 0.5 * r.case.fluid.rho0 * u * u;
    let t = col(r, "t");
    let steady: Vec<usize> = (0..t.len()).filter(|&k| t[k] >= JET_WALL_STEADY_FROM).collect();
    let mean = |v: &[f64]| steady.iter().map(|&k| v[k]).sum::<f64>() / steady.len().max(1) as f64;
    let sensors = r
        .case
        .probes
        .pressure
        .iter()
        .map(|p| {
            let y = p.position[1];
            let cp = mean(&col(r, &format!("p_{}", p.name))) / q;
            (y / (2.0 * b), cp, taylor_jet_cp(y, 2.0 * b))
        })
        .collect();
    let width = if r.case.name == "jet-plate" { 2.0 * b } else { b };
    let wall = r.case.walls.first().map_or("tank", |w| w.name.as_str());
    (mean(&col(r, &format!("fx_{wall}"))), 2.0 * q * width, sensors)
}

/// (|Cp − Cp_Taylor|, Cp, Cp_Taylor) of the sensor nearest the symmetry plane (the floor of `jet-wall`, the jet
/// axis of `jet-plate`), whatever the order of the case file's sensors.
fn lowest_sensor(sensors: &[(f64, f64, f64)]) -> (f64, f64, f64) {
    sensors
        .iter()
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map_or((f64::NAN, f64::NAN, f64::NAN), |&(_, cp, cp_ref)| {
            ((cp - cp_ref).abs(), cp, cp_ref)
        })
}

/// (|Cp − Cp_Taylor|, Cp, Cp_Taylor) of the sensor farthest from Taylor's solution.
fn worst_sensor(sensors: &[(f64, f64, f64)]) -> (f64, f64, f64) {
    sensors
        .iter()
        .map(|&(_, cp, cp_ref)| ((cp - cp_ref).abs(), cp, cp_ref))
        .fold((0.0, f64::NAN, f64::NAN), |a, b| if b.0 >= a.0 { b } else { a })
}

/// The mean wall force of a jet case against its momentum-theorem value ρU² × `width` (named in the label),
/// within 2 %: the mean of a signal that the slug's sound waves still stir by about 1 %.
fn jet_force_check(r: &RunResult, force: f64, force_ref: f64, width: &str) -> Check {
    check(
        r,
        &format!("wall force / (rho U^2 {width}), mean over the steady window, rel. error"),
        force / force_ref,
        1.0,
        (force / force_ref - 1.0).abs(),
        Some(0.02),
    )
}

/// A check of a sensor's mean Cp against Taylor's, from (|Cp − Cp_Taylor|, Cp, Cp_Taylor).
fn cp_check(r: &RunResult, quantity: &str, (error, cp, cp_ref): (f64, f64, f64), tolerance: Option<f64>) -> Check {
    check(r, quantity, cp, cp_ref, error, tolerance)
}

/// Jet on a wall: the mean wall force over the steady window within 2 % of ρU²b (the momentum theorem; the
/// mean of a signal that the slug's sound waves still stir by about 1 %), and, reported, the sensors'
/// mean Cp against Taylor's free-streamline solution away from the corner (y/h ≥ 0.3) and at it (y/h 0.025).
pub fn jet_wall(r: &RunResult) -> Vec<Check> {
    let (force, force_ref, sensors) = jet_wall_means(r);
    let mut far = (0.0, 0.0, 0.0);
    for &(y_over_h, cp, cp_ref) in &sensors {
        let e = (cp - cp_ref).abs();
        if y_over_h >= 0.3 && e >= far.0 {
            far = (e, cp, cp_ref);
        }
    }
    let corner = lowest_sensor(&sensors);
    vec![
        jet_force_check(r, force, force_ref, "b"),
        cp_check(r, "wall Cp at y/h >= 0.3 vs Taylor, max abs. error", far, None),
        cp_check(r, "wall Cp at the corner sensor (y/h 0.025) vs Taylor", corner, None),
    ]
}

/// Largest |Cp − Cp_Taylor| a `jet-plate` sensor may show: 3 % of the stagnation pressure (the issue's
/// tolerance for the oscillating drop). Set after a first measurement, which it does not loosen: 0.0195 at
/// b/dx 10 and 0.0107 at b/dx 20 (first order), the largest errors at the stagnation sensors; the slug's sound
/// waves stir the means by about 1 %.
pub const JET_PLATE_CP_TOLERANCE: f64 = 0.03;

/// Jet on a flat wall (`jet-plate`): the mean wall force over the steady window within 2 % of ρU²h, and every
/// sensor's mean Cp within [`JET_PLATE_CP_TOLERANCE`] of Taylor's free-streamline solution, the stagnation
/// point included (reported on its own).
pub fn jet_plate(r: &RunResult) -> Vec<Check> {
    let (force, force_ref, sensors) = jet_wall_means(r);
    let worst = worst_sensor(&sensors);
    let stagnation = lowest_sensor(&sensors);
    vec![
        jet_force_check(r, force, force_ref, "h"),
        cp_check(
            r,
            "wall Cp vs Taylor, every sensor (y/h 0.025-1.5), max abs. error",
            worst,
            Some(JET_PLATE_CP_TOLERANCE),
        ),
        cp_check(
            r,
            "wall Cp at the stagnation sensor (y/h 0.025) vs Taylor",
            stagnation,
            None,
        ),
    ]
}

/// Two jets meeting over a floor (`jet-floor`): every sensor's mean Cp on the symmetry plane within
/// [`JET_PLATE_CP_TOLERANCE`] of Taylor's solution, as on the flat wall, and the stagnation sensor reported.
/// It fails: the floor's ghosts under the stagnation point over-pressure it (studies/results/validation/LOG.md, check 11). No
/// force check: the plane x = 0 is not a wall.
pub fn jet_floor(r: &RunResult) -> Vec<Check> {
    let (_, _, sensors) = jet_wall_means(r);
    let worst = worst_sensor(&sensors);
    vec![
        cp_check(
            r,
            "symmetry-plane Cp vs Taylor, every sensor (y/h 0.025-1.5), max abs. error",
            worst,
            Some(JET_PLATE_CP_TOLERANCE),
        ),
        cp_check(
            r,
            "symmetry-plane Cp at the stagnation sensor (y/h 0.025) vs Taylor",
            lowest_sensor(&sensors),
            None,
        ),
    ]
}
