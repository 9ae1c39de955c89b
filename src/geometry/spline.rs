//! One-dimensional interpolants: the natural cubic spline (C², linear in the data, so derivatives of
//! interpolated data equal interpolated derivatives) and the monotone piecewise-cubic Hermite (PCHIP,
//! Fritsch–Carlson), which does not overshoot and so cannot fold a section.
//!
//! The `splines` crate's Catmull-Rom is only C¹ across knots; the wall acceleration of a 2D+t section needs
//! y_xx, so the x-direction uses the natural cubic spline written here.

/// A natural cubic spline through (x_k, y_k), x strictly increasing.
#[derive(Clone, Debug, PartialEq)]
pub struct CubicSpline {
    x: Vec<f64>,
    y: Vec<f64>,
    /// Second derivatives at the knots.
    m: Vec<f64>,
}

impl CubicSpline {
    /// Clamped spline whose end slopes are those of the cubic through the 4 end knots (natural with fewer
    /// knots): reproduces cubic data exactly, unlike the natural end condition y'' = 0.
    pub fn clamped_cubic_ends(x: &[f64], y: &[f64]) -> Self {
        let n = x.len();
        if n < 4 {
            return Self::new(x, y);
        }
        let slope = |xs: [f64; 4], ys: [f64; 4], t: f64| {
            // Derivative of the Lagrange cubic through (xs, ys) at t.
            let mut d = 0.0;
            for i in 0..4 {
                let mut term = 0.0;
                for k in 0..4 {
                    if k == i {
                        continue;
                    }
                    let mut prod = 1.0 / (xs[i] - xs[k]);
                    for m in 0..4 {
                        if m != i && m != k {
                            prod *= (t - xs[m]) / (xs[i] - xs[m]);
                        }
                    }
                    term += prod;
                }
                d += ys[i] * term;
            }
            d
        };
        let d0 = slope([x[0], x[1], x[2], x[3]], [y[0], y[1], y[2], y[3]], x[0]);
        let dn = slope(
            [x[n - 4], x[n - 3], x[n - 2], x[n - 1]],
            [y[n - 4], y[n - 3], y[n - 2], y[n - 1]],
            x[n - 1],
        );
        // Tridiagonal system for all second derivatives with the clamped end rows.
        let mut a = vec![0.0; n];
        let mut b = vec![0.0; n];
        let mut c = vec![0.0; n];
        let mut r = vec![0.0; n];
        let h0 = x[1] - x[0];
        b[0] = h0 / 3.0;
        c[0] = h0 / 6.0;
        r[0] = (y[1] - y[0]) / h0 - d0;
        for i in 1..n - 1 {
            let (hl, hr) = (x[i] - x[i - 1], x[i + 1] - x[i]);
            a[i] = hl / 6.0;
            b[i] = (hl + hr) / 3.0;
            c[i] = hr / 6.0;
            r[i] = (y[i + 1] - y[i]) / hr - (y[i] - y[i - 1]) / hl;
        }
        let hn = x[n - 1] - x[n - 2];
        a[n - 1] = hn / 6.0;
        b[n - 1] = hn / 3.0;
        r[n - 1] = dn - (y[n - 1] - y[n - 2]) / hn;
        // Thomas algorithm.
        for i in 1..n {
            let w = a[i] / b[i - 1];
            b[i] -= w * c[i - 1];
            r[i] -= w * r[i - 1];
        }
        let mut m = vec![0.0; n];
        m[n - 1] = r[n - 1] / b[n - 1];
        for i in (0..n - 1).rev() {
            m[i] = (r[i] - c[i] * m[i + 1]) / b[i];
        }
        CubicSpline {
            x: x.to_vec(),
            y: y.to_vec(),
            m,
        }
    }

    /// Natural spline (y'' = 0 at both ends).
    pub fn new(x: &[f64], y: &[f64]) -> Self {
        let n = x.len();
        assert!(n >= 2 && y.len() == n, "a spline needs at least two knots");
        let mut m = vec![0.0; n];
        if n > 2 {
            // Tridiagonal system for the interior second derivatives (Thomas algorithm).
            let mut c = vec![0.0; n];
            let mut d = vec![0.0; n];
            for i in 1..n - 1 {
                let h0 = x[i] - x[i - 1];
                let h1 = x[i + 1] - x[i];
                let a = h0 / 6.0;
                let b = (h0 + h1) / 3.0;
                let cc = h1 / 6.0;
                let r = (y[i + 1] - y[i]) / h1 - (y[i] - y[i - 1]) / h0;
                let denom = b - a * c[i - 1];
                c[i] = cc / denom;
                d[i] = (r - a * d[i - 1]) / denom;
            }
            for i in (1..n - 1).rev() {
                m[i] = d[i] - c[i] * m[i + 1];
            }
        }
        CubicSpline {
            x: x.to_vec(),
            y: y.to_vec(),
            m,
        }
    }

    fn interval(&self, t: f64) -> usize {
        let n = self.x.len();
        self.x.partition_point(|&v| v <= t).clamp(1, n - 1) - 1
    }

    /// (value, first derivative, second derivative) at t (extrapolated linearly outside).
    pub fn eval(&self, t: f64) -> (f64, f64, f64) {
        let n = self.x.len();
        if t < self.x[0] || t > self.x[n - 1] {
            let (k, edge) = if t < self.x[0] {
                (0, self.x[0])
            } else {
                (n - 1, self.x[n - 1])
            };
            let (v, d, _) = self.eval_inside(edge, if k == 0 { 0 } else { n - 2 });
            return (v + d * (t - edge), d, 0.0);
        }
        self.eval_inside(t, self.interval(t))
    }

