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

/// The energies of `fluid`; `eos[k]` is the state equation of phase k (one entry for a single phase).
pub fn energies<const D: usize>(fluid: &Fluid<D>, eos: &[Eos], body: &BodyForce<D>) -> Energies {
    let mut e = Energies::default();
    for i in 0..fluid.len() {
        let m = fluid.mass[i];
        e.kinetic += 0.5 * m * fluid.vel[i].norm_squared();
        e.potential += m * body.potential(&fluid.pos[i]);
        e.elastic += m * eos[fluid.phase[i] as usize].elastic_energy(fluid.rho[i]);
    }
    e
}

/// Largest coordinate `axis` over the fluid, plus half a particle spacing (the particle's own extent).
pub fn front<const D: usize>(fluid: &Fluid<D>, axis: usize, dx: f64) -> f64 {
    fluid.pos.iter().map(|p| p[axis]).fold(f64::NEG_INFINITY, f64::max) + 0.5 * dx
}

/// The tips of the interface between phase 0 (heavy, above) and phase 1 (light, below) along the last axis: the
/// lowest particle of phase 0 minus dx/2 (the spike) and the highest of phase 1 plus dx/2 (the bubble); NaN for
/// a phase with no particle.
pub fn interface_tips<const D: usize>(fluid: &Fluid<D>, dx: f64) -> (f64, f64) {
    let (mut spike, mut bubble) = (f64::INFINITY, f64::NEG_INFINITY);
    for (p, &k) in fluid.pos.iter().zip(&fluid.phase) {
        match k {
            0 => spike = spike.min(p[D - 1]),
            1 => bubble = bubble.max(p[D - 1]),
            _ => {}
        }
    }
    let or_nan = |v: f64| if v.is_finite() { v } else { f64::NAN };
    (or_nan(spike - 0.5 * dx), or_nan(bubble + 0.5 * dx))
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

/// Water level at abscissa `x` (axis 0) for a wave gauge standing on `bottom` (height along the last axis):
/// the particles within dx of x (the [`gauge`] window), sorted by height; with `connected`, only those
/// reached from the bottom without crossing a vertical gap wider than 2 dx (air: spray, a jet above the
/// trough of a breaker), the stack starting within 1.5 dx of the bottom; the level is the top of what is
/// counted plus dx/2. A dry gauge reads `bottom` (zero depth), never NaN.
pub fn water_level<const D: usize>(fluid: &Fluid<D>, x: f64, dx: f64, bottom: f64, connected: bool) -> f64 {
    if !connected {
        return gauge(fluid, x, dx).unwrap_or(bottom);
    }
    let mut z: Vec<f64> = fluid
        .pos
        .iter()
        .filter(|p| (p[0] - x).abs() <= dx)
        .map(|p| p[D - 1])
        .collect();
    if z.is_empty() {
        return bottom;
    }
    z.sort_by(f64::total_cmp);
    if z[0] - bottom > 1.5 * dx {
        return bottom;
    }
    let mut top = z[0];
    for w in z.windows(2) {
        if w[1] - w[0] > 2.0 * dx {
            break;
        }
        top = w[1];
    }
    top + 0.5 * dx
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
    /// Heavy particles (phase 0) down to y 0.4 and light ones (phase 1) up to 1.3, a third phase ignored: the
    /// tips are 0.4 − dx/2 and 1.3 + dx/2; without a light particle the bubble is NaN.
    #[test]
    fn interface_tips_are_the_lowest_heavy_and_highest_light_points() {
        use crate::sph::particles::Fluid;
        let dx = 0.1;
        let mut f = Fluid::<2>::default();
        for (y, k) in [(0.4, 0u8), (1.5, 0), (1.3, 1), (0.1, 1), (2.0, 2), (-1.0, 2)] {
            f.push(
                nalgebra::Vector2::new(0.5, y),
                nalgebra::Vector2::zeros(),
                1.0,
                1.0,
                0.0,
            );
            *f.phase.last_mut().unwrap() = k;
        }
        let (spike, bubble) = super::interface_tips(&f, dx);
        assert!(
            (spike - 0.35).abs() < 1e-12 && (bubble - 1.35).abs() < 1e-12,
            "{spike} {bubble}"
        );
        f.phase.iter_mut().filter(|k| **k == 1).for_each(|k| *k = 0);
        assert!(super::interface_tips(&f, dx).1.is_nan());
    }

    /// A column of water 10 rows deep on a floor at 0, a drop 5 dx above it, an empty stretch beside it:
    /// the connected gauge reads the column, the plain one the drop, the dry one the floor.
    #[test]
    fn gauges_read_connected_water_and_zero_depth_when_dry() {
        use super::water_level;
        use crate::sph::particles::Fluid;
        let dx = 0.01;
        let mut pos = vec![];
        for i in 0..4 {
            for j in 0..10 {
                pos.push(nalgebra::Vector2::new((i as f64 + 0.5) * dx, (j as f64 + 0.5) * dx));
            }
        }
        pos.push(nalgebra::Vector2::new(0.015, 0.15));
        let mut fluid = Fluid::<2>::default();
        for p in pos {
            fluid.push(p, nalgebra::Vector2::zeros(), 1000.0, 0.1, 0.0);
        }
        let connected = water_level(&fluid, 0.02, dx, 0.0, true);
        assert!((connected - 0.10).abs() < 1e-12, "{connected}");
        let plain = water_level(&fluid, 0.02, dx, 0.0, false);
        assert!((plain - 0.155).abs() < 1e-12, "{plain}");
        assert_eq!(water_level(&fluid, 0.5, dx, 0.0, true), 0.0);
        assert_eq!(water_level(&fluid, 0.5, dx, 0.0, false), 0.0);
    }

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
