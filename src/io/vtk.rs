//! ParaView-readable VTK XML: one PolyData file (.vtp) per snapshot and a .pvd collection indexing them by
//! time. Written directly as ASCII XML (no dependency).

use super::atomic::write_atomic;
use std::fmt::Write as _;
use std::path::Path;

/// A point-data array: scalars (1 component) or vectors (padded to 3 components).
pub enum PointData<'a> {
    Scalar(&'a str, Vec<f64>),
    Vector(&'a str, Vec<[f64; 3]>),
}

/// Writes points (padded to 3D) with their data as a .vtp file.
pub fn write_vtp(path: &Path, points: &[[f64; 3]], data: &[PointData]) -> std::io::Result<()> {
    let n = points.len();
    let mut s = String::with_capacity(64 * n + 1024);
    s.push_str("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n");
    let _ = writeln!(s, "<Piece NumberOfPoints=\"{n}\" NumberOfVerts=\"{n}\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">");
    s.push_str("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for p in points {
        let _ = writeln!(s, "{:.8e} {:.8e} {:.8e}", p[0], p[1], p[2]);
    }
    s.push_str("</DataArray>\n</Points>\n<PointData>\n");
    for d in data {
        match d {
            PointData::Scalar(name, v) => {
                let _ = writeln!(s, "<DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">");
                for x in v {
                    let _ = writeln!(s, "{x:.8e}");
                }
            }
            PointData::Vector(name, v) => {
                let _ = writeln!(
                    s,
                    "<DataArray type=\"Float64\" Name=\"{name}\" NumberOfComponents=\"3\" format=\"ascii\">"
                );
                for x in v {
                    let _ = writeln!(s, "{:.8e} {:.8e} {:.8e}", x[0], x[1], x[2]);
                }
            }
        }
        s.push_str("</DataArray>\n");
    }
    s.push_str("</PointData>\n<Verts>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for i in 0..n {
        let _ = writeln!(s, "{i}");
    }
    s.push_str("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for i in 0..n {
        let _ = writeln!(s, "{}", i + 1);
    }
    s.push_str("</DataArray>\n</Verts>\n</Piece>\n</PolyData>\n</VTKFile>\n");
    write_atomic(path, s.as_bytes())
}

/// Writes a .pvd collection: (time, file name relative to the .pvd) pairs.
pub fn write_pvd(path: &Path, entries: &[(f64, String)]) -> std::io::Result<()> {
    let mut s = String::from("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n");
    for (t, f) in entries {
        let _ = writeln!(s, "<DataSet timestep=\"{t:.9e}\" group=\"\" part=\"0\" file=\"{f}\"/>");
    }
    s.push_str("</Collection>\n</VTKFile>\n");
    write_atomic(path, s.as_bytes())
}
