//! The hull surface y(x, ξ), z(x, ξ) in units of L, with ξ ∈ [0, 1] the normalised girth from the keel (0)
//! to the deck (1); and its 2D+t sections.
//!
//! Along the girth each station is interpolated by a monotone cubic (PCHIP) in its normalised chord length
//! (no overshoot, so no folded section) and resampled on a common grid of [`NXI`] values of ξ. Across the
//! stations each grid line is a C² cubic spline in x (clamped with cubic end slopes), which gives y_x, z_x,
//! y_xx, z_xx. At any x the grid values are joined along the girth by natural cubic splines, which are linear
//! in the data, so ξ-derivatives of x-derivatives are consistent.

use super::hull_file::{HullMeta, HullOffsets};
use super::spline::{CubicSpline, Pchip};

/// Girth samples per station on the common ξ grid.
pub const NXI: usize = 161;

/// The interpolated hull surface.
#[derive(Clone, Debug)]
pub struct HullSurface {
    pub meta: HullMeta,
    /// x/L of the first and last stations (the stem and the stern or transom).
    pub x_range: (f64, f64),
    xi: Vec<f64>,
    y_of_x: Vec<CubicSpline>,
    z_of_x: Vec<CubicSpline>,
}

/// One point of the surface with its derivatives (all in units of L).
#[derive(Clone, Copy, Debug, Default)]
pub struct SurfacePoint {
    pub y: f64,
    pub z: f64,
    pub y_xi: f64,
    pub z_xi: f64,
    pub y_x: f64,
    pub z_x: f64,
    pub y_xx: f64,
    pub z_xx: f64,
}

impl SurfacePoint {
    /// Outward unit normal of the section (into the fluid), N_2D = (z_ξ, −y_ξ)/|r_ξ|, eq. (10.3).
    pub fn normal(&self) -> [f64; 2] {
        let n = self.y_xi.hypot(self.z_xi).max(1e-300);
        [self.z_xi / n, -self.y_xi / n]
    }
    /// Expansion velocity per unit ship speed, eq. (10.4): w_n/U = (y_x z_ξ − z_x y_ξ)/√(y_ξ² + z_ξ²).
    pub fn w_n_over_u(&self) -> f64 {
        let n = self.normal();
        self.y_x * n[0] + self.z_x * n[1]
    }
    /// Normal acceleration of the wall per U²/L: (y_xx, z_xx)·N.
    pub fn a_n_over_u2_per_l(&self) -> f64 {
        let n = self.normal();
        self.y_xx * n[0] + self.z_xx * n[1]
    }
}

/// The curve of one section: girth splines of the grid values and of their x-derivatives.
#[derive(Clone, Debug)]
pub struct SectionCurve {
    pub x: f64,
    y: [CubicSpline; 3],
    z: [CubicSpline; 3],
}

impl SectionCurve {
    pub fn point(&self, xi: f64) -> SurfacePoint {
        let (y, y_xi, _) = self.y[0].eval(xi);
        let (z, z_xi, _) = self.z[0].eval(xi);
        SurfacePoint {
            y,
            z,
            y_xi,
            z_xi,
            y_x: self.y[1].eval(xi).0,
            z_x: self.z[1].eval(xi).0,
            y_xx: self.y[2].eval(xi).0,
            z_xx: self.z[2].eval(xi).0,
        }
    }
}

/// A section sample for ghost-particle generation (units of L, of U for w_n, of U²/L for a_n).
#[derive(Clone, Copy, Debug)]
pub struct SectionSample {
    pub y: f64,
    pub z: f64,
    pub xi: f64,
    pub normal: [f64; 2],
    pub w_n_over_u: f64,
    pub a_n_over_u2_per_l: f64,
    /// The surface point with its derivatives (velocity of the section point U(y_x, z_x), acceleration
    /// U²(y_xx, z_xx) at fixed ξ).
    pub point: SurfacePoint,
}

