//! The 3D comparison mode: the same flow in 2D (or 2D+t) and in 3D at the same spacing, to show where the
//! cheaper model holds and what the third dimension costs: the dam break as a 3D slab (`slab`); a hull as a 3D
//! wall in the 2D+t tank extruded (`ship`), towed in steady forward motion beside its 2D+t solution
//! (`towed_ship`); the bent-wall channel of thesis §10.2.1 in 2D+t (`bent_wall`) and in 3D, the ruled surface
//! towed through a still channel beside its 2D+t analogue (`bent_wall_3d`).

pub mod bent_wall;
pub mod bent_wall_3d;
pub mod ship;
pub mod slab;
pub mod towed_checkpoint;
pub mod towed_ship;
