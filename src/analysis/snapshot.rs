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
}

impl Snapshot {
    /// The fluid of a simulation now, with its free surface detected (7.21–7.24, thresholds 0.20/0.75);
    /// `dx` is the finest particle spacing. Refreshes the simulation's derived fields first.
    pub fn from_simulation(sim: &mut crate::sph::solver::Simulation<2>, dx: f64) -> Self {
        sim.refresh();
        let fs = sim.free_surface(crate::sph::free_surface::Thresholds::default());
        let f = &sim.fluid;
        Snapshot {
            pos: f.pos.clone(),
            vel: f.vel.clone(),
            vol: f.mass.iter().zip(&f.rho).map(|(m, r)| m / r).collect(),
            on_surface: fs.on_surface,
            normal: fs.normal,
            lambda: fs.lambda,
            h: sim.kernel.h,
            dx,
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