impl HullSurface {
    pub fn new(h: &HullOffsets) -> Self {
        let xi: Vec<f64> = (0..NXI).map(|k| k as f64 / (NXI - 1) as f64).collect();
        let xs: Vec<f64> = h.stations.iter().map(|s| s.x).collect();
        let mut ys = vec![vec![0.0; xs.len()]; NXI];
        let mut zs = vec![vec![0.0; xs.len()]; NXI];
        for (j, st) in h.stations.iter().enumerate() {
            let mut s = vec![0.0];
            for w in st.points.windows(2) {
                s.push(s.last().unwrap() + (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]));
            }
            let total = *s.last().unwrap();
            let t: Vec<f64> = s.iter().map(|v| v / total).collect();
            let py = Pchip::new(&t, &st.points.iter().map(|p| p[0]).collect::<Vec<_>>());
            let pz = Pchip::new(&t, &st.points.iter().map(|p| p[1]).collect::<Vec<_>>());
            for k in 0..NXI {
                ys[k][j] = py.eval(xi[k]).0;
                zs[k][j] = pz.eval(xi[k]).0;
            }
        }
        HullSurface {
            meta: h.meta.clone(),
            x_range: (xs[0], *xs.last().unwrap()),
            y_of_x: ys.iter().map(|v| CubicSpline::clamped_cubic_ends(&xs, v)).collect(),
            z_of_x: zs.iter().map(|v| CubicSpline::clamped_cubic_ends(&xs, v)).collect(),
            xi,
        }
    }

    /// The section curve at x/L; `None` before the stem or after the stern (the section is empty there).
    pub fn curve(&self, x: f64) -> Option<SectionCurve> {
        if x < self.x_range.0 || x > self.x_range.1 {
            return None;
        }
        let mut yv = [vec![0.0; NXI], vec![0.0; NXI], vec![0.0; NXI]];
        let mut zv = [vec![0.0; NXI], vec![0.0; NXI], vec![0.0; NXI]];
        for k in 0..NXI {
            let (a, b, c) = self.y_of_x[k].eval(x);
            yv[0][k] = a.max(0.0);
            yv[1][k] = b;
            yv[2][k] = c;
            let (a, b, c) = self.z_of_x[k].eval(x);
            zv[0][k] = a;
            zv[1][k] = b;
            zv[2][k] = c;
        }
        let sp = |v: &Vec<f64>| CubicSpline::new(&self.xi, v);
        Some(SectionCurve {
            x,
            y: [sp(&yv[0]), sp(&yv[1]), sp(&yv[2])],
            z: [sp(&zv[0]), sp(&zv[1]), sp(&zv[2])],
        })
    }

    /// The section at x/L sampled at arc-length spacing `ds` (units of L) from keel to deck, with normals,
    /// w_n/U and a_n/(U²/L); `None` outside the hull.
    pub fn section(&self, x: f64, ds: f64) -> Option<Vec<SectionSample>> {
        let c = self.curve(x)?;
        // Dense polyline for the arc length.
        let n = 8 * NXI;
        let pts: Vec<(f64, f64, f64)> = (0..=n)
            .map(|k| {
                let xi = k as f64 / n as f64;
                let p = c.point(xi);
                (xi, p.y, p.z)
            })
            .collect();
        let mut s = vec![0.0];
        for w in pts.windows(2) {
            s.push(s.last().unwrap() + (w[1].1 - w[0].1).hypot(w[1].2 - w[0].2));
        }
        let total = *s.last().unwrap();
        let m = ((total / ds).round() as usize).max(1);
        Some(
            (0..=m)
                .map(|k| {
                    let target = total * k as f64 / m as f64;
                    let i = s.partition_point(|&v| v < target).clamp(1, n);
                    let f = if s[i] > s[i - 1] {
                        (target - s[i - 1]) / (s[i] - s[i - 1])
                    } else {
                        0.0
                    };
                    let xi = pts[i - 1].0 + f * (pts[i].0 - pts[i - 1].0);
                    let p = c.point(xi);
                    SectionSample {
                        y: p.y,
                        z: p.z,
                        xi,
                        normal: p.normal(),
                        w_n_over_u: p.w_n_over_u(),
                        a_n_over_u2_per_l: p.a_n_over_u2_per_l(),
                        point: p,
                    }
                })
                .collect(),
        )
    }
}
