//! First-order moving-least-squares interpolation at an arbitrary point from fluid particles,
//! thesis eq. (7.6): W^MLS_j = (M⁻¹ e1)·b_j W_j V_j, M = Σ b_j ⊗ b_j W_j V_j, b_j = [1, (x_j − x)/h].
//! Positions are scaled by h so that M is O(1). The same fit also gives the gradient of the field
//! (rows 2..D+1 of M⁻¹), used for the ghosts' density gradient.
//!
//! M is a 4×4 matrix for any D ≤ 3: the unused rows and columns are the identity.
//! Where M is ill-conditioned (a point with too few or one-sided neighbours: det M < 1e-3 M₀₀^{D+1}) the
//! fit falls back to the Shepard average Σ f_j W_j V_j / Σ W_j V_j with zero gradient.

use nalgebra::{Matrix4, SVector, Vector4};

/// Weights of one MLS fit: value f(x) = Σ f_j w_j; gradient ∇f(x) = Σ f_j g_j.
#[derive(Clone, Debug, Default)]
pub struct MlsWeights<const D: usize> {
    pub neighbours: Vec<usize>,
    pub value: Vec<f64>,
    pub gradient: Vec<SVector<f64, D>>,
    /// Whether the first-order fit was used (false: Shepard fallback or no neighbours).
    pub first_order: bool,
}

impl<const D: usize> MlsWeights<D> {
    pub fn is_empty(&self) -> bool {
        self.neighbours.is_empty()
    }
    pub fn interpolate(&self, f: impl Fn(usize) -> f64) -> f64 {
        self.neighbours.iter().zip(&self.value).map(|(&j, w)| f(j) * w).sum()
    }
    pub fn interpolate_vec(&self, f: impl Fn(usize) -> SVector<f64, D>) -> SVector<f64, D> {
        let mut s = SVector::zeros();
        for (&j, w) in self.neighbours.iter().zip(&self.value) {
            s += f(j) * *w;
        }
        s
    }
    pub fn gradient_of(&self, f: impl Fn(usize) -> f64) -> SVector<f64, D> {
        let mut s = SVector::zeros();
        for (&j, g) in self.neighbours.iter().zip(&self.gradient) {
            s += g * f(j);
        }
        s
    }
}

/// Builds the MLS weights at `x` from neighbours given as (index, x − x_j, W_j V_j).
pub fn mls_weights<const D: usize>(h: f64, neighbours: &[(usize, SVector<f64, D>, f64)]) -> MlsWeights<D> {
    assert!(D <= 3);
    let mut out = MlsWeights { first_order: false, ..Default::default() };
    if neighbours.is_empty() {
        return out;
    }
    let b_of = |dx: &SVector<f64, D>| {
        let mut b = Vector4::new(1.0, 0.0, 0.0, 0.0);
        for d in 0..D {
            b[d + 1] = -dx[d] / h; // (x_j − x)/h
        }
        b
    };
    let mut m = Matrix4::<f64>::zeros();
    for (_, dx, wv) in neighbours {
        let b = b_of(dx);
        m += b * b.transpose() * *wv;
    }
    for d in D + 1..4 {
        m[(d, d)] = 1.0;
    }
    let m00 = m[(0, 0)];
    let det = m.determinant();
    let inv = if m00 > 0.0 && det > 1e-3 * m00.powi(D as i32 + 1) { m.try_inverse() } else { None };
    out.neighbours = neighbours.iter().map(|n| n.0).collect();
    match inv {
        Some(inv) => {
            out.first_order = true;
            for (_, dx, wv) in neighbours {
                let b = b_of(dx);
                let c = inv * b * *wv;
                out.value.push(c[0]);
                let mut g = SVector::<f64, D>::zeros();
                for d in 0..D {
                    g[d] = c[d + 1] / h;
                }
                out.gradient.push(g);
            }
        }
        None => {
            let s: f64 = neighbours.iter().map(|n| n.2).sum();
            for (_, _, wv) in neighbours {
                out.value.push(if s > 0.0 { wv / s } else { 0.0 });
                out.gradient.push(SVector::zeros());
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::kernel::{Kernel, KernelKind};

    #[test]
    fn mls_reproduces_linear_fields_even_one_sided() {
        let dx = 0.1;
        let k = Kernel::<2>::new(KernelKind::RenormalizedGaussian, 1.33 * dx);
        // Fluid only at y > 0 (a wall below); evaluate at a mirror point close to the wall.
        let pts: Vec<SVector<f64, 2>> = (0..20)
            .flat_map(|i| (0..10).map(move |j| SVector::from([(i as f64 + 0.5) * dx, (j as f64 + 0.5) * dx])))
            .collect();
        let f = |p: &SVector<f64, 2>| 3.0 + 2.0 * p[0] - 5.0 * p[1];
        let x = SVector::from([1.03, 0.07]);
        let nb: Vec<_> = pts
            .iter()
            .enumerate()
            .filter_map(|(j, p)| {
                let r = (x - p).norm();
                (r < k.support).then(|| (j, x - p, k.w(r) * dx * dx))
            })
            .collect();
        let w = mls_weights::<2>(k.h, &nb);
        assert!(w.first_order);
        assert!((w.interpolate(|j| f(&pts[j])) - f(&x)).abs() < 1e-10);
        let g = w.gradient_of(|j| f(&pts[j]));
        assert!((g[0] - 2.0).abs() < 1e-9 && (g[1] + 5.0).abs() < 1e-9);
    }
}
