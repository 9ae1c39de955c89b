//! Sloshing in a rectangular tank in sway, against linear potential theory.
//!
//! A tank of width L, water depth h, moves horizontally by x(t) = A [sin(ωt + φ) − sin φ] from rest (cos φ = 0:
//! no velocity at t = 0). In the tank's frame, with s the abscissa from its left wall, the linearised problem
//! (potential Φ = ẋ X + ψ, free-surface conditions at z = 0) gives the elevation as a sum of the natural modes
//! η(s, t) = Σ_n β_n(t) cos(k_n s), k_n = nπ/L, ω_n² = g k_n tanh(k_n h) (Faltinsen & Timokha 2009, ch. 5; our
//! derivation in `docs/reference/method.md`, "Sloshing"), each a forced oscillator
//!   β̈_n + ω_n² β_n = −λ_n ẍ,   λ_n = k_n tanh(k_n h) c_n,   c_n = (2L/(nπ)²) ((−1)ⁿ − 1),
//! c_n the coefficients of X = s − L/2 in the modes (only odd n are forced), from β_n = β̇_n = 0. With ẍ =
//! −Aω² sin(ωt + φ) each has a closed form; at resonance (ω = ω_n) it grows linearly in time. The quasi-static
//! limit is the tilted surface η = −ẍ X/g.
//!
//! The check: the elevation at each gauge that moves with the tank, η = level − level at t = 0, against the
//! theory at the gauge's abscissa, over the last forcing period: both fitted by a sin ωt + b cos ωt + c, the
//! amplitudes √(a² + b²) within 5 % and the phases within 5 % of a period (the tolerance).

use super::{check, col, Check};
use crate::cases::run::RunResult;
use crate::cases::wall_motion::Sine;

/// Odd modes summed: up to n = 199 (the c_n fall as 1/n², the forced response as 1/n³ off resonance).
const MODES: usize = 199;

/// Largest relative error of the amplitude, and of the phase as a fraction of the period.
pub const SLOSHING_TOLERANCE: f64 = 0.05;

/// Linear elevation (m) at abscissa `s` (m from the left wall) and time `t` (s) of a tank `l` wide, water `h`
/// deep, in sway `sway` (period in seconds, started at rest), under gravity `g`.
pub fn linear_elevation(l: f64, h: f64, g: f64, sway: &Sine, s: f64, t: f64) -> f64 {
    let w = 2.0 * std::f64::consts::PI / sway.period;
    let phi = sway.phase.to_radians();
    let mut eta = 0.0;
    for n in (1..=MODES).step_by(2) {
        let k = n as f64 * std::f64::consts::PI / l;
        let wn = (g * k * (k * h).tanh()).sqrt();
        let c = 2.0 * l / (n as f64 * std::f64::consts::PI).powi(2) * (if n % 2 == 0 { 0.0 } else { -2.0 });
        let lam = k * (k * h).tanh() * c;
        let f = lam * sway.amplitude * w * w; // β̈ + ω_n² β = f sin(ωt + φ)
        let beta = if (wn - w).abs() > 1e-9 * w {
            f / (wn * wn - w * w)
                * ((w * t + phi).sin() - phi.sin() * (wn * t).cos() - (w / wn) * phi.cos() * (wn * t).sin())
        } else {
            let kk = -f / (2.0 * w);
            kk * t * (w * t + phi).cos() - kk * phi.cos() / w * (w * t).sin()
        };
        eta += beta * (k * s).cos();
    }
    eta
}

/// (amplitude, phase) of the least-squares fit a sin ωt + b cos ωt + c to (t, y): (√(a² + b²), atan2(b, a)).
pub fn harmonic_fit(t: &[f64], y: &[f64], w: f64) -> (f64, f64) {
    let mut m = nalgebra::Matrix3::<f64>::zeros();
    let mut r = nalgebra::Vector3::<f64>::zeros();
    for (&t, &y) in t.iter().zip(y) {
        let b = nalgebra::Vector3::new((w * t).sin(), (w * t).cos(), 1.0);
        m += b * b.transpose();
        r += b * y;
    }
    let x = m.lu().solve(&r).unwrap_or_default();
    (x[0].hypot(x[1]), x[1].atan2(x[0]))
}

/// The tank of a sloshing case: (left wall abscissa, width, depth, sway) from its first wall with a sway sine
/// that starts at rest and its first fluid block; `None` if the case is not one.
pub fn tank(r: &RunResult) -> Option<(f64, f64, f64, Sine)> {
    let w = r
        .case
        .walls
        .iter()
        .find(|w| w.motion.as_ref().is_some_and(|m| m.sway.is_some()))?;
    let m = w.motion.as_ref()?;
    if m.heave.is_some() || m.roll.is_some() || m.table.is_some() {
        return None;
    }
    let sway = m.sway?;
    if sway.phase.to_radians().cos().abs() > 1e-9 {
        return None; // not from rest: an impulsive start the theory here does not cover
    }
    let xs: Vec<f64> = w.points.iter().map(|p| p[0]).collect();
    let (x0, x1) = (
        xs.iter().copied().fold(f64::INFINITY, f64::min),
        xs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    );
    let depth = match r.case.blocks.first()? {
        crate::cases::case_file::BlockSpec::Rectangle { min, max, .. } => max[1] - min[1],
        _ => return None,
    };
    Some((x0, x1 - x0, depth, sway))
}

