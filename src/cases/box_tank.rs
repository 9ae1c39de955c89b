//! A block of water in a rectangular tank, in any dimension D: the set-up of the 3D comparison runs (the
//! hydrostatic tank, and the dam break as a slab between free-slip side walls), built on
//! [`crate::sph::box_wall::BoxWall`]. The 2D cases come from case files (`setup.rs`); this builder exists so
//! that the same solver runs in 3D from code, before 3D case files do.

use crate::sph::body_force::BodyForce;
use crate::sph::box_wall::{whole_spacings, BoxWall};
use crate::sph::particles::Fluid;
use crate::sph::polyline_wall::GhostKind;
use crate::sph::solver::{Simulation, SolverConfig};
use nalgebra::SVector;

/// Water filling [0, water] at rest with its hydrostatic pressure, in the open tank [0, tank]; the last axis is
/// vertical, gravity g (m/s²) points down it.
#[derive(Clone, Debug)]
pub struct BoxTank<const D: usize> {
    /// Tank size (m); each side a whole number of spacings.
    pub tank: SVector<f64, D>,
    /// Water block size (m), from the tank's origin corner; each side a whole number of spacings.
    pub water: SVector<f64, D>,
    /// Particle spacing (m).
    pub dx: f64,
    /// Reference density (kg/m³).
    pub rho0: f64,
    /// Sound speed c0 (m/s).
    pub c0: f64,
    /// Gravity (m/s²).
    pub g: f64,
}

impl<const D: usize> BoxTank<D> {
    /// The solver's defaults (thesis values, [`SolverConfig::new`]) with particles leaving a box one tank size
    /// around the tank counted as a blow-up.
    pub fn config(&self) -> SolverConfig<D> {
        let mut gravity = SVector::<f64, D>::zeros();
        gravity[D - 1] = -self.g;
        let mut cfg = SolverConfig::new(self.dx, self.rho0, self.c0, BodyForce::Uniform(gravity));
        cfg.domain = Some((-self.tank, self.tank * 2.0));
        cfg
    }

    /// The water on the lattice (i + ½) dx, each particle at the density of its hydrostatic pressure
    /// ρ0 g (depth) and of mass ρ dx^D; the tag is its initial depth.
    pub fn fluid(&self, cfg: &SolverConfig<D>) -> Result<Fluid<D>, String> {
        let mut n = [0usize; D];
        for (k, nk) in n.iter_mut().enumerate() {
            *nk = whole_spacings(self.water[k], self.dx)
                .filter(|_| self.water[k] <= self.tank[k])
                .ok_or_else(|| {
                    format!(
                        "water block side {k} is {} m: expected a positive whole number of spacings {} m, inside the \
                         tank",
                        self.water[k], self.dx
                    )
                })?;
        }
        let mut f = Fluid::default();
        let mut idx = [0usize; D];
        let total: usize = n.iter().product();
        for _ in 0..total {
            let x = SVector::<f64, D>::from_fn(|k, _| (idx[k] as f64 + 0.5) * self.dx);
            let depth = self.water[D - 1] - x[D - 1];
            let rho = cfg.eos.density(self.rho0 * self.g * depth);
            f.push(x, SVector::zeros(), rho, rho * self.dx.powi(D as i32), depth);
            for k in 0..D {
                idx[k] += 1;
                if idx[k] < n[k] {
                    break;
                }
                idx[k] = 0;
            }
        }
        Ok(f)
    }

    /// The simulation: the water, the tank's walls, the configuration `cfg` (from [`BoxTank::config`], changed
    /// as wished).
    pub fn build(&self, cfg: SolverConfig<D>) -> Result<Simulation<D>, String> {
        self.build_with_ghosts(cfg, GhostKind::Fixed)
    }

    /// [`BoxTank::build`] with the walls' faces made of ghosts of kind `ghosts`.
    pub fn build_with_ghosts(&self, cfg: SolverConfig<D>, ghosts: GhostKind) -> Result<Simulation<D>, String> {
        let fluid = self.fluid(&cfg)?;
        let support = cfg.kernel.support_over_h() * cfg.h;
        let wall = BoxWall::new("tank", SVector::zeros(), self.tank, self.dx, support)?.with_ghosts(ghosts);
        Ok(Simulation::new(cfg, fluid, vec![Box::new(wall)]))
    }
}
