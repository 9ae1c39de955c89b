//! Fluid particles stored as a structure of arrays.

use nalgebra::SVector;
use rayon::prelude::*;

/// The most particles (fluid and ghosts), and neighbour-search cells, that a scene may ask for: 1e8, about
/// 100 GB at the measured 0.75–1.1 KB per particle (BENCHMARKS.md), more than the machines this runs on
/// hold. Scene builders check their estimate against it first, so that a spacing or a size typed wrong
/// stops with an error naming it instead of a failed allocation.
pub const MAX_PARTICLES: f64 = 1e8;

/// The fluid particles. Every field has one entry per particle; `id` is the particle's index at creation,
/// kept through the re-ordering by cell so outputs can follow a particle.
#[derive(Clone, Debug, Default)]
pub struct Fluid<const D: usize> {
    pub pos: Vec<SVector<f64, D>>,
    pub vel: Vec<SVector<f64, D>>,
    /// Density ρ (kg/m³).
    pub rho: Vec<f64>,
    /// Mass m (kg per m^{3−D}, i.e. per unit depth in 2D).
    pub mass: Vec<f64>,
    pub id: Vec<u32>,
    /// A free scalar carried with the particle (the built-in cases store the initial depth), for colouring.
    pub tag: Vec<f64>,
    /// The phase of each particle, an index into [`crate::sph::multi_fluid::MultiFluid::phases`]; all 0 in a
    /// single-phase scene.
    pub phase: Vec<u8>,
}

impl<const D: usize> Fluid<D> {
    pub fn len(&self) -> usize {
        self.pos.len()
    }

    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }

    pub fn push(&mut self, pos: SVector<f64, D>, vel: SVector<f64, D>, rho: f64, mass: f64, tag: f64) {
        self.id.push(self.pos.len() as u32);
        self.pos.push(pos);
        self.vel.push(vel);
        self.rho.push(rho);
        self.mass.push(mass);
        self.tag.push(tag);
        self.phase.push(0);
    }

    /// Re-orders every field so that new index k holds old index `order[k]`.
    pub fn permute(&mut self, order: &[u32]) {
        fn apply<T: Copy + Send + Sync>(v: &mut Vec<T>, order: &[u32]) {
            let new: Vec<T> = order.par_iter().map(|&k| v[k as usize]).collect();
            *v = new;
        }
        apply(&mut self.pos, order);
        apply(&mut self.vel, order);
        apply(&mut self.rho, order);
        apply(&mut self.mass, order);
        apply(&mut self.id, order);
        apply(&mut self.tag, order);
        apply(&mut self.phase, order);
    }

    /// The particles of phase `k` alone (a copy), e.g. the water of a multi-fluid scene for the analyses of its
    /// free surface.
    pub fn phase_subset(&self, k: u8) -> Fluid<D> {
        let keep: Vec<usize> = (0..self.len()).filter(|&i| self.phase[i] == k).collect();
        fn pick<T: Copy>(v: &[T], keep: &[usize]) -> Vec<T> {
            keep.iter().map(|&i| v[i]).collect()
        }
        Fluid {
            pos: pick(&self.pos, &keep),
            vel: pick(&self.vel, &keep),
            rho: pick(&self.rho, &keep),
            mass: pick(&self.mass, &keep),
            id: pick(&self.id, &keep),
            tag: pick(&self.tag, &keep),
            phase: pick(&self.phase, &keep),
        }
    }

    /// Total mass.
    pub fn total_mass(&self) -> f64 {
        self.mass.iter().sum()
    }
}
