//! Smoothing kernels, generic over the spatial dimension `D`.
//!
//! * [`KernelKind::RenormalizedGaussian`]: Marrone (2011) eq. (4.21), a Gaussian cut at ε_h = 3h and shifted
//!   so that it vanishes there, renormalised to unit integral. Default, with h = 1.33 dx (thesis §4.2).
//! * [`KernelKind::WendlandC2`]: Wendland's C2 kernel with support 2h; used with h = 2 dx so that its support
//!   (4 dx) matches the Gaussian's (3 × 1.33 dx ≈ 4 dx) and the neighbour count is the same.

use nalgebra::SVector;
use serde::{Deserialize, Serialize};

/// Which kernel shape to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum KernelKind {
    /// Eq. (4.21): (e^{-(r/h)²} − C0)/norm for r ≤ 3h.
    RenormalizedGaussian,
    /// Wendland C2: a_D (1 − q/2)⁴ (2q + 1), q = r/h ≤ 2.
    WendlandC2,
}

impl KernelKind {
    /// Default ratio h/dx for this kernel (dimensionless): 1.33 for the Gaussian (thesis §4.2),
    /// 2.0 for Wendland C2 (same 4 dx support).
    pub fn default_h_over_dx(self) -> f64 {
        match self {
            KernelKind::RenormalizedGaussian => 1.33,
            KernelKind::WendlandC2 => 2.0,
        }
    }

    /// Support radius in units of h.
    pub fn support_over_h(self) -> f64 {
        match self {
            KernelKind::RenormalizedGaussian => 3.0,
            KernelKind::WendlandC2 => 2.0,
        }
    }
}

/// A kernel of fixed smoothing length `h` in dimension `D`.
#[derive(Clone, Copy, Debug)]
pub struct Kernel<const D: usize> {
    pub kind: KernelKind,
    /// Smoothing length h (m).
    pub h: f64,
    /// Support radius (m): 3h (Gaussian) or 2h (Wendland).
    pub support: f64,
    norm: f64,
    shift: f64,
    inv_h2: f64,
}

/// Surface of the unit sphere in dimension `d` (2 for d = 1, 2π for d = 2, 4π for d = 3).
fn unit_sphere_surface(d: usize) -> f64 {
    match d {
        1 => 2.0,
        2 => 2.0 * std::f64::consts::PI,
        3 => 4.0 * std::f64::consts::PI,
        _ => panic!("kernel: dimension {d} is not supported (1, 2 or 3)"),
    }
}

impl<const D: usize> Kernel<D> {
    pub fn new(kind: KernelKind, h: f64) -> Self {
        let support = kind.support_over_h() * h;
        let inv_h2 = 1.0 / (h * h);
        match kind {
            KernelKind::RenormalizedGaussian => {
                let shift = (-(support * support) * inv_h2).exp();
                // norm = S_D ∫_0^R r^{D-1} (e^{-r²/h²} − C0) dr, by composite Simpson (error ≪ 1e-12).
                let n = 4000;
                let dr = support / n as f64;
                let f = |r: f64| r.powi(D as i32 - 1) * ((-(r * r) * inv_h2).exp() - shift);
                let mut s = f(0.0) + f(support);
                for k in 1..n {
                    let w = if k % 2 == 1 { 4.0 } else { 2.0 };
                    s += w * f(k as f64 * dr);
                }
                let integral = s * dr / 3.0;
                Kernel {
                    kind,
                    h,
                    support,
                    norm: 1.0 / (unit_sphere_surface(D) * integral),
                    shift,
                    inv_h2,
                }
            }
            KernelKind::WendlandC2 => {
                let a = match D {
                    1 => 3.0 / (4.0 * h),
                    2 => 7.0 / (4.0 * std::f64::consts::PI * h * h),
                    3 => 21.0 / (16.0 * std::f64::consts::PI * h * h * h),
                    _ => panic!("kernel: dimension {D} is not supported"),
                };
                Kernel {
                    kind,
                    h,
                    support,
                    norm: a,
                    shift: 0.0,
                    inv_h2,
                }
            }
        }
    }

    /// W(r) (1/m^D).
    #[inline]
    pub fn w(&self, r: f64) -> f64 {
        if r >= self.support {
            return 0.0;
        }
        match self.kind {
            KernelKind::RenormalizedGaussian => self.norm * ((-(r * r) * self.inv_h2).exp() - self.shift),
            KernelKind::WendlandC2 => {
                let q = r / self.h;
                let t = 1.0 - 0.5 * q;
                self.norm * t * t * t * t * (2.0 * q + 1.0)
            }
        }
    }

    /// dW/dr (1/m^{D+1}); ≤ 0 inside the support.
    #[inline]
    pub fn dw_dr(&self, r: f64) -> f64 {
        if r >= self.support {
            return 0.0;
        }
        match self.kind {
            KernelKind::RenormalizedGaussian => -2.0 * r * self.inv_h2 * self.norm * (-(r * r) * self.inv_h2).exp(),
            KernelKind::WendlandC2 => {
                let q = r / self.h;
                let t = 1.0 - 0.5 * q;
                -5.0 * q * t * t * t * self.norm / self.h
            }
        }
    }

    /// F(r²) = (dW/dr)/r (1/m^{D+2}), so that ∇_i W_ij = r_ij F(|r_ij|²): the form the gather loops use.
    /// For the Gaussian it needs no square root and no division; zero outside the support.
    #[inline]
    pub fn grad_factor(&self, r2: f64) -> f64 {
        if r2 >= self.support * self.support {
            return 0.0;
        }
        match self.kind {
            KernelKind::RenormalizedGaussian => -2.0 * self.inv_h2 * self.norm * (-r2 * self.inv_h2).exp(),
            KernelKind::WendlandC2 => {
                let t = 1.0 - 0.5 * r2.sqrt() / self.h;
                -5.0 * t * t * t * self.norm * self.inv_h2
            }
        }
    }

