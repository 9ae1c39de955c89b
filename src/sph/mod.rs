//! The δ-SPH solver core, generic over the spatial dimension `D`. It knows nothing of hulls, the CLI or
//! file formats: boundaries come in through the [`boundary::Boundary`] trait.

pub mod body_force;
pub mod boundary;
pub mod box_wall;
pub mod deforming_wall;
pub mod diagnostics;
pub mod eos;
pub mod equations;
pub mod free_surface;
pub mod integrator;
pub mod kernel;
pub mod kernel_table;
pub mod main_loop;
pub mod mls;
pub mod multi_fluid;
pub mod neighbours;
pub mod normal_flux;
pub mod packing;
pub mod particle_shifting;
pub mod particles;
pub mod polyline_wall;
pub mod rigid_pose;
pub mod solver;
pub mod surface_wall;
pub mod wall_sensor;

pub use equations::{density_diffusion, viscosity};
