//! The physics terms of the δ-SPH system, one small function per term, apart from the loops that run them
//! (those are in [`crate::sph::solver`]). Notation: r_ij = r_i − r_j, ∇_i W_ij = W'(r) r_ij / r, V_j = m_j/ρ_j.

pub mod continuity;
pub mod density_diffusion;
pub mod ghost_conditions;
pub mod interface_repulsion;
pub mod normal_flux;
pub mod pressure_force;
pub mod renormalization;
pub mod timestep;
pub mod viscosity;
pub mod wall_force;
