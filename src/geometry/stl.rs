//! Triangulated surfaces (STL): export of a hull surface, and import of a CAD hull by slicing it at chosen
//! stations, keeping the y ≥ 0 half and chaining the cut segments into ordered sections (keel → deck).
//!
//! Conventions of an imported STL: metres, x along the ship, the stem at the smallest x (or the largest,
//! with `stem_at_max_x`), y transverse (either or both sides), z up with the calm waterline at z = 0.
//! A closed hull's slice runs on over the deck back to the centre plane: the section is cut where it first
//! turns inboard over the deck above the waterline (going inwards at less than 45° to the horizontal).

use super::hull_file::{HullMeta, HullOffsets, HullStatus, Station};
use super::surface::HullSurface;
use std::collections::BTreeMap;
use std::path::Path;
use stl_io::{Normal, Triangle, Vertex};

/// Triangles of the surface (metres), `nx` × `nxi` quads per side, both sides if `both_sides`.
pub fn surface_triangles(s: &HullSurface, nx: usize, nxi: usize, both_sides: bool) -> Vec<Triangle> {
    let l = s.meta.length_m;
    let (x0, x1) = s.x_range;
    let grid: Vec<Vec<[f64; 3]>> = (0..=nx)
        .map(|i| {
            let x = x0 + (x1 - x0) * i as f64 / nx as f64;
            let c = s.curve(x).expect("x inside the hull");
            (0..=nxi)
                .map(|k| {
                    let p = c.point(k as f64 / nxi as f64);
                    [x * l, p.y.max(0.0) * l, p.z * l]
                })
                .collect()
        })
        .collect();
    let mut tris = vec![];
    for side in if both_sides { vec![1.0, -1.0] } else { vec![1.0] } {
        for i in 0..nx {
            for k in 0..nxi {
                let v = |a: [f64; 3]| Vertex::new([a[0] as f32, (side * a[1]) as f32, a[2] as f32]);
                let (a, b, c, d) = (grid[i][k], grid[i + 1][k], grid[i + 1][k + 1], grid[i][k + 1]);
                for t in [[a, b, c], [a, c, d]] {
                    tris.push(Triangle {
                        normal: Normal::new([0.0, side as f32, 0.0]),
                        vertices: [v(t[0]), v(t[1]), v(t[2])],
                    });
                }
            }
        }
    }
    tris
}

/// Writes triangles as a binary STL.
pub fn write_stl(path: &Path, tris: &[Triangle]) -> anyhow::Result<()> {
    let mut buf = Vec::new();
    stl_io::write_stl(&mut buf, tris.iter())?;
    crate::io::atomic::write_atomic(path, &buf)?;
    Ok(())
}

/// Options of an STL import.
#[derive(Clone, Debug)]
pub struct ImportOptions {
    pub name: String,
    /// Stations x/L (from the stem) at which to slice; each must cut the hull.
    pub stations: Vec<f64>,
    /// Reference length L (m); `None`: the x-extent of the mesh.
    pub length_m: Option<f64>,
    pub stem_at_max_x: bool,
    pub transom: bool,
}

/// Points of the cut of triangle `t` by the plane x = xc (0 or 2 points).
fn cut(t: &[[f64; 3]; 3], xc: f64) -> Option<[[f64; 2]; 2]> {
    let mut pts = vec![];
    for e in 0..3 {
        let (a, b) = (t[e], t[(e + 1) % 3]);
        let (da, db) = (a[0] - xc, b[0] - xc);
        if (da < 0.0 && db >= 0.0) || (da >= 0.0 && db < 0.0) {
            let f = da / (da - db);
            pts.push([a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])]);
        }
    }
    (pts.len() == 2).then(|| [pts[0], pts[1]])
}

/// Clips a segment to y ≥ 0.
fn clip_half(s: [[f64; 2]; 2]) -> Option<[[f64; 2]; 2]> {
    let [a, b] = s;
    match (a[0] >= 0.0, b[0] >= 0.0) {
        (true, true) => Some(s),
        (false, false) => None,
        _ => {
            let f = a[0] / (a[0] - b[0]);
            let c = [0.0, a[1] + f * (b[1] - a[1])];
            Some(if a[0] >= 0.0 { [a, c] } else { [c, b] })
        }
    }
}

/// Chains segments into one polyline from the lowest point on the centre plane, cut at the deck.
fn chain(segs: &[[[f64; 2]; 2]], tol: f64) -> Option<Vec<[f64; 2]>> {
    if segs.is_empty() {
        return None;
    }
    let key = |p: [f64; 2]| ((p[0] / tol).round() as i64, (p[1] / tol).round() as i64);
    let mut adj: BTreeMap<(i64, i64), Vec<usize>> = BTreeMap::new();
    for (i, s) in segs.iter().enumerate() {
        adj.entry(key(s[0])).or_default().push(i);
        adj.entry(key(s[1])).or_default().push(i);
    }
    // Start: the segment end nearest the centre plane, lowest first.
    let start = segs.iter().flat_map(|s| s.iter().copied()).min_by(|a, b| {
        (a[0].abs() > 2.0 * tol)
            .cmp(&(b[0].abs() > 2.0 * tol))
            .then(a[1].total_cmp(&b[1]))
    })?;
    let mut used = vec![false; segs.len()];
    let mut line = vec![[0.0, start[1]]];
    let mut cur = start;
    loop {
        let next = adj.get(&key(cur)).and_then(|v| v.iter().copied().find(|&i| !used[i]));
        let Some(i) = next else { break };
        used[i] = true;
        let s = segs[i];
        let other = if key(s[0]) == key(cur) { s[1] } else { s[0] };
        let last = *line.last().unwrap();
        let (dy, dz) = (other[0] - last[0], other[1] - last[1]);
        if last[1] > 0.0 && dy < 0.0 && dz.abs() < dy.abs() {
            break; // over the deck, going inboard
        }
        if (other[0] - last[0]).hypot(other[1] - last[1]) > tol {
            line.push(other);
        }
        cur = other;
    }
    (line.len() >= 3).then_some(line)
}

