//! Particle shifting of the δ⁺-SPH of Sun, Colagrossi, Marrone & Zhang (2017), an option after each step.
//!
//! δr_i = −CFL·Ma·(2h)² Σ_j [1 + R (W_ij / W(Δx))^n] ∇_i W_ij V_j, with CFL·Ma = U_max Δt / h, so that the
//! coefficient is [`A`] h U_max Δt with A = 4; R = 0.2, n = 4 as in the paper (U_max the largest fluid speed).
//!
//! Near the free surface only the part tangent to it is kept, and splashes do not move; both are read from the
//! minimum eigenvalue λ of the renormalisation matrix and the normal of thesis §7.2
//! ([`super::free_surface`]): λ ≤ 0.2 no shift; the tangential part for a surface particle (λ ≤ 0.75: every
//! free-surface particle and the layer under it) and for every particle within a kernel support of one (the
//! surface's vicinity, as in the paper), whose sum the surface truncates: its normal part points out of the
//! water and would lift the layers under the surface (docs/reference/method.md, "Particle shifting"); all of
//! it elsewhere. The density is carried to the new
//! position to first order with the renormalised gradient of eq. (4.19) (ρ_i += ∇ρ_i · δr_i); the velocity is
//! not corrected (the paper's simple form).
//!
//! Why it is here (issue #35): at a stagnation point that the flow leaves a wall from, the Lagrangian particles
//! move apart along the outflow and a void opens over the fixed ghosts; the ghosts' MLS values, extrapolated
//! into the void, over-read the pressure by a factor up to 2.8 (`jet-floor`) and the dam break's corner by
//! 20–60 %. Shifting keeps the particles spread evenly and removes most of it
//! (docs/reference/method.md, "Particle shifting").

use super::free_surface::SurfaceSums;
use super::kernel::Kernel;
use super::neighbours::CellList;
use nalgebra::SVector;
use rayon::prelude::*;

/// Whether (and whose) particle shifting runs after each step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ParticleShifting {
    /// None: the thesis's δ-SPH (the default).
    #[default]
    None,
    /// Sun et al. (2017), δ⁺-SPH.
    Sun2017,
}

impl std::str::FromStr for ParticleShifting {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "none" => Ok(Self::None),
            "sun2017" => Ok(Self::Sun2017),
            v => Err(format!("expected `none` or `sun2017`, got `{v}`")),
        }
    }
}

impl std::fmt::Display for ParticleShifting {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::None => "none",
            Self::Sun2017 => "sun2017",
        })
    }
}

/// Why particle shifting and several phases are refused together (a case's `[[phases]]`, the 2D+t air layer):
/// what is expected instead.
pub const WITH_PHASES: &str = "no particle shifting with it (`shifting = none`): the shift of Sun et al. (2017) \
is single-phase and moves particles across the interface between phases";

/// A of δr = −A h U_max Δt Σ…: (2h)²/h² = 4 (Sun et al. 2017), dimensionless.
pub const A: f64 = 4.0;
/// R of the anti-clumping term (Sun et al. 2017: 0.2), dimensionless.
pub const R: f64 = 0.2;
/// Its power n (Sun et al. 2017: 4).
pub const N: i32 = 4;
/// The largest displacement in one step, in Δx: 0.25 (ours; a bound the shift reaches only where the
/// particles are far from even, as at the first impacts).
pub const CAP: f64 = 0.25;
/// λ at or below which a particle does not move (splashes, thesis eq. 7.22's lower threshold).
pub const LAMBDA_SPLASH: f64 = 0.2;
/// λ at or below which only the tangential part is kept (eq. 7.22's upper threshold).
pub const LAMBDA_SURFACE: f64 = 0.75;

