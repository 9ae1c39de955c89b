//! A frozen 2D particle set with what the analyses need: positions, velocities, volumes and the result of
//! the free-surface detection.

use crate::sph::neighbours::CellList;
use nalgebra::Vector2;

pub type V2 = Vector2<f64>;

/// Fluid particles at one instant.
#[derive(Clone, Debug, Default)]
pub struct Snapshot {
    pub pos: Vec<V2>,
    pub vel: Vec<V2>,
    /// Particle volumes m/ρ.
    pub vol: Vec<f64>,
    pub on_surface: Vec<bool>,
    /// Outward free-surface normal (7.23), zero where undefined.
    pub normal: Vec<V2>,
    /// Minimum eigenvalue of B⁻¹ (7.21).
    pub lambda: Vec<f64>,
    /// Smoothing length h.
    pub h: f64,
    /// Finest particle spacing dx.
    pub dx: f64,
    /// Each particle's index in the simulation's fluid at the time (a snapshot of one phase holds a subset);
    /// empty for a particle set built by hand.
    pub index: Vec<usize>,
}

impl Snapshot {
    /// The fluid of a simulation now, with its free surface detected (7.21–7.24, thresholds 0.20/0.75);
    /// `dx` is the finest particle spacing. Refreshes the simulation's derived fields first.
    pub fn from_simulation(sim: &mut crate::sph::solver::Simulation<2>, dx: f64) -> Self {
        sim.refresh();
        // The first phase (the water) alone: with several phases the others fill what the analyses read as
        // empty (cavities, the region above a jet).
        let fs = sim.free_surface_of_phase(crate::sph::free_surface::Thresholds::default(), 0);
        let f = &sim.fluid;
        let keep: Vec<usize> = (0..f.len()).filter(|&i| f.phase[i] == 0).collect();
        Snapshot {
            pos: keep.iter().map(|&i| f.pos[i]).collect(),
            vel: keep.iter().map(|&i| f.vel[i]).collect(),
            vol: keep.iter().map(|&i| f.mass[i] / f.rho[i]).collect(),
            on_surface: keep.iter().map(|&i| fs.on_surface[i]).collect(),
            normal: keep.iter().map(|&i| fs.normal[i]).collect(),
            lambda: keep.iter().map(|&i| fs.lambda[i]).collect(),
            h: sim.kernel.h,
            dx,
            index: keep,
        }
    }

    /// Cell list over the positions with the given cell size.
    pub fn cells(&self, cell: f64) -> CellList<2> {
        CellList::build(&self.pos, cell)
    }

    pub fn len(&self) -> usize {
        self.pos.len()
    }

    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }
}
