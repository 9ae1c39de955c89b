//! Equations of state p(ρ) for the weakly-compressible fluid (thesis §3.5).

use serde::{Deserialize, Serialize};

/// Which state equation to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum EosKind {
    /// p = c0² (ρ − ρ0), thesis eq. (3.54): the default, since c varies by < 1 % at Ma ≤ 0.1.
    #[default]
    Linear,
    /// Tait: p = (ρ0 c0²/γ) [(ρ/ρ0)^γ − 1] (thesis eq. 3.49), γ = [`Eos::gamma`] (7 for water).
    Tait,
}

/// A state equation with its constants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Eos {
    pub kind: EosKind,
    /// Reference density ρ0 (kg/m³), the density at p = 0.
    pub rho0: f64,
    /// Speed of sound at ρ0 (m/s).
    pub c0: f64,
    /// The Tait exponent γ, dimensionless (ignored by the linear law): 7 for water (thesis eq. 3.49), 1.4 for
    /// air as a multi-fluid phase (Hammani et al., eq. 23; Grenier et al. §4.2).
    pub gamma: f64,
}

/// γ of the Tait law for water (thesis eq. 3.49).
pub const TAIT_GAMMA_WATER: f64 = 7.0;

impl Eos {
    pub fn pressure(&self, rho: f64) -> f64 {
        match self.kind {
            EosKind::Linear => self.c0 * self.c0 * (rho - self.rho0),
            EosKind::Tait => self.rho0 * self.c0 * self.c0 / self.gamma * ((rho / self.rho0).powf(self.gamma) - 1.0),
        }
    }

    /// Inverse of [`Eos::pressure`] (used for the ghost particles' density).
    pub fn density(&self, p: f64) -> f64 {
        match self.kind {
            EosKind::Linear => self.rho0 + p / (self.c0 * self.c0),
            EosKind::Tait => {
                let base = (1.0 + self.gamma * p / (self.rho0 * self.c0 * self.c0)).max(1e-6);
                self.rho0 * base.powf(1.0 / self.gamma)
            }
        }
    }

    /// The law's exponent: γ for Tait, 1 for the linear law (p = ρ0c0²(ρ/ρ0 − 1)).
    pub fn exponent(&self) -> f64 {
        match self.kind {
            EosKind::Linear => 1.0,
            EosKind::Tait => self.gamma,
        }
    }

    /// The stiffness B = ρ0 c0² / exponent (Pa), the constant in front of the law.
    pub fn stiffness(&self) -> f64 {
        self.rho0 * self.c0 * self.c0 / self.exponent()
    }

    /// Speed of sound c(ρ) (m/s).
    pub fn sound_speed(&self, rho: f64) -> f64 {
        match self.kind {
            EosKind::Linear => self.c0,
            EosKind::Tait => self.c0 * (rho / self.rho0).powf(0.5 * (self.gamma - 1.0)),
        }
    }

    /// dρ/dp at density ρ (s²/m²).
    pub fn drho_dp(&self, rho: f64) -> f64 {
        let c = self.sound_speed(rho);
        1.0 / (c * c)
    }

    /// Elastic (compressible) energy per unit mass e(ρ) = ∫_{ρ0}^{ρ} p/ρ² dρ (J/kg).
    pub fn elastic_energy(&self, rho: f64) -> f64 {
        let c2 = self.c0 * self.c0;
        match self.kind {
            EosKind::Linear => c2 * ((rho / self.rho0).ln() + self.rho0 / rho - 1.0),
            EosKind::Tait => {
                let b = self.rho0 * c2 / self.gamma;
                b * (((rho / self.rho0).powf(self.gamma - 1.0) - 1.0) / (self.rho0 * (self.gamma - 1.0)) + 1.0 / rho
                    - 1.0 / self.rho0)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn density_inverts_pressure() {
        for kind in [EosKind::Linear, EosKind::Tait] {
            let e = Eos {
                kind,
                rho0: 1000.0,
                c0: 30.0,
                gamma: TAIT_GAMMA_WATER,
            };
            for rho in [990.0, 1000.0, 1013.0] {
                assert!((e.density(e.pressure(rho)) - rho).abs() < 1e-9);
            }
        }
    }

    #[test]
    fn elastic_energy_is_integral_of_p_over_rho_squared() {
        for kind in [EosKind::Linear, EosKind::Tait] {
            let e = Eos {
                kind,
                rho0: 1000.0,
                c0: 30.0,
                gamma: TAIT_GAMMA_WATER,
            };
            let (a, b, n) = (1000.0, 1020.0, 2000);
            let d = (b - a) / n as f64;
            let s: f64 = (0..n)
                .map(|k| {
                    let r = a + (k as f64 + 0.5) * d;
                    e.pressure(r) / (r * r) * d
                })
                .sum();
            assert!((s - e.elastic_energy(b)).abs() < 1e-6 * s.abs());
        }
    }
}
