//! Body forces per unit mass.

use nalgebra::SVector;

/// A body force field per unit mass (m/s²).
#[derive(Clone, Copy, Debug)]
pub enum BodyForce<const D: usize> {
    /// Uniform gravity g (m/s²), e.g. (0, −9.81).
    Uniform(SVector<f64, D>),
    /// Central (harmonic) force −Ω² (x − centre) of Monaghan & Rafiee's oscillating drop; Ω in 1/s.
    Central { omega: f64, centre: SVector<f64, D> },
}

impl<const D: usize> BodyForce<D> {
    #[inline]
    pub fn acceleration(&self, x: &SVector<f64, D>) -> SVector<f64, D> {
        match self {
            BodyForce::Uniform(g) => *g,
            BodyForce::Central { omega, centre } => -(omega * omega) * (x - centre),
        }
    }

    /// Potential per unit mass φ with acceleration = −∇φ (J/kg), zero at the origin (or centre).
    #[inline]
    pub fn potential(&self, x: &SVector<f64, D>) -> f64 {
        match self {
            BodyForce::Uniform(g) => -g.dot(x),
            BodyForce::Central { omega, centre } => 0.5 * omega * omega * (x - centre).norm_squared(),
        }
    }
}
