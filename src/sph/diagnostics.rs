//! Integral diagnostics of the fluid: energies, extents, second moments. Sequential sums, so the result does
//! not depend on the thread count.

use super::body_force::BodyForce;
use super::eos::Eos;
use super::particles::Fluid;
use nalgebra::SVector;

/// Kinetic, potential and elastic (compressible) energy (J, or J per unit depth in 2D).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Energies {
    pub kinetic: f64,
    pub potential: f64,
    pub elastic: f64,
}

impl Energies {
    /// Mechanical energy E_K + E_P + E_C.
    pub fn mechanical(&self) -> f64 {
        self.kinetic + self.potential + self.elastic
    }
}

pub fn energies<const D: usize>(fluid: &Fluid<D>, eos: &Eos, body: &BodyForce<D>) -> Energies {
    let mut e = Energies::default();
    for i in 0..fluid.len() {
        let m = fluid.mass[i];
        e.kinetic += 0.5 * m * fluid.vel[i].norm_squared();
        e.potential += m * body.potential(&fluid.pos[i]);
        e.elastic += m * eos.elastic_energy(fluid.rho[i]);
    }
    e
}

/// Largest coordinate `axis` over the fluid, plus half a particle spacing (the particle's own extent).
pub fn front<const D: usize>(fluid: &Fluid<D>, axis: usize, dx: f64) -> f64 {
    fluid.pos.iter().map(|p| p[axis]).fold(f64::NEG_INFINITY, f64::max) + 0.5 * dx
}

/// Free-surface elevation at abscissa `x` (axis 0): the highest particle within dx/2 of it, plus dx/2.
/// `None` if there is no particle in that column.
pub fn gauge<const D: usize>(fluid: &Fluid<D>, x: f64, dx: f64) -> Option<f64> {
    let top = fluid
        .pos
        .iter()
        .filter(|p| (p[0] - x).abs() <= 0.5 * dx)
        .map(|p| p[D - 1])
        .fold(f64::NEG_INFINITY, f64::max);
    top.is_finite().then_some(top + 0.5 * dx)
}

/// Volume-weighted centroid and second central moments ⟨(x_d − x̄_d)²⟩ of the fluid.
pub fn moments<const D: usize>(fluid: &Fluid<D>) -> (SVector<f64, D>, SVector<f64, D>) {
    let mut vol = 0.0;
    let mut c = SVector::<f64, D>::zeros();
    for i in 0..fluid.len() {
        let v = fluid.mass[i] / fluid.rho[i];
        vol += v;
        c += fluid.pos[i] * v;
    }
    c /= vol;
    let mut m2 = SVector::<f64, D>::zeros();
    for i in 0..fluid.len() {
        let v = fluid.mass[i] / fluid.rho[i];
        let d = fluid.pos[i] - c;
        m2 += d.component_mul(&d) * v;
    }
    (c, m2 / vol)
}
