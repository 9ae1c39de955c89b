//! Force of the fluid on a wall through its ghost particles, eqs. (7.12)–(7.13):
//! F = Σ_{j∈ghosts} Σ_{i∈fluid} [(p_j + p_i) − ρ0 ν π_ij] ∇_i W_ij V_i V_j … written here as the reaction
//! to the force the ghosts exert on the fluid, so that a still tank's bottom carries the weight of the water.

use nalgebra::SVector;

/// Contribution of the pair (fluid i, ghost j) to the force on the wall (N per unit depth in 2D).
/// `grad_w` is ∇_i W_ij (r_ij = r_i − r_j); `visc` = K μ π_ij as in the momentum equation.
#[inline]
pub fn pair_force<const D: usize>(
    p_i: f64,
    p_j: f64,
    visc: f64,
    grad_w: &SVector<f64, D>,
    v_i: f64,
    v_j: f64,
) -> SVector<f64, D> {
    grad_w * (((p_i + p_j) - visc) * v_i * v_j)
}
