//! Writers, one file per format. Every file is written atomically (temporary file, then rename).

pub mod atomic;
pub mod checkpoint;
pub mod csv_table;
pub mod json_float;
pub mod plot;
pub mod vtk;
