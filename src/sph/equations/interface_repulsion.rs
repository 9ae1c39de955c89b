//! Interface repulsion between phases, Grenier, Le Touzé, Antuono & Colagrossi (2009) eq. (23): a small extra
//! pressure force ε_I Σ_{j∉χ} (|p_i| + |p_j|) ∇_i W_ij V_j from the particles of the other phases (an option of
//! the multi-fluid model, [`crate::sph::multi_fluid`]).

use nalgebra::SVector;

/// The acceleration on particle i from a neighbour j of another phase (m/s²): −ε_I (|p_i| + |p_j|) ∇_i W_ij V_j / ρ_i.
#[inline]
pub fn interface_repulsion<const D: usize>(
    eps: f64,
    p_i: f64,
    p_j: f64,
    rho_i: f64,
    grad_w: &SVector<f64, D>,
    v_j: f64,
) -> SVector<f64, D> {
    grad_w * (-eps * (p_i.abs() + p_j.abs()) * v_j / rho_i)
}
