//! Post-processing of particle sets: for 2D ones the level-set function on a grid (thesis appendix B), the air
//! cavities it encloses, the circulation around them, and the plunging-jet metrics; the wave-pattern maps
//! η(x, y) of 2D+t and 3D runs. Knows particles, not hulls or the solver's internals.

pub mod cavity;
pub mod contour;
pub mod jet;
pub mod level_set;
pub mod snapshot;
pub mod wave_pattern;

pub use snapshot::Snapshot;
