//! Validation of the built-in cases against analytic solutions and published data: each check gives our
//! value, the reference, the error and the tolerance it must meet. `bowwave validate` runs them at full
//! resolution; the tests in `tests/` run the same checks at coarse resolution.

use crate::cases::{
    self,
    case_file::BlockSpec,
    run::{run, RunOptions, RunResult},
    CaseFile,
};
use crate::io::plot::{line_plot, Series, Style};
use crate::reference::{self, interp, named};
use crate::sph::polyline_wall::GhostKind;
use std::path::Path;

/// One validated quantity.
#[derive(Clone, Debug)]
pub struct Check {
    pub case: String,
    pub quantity: String,
    pub value: f64,
    pub reference: f64,
    /// The error measure (defined per check in `quantity`).
    pub error: f64,
    /// `None`: reported only.
    pub tolerance: Option<f64>,
}

impl Check {
    pub fn pass(&self) -> bool {
        self.error.is_finite() && self.tolerance.is_none_or(|t| self.error <= t)
    }
}

fn check(r: &RunResult, quantity: &str, value: f64, reference: f64, error: f64, tolerance: Option<f64>) -> Check {
    Check {
        case: format!(
            "{} (res {:.0}{})",
            r.case.name,
            r.case.scales.length / r.dx,
            if r.case.walls.iter().any(|w| w.ghosts == GhostKind::Images) {
                ", images"
            } else {
                ""
            }
        ),
        quantity: quantity.into(),
        value,
        reference,
        error,
        tolerance,
    }
}

fn col(r: &RunResult, name: &str) -> Vec<f64> {
    r.series
        .column(name)
        .unwrap_or_else(|| panic!("series column `{name}` missing"))
}

/// Resolution used by `bowwave validate` (full) for each built-in case.
pub fn full_resolution(case: &str) -> Option<f64> {
    match case {
        "hydrostatic" => Some(40.0),
        "elliptic-drop" => Some(50.0),
        "oscillating-drop" => Some(40.0),
        "dam-break-mm" => Some(50.0),
        "dam-break" => Some(80.0),
        "jet-wall" | "jet-plate" | "jet-floor" => Some(20.0),
        _ => None,
    }
}

/// Largest |a − a_ref|/a_ref over the samples with t ≤ t_max, as (error, ours, reference).
fn worst_relative_error(t: &[f64], a: &[f64], tr: &[f64], ar: &[f64], t_max: f64) -> (f64, f64, f64) {
    let mut worst = (0.0, 0.0, 0.0);
    for (ti, ai) in t.iter().zip(a) {
        if *ti > t_max {
            break;
        }
        if let Some(aref) = interp(tr, ar, *ti) {
            let e = (ai - aref).abs() / aref;
            if e >= worst.0 {
                worst = (e, *ai, aref);
            }
        }
    }
    worst
}

/// Hydrostatic tank: bottom pressure within 1 % of ρgH and E_K/(M g H) < 1e-5 at the end.
pub fn hydrostatic(r: &RunResult) -> Vec<Check> {
    let p = col(r, "pstar_bottom");
    let ek = col(r, "e_kinetic");
    let last = p.len() - 1;
    let g = r.case.gravity_magnitude();
    let mgh = r.sim.fluid.total_mass() * g * r.case.scales.length;
    let fy = col(r, "fy_tank");
    let weight = r.sim.fluid.total_mass() * g;
    vec![
        check(
            r,
            "bottom p/(rho g H) at end, |rel. error|",
            p[last],
            1.0,
            (p[last] - 1.0).abs(),
            Some(0.01),
        ),
        check(r, "E_K/(M g H) at end", ek[last] / mgh, 0.0, ek[last] / mgh, Some(1e-5)),
        check(
            r,
            "bottom force / weight at end, |rel. error| (7.12)",
            -fy[last] / weight,
            1.0,
            (-fy[last] / weight - 1.0).abs(),
            None,
        ),
        check(
            r,
            "near-surface pressure: mean |p - rho0 g (H - z)|/(rho0 g H), top 0.2 H, at end",
            f64::NAN,
            0.0,
            near_surface_pressure_error(r),
            None,
        ),
    ]
}

