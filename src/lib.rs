//! bowwave: 2D+t δ-SPH simulation of breaking bow waves.
//!
//! Every module, from the bottom of the house up:
//!
//! * [`sph`]: the solver core, generic over the dimension; knows nothing of hulls, CLI or files.
//! * [`geometry`]: hull offsets files, the spline surface and its 2D+t sections; knows nothing of SPH.
//! * [`analysis`]: post-processing of 2D particle sets (level set, cavities, circulation, jet metrics).
//! * [`driver`]: the one run driver: steps a simulation and calls its observers; progress bars and lines.
//! * [`cases`]: case descriptions (TOML) and the built-in cases, turned into simulations and run.
//! * [`twodt`]: the 2D+t bow-wave run: its configuration, scene, passage observers, checkpoints, results.
//! * [`studies`]: Froude sweeps of 2D+t cases from study files: resumable, spread over jobs, gathered.
//! * [`methods`]: convergence, speed against accuracy, stability maps and the throughput benchmark.
//! * [`compare3d`]: the same flow in 2D and 3D (the dam-break slab).
//! * [`validation`]: comparisons with analytic solutions and published data; `bowwave validate`.
//! * [`mod@reference`]: the validation data embedded from `data/reference/`.
//! * [`io`]: writers, one file per format (CSV, VTK, PNG plots, checkpoints), and atomic writes.
//! * [`input_error`]: errors in user files, naming the file, the field and what was expected.
//! * [`process_usage`]: CPU seconds and peak memory of this process.

pub mod analysis;
pub mod cases;
pub mod compare3d;
pub mod driver;
pub mod geometry;
pub mod input_error;
pub mod io;
pub mod methods;
pub mod process_usage;
pub mod reference;
pub mod sph;
pub mod studies;
pub mod twodt;
pub mod validation;
