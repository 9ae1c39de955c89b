//! Continuity equation, first term of eq. (5.1): Dρ_i/Dt ⊃ −ρ_i Σ_j (u_j − u_i)·∇_i W_ij V_j.

use nalgebra::SVector;

/// Contribution of neighbour j: −ρ_i (u_j − u_i)·∇_i W_ij V_j (kg/m³/s).
#[inline]
pub fn velocity_divergence<const D: usize>(
    rho_i: f64,
    u_ji: &SVector<f64, D>,
    grad_w: &SVector<f64, D>,
    v_j: f64,
) -> f64 {
    -rho_i * u_ji.dot(grad_w) * v_j
}