/// Mean |p − ρ0 g (H − z)|/(ρ0 g H) over the particles in the top 0.2 H of the still tank at the end, H the
/// initial depth (scales.length): where the density diffusion without the gradient correction (5.4) drifts
/// (Antuono et al. 2010), while δ-SPH (5.2) keeps the hydrostatic solution.
pub fn near_surface_pressure_error(r: &RunResult) -> f64 {
    let f = &r.sim.fluid;
    let eos = r.sim.cfg.eos;
    let g = r.case.gravity_magnitude();
    let h = r.case.scales.length;
    let rho0 = r.case.fluid.rho0;
    let (mut s, mut n) = (0.0, 0usize);
    for (x, rho) in f.pos.iter().zip(&f.rho) {
        let (z, p) = (x[1], eos.pressure(*rho));
        if z > 0.8 * h {
            s += (p - rho0 * g * (h - z)).abs() / (rho0 * g * h);
            n += 1;
        }
    }
    s / n.max(1) as f64
}

/// Free elliptic drop: max |a − a_ref|/a_ref over t ≤ 0.008 s within 2 %.
pub fn elliptic_drop(r: &RunResult) -> Vec<Check> {
    let rt = reference::load("elliptic_drop");
    let (tr, ar) = (named(&rt, "t_s"), named(&rt, "a_semi_axis_x_m"));
    let (t, a) = (col(r, "t"), col(r, "semi_axis_x"));
    let worst = worst_relative_error(&t, &a, &tr, &ar, 0.008 + 1e-12);
    let a_end = interp(&t, &a, 0.008).unwrap_or(f64::NAN);
    let aref_end = interp(&tr, &ar, 0.008).unwrap_or(f64::NAN);
    vec![
        check(
            r,
            "semi-axis a(t), max rel. error for t <= 0.008 s",
            worst.1,
            worst.2,
            worst.0,
            Some(0.02),
        ),
        check(
            r,
            "semi-axis a at t = 0.008 s (m), rel. error",
            a_end,
            aref_end,
            (a_end - aref_end).abs() / aref_end,
            None,
        ),
    ]
}

/// Oscillating drop: max |A − A_ref|/A_ref over two periods within 3 %; energy decay reported.
pub fn oscillating_drop(r: &RunResult) -> Vec<Check> {
    let rt = reference::load("oscillating_drop");
    let (tr, ar) = (named(&rt, "t"), named(&rt, "A_semi_axis_x"));
    let (t, a) = (col(r, "t"), col(r, "semi_axis_x"));
    let period = 4.567375;
    let worst = worst_relative_error(&t, &a, &tr, &ar, 2.0 * period);
    let de = col(r, "de_mechanical_rel");
    let e_end = *de.last().unwrap();
    vec![
        check(
            r,
            "semi-axis A(t), max rel. error over two periods",
            worst.1,
            worst.2,
            worst.0,
            Some(0.03),
        ),
        check(
            r,
            "mechanical energy change over the run / initial (E_K + E_C)",
            e_end,
            0.0,
            e_end.abs(),
            None,
        ),
    ]
}

