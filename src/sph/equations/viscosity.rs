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
