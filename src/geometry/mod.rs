//! Hull geometry: offsets files, their validation, generators, the spline surface and its sections.
//! Knows nothing of SPH.

pub mod bent_wall;
pub mod drawings;
pub mod hull_file;
pub mod hull_solid;
pub mod hydrostatics;
pub mod parametric;
pub mod report;
pub mod spline;
pub mod station_facts;
pub mod stl;
pub mod surface;
pub mod wigley;
