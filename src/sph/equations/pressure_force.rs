//! Pressure term of the momentum equation (5.1): Du_i/Dt ⊃ −(1/ρ_i) Σ_j (p_j + p_i) ∇_i W_ij V_j.
//! The symmetric (p_j + p_i) form conserves linear and angular momentum.

use nalgebra::SVector;

/// Contribution of neighbour j (m/s²).
#[inline]
pub fn pressure_acceleration<const D: usize>(
    p_i: f64,
    p_j: f64,
    rho_i: f64,
    grad_w: &SVector<f64, D>,
    v_j: f64,
) -> SVector<f64, D> {
    grad_w * (-(p_i + p_j) * v_j / rho_i)
}
