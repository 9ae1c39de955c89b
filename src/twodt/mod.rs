//! The 2D+t bow-wave simulation (thesis §10.1): a hull section crossing an Earth-fixed plane at x = U t + x0
//! is a deforming wall in the δ-SPH solver. Orchestrates geometry, solver and analysis.

pub mod checkpoint;
pub mod config;
pub mod external_frames;
pub mod lattice;
pub mod lid;
mod passage;
pub mod pictures;
pub mod profile;

pub mod report;
pub mod result;
pub mod run;
pub mod scene;
pub mod wedge;
