//! The drops with a free surface all round: Monaghan's elliptic drop and the drop in a central force field
//! (issue #2, check 2).

use super::{check, col, Check};
use crate::cases::run::RunResult;
use crate::reference::{self, interp, named};

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