    fn eval_inside(&self, t: f64, i: usize) -> (f64, f64, f64) {
        let (x0, x1) = (self.x[i], self.x[i + 1]);
        let h = x1 - x0;
        let a = (x1 - t) / h;
        let b = (t - x0) / h;
        let (m0, m1) = (self.m[i], self.m[i + 1]);
        let v = a * self.y[i] + b * self.y[i + 1] + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6.0;
        let d = (self.y[i + 1] - self.y[i]) / h + (-(3.0 * a * a - 1.0) * m0 + (3.0 * b * b - 1.0) * m1) * h / 6.0;
        let dd = a * m0 + b * m1;
        (v, d, dd)
    }
}

/// Monotone piecewise-cubic Hermite interpolant (Fritsch–Carlson slopes).
#[derive(Clone, Debug)]
pub struct Pchip {
    x: Vec<f64>,
    y: Vec<f64>,
    d: Vec<f64>,
}

impl Pchip {
    pub fn new(x: &[f64], y: &[f64]) -> Self {
        let n = x.len();
        assert!(n >= 2);
        let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
        let delta: Vec<f64> = (0..n - 1).map(|i| (y[i + 1] - y[i]) / h[i]).collect();
        let mut d = vec![0.0; n];
        if n == 2 {
            d[0] = delta[0];
            d[1] = delta[0];
        } else {
            for i in 1..n - 1 {
                if delta[i - 1] * delta[i] > 0.0 {
                    let w1 = 2.0 * h[i] + h[i - 1];
                    let w2 = h[i] + 2.0 * h[i - 1];
                    d[i] = (w1 + w2) / (w1 / delta[i - 1] + w2 / delta[i]);
                }
            }
            let end = |h0: f64, h1: f64, d0: f64, d1: f64| {
                let s = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
                if s * d0 <= 0.0 {
                    0.0
                } else if d0 * d1 <= 0.0 && s.abs() > 3.0 * d0.abs() {
                    3.0 * d0
                } else {
                    s
                }
            };
            d[0] = end(h[0], h[1], delta[0], delta[1]);
            d[n - 1] = end(h[n - 2], h[n - 3], delta[n - 2], delta[n - 3]);
        }
        Pchip {
            x: x.to_vec(),
            y: y.to_vec(),
            d,
        }
    }

    /// (value, first derivative) at t, clamped to the data range.
    pub fn eval(&self, t: f64) -> (f64, f64) {
        let n = self.x.len();
        let t = t.clamp(self.x[0], self.x[n - 1]);
        let i = self.x.partition_point(|&v| v <= t).clamp(1, n - 1) - 1;
        let h = self.x[i + 1] - self.x[i];
        let s = (t - self.x[i]) / h;
        let (y0, y1, d0, d1) = (self.y[i], self.y[i + 1], self.d[i] * h, self.d[i + 1] * h);
        let h00 = 2.0 * s * s * s - 3.0 * s * s + 1.0;
        let h10 = s * s * s - 2.0 * s * s + s;
        let h01 = -2.0 * s * s * s + 3.0 * s * s;
        let h11 = s * s * s - s * s;
        let v = h00 * y0 + h10 * d0 + h01 * y1 + h11 * d1;
        let dv = ((6.0 * s * s - 6.0 * s) * y0
            + (3.0 * s * s - 4.0 * s + 1.0) * d0
            + (-6.0 * s * s + 6.0 * s) * y1
            + (3.0 * s * s - 2.0 * s) * d1)
            / h;
        (v, dv)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn natural_spline_reproduces_a_cubic_interior_and_converges_on_sine() {
        let xs: Vec<f64> = (0..=40).map(|i| i as f64 * 0.05).collect();
        let ys: Vec<f64> = xs.iter().map(|x| x.sin()).collect();
        let s = CubicSpline::new(&xs, &ys);
        for t in [0.33, 0.91, 1.37] {
            let (v, d, dd) = s.eval(t);
            assert!((v - t.sin()).abs() < 1e-6);
            assert!((d - t.cos()).abs() < 1e-4);
            assert!((dd + t.sin()).abs() < 2e-2);
        }
    }

    #[test]
    fn clamped_spline_reproduces_cubics() {
        let xs: Vec<f64> = (0..=10).map(|i| (i as f64 * 0.1).powf(1.3)).collect();
        let f = |t: f64| 1.0 + 2.0 * t - 3.0 * t * t + 0.5 * t * t * t;
        let ys: Vec<f64> = xs.iter().map(|&t| f(t)).collect();
        let s = CubicSpline::clamped_cubic_ends(&xs, &ys);
        for t in [0.01, 0.2, 0.55, 0.97] {
            let (v, d, dd) = s.eval(t);
            assert!((v - f(t)).abs() < 1e-12);
            assert!((d - (2.0 - 6.0 * t + 1.5 * t * t)).abs() < 1e-10);
            assert!((dd - (-6.0 + 3.0 * t)).abs() < 1e-8);
        }
    }

    #[test]
    fn pchip_is_monotone_on_monotone_data() {
        let xs = [0.0, 1.0, 2.0, 3.0, 4.0];
        let ys = [0.0, 0.0, 1.0, 1.0, 5.0];
        let p = Pchip::new(&xs, &ys);
        let mut last = -1.0;
        for k in 0..=400 {
            let (v, _) = p.eval(k as f64 * 0.01);
            assert!(v >= last - 1e-12, "overshoot at {k}");
            last = v;
        }
    }
}