    /// ∇_i W_ij for r_ij = r_i − r_j with |r_ij| = r (zero at r = 0).
    #[inline]
    pub fn grad(&self, rij: &SVector<f64, D>, r: f64) -> SVector<f64, D> {
        if r <= 1e-14 * self.h {
            return SVector::zeros();
        }
        rij * (self.dw_dr(r) / r)
    }

    /// ([`Kernel::w`], [`Kernel::grad`]) to the bit, the Gaussian's exponential taken once.
    #[inline]
    pub fn w_and_grad(&self, rij: &SVector<f64, D>, r: f64) -> (f64, SVector<f64, D>) {
        match self.kind {
            KernelKind::RenormalizedGaussian if r < self.support => {
                let e = (-(r * r) * self.inv_h2).exp();
                let grad = if r <= 1e-14 * self.h {
                    SVector::zeros()
                } else {
                    rij * (-2.0 * r * self.inv_h2 * self.norm * e / r)
                };
                (self.norm * (e - self.shift), grad)
            }
            _ => (self.w(r), self.grad(rij, r)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn w_and_grad_are_w_and_grad_to_the_bit() {
        for kind in [KernelKind::RenormalizedGaussian, KernelKind::WendlandC2] {
            let k = Kernel::<2>::new(kind, 0.013);
            for n in 0..=400 {
                let r = k.support * 1.1 * n as f64 / 400.0;
                let rij = SVector::<f64, 2>::new(-0.6 * r, 0.8 * r);
                let r = rij.norm();
                let (w, g) = k.w_and_grad(&rij, r);
                assert_eq!(w.to_bits(), k.w(r).to_bits(), "{kind:?} W at r = {r}");
                let g0 = k.grad(&rij, r);
                assert!(
                    (0..2).all(|d| g[d].to_bits() == g0[d].to_bits()),
                    "{kind:?} grad at r = {r}"
                );
            }
        }
    }

    fn integrate_2d(k: &Kernel<2>, dx: f64) -> f64 {
        let n = (k.support / dx).ceil() as i64 + 1;
        let mut s = 0.0;
        for i in -n..=n {
            for j in -n..=n {
                let r = ((i as f64 + 0.5) * dx).hypot((j as f64 + 0.5) * dx);
                s += k.w(r) * dx * dx;
            }
        }
        s
    }

    #[test]
    fn kernels_integrate_to_one_in_2d_and_3d() {
        for kind in [KernelKind::RenormalizedGaussian, KernelKind::WendlandC2] {
            let k2 = Kernel::<2>::new(kind, 0.1);
            assert!((integrate_2d(&k2, 0.002) - 1.0).abs() < 1e-6, "{kind:?} 2D");
            // 3D: radial quadrature of 4π ∫ r² W dr.
            let k3 = Kernel::<3>::new(kind, 0.1);
            let n = 20000;
            let dr = k3.support / n as f64;
            let s: f64 = (0..n)
                .map(|i| {
                    let r = (i as f64 + 0.5) * dr;
                    4.0 * std::f64::consts::PI * r * r * k3.w(r) * dr
                })
                .sum();
            assert!((s - 1.0).abs() < 1e-6, "{kind:?} 3D: {s}");
        }
    }

    #[test]
    fn kernels_have_compact_support() {
        for kind in [KernelKind::RenormalizedGaussian, KernelKind::WendlandC2] {
            let k = Kernel::<2>::new(kind, 0.1);
            assert_eq!(k.w(k.support), 0.0);
            assert_eq!(k.w(k.support * 1.5), 0.0);
            assert_eq!(k.dw_dr(k.support * 1.01), 0.0);
            // Continuous at the cut: the value just inside is tiny compared with the peak.
            assert!(k.w(k.support * 0.999_999) < 1e-5 * k.w(0.0));
            assert!(k.w(0.0) > 0.0);
        }
    }

    #[test]
    fn grad_factor_times_r_is_dw_dr() {
        for kind in [KernelKind::RenormalizedGaussian, KernelKind::WendlandC2] {
            let k = Kernel::<2>::new(kind, 0.1);
            for i in 1..300 {
                let r = k.support * i as f64 / 300.0;
                let a = k.grad_factor(r * r) * r;
                assert!((a - k.dw_dr(r)).abs() <= 1e-12 * k.w(0.0) / k.h, "{kind:?} at r = {r}");
            }
            assert_eq!(k.grad_factor(k.support * k.support), 0.0);
        }
    }

    #[test]
    fn kernel_gradient_matches_finite_differences() {
        for kind in [KernelKind::RenormalizedGaussian, KernelKind::WendlandC2] {
            let k = Kernel::<2>::new(kind, 0.1);
            let eps = 1e-7;
            for &(x, y) in &[(0.03, 0.01), (0.1, -0.05), (-0.15, 0.12), (0.0, 0.2)] {
                let v = SVector::<f64, 2>::new(x, y);
                let g = k.grad(&v, v.norm());
                let fx = (k.w((x + eps).hypot(y)) - k.w((x - eps).hypot(y))) / (2.0 * eps);
                let fy = (k.w(x.hypot(y + eps)) - k.w(x.hypot(y - eps))) / (2.0 * eps);
                let scale = k.w(0.0) / k.h;
                assert!((g[0] - fx).abs() < 1e-6 * scale, "{kind:?} dx at ({x},{y})");
                assert!((g[1] - fy).abs() < 1e-6 * scale, "{kind:?} dy at ({x},{y})");
            }
        }
    }
}
