//! bowwave: 2D+t δ-SPH simulation of breaking bow waves.
//!
//! * [`sph`]: the solver core, generic over the dimension; knows nothing of hulls, CLI or files.
//! * [`geometry`]: hull offsets files, the spline surface and its 2D+t sections; knows nothing of SPH.
//! * [`cases`]: case descriptions (TOML) and the built-in cases, turned into simulations and run.
//! * [`input_error`]: errors in user files, naming the file, the field and what was expected.
//! * [`validation`]: comparisons with analytic solutions and published data.
//! * [`io`]: writers, one file per format (CSV, VTK, PNG plots), and atomic writes.
//! * [`mod@bench`]: throughput measurement.

pub mod analysis;
pub mod bench;
pub mod cases;
pub mod convergence;
pub mod geometry;
pub mod input_error;
pub mod io;
pub mod reference;
pub mod sph;
pub mod studies;
pub mod twodt;
pub mod validation;
