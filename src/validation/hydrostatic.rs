//! The hydrostatic tank: bottom pressure and residual motion (issue #2, check 1).

use super::{check, col, Check};
use crate::cases::run::RunResult;

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
