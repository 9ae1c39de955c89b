//! Wave-pattern fields η(x, y) on regular grids: from a 2D+t run's η(y) profiles (`eta.csv`, one per output
//! x/L) and from a 3D run's particles, so that the two can be drawn, sampled at the same points and subtracted.

use super::contour;
use crate::io::plot::Field;

/// Regular grid of η from (x, y, η) rows: one column per distinct x (the 2D+t outputs), y bins of the run's
/// spacing. `None` with fewer than two distinct x or y.
pub fn eta_field(x: &[f64], y: &[f64], eta: &[f64]) -> Option<Field> {
    let mut xs: Vec<f64> = x.to_vec();
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let mut ys: Vec<f64> = y.to_vec();
    ys.sort_by(f64::total_cmp);
    ys.dedup();
    if xs.len() < 2 || ys.len() < 2 {
        return None;
    }
    let dx = (xs[xs.len() - 1] - xs[0]) / (xs.len() - 1) as f64;
    let dy = ys[1] - ys[0];
    let ny = ((ys[ys.len() - 1] - ys[0]) / dy).round() as usize + 1;
    let mut values = vec![vec![f64::NAN; ny]; xs.len()];
    for k in 0..x.len() {
        let i = xs.partition_point(|v| *v < x[k]);
        let j = ((y[k] - ys[0]) / dy).round() as usize;
        if i < xs.len() && j < ny {
            values[i][j] = eta[k];
        }
    }
    Some(Field {
        x0: xs[0],
        dx,
        y0: ys[0],
        dy,
        values,
    })
}

/// Contour segments of `f` every 0.1 (in the field's unit, D for η/D) from `lowest` to `highest` tenths, the
/// zero level left out (it outlines the calm far field, not the waves).
pub fn tenth_contours(f: &Field, lowest: i32, highest: i32) -> Vec<[(f64, f64); 2]> {
    let grid = contour::Grid {
        values: &f.values,
        x0: f.x0,
        dx: f.dx,
        y0: f.y0,
        dy: f.dy,
    };
    (lowest..=highest)
        .filter(|k| *k != 0)
        .flat_map(|k| contour::segments(&grid, 0.1 * k as f64))
        .collect()
}

/// The grid of a 3D free-surface map: `nx` × `ny` square bins of edge `bin`, the first centred at (x0, y0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bins {
    pub x0: f64,
    pub y0: f64,
    pub bin: f64,
    pub nx: usize,
    pub ny: usize,
}

/// The free surface of a 3D particle set (x, y, z) over `bins`: in each bin the top particle's z + dx/2, as the
/// 2D+t η(y) bins are read (`twodt::passage::eta_profile`); NaN where a bin holds no particle or `masked(x, y)`
/// says the bin's centre is not open water (inside a hull's waterplane), all divided by `scale`.
pub fn eta_field_3d(
    points: impl Iterator<Item = (f64, f64, f64)>,
    bins: Bins,
    dx: f64,
    scale: f64,
    masked: impl Fn(f64, f64) -> bool,
) -> Field {
    let Bins { x0, y0, bin, nx, ny } = bins;
    let mut top = vec![vec![f64::NEG_INFINITY; ny]; nx];
    for (x, y, z) in points {
        let (i, j) = (((x - x0) / bin + 0.5).floor(), ((y - y0) / bin + 0.5).floor());
        if i >= 0.0 && j >= 0.0 && (i as usize) < nx && (j as usize) < ny {
            let t = &mut top[i as usize][j as usize];
            *t = t.max(z);
        }
    }
    let values = (0..nx)
        .map(|i| {
            (0..ny)
                .map(|j| {
                    let (x, y) = (x0 + i as f64 * bin, y0 + j as f64 * bin);
                    let t = top[i][j];
                    if t.is_finite() && !masked(x, y) {
                        (t + 0.5 * dx) / scale
                    } else {
                        f64::NAN
                    }
                })
                .collect()
        })
        .collect();
    Field {
        x0,
        dx: bin,
        y0,
        dy: bin,
        values,
    }
}