/// Worst (error, ours, reference) and mean of |z(t) − z_ref|/z_ref over the reference times t ≤ `t_max`
/// (`relative`), or of |z(t) − z_ref| (absolute), with our series interpolated at the reference's sparse
/// times (`worst_relative_error` goes the other way, for dense references). Reference times outside the
/// run give NaN.
fn errors_at_reference_times(
    t: &[f64],
    z: &[f64],
    t_ref: &[f64],
    z_ref: &[f64],
    t_max: f64,
    relative: bool,
) -> ((f64, f64, f64), f64) {
    let mut worst = (0.0, 0.0, 0.0);
    let (mut sum, mut n) = (0.0, 0);
    for (tr, zr) in t_ref.iter().zip(z_ref).filter(|(tr, _)| **tr <= t_max) {
        let zz = interp(t, z, *tr).unwrap_or(f64::NAN);
        let e = if relative {
            (zz - zr).abs() / zr
        } else {
            (zz - zr).abs()
        };
        sum += e;
        n += 1;
        if e.is_nan() || e >= worst.0 {
            worst = (e, zz, *zr);
        }
    }
    (worst, sum / n.max(1) as f64)
}

/// Largest reference time τ = t√(g/a) of the residual-height comparison. The run ends at T = 3.4 (τ = 2.40):
/// Table 6's last point inside it is τ = 2.21, the next (2.45) is past the end.
const MM_HEIGHT_TAU_MAX: f64 = 2.3;

/// The Martin–Moyce column height h/(n²a) = h/(2a) over the run, from the `column` gauge.
fn mm_column_height(r: &RunResult) -> Vec<f64> {
    let two_a = 2.0 * r.case.scales.length;
    col(r, "eta_column").iter().map(|e| e / two_a).collect()
}

/// Martin–Moyce (n² = 2): the surge front |x − x_exp|/x_exp ≤ 10 % at every T ≤ 2.5, T = √2 t √(g/a)
/// (the tolerance); the residual column height h/(2a) against their Table 6 within 1/18, the spacing
/// of the markers it was read from (their values are multiples of 1/18 ≈ 0.056); and, reported only, the
/// front against the other experiment with this column, Koshizuka & Oka (1996), at the same times.
pub fn martin_moyce(r: &RunResult) -> Vec<Check> {
    let ts = col(r, "t_star");
    let big_t: Vec<f64> = ts.iter().map(|t| t * 2f64.sqrt()).collect();
    let fs = col(r, "front_star");
    let mm = reference::load("martin_moyce_front");
    let (front, front_mean) =
        errors_at_reference_times(&big_t, &fs, &reference::col(&mm, 0), &reference::col(&mm, 1), 2.5, true);
    let ko = reference::load("koshizuka_oka_front");
    let (ko_front, ko_mean) =
        errors_at_reference_times(&big_t, &fs, &reference::col(&ko, 0), &reference::col(&ko, 1), 2.5, true);
    let hr = reference::load("martin_moyce_height");
    let h = mm_column_height(r);
    let (height, height_mean) = errors_at_reference_times(
        &ts,
        &h,
        &reference::col(&hr, 0),
        &reference::col(&hr, 1),
        MM_HEIGHT_TAU_MAX,
        false,
    );
    vec![
        check(
            r,
            "front x/a, max rel. error at experimental T <= 2.5",
            front.1,
            front.2,
            front.0,
            Some(0.10),
        ),
        check(
            r,
            "front x/a, mean rel. error at experimental T <= 2.5",
            f64::NAN,
            f64::NAN,
            front_mean,
            None,
        ),
        check(
            r,
            "column height h/(2a), max abs. error at experimental tau <= 2.3",
            height.1,
            height.2,
            height.0,
            Some(1.0 / 18.0),
        ),
        check(
            r,
            "column height h/(2a), mean abs. error",
            f64::NAN,
            f64::NAN,
            height_mean,
            None,
        ),
        check(
            r,
            "front x/a vs Koshizuka & Oka 1996, max rel. error at T <= 2.5",
            ko_front.1,
            ko_front.2,
            ko_front.0,
            None,
        ),
        check(
            r,
            "front x/a vs Koshizuka & Oka 1996, mean rel. error",
            f64::NAN,
            f64::NAN,
            ko_mean,
            None,
        ),
    ]
}

