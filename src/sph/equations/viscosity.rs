//! Viscous term of the momentum equation: K (μ/ρ_i) Σ_j π_ij ∇_i W_ij V_j with
//! π_ij = (u_j − u_i)·(r_j − r_i)/|r_j − r_i|² (eq. 4.2) and K = 2(D + 2).
//! Artificial viscosity (eqs. 4.11–4.12, 5.1): K μ = ρ0 α h c0. Physical viscosity (eq. 5.3): μ = ρ0 ν.

use nalgebra::SVector;
use serde::{Deserialize, Serialize};

/// The viscosity model.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Viscosity {
    /// Artificial viscosity α (dimensionless). Default α = 0.02; the thesis (§4.1.1) finds α > 0.01 needed
    /// for stability, i.e. a cell Reynolds number Re_h = c0 h/ν < 100 (eq. 4.14).
    Artificial { alpha: f64 },
    /// Kinematic viscosity ν (m²/s), eq. (5.3).
    Physical { nu: f64 },
}

impl Default for Viscosity {
    fn default() -> Self {
        Viscosity::Artificial { alpha: 0.02 }
    }
}

impl Viscosity {
    /// K μ (kg/(m s) in 3D), the coefficient in front of Σ π_ij ∇W V_j / ρ_i.
    pub fn coefficient(&self, dim: usize, rho0: f64, h: f64, c0: f64) -> f64 {
        match *self {
            Viscosity::Artificial { alpha } => rho0 * alpha * h * c0,
            Viscosity::Physical { nu } => 2.0 * (dim as f64 + 2.0) * rho0 * nu,
        }
    }
}

/// The coefficient K μ_ij of the pair (i, j) in a scene of several phases, or `None` where the pair takes no
/// viscous term. Artificial viscosity acts within a phase only, with the phase's ρ0 and c0 (Hammani et al.
/// eq. 21). A physical viscosity ν acts across the interface too, with the harmonic mean of the two dynamic
/// viscosities μ = ρ0 ν (Grenier et al. 2009, eq. 22), so that the interface carries shear stress; within a phase
/// it is [`Viscosity::coefficient`]. One ν for every phase (the Rayleigh–Taylor set-up's single Reynolds number).
pub fn pair_coefficient(
    viscosity: &Viscosity,
    dim: usize,
    h: f64,
    (rho0_i, c0_i): (f64, f64),
    rho0_j: f64,
    same_phase: bool,
) -> Option<f64> {
    match *viscosity {
        Viscosity::Artificial { .. } if !same_phase => None,
        Viscosity::Physical { nu } if !same_phase => {
            let (mu_i, mu_j) = (rho0_i * nu, rho0_j * nu);
            Some(2.0 * (dim as f64 + 2.0) * (2.0 * mu_i * mu_j / (mu_i + mu_j)))
        }
        _ => Some(viscosity.coefficient(dim, rho0_i, h, c0_i)),
    }
}

/// π_ij (1/s). The denominator is softened by 0.01 h² (a standard guard against coincident particles).
#[inline]
pub fn pi_ij<const D: usize>(u_ji: &SVector<f64, D>, r_ij: &SVector<f64, D>, r2: f64, h: f64) -> f64 {
    // (u_j − u_i)·(r_j − r_i) = −u_ji·r_ij
    -u_ji.dot(r_ij) / (r2 + 0.01 * h * h)
}

/// Contribution of neighbour j (m/s²).
#[inline]
pub fn viscous_acceleration<const D: usize>(
    coef: f64,
    rho_i: f64,
    pi: f64,
    grad_w: &SVector<f64, D>,
    v_j: f64,
) -> SVector<f64, D> {
    grad_w * (coef * pi * v_j / rho_i)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Across an interface a physical viscosity takes the harmonic mean of the two μ = ρ0 ν (Grenier et al. eq.
    /// 22): for a density ratio of 1.8, μ_ij = 2·1.8/2.8 μ_light; within a phase the single-phase coefficient;
    /// artificial viscosity does not cross the interface.
    #[test]
    fn viscosity_crosses_an_interface_with_the_harmonic_mean_of_the_dynamic_viscosities() {
        let nu = Viscosity::Physical { nu: 1.0 / 420.0 };
        let within = pair_coefficient(&nu, 2, 0.01, (1.8, 10.0), 1.8, true).unwrap();
        assert_eq!(within, nu.coefficient(2, 1.8, 0.01, 10.0));
        let across = pair_coefficient(&nu, 2, 0.01, (1.8, 10.0), 1.0, false).unwrap();
        let expected = 8.0 * (2.0 * 1.8 / 2.8) / 420.0;
        assert!((across - expected).abs() < 1e-15, "{across} against {expected}");
        // The same from either side: the pair forces stay equal and opposite.
        assert_eq!(across, pair_coefficient(&nu, 2, 0.01, (1.0, 10.0), 1.8, false).unwrap());
        let alpha = Viscosity::Artificial { alpha: 0.02 };
        assert_eq!(pair_coefficient(&alpha, 2, 0.01, (1.0, 10.0), 1000.0, false), None);
        assert_eq!(
            pair_coefficient(&alpha, 2, 0.01, (1.0, 10.0), 1.0, true),
            Some(alpha.coefficient(2, 1.0, 0.01, 10.0))
        );
    }
}