/// An edge of the wetted surface that only one triangle has (a hole, or a gap between triangles): its ends.
/// Edges on the centre plane (a half hull), above the waterline (an open deck) or at the mesh's ends in x (an
/// open transom) may be open; the vertices are the mesh's own, merged where they coincide.
fn open_wetted_edge(
    faces: &[stl_io::IndexedTriangle],
    v: &[[f64; 3]],
    (xmin, xmax): (f64, f64),
    tol: f64,
) -> Option<([f64; 3], [f64; 3])> {
    let mut count: BTreeMap<(usize, usize), u32> = BTreeMap::new();
    for t in faces {
        for e in 0..3 {
            let (a, b) = (t.vertices[e], t.vertices[(e + 1) % 3]);
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    count
        .iter()
        .find(|(&(a, b), &n)| n == 1 && !on_an_open_line(v[a], v[b], (xmin, xmax), tol))
        .map(|(&(a, b), _)| (v[a], v[b]))
}

/// Whether an edge lies wholly on one of the lines or planes where a hull surface may be open.
fn on_an_open_line(a: [f64; 3], b: [f64; 3], (xmin, xmax): (f64, f64), tol: f64) -> bool {
    (a[1].abs() <= tol && b[1].abs() <= tol)
        || (a[2] >= -tol && b[2] >= -tol)
        || (a[0] <= xmin + tol && b[0] <= xmin + tol)
        || (a[0] >= xmax - tol && b[0] >= xmax - tol)
}

/// Reads an STL and slices it into a hull offsets description.
pub fn import_stl(path: &Path, opts: &ImportOptions) -> anyhow::Result<HullOffsets> {
    let file = path.display().to_string();
    let mut f = std::fs::File::open(path).map_err(|e| anyhow::anyhow!("{file}: cannot open: {e}"))?;
    let mesh = stl_io::read_stl(&mut f).map_err(|e| anyhow::anyhow!("{file}: not a readable STL: {e}"))?;
    anyhow::ensure!(!mesh.faces.is_empty(), "{file}: the mesh has no triangle");
    let v: Vec<[f64; 3]> = mesh
        .vertices
        .iter()
        .map(|p| [p[0] as f64, p[1] as f64, p[2] as f64])
        .collect();
    let (xmin, xmax) = v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
        (a.0.min(p[0]), a.1.max(p[0]))
    });
    let l = opts.length_m.unwrap_or(xmax - xmin);
    anyhow::ensure!(l > 0.0, "{file}: the mesh has no length along x");
    let tol = 1e-6 * l;
    if let Some((a, b)) = open_wetted_edge(&mesh.faces, &v, (xmin, xmax), tol) {
        let p = |q: [f64; 3]| format!("({:.4}, {:.4}, {:.4})", q[0], q[1], q[2]);
        anyhow::bail!(
            "{file}: the mesh is not watertight below the waterline: the edge from {} to {} m belongs to one triangle \
             only; expected a closed wetted surface (an edge may be open only on the centre plane y = 0, above the \
             waterline z = 0, or at the ends, as an open transom)",
            p(a),
            p(b)
        );
    }
    let mut stations = vec![];
    for &xs in &opts.stations {
        let xc = if opts.stem_at_max_x {
            xmax - xs * l
        } else {
            xmin + xs * l
        };
        let segs: Vec<[[f64; 2]; 2]> = mesh
            .faces
            .iter()
            .filter_map(|t| cut(&[v[t.vertices[0]], v[t.vertices[1]], v[t.vertices[2]]], xc))
            .filter_map(clip_half)
            .filter(|s| (s[0][0] - s[1][0]).hypot(s[0][1] - s[1][1]) > tol)
            .collect();
        let line = chain(&segs, tol).ok_or_else(|| {
            anyhow::anyhow!("{file}: station x/L = {xs} does not cut the hull in a section from the keel up")
        })?;
        stations.push(Station {
            x: xs,
            points: line.iter().map(|p| [p[0] / l, p[1] / l]).collect(),
        });
    }
    let max_y = stations
        .iter()
        .flat_map(|s| s.points.iter())
        .filter(|p| p[1] <= 0.0)
        .map(|p| p[0])
        .fold(0.0, f64::max);
    let min_z = stations
        .iter()
        .flat_map(|s| s.points.iter())
        .map(|p| p[1])
        .fold(f64::INFINITY, f64::min);
    let mut notes = BTreeMap::new();
    notes.insert(
        "imported_from".into(),
        path.file_name()
            .map(|n| n.to_string_lossy().to_string())
            .unwrap_or_default(),
    );
    Ok(HullOffsets {
        meta: HullMeta {
            name: opts.name.clone(),
            status: HullStatus::Exact,
            length_m: l,
            draft_m: -min_z * l,
            beam_m: 2.0 * max_y * l,
            model_scale: 1.0,
            transom: opts.transom,
            transom_immersion_m: 0.0,
            source: format!("sliced from the STL {file} by bowwave hull import"),
            notes,
        },
        stations,
    })
}
