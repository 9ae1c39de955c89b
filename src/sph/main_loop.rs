//! Stage 5 of an evaluation, the main loop: continuity and momentum, eq. (5.1), gathered over each fluid
//! particle's neighbours, in one of two forms:
//!
//! - `MainLoop::over_lists` reads the neighbour lists stage 4 built while it took the renormalised density
//!   gradients ⟨∇ρ⟩^L of the same state (eqs. 4.19–4.20): two passes over the pairs, the thesis's scheme.
//! - `MainLoop::with_next_gradient` scans the cells itself, reads the gradients of the integrator's previous
//!   stage and sums this state's on the way, for the next stage: one pass over the pairs
//!   ([`GradientStage::Previous`]).
//!
//! The pair terms are the same functions in both (`MainLoop::add_pair`).

use super::body_force::BodyForce;
use super::eos::Eos;
use super::equations::{
    continuity,
    density_diffusion::{self, DensityDiffusion},
    pressure_force,
    renormalization::RenormalizedGradient,
    timestep, viscosity,
};
use super::kernel_table::GradientFactor;
use super::neighbours::CellList;
use super::solver::{Gathered, GhostState};
use nalgebra::SVector;
use rayon::prelude::*;

/// Which state the δ-term's renormalised density gradient ⟨∇ρ⟩^L (eqs. 4.19–4.20) is taken at, stage by stage
/// of a time step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum GradientStage {
    /// Every stage its own state's, from a pass over the pairs of its own before the main loop (the thesis's
    /// δ-SPH). The default.
    #[default]
    Own,
    /// The first stage of a step its own; each later stage the previous stage's, summed in that stage's main
    /// loop: one pass over the pairs per stage instead of two after the first (ours, issue #34). A step still
    /// starts from its state alone, so a resumed run takes the same steps. Single phase only (the multi-fluid
    /// path keeps its own gradients).
    Previous,
}

impl std::str::FromStr for GradientStage {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "own" => Ok(Self::Own),
            "previous" => Ok(Self::Previous),
            v => Err(format!("expected `own` or `previous`, got `{v}`")),
        }
    }
}

impl std::fmt::Display for GradientStage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Own => "own",
            Self::Previous => "previous",
        })
    }
}

/// What stage 5 reads: the state of the stage, the ghosts' values and the gradients it takes the δ-term from.
pub(super) struct MainLoop<'a, const D: usize> {
    pub pos: &'a [SVector<f64, D>],
    pub vel: &'a [SVector<f64, D>],
    pub rho: &'a [f64],
    pub pressure: &'a [f64],
    pub volume: &'a [f64],
    /// The fluid's ⟨∇ρ⟩^L the δ-term reads (this state's, or the previous stage's).
    pub grad_rho: &'a [SVector<f64, D>],
    /// Fluid then ghost positions (the cell list's points).
    pub all_pos: &'a [SVector<f64, D>],
    pub ghosts: &'a GhostState<D>,
    pub gradient: GradientFactor<'a, D>,
    pub eos: Eos,
    pub body: BodyForce<D>,
    pub diffusion: DensityDiffusion,
    /// δ c0 h of eq. (5.1) (m²/s).
    pub diff: f64,
    /// The artificial viscosity's coefficient (eq. 4.11).
    pub visc: f64,
    pub h: f64,
}

/// A fluid particle's own values in its pairs.
struct Particle<const D: usize> {
    rho: f64,
    vel: SVector<f64, D>,
    p: f64,
    grad_rho: SVector<f64, D>,
}

/// One particle's sums over its neighbours.
#[derive(Clone, Copy)]
struct PairSums<const D: usize> {
    drho: f64,
    dvel: SVector<f64, D>,
    max_pi: f64,
}

impl<const D: usize> Default for PairSums<D> {
    fn default() -> Self {
        PairSums {
            drho: 0.0,
            dvel: SVector::zeros(),
            max_pi: 0.0,
        }
    }
}

