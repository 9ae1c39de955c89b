//! Free-surface detection of Marrone et al. (2010), thesis §7.2.1, generic over D.
//!
//! Step 1: the minimum eigenvalue λ of B⁻¹ = Σ_j ∇W_ij ⊗ (r_j − r_i) V_j (7.21) sorts the particles into
//! E (λ ≤ 0.20: jets and drops, free surface outright), I (λ > 0.75: interior) and B (in between), eq. (7.22).
//! Step 2, for B only: the normal n = ξ/|ξ|, ξ = −B Σ_j ∇W_ij V_j (7.23), and the scan region of eq. (7.24)
//! (a half disc of radius h centred at T = r_i + h n for neighbours at |r_ji| ≥ √2 h, a square rotated
//! by 45° of half-diagonal h about T for the closer ones): a particle is on the free surface when no
//! neighbour lies in the scan region.
//!
//! The thresholds hold for the renormalised Gaussian with h = 1.33 dx (thesis); for other kernels they must
//! be recalibrated. Ghost particles take part with their volumes, so that the fluid next to a wall is not
//! mistaken for free surface.

use super::kernel::Kernel;
use super::neighbours::CellList;
use nalgebra::{SMatrix, SVector};
use rayon::prelude::*;

/// Thresholds of eq. (7.22).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Thresholds {
    /// λ at or below which a particle is free surface outright (jets, drops). Thesis: 0.20.
    pub lower: f64,
    /// λ above which a particle is interior. Thesis: 0.75.
    pub upper: f64,
}

impl Default for Thresholds {
    fn default() -> Self {
        Thresholds {
            lower: 0.20,
            upper: 0.75,
        }
    }
}

/// The result for every fluid particle.
#[derive(Clone, Debug, Default)]
pub struct FreeSurface<const D: usize> {
    /// Minimum eigenvalue of B⁻¹ (7.21).
    pub lambda: Vec<f64>,
    pub on_surface: Vec<bool>,
    /// Outward unit normal (7.23); zero where B⁻¹ is singular (isolated particles) or far inside.
    pub normal: Vec<SVector<f64, D>>,
}

/// Detects the free-surface particles among the first `n_fluid` entries of `pos`; `pos` also holds the
/// ghosts (or any other particles that count as matter), `volume[j]` is each particle's volume, `cells` the
/// cell list over `pos` with cell ≥ the kernel support.
pub fn detect<const D: usize>(
    kernel: &Kernel<D>,
    cells: &CellList<D>,
    pos: &[SVector<f64, D>],
    volume: &[f64],
    n_fluid: usize,
    th: Thresholds,
) -> FreeSurface<D> {
    let h = kernel.h;
    let out: Vec<(f64, bool, SVector<f64, D>)> = (0..n_fluid)
        .into_par_iter()
        .map(|i| {
            let mut sums = SurfaceSums::<D>::new();
            cells.for_each_within(pos, &pos[i], kernel.support, |j, rij, r| {
                if j == i || volume[j] == 0.0 {
                    return;
                }
                sums.add(&kernel.grad(&rij, r), &rij, volume[j]);
            });
            let (lambda, normal) = sums.lambda_and_normal();
            let surface = if lambda <= th.lower {
                true
            } else if lambda > th.upper {
                false
            } else if normal.norm_squared() == 0.0 {
                true
            } else {
                scan_region_empty(cells, pos, volume, i, &normal, h, kernel.support)
            };
            (lambda, surface, normal)
        })
        .collect();
    FreeSurface {
        lambda: out.iter().map(|o| o.0).collect(),
        on_surface: out.iter().map(|o| o.1).collect(),
        normal: out.iter().map(|o| o.2).collect(),
    }
}

/// The sums of one particle's neighbours that §7.2 reads: B⁻¹ = Σ_j ∇W_ij ⊗ (r_j − r_i) V_j (7.21) and
/// s = Σ_j ∇W_ij V_j (7.23).
pub struct SurfaceSums<const D: usize> {
    m: SMatrix<f64, D, D>,
    s: SVector<f64, D>,
}

impl<const D: usize> SurfaceSums<D> {
    pub fn new() -> Self {
        SurfaceSums {
            m: SMatrix::zeros(),
            s: SVector::zeros(),
        }
    }