/// The Marrone et al. (2011) column closest to resolution `res` (40, 80 or 320).
fn marrone_column(res: f64) -> (usize, &'static str) {
    let choices = [
        (40usize, "p_over_rho_g_H_deltaSPH_H_over_dx_40"),
        (80, "p_over_rho_g_H_deltaSPH_H_over_dx_80"),
        (320, "p_over_rho_g_H_deltaSPH_H_over_dx_320"),
    ];
    *choices
        .iter()
        .min_by(|a, b| {
            ((a.0 as f64).ln() - res.ln())
                .abs()
                .total_cmp(&((b.0 as f64).ln() - res.ln()).abs())
        })
        .unwrap()
}

/// First time a pressure signal exceeds `level` (linear interpolation); NaN if never.
pub fn first_rise(t: &[f64], p: &[f64], level: f64) -> f64 {
    for k in 1..t.len() {
        if p[k] >= level && p[k - 1] < level {
            return t[k - 1] + (level - p[k - 1]) / (p[k] - p[k - 1]) * (t[k] - t[k - 1]);
        }
    }
    f64::NAN
}

/// Pressure level (p/(ρgH)) that defines the first impact at P1.
pub const IMPACT_LEVEL: f64 = 0.1;

/// Width (in t√(g/H)) of the centred moving average applied to a P1 signal, ours and the references' alike,
/// before its first rise is read: 0.05, about 0.007 s at Buchner's scale, five of our samples. Why: a
/// single-sample blip of 0.1–0.3 ρgH before the water arrives should not count as the impact (Shepard ghosts,
/// H/dx 40: raw first crossing 2.488 on one such sample, averaged 2.719). Larger spikes survive it (a blip of 2
/// still averages to 0.4), and so does the ±2 ρgH ringing of image ghosts at the impact. The references' rises
/// are sharp and nearly linear, which a centred average leaves within 0.004 of where they were (test
/// `impact_time_measure_reads_the_published_curves`).
pub const IMPACT_SMOOTHING: f64 = 0.05;

/// `p` averaged over the samples within `width`/2 of each time (a centred moving average, for uneven
/// sampling too).
pub fn moving_average(t: &[f64], p: &[f64], width: f64) -> Vec<f64> {
    let (mut lo, mut hi) = (0, 0);
    let mut sum = 0.0;
    let mut out = Vec::with_capacity(t.len());
    for k in 0..t.len() {
        while hi < t.len() && t[hi] <= t[k] + 0.5 * width {
            sum += p[hi];
            hi += 1;
        }
        while t[lo] < t[k] - 0.5 * width {
            sum -= p[lo];
            lo += 1;
        }
        out.push(sum / (hi - lo) as f64);
    }
    out
}

/// First impact time: the signal, linear between its samples, is read every 0.005 t√(g/H) (so that sparse
/// digitised curves and our series are averaged alike), averaged over [`IMPACT_SMOOTHING`], and its first rise
/// through [`IMPACT_LEVEL`] is taken.
pub fn impact_time(t: &[f64], p: &[f64]) -> f64 {
    if t.len() < 2 {
        return f64::NAN;
    }
    let step = 0.005;
    let n = ((t[t.len() - 1] - t[0]) / step).floor() as usize; // the last grid point stays within t
    let grid: Vec<f64> = (0..n).map(|k| t[0] + step * k as f64).collect();
    let values: Vec<f64> = grid.iter().map(|&x| interp(t, p, x).unwrap_or(f64::NAN)).collect();
    first_rise(&grid, &moving_average(&grid, &values, IMPACT_SMOOTHING), IMPACT_LEVEL)
}

/// t√(g/H) at which the dam break's plunging wave closes an air cavity (thesis §8.4, text beside Fig. 8.30).
pub const CAVITY_CLOSURE_T_STAR: f64 = 6.0;

