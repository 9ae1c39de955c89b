//! The Martin & Moyce (1952) column collapse: surge front and residual column height (issue #2, check 3).

use super::{check, col, Check};
use crate::cases::run::RunResult;
use crate::reference::{self, interp};

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

/// Window of T = √2 t √(g/a) over which the front's speed is checked: Table 2's times from 1.19 to 2.32. The
/// owner's decision (issue #35): the check is the speed there, within 10 %; the position error is reported
/// beside it. At T = 0.41 our front and theirs agree within 0.01 a, at 0.84 ours is 0.16 a ahead and from 1.19
/// on 0.24–0.34 a: a lead gained in the first instants and then kept, what a gate that takes time to lift
/// leaves against a release the model makes instantaneous, so the speed after T ≈ 1.2 is what the release no
/// longer sets (studies/results/validation/LOG.md).
const MM_SPEED_WINDOW: (f64, f64) = (1.1, 2.5);

/// Least-squares slope of y against x.
fn slope(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - mx) * (b - my)).sum();
    let sxx: f64 = x.iter().map(|a| (a - mx) * (a - mx)).sum();
    sxy / sxx
}

/// The front's speed dZ/dT over [`MM_SPEED_WINDOW`]: (ours, theirs), both fitted at the reference's times
/// (ours interpolated there; NaN if the run does not cover them).
fn front_speeds(big_t: &[f64], fs: &[f64], t_ref: &[f64], z_ref: &[f64]) -> (f64, f64) {
    let (from, to) = MM_SPEED_WINDOW;
    let (tr, zr): (Vec<f64>, Vec<f64>) = t_ref
        .iter()
        .zip(z_ref)
        .filter(|(t, _)| (from..=to).contains(*t))
        .map(|(t, z)| (*t, *z))
        .unzip();
    let ours: Vec<f64> = tr.iter().map(|t| interp(big_t, fs, *t).unwrap_or(f64::NAN)).collect();
    (slope(&tr, &ours), slope(&tr, &zr))
}

/// Largest reference time τ = t√(g/a) of the residual-height comparison. The run ends at T = 3.4 (τ = 2.40):
/// Table 6's last point inside it is τ = 2.21, the next (2.45) is past the end.
const MM_HEIGHT_TAU_MAX: f64 = 2.3;

/// The Martin–Moyce column height h/(n²a) = h/(2a) over the run, from the `column` gauge.
pub(super) fn mm_column_height(r: &RunResult) -> Vec<f64> {
    let two_a = 2.0 * r.case.scales.length;
    col(r, "eta_column").iter().map(|e| e / two_a).collect()
}

/// Martin–Moyce (n² = 2): the surge front's speed dZ/dT over Table 2's T in [1.1, 2.5] within 10 % of theirs, with
/// the position error |x − x_exp|/x_exp at every T ≤ 2.5, T = √2 t √(g/a), reported beside it; the residual
/// column height h/(2a) against their Table 6 within 1/18, the spacing
/// of the markers it was read from (their values are multiples of 1/18 ≈ 0.056); and, reported only, the
/// front against the other experiment with this column, Koshizuka & Oka (1996), at the same times.
pub fn martin_moyce(r: &RunResult) -> Vec<Check> {
    let ts = col(r, "t_star");
    let big_t: Vec<f64> = ts.iter().map(|t| t * 2f64.sqrt()).collect();
    let fs = col(r, "front_star");
    let mm = reference::load("martin_moyce_front");
    let (front, front_mean) =
        errors_at_reference_times(&big_t, &fs, &reference::col(&mm, 0), &reference::col(&mm, 1), 2.5, true);
    let (speed, speed_ref) = front_speeds(&big_t, &fs, &reference::col(&mm, 0), &reference::col(&mm, 1));
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
            "front x/a, max rel. error at experimental T <= 2.5 (a constant lead from the release, see the speed)",
            front.1,
            front.2,
            front.0,
            None,
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
            &format!(
                "front speed dZ/dT, least squares at Table 2's T in [{}, {}], rel. diff.",
                MM_SPEED_WINDOW.0, MM_SPEED_WINDOW.1
            ),
            speed,
            speed_ref,
            (speed / speed_ref - 1.0).abs(),
            Some(0.10),
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slope_of_a_line_is_exact_and_speeds_read_the_window_only() {
        let x = [1.0, 2.0, 4.0];
        assert!((slope(&x, &[3.0, 5.0, 9.0]) - 2.0).abs() < 1e-14);
        // A front moving at 1.5 a per unit T, and a reference at 1.2 inside the window but not outside it.
        let big_t: Vec<f64> = (0..=300).map(|k| 0.01 * k as f64).collect();
        let fs: Vec<f64> = big_t.iter().map(|t| 1.0 + 1.5 * t).collect();
        let t_ref = [0.5, 1.2, 1.8, 2.4, 2.9];
        let z_ref = [9.0, 2.0, 2.72, 3.44, -9.0];
        let (ours, theirs) = front_speeds(&big_t, &fs, &t_ref, &z_ref);
        assert!(
            (ours - 1.5).abs() < 1e-12 && (theirs - 1.2).abs() < 1e-12,
            "{ours} {theirs}"
        );
    }
}