/// The sloshing checks: for each gauge moving with the tank, the amplitude and phase of the elevation over the
/// last forcing period against linear theory.
pub fn sloshing(r: &RunResult) -> Vec<Check> {
    let Some((x0, l, h, sway)) = tank(r) else { return vec![] };
    let g = r.case.gravity_magnitude();
    let w = 2.0 * std::f64::consts::PI / sway.period;
    let t = col(r, "t");
    let end = *t.last().unwrap_or(&0.0);
    let last: Vec<usize> = (0..t.len()).filter(|&k| t[k] >= end - sway.period - 1e-9).collect();
    let tl: Vec<f64> = last.iter().map(|&k| t[k]).collect();
    let mut out = vec![];
    for gauge in r.case.probes.gauge.iter().filter(|g| g.moves_with.is_some()) {
        let level = col(r, &format!("eta_{}", gauge.name));
        let ours: Vec<f64> = last.iter().map(|&k| level[k] - level[0]).collect();
        let s = gauge.x - x0;
        let theory: Vec<f64> = tl.iter().map(|&t| linear_elevation(l, h, g, &sway, s, t)).collect();
        let (a1, p1) = harmonic_fit(&tl, &ours, w);
        let (a2, p2) = harmonic_fit(&tl, &theory, w);
        let mut dp = (p1 - p2) / (2.0 * std::f64::consts::PI);
        dp -= dp.round();
        out.push(check(
            r,
            &format!(
                "elevation at gauge {} (s/L {:.3}), amplitude over the last period (m)",
                gauge.name,
                s / l
            ),
            a1,
            a2,
            (a1 / a2 - 1.0).abs(),
            Some(SLOSHING_TOLERANCE),
        ));
        out.push(check(
            r,
            &format!(
                "elevation at gauge {}, phase lead over the last period / period",
                gauge.name
            ),
            dp,
            0.0,
            dp.abs(),
            Some(SLOSHING_TOLERANCE),
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The slow oracle: each mode's oscillator integrated by RK4 from rest, summed as the closed form is.
    fn integrated_elevation(l: f64, h: f64, g: f64, sway: &Sine, s: f64, t_end: f64) -> f64 {
        let w = 2.0 * std::f64::consts::PI / sway.period;
        let phi = sway.phase.to_radians();
        let acc = |t: f64| -sway.amplitude * w * w * (w * t + phi).sin();
        let steps = 20_000;
        let dt = t_end / steps as f64;
        let mut eta = 0.0;
        for n in (1..=MODES).step_by(2) {
            let k = n as f64 * std::f64::consts::PI / l;
            let wn2 = g * k * (k * h).tanh();
            let lam = k * (k * h).tanh() * (-4.0 * l / (n as f64 * std::f64::consts::PI).powi(2));
            let f = |t: f64, b: f64, v: f64| (v, -wn2 * b - lam * acc(t));
            let (mut b, mut v, mut t) = (0.0, 0.0, 0.0);
            for _ in 0..steps {
                let k1 = f(t, b, v);
                let k2 = f(t + 0.5 * dt, b + 0.5 * dt * k1.0, v + 0.5 * dt * k1.1);
                let k3 = f(t + 0.5 * dt, b + 0.5 * dt * k2.0, v + 0.5 * dt * k2.1);
                let k4 = f(t + dt, b + dt * k3.0, v + dt * k3.1);
                b += dt / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
                v += dt / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
                t += dt;
            }
            eta += b * (k * s).cos();
        }
        eta
    }

    #[test]
    fn the_closed_form_is_the_integrated_modal_oscillators() {
        let (l, h, g) = (1.0, 0.5, 9.81);
        let k = std::f64::consts::PI / l;
        let t1 = 2.0 * std::f64::consts::PI / (g * k * (k * h).tanh()).sqrt();
        // Off resonance (period 1.4 T_1) and at it, at the walls and inside, after 2.3 periods.
        for period in [1.4 * t1, t1] {
            let sway = Sine {
                amplitude: 0.003,
                period,
                phase: -90.0,
            };
            for s in [0.0, 0.3, 1.0] {
                let t = 2.3 * period;
                let a = linear_elevation(l, h, g, &sway, s, t);
                let b = integrated_elevation(l, h, g, &sway, s, t);
                assert!(
                    (a - b).abs() < 1e-6 * sway.amplitude.max(a.abs()),
                    "T {period}, s {s}: {a} vs {b}"
                );
            }
        }
    }

    #[test]
    fn at_resonance_the_first_mode_grows_linearly() {
        let (l, h, g) = (1.0, 0.5, 9.81);
        let k = std::f64::consts::PI / l;
        let w1 = (g * k * (k * h).tanh()).sqrt();
        let sway = Sine {
            amplitude: 0.001,
            period: 2.0 * std::f64::consts::PI / w1,
            phase: -90.0,
        };
        // Envelope of mode 1 at the left wall: |λ_1| A ω t / 2, λ_1 = −(4/π) tanh(kh).
        let grow = (4.0 / std::f64::consts::PI) * (k * h).tanh() * sway.amplitude * w1 / 2.0;
        let n = 20.0;
        let t = n * sway.period + 0.25 * sway.period; // sin(ωt) = 1
        let eta = linear_elevation(l, h, g, &sway, 0.0, t);
        assert!((eta / (grow * t) - 1.0).abs() < 0.02, "{eta} vs {}", grow * t);
    }

    #[test]
    fn the_harmonic_fit_reads_amplitude_and_phase() {
        let w = 3.0;
        let t: Vec<f64> = (0..200).map(|k| k as f64 * 0.01).collect();
        let y: Vec<f64> = t.iter().map(|t| 0.2 * (w * t + 0.7).sin() + 0.05).collect();
        let (a, p) = harmonic_fit(&t, &y, w);
        assert!((a - 0.2).abs() < 1e-9 && (p - 0.7).abs() < 1e-9);
    }
}
