//! Convergence analysis (thesis appendix C) and Richardson extrapolation, and `bowwave converge`: a case
//! run at several resolutions, each validated quantity's value and error per resolution, the observed
//! order, and an extrapolated value with an uncertainty band.
//!
//! Orders: with errors e_k against a reference at resolutions r_k (r = length/dx), the order between two
//! resolutions is p = ln(e_k/e_{k+1}) / ln(r_{k+1}/r_k). Without a reference, (C.2) compares successive
//! differences: C = ln(|f_1 − f_2| / |f_2 − f_3|) / ln(ρ), ρ the (constant) refinement ratio, so that C > 0
//! when the differences shrink. (The thesis writes the ratio the other way up, with f_1 the finest.)
//! Richardson: f_∞ = f_3 + (f_3 − f_2)/(ρ^C − 1), with the band ±1.25 |f_∞ − f_3| (the safety factor of
//! Roache's grid-convergence index for three grids).

use crate::cases::run::{run, RunOptions};
use crate::cases::CaseFile;
use crate::validation::{checks, Check};

/// Observed order between two errors at resolutions r1 < r2.
pub fn order(e1: f64, e2: f64, r1: f64, r2: f64) -> f64 {
    (e1 / e2).ln() / (r2 / r1).ln()
}

/// Appendix C order from three values at resolutions in constant ratio `rho` (coarse to fine).
pub fn order_c2(f1: f64, f2: f64, f3: f64, rho: f64) -> f64 {
    ((f1 - f2).abs() / (f2 - f3).abs()).ln() / rho.ln()
}

/// Richardson-extrapolated value and its uncertainty band from three values (coarse to fine) in ratio `rho`.
/// `None` when the differences do not shrink (no convergence to extrapolate).
pub fn richardson(f1: f64, f2: f64, f3: f64, rho: f64) -> Option<(f64, f64, f64)> {
    let c = order_c2(f1, f2, f3, rho);
    // Only monotone convergence is extrapolated: oscillating values have no meaningful order.
    if !(c.is_finite() && c > 0.0) || (f1 - f2) * (f2 - f3) <= 0.0 {
        return None;
    }
    let ext = f3 + (f3 - f2) / (rho.powf(c) - 1.0);
    Some((ext, 1.25 * (ext - f3).abs(), c))
}

/// One quantity across resolutions.
#[derive(Clone, Debug)]
pub struct Quantity {
    pub name: String,
    pub reference: f64,
    /// Per resolution: (value, error against the reference).
    pub values: Vec<(f64, f64)>,
}

/// A convergence study of a case.
#[derive(Clone, Debug)]
pub struct Convergence {
    pub case: String,
    pub res: Vec<f64>,
    pub wall_seconds: Vec<f64>,
    pub particles: Vec<usize>,
    pub quantities: Vec<Quantity>,
    /// Remarks printed under the table (e.g. runs that did not plunge).
    pub notes: Vec<String>,
}

/// Runs `case` at each resolution (length/dx) and collects its validation checks.
pub fn converge(case: &CaseFile, res: &[f64], end_time: Option<f64>) -> anyhow::Result<Convergence> {
    anyhow::ensure!(res.len() >= 2, "--res: expected at least two resolutions");
    let mut out = Convergence {
        case: case.name.clone(),
        res: res.to_vec(),
        wall_seconds: vec![],
        particles: vec![],
        quantities: vec![],
        notes: vec![],
    };
    for (k, &r) in res.iter().enumerate() {
        let opts = RunOptions {
            res: Some(r),
            end_time,
            ..Default::default()
        };
        let result = run(case, &opts)?;
        if let Some(b) = &result.blowup {
            anyhow::bail!("{} at resolution {r} stopped early: {b}", case.name);
        }
        out.wall_seconds.push(result.wall_seconds);
        out.particles.push(result.n_fluid);
        let mut cs: Vec<Check> = checks(&result).unwrap_or_default();
        cs.extend(reported_quantities(&result));
        anyhow::ensure!(
            !cs.is_empty(),
            "case `{}` has no validation checks nor reported quantities (`probes.interface_tips`) to converge",
            case.name
        );
        // The checks come in the same order at every resolution (their labels may name the reference's
        // own resolution, so they are matched by position).
        if k == 0 {
            out.quantities = cs
                .iter()
                .map(|c| Quantity {
                    name: c.quantity.clone(),
                    reference: c.reference,
                    values: vec![(c.value, c.error)],
                })
                .collect();
        } else {
            anyhow::ensure!(
                cs.len() == out.quantities.len(),
                "the checks differ between resolutions"
            );
            for (q, c) in out.quantities.iter_mut().zip(&cs) {
                q.values.push((c.value, c.error));
            }
        }
    }
    out.quantities.retain(|q| q.values.len() == res.len());
    Ok(out)
}