impl<const D: usize> MainLoop<'_, D> {
    /// Particle i's own values, read once for all its pairs.
    #[inline(always)]
    fn particle(&self, i: usize) -> Particle<D> {
        Particle {
            rho: self.rho[i],
            vel: self.vel[i],
            p: self.pressure[i],
            grad_rho: self.grad_rho[i],
        }
    }

    /// Neighbour j's share of particle i's rates: `rij` = r_i − r_j, `r2` = |rij|², `gw` = ∇_i W_ij.
    #[inline(always)]
    fn add_pair(
        &self,
        pi: &Particle<D>,
        j: usize,
        rij: &SVector<f64, D>,
        r2: f64,
        gw: &SVector<f64, D>,
        s: &mut PairSums<D>,
    ) {
        let nf = self.pos.len();
        let gs = self.ghosts;
        let (rho_i, u_i, p_i) = (pi.rho, pi.vel, pi.p);
        let (u_j, rho_j, p_j, v_j, grad_j, u_visc_j) = if j < nf {
            let u = self.vel[j];
            (u, self.rho[j], self.pressure[j], self.volume[j], self.grad_rho[j], u)
        } else {
            let g = j - nf;
            (
                gs.vel[g],
                gs.rho[g],
                gs.p[g],
                gs.volume[g],
                gs.grad_rho[g],
                gs.viscous_velocity(g),
            )
        };
        let u_ji = u_j - u_i;
        s.drho += continuity::velocity_divergence(rho_i, &u_ji, gw, v_j);
        if self.diffusion != DensityDiffusion::None {
            let psi = density_diffusion::psi(self.diffusion, rho_i, rho_j, rij, r2, &pi.grad_rho, &grad_j);
            s.drho += self.diff * psi.dot(gw) * v_j;
        }
        s.dvel += pressure_force::pressure_acceleration(p_i, p_j, rho_i, gw, v_j);
        let pi = viscosity::pi_ij(&(u_visc_j - u_i), rij, r2, self.h);
        s.dvel += viscosity::viscous_acceleration(self.visc, rho_i, pi, gw, v_j);
        s.max_pi = s.max_pi.max(pi.abs());
    }

    /// Particle i's rates from its sums: dρ/dt, and du/dt with the body force and the signal speed of (4.22).
    #[inline(always)]
    fn finish(&self, i: usize, pi: &Particle<D>, s: PairSums<D>) -> (f64, (SVector<f64, D>, f64)) {
        let dvel = s.dvel + self.body.acceleration(&self.pos[i]);
        let signal = timestep::signal_speed(self.eos.sound_speed(pi.rho), pi.vel.norm(), self.h, s.max_pi);
        (s.drho, (dvel, signal))
    }

    /// The gather over the neighbour lists of stage 4.
    pub(super) fn over_lists(&self, neighbours: &[Vec<u32>]) -> Gathered<D> {
        (0..self.pos.len())
            .into_par_iter()
            .map(|i| {
                let (pi, mut s) = (self.particle(i), PairSums::default());
                for &j in &neighbours[i] {
                    let j = j as usize;
                    let rij = self.pos[i] - self.all_pos[j];
                    let r2 = rij.norm_squared();
                    let gw = rij * self.gradient.at(r2);
                    self.add_pair(&pi, j, &rij, r2, &gw, &mut s);
                }
                self.finish(i, &pi, s)
            })
            .unzip()
    }

    /// The gather over the cells within `support`, which also sums this state's ⟨∇ρ⟩^L of every fluid particle
    /// (eqs. 4.19–4.20, over the same neighbours in the same order as stage 4's pass), returned beside the rates.
    pub(super) fn with_next_gradient(&self, cells: &CellList<D>, support: f64) -> (Gathered<D>, Vec<SVector<f64, D>>) {
        let nf = self.pos.len();
        let gs = self.ghosts;
        (0..nf)
            .into_par_iter()
            .map(|i| {
                let (pi, mut s) = (self.particle(i), PairSums::default());
                let mut acc = RenormalizedGradient::<D>::default();
                cells.for_each_within_r2(self.all_pos, &self.pos[i], support, |j, rij, r2| {
                    if j == i {
                        return;
                    }
                    let gw = rij * self.gradient.at(r2);
                    let (rho_j, v_j) = gs.density_and_volume(j, self.rho, self.volume);
                    acc.add(&gw, &rij, rho_j - pi.rho, v_j);
                    self.add_pair(&pi, j, &rij, r2, &gw, &mut s);
                });
                (self.finish(i, &pi, s), acc.gradient())
            })
            .unzip()
    }
}
