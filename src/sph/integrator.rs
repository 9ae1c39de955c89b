//! Time integrators and their default CFL numbers (for Δt of eq. 4.22).

use serde::{Deserialize, Serialize};

/// Which explicit scheme advances (r, u, ρ).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, Default)]
#[serde(rename_all = "kebab-case")]
pub enum Integrator {
    /// Classical 4th-order Runge–Kutta, 4 right-hand-side evaluations per step. The default.
    #[default]
    Rk4,
    /// Predictor–corrector (modified Euler) of thesis §4.2, 2 evaluations per step.
    PredictorCorrector,
}

impl Integrator {
    /// Right-hand-side evaluations per time step.
    pub fn stages(self) -> usize {
        match self {
            Integrator::Rk4 => 4,
            Integrator::PredictorCorrector => 2,
        }
    }

    /// Default CFL: chosen from the stability limits measured on the dam break (see docs/method.md):
    /// about 0.8 of the largest stable value.
    pub fn default_cfl(self) -> f64 {
        match self {
            Integrator::Rk4 => 1.5,
            Integrator::PredictorCorrector => 0.3,
        }
    }
}