/// The shift of one particle from its sum S = Σ_j [1 + R (W_ij/W(Δx))^n] ∇_i W_ij V_j: −coef S, projected
/// on the free surface's tangent (normal `normal`) where the particle is `near_surface` (on it or within a
/// kernel support of it), zero in a splash (λ ≤ [`LAMBDA_SPLASH`]), at most [`CAP`] Δx long.
pub fn shift_from_sum<const D: usize>(
    sum: &SVector<f64, D>,
    coef: f64,
    lambda: f64,
    near_surface: bool,
    normal: &SVector<f64, D>,
    dx: f64,
) -> SVector<f64, D> {
    if lambda <= LAMBDA_SPLASH {
        return SVector::zeros();
    }
    let mut d = -sum * coef;
    if near_surface {
        if normal.norm_squared() == 0.0 {
            return SVector::zeros();
        }
        d -= normal * normal.dot(&d);
    }
    let m = d.norm();
    if m > CAP * dx {
        d *= CAP * dx / m;
    }
    d
}

/// The shift of every fluid particle (the first `n_fluid` of `pos`; `volume` for all of `pos`, 0 for a ghost
/// that takes no part), for a step of U_max Δt = `u_max_dt`. A first pass over the neighbours gathers the
/// shift's sum and the matrix and vector of §7.2 (λ and the normal, as [`super::free_surface::detect`]
/// computes them; its scan-region test is not needed, since every particle it would decide, λ in (0.2, 0.75],
/// is projected on its tangent anyway); a second finds the particles within a kernel support of a surface
/// particle (λ ≤ [`LAMBDA_SURFACE`]).
pub fn displacements<const D: usize>(
    kernel: &Kernel<D>,
    cells: &CellList<D>,
    pos: &[SVector<f64, D>],
    volume: &[f64],
    n_fluid: usize,
    dx: f64,
    u_max_dt: f64,
) -> Vec<SVector<f64, D>> {
    let w_dx = kernel.w(dx);
    let coef = A * kernel.h * u_max_dt;
    let sums: Vec<(SVector<f64, D>, f64, SVector<f64, D>)> = (0..n_fluid)
        .into_par_iter()
        .map(|i| {
            let mut surface = SurfaceSums::<D>::new();
            let mut sum = SVector::<f64, D>::zeros();
            cells.for_each_within(pos, &pos[i], kernel.support, |j, rij, r| {
                if j == i || volume[j] == 0.0 {
                    return;
                }
                let gw = kernel.grad(&rij, r);
                surface.add(&gw, &rij, volume[j]);
                let f = 1.0 + R * (kernel.w(r) / w_dx).powi(N);
                sum += gw * (f * volume[j]);
            });
            let (lambda, normal) = surface.lambda_and_normal();
            (sum, lambda, normal)
        })
        .collect();
    let on_surface = |j: usize| j < n_fluid && sums[j].1 <= LAMBDA_SURFACE;
    (0..n_fluid)
        .into_par_iter()
        .map(|i| {
            let (sum, lambda, normal) = &sums[i];
            let mut near_surface = on_surface(i);
            if !near_surface {
                cells.for_each_within(pos, &pos[i], kernel.support, |j, _, _| near_surface |= on_surface(j));
            }
            shift_from_sum(sum, coef, *lambda, near_surface, normal, dx)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    #[test]
    fn a_splash_does_not_move_and_the_surface_moves_along_itself() {
        let s = Vector2::new(3.0, -4.0);
        let n = Vector2::new(0.0, 1.0);
        assert_eq!(shift_from_sum(&s, 1e-3, 0.1, true, &n, 1.0), Vector2::zeros());
        let d = shift_from_sum(&s, 1e-3, 0.5, true, &n, 1.0);
        assert_eq!(d.y, 0.0);
        assert!((d.x + 3e-3).abs() < 1e-15);
        // Inside the water (λ near 1) but within a support of the surface: along it too.
        let d = shift_from_sum(&s, 1e-3, 0.9, true, &n, 1.0);
        assert_eq!(d.y, 0.0);
        let d = shift_from_sum(&s, 1e-3, 0.9, false, &n, 1.0);
        assert!((d - Vector2::new(-3e-3, 4e-3)).norm() < 1e-15);
        // The cap: at most CAP dx.
        let d = shift_from_sum(&s, 1.0, 0.9, false, &n, 1.0);
        assert!((d.norm() - CAP).abs() < 1e-12);
    }
}