    /// Adds neighbour j: its kernel gradient ∇_i W_ij, r_ij = r_i − r_j and volume V_j.
    #[inline]
    pub fn add(&mut self, grad_w: &SVector<f64, D>, r_ij: &SVector<f64, D>, v_j: f64) {
        self.m += grad_w * (-r_ij).transpose() * v_j;
        self.s += grad_w * v_j;
    }

    /// λ, the minimum eigenvalue of B⁻¹ (its symmetric part), and the outward normal ξ/|ξ|, ξ = −B s (7.23);
    /// the normal is zero where B⁻¹ is singular.
    pub fn lambda_and_normal(&self) -> (f64, SVector<f64, D>) {
        let sym = (self.m + self.m.transpose()) * 0.5;
        let lambda = min_eigenvalue(&sym);
        let normal = match self.m.try_inverse() {
            Some(b) if lambda > 1e-6 => {
                let xi = -(b * self.s);
                let n = xi.norm();
                if n > 0.0 {
                    xi / n
                } else {
                    SVector::zeros()
                }
            }
            _ => SVector::zeros(),
        };
        (lambda, normal)
    }
}

impl<const D: usize> Default for SurfaceSums<D> {
    fn default() -> Self {
        Self::new()
    }
}

/// Smallest eigenvalue of a symmetric D×D matrix (closed form in 2D, nalgebra's dynamic solver otherwise).
fn min_eigenvalue<const D: usize>(a: &SMatrix<f64, D, D>) -> f64 {
    if D == 2 {
        let (p, q, r) = (a[(0, 0)], a[(1, 1)], a[(0, 1)]);
        let mean = 0.5 * (p + q);
        let dev = (0.25 * (p - q) * (p - q) + r * r).sqrt();
        return mean - dev;
    }
    nalgebra::DMatrix::from_iterator(D, D, a.iter().copied())
        .symmetric_eigenvalues()
        .min()
}

/// Eq. (7.24): true when no neighbour of i lies in the scan region in the direction n.
fn scan_region_empty<const D: usize>(
    cells: &CellList<D>,
    pos: &[SVector<f64, D>],
    volume: &[f64],
    i: usize,
    n: &SVector<f64, D>,
    h: f64,
    support: f64,
) -> bool {
    let t = pos[i] + n * h;
    let mut empty = true;
    cells.for_each_within(pos, &pos[i], support, |j, _, r| {
        if !empty || j == i || volume[j] == 0.0 {
            return;
        }
        let r_jt = pos[j] - t;
        let inside = if r >= std::f64::consts::SQRT_2 * h {
            r_jt.norm() < h
        } else {
            let along = n.dot(&r_jt);
            let across = (r_jt - n * along).norm();
            along.abs() + across < h
        };
        if inside {
            empty = false;
        }
    });
    empty
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::kernel::KernelKind;
    use nalgebra::Vector2;

    /// A square block of lattice particles: the top row is surface, the rows below are not.
    #[test]
    fn top_row_of_a_lattice_is_surface_and_the_second_is_not() {
        let dx = 1.0;
        let kernel = Kernel::<2>::new(KernelKind::RenormalizedGaussian, 1.33 * dx);
        let mut pos = vec![];
        for i in 0..30 {
            for j in 0..15 {
                pos.push(Vector2::new((i as f64 + 0.5) * dx, (j as f64 + 0.5) * dx));
            }
        }
        let vol = vec![dx * dx; pos.len()];
        let cells = CellList::build(&pos, kernel.support);
        let fs = detect(&kernel, &cells, &pos, &vol, pos.len(), Thresholds::default());
        for (k, p) in pos.iter().enumerate() {
            let inner_x = p.x > 5.0 && p.x < 25.0;
            if inner_x && (p.y - 14.5).abs() < 1e-9 {
                assert!(fs.on_surface[k], "top row particle {p:?} not detected");
                assert!((fs.normal[k] - Vector2::new(0.0, 1.0)).norm() < 1e-6);
            }
            if inner_x && p.y > 5.0 && p.y < 14.0 {
                assert!(!fs.on_surface[k], "particle {p:?} below the top row detected");
                assert!(fs.lambda[k] > 0.75, "interior λ = {}", fs.lambda[k]);
            }
        }
    }
}