/// Along x, one row per column of `f` (an η(x, y) map whose first bins are at the hull): x, the first finite bin's
/// value (the wave profile on the hull, its run-up), the column's largest value (the crest) and its y; NaN where a
/// column holds nothing.
pub fn along_x(f: &Field) -> Vec<[f64; 4]> {
    f.values
        .iter()
        .enumerate()
        .map(|(i, col)| {
            let x = f.x0 + i as f64 * f.dx;
            let hull = col.iter().copied().find(|v| v.is_finite()).unwrap_or(f64::NAN);
            let crest =
                col.iter()
                    .enumerate()
                    .filter(|(_, v)| v.is_finite())
                    .fold((f64::NAN, f64::NAN), |best, (j, v)| {
                        if best.0.is_nan() || *v > best.0 {
                            (*v, f.y0 + j as f64 * f.dy)
                        } else {
                            best
                        }
                    });
            [x, hull, crest.0, crest.1]
        })
        .collect()
}

/// The field at (x, y): the nearest column in x (NaN beyond half a column of either end), linear in y between the
/// two nearest bins (the nearer one where the other is NaN; NaN outside the column).
pub fn sample(f: &Field, x: f64, y: f64) -> f64 {
    let nx = f.values.len();
    let i = ((x - f.x0) / f.dx).round();
    if nx == 0 || i < 0.0 || i as usize >= nx {
        return f64::NAN;
    }
    let col = &f.values[i as usize];
    let s = (y - f.y0) / f.dy;
    if s < -0.5 || s > col.len() as f64 - 0.5 {
        return f64::NAN;
    }
    let j0 = s.floor().max(0.0) as usize;
    let j1 = (j0 + 1).min(col.len() - 1);
    let w = (s - j0 as f64).clamp(0.0, 1.0);
    match (col[j0].is_finite(), col[j1].is_finite()) {
        (true, true) => col[j0] * (1.0 - w) + col[j1] * w,
        (true, false) if w <= 0.5 => col[j0],
        (false, true) if w >= 0.5 => col[j1],
        _ => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A plane free surface z = a x + b y read back from a lattice of particles below it: each bin's top particle
    /// plus half a spacing is the surface at that particle, within a spacing's slope of the bin centre.
    #[test]
    fn a_sloping_plane_is_read_back_and_sampled() {
        let (dx, a, b) = (0.01, 0.05, -0.02);
        let mut pts = vec![];
        for i in 0..200 {
            for j in 0..100 {
                let (x, y) = ((i as f64 + 0.5) * dx, (j as f64 + 0.5) * dx);
                let surface = a * x + b * y;
                let mut z = -0.3 + 0.5 * dx;
                while z + 0.5 * dx <= surface {
                    pts.push((x, y, z));
                    z += dx;
                }
            }
        }
        let bins = Bins {
            x0: 0.02,
            y0: 0.02,
            bin: 0.04,
            nx: 49,
            ny: 24,
        };
        let f = eta_field_3d(pts.iter().copied(), bins, dx, 1.0, |x, _| x > 1.5);
        for (i, col) in f.values.iter().enumerate() {
            for (j, v) in col.iter().enumerate() {
                let (x, y) = (bins.x0 + i as f64 * bins.bin, bins.y0 + j as f64 * bins.bin);
                if x > 1.5 {
                    assert!(v.is_nan());
                } else {
                    assert!((v - (a * x + b * y)).abs() < 2.0 * dx, "bin ({x}, {y}): {v}");
                }
            }
        }
        // Sampling between bin centres interpolates in y.
        let s = sample(&f, 0.5, 0.5);
        assert!((s - (a * 0.5 + b * 0.5)).abs() < 2.0 * dx);
        assert!(sample(&f, 5.0, 0.5).is_nan());
        // The 2D+t rows' grid: one column per x, bins in y.
        let rows: Vec<(f64, f64, f64)> = (0..3)
            .flat_map(|i| (0..4).map(move |j| (0.1 * i as f64, 0.05 * j as f64, (i * 10 + j) as f64)))
            .collect();
        let (x, y, e): (Vec<f64>, Vec<f64>, Vec<f64>) = (
            rows.iter().map(|r| r.0).collect(),
            rows.iter().map(|r| r.1).collect(),
            rows.iter().map(|r| r.2).collect(),
        );
        let g = eta_field(&x, &y, &e).unwrap();
        assert_eq!(g.values[2][3], 23.0);
        assert_eq!(sample(&g, 0.1, 0.075), 11.5);
        // Along x: the first bin (the hull's), the crest and its y.
        let a = along_x(&g);
        assert_eq!(a[1], [0.1, 10.0, 13.0, 0.15000000000000002]);
    }
}
