//! Post-processing of 2D particle sets: the level-set function on a grid (thesis appendix B), the air
//! cavities it encloses, the circulation around them, and the plunging-jet metrics. Knows particles, not
//! hulls or the solver's internals.

pub mod cavity;
pub mod contour;
pub mod jet;
pub mod level_set;
pub mod snapshot;

pub use snapshot::Snapshot;