/// Quantities a case reports without a reference, converged on their own values (C.2): with
/// `probes.interface_tips`, `spike_y` and `bubble_y` at every whole t√(g/L) up to the end (linear between series
/// rows). Their `reference` and `error` are NaN.
fn reported_quantities(r: &crate::cases::run::RunResult) -> Vec<Check> {
    let case = &r.case;
    if !case.probes.interface_tips {
        return vec![];
    }
    let (Some(t), t_scale) = (
        r.series.column("t"),
        (case.scales.length / case.gravity_magnitude()).sqrt(),
    ) else {
        return vec![];
    };
    let mut out = vec![];
    for column in ["spike_y", "bubble_y"] {
        let Some(v) = r.series.column(column) else { continue };
        let mut k = 1.0;
        while k * t_scale <= t.last().copied().unwrap_or(0.0) + 1e-12 {
            let at = k * t_scale;
            let i = t.partition_point(|&ti| ti < at).clamp(1, t.len() - 1);
            let w = ((at - t[i - 1]) / (t[i] - t[i - 1])).clamp(0.0, 1.0);
            out.push(Check {
                case: case.name.clone(),
                quantity: format!("{column} (m) at t√(g/L) = {k}"),
                value: v[i - 1] + w * (v[i] - v[i - 1]),
                reference: f64::NAN,
                error: f64::NAN,
                tolerance: None,
            });
            k += 1.0;
        }
    }
    out
}

impl Convergence {
    /// A table: per quantity and resolution the value and error, the order of the errors between successive
    /// resolutions, and (with three or more resolutions in constant ratio) the appendix C order of the values
    /// and the Richardson estimate.
    pub fn report(&self) -> String {
        use std::fmt::Write as _;
        let mut s = String::new();
        let _ = writeln!(s, "convergence of `{}` at length/dx = {:?}", self.case, self.res);
        for (k, r) in self.res.iter().enumerate() {
            let _ = writeln!(
                s,
                "  res {r:.1}: {} particles, wall {:.1} s",
                self.particles[k], self.wall_seconds[k]
            );
        }
        for q in &self.quantities {
            let _ = writeln!(s, "{}", q.name);
            for (k, (v, e)) in q.values.iter().enumerate() {
                let p = (k > 0)
                    .then(|| order(q.values[k - 1].1, *e, self.res[k - 1], self.res[k]))
                    .filter(|p| p.is_finite())
                    .map(|p| format!("   order of the error {p:.2}"))
                    .unwrap_or_default();
                let e = if e.is_finite() {
                    format!("error {e:>10.3e}")
                } else {
                    "(no reference)".to_string()
                };
                let _ = writeln!(s, "  res {:>6.1}: value {:>12.5e}  {e}{p}", self.res[k], v);
            }
            let n = q.values.len();
            if n >= 3 {
                let (f1, f2, f3) = (q.values[n - 3].0, q.values[n - 2].0, q.values[n - 1].0);
                let rho = self.res[n - 1] / self.res[n - 2];
                // Constant to 0.1 %: typed spacings such as 3e-3, 2e-3, 1.333e-3 count as ratio 1.5.
                let constant = ((self.res[n - 2] / self.res[n - 3]) - rho).abs() < 1e-3 * rho;
                if f1.is_finite() && constant {
                    match richardson(f1, f2, f3, rho) {
                        Some((ext, band, c)) => {
                            let refn = if q.reference.is_finite() && q.reference != 0.0 {
                                format!(
                                    ", reference {:.5e} ({:+.2} %)",
                                    q.reference,
                                    100.0 * (ext - q.reference) / q.reference
                                )
                            } else {
                                String::new()
                            };
                            let _ = writeln!(s, "  order (C.2) {c:.2}; Richardson {ext:.5e} ± {band:.2e}{refn}");
                        }
                        None => {
                            let _ = writeln!(
                                s,
                                "  successive differences {:.3e}, {:.3e} do not shrink monotonically: no order (C.2), \
                                 no extrapolation",
                                f2 - f1,
                                f3 - f2
                            );
                        }
                    }
                }
            }
        }
        for n in &self.notes {
            let _ = writeln!(s, "note: {n}");
        }
        s
    }

    /// CSV rows: quantity, res, value, error, reference.
    pub fn csv(&self) -> String {
        let mut s = String::from("quantity,res,value,error,reference,wall_seconds,particles\n");
        for q in &self.quantities {
            for (k, (v, e)) in q.values.iter().enumerate() {
                s += &format!(
                    "{},{},{v},{e},{},{},{}\n",
                    q.name.replace(',', ";"),
                    self.res[k],
                    q.reference,
                    self.wall_seconds[k],
                    self.particles[k]
                );
            }
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f(h) = 1 + h²: the order (C.2) is 2 and the Richardson value is the exact limit.
    #[test]
    fn richardson_recovers_a_second_order_limit() {
        let f = |r: f64| 1.0 + (1.0 / r).powi(2);
        let (ext, band, c) = richardson(f(10.0), f(20.0), f(40.0), 2.0).unwrap();
        assert!((c - 2.0).abs() < 1e-9, "order {c}");
        assert!((ext - 1.0).abs() < 1e-12, "limit {ext}");
        assert!(band < 1e-3);
        assert!((order(0.01, 0.0025, 10.0, 20.0) - 2.0).abs() < 1e-12);
        assert!(
            richardson(1.0, 2.0, 4.0, 2.0).is_none(),
            "diverging values are not extrapolated"
        );
        assert!(
            richardson(3.7, 0.9, 1.2, 2.0).is_none(),
            "oscillating values are not extrapolated"
        );
    }
}
