//! The 3D comparison mode: the same flow in 2D (or 2D+t) and in 3D at the same spacing, to show where the
//! cheaper model holds and what the third dimension costs. Today the dam break as a 3D slab (`slab`); the 3D
//! ship in steady forward motion against its 2D+t solution goes here too.

pub mod ship;
pub mod slab;
