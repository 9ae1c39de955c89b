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

    /// Default CFL, from the limits measured on the dam break at H/dx = 20 (docs/reference/method.md): RK4 stays
    /// stable up to CFL 3 (at 4 the step is force-limited 40 % of the time), so 2.0 keeps a 1.5× margin and
    /// stays below the thesis's 2.5; the predictor–corrector starts to create energy at CFL 1.0–1.5 and
    /// blows up from 2.5, so 0.5 (the thesis uses 0.3).
    pub fn default_cfl(self) -> f64 {
        match self {
            Integrator::Rk4 => 2.0,
            Integrator::PredictorCorrector => 0.5,
        }
    }
}
