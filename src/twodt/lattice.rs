//! Graded initial particle lattice at constant h (thesis §10.1.2, Fig. 10.4): rows of spacing dx_f from the
//! calm level down to a depth d1, dx_c = r dx_f below a depth d2, spacing varying linearly with depth in
//! between. Each row is uniform across the width; each particle's mass is ρ0 times its row's spacing
//! times its row's height (half-way to the rows above and below), so the masses add up to ρ0 W Z exactly.
//! The rows below d2 are stretched uniformly (by a few per cent at most) so that the last row lies half a
//! spacing above the bottom.

use nalgebra::Vector2;

type V2 = Vector2<f64>;

/// One horizontal row of particles.
#[derive(Clone, Copy, Debug)]
pub struct Row {
    /// Depth of the row below the calm level (positive).
    pub depth: f64,
    /// Height of the strip the row stands for.
    pub height: f64,
    /// Spacing across.
    pub spacing: f64,
}

/// Local spacing at a depth.
pub fn spacing_at(depth: f64, dx_f: f64, dx_c: f64, d1: f64, d2: f64) -> f64 {
    if depth <= d1 {
        dx_f
    } else if depth >= d2 {
        dx_c
    } else {
        dx_f + (dx_c - dx_f) * (depth - d1) / (d2 - d1)
    }
}

/// The rows filling a layer of depth `z` (calm level 0, bottom at −z).
pub fn rows(z: f64, width: f64, dx_f: f64, dx_c: f64, d1: f64, d2: f64) -> Vec<Row> {
    let mut depths = vec![0.5 * dx_f];
    loop {
        let d = *depths.last().unwrap();
        let s = spacing_at(d, dx_f, dx_c, d1, d2);
        // The last row should stand half a spacing above the bottom: add rows while the next one is nearer
        // to that than the current one (d + s/2 < z − s/2), so the stretch below is at most s/2 overall.
        if d + s >= z {
            break;
        }
        depths.push(d + s);
    }
    // Stretch the rows below d2 so the last lies half a spacing above the bottom.
    let last = *depths.last().unwrap();
    let s_last = spacing_at(last, dx_f, dx_c, d1, d2);
    let target = z - 0.5 * s_last;
    let pivot = depths.iter().copied().filter(|&d| d <= d2).fold(0.0, f64::max);
    if last > pivot {
        let a = (target - pivot) / (last - pivot);
        for d in depths.iter_mut().filter(|d| **d > pivot) {
            *d = pivot + (*d - pivot) * a;
        }
    }
    let n = depths.len();
    (0..n)
        .map(|k| {
            let above = if k == 0 { 0.0 } else { 0.5 * (depths[k - 1] + depths[k]) };
            let below = if k + 1 == n {
                z
            } else {
                0.5 * (depths[k] + depths[k + 1])
            };
            let s = spacing_at(depths[k], dx_f, dx_c, d1, d2);
            let m = ((width / s).round() as usize).max(1);
            Row {
                depth: depths[k],
                height: below - above,
                spacing: width / m as f64,
            }
        })
        .collect()
}

/// Particle positions and areas (mass / ρ0) of the rows across [0, width], with the index of each
/// particle's row.
pub fn particles(rows: &[Row], width: f64) -> Vec<(V2, f64, usize)> {
    let mut out = vec![];
    for (k, r) in rows.iter().enumerate() {
        let m = (width / r.spacing).round() as usize;
        for i in 0..m {
            out.push((V2::new((i as f64 + 0.5) * r.spacing, -r.depth), r.spacing * r.height, k));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn graded_rows_fill_the_layer_exactly_and_grade_smoothly() {
        let (z, w, dxf) = (2.0, 3.0, 0.01);
        let r = rows(z, w, dxf, 0.015, 0.2, 1.0);
        let total: f64 = r.iter().map(|r| r.height).sum();
        assert!((total - z).abs() < 1e-12);
        let area: f64 = particles(&r, w).iter().map(|p| p.1).sum();
        assert!((area / (z * w) - 1.0).abs() < 1e-12, "area {area}");
        assert!((r[0].depth - 0.005).abs() < 1e-12 && (r[0].spacing - dxf).abs() < 1e-12);
        let last = r.last().unwrap();
        assert!((z - last.depth - 0.5 * (last.depth - r[r.len() - 2].depth)).abs() < 1e-3 * dxf * 100.0);
        for w in r.windows(2) {
            let gap = w[1].depth - w[0].depth;
            assert!(gap > 0.95 * dxf && gap < 1.6 * dxf, "row gap {gap}");
        }
    }
}
