//! Contour lines of a scalar field on a regular grid, by marching squares: in each cell whose corners straddle
//! the level, the crossing points on its edges (linear interpolation) are joined by a segment. Cells with a NaN
//! corner are skipped; saddle cells take the pairing given by the cell's mean value.

/// A grid of values\[i\]\[j\] at (x0 + i dx, y0 + j dy).
pub struct Grid<'a> {
    pub values: &'a [Vec<f64>],
    pub x0: f64,
    pub dx: f64,
    pub y0: f64,
    pub dy: f64,
}

/// The segments of the contour `level`.
pub fn segments(g: &Grid, level: f64) -> Vec<[(f64, f64); 2]> {
    let nx = g.values.len();
    let mut out = vec![];
    for i in 0..nx.saturating_sub(1) {
        let ny = g.values[i].len().min(g.values[i + 1].len());
        for j in 0..ny.saturating_sub(1) {
            // Corners counter-clockwise from (i, j).
            let c = [
                (i, j, g.values[i][j]),
                (i + 1, j, g.values[i + 1][j]),
                (i + 1, j + 1, g.values[i + 1][j + 1]),
                (i, j + 1, g.values[i][j + 1]),
            ];
            if c.iter().any(|k| !k.2.is_finite()) {
                continue;
            }
            let point = |a: (usize, usize, f64), b: (usize, usize, f64)| {
                let t = (level - a.2) / (b.2 - a.2);
                let x = g.x0 + g.dx * (a.0 as f64 + t * (b.0 as f64 - a.0 as f64));
                let y = g.y0 + g.dy * (a.1 as f64 + t * (b.1 as f64 - a.1 as f64));
                (x, y)
            };
            let crossings: Vec<(f64, f64)> = (0..4)
                .filter_map(|e| {
                    let (a, b) = (c[e], c[(e + 1) % 4]);
                    ((a.2 < level) != (b.2 < level)).then(|| point(a, b))
                })
                .collect();
            match crossings.len() {
                2 => out.push([crossings[0], crossings[1]]),
                4 => {
                    let mean = c.iter().map(|k| k.2).sum::<f64>() / 4.0;
                    // Corner 0 above the level with a mean above too: the high corners 0 and 2 connect.
                    if (c[0].2 >= level) == (mean >= level) {
                        out.push([crossings[0], crossings[1]]);
                        out.push([crossings[2], crossings[3]]);
                    } else {
                        out.push([crossings[3], crossings[0]]);
                        out.push([crossings[1], crossings[2]]);
                    }
                }
                _ => {}
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The contour r = 0.5 of f = x² + y² lies on the circle (to the interpolation error of a fine grid).
    #[test]
    fn contour_of_a_paraboloid_is_a_circle() {
        let n = 81;
        let h = 2.0 / (n - 1) as f64;
        let values: Vec<Vec<f64>> = (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        let (x, y) = (-1.0 + i as f64 * h, -1.0 + j as f64 * h);
                        x * x + y * y
                    })
                    .collect()
            })
            .collect();
        let g = Grid {
            values: &values,
            x0: -1.0,
            dx: h,
            y0: -1.0,
            dy: h,
        };
        let s = segments(&g, 0.25);
        assert!(s.len() > 50);
        let length: f64 = s
            .iter()
            .map(|[a, b]| ((a.0 - b.0).powi(2) + (a.1 - b.1).powi(2)).sqrt())
            .sum();
        assert!((length - std::f64::consts::PI).abs() < 0.01, "perimeter {length}");
        for [a, _] in &s {
            let r = (a.0 * a.0 + a.1 * a.1).sqrt();
            assert!((r - 0.5).abs() < 2e-3, "r = {r}");
        }
    }
}