/// Dam break: first-impact time at P1 within 0.1 t√(g/H) of Marrone et al. at the same resolution; mean
/// |p − p_ref|/(ρgH) over t√(g/H) ∈ [2, 7] at P1 and P2 against Marrone and Buchner (reported); the cavity
/// closure of the plunging wave within 0.2 of [`CAVITY_CLOSURE_T_STAR`].
pub fn dam_break(r: &RunResult) -> Vec<Check> {
    let res = r.case.scales.length / r.dx;
    // The run refreshed the state at its last sample (the end time).
    let noise = r.sim.pressure_noise() / (r.case.fluid.rho0 * r.case.gravity_magnitude() * r.case.scales.length);
    let (nres, colname) = marrone_column(res);
    let ts = col(r, "t_star");
    let mut out = vec![];
    for (probe, mref, bref) in [("P1", "marrone_p1", "buchner_p1"), ("P2", "marrone_p2", "buchner_p2")] {
        let p = col(r, &format!("pstar_{probe}"));
        let m = reference::load(mref);
        let (tm, pm) = (reference::col(&m, 0), named(&m, colname));
        let b = reference::load(bref);
        let (tb, pb) = (reference::col(&b, 0), reference::col(&b, 1));
        if probe == "P1" {
            let ours = impact_time(&ts, &p);
            let theirs = impact_time(&tm, &pm);
            out.push(check(
                r,
                &format!("P1 first impact t*(p* >= {IMPACT_LEVEL}, {IMPACT_SMOOTHING} t* mean) vs Marrone H/dx={nres}, |diff|"),
                ours,
                theirs,
                (ours - theirs).abs(),
                Some(0.1),
            ));
            let exp = impact_time(&tb, &pb);
            out.push(check(
                r,
                &format!(
                    "P1 first impact t*(p* >= {IMPACT_LEVEL}, {IMPACT_SMOOTHING} t* mean) vs Buchner exp., |diff|"
                ),
                ours,
                exp,
                (ours - exp).abs(),
                Some(0.1),
            ));
        }
        for (label, tr, pr) in [
            (format!("Marrone H/dx={nres}"), &tm, &pm),
            ("Buchner exp.".to_string(), &tb, &pb),
        ] {
            let (mut s, mut n) = (0.0, 0);
            for (t, pv) in ts.iter().zip(&p) {
                if (2.0..=7.0).contains(t) {
                    if let Some(q) = interp(tr, pr, *t) {
                        s += (pv - q).abs();
                        n += 1;
                    }
                }
            }
            out.push(check(
                r,
                &format!("{probe} mean |p-p_ref|/(rho g H), t* in [2,7], vs {label}"),
                f64::NAN,
                f64::NAN,
                s / n.max(1) as f64,
                None,
            ));
        }
    }
    // The plunging wave that falls back from the wall run-up closes an air cavity at t* = 6.0 in the thesis
    // (§8.4, its δ-SPH run). Tolerance 0.2 (3 %), set before measuring: our front reaches the wall 3 % slower
    // than theirs (1.89 against 1.95 √(gH)), and everything after the impact inherits that lag.
    let t_scale = (r.case.scales.length / r.case.gravity_magnitude()).sqrt();
    let closure = r.cavity.as_ref().map_or(f64::NAN, |c| c.time / t_scale);
    out.push(check(
        r,
        "plunging wave closes its cavity, t* (thesis §8.4: 6.0), |diff|",
        closure,
        CAVITY_CLOSURE_T_STAR,
        (closure - CAVITY_CLOSURE_T_STAR).abs(),
        Some(0.2),
    ));
    out.push(check(
        r,
        "pressure noise at end: RMS of p minus its kernel-smoothed field, /(rho g H)",
        noise,
        0.0,
        noise,
        None,
    ));
    out
}

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
fn jet_wall_means(r: &RunResult) -> (f64, f64, Vec<(f64, f64, f64)>) {
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
/// It fails: the floor's ghosts under the stagnation point over-pressure it (docs/method.md, check 11). No
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

/// The checks of a built-in case, if it has any.
pub fn checks(r: &RunResult) -> Option<Vec<Check>> {
    Some(match r.case.name.as_str() {
        "hydrostatic" => hydrostatic(r),
        "elliptic-drop" => elliptic_drop(r),
        "oscillating-drop" => oscillating_drop(r),
        "dam-break-mm" => martin_moyce(r),
        "dam-break" => dam_break(r),
        "jet-wall" => jet_wall(r),
        "jet-plate" => jet_plate(r),
        "jet-floor" => jet_floor(r),
        _ => return None,
    })
}

/// Prints a table of checks.
pub fn print_checks(checks: &[Check]) {
    println!(
        "{:<26} {:<72} {:>11} {:>11} {:>10} {:>9}  result",
        "case", "quantity", "ours", "reference", "error", "tol."
    );
    for c in checks {
        let tol = c.tolerance.map(|t| format!("{t:.3}")).unwrap_or_else(|| "-".into());
        let res = match (c.tolerance, c.pass()) {
            (None, _) => "report",
            (Some(_), true) => "PASS",
            (Some(_), false) => "FAIL",
        };
        println!(
            "{:<26} {:<72} {:>11.5} {:>11.5} {:>10.4e} {:>9}  {res}",
            c.case, c.quantity, c.value, c.reference, c.error, tol
        );
    }
}

/// Plots of a run: energies, and per case its probes or semi-axes against the references.
pub fn plots(r: &RunResult, dir: &Path) -> anyhow::Result<Vec<std::path::PathBuf>> {
    let mut files = vec![];
    let ts = col(r, "t_star");
    let xy = |a: &[f64], b: &[f64]| a.iter().copied().zip(b.iter().copied()).collect::<Vec<_>>();
    let p = dir.join(format!("{}_energy.png", r.case.name));
    line_plot(
        &p,
        &format!("{}: mechanical energy change", r.case.name),
        "t*",
        "(E_M - E_M0) / scale",
        &[Series {
            name: "dE_M".into(),
            points: xy(&ts, &col(r, "de_mechanical_rel")),
            style: Style::Line,
        }],
    )?;
    files.push(p);
    match r.case.name.as_str() {
        "dam-break" => {
            let res = r.case.scales.length / r.dx;
            for (probe, mref, bref) in [("P1", "marrone_p1", "buchner_p1"), ("P2", "marrone_p2", "buchner_p2")] {
                let m = reference::load(mref);
                let b = reference::load(bref);
                let mut series = vec![Series {
                    name: format!("bowwave H/dx={res:.0}"),
                    points: xy(&ts, &col(r, &format!("pstar_{probe}"))),
                    style: Style::Line,
                }];
                for n in [40, 80, 320] {
                    let c = format!("p_over_rho_g_H_deltaSPH_H_over_dx_{n}");
                    series.push(Series {
                        name: format!("Marrone 2011 H/dx={n}"),
                        points: xy(&reference::col(&m, 0), &named(&m, &c)),
                        style: Style::Line,
                    });
                }
                series.push(Series {
                    name: "Buchner 2002 exp.".into(),
                    points: xy(&reference::col(&b, 0), &reference::col(&b, 1)),
                    style: Style::Markers,
                });
                let p = dir.join(format!("dam-break_{probe}.png"));
                line_plot(
                    &p,
                    &format!("Dam break: pressure at {probe}"),
                    "t sqrt(g/H)",
                    "p / (rho g H)",
                    &series,
                )?;
                files.push(p);
            }
        }
        "jet-wall" | "jet-plate" | "jet-floor" => {
            // Mean Cp of each sensor over the steady window, and Taylor's curve.
            let b = r.case.scales.length;
            let sph: Vec<(f64, f64)> = jet_wall_means(r).2.iter().map(|&(y, cp, _)| (y, cp)).collect();
            let theory: Vec<(f64, f64)> = (0..=160)
                .map(|k| {
                    let y_over_h = k as f64 * 0.01;
                    (y_over_h, taylor_jet_cp(y_over_h * 2.0 * b, 2.0 * b))
                })
                .collect();
            let p = dir.join(format!("{}_cp.png", r.case.name));
            let title = match r.case.name.as_str() {
                "jet-plate" => "Plane jet on a flat wall: pressure along the wall",
                "jet-floor" => "Two jets meeting over a floor: pressure on the symmetry plane",
                _ => "Plane jet into a floor-wall corner: pressure along the wall",
            };
            line_plot(
                &p,
                title,
                "y / h (h: full jet width)",
                "Cp = p / (rho U^2 / 2)",
                &[
                    Series {
                        name: "bowwave, mean over t >= 0.4 s".into(),
                        points: sph,
                        style: Style::Markers,
                    },
                    Series {
                        name: "free-streamline solution (Taylor 1966)".into(),
                        points: theory,
                        style: Style::Line,
                    },
                ],
            )?;
            files.push(p);
        }
        "dam-break-mm" => {
            let rt = reference::load("martin_moyce_front");
            let ko = reference::load("koshizuka_oka_front");
            let big_t: Vec<f64> = ts.iter().map(|t| t * 2f64.sqrt()).collect();
            let p = dir.join("dam-break-mm_front.png");
            line_plot(
                &p,
                "Martin-Moyce surge front (n^2 = 2)",
                "T = n t sqrt(g/a)",
                "x / a",
                &[
                    Series {
                        name: "bowwave".into(),
                        points: xy(&big_t, &col(r, "front_star")),
                        style: Style::Line,
                    },
                    Series {
                        name: "Martin & Moyce 1952, Table 2".into(),
                        points: xy(&reference::col(&rt, 0), &reference::col(&rt, 1)),
                        style: Style::Markers,
                    },
                    Series {
                        name: "Koshizuka & Oka 1996".into(),
                        points: xy(&reference::col(&ko, 0), &reference::col(&ko, 1)),
                        style: Style::Markers,
                    },
                ],
            )?;
            files.push(p);
            let hr = reference::load("martin_moyce_height");
            let h = mm_column_height(r);
            let p = dir.join("dam-break-mm_column_height.png");
            line_plot(
                &p,
                "Martin-Moyce residual column height (n^2 = 2)",
                "tau = t sqrt(g/a)",
                "h / (n^2 a)",
                &[
                    Series {
                        name: "bowwave (0.1a from the back wall)".into(),
                        points: xy(&ts, &h),
                        style: Style::Line,
                    },
                    Series {
                        name: "Martin & Moyce 1952, Table 6".into(),
                        points: xy(&reference::col(&hr, 0), &reference::col(&hr, 1)),
                        style: Style::Markers,
                    },
                ],
            )?;
            files.push(p);
        }
        "elliptic-drop" | "oscillating-drop" => {
            let (file, tc, ac) = if r.case.name == "elliptic-drop" {
                ("elliptic_drop", "t_s", "a_semi_axis_x_m")
            } else {
                ("oscillating_drop", "t", "A_semi_axis_x")
            };
            let rt = reference::load(file);
            let p = dir.join(format!("{}_semi_axis.png", r.case.name));
            line_plot(
                &p,
                &format!("{}: semi-axis along x", r.case.name),
                "t (s)",
                "a (m)",
                &[
                    Series {
                        name: "bowwave (2 sqrt<x^2>)".into(),
                        points: xy(&col(r, "t"), &col(r, "semi_axis_x")),
                        style: Style::Line,
                    },
                    Series {
                        name: "ODE solution".into(),
                        points: xy(&named(&rt, tc), &named(&rt, ac)),
                        style: Style::Line,
                    },
                ],
            )?;
            files.push(p);
        }
        "hydrostatic" => {
            let p = dir.join("hydrostatic_bottom_pressure.png");
            line_plot(
                &p,
                "Hydrostatic tank: bottom pressure",
                "t sqrt(g/H)",
                "p / (rho g H)",
                &[Series {
                    name: "bottom probe".into(),
                    points: xy(&ts, &col(r, "pstar_bottom")),
                    style: Style::Line,
                }],
            )?;
            files.push(p);
        }
        _ => {}
    }
    Ok(files)
}

/// `bowwave run`: runs a case with progress and outputs, prints where they went and the case's checks.
/// Returns the process exit code (2 after a blow-up).
pub fn run_and_report(case: &CaseFile, out: &Path, opts: RunOptions) -> anyhow::Result<i32> {
    let end = opts.end_time;
    let opts = RunOptions {
        out_dir: Some(out.to_path_buf()),
        ..opts
    };
    let r = run(case, &opts)?;
    let mut files = r.files.clone();
    files.extend(plots(&r, out)?);
    println!(
        "{}: {} fluid particles, dx = {:.4e} m, {} steps in {:.1} s wall ({:.3e} particle-steps/s), {} wall-penetration corrections",
        case.name, r.n_fluid, r.dx, r.steps, r.wall_seconds, r.particle_steps_per_second(), r.sim.wall_corrections
    );
    if let Some(line) = cavity_summary(&r) {
        println!("{line}");
    }
    if let Some(c) = checks(&r) {
        if r.blowup.is_none() && end.is_none() {
            print_checks(&c);
        }
    }
    println!("outputs:");
    for f in &files {
        println!("  {}", f.display());
    }
    if let Some(b) = &r.blowup {
        eprintln!("error: the run blew up: {b}");
        return Ok(2);
    }
    Ok(0)
}

/// One line on the cavity the run's cavity probe found, in the case's scales.
pub fn cavity_summary(r: &RunResult) -> Option<String> {
    let c = r.cavity.as_ref()?;
    let l = r.case.scales.length;
    let g = r.case.gravity_magnitude();
    let t_scale = (l / g).sqrt();
    Some(format!(
        "cavity closed between t* = {:.3} and {:.3}: area {:.4} H², centroid ({:.3}, {:.3}) H, circulation {:.3} √(g H³) (positive clockwise)",
        c.previous_time / t_scale,
        c.time / t_scale,
        c.area / (l * l),
        c.centroid.x / l,
        c.centroid.y / l,
        c.circulation / (g * l.powi(3)).sqrt()
    ))
}

/// `bowwave validate`: runs the named case (or all) at `res` (or full resolution), prints the checks.
///
/// `ghosts`: if given, the ghost kind of every wall of every case (as `bowwave validate --ghosts`).
pub fn validate_cli(
    case: Option<&str>,
    res: Option<f64>,
    out: Option<&Path>,
    ghosts: Option<GhostKind>,
) -> anyhow::Result<bool> {
    let names: Vec<&str> = match case {
        Some(n) => vec![n],
        None => cases::builtin::builtin_names(),
    };
    let mut all = vec![];
    let mut ok = true;
    for n in names {
        let mut c = cases::load(n)?;
        if let Some(kind) = ghosts {
            c.set_ghosts(kind);
        }
        let res = res.or(full_resolution(n));
        eprintln!(
            "validating {n} at resolution {:.0} ...",
            res.unwrap_or(c.scales.resolution)
        );
        let r = run(
            &c,
            &RunOptions {
                res,
                progress: true,
                ..Default::default()
            },
        )?;
        if let Some(b) = &r.blowup {
            eprintln!("{n}: blew up: {b}");
            ok = false;
            continue;
        }
        if let Some(dir) = out {
            r.series.write(&dir.join(format!("{n}_series.csv")))?;
            plots(&r, dir)?;
        }
        if let Some(line) = cavity_summary(&r) {
            eprintln!("{n}: {line}");
        }
        let c = checks(&r).unwrap_or_default();
        ok &= c.iter().all(|c| c.pass());
        all.extend(c);
    }
    print_checks(&all);
    Ok(ok)
}
