//! bowwave: 2D+t δ-SPH simulation of breaking bow waves.
//!
//! * [`sph`]: the solver core, generic over the dimension; knows nothing of hulls, CLI or files.
//! * [`cases`]: case descriptions (TOML) and the built-in cases, turned into simulations and run.
//! * [`validation`]: comparisons with analytic solutions and published data.
//! * [`io`]: writers, one file per format (CSV, VTK, PNG plots), and atomic writes.
//! * [`bench`]: throughput measurement.

pub mod bench;
pub mod cases;
pub mod io;
pub mod reference;
pub mod sph;
pub mod validation;
