//! Numerical diffusion of density in the continuity equation: δ c0 h Σ_j ψ_ij·∇_i W_ij V_j (eq. 5.1).

use nalgebra::SVector;
use serde::{Deserialize, Serialize};

/// Which diffusive term ψ_ij to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum DensityDiffusion {
    /// Standard weakly-compressible SPH: no diffusion (δ ignored).
    None,
    /// Molteni & Colagrossi (2009), eq. (5.4): ψ_ij = 2(ρ_j − ρ_i) r_ji/|r_ij|². Does not preserve the
    /// hydrostatic solution near the free surface (Antuono et al. 2010).
    MolteniColagrossi,
    /// δ-SPH, eq. (5.2): ψ_ij = 2(ρ_j − ρ_i) r_ji/|r_ij|² − (⟨∇ρ⟩_i^L + ⟨∇ρ⟩_j^L), with the renormalised
    /// gradients of eqs. (4.19)–(4.20). The default.
    #[default]
    DeltaSph,
}

impl std::str::FromStr for DensityDiffusion {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "none" => Ok(Self::None),
            "molteni-colagrossi" => Ok(Self::MolteniColagrossi),
            "delta-sph" => Ok(Self::DeltaSph),
            v => Err(format!(
                "expected `delta-sph`, `molteni-colagrossi` or `none`, got `{v}`"
            )),
        }
    }
}

impl std::fmt::Display for DensityDiffusion {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::None => "none",
            Self::MolteniColagrossi => "molteni-colagrossi",
            Self::DeltaSph => "delta-sph",
        })
    }
}

impl DensityDiffusion {
    /// Whether the renormalised density gradient must be computed.
    pub fn needs_gradient(self) -> bool {
        self == DensityDiffusion::DeltaSph
    }
}

/// ψ_ij (kg/m⁴) for r_ij = r_i − r_j; `grad_i`, `grad_j` are ⟨∇ρ⟩^L (ignored unless δ-SPH).
#[inline]
pub fn psi<const D: usize>(
    kind: DensityDiffusion,
    rho_i: f64,
    rho_j: f64,
    r_ij: &SVector<f64, D>,
    r2: f64,
    grad_i: &SVector<f64, D>,
    grad_j: &SVector<f64, D>,
) -> SVector<f64, D> {
    psi_with_factor(kind, 2.0, rho_i, rho_j, r_ij, r2, grad_i, grad_j)
}

/// ψ_ij with `factor` in place of the 2 of (ρ_j − ρ_i) r_ji/|r_ij|²: the volume form of the multi-fluid model
/// offers eq. (20) of Hammani et al. as printed (factor 1) beside the mapped δ-SPH term (2).
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn psi_with_factor<const D: usize>(
    kind: DensityDiffusion,
    factor: f64,
    rho_i: f64,
    rho_j: f64,
    r_ij: &SVector<f64, D>,
    r2: f64,
    grad_i: &SVector<f64, D>,
    grad_j: &SVector<f64, D>,
) -> SVector<f64, D> {
    let r_ji = -r_ij;
    match kind {
        DensityDiffusion::None => SVector::zeros(),
        DensityDiffusion::MolteniColagrossi => r_ji * (factor * (rho_j - rho_i) / r2),
        DensityDiffusion::DeltaSph => r_ji * (factor * (rho_j - rho_i) / r2) - (grad_i + grad_j),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn delta_sph_term_vanishes_for_a_linear_density_field() {
        let g = SVector::<f64, 2>::new(0.3, -9.0);
        let ri = SVector::<f64, 2>::new(0.1, 0.2);
        let rj = SVector::<f64, 2>::new(0.13, 0.17);
        let rho = |r: &SVector<f64, 2>| 1000.0 + g.dot(r);
        let rij = ri - rj;
        let p = psi(
            DensityDiffusion::DeltaSph,
            rho(&ri),
            rho(&rj),
            &rij,
            rij.norm_squared(),
            &g,
            &g,
        );
        // Its projection on r_ij (the only part that meets ∇W) vanishes.
        assert!(p.dot(&rij).abs() < 1e-12);
        let pm = psi(
            DensityDiffusion::MolteniColagrossi,
            rho(&ri),
            rho(&rj),
            &rij,
            rij.norm_squared(),
            &g,
            &g,
        );
        assert!(pm.dot(&rij).abs() > 1e-3);
    }
}
