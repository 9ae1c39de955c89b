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
    push_points(&mut s, points);
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

/// Writes a surface mesh as a .vtp file: its points (metres) and its polygons, each a list of point indices
/// (quadrilaterals or triangles), with no point data (a wall drawn beside the particles).
pub fn write_mesh_vtp(path: &Path, points: &[[f64; 3]], polys: &[Vec<usize>]) -> std::io::Result<()> {
    let (n, m) = (points.len(), polys.len());
    let mut s = String::with_capacity(48 * n + 24 * m + 512);
    s.push_str("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n");
    let _ = writeln!(s, "<Piece NumberOfPoints=\"{n}\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"{m}\">");
    push_points(&mut s, points);
    s.push_str("</DataArray>\n</Points>\n<Polys>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for q in polys {
        let line: Vec<String> = q.iter().map(|i| i.to_string()).collect();
        let _ = writeln!(s, "{}", line.join(" "));
    }
    s.push_str("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    let mut end = 0;
    for q in polys {
        end += q.len();
        let _ = writeln!(s, "{end}");
    }
    s.push_str("</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n");
    write_atomic(path, s.as_bytes())
}

/// Appends the `<Points>` block's opening and its coordinates (closed by the caller).
fn push_points(s: &mut String, points: &[[f64; 3]]) {
    s.push_str("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for p in points {
        let _ = writeln!(s, "{:.8e} {:.8e} {:.8e}", p[0], p[1], p[2]);
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A mesh of two quadrilaterals sharing an edge: six points, two polygons whose offsets end at 4 and 8, and
    /// the connectivity in the order given.
    #[test]
    fn mesh_lists_its_points_and_polygons_with_running_offsets() {
        let dir = std::env::temp_dir().join(format!("bowwave-vtk-mesh-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("mesh.vtp");
        let pts: Vec<[f64; 3]> = (0..6).map(|i| [(i % 3) as f64, (i / 3) as f64, 0.0]).collect();
        write_mesh_vtp(&path, &pts, &[vec![0, 1, 4, 3], vec![1, 2, 5, 4]]).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        assert!(text.contains("NumberOfPoints=\"6\"") && text.contains("NumberOfPolys=\"2\""));
        let block = |name: &str| -> Vec<String> {
            let start = text.find(&format!("Name=\"{name}\"")).unwrap();
            let body = &text[start..];
            let body = &body[body.find('>').unwrap() + 1..body.find("</DataArray>").unwrap()];
            body.lines()
                .map(str::trim)
                .filter(|l| !l.is_empty())
                .map(String::from)
                .collect()
        };
        assert_eq!(block("connectivity"), ["0 1 4 3", "1 2 5 4"]);
        assert_eq!(block("offsets"), ["4", "8"]);
    }
}
