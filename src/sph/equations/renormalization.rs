//! Renormalised gradient, eqs. (4.19)–(4.20): ⟨∇ρ⟩_i^L = B_i Σ_j (ρ_j − ρ_i) ∇_i W_ij V_j,
//! B_i = [Σ_j ∇_i W_ij ⊗ (r_j − r_i) V_j]⁻¹. Exact for linear fields on any particle distribution.

use nalgebra::{SMatrix, SVector};

/// Accumulates the two sums of eqs. (4.19)–(4.20) for one particle.
#[derive(Clone, Copy, Debug)]
pub struct RenormalizedGradient<const D: usize> {
    pub b_inv: SMatrix<f64, D, D>,
    pub sum: SVector<f64, D>,
}

impl<const D: usize> Default for RenormalizedGradient<D> {
    fn default() -> Self {
        Self {
            b_inv: SMatrix::zeros(),
            sum: SVector::zeros(),
        }
    }
}

impl<const D: usize> RenormalizedGradient<D> {
    /// Adds neighbour j: `r_ij` = r_i − r_j, `df` = f_j − f_i.
    #[inline]
    pub fn add(&mut self, grad_w: &SVector<f64, D>, r_ij: &SVector<f64, D>, df: f64, v_j: f64) {
        self.b_inv -= grad_w * r_ij.transpose() * v_j; // ∇W ⊗ (r_j − r_i) V_j
        self.sum += grad_w * (df * v_j);
    }

    /// The gradient; zero where B_i⁻¹ is singular (an isolated particle: det below 1e-6 of a full
    /// neighbourhood's, which is 1 in the continuum limit).
    pub fn gradient(&self) -> SVector<f64, D> {
        match invert_small(&self.b_inv, 1e-6) {
            Some(b) => b * self.sum,
            None => SVector::zeros(),
        }
    }
}

/// Inverse of a 1×1, 2×2 or 3×3 matrix by cofactors; `None` if |det| < `min_det`.
pub fn invert_small<const D: usize>(m: &SMatrix<f64, D, D>, min_det: f64) -> Option<SMatrix<f64, D, D>> {
    let mut inv = SMatrix::<f64, D, D>::zeros();
    match D {
        1 => {
            let det = m[(0, 0)];
            if det.abs() < min_det {
                return None;
            }
            inv[(0, 0)] = 1.0 / det;
        }
        2 => {
            let det = m[(0, 0)] * m[(1, 1)] - m[(0, 1)] * m[(1, 0)];
            if det.abs() < min_det {
                return None;
            }
            inv[(0, 0)] = m[(1, 1)] / det;
            inv[(1, 1)] = m[(0, 0)] / det;
            inv[(0, 1)] = -m[(0, 1)] / det;
            inv[(1, 0)] = -m[(1, 0)] / det;
        }
        3 => {
            let c = |r: usize, k: usize| {
                let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
                let (k1, k2) = ((k + 1) % 3, (k + 2) % 3);
                m[(r1, k1)] * m[(r2, k2)] - m[(r1, k2)] * m[(r2, k1)]
            };
            let det = m[(0, 0)] * c(0, 0) + m[(0, 1)] * c(0, 1) + m[(0, 2)] * c(0, 2);
            if det.abs() < min_det {
                return None;
            }
            for r in 0..3 {
                for k in 0..3 {
                    inv[(k, r)] = c(r, k) / det;
                }
            }
        }
        _ => return None,
    }
    Some(inv)
}
