//! The level-set function of thesis appendix B on a regular grid.
//!
//! For a node N, with F_N its nearest free-surface particle among those within 2h (B.3):
//! * no particle within 2h: φ = −1 (outside the fluid);
//! * particles within 2h but none on the free surface: φ = +1 (inside);
//! * otherwise d = (r_F − r_N)·n_F (B.1) and φ = clamp(d / 2h, −1, 1) (B.2). For an isolated particle
//!   (λ_F < 0.1, no normal) the thesis substitutes the distance |r_N − r_F|; we use d = dx/2 − |r_N − r_F|
//!   so that a lone drop is a small disc of fluid rather than a disc of "inside" of radius 2h (our choice).
//!
//! φ > 0 in the fluid; the free surface, half a spacing beyond the free-surface particles, is the contour
//! φ = −dx/(4h). The Gaussian filter of the thesis is not applied (our choice: the cavity search below
//! needs the unfiltered sign, and contours are drawn from the raw field).

use super::snapshot::{Snapshot, V2};

/// φ on a regular grid of nodes origin + (i, j)·spacing, i along y, j along z.
#[derive(Clone, Debug)]
pub struct LevelSet {
    pub origin: V2,
    pub spacing: f64,
    pub ny: usize,
    pub nz: usize,
    /// φ at node (i, j) is `phi[j * ny + i]`.
    pub phi: Vec<f64>,
    /// The level of the free surface, −dx/(4h).
    pub surface_level: f64,
}

impl LevelSet {
    pub fn node(&self, i: usize, j: usize) -> V2 {
        self.origin + V2::new(i as f64, j as f64) * self.spacing
    }
    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.phi[j * self.ny + i]
    }
    /// Whether node (i, j) is air (φ below the free-surface level).
    pub fn is_air(&self, i: usize, j: usize) -> bool {
        self.at(i, j) < self.surface_level
    }
}

/// Computes φ over the box [lo, hi] with the given node spacing.
pub fn level_set(s: &Snapshot, lo: V2, hi: V2, spacing: f64) -> LevelSet {
    use rayon::prelude::*;
    let ny = ((hi.x - lo.x) / spacing).floor() as usize + 1;
    let nz = ((hi.y - lo.y) / spacing).floor() as usize + 1;
    let r2h = 2.0 * s.h;
    let cells = s.cells(r2h);
    let phi: Vec<f64> = (0..ny * nz)
        .into_par_iter()
        .map(|k| {
            let (i, j) = (k % ny, k / ny);
            let x = lo + V2::new(i as f64, j as f64) * spacing;
            let mut any = false;
            let mut best: Option<(f64, usize)> = None;
            cells.for_each_within(&s.pos, &x, r2h, |p, _, r| {
                any = true;
                if s.on_surface[p] && best.is_none_or(|b| r < b.0) {
                    best = Some((r, p));
                }
            });
            match (any, best) {
                (false, _) => -1.0,
                (true, None) => 1.0,
                (true, Some((r, f))) => {
                    let n = s.normal[f];
                    let d = if s.lambda[f] < 0.1 || n.norm_squared() == 0.0 {
                        0.5 * s.dx - r
                    } else {
                        (s.pos[f] - x).dot(&n)
                    };
                    (d / r2h).clamp(-1.0, 1.0)
                }
            }
        })
        .collect();
    LevelSet {
        origin: lo,
        spacing,
        ny,
        nz,
        phi,
        surface_level: -s.dx / (4.0 * s.h),
    }
}
