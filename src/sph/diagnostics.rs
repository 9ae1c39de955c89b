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

/// Free-surface elevation at abscissa `x` (axis 0): the highest particle within one particle spacing dx of
/// it, plus dx/2. `None` if there is no particle there. The window is 2dx wide so that it always holds a
/// whole column of particles: columns drift and tilt as the fluid moves, and a window of width dx caught
/// only the lower part of a sheared column (a drop of four particles in one sample on the Martin–Moyce
/// column at a/dx = 25). On a sloping surface the window reads high by at most slope × dx.
pub fn gauge<const D: usize>(fluid: &Fluid<D>, x: f64, dx: f64) -> Option<f64> {
    let top = fluid
        .pos
        .iter()
        .filter(|p| (p[0] - x).abs() <= dx)
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

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector2;

    /// A block whose top row is stretched (columns 1.25 dx apart, as a surface is when the fluid spreads):
    /// between two top particles there is a gap wider than dx. The gauge must still read the top row
    /// (10 dx) wherever it is put; a window of width dx read the row below in the gaps (the Martin–Moyce
    /// column-height drop).
    #[test]
    fn gauge_reads_the_top_row_in_the_gaps_of_a_stretched_surface() {
        let dx = 0.01;
        let mut f = Fluid::<2>::default();
        for row in 0..10 {
            let spacing = if row == 9 { 1.25 } else { 1.0 };
            for c in 0..20 {
                let x = (c as f64 * spacing + 0.5) * dx;
                f.push(
                    Vector2::new(x, (row as f64 + 0.5) * dx),
                    Vector2::zeros(),
                    1000.0,
                    0.1,
                    0.0,
                );
            }
        }
        for k in 0..40 {
            let x = (5.0 + 0.25 * k as f64) * dx;
            let eta = gauge(&f, x, dx).expect("particles under the gauge");
            assert!(
                (eta - 10.0 * dx).abs() < 1e-12,
                "gauge at x/dx = {} reads {}",
                x / dx,
                eta / dx
            );
        }
    }
}
