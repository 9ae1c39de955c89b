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

/// Largest reference time τ = t√(g/a) of the residual-height comparison. The run ends at T = 3.4 (τ = 2.40):
/// Table 6's last point inside it is τ = 2.21, the next (2.45) is past the end.
const MM_HEIGHT_TAU_MAX: f64 = 2.3;

/// The Martin–Moyce column height h/(n²a) = h/(2a) over the run, from the `column` gauge.
pub(super) fn mm_column_height(r: &RunResult) -> Vec<f64> {
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
